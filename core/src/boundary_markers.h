// Boundary markers of the output (Triangle's convention, see "Boundary markers" in ruppert.h).
#pragma once

#include <cstdint>
#include <algorithm>
#include <vector>

#include "ruppert/ruppert.h"

namespace ruppert::detail {

// Key of the undirected edge {a, b}.
inline std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

// The edges of the mesh with a triangle on one side only, as sorted keys. (Sorted vectors, not hash
// tables: these instantiations cost the wasm module several kilobytes.)
std::vector<std::uint64_t> boundaryEdges(const Mesh& mesh);
inline bool contains(const std::vector<std::uint64_t>& sorted, std::uint64_t key) {
  return std::binary_search(sorted.begin(), sorted.end(), key);
}

struct Markers {
  std::vector<std::int32_t> points, segments;  // one per point, one per subsegment
};

// The markers from the input's markers, mesh.segmentIds (kNoInputSegment where missing) and the
// mesh's boundary. Points [0, plc's point count) are the input points, with their own indices
// (before any jettison).
Markers computeMarkers(const Mesh& mesh, const Plc& plc);
// Sets mesh.pointMarkers and mesh.segmentMarkers to computeMarkers(mesh, plc).
void assignMarkers(Mesh& mesh, const Plc& plc);

// meshEdges() with the given marker per subsegment.
MeshEdges edgesWith(const Mesh& mesh, const std::vector<std::int32_t>& segmentMarkers);

}  // namespace ruppert::detail
