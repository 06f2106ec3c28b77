// Refinement toward an angle bound that may be out of reach (above ~34 degrees, §6.8): meet a bound
// that completes first, then raise it a degree at a time while the mesh keeps improving, and keep
// track of the best mesh seen so that it, not a runaway's last state, is what the caller gets.
//
// Before that, the requested bound is tried directly, from the unrefined mesh, up to sixteen times the
// 33-degree mesh's triangles: where it completes that way (most inputs at 35 degrees), the mesh is
// the same as without stages. With the optimal placement a second direct attempt follows, which
// inserts the best point below the bound where the first fell back to an off-center
// (RefinePlan::bestBelowBound: 38 degrees on 278 of 300 generated PLCs against 226 without it), and
// splits the skinny triangles with the longest shortest edge first (RefinePlan::largestFirst),
// up to 128 times the 33-degree mesh's triangles (at most kSecondDirectTriangleCeiling); where that
// fails too, a third does the same with a stricter test for the points below the bound
// (kStrictBelowBoundGain), and a fourth goes smallest first again with the best points below the
// bound, up to sixteen times (the second attempt before largest first). Every attempt and the push
// also slide vertices along segments (RefinePlan::slide). Over the 300 generated PLCs at 38 / 40
// degrees: 278 / 14 complete with the first attempt and the fourth alone, 299 / 211 with the four,
// 300 / 272 with sliding too.
// The push keeps a copy of its best mesh; the mesh is scored every quarter of its size in
// insertions, so scores and copies cost a fraction of the refinement.
#pragma once

#include <algorithm>
#include <cstdint>

#include "ruppert/ruppert.h"

namespace ruppert::detail {

// Requests above this many degrees are refined in stages; below it directly (as always).
inline constexpr double kStagedAboveDegrees = 34;
// The first stage's bound: refinement completes at it on every input we have measured (§6.8).
inline constexpr double kReachableDegrees = 33;
inline constexpr double kStageStepDegrees = 1;
// The push stops once the mesh has this many times the first stage's triangles, and the direct try
// at the requested bound once it has kDirectTriangleFactor times (a direct run that completes may
// be larger: earcut_earcut.poly completes at 35 degrees with 6.1 times the 33-degree triangles).
inline constexpr std::uint64_t kPushTriangleFactor = 4;
inline constexpr std::uint64_t kDirectTriangleFactor = 16;
// The second and third direct attempts' cap (the fourth's is the first's): this many times the
// 33-degree mesh's triangles, but no more than the ceiling (memory: about 200 bytes a triangle;
// time: on the corpus's largest, p2t_debug2.poly, a miss at 40 degrees took 48 s with a ceiling of
// 2^21 and 21.5 s with 2^19, 24.7 s before these attempts). Measured before sliding
// (RefinePlan::slide), on 60 generated PLCs at 40 degrees: 128 times completed 35 where 16 completed
// 18 and 64 completed 30; 256 no more. Where the cap would be under kLargestFirstLeast times, the
// attempt is skipped.
inline constexpr std::uint64_t kSecondDirectTriangleFactor = 128;
inline constexpr std::uint64_t kSecondDirectTriangleCeiling = std::uint64_t(1) << 19;
inline constexpr std::uint64_t kLargestFirstLeast = 2;
// A direct attempt that completes within this many times the 33-degree mesh's triangles ends the
// search; a larger one is kept only until a later attempt, capped at its size, completes smaller.
inline constexpr double kDirectEnoughFactor = 1.5;

// How one run proceeds.
struct RefinePlan {
  double requested = 0;  // degrees: the bound asked for (Options::minAngle)
  double first = 0;      // degrees: the first stage's bound (== requested: one stage)
  bool track = false;    // push: raise the bound stage by stage, keep the best mesh, stop on a stall
  std::uint64_t triangleCap = 0;  // stop once the mesh has more triangles (0: no cap)
  std::uint64_t used = 0;         // steps (insertions, moves) an earlier run already took (budget)
  // The request's Steiner budget in steps, this run's being budget - used; kAutoSteinerBudget:
  // the automatic one, a checkpoint for the size measure's guard (refine_setup.h), not a stop.
  std::uint64_t budget = kAutoSteinerBudget;
  // Replaying the first `budget` steps of a longer run (staged.cpp): at the budget the mesh as it
  // stands, not the push's best mesh so far.
  bool prefix = false;
  // Optimal placement, where no point meets the bound: first try moving any free vertex of the
  // skinny triangle (not only its shortest edge's), and where nothing helps insert the best point
  // below the bound (OptimalPlacement::bestBelowBound) rather than the off-center. Only above
  // kReachableDegrees, for the second to fourth direct attempts (staged.cpp's directPlan).
  bool bestBelowBound = false;
  // Split the skinny triangles with the longest shortest edge first (BadTriangleQueue). Above
  // kReachableDegrees, smallest-first grading leaves small features inside cavities of triangles
  // many times larger, where no point meets the bound; largest-first refines the surroundings first
  // (at 40 degrees, with bestBelowBound: 18 of 60 generated PLCs complete against 3; without it, 3).
  // Below, it makes more triangles (cloud-2 at 33 degrees: 5,380 against 4,584).
  bool largestFirst = false;
  // bestBelowBound's required gain over the off-center (optimal_placement.h).
  double belowBoundGain = 0;
  // Optimal placement: try sliding an endpoint of the shortest edge that lies on a segment along it
  // (segment_slide.h), before the search with slideFirst, else where no point meets the bound and
  // before moving a free vertex. At every bound: added for the
  // bounds above kStagedAboveDegrees, it makes fewer triangles below them too (the 300 generated
  // PLCs against Triangle's: 0.942 -> 0.940 at 20 degrees, 0.863 -> 0.834 at 30, 0.761 -> 0.725 at
  // 33, no family more), and 13-23% fewer in thin strips between parallel segments, which midpoint
  // splits on both sides fill with right triangles (combs of 5 to 40 teeth 0.8 long at 30 degrees;
  // 40 teeth 1/79 wide: 5,326 -> 4,083, Triangle 4,543). Instructions per mesh: -0.2% to +1.7% on
  // six corpus and family PLCs, 5-10% more on combs for their fewer triangles.
  bool slide = true;
  // Slide before looking for an optimal point, not after (at bounds up to kStagedAboveDegrees, see
  // direct()): a move where it works rather than a new vertex. The 300 generated PLCs against
  // Triangle's: 0.940 -> 0.921 at 20 degrees, 0.901 -> 0.879 at 25, 0.834 -> 0.830 at 30, 0.725 ->
  // 0.720 at 33 (no PLC more at 20-30, two at 33 by 2-3 triangles); instructions per mesh -4.5% to
  // +0.3% on seven corpus and family PLCs. Above 34 degrees the direct attempts slide after the
  // search, as before: sliding first there, 269 of the 300 completed 40 degrees instead of 272.
  bool slideFirst = false;
  // The push's promise (ruppert.h: never over four times the 33-degree mesh's triangles), counted
  // in the domain only: the bounding-box variant's triangles outside it, which triangleCap counts
  // too, leave the mesh. A scored mesh over it is never the result, and the push stops (0: none).
  std::uint64_t domainCap = 0;

