// gnuplot as an SVG renderer: one script per plot with its data inline
// (here-documents), run in a private temporary directory.
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "particles/html/document.h"

namespace particles::html {
namespace {

namespace fs = std::filesystem;

// Colour-blind-safe palette (Okabe-Ito).
constexpr const char* kPalette[] = {"#0072B2", "#E69F00", "#009E73", "#D55E00",
                                    "#CC79A7", "#56B4E9", "#F0E442", "#000000"};

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string script(const Plot& p, const fs::path& svg) {
  std::ostringstream g;
  g.precision(17);
  g << "set terminal svg size " << p.width << "," << p.height
    << " font 'sans,12' background rgb 'white'\n";
  g << "set output " << quoted(svg.string()) << "\n";
  // Labels are plain text ("slide_roll" must not become a subscript); only
  // the tick format uses enhanced text for its powers of ten.
  g << "set title " << quoted(p.title) << " noenhanced\n";
  g << "set xlabel " << quoted(p.xLabel) << " noenhanced\nset ylabel " << quoted(p.yLabel)
    << " noenhanced\n";
  if (p.logX) g << "set logscale x\nset format x '10^{%L}'\n";
  if (p.logY) g << "set logscale y\nset format y '10^{%L}'\n";
  g << "set grid\nset key outside right top\nset datafile missing 'NaN'\n";
  for (std::size_t i = 0; i < p.series.size(); ++i) {
    g << "$d" << i << " << EOD\n";
    for (const auto& [x, y] : p.series[i].points) {
      if (!std::isfinite(x) || !std::isfinite(y)) continue;
      if ((p.logX && x <= 0) || (p.logY && y <= 0)) continue;
      g << x << " " << y << "\n";
    }
    g << "EOD\n";
  }
  bool any = false;
  for (std::size_t i = 0; i < p.series.size(); ++i) {
    const Series& s = p.series[i];
    g << (any ? ", " : "plot ") << "$d" << i << " using 1:2 with " << s.style << " lc rgb '"
      << kPalette[static_cast<std::size_t>(s.color) % 8] << "'";
    if (s.style != "lines") g << " pt " << s.pointType << " ps 0.9";
    if (s.style != "points") g << " lw 1.5";
    g << " title " << quoted(s.title) << " noenhanced";
    any = true;
  }
  if (!any) g << "plot NaN notitle";
  g << "\n";
  return g.str();
}

}  // namespace

bool gnuplotAvailable() {
  return std::system("command -v gnuplot >/dev/null 2>&1") == 0;
}

std::string renderSvg(const Plot& p) {
  static std::atomic<int> counter{0};
  if (!gnuplotAvailable()) return "";
  const fs::path dir = fs::temp_directory_path() / ("particles-plot-" + std::to_string(::getpid()) +
                                                    "-" + std::to_string(counter++));
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return "";
  const fs::path gp = dir / "plot.gp", svg = dir / "plot.svg";
  {
    std::ofstream out(gp);
    out << script(p, svg);
  }
  const std::string cmd = "gnuplot " + quoted(gp.string()) + " >/dev/null 2>&1";
  std::string text;
  if (std::system(cmd.c_str()) == 0) {
    std::ifstream in(svg);
    std::stringstream buf;
    buf << in.rdbuf();
    text = buf.str();
  }
  fs::remove_all(dir, ec);
  // Inline SVG needs no XML prolog or DOCTYPE: keep from <svg on.
  const std::size_t start = text.find("<svg");
  return start == std::string::npos ? "" : text.substr(start);
}

}  // namespace particles::html
