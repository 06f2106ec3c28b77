// Delaunay triangulation of the distinct input points inside four far-away box corners.
//
// The corners keep every input point strictly inside the triangulation, so insertion never has to
// handle points outside the hull. They are not part of the result: either segments enclose the domain
// (and the corners lie outside it), or the convex hull is inserted as constraints (insertHull), which
// cuts the corners off. Inside the domain the corners are never visible, so they cannot change the
// constrained Delaunay triangulation there.
#include "cdt/build_delaunay.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "mesh_state.h"
#include "cdt/old_mesh.h"
#include "cdt/prepare_input.h"
#include "mesh/predicates.h"

namespace ruppert::detail {

bool refinementRequested(const MeshState& m) {
  const Options& o = *m.options;
  bool regionArea = false;
  for (const Region& r : m.input.regions) regionArea = regionArea || r.maxArea > 0;
  const bool oldMeshArea = m.oldMesh != nullptr && m.oldMesh->hasBounds();
  return o.minAngle > 0 || o.maxAngle > 0 || o.maxArea > 0 || regionArea || oldMeshArea || static_cast<bool>(o.sizeFunction);
}

void buildDelaunay(MeshState& m) {
  PreparedInput& in = m.input;
  const std::uint32_t n = in.distinctCount();
  m.inputCount = n;
  if (n < 3)
    throw Error(ErrorCode::DegenerateInput, "the input has " + std::to_string(n) +
                                                " distinct point(s); at least 3 not on one line are needed");
  // Constrained variant: scaled coordinates lie in (-2, 2); corners at +-8 are exact and the domain
  // never sees them. Bounding-box variant (Ruppert's original): the box is part of what is refined,
  // so it is a square 1.5 times the points' extent around them, as in §6.3.
  double lo[2] = {-8, -8}, hi[2] = {8, 8};
  if (m.options->variant == Variant::BoundingBox) {
    double minX = HUGE_VAL, minY = HUGE_VAL, maxX = -HUGE_VAL, maxY = -HUGE_VAL;
    for (std::uint32_t v = 0; v < n; ++v) {
      minX = std::min(minX, in.xy[2 * v]), maxX = std::max(maxX, in.xy[2 * v]);
      minY = std::min(minY, in.xy[2 * v + 1]), maxY = std::max(maxY, in.xy[2 * v + 1]);
    }
    const double half = 0.75 * std::max(maxX - minX, maxY - minY);
    const double cx = 0.5 * (minX + maxX), cy = 0.5 * (minY + maxY);
    lo[0] = cx - half, lo[1] = cy - half, hi[0] = cx + half, hi[1] = cy + half;
  }
  // Refinement grows from twice the input and the box corners. A plain CDT adds only the corners
  // and its segments' crossings, usually none or few (more still fit: the arrays then grow).
  const std::size_t vertices =
      refinementRequested(m) ? 2 * (std::size_t(n) + 4) + 16 : std::size_t(n) + kCdtExtraVertices;
  // The triangulation takes the prepared coordinates: one copy of the points, not two.
  m.adoptInputPoints(std::move(in.xy), vertices, 2 * vertices + 8);
  m.boxFirst = m.addVertex(lo[0], lo[1], VertexKind::Unused, -1);
  m.addVertex(hi[0], lo[1], VertexKind::Unused, -1);
  m.addVertex(hi[0], hi[1], VertexKind::Unused, -1);
  m.addVertex(lo[0], hi[1], VertexKind::Unused, -1);
  Triangulation& t = m.tri;
  const std::uint32_t c = m.boxFirst;
  const std::uint32_t t0 = t.newTriangle(c, c + 1, c + 2);
  const std::uint32_t t1 = t.newTriangle(c, c + 2, c + 3);
  t.link(3 * t0 + 1, 3 * t1 + 2);  // edge c+2 -> c  and  c -> c+2

  bool allCollinear = true;
  const std::uint32_t p0 = 0, p1 = 1;
  std::uint32_t hint = t0;
  for (std::uint32_t v = 0; v < n; ++v) {  // internal numbering is the insertion order
    // (Points 0 and 1 are on their own line: no need to ask.)
    if (allCollinear && v > p1 && orient2d(t.pt(p0), t.pt(p1), t.pt(v)) != 0) allCollinear = false;
    Location loc = t.locate(t.pt(v), hint);
    if (loc.kind != Location::InTriangle && loc.kind != Location::OnEdge)
      throw Error(ErrorCode::Internal, "point location failed for points[" + std::to_string(in.inputIndex[v]) + "]");
    if (!t.insertVertex(v, loc, nullptr, nullptr, /*checkOrientation=*/false))
      throw Error(ErrorCode::Internal, "could not insert points[" + std::to_string(in.inputIndex[v]) + "]");
    hint = t.vtri[v];
  }
  if (allCollinear)
    throw Error(ErrorCode::DegenerateInput, "all " + std::to_string(n) +
                                                " distinct points lie on one line; there is nothing to triangulate");
}

}  // namespace ruppert::detail
