// Quadratic elements (addQuadraticNodes, --order 2) and the Voronoi dual (voronoiDiagram, --voronoi).
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "plc_generators.h"
#include "mesh/predicates.h"
#include "ruppert/ruppert.h"

using ruppert::Mesh;
namespace fs = std::filesystem;

namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;
Edge edgeOf(std::uint32_t a, std::uint32_t b) { return a < b ? Edge{a, b} : Edge{b, a}; }

// Every edge of the mesh with the triangles (t, i: edge i of t) that have it.
std::map<Edge, std::vector<std::pair<std::uint32_t, int>>> edgesOf(const Mesh& m) {
  std::map<Edge, std::vector<std::pair<std::uint32_t, int>>> edges;
  for (std::uint32_t t = 0; 3 * t < m.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) edges[edgeOf(m.triangles[3 * t + (i + 1) % 3], m.triangles[3 * t + (i + 2) % 3])].push_back({t, i});
  return edges;
}

// Whether x + y is exact in doubles (Knuth's TwoSum leaves no error).
bool exactSum(double x, double y) {
  const double s = x + y, yy = s - x;
  return (x - (s - yy)) + (y - yy) == 0;
}

std::vector<Mesh> sampleMeshes() {
  std::vector<Mesh> meshes;
  ruppert::Options options;
  options.minAngle = 25;
  meshes.push_back(ruppert::triangulate(ruppert_test::randomStarPolygon(4, 30, 2).plc, options));
  meshes.push_back(ruppert::triangulate(ruppert_test::randomPointsInSquare(9, 80).plc, options));
  options.minAngle = 0;
  meshes.push_back(ruppert::triangulate(ruppert_test::randomPointsInSquare(10, 50).plc, options));
  const std::string dir = ruppert_test::sharedDataDir();
  if (dir.empty()) {
    WARN("shared data folder not found (RUPPERT_SHARED_DATA): quadratic and Voronoi tests on generated inputs only");
    return meshes;
  }
  options.minAngle = 20;
  for (const char* name : {"/A.poly", "/box.poly", "/cdt_guitar.poly"}) {
    if (!fs::exists(dir + name)) continue;
    meshes.push_back(ruppert::triangulate(ruppert::readFile(dir + name), options));
  }
  return meshes;
}

}  // namespace

TEST_CASE("quadratic nodes: exact midpoints, shared across interior edges, V + E nodes", "[derived]") {
  for (const Mesh& corners : sampleMeshes()) {
    Mesh m = corners;
    ruppert::addQuadraticNodes(m);
    const auto edges = edgesOf(corners);
    const std::size_t v = corners.points.size() / 2;
    REQUIRE(m.points.size() / 2 == v + edges.size());
    REQUIRE(m.triangles6.size() == 2 * m.triangles.size());
    REQUIRE(m.pointMarkers.size() == m.points.size() / 2);
    std::set<std::uint32_t> used;
    for (const auto& [edge, sides] : edges) {
      const std::uint32_t node = m.triangles6[6 * sides[0].first + 3 + sides[0].second];
      used.insert(node);
      CHECK(node >= v);
      for (const auto& [t, i] : sides) CHECK(m.triangles6[6 * t + 3 + i] == node);  // shared by both triangles
      const double* a = &m.points[2 * edge.first];
      const double* b = &m.points[2 * edge.second];
      const double* p = &m.points[2 * node];
      CHECK(p[0] == 0.5 * a[0] + 0.5 * b[0]);
      CHECK(p[1] == 0.5 * a[1] + 0.5 * b[1]);
      // Where the midpoint is representable (the generated inputs' dyadic coordinates) it is exact.
      if (exactSum(a[0], b[0]) && exactSum(a[1], b[1]))
        CHECK(ruppert::detail::orient2d(a, b, p) == 0);
      // On a subsegment its marker (as a vertex inserted there gets), else 1 on the boundary, 0 inside.
      int expected = sides.size() == 1 ? 1 : 0;
      for (std::size_t k = 0; k + 1 < corners.segments.size(); k += 2)
        if (edgeOf(corners.segments[k], corners.segments[k + 1]) == edge)
          expected = k / 2 < corners.segmentMarkers.size() ? corners.segmentMarkers[k / 2] : 1;
      CHECK(m.pointMarkers[node] == expected);
    }
    CHECK(used.size() == edges.size());
    for (std::size_t t = 0; 3 * t < m.triangles.size(); ++t)
      for (int i = 0; i < 3; ++i) CHECK(m.triangles6[6 * t + i] == m.triangles[3 * t + i]);
    // The .ele says 6 nodes per triangle and reads back with the same corners.
    const std::string ele = ruppert::toEle(m);
    CHECK(ele.substr(0, ele.find('\n')).find(" 6 ") != std::string::npos);
    ruppert::MeshFiles files;
    files.node = ruppert::toNode(m);
    files.ele = ele;
    CHECK(ruppert::parseMeshFiles(files).triangles == m.triangles);
  }
}

