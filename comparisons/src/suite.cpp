#include "particles/compare/suite.h"

#include <algorithm>
#include <chrono>
#include <sstream>
#include <thread>

namespace particles::compare {
namespace {

reference::Box2DSettings box2dSettingsFor(const ImpactCase& c, const SuiteSettings& s) {
  reference::Box2DSettings b = reference::Box2DSettings::forScene(c.scene);
  b.velocityIterations = s.box2dVelocityIterations;
  b.positionIterations = s.box2dPositionIterations;
  return b;
}

// Why the engine's answer to a case is wrong, or "" when it is right: the
// judgement both the suite and the mutation check use.
std::string engineVerdict(const ImpactCase& c, const Outcome& engine, const Invariants& invariants,
                          const std::optional<Outcome>& truth,
                          std::vector<std::string>* violations = nullptr) {
  if (!engine.finite) return "non-finite velocities";
  std::vector<std::string> broken = violatedInvariants(invariants, toleranceFor(Source::Engine));
  if (violations) *violations = broken;
  if (truth) {
    const Discrepancy d = measureDiscrepancy(c, engine, *truth);
    if (d.relative > kDoubleTolerance) {
      std::ostringstream s;
      s << "differs from the closed form by " << d.relative << " (relative)";
      return s.str();
    }
  }
  if (!broken.empty()) return "breaks " + broken.front();
  return "";
}

}  // namespace

int SuiteResult::failed() const {
  return static_cast<int>(
      std::count_if(cases.begin(), cases.end(), [](const CaseRecord& r) { return !r.pass; }));
}

int SuiteResult::unexplained() const {
  return static_cast<int>(std::count_if(cases.begin(), cases.end(), [](const CaseRecord& r) {
    return r.attribution.cause == Cause::Unexplained;
  }));
}

double SuiteResult::mutantCatchRate() const {
  if (mutants.empty()) return 1.0;
  const auto caught =
      std::count_if(mutants.begin(), mutants.end(), [](const MutantRecord& m) { return m.caught; });
  return static_cast<double>(caught) / static_cast<double>(mutants.size());
}

std::vector<ImpactCase> suiteCases(const SuiteSettings& settings) {
  std::vector<ImpactCase> cases = catalogue();
  for (Family f : kAllFamilies)
    for (int i = 0; i < settings.casesPerFamily; ++i)
      cases.push_back(randomCase(f, settings.seed, i, settings.generator));
  return cases;
}

bool inShard(int index, const SuiteSettings& settings) {
  return index % settings.shards == settings.shard - 1;
}

CaseRecord evaluateCase(const ImpactCase& c, const SuiteSettings& settings) {
  CaseRecord r;
  r.kase = c;
  const reference::Box2DSettings b2 = box2dSettingsFor(c, settings);
  r.engine = runEngine(c);
  r.box2d = runBox2D(c, b2);
  r.truth = runTruth(c);

  r.box2dInvariants = measureInvariants(c, r.box2d);
  r.box2dViolations = violatedInvariants(r.box2dInvariants, toleranceFor(Source::Box2D));
  r.engineInvariants = measureInvariants(c, r.engine);
  const std::string verdict =
      engineVerdict(c, r.engine, r.engineInvariants, r.truth, &r.engineViolations);
  r.engineOk = verdict.empty();
  if (r.truth) {
    r.engineTruth = measureDiscrepancy(c, r.engine, *r.truth);
    r.truthInvariants = measureInvariants(c, *r.truth);
    r.truthViolations = violatedInvariants(*r.truthInvariants, toleranceFor(Source::Truth));
  }
  r.engineBox2D = measureDiscrepancy(c, r.engine, r.box2d);
  r.attribution = attributeBox2D(c, r.truth ? *r.truth : r.engine, r.box2d, b2);
  r.pass = r.engineOk && r.truthViolations.empty() && r.attribution.cause != Cause::Unexplained;
  return r;
}

void parallelFor(int count, int jobs, const std::function<void(int)>& fn, std::atomic<int>* done,
                 int block) {
  // Contiguous blocks handed out in order: cheap, and slot i is always
  // written by exactly one call fn(i), whichever thread runs it.
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int start; (start = next.fetch_add(block)) < count;) {
      const int end = std::min(count, start + block);
      for (int i = start; i < end; ++i) fn(i);
      if (done) done->fetch_add(end - start);
    }
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < jobs; ++t) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
}

