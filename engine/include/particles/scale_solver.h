// The large-scene path of the step (docs/scale.md): for scenes of at least
// SolverSettings::scaleThreshold balls, World hands its contact, position
// and overlap stages to this solver. Contacts are found once per step with a
// margin, solved as accumulated impulses warm-started from the previous
// step, Gauss-Seidel in vertical strips so that threads can share the strips
// of one parity; the result is bit-identical for every thread count.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "particles/material.h"
#include "particles/scene.h"
#include "particles/thread_pool.h"
#include "particles/types.h"

namespace particles {

struct ImpactEvent;
struct StepStats;

// The World's per-ball arrays, as the solver reads and writes them.
struct ScaleBodies {
  std::span<Vec2> position;            // m
  std::span<Vec2> velocity;            // m/s
  std::span<double> angle;             // rad
  std::span<double> angularVelocity;   // rad/s
  std::span<const double> radius;      // m
  std::span<const double> invMass;     // 1/kg
  std::span<const double> invInertia;  // 1/(kg m^2)
  std::span<const ContactMaterial> material;
  std::span<const Vec2> forcedVelocity;  // m/s, this step's forces; empty = none
  std::span<const WallDef> walls;
  std::span<const ContactMaterial> wallMaterial;
  Vec2 down{0.0, 0.0};       // unit vector along gravity; zero without gravity
  double gravityStep = 0.0;  // m/s, |g| dt: what gravity adds to a velocity in one step
  double dt = 0.0;           // s
  bool spin = false;         // integrate angles
};

class ScaleSolver {
 public:
  // Forgets the previous step's impulses (a new scene).
  void reset();
  // Contacts, positions and overlap removal of one step. `impacts` (when not
  // null) receives the contacts that exchanged an impulse.
  void step(const ScaleBodies& bodies, const SolverSettings& settings, StepStats& stats,
            std::vector<ImpactEvent>* impacts);
  std::size_t memoryBytes() const;

  // One contact row: a ball pair, or a ball and a wall (b < 0). Its balls
  // are their places in motion_, which holds them strip by strip (slotOf_
  // says why), not as the scene numbers them. 72 bytes, what the velocity
  // iterations read and write: the reach is in the row's Pair and the bounce
  // in bounce_ (96 bytes with both and an aligned Vec2; at N = 100,000 the
  // rows are read from memory on every sweep).
  struct Row {
    double nx = 1.0, ny = 0.0;  // unit normal, from a to b
    int a = 0;
    int b = 0;              // ball's place in motion_, or -1 - wall index
    double massN = 0.0;     // kg, 1 / (1/m_a + 1/m_b)
    double massT = 0.0;     // kg, 1 / (1/m_a + 1/m_b + r_a^2/J_a + r_b^2/J_b)
    double friction = 0.0;  // mixed mu
    double target = 0.0;    // m/s, the least normal relative velocity allowed
    double lambdaN = 0.0;   // N s, accumulated normal impulse (>= 0)
    double lambdaT = 0.0;   // N s, accumulated tangential impulse
    Vec2 normal() const { return {nx, ny}; }
  };

  // A row as the overlap removal sees it: 16 bytes instead of a Row's 72.
  // Its balls are numbered in cell order (CellBall).
  struct Pair {
    int a = 0;
    int b = 0;           // ball index (cell order), or -1 - wall index
    double reach = 0.0;  // m
  };

  // A ball in the grid's cell order: cells bottom row first, left to right,
  // and within a cell by y, then x (then scene index). The solver numbers the balls in this
  // order for the whole step, so that its Gauss-Seidel order runs bottom-up
  // whatever the scene's numbering, and balls that touch lie close in memory.
  struct CellBall {
    Vec2 position;  // m; moved by the step, copied back at its end
    double radius;  // m
    int index;      // the ball's index in the scene
  };

