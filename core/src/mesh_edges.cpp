// The edge list of a mesh (Triangle's -e): every edge once, with its boundary marker.
#include <algorithm>
#include <utility>
#include <vector>

#include "boundary_markers.h"

namespace ruppert {

namespace detail {

MeshEdges edgesWith(const Mesh& mesh, const std::vector<std::int32_t>& segmentMarkers) {
  MeshEdges out;
  // A subsegment's marker is its own (mesh.segmentMarkers); any other edge on the boundary gets 1.
  // (key, subsegment) sorted by key, looked up by binary search.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> subsegments;
  subsegments.reserve(mesh.segments.size() / 2);
  for (std::size_t s = 0; 2 * s + 1 < mesh.segments.size(); ++s)
    subsegments.emplace_back(detail::edgeKey(mesh.segments[2 * s], mesh.segments[2 * s + 1]), std::uint32_t(s));
  std::sort(subsegments.begin(), subsegments.end());
  auto subsegmentMarker = [&](std::uint64_t key, std::int32_t otherwise) {
    const auto found = std::lower_bound(subsegments.begin(), subsegments.end(), std::make_pair(key, std::uint32_t(0)));
    if (found == subsegments.end() || found->first != key) return otherwise;
    return found->second < segmentMarkers.size() ? segmentMarkers[found->second] : 1;
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
      out.markers.push_back(subsegmentMarker(detail::edgeKey(a, b), across == kNoNeighbor ? 1 : 0));
    }
  }
  return out;
}

}  // namespace detail

MeshEdges meshEdges(const Mesh& mesh) { return detail::edgesWith(mesh, mesh.segmentMarkers); }

}  // namespace ruppert