TEST_CASE("voronoi: equidistant circumcenters, one dual per mesh edge, rays outward", "[derived]") {
  for (const Mesh& m : sampleMeshes()) {
    const ruppert::Voronoi vd = ruppert::voronoiDiagram(m);
    const std::size_t n = m.triangles.size() / 3;
    REQUIRE(vd.points.size() == 2 * n);
    for (std::size_t t = 0; t < n; ++t) {
      const double* c = &vd.points[2 * t];
      double r[3];
      for (int i = 0; i < 3; ++i) {
        const double* p = &m.points[2 * m.triangles[3 * t + i]];
        r[i] = std::hypot(p[0] - c[0], p[1] - c[1]);
      }
      CHECK(std::fabs(r[1] - r[0]) <= 1e-9 * r[0]);
      CHECK(std::fabs(r[2] - r[0]) <= 1e-9 * r[0]);
    }
    const auto edges = edgesOf(m);
    REQUIRE(vd.edges.size() == 2 * edges.size());
    REQUIRE(vd.meshEdges.size() == 2 * edges.size());
    std::set<Edge> seen;
    for (std::size_t e = 0; 2 * e < vd.edges.size(); ++e) {
      const Edge edge = edgeOf(vd.meshEdges[2 * e], vd.meshEdges[2 * e + 1]);
      CHECK(seen.insert(edge).second);
      const auto& sides = edges.at(edge);
      std::set<std::int32_t> duals{vd.edges[2 * e], vd.edges[2 * e + 1]};
      if (sides.size() == 2) {
        CHECK(duals == std::set<std::int32_t>{std::int32_t(sides[0].first), std::int32_t(sides[1].first)});
        CHECK(vd.rayDirections[2 * e] == 0);
        CHECK(vd.rayDirections[2 * e + 1] == 0);
        continue;
      }
      // A ray: from its triangle's circumcenter, perpendicular to the edge, away from the apex.
      REQUIRE(sides.size() == 1);
      CHECK(vd.edges[2 * e] == std::int32_t(sides[0].first));
      CHECK(vd.edges[2 * e + 1] == -1);
      const double* a = &m.points[2 * edge.first];
      const double* b = &m.points[2 * edge.second];
      const double* apex = &m.points[2 * m.triangles[3 * sides[0].first + sides[0].second]];
      const double dx = vd.rayDirections[2 * e], dy = vd.rayDirections[2 * e + 1];
      const double ex = b[0] - a[0], ey = b[1] - a[1];
      CHECK(std::fabs(dx * ex + dy * ey) <= 1e-12 * (ex * ex + ey * ey));
      CHECK(dx * (apex[0] - a[0]) + dy * (apex[1] - a[1]) < 0);
    }
    CHECK(seen.size() == edges.size());
  }
}

namespace {

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t firstNumber(const std::string& text) { return std::stoul(text.substr(0, text.find(' '))); }

}  // namespace

