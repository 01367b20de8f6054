// particles bench: registers the subcommand. Two benchmarks share it:
// without --scale, run time against error of the time-stepped catalogue
// (bench_timestep_command.cpp); with --scale, the many-ball pile
// (bench_scale_command.cpp). Each one's options are refused with the other,
// so a typo never silently runs the wrong benchmark.
#include <CLI/CLI.hpp>
#include <array>
#include <memory>
#include <string>
#include <string_view>

#include "bench_scale_command.h"
#include "bench_timestep_command.h"
#include "cli_common.h"
#include "commands.h"
#include "particles/step_error.h"

namespace particles::cli {
namespace {

// clang-format off
constexpr std::array<std::string_view, 19> kScaleOnly{
    "--n", "--threads", "--poly", "--steps", "--no-box2d", "--iterations", "--position-passes",
    "--fast-pair-cells", "--band-rows", "--relaxation", "--shock", "--seed", "--seeds",
    "--no-velocity-shock", "--no-settle-iteration", "--no-wavefront", "--sequential-impacts",
    "--substeps", "--contact-hertz"};
// clang-format on
// --repeats is shared: with --scale it repeats each engine run (default 1).
constexpr std::array<std::string_view, 5> kTimestepOnly{"--full", "--scene", "--skip-csv",
                                                        "--no-skip-study", "--report"};

// The first option of `names` given on the command line, or "".
template <std::size_t N>
std::string givenOption(const CLI::App& cmd, const std::array<std::string_view, N>& names) {
  for (std::string_view name : names)
    if (cmd.get_option(std::string(name))->count() > 0) return std::string(name);
  return "";
}

}  // namespace

void addBenchCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "Run time against error of the time-stepped catalogue, engine vs Box2D; with --scale, the "
      "pile of N disks, engine vs Box2D");
  auto timestep = std::make_shared<TimestepBenchOptions>();
  auto scale = std::make_shared<ScaleBenchOptions>();
  addTimestepBenchOptions(*cmd, *timestep);  // registers --csv, shared by both
  addScaleBenchOptions(*cmd, *scale);
  cmd->callback([cmd, timestep, scale, &action] {
    const bool csvGiven = cmd->get_option("--csv")->count() > 0;
    const bool repeatsGiven = cmd->get_option("--repeats")->count() > 0;
    const std::string misplaced =
        scale->scale ? givenOption(*cmd, kTimestepOnly) : givenOption(*cmd, kScaleOnly);
    action = [timestep, scale, csvGiven, repeatsGiven, misplaced] {
      if (!misplaced.empty()) {
        printError("bench: " + misplaced +
                   (scale->scale ? " is an option of the catalogue benchmark, not of --scale"
                                 : " needs --scale (the pile benchmark)") +
                   " (see 'particles bench --help')");
        return kExitBadInput;
      }
      try {
        if (scale->scale) {
          ScaleBenchOptions o = *scale;
          if (csvGiven) o.csv = timestep->csv;  // else the pile's own default, pile.csv
          // Else 1: a 100,000-disk run takes half a minute, not milliseconds.
          if (repeatsGiven) o.repeats = timestep->repeats;
          return runScaleBench(o);
        }
        return runTimestepBench(*timestep);
      } catch (const StepError& e) {  // a state a run reached (docs/scale.md)
        printError(std::string("bench: ") + e.what());
        return kExitFailed;
      } catch (const std::exception& e) {
        printError(std::string("internal error: ") + e.what());
        return kExitFailed;
      }
    };
  });
}

}  // namespace particles::cli
