// The subcommands of `particles`. Each registers itself on the app; when the
// command line selects it, its callback stores in `action` what to run, and
// main() runs that after CLI11 has finished parsing.
#pragma once

#include <functional>

namespace CLI {
class App;
}

namespace particles::cli {

// Exit statuses, the same for every subcommand (docs/cli.md).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;    // the simulation diverged, the suite failed, or an I/O or
                                         // internal error
inline constexpr int kExitBadInput = 2;  // a bad scene file or bad command-line arguments

// Runs the selected command and returns the exit status.
using CommandAction = std::function<int()>;

void addRunCommand(CLI::App& app, CommandAction& action);      // run_command.cpp
void addCompareCommand(CLI::App& app, CommandAction& action);  // compare_command.cpp
void addSuiteCommand(CLI::App& app, CommandAction& action);    // suite_command.cpp
void addMergeCommand(CLI::App& app, CommandAction& action);    // merge_command.cpp
void addBenchCommand(CLI::App& app, CommandAction& action);    // bench_command.cpp
// viewer/cli/view_command.cpp, or view_unavailable.cpp in a build without SFML
void addViewCommand(CLI::App& app, CommandAction& action);

}  // namespace particles::cli
