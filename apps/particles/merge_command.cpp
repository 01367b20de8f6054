// particles merge DIR...: combines the reports of `particles suite --shard
// K/N` runs into the report of one run of the same cases.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli_common.h"
#include "commands.h"
#include "particles/compare/case_generator.h"
#include "particles/compare/suite_merge.h"
#include "particles/compare/suite_report.h"
#include "suite_html.h"
#include "suite_output.h"

namespace particles::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSummary =
    "Combine the reports of 'particles suite --shard K/N' runs into the report of one run";

constexpr const char* kFooter =
    R"(Input: the N shard report directories (or their report.json files), in any
order, written with every case record (the default with --shard). They must
come from the same settings (--cases, --seed, iterations) and form shards 1..N
exactly once each.
Output: DIR/report.json and DIR/report.md, byte for byte those of one
'particles suite' run of the same cases, except "timing" (the shards' seconds
summed, rates recomputed, jobs the largest, plus "shards": N) and the speed
line of report.md; DIR/index.html identical to the single run's; the summary
on stdout as 'particles suite' prints it.
Exit status:
  0  merged, and the merged suite passed
  1  merged, and the merged suite failed; or an I/O or internal error
  2  bad arguments, or shard reports that cannot be merged (one line on stderr
     naming the report and the reason: notable records only, other settings,
     a shard missing or given twice, a report that does not add up)
)";

struct MergeOptions {
  std::vector<std::string> inputs;
  std::string report = "report";
  std::string records;  // "all", "notable", or "" for suite's default
};

fs::path reportFile(const fs::path& input) {
  std::error_code ec;
  return fs::is_directory(input, ec) ? input / "report.json" : input;
}

bool sameDirectory(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return fs::weakly_canonical(a, ec) == fs::weakly_canonical(b, ec);
}

int merge(const MergeOptions& o) {
  const fs::path out = o.report;
  for (const std::string& input : o.inputs)
    if (sameDirectory(reportFile(input).parent_path(), out)) {
      printError("--report: '" + o.report + "' is one of the inputs; merge into another directory");
      return kExitBadInput;
    }
  if (!prepareReportDir(out)) return kExitBadInput;

  compare::ShardMerger merger;
  compare::SuiteResult result;
  try {
    // One report at a time: a shard of a large suite is hundreds of MB.
    for (const std::string& input : o.inputs) {
      const fs::path file = reportFile(input);
      std::ifstream in(file, std::ios::binary);
      if (!in) {
        printError(file.string() + ": cannot open");
        return kExitBadInput;
      }
      nlohmann::json report = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
      if (report.is_discarded()) {
        printError(file.string() + ": not valid JSON");
        return kExitBadInput;
      }
      merger.add(report, file.string());
    }
    result = merger.finish();
  } catch (const compare::ReportError& e) {
    printError(e.what());
    return kExitBadInput;
  }

  const long long total = static_cast<long long>(result.cases.size());
  const compare::CaseRecords records = caseRecordsFor(total, o.records);
  try {
    nlohmann::json json = compare::suiteJson(result, records);
    json["timing"]["shards"] = merger.shards();
    writeReportFiles(out, json, compare::suiteMarkdown(result));
    writeSuiteHtml(out, result);
  } catch (const std::exception& e) {
    printError(std::string("--report: ") + e.what());
    return kExitFailed;
  }
  std::cout << "Merged " << merger.shards() << " shard reports.\n"
            << suiteSummaryText(result, out, records) << std::flush;
  if (!std::cout) return kExitFailed;
  return result.passed() ? kExitOk : kExitFailed;
}

}  // namespace

void addMergeCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand("merge", kSummary);
  cmd->footer(kFooter);
  auto o = std::make_shared<MergeOptions>();
  cmd->add_option("reports", o->inputs,
                  "Shard report directories (DIR/report.json) or report.json files")
      ->required()
      ->type_name("DIR...");
  cmd->add_option(
         "--report", o->report,
         "Directory for the merged report.json, report.md and index.html, created if missing")
      ->type_name("DIR")
      ->default_val(o->report);
  cmd->add_option("--records", o->records,
                  "Per-case records in the merged report.json: all, or notable. Default as "
                  "'particles suite': all up to 100000 cases in total, notable above")
      ->type_name("WHICH")
      ->check(CLI::IsMember({"all", "notable"}));
  cmd->callback([o, &action] {
    action = [o] {
      try {
        return merge(*o);
      } catch (const std::exception& e) {
        printError(std::string("internal error: ") + e.what());
        return kExitFailed;
      }
    };
  });
}

}  // namespace particles::cli
