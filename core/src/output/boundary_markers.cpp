// Boundary markers: what a solver uses to find where its boundary conditions apply. The rules are
// Triangle's (ruppert.h, "Boundary markers"); the code only needs the output mesh and the input.
#include "output/boundary_markers.h"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace ruppert::detail {

EdgeIndex::EdgeIndex(const std::vector<std::uint32_t>& ends, std::size_t n) : start_(n + 1, 0) {
  // An edge naming a vertex >= n (a mesh handed to a writer may be inconsistent) is left out.
  const std::size_t edges = ends.size() / 2;
  auto valid = [&](std::size_t k) { return ends[2 * k] < n && ends[2 * k + 1] < n; };
  for (std::size_t k = 0; k < edges; ++k)
    if (valid(k)) ++start_[std::min(ends[2 * k], ends[2 * k + 1]) + 1];
  for (std::size_t v = 0; v < n; ++v) start_[v + 1] += start_[v];
  other_.resize(start_[n]), id_.resize(start_[n]);
  // Filled through start_ itself (each vertex's start moves to the next one's), then shifted back:
  // no second array of n + 1 cursors.
  for (std::size_t k = 0; k < edges; ++k) {
    if (!valid(k)) continue;
    const std::uint32_t a = ends[2 * k], b = ends[2 * k + 1], slot = start_[std::min(a, b)]++;
    other_[slot] = std::max(a, b), id_[slot] = static_cast<std::uint32_t>(k);
  }
  for (std::size_t v = n; v > 0; --v) start_[v] = start_[v - 1];
  start_[0] = 0;
}

std::int64_t EdgeIndex::find(std::uint32_t a, std::uint32_t b) const {
  const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
  if (std::size_t(lo) + 1 >= start_.size()) return -1;
  for (std::uint32_t i = start_[lo]; i < start_[lo + 1]; ++i)
    if (other_[i] == hi) return id_[i];
  return -1;
}

std::vector<std::uint32_t> boundaryEdges(const Mesh& mesh) {
  std::vector<std::uint32_t> out;
  // The domain's boundary edges are subsegments (segments or hull edges): room for as many.
  out.reserve(mesh.segments.size());
  const std::size_t halfEdges = std::min(mesh.neighbors.size(), mesh.triangles.size());
  for (std::size_t h = 0; h < halfEdges; ++h) {
    if (mesh.neighbors[h] != kNoNeighbor) continue;
    const std::size_t t = h / 3, i = h % 3;
    out.push_back(mesh.triangles[3 * t + (i + 1) % 3]);
    out.push_back(mesh.triangles[3 * t + (i + 2) % 3]);
  }
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
  const std::vector<std::uint32_t> boundary = boundaryEdges(mesh);
  const EdgeIndex outer(boundary, n);
  out.segments.assign(subsegments, 0);
  // Per point: the lowest input segment index with a nonzero marker that the point lies on.
  constexpr std::int32_t kNone = std::numeric_limits<std::int32_t>::max();
  std::vector<std::int32_t> markedSegment(n, kNone);
  std::vector<std::uint8_t> onBoundary(n, 0);
  for (std::size_t s = 0; s < subsegments; ++s) {
    const std::uint32_t a = mesh.segments[2 * s], b = mesh.segments[2 * s + 1];
    const std::int32_t id = s < mesh.segmentIds.size() ? mesh.segmentIds[s] : kNoInputSegment, marker = inputSegmentMarker(plc, id);
    out.segments[s] = marker != 0 ? marker : a < n && b < n && outer.find(a, b) >= 0 ? 1 : 0;
    if (marker != 0 && a < n && b < n) {
      if (id < markedSegment[a]) markedSegment[a] = id;
      if (id < markedSegment[b]) markedSegment[b] = id;
    }
  }
  for (std::uint32_t v : boundary)
    if (v < n) onBoundary[v] = 1;
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

// computeMarkers' rules, for the mesh output assembly has just written: which subsegments have a
// triangle on one side only is known from the triangulation, and the boundary's vertices from
// mesh.neighbors, so no list of boundary edges or index over them is built (on a small mesh, they
// were most of the markers' cost).
void assignMarkers(Mesh& mesh, const Plc& plc, const std::vector<std::uint8_t>& boundarySubsegment) {
  const std::size_t n = mesh.points.size() / 2, subsegments = mesh.segments.size() / 2;
  std::vector<std::int32_t>& points = mesh.pointMarkers;
  points.assign(n, 0);
  // The boundary's vertices first: 1, the rule of least precedence.
  const std::size_t halfEdges = std::min(mesh.neighbors.size(), mesh.triangles.size());
  for (std::size_t h = 0; h < halfEdges; ++h) {
    if (mesh.neighbors[h] != kNoNeighbor) continue;
    const std::size_t t = h / 3, i = h % 3;
    const std::uint32_t a = mesh.triangles[3 * t + (i + 1) % 3], b = mesh.triangles[3 * t + (i + 2) % 3];
    if (a < n) points[a] = 1;
    if (b < n) points[b] = 1;
  }
  // Per point: the lowest input segment index with a nonzero marker that the point lies on (only
  // when the input has segment markers).
  constexpr std::int32_t kNone = std::numeric_limits<std::int32_t>::max();
  std::vector<std::int32_t> markedSegment;
  if (!plc.segmentMarkers.empty()) markedSegment.assign(n, kNone);
  mesh.segmentMarkers.assign(subsegments, 0);
  for (std::size_t s = 0; s < subsegments; ++s) {
    const std::uint32_t a = mesh.segments[2 * s], b = mesh.segments[2 * s + 1];
    const std::int32_t id = s < mesh.segmentIds.size() ? mesh.segmentIds[s] : kNoInputSegment, marker = inputSegmentMarker(plc, id);
    const bool boundary = s < boundarySubsegment.size() && boundarySubsegment[s] != 0;
    mesh.segmentMarkers[s] = marker != 0 ? marker : boundary ? 1 : 0;
    if (marker != 0 && a < n && b < n) {
      if (id < markedSegment[a]) markedSegment[a] = id;
      if (id < markedSegment[b]) markedSegment[b] = id;
    }
  }
  const std::size_t inputPoints = plc.points.size() / 2;
  for (std::size_t v = 0; v < n; ++v) {
    const std::int32_t own = v < inputPoints && v < plc.pointMarkers.size() ? plc.pointMarkers[v] : 0;
    if (own != 0) points[v] = own;
    else if (!markedSegment.empty() && markedSegment[v] != kNone) points[v] = inputSegmentMarker(plc, markedSegment[v]);
  }
}

}  // namespace ruppert::detail
