// The classify stage (classify.cpp): which triangles form the domain (§6.7), their regions'
// attributes and area bounds, and the removal of the rest.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh_state.h"

namespace ruppert::detail {

// Which triangles are outside the domain (findDomain), before anything is removed.
struct Domain {
  std::vector<std::uint8_t> outside;         // per slot: 1 outside the domain (exterior, holes), else 0
  bool segmentsEncloseNothing = false;       // no triangle is enclosed, before the holes (once the
                                             // hull stands in: what the first call found)
  std::int64_t emptiedBy = -1;               // the hole seed that removed the last triangle, or -1
  std::size_t noticesBefore = 0;             // MeshState::notices' size when findDomain began
  // Nothing to mesh: the pipeline then meshes the convex hull instead, where it can.
  bool empty() const { return segmentsEncloseNothing || emptiedBy >= 0; }
};
// Exterior, then holes. `hullStandsIn`: the convex hull was inserted because a first call found
// the domain empty (the holes then apply even to an empty domain).
Domain findDomain(MeshState& m, bool hullStandsIn = false);
void classifyTriangles(MeshState& m, const Domain& domain);  // inDomain; regions' attributes and areas;
                                                             // throws EmptyDomain if a hole took all
void removeOutside(MeshState& m);          // drop the triangles outside the domain (and the box corners)

}  // namespace ruppert::detail
