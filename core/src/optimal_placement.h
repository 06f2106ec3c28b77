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

#include "optimal_point.h"
#include "placement.h"

namespace ruppert::detail {

class OptimalPlacement {
 public:
  enum class Result {
    Found,      // target and loc hold a point whose new triangles all meet the bound
    FirstFine,  // the first choice can be inserted and makes no skinny triangle: use it
    None,       // no point found meets the bound
  };
  explicit OptimalPlacement(double theta) : theta_(theta) {}

  // st.first is the first choice (it may lie beyond a subsegment; st.firstCavity is not used), cc
  // the triangle's circumcenter.
  Result propose(const MeshAccess& mesh, const SkinnyTriangle& st, const double* cc, double target[2], Location& loc);

  // Where vertex v (an interior vertex with a closed fan of triangles and no subsegment among their
  // edges) can move so that every triangle of its star meets the bound, the point maximising the
  // star's smallest angle: into x, and star() then holds the star's outer half-edges. False if v's
  // fan is not such a fan or no point of its kernel meets the bound.
  bool relocation(const MeshAccess& mesh, std::uint32_t v, double x[2]);
  const std::vector<std::uint32_t>& star() const { return star_; }

  // After propose() returned FirstFine or None with the mesh unchanged since: whether the first
  // choice fitted (no subsegment in the way, none encroached, not too close to a vertex), and then
  // its location and cavity, swapped into tris and boundary, so the insertion need not find them
  // again. Each propose() answers once; forget() drops an answer no insertion will use.
  bool takeFirst(Location& loc, std::vector<std::uint32_t>& tris, std::vector<std::uint32_t>& boundary);
  void forget() { firstFits_ = false; }

 private:
  double theta_;
  std::vector<CavityEdge> edges_;
  std::vector<std::uint32_t> cavity_, candidateTris_, candidateBoundary_, star_;
  bool firstFits_ = false;  // the first choice's location and cavity are in first*_
  Location firstLoc_;
  std::vector<std::uint32_t> firstTris_, firstBoundary_;

  void edgesOf(const Triangulation& t, const std::vector<std::uint32_t>& boundary);
  OptimalPoint pointMeeting(OptimalPointQuery& query, const double* guess, const double* seeds, std::size_t seedCount) const;
  bool fits(const MeshAccess& mesh, std::uint32_t s, const double* x, Location& loc);
  bool closedFreeFan(const Triangulation& t, std::uint32_t v);
};

}  // namespace ruppert::detail
