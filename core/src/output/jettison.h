// Options::jettison (Triangle's -j): unused input points left out of the output.
#pragma once

#include <cstdint>
#include <vector>

#include "ruppert/ruppert.h"

namespace ruppert::detail {

// Removes the Unused points from index keepBelow on from mesh.points and renumbers every array that
// holds point indices (triangles, segments, edges, events) and every per-point array; fills
// mesh.inputToOutput unless mergedInto is empty. mergedInto[i]: the input point that input point i
// was merged into (i itself if it was not).
void jettisonUnused(Mesh& mesh, const std::vector<std::uint32_t>& mergedInto, std::size_t keepBelow = 0);

}  // namespace ruppert::detail
