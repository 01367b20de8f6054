// Reading report.json back into the SuiteResult it was written from, so that
// suiteJson and suiteMarkdown print it again byte for byte: `particles merge`
// rebuilds one result from shard reports and writes it with the same code as
// a single run (docs/report-format.md, "Shards and merging").
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "particles/compare/suite.h"

namespace particles::compare {

// A report that cannot be read back; what() says which key and why.
class ReportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "settings": the case count, seed and iteration counts. The tolerances must
// be this build's: a report judged with others cannot be re-summarised.
// `mutants` is true; shard and shards are 1.
SuiteSettings suiteSettingsFromJson(const nlohmann::json& report);

// "cases", in file order. Each record's ImpactCase is regenerated from the
// settings and its index (catalogue, or randomCase of its family), and must
// bear the record's name; everything else is read from the record, a null
// number as NaN (what the writer turns into null).
std::vector<CaseRecord> caseRecordsFromJson(const nlohmann::json& report,
                                            const SuiteSettings& settings);

// "mutants", in file order.
std::vector<MutantRecord> mutantRecordsFromJson(const nlohmann::json& report);

// All of the above plus "timing". Throws ReportError unless "case_records" is
// "all": summaries cannot be recomputed from the notable records alone.
SuiteResult suiteResultFromJson(const nlohmann::json& report);

}  // namespace particles::compare
