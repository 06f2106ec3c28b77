// Boundary markers of the output (Triangle's convention, see "Boundary markers" in ruppert.h).
#pragma once

#include <cstdint>
#include <vector>

#include "ruppert/ruppert.h"

namespace ruppert::detail {

// A set of undirected edges {a, b} with an id each, indexed by their lower vertex (compressed rows,
// built by counting: no sorting and no hash table, which cost the wasm module kilobytes).
class EdgeIndex {
 public:
  // ends: a0, b0, a1, b1, ... (edge k has id k); vertices below n.
  EdgeIndex(const std::vector<std::uint32_t>& ends, std::size_t n);
  // The id of edge {a, b}, or -1.
  std::int64_t find(std::uint32_t a, std::uint32_t b) const;

 private:
  std::vector<std::uint32_t> start_, other_, id_;
};

// The edges of the mesh with a triangle on one side only: a0, b0, a1, b1, ...
std::vector<std::uint32_t> boundaryEdges(const Mesh& mesh);

struct Markers {
  std::vector<std::int32_t> points, segments;  // one per point, one per subsegment
};

// The markers from the input's markers, mesh.segmentIds (kNoInputSegment where missing) and the
// mesh's boundary. Points [0, plc's point count) are the input points, with their own indices
// (before any jettison).
Markers computeMarkers(const Mesh& mesh, const Plc& plc);
// Sets mesh.pointMarkers and mesh.segmentMarkers to what computeMarkers(mesh, plc) gives, for a mesh
// whose subsegment s has a triangle on one side only exactly where boundarySubsegment[s] != 0.
void assignMarkers(Mesh& mesh, const Plc& plc, const std::vector<std::uint8_t>& boundarySubsegment);

// meshEdges() with the given marker per subsegment.
MeshEdges edgesWith(const Mesh& mesh, const std::vector<std::int32_t>& segmentMarkers);

}  // namespace ruppert::detail
