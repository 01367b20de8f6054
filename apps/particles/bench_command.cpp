// particles bench: registers the subcommand. `--scale` is the pile benchmark
// (bench_scale_command.cpp); the time-step benchmark is registered here too
// once it exists.
#include <CLI/CLI.hpp>
#include <memory>

#include "bench_scale_command.h"
#include "cli_common.h"
#include "commands.h"

namespace particles::cli {

void addBenchCommand(CLI::App& app, CommandAction& action) {
  CLI::App* bench = app.add_subcommand("bench",
                                       "Benchmarks; --scale: the pile scene at N disks, "
                                       "engine and Box2D side by side");
  auto options = std::make_shared<ScaleBenchOptions>();
  addScaleBenchOptions(*bench, *options);
  bench->callback([options, &action] {
    action = [options] {
      if (!options->scale) {
        printError("bench: choose a benchmark, e.g. 'particles bench --scale'");
        return kExitBadInput;
      }
      return runScaleBench(*options);
    };
  });
}

}  // namespace particles::cli
