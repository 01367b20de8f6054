#include "particles/compare/suite_from_json.h"

#include <cmath>
#include <string>

#include "particles/compare/case_generator.h"
#include "particles/compare/suite_report.h"

namespace particles::compare {
namespace {

using nlohmann::json;

// The writer prints NaN (and infinity) as null.
double number(const json& j) {
  return j.is_null() ? std::nan("") : j.get<double>();
}

Outcome outcomeFrom(const json& balls) {
  Outcome o;
  for (const json& b : balls) {
    BodyVelocity v;
    v.velocity = Vec2(number(b.at("velocity").at(0)), number(b.at("velocity").at(1)));
    v.angularVelocity = number(b.at("angular_velocity"));
    o.finite = o.finite && v.velocity.allFinite() && std::isfinite(v.angularVelocity);
    o.balls.push_back(v);
  }
  return o;
}

Discrepancy discrepancyFrom(const json& j) {
  return {number(j.at("velocity")), number(j.at("spin")), number(j.at("relative"))};
}

Invariants invariantsFrom(const json& j) {
  Invariants i;
  i.momentum = number(j.at("momentum"));
  i.angularMomentum = number(j.at("angular_momentum"));
  i.energyChange = number(j.at("energy_change"));
  i.restitution = number(j.at("restitution"));
  i.noSlip = number(j.at("no_slip"));
  i.coulomb = number(j.at("coulomb"));
  i.tangentSign = j.at("tangent_sign_wrong").get<bool>() ? 1.0 : 0.0;
  i.normalImpulse = number(j.at("normal_impulse"));
  i.tangentImpulse = number(j.at("tangent_impulse"));
  return i;
}

Cause causeFrom(const std::string& name) {
  for (Cause c :
       {Cause::Agrees, Cause::OutsideRange, Cause::VelocityIterations, Cause::RestitutionThreshold,
        Cause::MidOverlapContact, Cause::SequentialOrder, Cause::FloatRounding, Cause::Unexplained})
    if (causeName(c) == name) return c;
  throw ReportError("unknown box2d_cause '" + name + "'");
}

// The case with this suite index, as suiteCases(settings) would list it,
// without generating the others.
ImpactCase caseAt(int index, const SuiteSettings& s, const std::vector<ImpactCase>& named) {
  const int catalogueSize = static_cast<int>(named.size());
  if (index < 0) throw ReportError("negative case index");
  if (index < catalogueSize) return named[static_cast<std::size_t>(index)];
  const long long k = index - catalogueSize;
  const long long family = s.casesPerFamily > 0 ? k / s.casesPerFamily : kAllFamilies.size();
  if (family >= static_cast<long long>(kAllFamilies.size()))
    throw ReportError("case index " + std::to_string(index) + " is beyond the suite's " +
                      std::to_string(catalogueSize + kAllFamilies.size() * s.casesPerFamily) +
                      " cases");
  return randomCase(kAllFamilies[static_cast<std::size_t>(family)], s.seed,
                    static_cast<int>(k % s.casesPerFamily), s.generator);
}

CaseRecord recordFrom(const json& j, const SuiteSettings& s, const std::vector<ImpactCase>& named) {
  CaseRecord r;
  r.index = j.at("index").get<int>();
  r.kase = caseAt(r.index, s, named);
  if (r.kase.name != j.at("name").get<std::string>())
    throw ReportError("case " + std::to_string(r.index) + " is '" +
                      j.at("name").get<std::string>() + "' in the report but '" + r.kase.name +
                      "' for these settings in this build of particles");
  r.engine = outcomeFrom(j.at("engine"));
  r.box2d = outcomeFrom(j.at("box2d"));
  if (!j.at("truth").is_null()) r.truth = outcomeFrom(j.at("truth"));
  const json& d = j.at("discrepancy");
  if (!d.at("engine_truth").is_null()) r.engineTruth = discrepancyFrom(d.at("engine_truth"));
  r.engineBox2D = discrepancyFrom(d.at("engine_box2d"));
  r.attribution.discrepancy = discrepancyFrom(d.at("box2d_reference"));
  r.attribution.cause = causeFrom(j.at("box2d_cause").get<std::string>());
  r.attribution.detail = j.at("box2d_detail").get<std::string>();
  const json& inv = j.at("invariants");
  r.engineInvariants = invariantsFrom(inv.at("engine"));
  r.box2dInvariants = invariantsFrom(inv.at("box2d"));
  if (!inv.at("truth").is_null()) r.truthInvariants = invariantsFrom(inv.at("truth"));
  const json& v = j.at("violations");
  r.engineViolations = v.at("engine").get<std::vector<std::string>>();
  r.box2dViolations = v.at("box2d").get<std::vector<std::string>>();
  r.truthViolations = v.at("truth").get<std::vector<std::string>>();
  r.engineOk = j.at("engine_ok").get<bool>();
  r.pass = j.at("pass").get<bool>();
  return r;
}

// Runs `read`, turning nlohmann's errors (a missing key, a wrong type) into
// ReportError naming `where`.
template <typename F>
auto reading(const std::string& where, F read) {
  try {
    return read();
  } catch (const json::exception& e) {
    throw ReportError(where + ": " + e.what());
  } catch (const ReportError& e) {
    throw ReportError(where + ": " + e.what());
  }
}

}  // namespace

SuiteSettings suiteSettingsFromJson(const json& report) {
  return reading("settings", [&] {
    const json& j = report.at("settings");
    SuiteSettings s;
    s.casesPerFamily = j.at("cases_per_family").get<int>();
    s.seed = j.at("seed").get<std::uint64_t>();
    s.box2dVelocityIterations = j.at("box2d_velocity_iterations").get<int>();
    s.box2dPositionIterations = j.at("box2d_position_iterations").get<int>();
    s.mutantCasesPerFamily = j.at("mutant_cases_per_family").get<int>();
    // The tolerances are constants of the build: compare them as suiteJson
    // prints them.
    SuiteResult probe;
    probe.settings = s;
    if (suiteJson(probe, CaseRecords::All).at("settings") != j)
      throw ReportError("the tolerances differ from this build's " +
                        suiteJson(probe, CaseRecords::All)["settings"]["tolerances"].dump());
    return s;
  });
}

std::vector<CaseRecord> caseRecordsFromJson(const json& report, const SuiteSettings& settings) {
  const std::vector<ImpactCase> named = catalogue();
  if (!report.contains("cases") || !report["cases"].is_array())
    throw ReportError("cases: missing, or not an array");
  const json& cases = report["cases"];
  std::vector<CaseRecord> records;
  records.reserve(cases.size());
  for (std::size_t k = 0; k < cases.size(); ++k)
    records.push_back(reading("cases[" + std::to_string(k) + "]",
                              [&] { return recordFrom(cases[k], settings, named); }));
  return records;
}

std::vector<MutantRecord> mutantRecordsFromJson(const json& report) {
  return reading("mutants", [&] {
    std::vector<MutantRecord> mutants;
    for (const json& j : report.at("mutants")) {
      MutantRecord m;
      const std::string name = j.at("mutation").get<std::string>();
      m.mutation = Mutation::None;
      for (Mutation candidate : kAllMutations)
        if (mutationName(candidate) == name) m.mutation = candidate;
      if (m.mutation == Mutation::None) throw ReportError("unknown mutation '" + name + "'");
      m.caught = j.at("caught").get<bool>();
      m.casesRun = j.at("cases_run").get<int>();
      m.caughtBy = j.at("caught_by").get<std::string>();
      m.reason = j.at("reason").get<std::string>();
      mutants.push_back(m);
    }
    return mutants;
  });
}

SuiteResult suiteResultFromJson(const json& report) {
  if (report.value("case_records", std::string()) != "all")
    throw ReportError(
        "case_records: the report holds only the notable case records; the per-family "
        "summaries need all of them (run the suite with --records all)");
  SuiteResult r;
  r.settings = suiteSettingsFromJson(report);
  r.cases = caseRecordsFromJson(report, r.settings);
  r.mutants = mutantRecordsFromJson(report);
  reading("timing", [&] {
    const json& t = report.at("timing");
    r.jobs = t.at("jobs").get<int>();
    r.seconds = t.at("seconds").get<double>();
    r.casesPerSecond = t.at("cases_per_second").get<double>();
    r.isolatedCases = t.at("isolated_cases").get<int>();
    r.isolatedSeconds = t.at("isolated_seconds").get<double>();
    r.isolatedCasesPerSecond = t.at("isolated_cases_per_second").get<double>();
    return 0;
  });
  return r;
}

}  // namespace particles::compare
