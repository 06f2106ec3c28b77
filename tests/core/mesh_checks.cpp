#include "mesh_checks.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ruppert_test {

std::vector<std::uint32_t> segmentsThrough(const ruppert::Plc& plc, double x, double y) {
  std::vector<std::uint32_t> out;
  for (std::size_t j = 0; 2 * j + 1 < plc.segments.size(); ++j) {
    const double ax = plc.points[2 * plc.segments[2 * j]], ay = plc.points[2 * plc.segments[2 * j] + 1];
    const double bx = plc.points[2 * plc.segments[2 * j + 1]], by = plc.points[2 * plc.segments[2 * j + 1] + 1];
    const double dx = bx - ax, dy = by - ay, len = std::hypot(dx, dy);
    if (len == 0) continue;
    const double off = std::fabs((x - ax) * dy - (y - ay) * dx) / len;  // distance from the line
    const double along = ((x - ax) * dx + (y - ay) * dy) / (len * len);
    const double tol = 1e-9 * len + 0x1p-46 * std::max({std::fabs(ax), std::fabs(ay), std::fabs(bx), std::fabs(by)});
    if (off <= tol && along >= -1e-9 && along <= 1 + 1e-9) out.push_back(static_cast<std::uint32_t>(j));
  }
  return out;
}

std::set<std::pair<std::uint32_t, std::uint32_t>> boundaryEdgesOf(const ruppert::Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t t = 0; 3 * t + 2 < mesh.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = mesh.triangles[3 * t + i], b = mesh.triangles[3 * t + (i + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::set<std::pair<std::uint32_t, std::uint32_t>> out;
  for (const auto& [edge, count] : uses)
    if (count == 1) out.insert(edge);
  return out;
}

namespace {

std::int32_t markerOf(const std::vector<std::int32_t>& markers, std::size_t i) {
  return i < markers.size() ? markers[i] : 0;
}

}  // namespace

std::vector<std::string> markerProblems(const ruppert::Mesh& mesh, const ruppert::Plc& plc) {
  std::vector<std::string> problems;
  const std::size_t n = mesh.points.size() / 2, inputPoints = plc.points.size() / 2;
  if (mesh.pointMarkers.size() != n) problems.push_back("pointMarkers has " + std::to_string(mesh.pointMarkers.size()) + " entries for " + std::to_string(n) + " points");
  if (mesh.segmentMarkers.size() != mesh.segments.size() / 2) problems.push_back("segmentMarkers has the wrong size");
  if (!problems.empty()) return problems;
  const auto boundary = boundaryEdgesOf(mesh);
  std::vector<char> onBoundary(n, 0);
  for (const auto& e : boundary) onBoundary[e.first] = onBoundary[e.second] = 1;
  for (std::size_t s = 0; s < mesh.segmentMarkers.size(); ++s) {
    const std::uint32_t a = mesh.segments[2 * s], b = mesh.segments[2 * s + 1];
    // The input segment the subsegment lies on: one through both its ends.
    const auto ta = segmentsThrough(plc, mesh.points[2 * a], mesh.points[2 * a + 1]);
    const auto tb = segmentsThrough(plc, mesh.points[2 * b], mesh.points[2 * b + 1]);
    std::vector<std::uint32_t> both;
    std::set_intersection(ta.begin(), ta.end(), tb.begin(), tb.end(), std::back_inserter(both));
    const bool outer = boundary.count({std::min(a, b), std::max(a, b)}) != 0;
    std::int32_t expected = outer ? 1 : 0;
    for (std::uint32_t j : both)
      if (markerOf(plc.segmentMarkers, j) != 0) {
        expected = markerOf(plc.segmentMarkers, j);
        break;
      }
    if (mesh.segmentIds[s] >= 0 && std::find(both.begin(), both.end(), std::uint32_t(mesh.segmentIds[s])) == both.end())
      problems.push_back("subsegment " + std::to_string(s) + " has segmentId " + std::to_string(mesh.segmentIds[s]) + " but does not lie on it");
    if (mesh.segmentMarkers[s] != expected)
      problems.push_back("subsegment " + std::to_string(s) + " (" + std::to_string(a) + ", " + std::to_string(b) +
                         ") has marker " + std::to_string(mesh.segmentMarkers[s]) + ", expected " + std::to_string(expected));
  }
  for (std::size_t v = 0; v < n; ++v) {
    const bool unused = mesh.vertexKinds[v] == std::uint8_t(ruppert::VertexKind::Unused);
    std::int32_t expected = v < inputPoints ? markerOf(plc.pointMarkers, v) : 0;
    if (expected == 0 && !unused) {
      for (std::uint32_t j : segmentsThrough(plc, mesh.points[2 * v], mesh.points[2 * v + 1]))
        if (markerOf(plc.segmentMarkers, j) != 0) {
          expected = markerOf(plc.segmentMarkers, j);
          break;
        }
      if (expected == 0) expected = onBoundary[v] ? 1 : 0;
    }
    if (mesh.pointMarkers[v] != expected)
      problems.push_back("vertex " + std::to_string(v) + " has marker " + std::to_string(mesh.pointMarkers[v]) +
                         ", expected " + std::to_string(expected));
    if (problems.size() > 20) break;
  }
  return problems;
}

std::vector<std::string> edgeProblems(const ruppert::Mesh& mesh, const std::vector<std::uint32_t>& edges,
                                      const std::vector<std::int32_t>& markers) {
  std::vector<std::string> problems;
  const std::size_t triangles = mesh.triangles.size() / 3;
  const auto boundary = boundaryEdgesOf(mesh);
  if (edges.size() != 2 * markers.size()) return {"edges and markers differ in length"};
  if (2 * markers.size() != 3 * triangles + boundary.size())
    problems.push_back(std::to_string(markers.size()) + " edges for " + std::to_string(triangles) + " triangles and " +
                       std::to_string(boundary.size()) + " boundary edges: not (3T + B) / 2");
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::int32_t> subsegment;
  for (std::size_t s = 0; s < mesh.segmentMarkers.size(); ++s) {
    const std::uint32_t a = mesh.segments[2 * s], b = mesh.segments[2 * s + 1];
    subsegment[{std::min(a, b), std::max(a, b)}] = mesh.segmentMarkers[s];
  }
  std::set<std::pair<std::uint32_t, std::uint32_t>> triangleEdges, listed;
  for (std::size_t t = 0; t < triangles; ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = mesh.triangles[3 * t + i], b = mesh.triangles[3 * t + (i + 1) % 3];
      triangleEdges.insert({std::min(a, b), std::max(a, b)});
    }
  for (std::size_t e = 0; e < markers.size(); ++e) {
    const std::pair<std::uint32_t, std::uint32_t> key{std::min(edges[2 * e], edges[2 * e + 1]), std::max(edges[2 * e], edges[2 * e + 1])};
    if (!listed.insert(key).second) problems.push_back("edge " + std::to_string(e) + " is listed twice");
    if (!triangleEdges.count(key)) problems.push_back("edge " + std::to_string(e) + " is no triangle's edge");
    const auto sub = subsegment.find(key);
    const std::int32_t expected = sub != subsegment.end() ? sub->second : boundary.count(key) ? 1 : 0;
    if (markers[e] != expected)
      problems.push_back("edge " + std::to_string(e) + " has marker " + std::to_string(markers[e]) + ", expected " + std::to_string(expected));
    if (problems.size() > 20) break;
  }
  if (listed.size() != triangleEdges.size())
    problems.push_back(std::to_string(triangleEdges.size() - listed.size()) + " triangle edges are not listed");
  return problems;
}

}  // namespace ruppert_test
