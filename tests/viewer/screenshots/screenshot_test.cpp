// Pictures from `particles view --screenshot`, checked pixel by pixel against
// where the viewer's own camera (a pure function) puts the world. Rendering
// off screen is not antialiased, so colours are exact. Needs an X display
// (tests/viewer/with_display.sh provides Xvfb when there is none).
#include <gtest/gtest.h>

#include <numbers>

#include "particles/scenefile.h"
#include "particles/viewer/palette.h"
#include "screenshot_support.h"

namespace particles::viewer::test {
namespace {

constexpr int kWidth = 640, kHeight = 480;
constexpr double kPi = std::numbers::pi;

struct Case {
  std::string file;
  SceneDef scene;
};

Case sceneCase(const std::string& json) {
  Case c;
  c.file = writeScene(json);
  c.scene = parseScene(json, c.file);
  return c;
}

Camera cameraFor(const SceneDef& scene, ViewMode mode = ViewMode::Engine, std::size_t k = 0) {
  return camerasFor(mode, runBounds(scene), kWidth, kHeight, {}).at(k);
}

// A point of ball i's disk at `fraction` of its radius in world direction
// `angle` (rad, counter-clockwise), on screen.
Vec2 onDisk(const Camera& c, const BallState& b, double radius, double angle, double fraction) {
  return c.toScreen(b.position + fraction * radius * Vec2(std::cos(angle), std::sin(angle)));
}

#define EXPECT_COLOUR(image, point, colour)                                                     \
  EXPECT_EQ(pixel(image, point), colour)                                                        \
      << "at (" << (point).x() << ", " << (point).y() << "): " << describe(pixel(image, point)) \
      << ", want " << describe(colour)

const char* kThreeBalls = R"({
  "box": {"min": [0, 0], "max": [4, 3]},
  "balls": [
    {"position": [1, 1], "radius": 0.3, "mass": 1},
    {"position": [2.5, 2], "radius": 0.4, "mass": 1},
    {"position": [3.2, 0.8], "radius": 0.25, "mass": 1}
  ],
  "dt": 0.001, "duration": 1
})";

TEST(Screenshot, EveryBallAtItsProjectedPixels) {
  const Case c = sceneCase(kThreeBalls);
  const Shot shot = screenshot(c.file, kWidth, kHeight, "--mode engine");
  ASSERT_TRUE(shot.loaded) << shot.run.err;
  keep(shot, "three_balls_engine");
  const Camera cam = cameraFor(c.scene);
  const std::vector<BallState> balls = sessionAfter(c.scene, 0).engineBalls();
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const double r = c.scene.balls[i].radius;
    // Off the marker (which points along the angle, 0 here): the ball's fill.
    for (double a : {kPi / 2.0, kPi, 3.0 * kPi / 2.0})
      for (double f : {0.2, 0.5, 0.85})
        EXPECT_COLOUR(shot.image, onDisk(cam, balls[i], r, a, f), palette::kEngineBall);
    // Just outside: background.
    for (double a : {0.0, kPi / 2.0, kPi, 3.0 * kPi / 2.0})
      EXPECT_COLOUR(shot.image, onDisk(cam, balls[i], r, a, 1.2), palette::kBackground);
  }
  // Exactly three disks (fill and marker together), centred where the camera
  // projects the balls.
  const std::vector<Vec2> found = blobs(shot.image, {palette::kEngineBall, palette::kMarker});
  ASSERT_EQ(found.size(), balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) {
    double nearest = 1e9;  // blobs come in scan order, not in the file's
    for (const Vec2& f : found)
      nearest = std::min(nearest, (f - cam.toScreen(balls[i].position)).norm());
    EXPECT_LT(nearest, 1.5) << "ball " << i;
  }
}

TEST(Screenshot, WallsAreDrawnWhereTheyAre) {
  const Case c = sceneCase(kThreeBalls);
  const Shot shot = screenshot(c.file, kWidth, kHeight, "--mode engine");
  ASSERT_TRUE(shot.loaded) << shot.run.err;
  const Camera cam = cameraFor(c.scene);
  for (double x : {0.5, 2.0, 3.5}) {
    EXPECT_COLOUR(shot.image, cam.toScreen({x, 0.0}), palette::kWall);  // floor
    EXPECT_COLOUR(shot.image, cam.toScreen({x, 3.0}) + Vec2(0.0, -0.5), palette::kWall);
  }
  EXPECT_COLOUR(shot.image, cam.toScreen({2.0, 1.0}), palette::kBackground);
}

const char* kSpinner = R"({
  "box": {"min": [-2, -1.5], "max": [2, 1.5]},
  "balls": [{"position": [0, 0], "radius": 1, "mass": 1, "angular_velocity": %W}],
  "dt": 0.001, "duration": 5
})";

Case spinner(double omega) {
  std::string json = kSpinner;
  char number[32];
  std::snprintf(number, sizeof number, "%.17g", omega);
  json.replace(json.find("%W"), 2, number);
  return sceneCase(json);
}