SuiteResult runSuite(const SuiteSettings& settings, const std::function<void(int, int)>& progress) {
  SuiteResult result;
  result.settings = settings;
  result.jobs = settings.jobs > 0
                    ? settings.jobs
                    : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const std::vector<ImpactCase> cases = suiteCases(settings);
  // This shard's cases by suite index: all of them unless sharded.
  std::vector<int> mine;
  for (int i = 0; i < static_cast<int>(cases.size()); ++i)
    if (inShard(i, settings)) mine.push_back(i);
  const int total = static_cast<int>(mine.size());
  result.cases.resize(mine.size());

  // Isolated cases first, then the multi-contact ones; every case writes its
  // own slot, so the order of the phases changes no result.
  std::vector<int> order;  // slots, i.e. positions in `mine`
  for (int j = 0; j < total; ++j)
    if (cases[mine[j]].isolated) order.push_back(j);
  result.isolatedCases = static_cast<int>(order.size());
  for (int j = 0; j < total; ++j)
    if (!cases[mine[j]].isolated) order.push_back(j);

  std::atomic<int> done{0};
  const auto t0 = std::chrono::steady_clock::now();
  std::thread runner([&] {
    auto run = [&](int k) {
      const int j = order[k];
      result.cases[j] = evaluateCase(cases[mine[j]], settings);
      result.cases[j].index = mine[j];
    };
    parallelFor(result.isolatedCases, result.jobs, run, &done);
    result.isolatedSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    parallelFor(
        total - result.isolatedCases, result.jobs, [&](int k) { run(result.isolatedCases + k); },
        &done);
    // Timed here, not after the join: the progress loop below sleeps.
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  });
  while (progress && done.load() < total) {
    progress(done.load(), total);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  runner.join();
  if (progress) progress(total, total);
  result.casesPerSecond = result.seconds > 0.0 ? total / result.seconds : 0.0;
  result.isolatedCasesPerSecond =
      result.isolatedSeconds > 0.0 ? result.isolatedCases / result.isolatedSeconds : 0.0;

  // Shard 1 runs the whole mutation check: it depends on the settings only.
  if (settings.mutants && settings.shard == 1) {
    // The mutant's cases: the catalogue, then each family's first cases.
    std::vector<const ImpactCase*> pool;
    for (const ImpactCase& c : cases)
      if (c.name.rfind("catalogue/", 0) == 0) pool.push_back(&c);
    const int perFamily = std::min(settings.casesPerFamily, settings.mutantCasesPerFamily);
    for (std::size_t f = 0; f < kAllFamilies.size(); ++f)
      for (int i = 0; i < perFamily; ++i)
        pool.push_back(&cases[catalogue().size() + f * settings.casesPerFamily + i]);

    result.mutants.resize(kAllMutations.size());
    parallelFor(
        static_cast<int>(kAllMutations.size()), result.jobs,
        [&](int k) {
          MutantRecord& m = result.mutants[k];
          m.mutation = kAllMutations[k];
          for (const ImpactCase* c : pool) {
            ++m.casesRun;
            const Outcome mutated = runEngine(*c, m.mutation);
            m.reason = engineVerdict(*c, mutated, measureInvariants(*c, mutated), runTruth(*c));
            if (!m.reason.empty()) {
              m.caught = true;
              m.caughtBy = c->name;
              return;
            }
          }
        },
        nullptr, 1);
  }
  return result;
}

}  // namespace particles::compare
