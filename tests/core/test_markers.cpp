// Boundary markers and edges: Triangle's box.poly keeps its markers 5, 10
// and 33 where they belong; random markers on generated PLCs land on exactly the subsegments and
// vertices that lie on their segments; the edge list holds every edge once with the right marker.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "mesh_checks.h"
#include "plc_generators.h"
#include "validator.h"

using namespace ruppert_test;

namespace {

std::string describe(const std::vector<std::string>& problems) { return describeProblems(problems); }

// Random markers in [-2, 6] on every point and segment: zeros (the "find the boundary" default)
// among them, so both rules are exercised.
void addRandomMarkers(ruppert::Plc& plc, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto draw = [&] { return static_cast<std::int32_t>(rng() % 9) - 2; };
  plc.pointMarkers.resize(plc.points.size() / 2);
  for (auto& m : plc.pointMarkers) m = rng() % 3 == 0 ? draw() : 0;
  plc.segmentMarkers.resize(plc.segments.size() / 2);
  for (auto& m : plc.segmentMarkers) m = draw();
}

ruppert::Plc boxPoly() {
  const std::string dir = sharedDataDir();
  if (dir.empty()) return {};
  return ruppert::readFile(dir + "/box.poly");
}

}  // namespace

TEST_CASE("box.poly at 30 degrees keeps markers 5 and 10 on their subsegments and vertices, 33 on vertex 4", "[markers]") {
  const ruppert::Plc plc = boxPoly();
  if (plc.points.empty()) {
    WARN("../shared/data/box.poly not found: skipping");
    return;
  }
  ruppert::Options o;
  o.minAngle = 30;
  const ruppert::Mesh mesh = ruppert::triangulate(plc, o);
  REQUIRE_VALID(mesh);
  INFO(describe(markerProblems(mesh, plc)));
  CHECK(markerProblems(mesh, plc).empty());
  // By hand, from the file: segment 1 (0-based 0) is the left side x = 0 with marker 5; segment 4
  // (0-based 3) is y = 2, 1 <= x <= 2 with marker 10; point 4 (0-based 3) at (3, 3) has 33.
  auto onLeft = [&](std::uint32_t v) { return mesh.points[2 * v] == 0; };
  auto onTen = [&](std::uint32_t v) {
    return mesh.points[2 * v + 1] == 2 && mesh.points[2 * v] >= 1 && mesh.points[2 * v] <= 2;
  };
  std::size_t fives = 0, tens = 0, insertedOnLeft = 0;
  for (std::size_t s = 0; s < mesh.segmentMarkers.size(); ++s) {
    const std::uint32_t a = mesh.segments[2 * s], b = mesh.segments[2 * s + 1];
    const std::int32_t expected = onLeft(a) && onLeft(b) ? 5 : onTen(a) && onTen(b) ? 10 : 1;
    CHECK(mesh.segmentMarkers[s] == expected);
    fives += expected == 5, tens += expected == 10;
  }
  CHECK(fives >= 2);  // the left side is split at 30 degrees
  CHECK(tens >= 1);
  for (std::uint32_t v = 0; v < mesh.points.size() / 2; ++v) {
    const std::int32_t expected = v == 3 ? 33 : onLeft(v) ? 5 : onTen(v) ? 10 : mesh.pointMarkers[v];
    CHECK(mesh.pointMarkers[v] == expected);
    if (v >= 8 && onLeft(v)) ++insertedOnLeft;
  }
  CHECK(insertedOnLeft >= 1);
  // The same markers in the .poly, .node and .edge texts.
  const ruppert::Plc back = ruppert::parsePoly(ruppert::toPoly(mesh, plc));
  CHECK(back.pointMarkers == mesh.pointMarkers);
  CHECK(back.segmentMarkers == mesh.segmentMarkers);
  CHECK(ruppert::parseNode(ruppert::toNode(mesh)).pointMarkers == mesh.pointMarkers);
}

TEST_CASE("random markers on generated PLCs land on the subsegments and vertices of their segments", "[markers]") {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    GeneratedPlc g = seed % 3 == 0   ? randomCrossingSegments(seed, 8)
                     : seed % 3 == 1 ? randomNonCrossingSegments(seed, 30)
                                     : randomStarPolygon(seed, 20, 2);
    addRandomMarkers(g.plc, 1000 + seed);
    for (double angle : {0.0, 25.0}) {
      ruppert::Options o;
      o.minAngle = angle;
      o.edges = true;
      const ruppert::Mesh mesh = ruppert::triangulate(g.plc, o);
      INFO("seed " << seed << ", " << angle << " degrees");
      const auto problems = markerProblems(mesh, g.plc);
      INFO(describe(problems));
      CHECK(problems.empty());
      const auto edges = edgeProblems(mesh, mesh.edges, mesh.edgeMarkers);
      INFO(describe(edges));
      CHECK(edges.empty());
    }
  }
}

