// particles suite: the comparison suite (compare::runSuite) with its reports.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "cli_common.h"
#include "commands.h"
#include "particles/compare/case_generator.h"
#include "particles/compare/suite.h"
#include "particles/compare/suite_report.h"

namespace particles::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSummary =
    "Run the comparison suite (engine vs closed form vs Box2D over random and named impact "
    "cases, plus the mutation check) and write its report";

constexpr const char* kFooter =
    R"(What it does: the named catalogue of cases plus --cases random cases in
each of 6 families (no-slip, friction-sliding, friction-sticking, wall, smooth,
multi-contact), drawn from --seed. Each case is one step of bodies at contact
(dt 1/60 s), run in the engine, in Box2D and, for isolated impacts, in the
closed form. A case passes when the engine is within 1e-9 (relative) of the
closed form, breaks no invariant, and Box2D either agrees within 1e-5
(relative) or its difference is attributed to a named cause. Then the mutation
check: each deliberately wrong-signed solver ("mutant") must fail some case.
Same --seed and --cases give the same report, whatever --jobs (except
"timing").
Reports (the directory is created; old reports in it are replaced):
  DIR/report.md    summary per family, mutants, failed/unexplained cases
  DIR/report.json  everything, per-case records (docs/report-format.md)
Output: a per-family summary on stdout (worst differences in m/s and rad/s;
"n/a" where no case has a closed form), the PASS/FAIL line, cases/s, the
mutant catch rate and where the report is. A progress bar on stderr only when
stderr is a terminal.
Exit status:
  0  the suite passed: no case failed and every mutant was caught
  1  the suite failed (see DIR/report.md), or an I/O or internal error
  2  bad arguments, or DIR cannot be written: one line on stderr
)";

// Above this many cases in total, report.json keeps only the notable records
// unless --records all says otherwise (a record is ~2 kB of JSON).
constexpr long long kAllRecordsUpTo = 100000;
// Keeps the total case count (catalogue + 6 families) well inside an int.
constexpr long long kMaxCasesPerFamily = 100000000;
constexpr long long kMaxJobs = 1024;

struct SuiteOptions {
  int cases = 1000;
  std::uint64_t seed = 1;
  std::string report = "report";
  int jobs = 0;
  std::string records;  // "all", "notable", or "" for the default
  bool noMutants = false;
  Box2DIterations iterations;
};

// ---- Progress bar ---------------------------------------------------------------

// "\r[#####     ] 52% 15600/30015 cases" on stderr, redrawn only when the
// text changes; erased by finish(). Silent unless stderr is a terminal.
class ProgressBar {
 public:
  explicit ProgressBar(bool mutants) : enabled_(::isatty(2) == 1), mutants_(mutants) {}
  bool enabled() const { return enabled_; }

  void update(int done, int total) {
    if (!enabled_ || total <= 0) return;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(static_cast<long long>(kWidth) * done / total);
    const int percent = static_cast<int>(100LL * done / total);
    std::string line = "\r[" + std::string(filled, '#') + std::string(kWidth - filled, ' ') + "] " +
                       std::to_string(percent) + "% " + std::to_string(done) + "/" +
                       std::to_string(total) + " cases";
    if (done == total && mutants_) line += ", mutation check...";
    if (line == last_) return;
    std::fputs(line.c_str(), stderr);
    std::fflush(stderr);
    last_ = std::move(line);
  }

  void finish() {
    if (!enabled_ || last_.empty()) return;
    std::fputs(("\r" + std::string(last_.size() - 1, ' ') + "\r").c_str(), stderr);
    std::fflush(stderr);
    last_.clear();
  }

 private:
  bool enabled_;
  bool mutants_;
  std::string last_;
};

// ---- Summary on stdout ---------------------------------------------------------

std::string sci(double x) {
  if (std::isnan(x)) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", x);
  return buf;
}

std::string padded(const std::string& s, std::size_t width, bool right) {
  if (s.size() >= width) return s;
  const std::string fill(width - s.size(), ' ');
  return right ? fill + s : s + fill;
}

std::string summaryText(const compare::SuiteResult& result, const fs::path& dir,
                        compare::CaseRecords records) {
  std::ostringstream out;
  out << padded("family", 18, false) << padded("cases", 8, true) << padded("failed", 8, true)
      << padded("engine-truth worst", 22, true) << padded("Box2D-ref worst", 22, true)
      << padded("unexplained", 13, true) << "  Box2D causes\n";
  out << padded("", 34, false) << padded("|dv| m/s |dw| rad/s", 22, true)
      << padded("|dv| m/s |dw| rad/s", 22, true) << "\n";
  for (const compare::FamilySummary& s : compare::summarise(result)) {
    std::string causes;
    for (const auto& [name, n] : s.causes) {
      if (name == "agrees") continue;
      causes += (causes.empty() ? "" : ", ") + name + " " + std::to_string(n);
    }
    out << padded(std::string(compare::familyName(s.family)), 18, false)
        << padded(std::to_string(s.cases), 8, true) << padded(std::to_string(s.failed), 8, true)
        << padded(sci(s.engineWorstV), 13, true) << padded(sci(s.engineWorstW), 9, true)
        << padded(sci(s.box2dWorstV), 13, true) << padded(sci(s.box2dWorstW), 9, true)
        << padded(std::to_string(s.unexplained), 13, true) << "  "
        << (causes.empty() ? "-" : causes) << "\n";
  }
  out << "\n"
      << (result.passed() ? "PASS" : "FAIL") << ": " << result.cases.size() << " cases, "
      << result.failed() << " failed, " << result.unexplained()
      << " unexplained Box2D discrepancies\n";
  if (result.mutants.empty()) {
    out << "Mutant catch rate: not run (--no-mutants)\n";
  } else {
    int caught = 0;
    for (const compare::MutantRecord& m : result.mutants) caught += m.caught;
    out << "Mutant catch rate: " << std::lround(100.0 * result.mutantCatchRate()) << " % ("
        << caught << " of " << result.mutants.size() << " mutants caught)\n";
  }
  out << "Speed: " << std::lround(result.isolatedCasesPerSecond) << " isolated cases/s ("
      << result.isolatedCases << " cases), " << std::lround(result.casesPerSecond)
      << " cases/s overall, on " << result.jobs << " threads (" << std::fixed
      << std::setprecision(3) << result.seconds << " s; the mutation check is not counted)\n"
      << std::defaultfloat;
  out << "Report: " << (dir / "report.md").string() << " and " << (dir / "report.json").string()
      << " (case records: " << (records == compare::CaseRecords::All ? "all" : "notable") << ")\n";
  return out.str();
}

