// How one run of the refinement loop proceeds: its bound, its Steiner budget, and the placement's
// choices that the search above kSearchAboveDegrees (bound_search/) varies between its runs.
#pragma once

#include <cstdint>

#include "refine/refine_setup.h"

namespace ruppert::detail {

// Requests above this many degrees go to the bound search (bound_search/); at or below it the loop
// runs once, as asked.
inline constexpr double kSearchAboveDegrees = 34;

struct RefinePlan {
  double requested = 0;  // degrees: the bound asked for (Options::minAngle), the one the result is judged by
  double first = 0;      // degrees: the loop's bound at the start (a control may raise it, loop_control.h)
  std::uint64_t used = 0;  // steps (insertions, moves) an earlier run already took (budget)
  // The request's Steiner budget in steps, this run's being budget - used; kAutoSteinerBudget:
  // the automatic one, a checkpoint for the size measure's guard (refine_setup.h), not a stop.
  std::uint64_t budget = kAutoSteinerBudget;
  // Optimal placement, where no point meets the bound: first try moving any free vertex of the
  // skinny triangle (not only its shortest edge's), and where nothing helps insert the best point
  // below the bound (OptimalPlacement::bestBelowBound) rather than the off-center. Only above
  // kSearchAboveDegrees, for the second to fourth direct attempts (bound_search.cpp's directPlan).
  bool bestBelowBound = false;
  // Split the skinny triangles with the longest shortest edge first (BadTriangleQueue). Above
  // kSearchAboveDegrees, smallest-first grading leaves small features inside cavities of triangles
  // many times larger, where no point meets the bound; largest-first refines the surroundings first
  // (at 40 degrees, with bestBelowBound: 18 of 60 generated PLCs complete against 3; without it, 3).
  // Below, it makes more triangles (cloud-2 at 33 degrees: 5,380 against 4,584).
  bool largestFirst = false;
  // bestBelowBound's required gain over the off-center (optimal_placement.h).
  double belowBoundGain = 0;
  // Optimal placement: try sliding an endpoint of the shortest edge that lies on a segment along it
  // (segment_slide.h), before the search with slideFirst, else where no point meets the bound and
  // before moving a free vertex. At every bound: added for the bounds above kSearchAboveDegrees, it
  // makes fewer triangles below them too, and fewer in thin strips between parallel segments, which
  // midpoint splits on both sides fill with right triangles (docs/measurements.md has the figures).
  bool slide = true;
  // Slide before looking for an optimal point, not after (at bounds up to kSearchAboveDegrees): a
  // move where it works rather than a new vertex. Above them the direct attempts slide after the
  // search: sliding first there completed fewer PLCs at 40 degrees (docs/measurements.md).
  bool slideFirst = false;

  static RefinePlan direct(double degrees, std::uint64_t budget = kAutoSteinerBudget) {
    RefinePlan plan;
    plan.requested = plan.first = degrees;
    plan.budget = budget;
    plan.slideFirst = !(degrees > kSearchAboveDegrees);
    return plan;
  }
};

}  // namespace ruppert::detail
