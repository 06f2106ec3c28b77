// The edge list of a mesh (Triangle's -e): every edge once, with its boundary marker.
#include <vector>

#include "output/boundary_markers.h"
#include "cold_code.h"

// The edge list, asked for by option: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

namespace ruppert {

namespace detail {

MeshEdges edgesWith(const Mesh& mesh, const std::vector<std::int32_t>& segmentMarkers) {
  MeshEdges out;
  // A subsegment's marker is its own (mesh.segmentMarkers); any other edge on the boundary gets 1.
  const EdgeIndex subsegments(mesh.segments, mesh.points.size() / 2);
  auto subsegmentMarker = [&](std::uint32_t a, std::uint32_t b, std::int32_t otherwise) {
    const std::int64_t s = subsegments.find(a, b);
    if (s < 0) return otherwise;
    return std::size_t(s) < segmentMarkers.size() ? segmentMarkers[std::size_t(s)] : 1;
  };
  const std::size_t triangles = mesh.triangles.size() / 3;
  out.edges.reserve(3 * triangles + 2);
  out.markers.reserve(3 * triangles / 2 + 1);
  for (std::size_t t = 0; t < triangles; ++t) {
    for (std::size_t i = 0; i < 3; ++i) {
      const std::int32_t across = 3 * t + i < mesh.neighbors.size() ? mesh.neighbors[3 * t + i] : kNoNeighbor;
      if (across != kNoNeighbor && std::size_t(across) <= t) continue;  // listed from the other side
      const std::uint32_t a = mesh.triangles[3 * t + (i + 1) % 3], b = mesh.triangles[3 * t + (i + 2) % 3];
      out.edges.push_back(a);
      out.edges.push_back(b);
      out.markers.push_back(subsegmentMarker(a, b, across == kNoNeighbor ? 1 : 0));
    }
  }
  return out;
}

}  // namespace detail

MeshEdges meshEdges(const Mesh& mesh) { return detail::edgesWith(mesh, mesh.segmentMarkers); }

}  // namespace ruppert

RUPPERT_COLD_END
