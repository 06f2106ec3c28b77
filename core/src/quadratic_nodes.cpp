// Quadratic (6-node) triangles, Triangle's -o2: a node at the midpoint of every edge, shared by the
// edge's two triangles. See addQuadraticNodes in ruppert.h for the numbering.
#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "ruppert/ruppert.h"

namespace ruppert {
namespace {

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

}  // namespace

void addQuadraticNodes(Mesh& mesh) {
  const std::size_t corners = mesh.points.size() / 2;
  const std::size_t n = mesh.triangles.size() / 3;
  if (mesh.pointMarkers.size() != corners) {
    // Triangle's convention for the corners, as the .node writer prints it: 1 on a subsegment.
    mesh.pointMarkers.assign(corners, 0);
    for (std::uint32_t v : mesh.segments)
      if (v < corners) mesh.pointMarkers[v] = 1;
  }
  std::unordered_set<std::uint64_t> subsegments;
  for (std::size_t s = 0; s + 1 < mesh.segments.size(); s += 2) subsegments.insert(edgeKey(mesh.segments[s], mesh.segments[s + 1]));
  // How many triangles use each edge: an edge of one triangle only is on the boundary.
  std::unordered_map<std::uint64_t, std::uint32_t> node;  // edge -> its midpoint node
  node.reserve(3 * n / 2 + 1);
  std::vector<std::uint8_t> uses;
  mesh.triangles6.resize(6 * n);
  for (std::size_t t = 0; t < n; ++t) {
    for (int i = 0; i < 3; ++i) mesh.triangles6[6 * t + i] = mesh.triangles[3 * t + i];
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = mesh.triangles[3 * t + (i + 1) % 3], b = mesh.triangles[3 * t + (i + 2) % 3];
      const auto [it, added] = node.try_emplace(edgeKey(a, b), static_cast<std::uint32_t>(mesh.points.size() / 2));
      if (added) {
        // Halving is exact (short of the subnormals), so this is the midpoint rounded once.
        mesh.points.push_back(0.5 * mesh.points[2 * std::size_t(a)] + 0.5 * mesh.points[2 * std::size_t(b)]);
        mesh.points.push_back(0.5 * mesh.points[2 * std::size_t(a) + 1] + 0.5 * mesh.points[2 * std::size_t(b) + 1]);
        uses.push_back(1);
      } else {
        ++uses[it->second - corners];
      }
      mesh.triangles6[6 * t + 3 + i] = it->second;
    }
  }
  for (std::size_t t = 0; t < n; ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = mesh.triangles[3 * t + (i + 1) % 3], b = mesh.triangles[3 * t + (i + 2) % 3];
      const std::uint32_t m = mesh.triangles6[6 * t + 3 + i];
      if (mesh.pointMarkers.size() <= m) mesh.pointMarkers.resize(m + 1, 0);
      mesh.pointMarkers[m] = uses[m - corners] == 1 || subsegments.count(edgeKey(a, b)) ? 1 : 0;
    }
}

}  // namespace ruppert