TEST(Screenshot, MarkerPointsUpAfterAQuarterTurn) {
  // w = pi/2 rad/s for 1 s (60 frames of 1/60 s): angle pi/2, marker up.
  const Case c = spinner(kPi / 2.0);
  const Shot shot = screenshot(c.file, kWidth, kHeight, "--mode engine --frames 60");
  ASSERT_TRUE(shot.loaded) << shot.run.err;
  keep(shot, "quarter_turn");
  const Session s = sessionAfter(c.scene, 60);
  ASSERT_NEAR(s.engine().ball(0).angle, kPi / 2.0, 1e-9);
  const Camera cam = cameraFor(c.scene);
  const BallState b = s.engine().ball(0);
  const Vec2 centre = cam.toScreen(b.position);
  const double rPx = cam.scale;  // radius 1 m
  for (double f : {0.15, 0.4, 0.7, 0.95}) {
    EXPECT_COLOUR(shot.image, centre + Vec2(0.0, -f * rPx), palette::kMarker);     // up
    EXPECT_COLOUR(shot.image, centre + Vec2(0.0, f * rPx), palette::kEngineBall);  // down
    EXPECT_COLOUR(shot.image, centre + Vec2(f * rPx, 0.0), palette::kEngineBall);  // start
  }
  EXPECT_NEAR(seenMarkerAngle(shot.image, centre, rPx, palette::kMarker), kPi / 2.0, 0.02);
}

// Screen angle of the marker at several frames, in one engine's mode.
std::vector<double> seenAngles(const Case& c, const std::string& mode,
                               const std::vector<int>& frames) {
  std::vector<double> seen;
  const Camera cam = cameraFor(c.scene);
  for (int f : frames) {
    const Shot shot =
        screenshot(c.file, kWidth, kHeight, "--mode " + mode + " --frames " + std::to_string(f));
    EXPECT_TRUE(shot.loaded) << shot.run.err;
    if (f == frames.back()) keep(shot, "spin_" + mode + "_" + std::to_string(f));
    const double rPx = cam.scale;
    seen.push_back(seenMarkerAngle(shot.image, cam.toScreen({0.0, 0.0}), rPx, palette::kMarker));
  }
  return seen;
}

double wrapped(double a) {
  return a - 2.0 * kPi * std::round(a / (2.0 * kPi));
}

TEST(Screenshot, PositiveSpinTurnsCounterClockwiseOnScreen) {
  // w = +1 rad/s: every 30 frames (0.5 s) the marker turns +0.5 rad as seen,
  // i.e. counter-clockwise, in both engines.
  const Case c = spinner(1.0);
  for (const char* mode : {"engine", "box2d"}) {
    const std::vector<double> seen = seenAngles(c, mode, {0, 30, 60, 90, 120});
    for (std::size_t k = 0; k < seen.size(); ++k)
      EXPECT_NEAR(wrapped(seen[k] - 0.5 * static_cast<double>(k)), 0.0, 0.03)
          << mode << " at frame " << 30 * k;
  }
}

TEST(Screenshot, NegativeSpinTurnsClockwise) {
  const Case c = spinner(-1.0);
  const std::vector<double> seen = seenAngles(c, "engine", {0, 30, 60});
  for (std::size_t k = 0; k < seen.size(); ++k)
    EXPECT_NEAR(wrapped(seen[k] + 0.5 * static_cast<double>(k)), 0.0, 0.03) << "frame " << 30 * k;
}

const char* kDragScene = R"({
  "box": {"min": [0, 0], "max": [4, 3]},
  "balls": [{"position": [1, 1], "radius": 0.3, "mass": 2}],
  "dt": 0.001, "duration": 5
})";

// Pixels along the pull's segment outside the ball: from just past the rim
// to just before the cursor's dot.
std::vector<Vec2> alongPull(const Camera& cam, const Vec2& centre, double radius,
                            const Vec2& cursor) {
  const Vec2 a = cam.toScreen(centre), b = cam.toScreen(cursor);
  const double len = (b - a).norm(), rPx = radius * cam.scale;
  std::vector<Vec2> points;
  for (double t = (rPx + 4.0) / len; t < 1.0 - 6.0 / len; t += 0.05)
    points.push_back(a + t * (b - a));
  return points;
}

