// The comparison suite: every family with N random cases plus the named
// catalogue, each run in the engine, Box2D and (isolated cases) the closed
// form, checked, attributed, and summarised; then the mutation check.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "particles/compare/attribution.h"
#include "particles/compare/case_generator.h"
#include "particles/compare/invariants.h"

namespace particles::compare {

struct SuiteSettings {
  int casesPerFamily = 1000;  // random cases per family, besides the catalogue
  std::uint64_t seed = 1;
  int jobs = 0;  // threads; 0 = all hardware threads
  int box2dVelocityIterations = 8;
  int box2dPositionIterations = 3;
  // Mutation check: each mutant runs the catalogue and up to this many random
  // cases per family until one case catches it.
  int mutantCasesPerFamily = 200;
  bool mutants = true;
  GeneratorSettings generator;
  // Sharding (`particles suite --shard K/N`, docs/cli.md): run only the
  // cases whose suite index i has i % shards == shard - 1, so that N
  // machines share the suite; shard 1 also runs the mutation check. 1 of 1
  // is the whole suite.
  int shard = 1;   // 1..shards
  int shards = 1;  // >= 1
};

// Everything the suite learned about one case.
struct CaseRecord {
  int index = 0;
  ImpactCase kase;
  Outcome engine, box2d;
  std::optional<Outcome> truth;
  std::optional<Discrepancy> engineTruth;  // isolated cases
  Discrepancy engineBox2D;
  Attribution attribution;  // Box2D against the truth where there is one, else the engine
  Invariants engineInvariants, box2dInvariants;
  std::optional<Invariants> truthInvariants;
  std::vector<std::string> engineViolations, box2dViolations, truthViolations;
  bool engineOk = true;  // within kDoubleTolerance of the truth, no invariant broken
  bool pass = true;      // engineOk, the truth sane, and Box2D agrees or is attributed
};

struct MutantRecord {
  Mutation mutation = Mutation::None;
  bool caught = false;
  int casesRun = 0;      // until the first catch
  std::string caughtBy;  // case name
  std::string reason;    // what the case saw
};

struct SuiteResult {
  SuiteSettings settings;
  std::vector<CaseRecord> cases;  // catalogue first, then families in order
  std::vector<MutantRecord> mutants;
  double seconds = 0.0;  // s, wall time of the case runs (not the mutants)
  double casesPerSecond = 0.0;
  // The isolated cases (two bodies, one contact: the design card's headline
  // figure) run first as a phase of their own, timed on their own.
  int isolatedCases = 0;
  double isolatedSeconds = 0.0;  // s
  double isolatedCasesPerSecond = 0.0;
  int jobs = 1;
  int failed() const;
  int unexplained() const;
  double mutantCatchRate() const;  // 1 when there are no mutants
  bool passed() const { return failed() == 0 && mutantCatchRate() == 1.0; }
};

// The case list the suite runs, in order.
std::vector<ImpactCase> suiteCases(const SuiteSettings& settings);

// Whether the case with this suite index belongs to the settings' shard.
bool inShard(int index, const SuiteSettings& settings);

// Runs one case through all sources and judges it.
CaseRecord evaluateCase(const ImpactCase& c, const SuiteSettings& settings);

// Runs `count` jobs over [0, count) on `jobs` threads; fn(i) must only write
// to slot i of its own output, so results never depend on the thread count.
// Work is handed out in contiguous blocks of `block` indices.
void parallelFor(int count, int jobs, const std::function<void(int)>& fn,
                 std::atomic<int>* done = nullptr, int block = 64);

// progress(doneCases, totalCases) is called from the calling thread now and
// then, for a progress bar.
SuiteResult runSuite(const SuiteSettings& settings,
                     const std::function<void(int, int)>& progress = {});

}  // namespace particles::compare
