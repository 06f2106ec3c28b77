// Placement::Optimal: Erten and Üngör's locally optimal Steiner points (optimal_point.h) on the mesh,
// and their relocation of a free vertex where no new point can meet the bound.
//
// It follows placement.h's scheme with two differences: the refiner asks it before the first choice
// is checked (a first choice that would be rejected for encroaching a subsegment may still have a
// good point beside it), and when it finds no point the refiner may move a vertex instead
// (Refiner::relocate applies what relocation() computes).
#pragma once

#include <cstdint>
#include <vector>

#include "refine/placement/feasible_region.h"
#include "refine/placement/optimal_point.h"
#include "refine/placement/placement.h"

namespace ruppert::detail {

// bestBelowBound's point must beat the first choice's smallest new angle by this much (in sin^2):
// kBelowBoundGain in the second direct attempt, kStrictBelowBoundGain in the third (bound_push.h).
// Over the 300 generated PLCs with the largest skinny triangles first, 0.2 completes 293 at 38
// degrees and 173 at 40, 1.0 completes 280 and 205, the two in turn 296 and 211. (Smallest first,
// at 38 degrees: 278 at 0.1 and 0.2, 266 at 0.35.) On 60 of them at 40 degrees: 0.1: 31, 0.2: 35,
// 0.35: 39, 0.5: 41, 0.75: 42, 1.0: 44, 1.5: 42.
inline constexpr double kBelowBoundGain = 0.2;
inline constexpr double kStrictBelowBoundGain = 1.0;

// Below this bound, a first choice that cannot go in (it encroaches a subsegment, say) is rejected
// as usual, and the subsegment split, rather than searched around. A new vertex on the domain's
// boundary adds one triangle, one inside it two (Euler's formula), and at small bounds the split
// rarely cascades: on the generated families and the corpus, the split makes fewer triangles than
// the search below about 28 degrees and more above (docs/measurements.md, "split before search").
inline constexpr double kSplitBeforeSearchBelowDegrees = 28;

class OptimalPlacement {
 public:
  enum class Result {
    Found,      // target and loc hold a point whose new triangles all meet the bound
    UseFirst,   // the refiner goes on with the first choice: it can be inserted and makes no
                // skinny triangle, or (below kSplitBeforeSearchBelowDegrees) it cannot be
                // inserted, and the refiner rejects it and splits what it encroaches
    None,       // no point found meets the bound
  };
  // gain: bestBelowBound's (kBelowBoundGain or kStrictBelowBoundGain).
  OptimalPlacement(double theta, double gain) : theta_(theta), bound_(theta), gain_(gain) {}
  // Room for a typical cavity in the scratch lists (see kScratchReserve), once per call: only the
  // refiner that uses this placement asks.
  void reserveScratch();

  // st.first is the first choice (it may lie beyond a subsegment; st.firstCavity is not used), cc
  // the triangle's circumcenter.
  Result propose(const MeshAccess& mesh, const SkinnyTriangle& st, const double* cc, double target[2], Location& loc);

  // Where vertex v (an interior vertex with a closed fan of triangles and no subsegment among their
  // edges) can move so that every triangle of its star meets the bound, the point maximising the
  // star's smallest angle: into x, and star() then holds the star's outer half-edges. False if v's
  // fan is not such a fan or no point of its kernel meets the bound.
  bool relocation(const MeshAccess& mesh, std::uint32_t v, double x[2]);
  const std::vector<std::uint32_t>& star() const { return star_; }
  // Whether v has a closed fan of triangles with no subsegment among their edges (at most 64); its
  // outer half-edges are then in star().
  bool freeFan(const Triangulation& t, std::uint32_t v) { return closedFreeFan(t, v); }

  // After propose() returned UseFirst or None with the mesh unchanged since: whether the first
  // choice fitted (no subsegment in the way, none encroached, not too close to a vertex), and then
  // its location and cavity, swapped into tris and boundary, so the insertion need not find them
  // again. Each propose() answers once; forget() drops an answer no insertion will use.
  bool takeFirst(Location& loc, std::vector<std::uint32_t>& tris, std::vector<std::uint32_t>& boundary);
  void forget() { firstFits_ = false; }
  // Right after propose() returned Found, or bestBelowBound() true, with the mesh unchanged since:
  // the point's cavity (fits() left it there), swapped into tris and boundary.
  void takeCandidate(std::vector<std::uint32_t>& tris, std::vector<std::uint32_t>& boundary) {
    tris.swap(candidateTris_), boundary.swap(candidateBoundary_);
  }

  // After propose() returned None with the mesh unchanged since (bound_push.h's bestBelowBound):
  // the point of the last search's cavity that maximises the smallest new angle, below the bound
  // though it is, if it beats the first choice's smallest new angle by the gain in sin^2
  // (any point, where the first choice cannot go in) and no new edge is shorter than st's shortest
  // edge. Into target and loc; false if there is none.
  bool bestBelowBound(const MeshAccess& mesh, const SkinnyTriangle& st, double target[2], Location& loc);

 private:
  double theta_;
  BoundAngle bound_;  // theta_ with its cosine and sine, for the screen
  double gain_;
  std::vector<CavityEdge> edges_;
  std::vector<std::uint32_t> cavity_, candidateTris_, candidateBoundary_, star_;
  bool firstFits_ = false;  // the first choice's location and cavity are in first*_
  Location firstLoc_;
  std::vector<std::uint32_t> firstTris_, firstBoundary_;
  double firstSin2_ = -1;           // sin^2 of the first choice's smallest new angle (-1: it does not fit)
  OptimalPointQuery lastQuery_;     // propose()'s last search (its edges aside) and seeds,
  double lastSeeds_[6] = {};        // for bestBelowBound
  std::size_t lastSeedCount_ = 0;

  void edgesOf(const Triangulation& t, const std::vector<std::uint32_t>& boundary);
  OptimalPoint pointMeeting(OptimalPointQuery& query, const double* guess, const double* seeds, std::size_t seedCount) const;
  bool fits(const MeshAccess& mesh, std::uint32_t s, const double* x, Location& loc, double& minSin2);
  bool closedFreeFan(const Triangulation& t, std::uint32_t v);
};

}  // namespace ruppert::detail
