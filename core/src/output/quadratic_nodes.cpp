// Quadratic (6-node) triangles, Triangle's -o2: a node at the midpoint of every edge, shared by the
// edge's two triangles (found through mesh.neighbors, without a hash table: the wasm module stays
// small). See addQuadraticNodes in ruppert.h for the numbering.
#include <algorithm>
#include <climits>
#include <utility>
#include <cstdint>
#include <string>
#include <vector>

#include "output/mesh_neighbors.h"
#include "ruppert/ruppert.h"
#include "cold_code.h"

RUPPERT_COLD_BEGIN

namespace ruppert {
namespace {

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

// The edge of triangle g that is edge i of triangle t (through neighbors), as 3g + j.
std::size_t twinEdge(const Mesh& mesh, std::size_t t, int i) {
  const std::size_t g = static_cast<std::size_t>(mesh.neighbors[3 * t + i]);
  const std::uint32_t a = mesh.triangles[3 * t + (i + 1) % 3], b = mesh.triangles[3 * t + (i + 2) % 3];
  for (int j = 0; j < 3; ++j)
    if (mesh.triangles[3 * g + (j + 1) % 3] == b && mesh.triangles[3 * g + (j + 2) % 3] == a) return 3 * g + j;
  throw Error(ErrorCode::MalformedInput, "neighbors[" + std::to_string(3 * t + i) + "] = " + std::to_string(g) +
                                             " does not share edge " + std::to_string(i) + " of triangle " + std::to_string(t));
}

}  // namespace

void detail::requireNeighbors(const Mesh& mesh) {
  const std::size_t n = mesh.triangles.size() / 3;
  if (mesh.neighbors.size() != 3 * n)
    throw Error(ErrorCode::MalformedInput, "the mesh needs its neighbors (3 per triangle, as triangulate() gives them)");
  for (std::size_t k = 0; k < mesh.neighbors.size(); ++k)
    if (mesh.neighbors[k] < kNoNeighbor || mesh.neighbors[k] >= static_cast<std::int64_t>(n))
      throw Error(ErrorCode::IndexOutOfRange, "neighbors[" + std::to_string(k) + "] = " + std::to_string(mesh.neighbors[k]) +
                                                  " is not a triangle");
  for (std::uint32_t v : mesh.triangles)
    if (v >= mesh.points.size() / 2) throw Error(ErrorCode::IndexOutOfRange, "a triangle refers to a point that does not exist");
}

void addQuadraticNodes(Mesh& mesh) {
  detail::requireNeighbors(mesh);
  const std::size_t corners = mesh.points.size() / 2;
  const std::size_t n = mesh.triangles.size() / 3;
  if (mesh.pointMarkers.size() != corners) {
    // Triangle's convention for the corners, as the .node writer prints it: 1 on a subsegment.
    mesh.pointMarkers.assign(corners, 0);
    for (std::uint32_t v : mesh.segments)
      if (v < corners) mesh.pointMarkers[v] = 1;
  }
  // Subsegments by their ends, with their markers (Mesh::segmentMarkers, else 1): a midpoint node on
  // a subsegment takes its marker, as a vertex inserted on a segment does.
  // (The marker is kept as unsigned bits: the pair type then shares the sort the triangulation's
  // edge keys instantiate.)
  std::vector<std::pair<std::uint64_t, std::uint32_t>> subsegments;
  for (std::size_t s = 0; s + 1 < mesh.segments.size(); s += 2) {
    const std::int32_t marker = s / 2 < mesh.segmentMarkers.size() ? mesh.segmentMarkers[s / 2] : 1;
    subsegments.emplace_back(edgeKey(mesh.segments[s], mesh.segments[s + 1]), static_cast<std::uint32_t>(marker));
  }
  std::sort(subsegments.begin(), subsegments.end());
  const std::size_t k = mesh.attributesPerPoint;
  const bool attributes = k > 0 && mesh.pointAttributes.size() == k * corners;
  mesh.triangles6.resize(6 * n);
  for (std::size_t t = 0; t < n; ++t) {
    for (int i = 0; i < 3; ++i) mesh.triangles6[6 * t + i] = mesh.triangles[3 * t + i];
    for (int i = 0; i < 3; ++i) {
      const std::int32_t g = mesh.neighbors[3 * t + i];
      if (g != kNoNeighbor && static_cast<std::size_t>(g) < t) {  // met first in g: its node
        const std::size_t h = twinEdge(mesh, t, i);
        mesh.triangles6[6 * t + 3 + i] = mesh.triangles6[6 * (h / 3) + 3 + h % 3];
        continue;
      }
      const std::uint32_t a = mesh.triangles[3 * t + (i + 1) % 3], b = mesh.triangles[3 * t + (i + 2) % 3];
      mesh.triangles6[6 * t + 3 + i] = static_cast<std::uint32_t>(mesh.points.size() / 2);
      // Halving is exact (short of the subnormals), so this is the midpoint rounded once.
      mesh.points.push_back(0.5 * mesh.points[2 * std::size_t(a)] + 0.5 * mesh.points[2 * std::size_t(b)]);
      mesh.points.push_back(0.5 * mesh.points[2 * std::size_t(a) + 1] + 0.5 * mesh.points[2 * std::size_t(b) + 1]);
      const auto sub = std::lower_bound(subsegments.begin(), subsegments.end(), std::make_pair(edgeKey(a, b), 0u));
      if (sub != subsegments.end() && sub->first == edgeKey(a, b)) mesh.pointMarkers.push_back(static_cast<std::int32_t>(sub->second));
      else mesh.pointMarkers.push_back(g == kNoNeighbor ? 1 : 0);
      // Attributes interpolated linearly: the mean of the edge's ends.
      for (std::size_t j = 0; attributes && j < k; ++j)
        mesh.pointAttributes.push_back(0.5 * mesh.pointAttributes[k * a + j] + 0.5 * mesh.pointAttributes[k * b + j]);
    }
  }
}

}  // namespace ruppert
RUPPERT_COLD_END
