// Where refinement puts the new vertex that splits a skinny triangle (§6.2, §6.8), and the mesh
// queries a placement may use.
//
// The first choice is always computed by the refiner: the circumcenter, or with Placement::OffCenter
// and Placement::Petal the off-center (refine_geometry.h). When that point is rejected (it would
// encroach a subsegment) the subsegment is split instead. When it passes, a placement may propose a
// better point. Adding a placement:
//   1. a value in ruppert::Placement (ruppert.h, with the CLI's and the bindings' spellings);
//   2. a class here with
//        bool propose(const MeshAccess&, const SkinnyTriangle&, double target[2], Location& loc);
//      returning a point that lies in the skinny triangle's circumcircle (so its insertion destroys
//      it), in a triangle of the mesh (loc, from MeshAccess::walk), encroaches no subsegment on its
//      cavity's boundary and is representable, or false to decline (the first choice is inserted);
//   3. a case in Refiner::improvePlacement (refine_split.cpp) that calls it.
// Placement::Optimal (optimal_placement.h) is asked before the first choice is checked, and may move
// a vertex instead, so the refiner calls it from splitTriangle itself.
#pragma once

#include <cstdint>
#include <vector>

#include "prepared_input.h"
#include "refine/placement/refine_geometry.h"
#include "mesh/triangle_shape.h"
#include "mesh/triangulation.h"

namespace ruppert::detail {

// No vertex is placed closer than this to another (internal units: coordinates lie within (-2, 2),
// where it is over 10^4 ulps): subsegments shorter than 3 floors and triangles whose shortest edge is
// under 2 floors are not split, and a split point this close to a vertex is refused.
inline constexpr double kLengthFloor = 0x1p-38;

// What a new vertex at x would do, from its cavity's boundary (MeshAccess::judgeCavity).
struct CavityVerdict {
  bool tooClose = false;    // a vertex of the boundary lies within the length floor of x
  bool encroaches = false;  // x encroaches a subsegment of the boundary
  double minSin2 = 1;       // the smallest sin^2 angle of the new triangles (1 unless asked for)
};

// Read-only queries on the mesh being refined, with the run's bound and encroachment rule.
class MeshAccess {
 public:
  const Triangulation& tri;
  const PreparedInput& input;
  double sin2Theta;  // sin^2 of the angle bound, slightly lowered against rounding
  double lensCos2;   // encroachment rule, as in encroaches() (0: closed diametral disk)
  // Subsegments carrying segment indices from here on are curve pieces (cdt/curves.h), tested
  // against the closed diametral disk, which holds the sliver between a piece and its curve.
  std::int32_t curveFirst = INT32_MAX;

  MeshAccess(const Triangulation& t, const PreparedInput& in, double sin2, double lens)
      : tri(t), input(in), sin2Theta(sin2), lensCos2(lens) {}

  // Straight walk from the centroid of triangle s towards p. Stops at the first subsegment in the
  // way (blocked = its half-edge), else returns p's location.
  Location walk(std::uint32_t s, const double* p, std::uint32_t& blocked) const;
  // Whether a new vertex at p can be kept exactly (see placement.cpp).
  bool representable(const double* p) const;
  // Whether x encroaches the subsegment or edge h.
  bool encroachesEdge(const double* x, std::uint32_t h) const {
    return encroaches(x, tri.pt(tri.origin(h)), tri.pt(tri.dest(h)), tri.con[h] >= curveFirst ? 0 : lensCos2);
  }
  // Whether a vertex of the cavity boundary lies within the length floor of x (the nearest existing
  // vertex to a new one is always on the boundary of its cavity).
  bool tooCloseToCavity(const double* x, const std::vector<std::uint32_t>& boundary) const;
  // Smallest sin^2 angle among the triangles that inserting x creates, given x's cavity boundary.
  double newMinSin2(const double* x, const std::vector<std::uint32_t>& boundary) const;
  // tooCloseToCavity, encroachment of the boundary's subsegments and (if `quality`) newMinSin2 in
  // one pass over the boundary.
  CavityVerdict judgeCavity(const double* x, const std::vector<std::uint32_t>& boundary, bool quality) const;
};

// The triangle to split, and the first choice of point, which has passed every check.
struct SkinnyTriangle {
  std::uint32_t slot;
  const double* const* p;  // its three corners, counter-clockwise
  TriangleShape shape;
  const double* first;                              // the off-center or circumcenter
  const std::vector<std::uint32_t>* firstCavity;    // boundary half-edges of first's cavity
};

// Locally better Steiner points, in the spirit of Erten and Üngör's: when the first choice would
// itself create a skinny triangle, look in the shortest edge's petal for a point whose new
// triangles all meet the bound, and take the one farthest from its neighbors.
class PetalPlacement {
 public:
  explicit PetalPlacement(double theta);
  bool propose(const MeshAccess& mesh, const SkinnyTriangle& st, double target[2], Location& loc);

 private:
  // Candidate points for a shortest edge from (-1/2, 0) to (1/2, 0) with the triangle above it
  // (scaled and rotated onto the real edge when used), sorted by `bound`, their distance to the
  // nearer endpoint (which no real placement's insertion radius can exceed).
  struct PetalPoint {
    double along, across, bound;
  };
  std::vector<PetalPoint> petal_;
  std::vector<std::uint32_t> candidateTris_, candidateBoundary_;

  bool mayHelp(const MeshAccess& mesh, const SkinnyTriangle& st) const;
};

}  // namespace ruppert::detail
