// Checks shared by the derived outputs (quadratic_nodes.cpp, voronoi.cpp), which walk a mesh
// through its neighbors.
#pragma once

#include "ruppert/ruppert.h"

namespace ruppert::detail {

// Throws MalformedInput / IndexOutOfRange unless neighbors has 3 entries per triangle, each a
// triangle or kNoNeighbor, and every triangle's vertices exist.
void requireNeighbors(const Mesh& mesh);

}  // namespace ruppert::detail
