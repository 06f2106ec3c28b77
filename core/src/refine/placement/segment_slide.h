// Sliding a vertex along its segment (RefinePlan::slide, bound_push.h: at every bound): the one-dimensional
// counterpart of Erten and Üngör's relocation of free vertices. A vertex that refinement put on a
// segment splits it into two subsegments; moving it along the segment between their far ends keeps
// both subsegments on the segment and changes only the triangles of its fan. Where midpoint splits
// leave a skinny triangle at a segment that no new point can fix, a better spot along the segment
// often makes every triangle of the fan meet the bound.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/triangulation.h"

namespace ruppert::detail {

// v's fan as the half-edges opposite v (counter-clockwise, open on the mesh boundary or closed)
// into `star`, and v's neighbors along its segment into ends: false unless v lies inside exactly
// one subsegment chain (two constrained edges of the same constraint at v, no other) and its fan has
// at most 64 triangles.
bool segmentVertexFan(const Triangulation& t, std::uint32_t v, std::vector<std::uint32_t>& star, std::uint32_t ends[2]);

// The point of the segment from u to w, at 15% to 85% of the way in steps of 2.5%, at which the fan's
// smallest angle is largest, every triangle staying counter-clockwise and no vertex encroaching a
// subsegment of the fan under the rule of lensCos2 (refine_geometry.h's encroaches); into x. False
// when even that point leaves a triangle with sin^2 of its smallest angle below sin2Bound. `skinny`:
// the slot of the fan's triangle to test first (the skinny one), or any other value.
bool bestSlide(const Triangulation& t, const std::vector<std::uint32_t>& star, const double* u, const double* w,
               std::uint32_t skinny, double sin2Bound, double lensCos2, double x[2]);

}  // namespace ruppert::detail
