// Boundary markers: what a solver uses to find where its boundary conditions apply. The rules are
// Triangle's (ruppert.h, "Boundary markers"); the code only needs the output mesh and the input.
#include "boundary_markers.h"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace ruppert::detail {

std::vector<std::uint64_t> boundaryEdges(const Mesh& mesh) {
  std::vector<std::uint64_t> out;
  const std::size_t halfEdges = std::min(mesh.neighbors.size(), mesh.triangles.size());
  for (std::size_t h = 0; h < halfEdges; ++h) {
    if (mesh.neighbors[h] != kNoNeighbor) continue;
    const std::size_t t = h / 3, i = h % 3;
    out.push_back(edgeKey(mesh.triangles[3 * t + (i + 1) % 3], mesh.triangles[3 * t + (i + 2) % 3]));
  }
  std::sort(out.begin(), out.end());
  return out;
}

namespace {

std::int32_t inputSegmentMarker(const Plc& plc, std::int32_t id) {
  if (id < 0 || std::size_t(id) >= plc.segmentMarkers.size()) return 0;
  return plc.segmentMarkers[std::size_t(id)];
}

}  // namespace

Markers computeMarkers(const Mesh& mesh, const Plc& plc) {
  Markers out;
  const std::size_t n = mesh.points.size() / 2, subsegments = mesh.segments.size() / 2;
  const std::vector<std::uint64_t> boundary = boundaryEdges(mesh);
  out.segments.assign(subsegments, 0);
  // Per point: the lowest input segment index with a nonzero marker that the point lies on.
  constexpr std::int32_t kNone = std::numeric_limits<std::int32_t>::max();
  std::vector<std::int32_t> markedSegment(n, kNone);
  std::vector<std::uint8_t> onBoundary(n, 0);
  for (std::size_t s = 0; s < subsegments; ++s) {
    const std::uint32_t a = mesh.segments[2 * s], b = mesh.segments[2 * s + 1];
    const std::int32_t id = s < mesh.segmentIds.size() ? mesh.segmentIds[s] : kNoInputSegment, marker = inputSegmentMarker(plc, id);
    const bool outer = contains(boundary, edgeKey(a, b));
    out.segments[s] = marker != 0 ? marker : outer ? 1 : 0;
    if (marker != 0 && a < n && b < n) {
      if (id < markedSegment[a]) markedSegment[a] = id;
      if (id < markedSegment[b]) markedSegment[b] = id;
    }
  }
  for (std::uint64_t key : boundary)
    if ((key >> 32) < n && (key & 0xFFFFFFFFu) < n) onBoundary[key >> 32] = onBoundary[key & 0xFFFFFFFFu] = 1;
  out.points.assign(n, 0);
  const std::size_t inputPoints = plc.points.size() / 2;
  for (std::size_t v = 0; v < n; ++v) {
    const std::int32_t own = v < inputPoints && v < plc.pointMarkers.size() ? plc.pointMarkers[v] : 0;
    if (own != 0) out.points[v] = own;
    else if (markedSegment[v] != kNone) out.points[v] = inputSegmentMarker(plc, markedSegment[v]);
    else out.points[v] = onBoundary[v] ? 1 : 0;
  }
  return out;
}

void assignMarkers(Mesh& mesh, const Plc& plc) {
  Markers m = computeMarkers(mesh, plc);
  mesh.pointMarkers = std::move(m.points);
  mesh.segmentMarkers = std::move(m.segments);
}

}  // namespace ruppert::detail