  // A ball as the velocity iterations see it, packed in 48 bytes.
  struct Motion {
    Vec2 velocity{0.0, 0.0};       // m/s
    double angularVelocity = 0.0;  // rad/s
    double invMass = 0.0;          // 1/kg
    double invInertia = 0.0;       // 1/(kg m^2)
    double radius = 0.0;           // m, the lever arm
  };

 private:
  // This step's grid: its columns and rows, and the contact margin (m).
  struct Grid {
    int cols = 1;
    int rows = 1;
    double margin = 0.0;
    double cell = 0.0;       // m, a cell's side
    double maxRadius = 0.0;  // m
    double minRadius = 0.0;  // m
    // Whether two balls may close on each other faster than the margin a
    // step: the scene's velocities span more than margin / dt.
    bool fast = false;
  };
  Grid buildGrid(const ScaleBodies& bodies, ThreadPool& pool);
  // fastCells: SolverSettings::scaleFastPairCells; bandRows:
  // SolverSettings::scaleBandRows.
  // soft: also fill separation_ (the soft step's rows).
  void findRows(const ScaleBodies& bodies, ThreadPool& pool, int fastCells, int bandRows,
                bool soft);
  // Rows for fast pairs: each ball's reach beyond touching (m) for the
  // longer search, 0 for a ball that needs none (fastReach_, cell order).
  void findFastReach(const ScaleBodies& bodies, const Grid& grid, int fastCells, int t,
                     ThreadPool& pool);

