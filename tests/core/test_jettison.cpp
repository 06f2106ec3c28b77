// Options::jettison (Triangle's -j): unused input points (merged duplicates,
// points outside the domain) are left out, the rest renumbered in order, and Mesh::inputToOutput says
// where every input point went.
#include <catch2/catch.hpp>

#include "plc_generators.h"
#include "validator.h"

using namespace ruppert_test;

TEST_CASE("jettison leaves unused points out and maps every input point", "[jettison]") {
  // A square with a duplicate of its corner 2, a point outside the domain (a hole) and a marker.
  ruppert::Plc plc;
  plc.points = {0, 0, 4, 0, 4, 4, 0, 4, 4, 4, 1, 1, 3, 1, 3, 3, 1, 3, 2, 2, 0.5, 3.5};
  plc.segments = {0, 1, 1, 2, 2, 3, 3, 0, 5, 6, 6, 7, 7, 8, 8, 5};
  plc.holes = {2.5, 2.5};  // point 9 (2, 2) lies in the hole
  plc.pointMarkers = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 77};
  plc.attributesPerPoint = 1;
  for (std::size_t i = 0; i < plc.points.size() / 2; ++i) plc.pointAttributes.push_back(plc.points[2 * i] + 10 * plc.points[2 * i + 1]);
  ruppert::Options o;
  o.minAngle = 30;
  o.trace = true;
  o.edges = true;
  const ruppert::Mesh full = ruppert::triangulate(plc, o);
  o.jettison = true;
  const ruppert::Mesh mesh = ruppert::triangulate(plc, o);
  REQUIRE(full.inputToOutput.empty());
  REQUIRE(mesh.inputToOutput.size() == 11);
  CHECK(mesh.inputToOutput[4] == mesh.inputToOutput[2]);  // the duplicate maps to the point it joined
  CHECK(mesh.inputToOutput[9] == -1);                     // outside the domain
  CHECK(mesh.inputToOutput[10] == 8);                     // after the two left out, in order
  for (std::uint32_t i : {0u, 1u, 2u, 3u}) CHECK(mesh.inputToOutput[i] == std::int32_t(i));
  // Two points fewer, nothing Unused, everything else the same mesh renumbered.
  CHECK(mesh.points.size() + 4 == full.points.size());
  for (std::uint8_t k : mesh.vertexKinds) CHECK(k != std::uint8_t(ruppert::VertexKind::Unused));
  CHECK(mesh.triangles.size() == full.triangles.size());
  CHECK(mesh.pointMarkers[8] == 77);
  REQUIRE(mesh.pointAttributes.size() == mesh.points.size() / 2);
  for (std::size_t v = 0; v < mesh.points.size() / 2; ++v) {
    CHECK(mesh.pointAttributes[v] == Approx(mesh.points[2 * v] + 10 * mesh.points[2 * v + 1]));
  }
  REQUIRE_VALID(mesh);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    // The same coordinates at every corner as in the full mesh.
    const std::uint32_t a = mesh.triangles[t], b = full.triangles[t];
    CHECK(mesh.points[2 * a] == full.points[2 * b]);
    CHECK(mesh.points[2 * a + 1] == full.points[2 * b + 1]);
  }
  CHECK(mesh.edges.size() == full.edges.size());
  for (std::uint32_t v : mesh.edges) CHECK(v < mesh.points.size() / 2);
  // The trace names the renumbered vertices.
  REQUIRE(mesh.events.size() == full.events.size());
  for (std::size_t e = 0; e < mesh.events.size(); ++e) {
    if (mesh.events[e].vertex == ruppert::kNoVertex) continue;
    CHECK(mesh.points[2 * mesh.events[e].vertex] == mesh.events[e].x);
  }
}

TEST_CASE("jettison on generated PLCs: valid meshes, no unused point, a consistent map", "[jettison]") {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    GeneratedPlc g = randomStarPolygon(seed, 16, 1);
    // Duplicates of some points and points outside the polygon.
    const std::size_t n = g.plc.points.size() / 2;
    for (std::size_t k = 0; k < 3; ++k) g.plc.points.insert(g.plc.points.end(), {g.plc.points[2 * k], g.plc.points[2 * k + 1]});
    g.plc.points.insert(g.plc.points.end(), {5.0, 5.0, -3.0, 0.5});
    ruppert::Options o;
    o.minAngle = 28;
    o.jettison = true;
    const ruppert::Mesh mesh = ruppert::triangulate(g.plc, o);
    INFO("seed " << seed);
    REQUIRE_VALID(mesh);
    REQUIRE(mesh.inputToOutput.size() == n + 5);
    for (std::size_t k = 0; k < 3; ++k) CHECK(mesh.inputToOutput[n + k] == mesh.inputToOutput[k]);
    CHECK(mesh.inputToOutput[n + 3] == -1);
    CHECK(mesh.inputToOutput[n + 4] == -1);
    for (std::size_t i = 0; i < mesh.inputToOutput.size(); ++i) {
      const std::int32_t o2 = mesh.inputToOutput[i];
      if (o2 < 0) continue;
      CHECK(mesh.points[2 * o2] == g.plc.points[2 * i]);
      CHECK(mesh.points[2 * o2 + 1] == g.plc.points[2 * i + 1]);
    }
    for (std::uint8_t k : mesh.vertexKinds) CHECK(k != std::uint8_t(ruppert::VertexKind::Unused));
  }
}