  static RefinePlan direct(double degrees, std::uint64_t budget = kAutoSteinerBudget) {
    RefinePlan plan;
    plan.requested = plan.first = degrees;
    plan.budget = budget;
    plan.slideFirst = !(degrees > kStagedAboveDegrees);
    return plan;
  }
};

// Whether a staged request gets the second to fourth direct attempts (RefinePlan::bestBelowBound):
// only where their placement applies, the optimal one without an area bound (refine_split.cpp).
inline bool secondDirectAttempt(const Options& o) { return o.placement == Placement::Optimal && !(o.maxArea > 0); }
inline int directAttempts(const Options& o) { return secondDirectAttempt(o) ? 4 : 1; }

// One look at the whole mesh.
struct MeshScore {
  double minSin2 = 1;               // smallest sin^2 angle over triangles not exempt (§6.6)
  std::uint64_t belowRequested = 0; // non-exempt triangles below the requested bound
  std::uint64_t belowStage = 0;     // ... below the current stage's bound
  std::uint64_t large = 0;          // triangles over their area bound
  std::uint64_t triangles = 0;
  std::uint64_t domainTriangles = 0;  // those inside the domain (all but the box variant's outside)
};

// Best-so-far and stall detection over the scores of a push.
class PushTracker {
 public:
  // Called with every score; `step` = insertions so far. True: this is the best mesh so far.
  bool observe(const MeshScore& s, std::uint64_t step) {
    if (s.belowStage < stageLeast_) stageLeast_ = s.belowStage, stageProgressAt_ = step;
    if (s.large != 0 || (haveBest_ && !better(s, best_))) return false;
    best_ = s, bestStep_ = step, haveBest_ = true;
    return true;
  }
  // A new stage starts at `step` (its bad triangles are counted afresh).
  void newStage(std::uint64_t step) { stageLeast_ = UINT64_MAX, stageProgressAt_ = step; }
  // Once the first stage is complete: its size sets the push's patience, the insertions a stage may
  // make without reducing its bad triangles.
  void setBase(std::uint64_t triangles) { patience_ = std::max<std::uint64_t>(4096, triangles / 2); }
  bool stalled(std::uint64_t step) const { return patience_ && step - stageProgressAt_ > patience_; }
  bool haveBest() const { return haveBest_; }
  std::uint64_t bestStep() const { return bestStep_; }
  const MeshScore& best() const { return best_; }

 private:
  static bool better(const MeshScore& a, const MeshScore& b) {
    if (a.minSin2 > b.minSin2 * (1 + 1e-9)) return true;
    if (a.minSin2 < b.minSin2 * (1 - 1e-9)) return false;
    return a.belowRequested < b.belowRequested;
  }
  MeshScore best_;
  bool haveBest_ = false;
  std::uint64_t bestStep_ = 0, stageLeast_ = UINT64_MAX, stageProgressAt_ = 0, patience_ = 0;
};

}  // namespace ruppert::detail