TEST_CASE("cli: --order 2 and --voronoi write 6-node triangles and BASE.v.node / BASE.v.edge", "[derived][cli]") {
#ifndef RUPPERT_CLI
  WARN("ruppert executable not configured: skipping");
#else
  const fs::path dir = fs::temp_directory_path() / ("ruppert-derived-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const Mesh m = ruppert::triangulate(ruppert_test::randomStarPolygon(8, 20, 1).plc, {});
  std::ofstream(dir / "in.node") << ruppert::toNode(m);
  std::ofstream(dir / "in.ele") << ruppert::toEle(m);
  auto run = [&](const std::string& args) {
    const std::string command = std::string("'") + RUPPERT_CLI + "' " + args + " >'" + (dir / "out").string() + "' 2>'" + (dir / "err").string() + "'";
    const int raw = std::system(command.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  };
  // Refining with no bounds and no angle leaves the mesh as it is: its edges are the ones counted.
  REQUIRE(run("--min-angle 0 --order 2 --voronoi -o '" + (dir / "q").string() + "' '" + (dir / "in.ele").string() + "'") == 0);
  const std::size_t edges = edgesOf(m).size();
  CHECK(firstNumber(slurp(dir / "q.node")) == m.points.size() / 2 + edges);
  const std::string ele = slurp(dir / "q.ele");
  CHECK(ele.substr(0, ele.find('\n')) == std::to_string(m.triangles.size() / 3) + " 6 0");
  CHECK(firstNumber(slurp(dir / "q.v.node")) == m.triangles.size() / 3);
  const std::string vedge = slurp(dir / "q.v.edge");
  CHECK(firstNumber(vedge) == edges);
  std::size_t rays = 0;
  for (std::size_t at = vedge.find(" -1 "); at != std::string::npos; at = vedge.find(" -1 ", at + 1)) ++rays;
  std::size_t boundary = 0;
  for (const auto& [edge, sides] : edgesOf(m)) boundary += sides.size() == 1;
  CHECK(rays == boundary);
  CHECK(run("--order 3 x.poly") == 2);
  CHECK(run("--order 2 --format json x.poly") == 2);
  CHECK_THAT(slurp(dir / "err"), Catch::Contains("--order 2 writes Triangle's .node and .ele"));
  fs::remove_all(dir);
#endif
}

// Midpoint nodes take the marker of the subsegment they split and attributes interpolated from the
// edge's ends: a linear field stays linear at every node of a 6-node mesh.
TEST_CASE("quadratic nodes carry segment markers and interpolated attributes", "[derived][markers][attributes]") {
  ruppert::Plc plc;
  plc.points = {0, 0, 4, 0, 4, 3, 0, 3, 1, 1, 3, 2};
  plc.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5};
  plc.segmentMarkers = {7, 0, 9, 0, 11};
  plc.attributesPerPoint = 1;
  for (std::size_t i = 0; i < plc.points.size() / 2; ++i)
    plc.pointAttributes.push_back(2 * plc.points[2 * i] - 3 * plc.points[2 * i + 1] + 5);
  ruppert::Options o;
  o.maxArea = 0.5;
  Mesh m = ruppert::triangulate(plc, o);
  const Mesh corners = m;
  ruppert::addQuadraticNodes(m);
  REQUIRE(m.attributesPerPoint == 1);
  REQUIRE(m.pointAttributes.size() == m.points.size() / 2);
  std::set<int> seen;
  for (std::size_t v = 0; v < m.points.size() / 2; ++v)
    CHECK(m.pointAttributes[v] == Approx(2 * m.points[2 * v] - 3 * m.points[2 * v + 1] + 5).margin(1e-12));
  for (std::size_t s = 0; s < corners.segmentIds.size(); ++s) {
    const auto edge = edgeOf(corners.segments[2 * s], corners.segments[2 * s + 1]);
    for (std::size_t t = 0; 3 * t < m.triangles.size(); ++t)
      for (int i = 0; i < 3; ++i)
        if (edgeOf(m.triangles[3 * t + (i + 1) % 3], m.triangles[3 * t + (i + 2) % 3]) == edge) {
          CHECK(m.pointMarkers[m.triangles6[6 * t + 3 + i]] == corners.segmentMarkers[s]);
          seen.insert(corners.segmentMarkers[s]);
        }
  }
  CHECK(seen == std::set<int>{1, 7, 9, 11});  // 1: the unmarked boundary segments
}
