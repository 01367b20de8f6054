// Merging the reports of a sharded suite (`particles suite --shard K/N`)
// into the result of one run of the same cases (`particles merge`,
// docs/report-format.md "Shards and merging").
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "particles/compare/suite.h"
#include "particles/compare/suite_from_json.h"

namespace particles::compare {

// report.json's "shard" object, which only shard runs carry: {"index": K,
// "count": N}. A report without one is shard 1 of 1.
nlohmann::json shardJson(const SuiteSettings& settings);

// Adds shard reports one at a time (each can be freed after add()), then
// finish() returns the merged result. Every problem is a ReportError whose
// message starts with the shard's name as given to add().
class ShardMerger {
 public:
  // Checks the report (schema, all case records, same settings and shard
  // count as the shards before it, not seen before, exactly its shard's
  // cases, mutants in shard 1 only, and that it reproduces from its own
  // records) and keeps its records.
  void add(const nlohmann::json& report, const std::string& name);

  // The merged result: cases in suite order, shard 1's mutants, timing
  // summed over the shards (seconds, isolated seconds; rates recomputed;
  // jobs the largest). Throws if a shard is missing.
  SuiteResult finish();

  int shards() const { return shards_; }

 private:
  std::optional<nlohmann::json> settingsJson_;
  std::string firstName_;
  int shards_ = 0;
  std::map<int, std::string> seen_;  // shard index -> name
  SuiteResult merged_;
};

}  // namespace particles::compare
