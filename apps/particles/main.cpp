// particles: the command-line front end. main() only registers the
// subcommands, parses, and maps every CLI11 error to exit status 2.
#include <CLI/CLI.hpp>
#include <iostream>

#include "commands.h"

namespace {

constexpr const char* kFooter = R"(Commands:
  particles run SCENE.json [--engine engine|box2d]   simulate, print the final state
  particles compare SCENE.json...                     engine vs Box2D, event by event
  particles suite [--cases N] [--report DIR]          the comparison suite and its report
  particles merge DIR... [--report DIR]               combine the reports of suite --shard
  particles bench [--full] [--report DIR]             run time against error, engine vs Box2D
  particles stress [--long] [--report DIR]            stability envelope, broken cases as scenes
  particles bench --scale [--n N...] [--threads T...] the pile benchmark, engine vs Box2D
'particles COMMAND --help' explains each command's options and output.
Units are SI throughout: metres, kilograms, seconds, radians.
Exit status: 0 success; 1 the simulation diverged (non-finite state), the
suite failed, or an I/O error; 2 a bad scene file or bad command-line arguments.
Errors go to stderr as one line, "particles: error: ...".
Docs: docs/cli.md (usage), docs/scene-format.md, docs/report-format.md.
)";

// Where to send the user for help after a parse error: the innermost
// subcommand that was recognised, else the program itself.
std::string helpHint(const CLI::App& app) {
  std::string command = "particles";
  for (const CLI::App* sub : app.get_subcommands()) command += " " + sub->get_name();
  return " (see '" + command + " --help')";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace particles::cli;
  CLI::App app{
      "Simulates 2D spinning balls colliding with friction (impulse solver) and checks the "
      "solver against closed forms and Box2D 2.4.1.",
      "particles"};
  // At most one subcommand; "none" is reported after parsing, so that an
  // unknown word reads "not expected: frob" rather than "subcommand required".
  app.require_subcommand(0, 1);
  app.footer(kFooter);

  CommandAction action;
  addRunCommand(app, action);
  addCompareCommand(app, action);
  addSuiteCommand(app, action);
  addMergeCommand(app, action);
  addBenchCommand(app, action);
  addStressCommand(app, action);
  addViewCommand(app, action);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help: prints help, exits 0
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // CLI11's own exit codes (105, 106, 109, ...) all mean "bad arguments".
    std::cerr << "particles: error: " << e.what() << helpHint(app) << '\n';
    return kExitBadInput;
  }
  if (!action) {
    std::cerr << "particles: error: a subcommand is required, e.g. 'particles run SCENE.json'"
              << helpHint(app) << '\n';
    return kExitBadInput;
  }
  return action();
}
