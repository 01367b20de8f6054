// `particles view`: the interactive window, and the headless run that saves
// one screenshot (for CI and the tests). Both need an X display for SFML's
// OpenGL context, a real one or Xvfb's (xvfb-run).
#pragma once

#include <optional>
#include <string>

#include "particles/scene.h"
#include "particles/viewer/view_mode.h"

namespace particles::viewer {

// A scripted mouse pull: ball `ball` held toward `target` from the start.
struct ScriptedDrag {
  int ball = 0;           // index into SceneDef::balls
  Vec2 target{0.0, 0.0};  // m, the cursor's world position
};

struct ViewOptions {
  ViewMode mode = ViewMode::Side;
  int width = 1280;  // px
  int height = 800;  // px
  // Headless: frames of kFrameSeconds run before the screenshot.
  // Window: quit after this many frames; 0 runs until closed.
  long long frames = 0;
  std::string screenshot;  // PNG path; non-empty means headless
  std::optional<ScriptedDrag> drag;
  bool readout = true;    // the text readout
  bool contacts = false;  // contact normals and impulses from the start (key D)
};

// s: the simulated time a frame adds at time scale 1 when the viewer runs
// headless (a 60 Hz display); the window uses the measured frame time.
inline constexpr double kFrameSeconds = 1.0 / 60.0;

// Exit statuses as in docs/cli.md: 0, or 1 when the picture cannot be made
// (no OpenGL surface, the PNG cannot be written).
int runHeadless(const SceneDef& scene, const ViewOptions& options);
int runWindow(const SceneDef& scene, const ViewOptions& options);

}  // namespace particles::viewer