TEST(Screenshot, ScriptedDragDrawsTheSegmentToTheCursor) {
  const Case c = sceneCase(kDragScene);
  const ScriptedDrag drag{0, {3.5, 2.5}};
  const Shot shot =
      screenshot(c.file, kWidth, kHeight, "--mode engine --frames 6 --drag 0:3.5,2.5");
  ASSERT_TRUE(shot.loaded) << shot.run.err;
  keep(shot, "drag_engine");
  const Session s = sessionAfter(c.scene, 6, drag);
  const BallState b = s.engine().ball(0);
  EXPECT_GT(b.position.x(), 1.0);  // the pull has started to move it
  const Camera cam = cameraFor(c.scene);
  const std::vector<Vec2> points = alongPull(cam, b.position, 0.3, drag.target);
  ASSERT_GT(points.size(), 5u);
  for (const Vec2& p : points) EXPECT_COLOUR(shot.image, p, palette::kDrag);
  EXPECT_COLOUR(shot.image, cam.toScreen(drag.target), palette::kDrag);  // the cursor's dot
  // The ball itself is where the session says.
  EXPECT_COLOUR(shot.image, onDisk(cam, b, 0.3, kPi, 0.5), palette::kEngineBall);

  // Without the drag, the same pixels are background.
  const Shot still = screenshot(c.file, kWidth, kHeight, "--mode engine --frames 6");
  ASSERT_TRUE(still.loaded) << still.run.err;
  for (const Vec2& p : points) EXPECT_COLOUR(still.image, p, palette::kBackground);
}

TEST(Screenshot, SideBySideShowsEachEngineInItsHalfWithThePull) {
  const Case c = sceneCase(kDragScene);
  const ScriptedDrag drag{0, {3.5, 2.5}};
  const Shot shot = screenshot(c.file, kWidth, kHeight, "--mode side --frames 6 --drag 0:3.5,2.5");
  ASSERT_TRUE(shot.loaded) << shot.run.err;
  keep(shot, "drag_side");
  const Session s = sessionAfter(c.scene, 6, drag);
  const Camera left = cameraFor(c.scene, ViewMode::Side, 0);
  const Camera right = cameraFor(c.scene, ViewMode::Side, 1);
  const BallState e = s.engine().ball(0), x = s.box2d()->ball(0);
  EXPECT_COLOUR(shot.image, onDisk(left, e, 0.3, kPi, 0.5), palette::kEngineBall);
  EXPECT_COLOUR(shot.image, onDisk(right, x, 0.3, kPi, 0.5), palette::kBox2DBall);
  for (const Vec2& p : alongPull(left, e.position, 0.3, drag.target))
    EXPECT_COLOUR(shot.image, p, palette::kDrag);
  for (const Vec2& p : alongPull(right, x.position, 0.3, drag.target))
    EXPECT_COLOUR(shot.image, p, palette::kDrag);
}

TEST(Screenshot, OverlayOutlinesBox2DOverTheEngine) {
  const Case c = sceneCase(kThreeBalls);
  const Shot shot = screenshot(c.file, kWidth, kHeight, "--mode overlay");
  ASSERT_TRUE(shot.loaded) << shot.run.err;
  keep(shot, "overlay");
  const Camera cam = cameraFor(c.scene, ViewMode::Overlay);
  const std::vector<BallState> balls = sessionAfter(c.scene, 0).engineBalls();
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const double r = c.scene.balls[i].radius;
    const Vec2 centre = cam.toScreen(balls[i].position);
    EXPECT_COLOUR(shot.image, onDisk(cam, balls[i], r, kPi, 0.5), palette::kEngineBall);
    // The ghost's outline is 2 px wide just outside the rim; its radius line
    // lies on the engine's white marker, drawn over it.
    EXPECT_COLOUR(shot.image, centre + Vec2(0.0, -(r * cam.scale + 1.0)), palette::kBox2DBall);
    EXPECT_COLOUR(shot.image, centre + Vec2(0.5 * r * cam.scale, 0.0), palette::kBox2DBall);
  }
}

// ---- The command line ----------------------------------------------------------

// A PNG path in the scratch directory, for runs that must fail before writing.
std::string unusedPng() {
  return shellQuote((scratchDir() / (uniqueName("unused") + ".png")).string());
}

TEST(ViewCli, WithoutADisplayItSaysHowToGetOne) {
  const Case c = sceneCase(kThreeBalls);
  const RunResult r = runParticles("view " + shellQuote(c.file) + " --screenshot " + unusedPng(),
                                   "env -u DISPLAY ");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("xvfb-run -a particles view"), std::string::npos) << r.err;
}

TEST(ViewCli, BadArgumentsAreExitStatus2) {
  const Case c = sceneCase(kThreeBalls);
  const std::string scene = shellQuote(c.file);
  for (const char* args : {" --mode both", " --size 10x10", " --size 640", " --drag 0:1",
                           " --drag x:1,2", " --drag 3:1,2", " --frames -1"}) {
    const RunResult r = runParticles("view " + scene + args + " --screenshot " + unusedPng());
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("particles: error: ", 0), 0u) << args << ": " << r.err;
  }
  const RunResult missing = runParticles("view /nonexistent.json --screenshot " + unusedPng());
  EXPECT_EQ(missing.status, 2);
}

TEST(ViewCli, UnwritableScreenshotIsExitStatus1) {
  const Case c = sceneCase(kThreeBalls);
  const RunResult r = runParticles("view " + shellQuote(c.file) +
                                   " --screenshot /nonexistent-dir/x.png --size 64x64");
  EXPECT_EQ(r.status, 1) << r.err;
}

}  // namespace
}  // namespace particles::viewer::test
