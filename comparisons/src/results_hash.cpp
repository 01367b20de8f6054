#include "particles/compare/results_hash.h"

#include <algorithm>
#include <vector>

#include "particles/state_hash.h"

namespace particles::compare {
namespace {

void addOutcome(StateHasher& h, char tag, const Outcome& o) {
  h.addByte(static_cast<std::uint8_t>(tag));
  for (const BodyVelocity& b : o.balls) {
    h.addDouble(b.velocity.x());
    h.addDouble(b.velocity.y());
    h.addDouble(b.angularVelocity);
  }
}

}  // namespace

std::uint64_t resultsHash(const SuiteResult& result) {
  // Suite order, so that a report merged from shards hashes as one run.
  std::vector<const CaseRecord*> order;
  order.reserve(result.cases.size());
  for (const CaseRecord& r : result.cases) order.push_back(&r);
  std::stable_sort(order.begin(), order.end(),
                   [](const CaseRecord* a, const CaseRecord* b) { return a->index < b->index; });

  StateHasher h;
  for (const CaseRecord* r : order) {
    h.addU64(static_cast<std::uint64_t>(r->index));
    addOutcome(h, 'E', r->engine);
    addOutcome(h, 'B', r->box2d);
    if (r->truth)
      addOutcome(h, 'T', *r->truth);
    else
      h.addByte('N');
    h.addByte(r->pass ? 1 : 0);
  }
  return h.value();
}

}  // namespace particles::compare
