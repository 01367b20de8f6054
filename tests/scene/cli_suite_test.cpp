// The command line of `particles suite`: a small run, its reports, the
// argument checks, and reports that do not depend on the thread count.
#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "cli_support.h"

namespace particles::test {
namespace {

using nlohmann::json;

CliResult runSuite(const std::string& args, const std::filesystem::path& report) {
  return runCli("suite " + args + " --report " + shellQuote(report.string()));
}

TEST(CliSuite, SmallRunPassesAndWritesBothReports) {
  const TempDir dir;
  const std::filesystem::path report = dir.file("report");  // created by the suite
  const CliResult r = runSuite("--cases 30 --jobs 2", report);
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "") << "no progress bar when stderr is not a terminal";

  const json j = json::parse(readFile(report / "report.json"));
  EXPECT_EQ(j["schema"], "particles-suite-report/1");
  EXPECT_EQ(j["summary"]["passed"], true) << j["summary"].dump();
  EXPECT_EQ(j["summary"]["mutant_catch_rate"].get<double>(), 1.0);
  EXPECT_EQ(j["summary"]["failed"], 0);
  ASSERT_EQ(j["families"].size(), 6u);
  EXPECT_EQ(j["settings"]["cases_per_family"], 30);
  EXPECT_EQ(j["settings"]["seed"], 1);
  EXPECT_EQ(j["timing"]["jobs"], 2);
  EXPECT_EQ(j["case_records"], "all");  // few cases: every record
  EXPECT_EQ(j["cases"].size(), j["summary"]["cases"].get<std::size_t>());
  EXPECT_FALSE(j["mutants"].empty());

  const std::string md = readFile(report / "report.md");
  EXPECT_TRUE(md.starts_with("# Comparison suite report\n")) << md.substr(0, 200);
  EXPECT_NE(md.find("**PASS**"), std::string::npos);

  // stdout: the family table, the verdict, the speed, the catch rate, the report.
  for (const char* family :
       {"no-slip", "friction-sliding", "friction-sticking", "wall", "smooth", "multi-contact"})
    EXPECT_NE(r.out.find(family), std::string::npos) << family;
  EXPECT_NE(r.out.find("\nPASS: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cases/s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Mutant catch rate: 100 %"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find((report / "report.md").string()), std::string::npos) << r.out;
  EXPECT_NE(r.out.find((report / "report.json").string()), std::string::npos) << r.out;
}

TEST(CliSuite, ReportDoesNotDependOnTheThreadCount) {
  const TempDir dir;
  const CliResult one = runSuite("--cases 30 --jobs 1", dir.file("one"));
  const CliResult two = runSuite("--cases 30 --jobs 2", dir.file("two"));
  ASSERT_EQ(one.status, 0) << one.out << one.err;
  ASSERT_EQ(two.status, 0) << two.out << two.err;
  json a = json::parse(readFile(dir.file("one") / "report.json"));
  json b = json::parse(readFile(dir.file("two") / "report.json"));
  EXPECT_EQ(a["timing"]["jobs"], 1);
  EXPECT_EQ(b["timing"]["jobs"], 2);
  a.erase("timing");
  b.erase("timing");
  EXPECT_TRUE(a == b) << "report.json differs beyond \"timing\"";
}

TEST(CliSuite, NotableRecordsAndNoMutants) {
  const TempDir dir;
  const CliResult r = runSuite("--cases 5 --records notable --no-mutants --seed 7", dir.file("r"));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const json j = json::parse(readFile(dir.file("r") / "report.json"));
  EXPECT_EQ(j["case_records"], "notable");
  EXPECT_TRUE(j["mutants"].empty());
  EXPECT_EQ(j["settings"]["seed"], 7);
  EXPECT_LE(j["cases"].size(), j["summary"]["cases"].get<std::size_t>());
  for (const json& c : j["cases"]) {
    const bool notable = c["name"].get<std::string>().starts_with("catalogue/") ||
                         !c["pass"].get<bool>() || c["box2d_cause"] != "agrees";
    EXPECT_TRUE(notable) << c["name"];
  }
  EXPECT_NE(r.out.find("not run"), std::string::npos) << r.out;
}

TEST(CliSuite, BadArgumentsExit2) {
  const TempDir dir;
  for (const char* args : {"--cases -1", "--cases abc", "--cases 1e3", "--jobs -1", "--jobs 5000",
                           "--seed -1", "--seed 18446744073709551616", "--records some",
                           "--velocity-iterations -1", "--position-iterations x", "--bogus"}) {
    const CliResult r = runSuite(args, dir.file("never"));
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(r.out, "") << args;
    EXPECT_TRUE(r.err.starts_with("particles: error: ")) << args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("never"))) << args;
  }
  const CliResult r = runSuite("--cases -1", dir.file("never"));
  EXPECT_NE(r.err.find("--cases: must be an integer >= 0"), std::string::npos) << r.err;
}

TEST(CliSuite, UnwritableReportDirectoryExit2) {
  const TempDir dir;
  writeFile(dir.file("file"), "not a directory");
  const CliResult r = runSuite("--cases 0", dir.file("file") / "report");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_TRUE(r.err.starts_with("particles: error: --report: ")) << r.err;
}

TEST(CliSuite, ProgressBarOnlyOnATerminal) {
  // Not a terminal: covered by SmallRunPassesAndWritesBothReports (stderr
  // empty). A terminal: util-linux `script` gives the program a pty.
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no `script`";
  const TempDir dir;
  const std::string suite = shellQuote(PARTICLES_CLI) + " suite --cases 3 --jobs 1 --report " +
                            shellQuote(dir.file("r").string());
  const std::string command = "script -qec " + shellQuote(suite) + " /dev/null </dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string tty;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) tty.append(buf, n);
  const int status = ::pclose(pipe);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || tty.find("PASS") == std::string::npos)
    GTEST_SKIP() << "no usable pseudo-terminal here: " << tty;
  const std::size_t total = tty.find("] 100% ");
  ASSERT_NE(total, std::string::npos) << tty;
  EXPECT_EQ(tty.substr(total - 31, 32), "[##############################]") << tty;
  EXPECT_NE(tty.find("\r["), std::string::npos) << tty;
  EXPECT_NE(tty.find(" cases, mutation check...\r"), std::string::npos) << tty;
  // Erased before the summary: the table starts on a blanked line.
  EXPECT_NE(tty.find("\rfamily"), std::string::npos) << tty;
}

TEST(CliSuite, HelpExplainsOptionsReportsAndExitCodes) {
  const CliResult r = runCli("suite --help");
  EXPECT_EQ(r.status, 0);
  for (const char* word : {"--cases", "--seed", "--report", "--jobs", "--records", "--no-mutants",
                           "--velocity-iterations", "--position-iterations", "report.json",
                           "report.md", "docs/report-format.md", "Exit status", "1000", "notable"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

}  // namespace
}  // namespace particles::test