  // This step's pairs (ball, ball or wall) in (a, b) order, one list per thread
  // (each thread takes its own range of balls). Each list on its own cache
  // line: side by side, every push_back of one thread evicted the other's
  // vector (measured: the pair search of two threads took 0.73 + 0.69 s where
  // one thread took 0.87).
  struct Link {
    int a = 0;
    int b = 0;  // ball index, or -1 - wall index
  };
  struct alignas(64) ThreadLinks {
    std::vector<Link> links;
  };
  std::vector<ThreadLinks> found_;
  std::vector<Row> rows_;    // by strip, then (a, b): each strip band by band
  std::vector<Pair> pairs_;  // rows_'s balls and reach, in the same order
  // Per row, in the same order: the normal relative velocity after the
  // restitution pass (m/s), for a speculative row whose bodies close their
  // gap within the step: -e times the approach they brought. 0: no
  // restitution pass for this row.
  std::vector<double> bounce_;
  // SolverSettings::scaleSequentialImpacts: each thread's rows that pushed
  // this step (a normal impulse before or after the restitution pass), and
  // replayImpacts' scratch (per ball: its node, -1 for none).
  struct alignas(64) ThreadRows {
    std::vector<int> rows;
  };
  std::vector<ThreadRows> impactRows_;
  std::vector<int> impactNode_;
  // Replays the groups of impacts described at scaleSequentialImpacts
  // (scale_impacts.cpp). One thread, after the velocity passes.
  void replayImpacts(const ScaleBodies& bodies);
  int replayedGroups_ = 0, leftGroups_ = 0;  // replayImpacts' counts, this step
  void replayGroup(const ScaleBodies& bodies, const std::vector<int>& rows);
  // The soft step's (SolverSettings::scaleSubsteps), per row in the same
  // order: the gap at the start of the step (m, < 0: overlap), and the
  // impulses the row gave over the whole step (N s; its lambdaN and lambdaT
  // are those of one substep, what the next substep and step start from).
  std::vector<double> separation_, totalN_, totalT_;
  // The soft step's, per ball in motion_'s order: how far it has moved and
  // turned so far in this step (m, rad).
  struct Moved {
    Vec2 by{0.0, 0.0};
    double turned = 0.0;
  };
  std::vector<Moved> moved_;
  // The rows of strip k in band j (ball a's grid row / bandRows) are
  // rows_[blockStart_[k * bands_ + j], blockStart_[k * bands_ + j + 1]).
  int strips_ = 1, bands_ = 1;
  // How many bands apart two rows' bands may be and still share a ball (a
  // row touches its own band's balls and those of the band above, and a
  // fast pair's up to scaleFastPairCells grid rows either way): the lag of
  // the velocity passes' wavefront.
  int bandReach_ = 1;
  std::vector<int> blockStart_;
  // The soft step's: the balls of strip k in band j (ball's grid row /
  // bandRows) are motion_[ballBlockStart_[k * bands_ + j], ballBlockStart_[k
  // * bands_ + j + 1]); ballBlockCount_ counts them per thread (as
  // blockCount_ the rows).
  std::vector<int> ballBlockStart_, ballBlockCount_;
  // The soft step's, per motion_ slot: a substep's share of this step's
  // forces as a velocity (m/s).
  std::vector<Vec2> forceShare_;
  std::vector<int> stripOf_;  // per ball (cell order): its vertical strip
  std::vector<int> bandOf_;   // per ball (cell order): its band (grid row / bandRows)
  // Per grid column its strip, per grid row its band.
  std::vector<int> stripOfColumn_, bandOfRow_;
  std::vector<Motion> motion_;  // per ball, during the velocity iterations, strip by strip
  // Per ball (cell order): its place in motion_. The balls of a strip lie
  // there one after another, each strip's bottom-up in cell order, so that
  // the rows of a strip read one run of balls instead of a piece of every
  // grid row (the cell order runs across the whole grid). At N = 10,000 on
  // one thread the step was faster in 7 of 8 interleaved A/B pairs (median
  // +9 %), on two threads in 3 of 5; at 100,000 no difference showed
  // (docs/scale.md, "Balls strip by strip"). Same results: only where a
  // ball's velocity is kept changes.
  std::vector<int> slotOf_;
  std::vector<int> slotCount_;  // per thread and strip: balls, then where they go
  // Per ball, 1/kg: what the overlap removal reads of the masses, 8 bytes a
  // ball instead of a Motion's 48 (at N = 100,000 it stays in the cache).
  std::vector<double> invMass_;
  // Per ball (cell order): the last overlap pass of this step that moved
  // it, -1 for none. A pass skips the rows whose balls neither the last
  // pass nor this one has moved so far (ScaleSolver::step).
  std::vector<int> movedIn_;
  std::vector<int> slot_;               // per row in (a, b) order: its index in rows_
  std::vector<std::size_t> linkStart_;  // slot_ of thread t: [linkStart_[t], linkStart_[t+1])
  std::vector<int> blockCount_;         // per thread, strip and band: rows, then where they go
  // The last step's accumulated impulses, by the last step's numbering: the
  // rows of ball a are [lastStart_[a], lastStart_[a + 1]), each with its
  // partner (the ball count + w for wall w; warm starts need the same count).
  std::vector<int> lastStart_, lastOther_;
  std::vector<double> lastN_, lastT_;
  std::vector<int> lastOf_;  // per ball: its number in the last step, or -1
  // Grid (counting sort of balls into cells).
  std::vector<int> cellStart_, ballCell_;
  // Per thread and cell: the thread's balls in the cell, then where the
  // first of them goes (the threads share the counting sort).
  std::vector<int> cellCount_;
  std::vector<int> cellOf_;          // per ball (cell order): its cell
  std::vector<CellBall> cellBalls_;  // the balls in cell order
  // Rows for fast pairs: per cell, the box of its balls' velocities (m/s;
  // floats: 16 bytes a cell, and a bound good to 1e-7 of a speed is far
  // inside the margin), the same box grown over the cells beside it in its
  // grid row, and per ball (cell order) its reach for the longer search.
  struct VelocityBox {
    float loX, loY, hiX, hiY;
  };
  std::vector<VelocityBox> cellBox_, rowBox_;
  std::vector<double> fastReach_;
  // Per scene index: the ball's number in this step's and the last step's
  // cell order.
  std::vector<int> numberOf_, lastNumberOf_;
  // Whether the last step left the pile settled (ScaleSolver::step): this
  // step then takes the settle iteration (SolverSettings::scaleSettleIteration).
  bool settled_ = false;
  PoolHandle pool_;
};

}  // namespace particles
