// What `particles suite` and `particles merge` print and write: the summary
// on stdout and the two report files, so that a merged report comes out of
// the same code as a single run.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "particles/compare/suite.h"
#include "particles/compare/suite_report.h"

namespace particles::cli {

// The per-family table, verdict, speed, catch rate and report paths.
std::string suiteSummaryText(const compare::SuiteResult& result, const std::filesystem::path& dir,
                             compare::CaseRecords records);

// Which records report.json keeps: `choice` ("all", "notable", or "" for the
// default: all up to kAllRecordsUpTo cases in total, notable above).
compare::CaseRecords caseRecordsFor(long long totalCases, const std::string& choice);
inline constexpr long long kAllRecordsUpTo = 100000;  // a record is ~2 kB of JSON

// Creates DIR and checks it can hold files (before any long work); prints
// the error and returns false if not.
bool prepareReportDir(const std::filesystem::path& dir);

// Writes DIR/report.json (`json`, as writeSuiteReport prints it) and
// DIR/report.md. Throws std::runtime_error if they cannot be written.
void writeReportFiles(const std::filesystem::path& dir, const nlohmann::json& json,
                      const std::string& markdown);

}  // namespace particles::cli
