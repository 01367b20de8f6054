#include "initial_overlaps.h"

#include <cstdio>

#include "particles/broad_phase.h"
#include "particles/scenefile.h"

namespace particles::scenefile {
namespace {

std::string metres(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

std::string ballName(int i) {
  return "balls[" + std::to_string(i) + "]";
}

}  // namespace

void checkInitialOverlaps(const SceneDef& scene, const std::vector<std::string>& wallNames,
                          const std::string& file) {
  std::vector<Vec2> position;
  std::vector<double> radius;
  for (const BallDef& b : scene.balls) {
    position.push_back(b.position);
    radius.push_back(b.radius);
  }

  // The finders report touching within a 1e-9 slop; the tolerance is ours.
  std::vector<BallPair> pairs;
  Vec2 lo = position.front(), hi = position.front();
  for (const Vec2& x : position) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  if ((hi - lo).allFinite()) {
    BroadPhase grid;
    grid.findPairs(position, radius, pairs);
  } else {
    // The grid cannot size its cells when the extent overflows a double.
    findPairsBruteForce(position, radius, pairs);
  }
  for (const BallPair& p : pairs) {
    if (p.overlap > kInitialOverlapTolerance * (radius[p.a] + radius[p.b]))
      throw SceneError(file, ballName(p.b),
                       "overlaps " + ballName(p.a) + " by " + metres(p.overlap) +
                           " m at t = 0 (tolerance 1e-9 of the radii sum)");
  }

  std::vector<WallHit> hits;
  findWallHits(position, radius, scene.walls, hits);
  for (const WallHit& h : hits) {
    if (h.overlap > kInitialOverlapTolerance * radius[h.ball])
      throw SceneError(file, ballName(h.ball),
                       "overlaps " + wallNames[h.wall] + " by " + metres(h.overlap) +
                           " m at t = 0 (its centre is closer to the wall than its radius; "
                           "tolerance 1e-9 of the radius)");
  }
}

}  // namespace particles::scenefile
