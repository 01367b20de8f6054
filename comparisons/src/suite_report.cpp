#include "particles/compare/suite_report.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "particles/compare/results_hash.h"
#include "particles/state_hash.h"

namespace particles::compare {
namespace {

using nlohmann::json;

constexpr const char* kSchema = "particles-suite-report/1";

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

double worst(const std::vector<double>& v) {
  return v.empty() ? std::nan("") : *std::max_element(v.begin(), v.end());
}

// JSON has no NaN; "does not apply" is null.
json number(double x) {
  return std::isfinite(x) ? json(x) : json(nullptr);
}

json outcomeJson(const Outcome& o) {
  json balls = json::array();
  for (const BodyVelocity& b : o.balls)
    balls.push_back({{"velocity", {number(b.velocity.x()), number(b.velocity.y())}},
                     {"angular_velocity", number(b.angularVelocity)}});
  return balls;
}

json discrepancyJson(const Discrepancy& d) {
  return {
      {"velocity", number(d.velocity)}, {"spin", number(d.spin)}, {"relative", number(d.relative)}};
}

json invariantsJson(const Invariants& i) {
  return {{"momentum", number(i.momentum)},
          {"angular_momentum", number(i.angularMomentum)},
          {"energy_change", number(i.energyChange)},
          {"restitution", number(i.restitution)},
          {"no_slip", number(i.noSlip)},
          {"coulomb", number(i.coulomb)},
          {"tangent_sign_wrong", i.tangentSign != 0.0},
          {"normal_impulse", number(i.normalImpulse)},
          {"tangent_impulse", number(i.tangentImpulse)}};
}

json caseJson(const CaseRecord& r) {
  const CaseParams& p = r.kase.params;
  json j = {{"index", r.index},
            {"name", r.kase.name},
            {"family", familyName(r.kase.family)},
            {"isolated", r.kase.isolated},
            {"params",
             {{"mass_ratio", number(p.massRatio)},
              {"radius_ratio", number(p.radiusRatio)},
              {"restitution", number(p.restitution)},
              {"friction", std::isinf(p.friction) ? json("infinite") : number(p.friction)},
              {"impact_angle", number(p.impactAngle)},
              {"speed", number(p.speed)}}},
            {"before", outcomeJson(initialState(r.kase))},
            {"engine", outcomeJson(r.engine)},
            {"box2d", outcomeJson(r.box2d)},
            {"truth", r.truth ? outcomeJson(*r.truth) : json(nullptr)},
            {"discrepancy",
             {{"engine_truth", r.engineTruth ? discrepancyJson(*r.engineTruth) : json(nullptr)},
              {"engine_box2d", discrepancyJson(r.engineBox2D)},
              {"box2d_reference", discrepancyJson(r.attribution.discrepancy)}}},
            {"invariants",
             {{"engine", invariantsJson(r.engineInvariants)},
              {"box2d", invariantsJson(r.box2dInvariants)},
              {"truth", r.truthInvariants ? invariantsJson(*r.truthInvariants) : json(nullptr)}}},
            {"violations",
             {{"engine", r.engineViolations},
              {"box2d", r.box2dViolations},
              {"truth", r.truthViolations}}},
            {"box2d_cause", causeName(r.attribution.cause)},
            {"box2d_detail", r.attribution.detail},
            {"engine_ok", r.engineOk},
            {"pass", r.pass}};
  return j;
}

std::string fmt(double x) {
  if (std::isnan(x)) return "–";
  std::ostringstream s;
  s << std::setprecision(2) << std::scientific << x;
  return s.str();
}

}  // namespace

std::vector<FamilySummary> summarise(const SuiteResult& result) {
  std::vector<FamilySummary> out;
  for (Family f : kAllFamilies) {
    FamilySummary s;
    s.family = f;
    std::vector<double> ev, ew, bv, bw;
    for (const CaseRecord& r : result.cases) {
      if (r.kase.family != f) continue;
      ++s.cases;
      s.failed += !r.pass;
      if (r.engineTruth) {
        ev.push_back(r.engineTruth->velocity);
        ew.push_back(r.engineTruth->spin);
      }
      bv.push_back(r.attribution.discrepancy.velocity);
      bw.push_back(r.attribution.discrepancy.spin);
      s.engineViolations += !r.engineViolations.empty();
      s.box2dViolations += !r.box2dViolations.empty();
      s.truthViolations += !r.truthViolations.empty();
      ++s.causes[std::string(causeName(r.attribution.cause))];
      s.unexplained += r.attribution.cause == Cause::Unexplained;
    }
    s.engineWorstV = worst(ev);
    s.engineMedianV = median(ev);
    s.engineWorstW = worst(ew);
    s.engineMedianW = median(ew);
    s.box2dWorstV = worst(bv);
    s.box2dMedianV = median(bv);
    s.box2dWorstW = worst(bw);
    s.box2dMedianW = median(bw);
    out.push_back(s);
  }
  return out;
}

nlohmann::json suiteJson(const SuiteResult& result, CaseRecords records) {
  const SuiteSettings& st = result.settings;
  json families = json::array();
  for (const FamilySummary& s : summarise(result)) {
    families.push_back({{"family", familyName(s.family)},
                        {"cases", s.cases},
                        {"failed", s.failed},
                        {"engine_truth",
                         {{"worst_velocity", number(s.engineWorstV)},
                          {"median_velocity", number(s.engineMedianV)},
                          {"worst_spin", number(s.engineWorstW)},
                          {"median_spin", number(s.engineMedianW)}}},
                        {"box2d_reference",
                         {{"worst_velocity", number(s.box2dWorstV)},
                          {"median_velocity", number(s.box2dMedianV)},
                          {"worst_spin", number(s.box2dWorstW)},
                          {"median_spin", number(s.box2dMedianW)}}},
                        {"cases_with_violations",
                         {{"engine", s.engineViolations},
                          {"box2d", s.box2dViolations},
                          {"truth", s.truthViolations}}},
                        {"causes", s.causes},
                        {"unexplained", s.unexplained}});
  }
  json mutants = json::array();
  for (const MutantRecord& m : result.mutants)
    mutants.push_back({{"mutation", mutationName(m.mutation)},
                       {"caught", m.caught},
                       {"cases_run", m.casesRun},
                       {"caught_by", m.caughtBy},
                       {"reason", m.reason}});
  json cases = json::array();
  for (const CaseRecord& r : result.cases) {
    const bool notable =
        r.kase.name.rfind("catalogue/", 0) == 0 || !r.pass || r.attribution.cause != Cause::Agrees;
    if (records == CaseRecords::All || notable) cases.push_back(caseJson(r));
  }
  return {{"schema", kSchema},
          {"results_hash", hashHex(resultsHash(result))},  // docs/determinism.md
          {"settings",
           {{"cases_per_family", st.casesPerFamily},
            {"seed", st.seed},
            {"box2d_velocity_iterations", st.box2dVelocityIterations},
            {"box2d_position_iterations", st.box2dPositionIterations},
            {"mutant_cases_per_family", st.mutantCasesPerFamily},
            {"tolerances",
             {{"engine_truth_relative", kDoubleTolerance},
              {"box2d_relative", kBox2DTolerance},
              {"engine_invariants", toleranceFor(Source::Engine).conservation},
              {"box2d_invariants", toleranceFor(Source::Box2D).conservation}}}}},
          {"timing",
           {{"cases", static_cast<int>(result.cases.size())},
            {"jobs", result.jobs},
            {"seconds", result.seconds},
            {"cases_per_second", result.casesPerSecond},
            {"isolated_cases", result.isolatedCases},
            {"isolated_seconds", result.isolatedSeconds},
            {"isolated_cases_per_second", result.isolatedCasesPerSecond}}},
          {"summary",
           {{"passed", result.passed()},
            {"cases", static_cast<int>(result.cases.size())},
            {"failed", result.failed()},
            {"unexplained", result.unexplained()},
            {"mutant_catch_rate", result.mutantCatchRate()}}},
          {"families", families},
          {"mutants", mutants},
          {"case_records", records == CaseRecords::All ? "all" : "notable"},
          {"cases", cases}};
}

std::string suiteMarkdown(const SuiteResult& result) {
  std::ostringstream md;
  md << "# Comparison suite report\n\n";
  md << "Result: **" << (result.passed() ? "PASS" : "FAIL") << "** — " << result.cases.size()
     << " cases (catalogue + " << result.settings.casesPerFamily << " random per family, seed "
     << result.settings.seed << "), " << result.failed() << " failed, " << result.unexplained()
     << " unexplained Box2D discrepancies, mutant catch rate "
     << std::lround(100.0 * result.mutantCatchRate()) << " %.\n\n";
  md << "Speed, end to end (engine, Box2D, closed form, checks and attribution) on " << result.jobs
     << " threads: " << std::lround(result.isolatedCasesPerSecond) << " isolated cases/s ("
     << result.isolatedCases << " cases), " << std::lround(result.casesPerSecond)
     << " cases/s overall, " << std::fixed << std::setprecision(2) << result.seconds << " s.\n\n";
  md << std::defaultfloat;
  md << "Discrepancies are maxima over the bodies of |Δv| (m/s) and |Δω| (rad/s). Engine vs "
        "closed form must stay within "
     << kDoubleTolerance << " relative; Box2D within " << kBox2DTolerance
     << " relative of the closed form (else of the engine) or be attributed to a cause.\n\n";
  md << "| family | cases | failed | engine–truth worst v | median v | worst ω | median ω | "
        "Box2D–ref worst v | median v | worst ω | median ω | violations (engine/Box2D/truth) | "
        "causes | unexplained |\n";
  md << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|---:|\n";
  for (const FamilySummary& s : summarise(result)) {
    std::string causes;
    for (const auto& [name, n] : s.causes) {
      if (name == "agrees") continue;
      causes += (causes.empty() ? "" : ", ") + name + " " + std::to_string(n);
    }
    md << "| " << familyName(s.family) << " | " << s.cases << " | " << s.failed << " | "
       << fmt(s.engineWorstV) << " | " << fmt(s.engineMedianV) << " | " << fmt(s.engineWorstW)
       << " | " << fmt(s.engineMedianW) << " | " << fmt(s.box2dWorstV) << " | "
       << fmt(s.box2dMedianV) << " | " << fmt(s.box2dWorstW) << " | " << fmt(s.box2dMedianW)
       << " | " << s.engineViolations << "/" << s.box2dViolations << "/" << s.truthViolations
       << " | " << (causes.empty() ? "–" : causes) << " | " << s.unexplained << " |\n";
  }
  md << "\n## Mutation check\n\n";
  if (result.mutants.empty()) {
    md << "Not run.\n";
  } else {
    md << "Each mutant is the engine's solver with one sign changed. Caught: "
       << std::lround(100.0 * result.mutantCatchRate()) << " %.\n\n";
    md << "| mutant | caught | after cases | by | what it saw |\n|---|---|---:|---|---|\n";
    for (const MutantRecord& m : result.mutants)
      md << "| " << mutationName(m.mutation) << " | " << (m.caught ? "yes" : "**no**") << " | "
         << m.casesRun << " | " << m.caughtBy << " | " << m.reason << " |\n";
  }
  md << "\n## Cases that failed or are unexplained\n\n";
  int listed = 0;
  for (const CaseRecord& r : result.cases) {
    if (r.pass && r.attribution.cause != Cause::Unexplained) continue;
    if (++listed > 50) {
      md << "- … (see report.json)\n";
      break;
    }
    md << "- `" << r.kase.name << "`: engine " << (r.engineOk ? "ok" : "WRONG") << ", Box2D "
       << causeName(r.attribution.cause) << " — " << r.attribution.detail << "\n";
  }
  if (listed == 0) md << "None.\n";
  return md.str();
}

void writeSuiteReport(const SuiteResult& result, const std::filesystem::path& dir,
                      CaseRecords records) {
  std::filesystem::create_directories(dir);
  std::ofstream js(dir / "report.json");
  std::ofstream md(dir / "report.md");
  if (!js || !md) throw std::runtime_error("cannot write the report in " + dir.string());
  js << suiteJson(result, records).dump(1) << "\n";
  md << suiteMarkdown(result);
}

}  // namespace particles::compare
