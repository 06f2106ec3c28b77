// Boundary markers of the output (Triangle's convention, see "Boundary markers" in ruppert.h).
#pragma once

#include <cstdint>
#include <unordered_set>

#include "ruppert/ruppert.h"

namespace ruppert::detail {

// Key of the undirected edge {a, b}.
inline std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

// The edges of the mesh with a triangle on one side only.
std::unordered_set<std::uint64_t> boundaryEdges(const Mesh& mesh);

// Fills mesh.pointMarkers (one per point) and mesh.segmentMarkers (one per subsegment) from the
// input's markers, mesh.segmentIds and the mesh's boundary. Points [0, plc's point count) are the
// input points, with their own indices (before any jettison).
void assignMarkers(Mesh& mesh, const Plc& plc);

}  // namespace ruppert::detail
