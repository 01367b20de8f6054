// The suite's reports: report.json (everything, schema in
// docs/report-format.md) and report.md (a summary table per family and the
// mutant catch rate).
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "particles/compare/suite.h"

namespace particles::compare {

// Per-family figures, as shown in report.md.
struct FamilySummary {
  Family family = Family::NoSlip;
  int cases = 0;
  int failed = 0;
  // Engine against the closed form (isolated cases; NaN when none).
  double engineWorstV = 0, engineMedianV = 0, engineWorstW = 0, engineMedianW = 0;
  // Box2D against the reference answer (truth, else engine).
  double box2dWorstV = 0, box2dMedianV = 0, box2dWorstW = 0, box2dMedianW = 0;
  int engineViolations = 0, box2dViolations = 0, truthViolations = 0;  // cases with any
  std::map<std::string, int> causes;                                   // cause name -> cases
  int unexplained = 0;
};

std::vector<FamilySummary> summarise(const SuiteResult& result);

// Which per-case records report.json holds: all of them, or only the
// catalogue and every case that failed or needed an attribution.
enum class CaseRecords { All, Notable };

nlohmann::json suiteJson(const SuiteResult& result, CaseRecords records);
std::string suiteMarkdown(const SuiteResult& result);

// Writes DIR/report.json and DIR/report.md, creating DIR.
void writeSuiteReport(const SuiteResult& result, const std::filesystem::path& dir,
                      CaseRecords records);

}  // namespace particles::compare
