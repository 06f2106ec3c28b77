// Checks shared by the marker, edge, attribute and boundary-Steiner tests: what the
// output must say, computed independently from the geometry of the mesh and its input.
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <ruppert/ruppert.h>

namespace ruppert_test {

// Input segments that point (x, y) lies on (within collinearity tolerance 1e-9 of the segment's
// length, and between its ends), in increasing index order.
std::vector<std::uint32_t> segmentsThrough(const ruppert::Plc& plc, double x, double y);

// Undirected edges {min, max} of the mesh with a triangle on one side only, from its triangles
// alone (an edge used once).
std::set<std::pair<std::uint32_t, std::uint32_t>> boundaryEdgesOf(const ruppert::Mesh& mesh);

// Problems with mesh.pointMarkers and mesh.segmentMarkers against Triangle's rules, the input's
// markers and where each vertex and subsegment lies geometrically; empty when all are right.
std::vector<std::string> markerProblems(const ruppert::Mesh& mesh, const ruppert::Plc& plc);

// Problems with an edge list (every edge of the mesh exactly once, nothing else; the count
// (3T + B) / 2; markers: the subsegment's, else 1 on the boundary, 0 inside).
std::vector<std::string> edgeProblems(const ruppert::Mesh& mesh, const std::vector<std::uint32_t>& edges,
                                      const std::vector<std::int32_t>& markers);

}  // namespace ruppert_test