TEST_CASE("without input markers: 1 on the boundary (holes included), 0 inside", "[markers]") {
  const GeneratedPlc g = randomStarPolygon(7, 16, 2);
  ruppert::Options o;
  o.minAngle = 28;
  const ruppert::Mesh mesh = ruppert::triangulate(g.plc, o);
  const auto boundary = boundaryEdgesOf(mesh);
  std::vector<char> onBoundary(mesh.points.size() / 2, 0);
  for (const auto& e : boundary) onBoundary[e.first] = onBoundary[e.second] = 1;
  std::size_t inside = 0;
  for (std::size_t v = 0; v < onBoundary.size(); ++v) {
    if (mesh.vertexKinds[v] == std::uint8_t(ruppert::VertexKind::Unused)) continue;
    CHECK(mesh.pointMarkers[v] == (onBoundary[v] ? 1 : 0));
    inside += !onBoundary[v];
  }
  CHECK(inside > 0);
  for (std::size_t s = 0; s < mesh.segmentMarkers.size(); ++s) CHECK(mesh.segmentMarkers[s] == 1);
}

TEST_CASE("meshEdges lists every edge once: (3T + B) / 2 edges, V - E + T = 1 - holes", "[edges]") {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const std::size_t holes = seed % 3;
    const GeneratedPlc g = randomStarPolygon(seed, 12 + seed, holes);
    ruppert::Options o;
    o.minAngle = 30;
    const ruppert::Mesh mesh = ruppert::triangulate(g.plc, o);
    const ruppert::MeshEdges edges = ruppert::meshEdges(mesh);
    INFO("seed " << seed);
    const auto problems = edgeProblems(mesh, edges.edges, edges.markers);
    INFO(describe(problems));
    CHECK(problems.empty());
    // Euler's formula for a connected domain with h holes (the holes count as faces left out).
    const std::int64_t V = static_cast<std::int64_t>(mesh.stats.vertices), E = static_cast<std::int64_t>(edges.markers.size()),
                       T = static_cast<std::int64_t>(mesh.triangles.size() / 3);
    std::size_t holesInside = holes;
    for (const ruppert::Notice& n : mesh.notices) holesInside -= n.kind == ruppert::NoticeKind::HoleOutsideDomain;
    CHECK(V - E + T == 1 - static_cast<std::int64_t>(holesInside));
  }
}

TEST_CASE("writeEdge prints Triangle's .edge: count and 1, then index, ends and marker", "[edges][io]") {
  const GeneratedPlc g = randomStarPolygon(3, 10, 1);
  ruppert::Plc plc = g.plc;
  plc.indexBase = 1;
  plc.segmentMarkers.assign(plc.segments.size() / 2, 0);
  plc.segmentMarkers[0] = 9;
  ruppert::Options o;
  o.minAngle = 25;
  o.edges = true;
  const ruppert::Mesh mesh = ruppert::triangulate(plc, o);
  std::istringstream in(ruppert::toEdge(mesh));
  std::size_t count = 0, one = 0;
  in >> count >> one;
  REQUIRE(count == mesh.edgeMarkers.size());
  CHECK(one == 1);
  std::size_t nines = 0;
  for (std::size_t e = 0; e < count; ++e) {
    std::size_t index = 0;
    std::uint32_t a = 0, b = 0;
    std::int32_t marker = 0;
    in >> index >> a >> b >> marker;
    CHECK(index == e + 1);
    CHECK(a == mesh.edges[2 * e] + 1);
    CHECK(b == mesh.edges[2 * e + 1] + 1);
    CHECK(marker == mesh.edgeMarkers[e]);
    nines += marker == 9;
  }
  CHECK(in);
  CHECK(nines >= 1);
  // A mesh without its own edge list gets the computed one.
  ruppert::Mesh bare = mesh;
  bare.edges.clear(), bare.edgeMarkers.clear();
  CHECK(ruppert::toEdge(bare) == ruppert::toEdge(mesh));
}

#ifdef RUPPERT_CLI
TEST_CASE("cli: -e writes BASE.edge; .node, .poly and .edge carry box.poly's markers", "[markers][edges][cli]") {
  const ruppert::Plc plc = boxPoly();
  if (plc.points.empty() || !std::filesystem::exists(RUPPERT_CLI)) {
    WARN("box.poly or the ruppert executable not found: skipping");
    return;
  }
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ruppert-markers-" + std::to_string(std::random_device{}()));
  std::filesystem::create_directories(dir);
  const std::string base = (dir / "box").string();
  const std::string command = std::string("'") + RUPPERT_CLI + "' --quiet --min-angle 30 -e -o '" + base + "' '" +
                              sharedDataDir() + "/box.poly'";
  REQUIRE(std::system(command.c_str()) == 0);
  ruppert::Options o;
  o.minAngle = 30;
  o.edges = true;
  const ruppert::Mesh mesh = ruppert::triangulate(plc, o);
  const ruppert::Plc poly = ruppert::readFile(base + ".poly");
  CHECK(poly.pointMarkers == mesh.pointMarkers);
  CHECK(poly.segmentMarkers == mesh.segmentMarkers);
  CHECK(ruppert::readFile(base + ".node").pointMarkers == mesh.pointMarkers);
  std::ifstream edge(base + ".edge");
  std::stringstream text;
  text << edge.rdbuf();
  CHECK(text.str() == ruppert::toEdge(mesh));
  CHECK(text.str().find(" 5\n") != std::string::npos);
  CHECK(text.str().find(" 10\n") != std::string::npos);
  std::filesystem::remove_all(dir);
}
#endif
