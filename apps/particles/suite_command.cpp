// particles suite: the comparison suite (compare::runSuite) with its reports.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "cli_common.h"
#include "commands.h"
#include "particles/compare/case_generator.h"
#include "particles/compare/suite.h"
#include "particles/compare/suite_merge.h"
#include "particles/compare/suite_report.h"
#include "suite_html.h"
#include "suite_output.h"

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
  DIR/index.html   per-family tables and discrepancy distributions (gnuplot SVG)
Shards (--shard K/N): N machines each run one slice of the same suite, case
i in shard (i mod N) + 1, the mutation check in shard 1; 'particles merge
DIR...' combines the N reports into the report of one run (docs/cli.md).
Output: a per-family summary on stdout (worst differences in m/s and rad/s;
"n/a" where no case has a closed form), the PASS/FAIL line, cases/s, the
mutant catch rate and where the report is. A progress bar on stderr only when
stderr is a terminal.
Exit status:
  0  the suite passed: no case failed and every mutant was caught
  1  the suite failed (see DIR/report.md), or an I/O or internal error
  2  bad arguments, or DIR cannot be written: one line on stderr
)";

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
  std::string shard;  // "K/N", or "" for the whole suite
};

// ---- Shards ----------------------------------------------------------------------

constexpr long long kMaxShards = 1000000;

// "K/N" with 1 <= K <= N <= kMaxShards, as two ints; nullopt otherwise.
std::optional<std::pair<int, int>> parseShard(const std::string& text) {
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) return std::nullopt;
  long long k = 0, n = 0;
  const char* end = text.data() + text.size();
  const auto [kEnd, kErr] = std::from_chars(text.data(), text.data() + slash, k);
  const auto [nEnd, nErr] = std::from_chars(text.data() + slash + 1, end, n);
  if (kErr != std::errc() || nErr != std::errc() || kEnd != text.data() + slash || nEnd != end ||
      k < 1 || n < k || n > kMaxShards)
    return std::nullopt;
  return std::pair{static_cast<int>(k), static_cast<int>(n)};
}

CLI::Validator shardSpec() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (parseShard(text)) return "";
        return "must be K/N with integers 1 <= K <= N <= " + std::to_string(kMaxShards) + ", got " +
               text;
      },
      "");
}

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

// ---- The command ---------------------------------------------------------------

int suite(const SuiteOptions& o) {
  compare::SuiteSettings settings;
  settings.casesPerFamily = o.cases;
  settings.seed = o.seed;
  settings.jobs = o.jobs;
  settings.mutants = !o.noMutants;
  settings.box2dVelocityIterations = o.iterations.velocity;
  settings.box2dPositionIterations = o.iterations.position;

  if (const auto shard = parseShard(o.shard)) std::tie(settings.shard, settings.shards) = *shard;
  const bool sharded = settings.shards > 1;

  const long long total = static_cast<long long>(compare::catalogue().size()) +
                          static_cast<long long>(compare::kAllFamilies.size()) * o.cases;
  // A shard keeps every record by default: `particles merge` needs them.
  const compare::CaseRecords records =
      caseRecordsFor(total, sharded && o.records.empty() ? "all" : o.records);

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
    if (!sharded) {
      compare::writeSuiteReport(result, dir, records);
    } else {
      // A shard's report says which shard it is, for `particles merge`.
      nlohmann::json json = compare::suiteJson(result, records);
      json["shard"] = compare::shardJson(settings);
      std::string md = compare::suiteMarkdown(result);
      md.insert(md.find("\n\n") + 2,
                "Shard " + std::to_string(settings.shard) + " of " +
                    std::to_string(settings.shards) + " (the cases whose index i has i mod " +
                    std::to_string(settings.shards) + " = " + std::to_string(settings.shard - 1) +
                    "): combine the shards with `particles merge`.\n\n");
      writeReportFiles(dir, json, md);
    }
    writeSuiteHtml(dir, result);
  } catch (const std::exception& e) {
    printError(std::string("--report: ") + e.what());
    return kExitFailed;
  }
  std::cout << suiteSummaryText(result, dir, records) << std::flush;
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
  cmd->add_option("--shard", o->shard,
                  "Run only shard K of N: the cases whose index i has i mod N = K - 1 (shard 1 "
                  "also runs the mutation check); keeps every case record by default. "
                  "Combine the N reports with 'particles merge'")
      ->type_name("K/N")
      ->check(shardSpec());
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
