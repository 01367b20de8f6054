// `particles view` in a build without SFML: the command exists, so that its
// absence is explained rather than reported as an unknown word.
#include <CLI/CLI.hpp>

#include "cli_common.h"
#include "commands.h"

namespace particles::cli {

void addViewCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand(
      "view", "Not available: this particles was built without SFML (apt-get install libsfml-dev)");
  cmd->allow_extras();
  cmd->callback([&action] {
    action = [] {
      printError(
          "'view' is not available: particles was built without SFML 2.5; install libsfml-dev "
          "(tools/setup.sh does) and rebuild");
      return kExitBadInput;
    };
  });
}

}  // namespace particles::cli
