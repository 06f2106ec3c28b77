// The search for an angle bound that may be out of reach (above kSearchAboveDegrees, §6.8): its
// constants, and the push's tracker of the best mesh.
//
// The 33-degree mesh comes first, for its size, the unit of every cap. Then the requested bound is
// tried directly, from the unrefined mesh, up to sixteen times that size: where it completes that
// way (most inputs at 35 degrees), the mesh is the same as without the search. With the optimal
// placement a second direct attempt follows, which inserts the best point below the bound where the
// first fell back to an off-center (RefinePlan::bestBelowBound), and splits the skinny triangles
// with the longest shortest edge first (RefinePlan::largestFirst), up to 128 times the 33-degree
// mesh's triangles (at most kSecondDirectTriangleCeiling); where that fails too, a third does the
// same with a stricter test for the points below the bound (kStrictBelowBoundGain), and a fourth
// goes smallest first again with the best points below the bound, up to sixteen times. Every
// attempt and the push also slide vertices along segments (RefinePlan::slide). Last, the push: from
// the 33-degree mesh, raise the bound a degree at a time while the mesh keeps improving, and keep
// the best mesh seen, so that it, not a runaway's last state, is the result. docs/measurements.md
// ("The size of meshes above 34 degrees") has what each part gains.
#pragma once

#include <algorithm>
#include <cstdint>

#include "refine/loop_control.h"
#include "ruppert/ruppert.h"

namespace ruppert::detail {

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
// time: a miss on the corpus's largest, p2t_debug2.poly, runs tens of seconds). Where the cap would
// be under kLargestFirstLeast times, the attempt is skipped. docs/measurements.md has the caps tried.
inline constexpr std::uint64_t kSecondDirectTriangleFactor = 128;
inline constexpr std::uint64_t kSecondDirectTriangleCeiling = std::uint64_t(1) << 19;
inline constexpr std::uint64_t kLargestFirstLeast = 2;
// A direct attempt that completes within this many times the 33-degree mesh's triangles ends the
// search; a larger one is kept only until a later attempt, capped at its size, completes smaller.
inline constexpr double kDirectEnoughFactor = 1.5;

// Whether a search gets the second to fourth direct attempts (RefinePlan::bestBelowBound): only
// where their placement applies, the optimal one without an area bound (refine_split.cpp).
inline bool secondDirectAttempt(const Options& o) { return o.placement == Placement::Optimal && !(o.maxArea > 0); }
inline int directAttempts(const Options& o) { return secondDirectAttempt(o) ? 4 : 1; }

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
