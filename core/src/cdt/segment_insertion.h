// The constrain stage (segment_insertion.cpp): segments, and the hull where asked or needed, as
// constrained edges, the input repaired on the way.
#pragma once

#include "mesh_state.h"

namespace ruppert::detail {

void insertHull(MeshState& m);             // convex hull edges as constraints (no segments / convexHull)
void insertSegments(MeshState& m);         // input segments, repairing crossings and overlaps
void constrainBoxSides(MeshState& m);      // bounding-box variant: the box's sides bound what is refined

}  // namespace ruppert::detail
