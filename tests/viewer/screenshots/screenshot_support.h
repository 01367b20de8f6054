// Helpers of the screenshot tests: run `particles view --screenshot` on a
// scene written to a private directory, read the PNG back, and find where
// the library's camera says a world point must appear.
#pragma once

#include <sys/wait.h>
#include <unistd.h>
#include <SFML/Graphics/Image.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "particles/viewer/camera.h"
#include "particles/viewer/debug_draw.h"
#include "particles/viewer/session.h"
#include "particles/viewer/viewer_app.h"

namespace particles::viewer::test {

inline std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// A directory of this process's own, removed at exit.
inline const std::filesystem::path& scratchDir() {
  struct Dir {
    std::filesystem::path path = std::filesystem::temp_directory_path() /
                                 ("particles-viewer-tests-" + std::to_string(::getpid()));
    Dir() { std::filesystem::create_directories(path); }
    ~Dir() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const Dir dir;
  return dir.path;
}

inline std::string uniqueName(const std::string& stem) {
  static int n = 0;
  return stem + "-" + std::to_string(n++);
}

struct RunResult {
  int status = -1;  // exit status, -1 if the program did not exit normally
  std::string out, err;
};

// In a sanitizer build, LeakSanitizer finds ~100 bytes leaked by Mesa's
// software OpenGL driver, which is unloaded before the check (an "unknown
// module", so no suppression can name it). Leak checking is off for the
// `particles view` processes only; the viewer's own code is leak-checked
// in-process by viewer_tests. Harmless without sanitizers.
inline constexpr const char* kNoDriverLeakCheck =
    "ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" ";

// Runs `particles ARGS` (already quoted) with `prefix` before it (e.g. an
// environment change), capturing stdout and stderr.
inline RunResult runParticles(const std::string& args, const std::string& prefix = "") {
  const std::filesystem::path errFile = scratchDir() / (uniqueName("stderr") + ".txt");
  const std::string command = kNoDriverLeakCheck + prefix + shellQuote(PARTICLES_CLI) + " " + args +
                              " 2>" + shellQuote(errFile.string());
  RunResult r;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return r;
  char buf[4096];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) r.out.append(buf, n);
  const int status = ::pclose(pipe);
  if (WIFEXITED(status)) r.status = WEXITSTATUS(status);
  std::ifstream in(errFile);
  std::ostringstream text;
  text << in.rdbuf();
  r.err = text.str();
  return r;
}

inline std::string writeScene(const std::string& json) {
  const std::filesystem::path file = scratchDir() / (uniqueName("scene") + ".json");
  std::ofstream(file) << json;
  return file.string();
}

// A screenshot and what it took to make it.
struct Shot {
  RunResult run;
  sf::Image image;
  bool loaded = false;
};

// `particles view SCENE --screenshot FILE --size WxH --no-readout EXTRA`.
inline Shot screenshot(const std::string& scene, int width, int height, const std::string& extra) {
  const std::filesystem::path png = scratchDir() / (uniqueName("shot") + ".png");
  Shot s;
  s.run = runParticles("view " + shellQuote(scene) + " --screenshot " + shellQuote(png.string()) +
                       " --size " + std::to_string(width) + "x" + std::to_string(height) +
                       " --no-readout " + extra);
  s.loaded = s.run.status == 0 && s.image.loadFromFile(png.string());
  return s;
}

// Keeps a copy of a screenshot for people to look at, when
// PARTICLES_VIEWER_TEST_OUTPUT names a directory.
inline void keep(const Shot& s, const std::string& name) {
  const char* dir = std::getenv("PARTICLES_VIEWER_TEST_OUTPUT");
  if (dir != nullptr && *dir != '\0' && s.loaded)
    s.image.saveToFile((std::filesystem::path(dir) / (name + ".png")).string());
}

inline Color pixel(const sf::Image& image, const Vec2& screen) {
  const int x = static_cast<int>(std::floor(screen.x()));
  const int y = static_cast<int>(std::floor(screen.y()));
  if (x < 0 || y < 0 || x >= static_cast<int>(image.getSize().x) ||
      y >= static_cast<int>(image.getSize().y))
    return {0, 0, 0, 0};
  const sf::Color c = image.getPixel(static_cast<unsigned>(x), static_cast<unsigned>(y));
  return {c.r, c.g, c.b, c.a};
}

// snprintf rather than string concatenation, which trips GCC 12's false
// -Wrestrict warning when inlined.
inline std::string describe(Color c) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "(%d, %d, %d)", c.r, c.g, c.b);
  return buf;
}

// The same session the command runs, advanced by the same frames: where the
// balls are when the screenshot is drawn.
inline Session sessionAfter(const SceneDef& scene, long long frames,
                            const std::optional<ScriptedDrag>& drag = std::nullopt) {
  Session session(scene);
  if (drag) session.hold(drag->ball, drag->target);
  for (long long f = 0; f < frames; ++f) session.advance(kFrameSeconds);
  return session;
}

// The angle at which the marker of a ball is seen on screen (rad,
// counter-clockwise from the right as a person reads the picture): the
// direction from the disk's centre to the centroid of the marker-coloured
// pixels inside the disk. -10 when there are none.
inline double seenMarkerAngle(const sf::Image& image, const Vec2& centre, double radiusPx,
                              Color marker) {
  double sx = 0.0, sy = 0.0;
  int n = 0;
  const int r = static_cast<int>(std::ceil(radiusPx));
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const Vec2 p = centre + Vec2(dx, dy);
      if (Vec2(dx, dy).norm() > 0.9 * radiusPx) continue;
      if (!(pixel(image, p) == marker)) continue;
      sx += dx;
      sy += dy;
      ++n;
    }
  }
  if (n == 0) return -10.0;
  return std::atan2(-sy, sx);
}

// Connected groups (4-neighbour) of pixels whose colour is one of `colours`,
// and the centroid of each, in pixels.
inline std::vector<Vec2> blobs(const sf::Image& image, const std::vector<Color>& colours) {
  const int w = static_cast<int>(image.getSize().x), h = static_cast<int>(image.getSize().y);
  std::vector<char> seen(static_cast<std::size_t>(w * h), 0);
  auto wanted = [&](int x, int y) {
    const Color c = pixel(image, Vec2(x, y));
    for (const Color& k : colours)
      if (c == k) return true;
    return false;
  };
  std::vector<Vec2> centroids;
  for (int y0 = 0; y0 < h; ++y0) {
    for (int x0 = 0; x0 < w; ++x0) {
      if (seen[static_cast<std::size_t>(y0 * w + x0)] || !wanted(x0, y0)) continue;
      Vec2 sum(0.0, 0.0);
      long n = 0;
      std::vector<std::pair<int, int>> stack{{x0, y0}};
      seen[static_cast<std::size_t>(y0 * w + x0)] = 1;
      while (!stack.empty()) {
        const auto [x, y] = stack.back();
        stack.pop_back();
        sum += Vec2(x + 0.5, y + 0.5);
        ++n;
        for (const auto& [nx, ny] : {std::pair{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}}) {
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          char& s = seen[static_cast<std::size_t>(ny * w + nx)];
          if (s || !wanted(nx, ny)) continue;
          s = 1;
          stack.push_back({nx, ny});
        }
      }
      centroids.push_back(sum / static_cast<double>(n));
    }
  }
  return centroids;
}

}  // namespace particles::viewer::test