// ---- The command ---------------------------------------------------------------

// Creates DIR and checks it can hold files, before the suite spends minutes.
bool prepareReportDir(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    printError("--report: cannot create the directory '" + dir.string() + "'");
    return false;
  }
  const fs::path probe = dir / ".particles-write-check";
  {
    std::ofstream out(probe, std::ios::binary | std::ios::trunc);
    if (!out) {
      printError("--report: cannot write in '" + dir.string() + "'");
      return false;
    }
  }
  fs::remove(probe, ec);
  return true;
}

int suite(const SuiteOptions& o) {
  compare::SuiteSettings settings;
  settings.casesPerFamily = o.cases;
  settings.seed = o.seed;
  settings.jobs = o.jobs;
  settings.mutants = !o.noMutants;
  settings.box2dVelocityIterations = o.iterations.velocity;
  settings.box2dPositionIterations = o.iterations.position;

  const long long total = static_cast<long long>(compare::catalogue().size()) +
                          static_cast<long long>(compare::kAllFamilies.size()) * o.cases;
  compare::CaseRecords records =
      total <= kAllRecordsUpTo ? compare::CaseRecords::All : compare::CaseRecords::Notable;
  if (o.records == "all") records = compare::CaseRecords::All;
  if (o.records == "notable") records = compare::CaseRecords::Notable;

  const fs::path dir = o.report;
  if (!prepareReportDir(dir)) return kExitBadInput;

  // No callback at all unless the bar shows: runSuite then waits for its
  // workers without polling, and its timing is not rounded up to a poll.
  ProgressBar bar(settings.mutants);
  std::function<void(int, int)> progress;
  if (bar.enabled()) progress = [&bar](int done, int all) { bar.update(done, all); };
  const compare::SuiteResult result = compare::runSuite(settings, progress);
  bar.finish();

  try {
    compare::writeSuiteReport(result, dir, records);
  } catch (const std::exception& e) {
    printError(std::string("--report: ") + e.what());
    return kExitFailed;
  }
  std::cout << summaryText(result, dir, records) << std::flush;
  if (!std::cout) return kExitFailed;
  return result.passed() ? kExitOk : kExitFailed;
}

}  // namespace

void addSuiteCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand("suite", kSummary);
  cmd->footer(kFooter);
  auto o = std::make_shared<SuiteOptions>();
  cmd->add_option("--cases", o->cases,
                  "Random cases per family (6 families), besides the named catalogue, "
                  "integer 0 to 100000000")
      ->type_name("N")
      ->default_val(o->cases)
      ->check(integerInRange(0, kMaxCasesPerFamily));
  cmd->add_option("--seed", o->seed,
                  "Seed of the random cases, integer 0 to 2^64-1; case k of a family is the "
                  "same whatever --cases and --jobs")
      ->type_name("S")
      ->default_val(o->seed)
      ->check(unsigned64());
  cmd->add_option("--report", o->report,
                  "Directory for report.json and report.md, created if missing")
      ->type_name("DIR")
      ->default_val(o->report);
  cmd->add_option("--jobs", o->jobs,
                  "Threads, integer 0 to 1024; 0 = all hardware threads. Results do not depend "
                  "on it")
      ->type_name("J")
      ->default_val(o->jobs)
      ->check(integerInRange(0, kMaxJobs));
  cmd->add_option("--records", o->records,
                  "Per-case records in report.json: all, or notable (the catalogue and every "
                  "case that failed or needed an attribution). Default: all up to 100000 cases "
                  "in total, notable above")
      ->type_name("WHICH")
      ->check(CLI::IsMember({"all", "notable"}));
  cmd->add_flag("--no-mutants", o->noMutants,
                "Skip the mutation check (the catch rate then counts as 100 %)");
  addBox2DIterationOptions(*cmd, o->iterations);
  cmd->callback([o, &action] {
    action = [o] {
      try {
        return suite(*o);
      } catch (const std::exception& e) {
        printError(std::string("internal error: ") + e.what());
        return kExitFailed;
      }
    };
  });
}

}  // namespace particles::cli
