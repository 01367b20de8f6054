// particles view SCENE.json: the engine and its Box2D twin on screen, or one
// frame of them saved as PNG (--screenshot). Built only with SFML
// (viewer/CMakeLists.txt); view_unavailable.cpp stands in otherwise.
#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>
#include <regex>
#include <string_view>

#include "cli_common.h"
#include "commands.h"
#include "particles/reference/box2d_range.h"
#include "particles/scenefile.h"
#include "particles/viewer/viewer_app.h"

namespace particles::cli {
namespace {

constexpr const char* kSummary =
    "Watch the engine and its Box2D twin run SCENE.json, side by side or overlaid, and pull "
    "balls with the mouse; or save one frame as PNG (--screenshot)";

constexpr const char* kFooter = R"(Modes (--mode, key M cycles):
  engine   the engine's balls (blue)
  box2d    the Box2D twin's balls (orange)
  overlay  the engine's balls with Box2D's as orange outlines on top
  side     engine on the left, Box2D on the right (the default)
Every ball has a white radius marker at its angle; counter-clockwise is
positive, as in the scene file. The readout shows each engine's energies
(translational, rotational, potential from the scene's gravity, zero at y = 0)
and momentum, and the largest position and velocity difference between them.
Keys: P pause, O one step, R restart, M mode, D contact normals and impulses,
  + / - time scale x2 / /2 (more or fewer fixed steps per frame; dt never
  changes), H readout, F12 screenshot (particles-view-N.png), Esc quit.
Mouse: left-drag a ball to pull it with F = k (cursor - centre),
  k = 50 N/m per kg of the ball, in both engines; wheel zooms; right-drag pans.
Headless (--screenshot FILE): runs --frames frames of 1/60 s, draws one
  frame off screen and writes FILE as PNG; no window opens.
Display: SFML needs an X display for OpenGL even off screen; without DISPLAY
  run it under Xvfb: xvfb-run -a particles view ...
Exit status:
  0  the window was closed, or the screenshot was written
  1  no display, no OpenGL surface, or the PNG cannot be written
  2  a bad scene file or bad arguments
)";

struct ViewCliOptions {
  std::string scene;
  std::string mode = "side";
  std::string size = "1280x800";
  std::string drag;
  viewer::ViewOptions view;
  bool noReadout = false;
};

// "WxH", each 64 to 8192 px.
std::optional<std::pair<int, int>> parseSize(const std::string& text) {
  static const std::regex pattern(R"(([0-9]{2,4})x([0-9]{2,4}))");
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) return std::nullopt;
  const int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 64 || h < 64 || w > 8192 || h > 8192) return std::nullopt;
  return std::pair{w, h};
}

// A whole string as one number (std::from_chars: no locale, no leftovers).
template <typename T>
std::optional<T> wholeNumber(std::string_view text) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

// "BALL:X,Y" with a ball index and a finite world point in metres.
std::optional<viewer::ScriptedDrag> parseDrag(std::string_view text) {
  const std::size_t colon = text.find(':'), comma = text.find(',');
  if (colon == std::string_view::npos || comma == std::string_view::npos || comma < colon)
    return std::nullopt;
  const std::optional<int> ball = wholeNumber<int>(text.substr(0, colon));
  const std::optional<double> x = wholeNumber<double>(text.substr(colon + 1, comma - colon - 1));
  const std::optional<double> y = wholeNumber<double>(text.substr(comma + 1));
  if (!ball || *ball < 0 || !x || !y || !std::isfinite(*x) || !std::isfinite(*y))
    return std::nullopt;
  return viewer::ScriptedDrag{*ball, Vec2(*x, *y)};
}

int view(const ViewCliOptions& o) {
  SceneDef scene;
  try {
    scene = loadScene(o.scene);
  } catch (const SceneError& e) {
    printError(e.what());
    return kExitBadInput;
  }
  if (o.view.drag && static_cast<std::size_t>(o.view.drag->ball) >= scene.balls.size()) {
    printError("--drag: no ball " + std::to_string(o.view.drag->ball) + " in " + o.scene +
               " (it has " + std::to_string(scene.balls.size()) + ")");
    return kExitBadInput;
  }
  printRangeWarnings(reference::checkBox2DRange(scene, reference::Box2DSettings::forScene(scene)));
  // SFML aborts the process when it cannot open the X display; say why first.
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') {
    printError(
        "view needs an X display for OpenGL, even with --screenshot, and DISPLAY is not set; "
        "run it under Xvfb: xvfb-run -a particles view ...");
    return kExitFailed;
  }
  return o.view.screenshot.empty() ? viewer::runWindow(scene, o.view)
                                   : viewer::runHeadless(scene, o.view);
}

}  // namespace

void addViewCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand("view", kSummary);
  cmd->footer(kFooter);
  auto o = std::make_shared<ViewCliOptions>();
  cmd->add_option("scene", o->scene, "Scene file, JSON (docs/scene-format.md)")
      ->required()
      ->type_name("SCENE.json");
  cmd->add_option("--mode", o->mode, "What to show: engine, box2d, overlay or side (default)")
      ->type_name("MODE")
      ->check(CLI::IsMember({"engine", "box2d", "overlay", "side"}));
  cmd->add_option("--size", o->size, "Window or picture size in pixels, each 64 to 8192")
      ->type_name("WxH")
      ->default_val(o->size);
  cmd->add_option("--frames", o->view.frames,
                  "Frames of 1/60 s before the screenshot; without --screenshot, quit after "
                  "N frames (0: run until closed). Integer 0 to 100000000")
      ->type_name("N")
      ->default_val(0)
      ->check(integerInRange(0, 100000000));
  cmd->add_option("--screenshot", o->view.screenshot,
                  "Draw off screen (no window) and write the last frame to FILE as PNG")
      ->type_name("FILE.png");
  cmd->add_option("--drag", o->drag,
                  "Pull ball BALL (index in the file) toward the world point X,Y (m) from the "
                  "start, as if held with the mouse")
      ->type_name("BALL:X,Y");
  cmd->add_flag("--no-readout", o->noReadout, "Hide the text readout (H toggles it)");
  cmd->add_flag("--contacts", o->view.contacts,
                "Show contact normals and impulses from the start (D toggles them)");
  cmd->callback([o, &action] {
    const std::optional<std::pair<int, int>> size = parseSize(o->size);
    if (!size)
      throw CLI::ValidationError("--size", "must be WxH with each 64 to 8192 px, got " + o->size);
    o->view.width = size->first;
    o->view.height = size->second;
    if (!o->drag.empty()) {
      o->view.drag = parseDrag(o->drag);
      if (!o->view.drag)
        throw CLI::ValidationError("--drag",
                                   "must be BALL:X,Y (an index and a point in m), got " + o->drag);
    }
    o->view.mode = *viewer::parseMode(o->mode);
    o->view.readout = !o->noReadout;
    action = [o] {
      try {
        return view(*o);
      } catch (const std::exception& e) {
        printError(std::string("internal error: ") + e.what());
        return kExitFailed;
      }
    };
  });
}

}  // namespace particles::cli
