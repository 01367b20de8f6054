#include "suite_output.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "cli_common.h"

namespace particles::cli {
namespace {

namespace fs = std::filesystem;

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

}  // namespace

std::string suiteSummaryText(const compare::SuiteResult& result, const fs::path& dir,
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

compare::CaseRecords caseRecordsFor(long long totalCases, const std::string& choice) {
  if (choice == "all") return compare::CaseRecords::All;
  if (choice == "notable") return compare::CaseRecords::Notable;
  return totalCases <= kAllRecordsUpTo ? compare::CaseRecords::All : compare::CaseRecords::Notable;
}

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

void writeReportFiles(const fs::path& dir, const nlohmann::json& json,
                      const std::string& markdown) {
  // As compare::writeSuiteReport writes them.
  std::filesystem::create_directories(dir);
  std::ofstream js(dir / "report.json");
  std::ofstream md(dir / "report.md");
  if (!js || !md) throw std::runtime_error("cannot write the report in " + dir.string());
  js << json.dump(1) << "\n";
  md << markdown;
  if (!js || !md) throw std::runtime_error("error writing the report in " + dir.string());
}

}  // namespace particles::cli
