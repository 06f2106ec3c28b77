// The edge list of a mesh (Triangle's -e): every edge once, with its boundary marker.
#include <unordered_map>

#include "boundary_markers.h"

namespace ruppert {

MeshEdges meshEdges(const Mesh& mesh) {
  MeshEdges out;
  // A subsegment's marker is its own (mesh.segmentMarkers); any other edge on the boundary gets 1.
  std::unordered_map<std::uint64_t, std::int32_t> subsegmentMarker;
  subsegmentMarker.reserve(mesh.segments.size() / 2);
  for (std::size_t s = 0; 2 * s + 1 < mesh.segments.size(); ++s) {
    const std::int32_t marker = s < mesh.segmentMarkers.size() ? mesh.segmentMarkers[s] : 1;
    subsegmentMarker[detail::edgeKey(mesh.segments[2 * s], mesh.segments[2 * s + 1])] = marker;
  }
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
      const auto found = subsegmentMarker.find(detail::edgeKey(a, b));
      out.markers.push_back(found != subsegmentMarker.end() ? found->second : across == kNoNeighbor ? 1 : 0);
    }
  }
  return out;
}

}  // namespace ruppert
