// Delaunay triangulation of the distinct input points inside four far-away box corners.
//
// The corners keep every input point strictly inside the triangulation, so insertion never has to
// handle points outside the hull. They are not part of the result: either segments enclose the domain
// (and the corners lie outside it), or the convex hull is inserted as constraints (insertHull), which
// cuts the corners off. Inside the domain the corners are never visible, so they cannot change the
// constrained Delaunay triangulation there.
#include <algorithm>
#include <string>

#include "mesh_state.h"
#include "predicates.h"

namespace ruppert::detail {

void buildDelaunay(MeshState& m) {
  const PreparedInput& in = m.input;
  const std::uint32_t n = static_cast<std::uint32_t>(in.xy.size() / 2);
  m.inputCount = n;
  m.tri.xy.reserve(2 * (n + 4));
  for (std::uint32_t i = 0; i < n; ++i) {
    const bool used = in.representative[i] == i;
    m.addVertex(in.xy[2 * i], in.xy[2 * i + 1], used ? VertexKind::Input : VertexKind::Unused, -1);
  }
  if (in.insertionOrder.size() < 3)
    throw Error(ErrorCode::DegenerateInput, "the input has " + std::to_string(in.insertionOrder.size()) +
                                                " distinct point(s); at least 3 not on one line are needed");
  // Scaled coordinates lie in (-2, 2); corners at +-8 are exact and far enough away that no
  // circumcircle of input points reaches past them in a way that matters (they are cut off anyway).
  m.boxFirst = m.addVertex(-8, -8, VertexKind::Unused, -1);
  m.addVertex(8, -8, VertexKind::Unused, -1);
  m.addVertex(8, 8, VertexKind::Unused, -1);
  m.addVertex(-8, 8, VertexKind::Unused, -1);
  Triangulation& t = m.tri;
  const std::uint32_t c = m.boxFirst;
  for (auto* v : {&t.tv, &t.twin}) v->reserve(3 * (2 * std::size_t(n) + 8));
  t.con.reserve(3 * (2 * std::size_t(n) + 8));
  const std::uint32_t t0 = t.newTriangle(c, c + 1, c + 2);
  const std::uint32_t t1 = t.newTriangle(c, c + 2, c + 3);
  t.link(3 * t0 + 1, 3 * t1 + 2);  // edge c+2 -> c  and  c -> c+2

  bool allCollinear = true;
  const std::uint32_t p0 = in.insertionOrder[0], p1 = in.insertionOrder[1];
  std::uint32_t hint = t0;
  for (std::uint32_t v : in.insertionOrder) {
    if (allCollinear && orient2d(t.pt(p0), t.pt(p1), t.pt(v)) != 0) allCollinear = false;
    Location loc = t.locate(t.pt(v), hint);
    if (loc.kind != Location::InTriangle && loc.kind != Location::OnEdge)
      throw Error(ErrorCode::Internal, "point location failed for points[" + std::to_string(v) + "]");
    if (!t.insertVertex(v, loc, nullptr, nullptr, /*checkOrientation=*/false))
      throw Error(ErrorCode::Internal, "could not insert points[" + std::to_string(v) + "]");
    hint = t.vtri[v];
  }
  if (allCollinear)
    throw Error(ErrorCode::DegenerateInput, "all " + std::to_string(in.insertionOrder.size()) +
                                                " distinct points lie on one line; there is nothing to triangulate");
}

}  // namespace ruppert::detail
