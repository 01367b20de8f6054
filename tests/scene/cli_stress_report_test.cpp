// particles stress --report DIR: with no --out everything lands in DIR
// (envelope.csv, broken/*.json, index.html), and every scene link in
// index.html resolves, relative to index.html, to a scene that exists. Each
// test is one whole stress run (~10 s in Release).
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "cli_support.h"

namespace particles::test {
namespace {

namespace fs = std::filesystem;

// The href targets in `html`, with the attribute escaping and the percent
// encoding undone: file paths relative to the document.
std::vector<std::string> linkTargets(const std::string& html) {
  std::vector<std::string> out;
  const std::string open = "href=\"";
  for (std::size_t at = html.find(open); at != std::string::npos; at = html.find(open, at)) {
    at += open.size();
    const std::string raw = html.substr(at, html.find('"', at) - at);
    std::string s;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw.compare(i, 5, "&amp;") == 0) {
        s += '&';
        i += 4;
      } else if (raw[i] == '%' && i + 2 < raw.size()) {
        s += static_cast<char>(std::stoi(raw.substr(i + 1, 2), nullptr, 16));
        i += 2;
      } else {
        s += raw[i];
      }
    }
    out.push_back(s);
  }
  return out;
}

std::set<fs::path> brokenScenes(const fs::path& dir) {
  std::set<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir / "broken"))
    if (e.path().extension() == ".json") files.insert(fs::canonical(e.path()));
  return files;
}

// Every link of `report`/index.html names an existing broken scene, and every
// broken scene in `out` is linked.
void expectLinksResolve(const fs::path& report, const fs::path& out) {
  const std::vector<std::string> links = linkTargets(readFile(report / "index.html"));
  const std::set<fs::path> scenes = brokenScenes(out);
  ASSERT_FALSE(scenes.empty()) << "5 r/step tunnels in both engines: some case is broken";
  std::set<fs::path> linked;
  for (const std::string& l : links) {
    ASSERT_FALSE(fs::path(l).is_absolute()) << l;
    const fs::path target = report / l;
    ASSERT_TRUE(fs::exists(target)) << "link " << l << " from " << report;
    linked.insert(fs::canonical(target));
  }
  EXPECT_EQ(linked, scenes);
  EXPECT_EQ(links.size(), scenes.size());
}

// Runs from inside a fresh directory with relative paths, as a user would,
// so that anything written to the default `stress/` would show.
class StressReport : public ::testing::Test {
 protected:
  void SetUp() override {
    home_ = fs::current_path();
    fs::current_path(dir_.file(""));
  }
  void TearDown() override { fs::current_path(home_); }
  TempDir dir_;
  fs::path home_;
};

TEST_F(StressReport, WithoutOutEverythingGoesToTheReportDirectory) {
  const CliResult r = runCli("stress --report rep");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists("rep/index.html"));
  EXPECT_TRUE(fs::exists("rep/envelope.csv"));
  EXPECT_FALSE(fs::exists("stress")) << "nothing in the default --out";
  expectLinksResolve("rep", "rep");
  // The CSV names the same scenes.
  const std::string csv = readFile("rep/envelope.csv");
  for (const fs::path& f : brokenScenes("rep"))
    EXPECT_NE(csv.find("rep/broken/" + f.filename().string()), std::string::npos) << f;
}

// An explicit --out still keeps the scenes there; the report's links reach
// them from its own directory.
TEST_F(StressReport, WithOutTheLinksReachTheScenesThere) {
  const CliResult r = runCli("stress --out 'my out' --report html/rep");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists("my out/envelope.csv"));
  EXPECT_TRUE(fs::exists("html/rep/envelope.csv"));
  EXPECT_FALSE(fs::exists("html/rep/broken"));
  expectLinksResolve("html/rep", "my out");
}

}  // namespace
}  // namespace particles::test
