// The build stage (build_delaunay.cpp): the Delaunay triangulation of the prepared points.
#pragma once

#include "mesh_state.h"

namespace ruppert::detail {

// Whether anything is refined after the CDT (an angle or area bound of any kind): the build reserves
// room for it, and the pipeline runs refine() only then.
bool refinementRequested(const MeshState& m);

void buildDelaunay(MeshState& m);          // box corners + every distinct input point

}  // namespace ruppert::detail
