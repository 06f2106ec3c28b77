// The dual of a mesh (Triangle's -v): the circumcenters and one dual edge or ray per mesh edge.
// See voronoiDiagram in ruppert.h; its text files: io/write_voronoi.cpp.
#include <cstdint>

#include "output/mesh_neighbors.h"
#include "ruppert/ruppert.h"
#include "cold_code.h"

RUPPERT_COLD_BEGIN

namespace ruppert {

namespace {

// Circumcenter of a b c, computed relative to a (the offsets are small where the triangle is).
void circumcenter(const double* a, const double* b, const double* c, double* out) {
  const double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double d = 2 * (bx * cy - by * cx);
  out[0] = a[0] + (cy * b2 - by * c2) / d;
  out[1] = a[1] + (bx * c2 - cx * b2) / d;
}

}  // namespace

Voronoi voronoiDiagram(const Mesh& mesh) {
  detail::requireNeighbors(mesh);
  Voronoi v;
  const std::size_t n = mesh.triangles.size() / 3;
  v.points.resize(2 * n);
  for (std::size_t t = 0; t < n; ++t)
    circumcenter(&mesh.points[2 * mesh.triangles[3 * t]], &mesh.points[2 * mesh.triangles[3 * t + 1]],
                 &mesh.points[2 * mesh.triangles[3 * t + 2]], &v.points[2 * t]);
  // An edge's dual is made at its first appearance: in t, unless the neighbor across comes first.
  for (std::size_t t = 0; t < n; ++t)
    for (int i = 0; i < 3; ++i) {
      const std::int32_t g = mesh.neighbors[3 * t + i];
      if (g != kNoNeighbor && static_cast<std::size_t>(g) < t) continue;
      const std::uint32_t a = mesh.triangles[3 * t + (i + 1) % 3], b = mesh.triangles[3 * t + (i + 2) % 3];
      v.edges.insert(v.edges.end(), {static_cast<std::int32_t>(t), g});
      v.meshEdges.insert(v.meshEdges.end(), {a, b});
      // A ray on the boundary: the outward normal of a -> b (the triangle, counter-clockwise, lies
      // to its left).
      const bool ray = g == kNoNeighbor;
      v.rayDirections.insert(v.rayDirections.end(), {ray ? mesh.points[2 * b + 1] - mesh.points[2 * a + 1] : 0.0,
                                                     ray ? mesh.points[2 * a] - mesh.points[2 * b] : 0.0});
    }
  return v;
}

}  // namespace ruppert
RUPPERT_COLD_END
