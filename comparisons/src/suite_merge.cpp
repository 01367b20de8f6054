#include "particles/compare/suite_merge.h"

#include <algorithm>

#include "particles/compare/case_generator.h"
#include "particles/compare/suite_report.h"

namespace particles::compare {
namespace {

using nlohmann::json;

constexpr const char* kSchema = "particles-suite-report/1";

std::string shardText(int index, int count) {
  return "shard " + std::to_string(index) + " of " + std::to_string(count);
}

// How many of the suite indices [0, total) fall into shard `index` of `count`.
long long shardSize(long long total, int index, int count) {
  return total / count + (index - 1 < total % count ? 1 : 0);
}

// The first key under which two settings objects differ, for the message.
std::string firstDifference(const json& a, const json& b, const std::string& path) {
  if (a.is_object() && b.is_object()) {
    for (const auto& [key, value] : a.items()) {
      if (!b.contains(key)) return path + key + " (missing in one)";
      if (value != b[key]) return firstDifference(value, b[key], path + key + ".");
    }
    return path + "(extra key)";
  }
  return path.substr(0, path.size() - 1) + " = " + a.dump() + " vs " + b.dump();
}

}  // namespace

json shardJson(const SuiteSettings& settings) {
  return {{"index", settings.shard}, {"count", settings.shards}};
}

void ShardMerger::add(const json& report, const std::string& name) {
  const auto fail = [&](const std::string& what) { throw ReportError(name + ": " + what); };
  if (!report.is_object() || !report.contains("schema") || report["schema"] != kSchema)
    fail(std::string("not a suite report (\"schema\" is not \"") + kSchema + "\")");
  if (report.value("case_records", std::string()) != "all")
    fail(
        "holds only the notable case records (\"case_records\": \"notable\"); merging needs "
        "every record: run the shards with --records all");

  int index = 1, count = 1;
  if (report.contains("shard")) {
    try {
      index = report["shard"].at("index").get<int>();
      count = report["shard"].at("count").get<int>();
    } catch (const json::exception& e) {
      fail(std::string("shard: ") + e.what());
    }
  }
  if (count < 1 || index < 1 || index > count)
    fail("shard: index " + std::to_string(index) + " of " + std::to_string(count) +
         " is not in 1..count");
  if (!report.contains("settings")) fail("settings: missing");
  if (!settingsJson_) {
    settingsJson_ = report["settings"];
    firstName_ = name;
    shards_ = count;
  } else {
    if (count != shards_)
      fail("is " + shardText(index, count) + ", but " + firstName_ + " is one of " +
           std::to_string(shards_) + ": shards of different runs");
    if (report["settings"] != *settingsJson_)
      fail("was run with other settings than " + firstName_ + ": " +
           firstDifference(report["settings"], *settingsJson_, "settings."));
  }
  if (const auto it = seen_.find(index); it != seen_.end())
    fail("is " + shardText(index, count) + ", and so is " + it->second + ": a shard given twice");

  SuiteResult shard;
  try {
    shard = suiteResultFromJson(report);
  } catch (const ReportError& e) {
    fail(e.what());
  }
  shard.settings.shard = index;
  shard.settings.shards = count;

  // Exactly this shard's cases, each once, in suite order.
  const long long total =
      static_cast<long long>(catalogue().size()) +
      static_cast<long long>(kAllFamilies.size()) * shard.settings.casesPerFamily;
  const long long want = shardSize(total, index, count);
  if (static_cast<long long>(shard.cases.size()) != want)
    fail("holds " + std::to_string(shard.cases.size()) + " case records; " +
         shardText(index, count) + " of this suite has " + std::to_string(want) +
         " (a truncated or partial report?)");
  for (std::size_t k = 0; k < shard.cases.size(); ++k) {
    const int i = shard.cases[k].index;
    if (!inShard(i, shard.settings) || (k > 0 && i <= shard.cases[k - 1].index))
      fail("case record " + std::to_string(k) + " has index " + std::to_string(i) +
           ", which is not the next case of " + shardText(index, count));
  }
  if (index != 1 && !shard.mutants.empty())
    fail("has mutation-check results, which only shard 1 runs");

  // The summaries, verdict and hash in the file must be what its own
  // records give: otherwise the merged report would silently disagree
  // with the shard reports.
  const json again = suiteJson(shard, CaseRecords::All);
  for (const auto& [key, value] : again.items())
    if (key != "timing" && (!report.contains(key) || report[key] != value))
      fail("\"" + key +
           "\" does not follow from the report's own case records (edited, or written by "
           "another version of particles?)");
  for (const auto& [key, value] : report.items())
    if (key != "shard" && !again.contains(key)) fail("unknown key \"" + key + "\"");

  seen_[index] = name;
  if (seen_.size() == 1) merged_.settings = shard.settings;
  if (index == 1) merged_.mutants = std::move(shard.mutants);
  merged_.seconds += shard.seconds;
  merged_.isolatedSeconds += shard.isolatedSeconds;
  merged_.isolatedCases += shard.isolatedCases;
  merged_.jobs = std::max(merged_.jobs, shard.jobs);
  merged_.cases.insert(merged_.cases.end(), std::make_move_iterator(shard.cases.begin()),
                       std::make_move_iterator(shard.cases.end()));
}

SuiteResult ShardMerger::finish() {
  if (seen_.empty()) throw ReportError("no shard reports to merge");
  std::string missing;
  for (int k = 1; k <= shards_; ++k)
    if (!seen_.contains(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
  if (!missing.empty())
    throw ReportError("missing shard(s) " + missing + " of " + std::to_string(shards_) + " (got " +
                      std::to_string(seen_.size()) + ")");
  SuiteResult r = std::move(merged_);
  merged_ = SuiteResult();
  std::sort(r.cases.begin(), r.cases.end(),
            [](const CaseRecord& a, const CaseRecord& b) { return a.index < b.index; });
  r.settings.shard = 1;
  r.settings.shards = 1;
  r.casesPerSecond = r.seconds > 0.0 ? static_cast<double>(r.cases.size()) / r.seconds : 0.0;
  r.isolatedCasesPerSecond = r.isolatedSeconds > 0.0 ? r.isolatedCases / r.isolatedSeconds : 0.0;
  return r;
}

}  // namespace particles::compare
