// particles bench: registers the subcommand; the work is in
// bench_timestep_command.cpp (run time against error, skip study).
#include <CLI/CLI.hpp>
#include <memory>

#include "bench_timestep_command.h"
#include "cli_common.h"
#include "commands.h"

namespace particles::cli {

void addBenchCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand(
      "bench", "Run time against error of the time-stepped catalogue, engine vs Box2D");
  auto timestep = std::make_shared<TimestepBenchOptions>();
  addTimestepBenchOptions(*cmd, *timestep);
  cmd->callback([timestep, &action] {
    action = [timestep] {
      try {
        return runTimestepBench(*timestep);
      } catch (const std::exception& e) {
        printError(std::string("internal error: ") + e.what());
        return kExitFailed;
      }
    };
  });
}

}  // namespace particles::cli
