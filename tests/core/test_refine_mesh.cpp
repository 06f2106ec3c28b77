// Refining an existing mesh (Plc::triangles, triangleMaxArea; the CLI's BASE.ele input): the result
// is a valid mesh of the old mesh's domain, and every new triangle lying within an old triangle
// (all three vertices inside or on it, by exact orient2d) has at most that triangle's area bound.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "cdt/old_mesh.h"
#include "plc_generators.h"
#include "mesh/predicates.h"
#include "ruppert/ruppert.h"
#include "validator.h"

using ruppert::Mesh;
using ruppert::Plc;
namespace fs = std::filesystem;

namespace {

// The old mesh as the input of a refinement.
Plc refinementInput(const Mesh& old, const std::vector<double>& bounds) {
  Plc plc;
  plc.points = old.points;
  plc.triangles = old.triangles;
  plc.triangleMaxArea = bounds;
  return plc;
}

// Per old triangle: a random fraction of its area (1/20 to 1), or -1 (no bound) one time in four.
std::vector<double> randomBounds(const Mesh& old, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<double> bounds(old.triangles.size() / 3);
  for (std::size_t t = 0; t < bounds.size(); ++t) {
    const double* a = &old.points[2 * old.triangles[3 * t]];
    const double* b = &old.points[2 * old.triangles[3 * t + 1]];
    const double* c = &old.points[2 * old.triangles[3 * t + 2]];
    const double area = 0.5 * std::fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    const std::uint64_t r = rng();
    bounds[t] = r % 4 == 0 ? -1 : area * (1 + double(r >> 11 & 0xFFFF) / 0xFFFF * 19) / 20;
  }
  return bounds;
}

bool inside(const double* a, const double* b, const double* c, const double* p) {
  using ruppert::detail::orient2d;
  return orient2d(a, b, p) >= 0 && orient2d(b, c, p) >= 0 && orient2d(c, a, p) >= 0;
}

// Checks the promise and returns how many (new, old) containments it covered.
std::size_t checkBoundsKept(const Mesh& old, const std::vector<double>& bounds, const Mesh& mesh) {
  std::size_t covered = 0;
  for (std::size_t t = 0; 3 * t < mesh.triangles.size(); ++t) {
    const double* q[3];
    for (int i = 0; i < 3; ++i) q[i] = &mesh.points[2 * mesh.triangles[3 * t + i]];
    const double area = 0.5 * std::fabs((q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0]));
    for (std::size_t o = 0; 3 * o < old.triangles.size(); ++o) {
      if (!(bounds[o] > 0)) continue;
      const double* a = &old.points[2 * old.triangles[3 * o]];
      const double* b = &old.points[2 * old.triangles[3 * o + 1]];
      const double* c = &old.points[2 * old.triangles[3 * o + 2]];
      if (ruppert::detail::orient2d(a, b, c) < 0) std::swap(b, c);
      if (!(inside(a, b, c, q[0]) && inside(a, b, c, q[1]) && inside(a, b, c, q[2]))) continue;
      ++covered;
      INFO("new triangle " << t << " lies within old triangle " << o);
      CHECK(area <= bounds[o]);
    }
  }
  return covered;
}

ruppert_test::ValidateOptions validation(const Plc& input, double minAngle, double maxArea, double area) {
  static Plc withBoundary;
  withBoundary = ruppert::detail::withOldMeshBoundary(input);
  ruppert_test::ValidateOptions v;
  v.input = &withBoundary;
  v.minAngle = minAngle;
  v.angleExempt = [](const Mesh& m, std::uint32_t t) { return ruppert_test::nestledInInputAngle(m, t); };
  v.maxArea = maxArea;
  v.expectedArea = area;
  return v;
}

}  // namespace

TEST_CASE("refining a mesh: one bound for all triangles passes the validator at that bound", "[refine-mesh]") {
  const auto gen = ruppert_test::randomStarPolygon(7, 40, 2);
  ruppert::Options options;
  options.minAngle = 20;
  const Mesh old = ruppert::triangulate(gen.plc, options);
  REQUIRE(old.complete);
  const double bound = ruppert_test::meshArea(old) / 500;
  const Plc input = refinementInput(old, std::vector<double>(old.triangles.size() / 3, bound));
  const Mesh mesh = ruppert::triangulate(input, options);
  CHECK(mesh.complete);
  CHECK(mesh.triangles.size() / 3 > 500);
  CHECK_VALID(mesh, validation(input, 20, bound, ruppert_test::meshArea(old)));
  CHECK(checkBoundsKept(old, input.triangleMaxArea, mesh) > 0);
}

TEST_CASE("refining a mesh: random per-triangle bounds are kept on generated inputs", "[refine-mesh]") {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    INFO("seed " << seed);
    const auto gen = seed % 2 ? ruppert_test::randomStarPolygon(seed, 30, 3) : ruppert_test::randomPointsInSquare(seed, 60);
    ruppert::Options options;
    options.minAngle = seed % 3 == 0 ? 0 : 25;
    const Mesh old = ruppert::triangulate(gen.plc, options);
    const Plc input = refinementInput(old, randomBounds(old, seed));
    const Mesh mesh = ruppert::triangulate(input, options);
    CHECK(mesh.complete);
    CHECK_VALID(mesh, validation(input, options.minAngle, 0, ruppert_test::meshArea(old)));
    CHECK(checkBoundsKept(old, input.triangleMaxArea, mesh) > old.triangles.size() / 6);
  }
}

TEST_CASE("refining a mesh: bounds are kept with optimal placement, which moves vertices", "[refine-mesh]") {
  const auto gen = ruppert_test::randomStarPolygon(12, 30, 1);
  ruppert::Options options;
  options.minAngle = 36;
  options.placement = ruppert::Placement::Optimal;
  const Mesh old = ruppert::triangulate(gen.plc, {});
  const Plc input = refinementInput(old, randomBounds(old, 12));
  const Mesh mesh = ruppert::triangulate(input, options);
  CHECK_VALID(mesh, validation(input, 0, 0, ruppert_test::meshArea(old)));
  CHECK(checkBoundsKept(old, input.triangleMaxArea, mesh) > old.triangles.size() / 6);
}

TEST_CASE("refining a mesh: shared .poly inputs meshed, then refined with random per-triangle areas", "[refine-mesh]") {
  const std::string dir = ruppert_test::sharedDataDir();
  if (dir.empty()) {
    WARN("shared data folder not found (RUPPERT_SHARED_DATA): skipping the refinement of real meshes");
    return;
  }
  std::size_t refined = 0;
  for (const std::string& file : ruppert_test::polyFilesIn(dir)) {
    INFO("file: " << file);
    ruppert::Options options;
    options.minAngle = 20;
    Mesh old;
    try {
      old = ruppert::triangulate(ruppert::readFile(file), options);
    } catch (const ruppert::Error&) {
      continue;  // the hostile inputs of the folder are other tests' business
    }
    if (old.triangles.size() / 3 > 1500 || !old.complete) continue;  // the brute-force check is quadratic
    const Plc input = refinementInput(old, randomBounds(old, refined + 11));
    const Mesh mesh = ruppert::triangulate(input, options);
    CHECK(mesh.complete);
    CHECK_VALID(mesh, validation(input, 0, 0, ruppert_test::meshArea(old)));
    CHECK(checkBoundsKept(old, input.triangleMaxArea, mesh) > 0);
    ++refined;
  }
  CHECK(refined >= 10);
}

TEST_CASE("refining a mesh: the old mesh's holes stay holes without hole seeds", "[refine-mesh]") {
  const auto gen = ruppert_test::randomStarPolygon(3, 24, 2);
  REQUIRE(!gen.plc.holes.empty());
  const Mesh old = ruppert::triangulate(gen.plc, {});
  const Mesh mesh = ruppert::triangulate(refinementInput(old, std::vector<double>(old.triangles.size() / 3, gen.area / 300)), {});
  CHECK(ruppert_test::meshArea(mesh) == Approx(gen.area).epsilon(1e-9));
  CHECK(mesh.triangles.size() / 3 > 300);
}

TEST_CASE("refining a mesh: malformed triangles and bounds are named", "[refine-mesh]") {
  Plc plc;
  plc.points = {0, 0, 1, 0, 0, 1, 1, 1};
  plc.triangles = {0, 1, 2, 1, 3, 7};
  auto fails = [](const Plc& p, ruppert::ErrorCode code, const std::string& text) {
    try {
      ruppert::triangulate(p, {});
      FAIL("no error for " << text);
    } catch (const ruppert::Error& e) {
      CHECK(e.code() == code);
      CHECK_THAT(e.what(), Catch::Contains(text));
    }
  };
  fails(plc, ruppert::ErrorCode::IndexOutOfRange, "triangles[5] = 7");
  plc.triangles = {0, 1, 2, 1, 3};
  fails(plc, ruppert::ErrorCode::MalformedInput, "triangles has length 5");
  plc.triangles = {0, 1, 2, 1, 3, 2};
  plc.triangleMaxArea = {1};
  fails(plc, ruppert::ErrorCode::MalformedInput, "triangleMaxArea has 1 entries for 2 triangles");
  plc.triangleMaxArea = {1, std::nan("")};
  fails(plc, ruppert::ErrorCode::MalformedInput, "triangleMaxArea[1] is NaN");
  plc.triangleMaxArea.clear();
  plc.triangles = {0, 1, 2, 1, 1, 3};
  fails(plc, ruppert::ErrorCode::DegenerateInput, "triangles[1] = (1, 1, 3) has zero area");
  Plc noTriangles;
  noTriangles.points = plc.points;
  noTriangles.triangleMaxArea = {1};
  fails(noTriangles, ruppert::ErrorCode::MalformedInput, "no triangles");
}

TEST_CASE("refining a mesh: .ele and .area readers name file, line and value", "[refine-mesh][io]") {
  ruppert::MeshFiles f;
  f.node = "4 2 0 0\n0 0 0\n1 1 0\n2 0 1\n3 1 1\n";
  f.ele = "2 3 0\n0 0 1 2\n1 1 3 2\n";
  Plc plc = ruppert::parseMeshFiles(f);
  CHECK(plc.triangles == std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2});
  CHECK(plc.triangleMaxArea.empty());
  f.hasArea = true;
  f.area = "2\n0 0.01\n1 -1\n";
  plc = ruppert::parseMeshFiles(f);
  CHECK(plc.triangleMaxArea == std::vector<double>{0.01, -1});
  // Six-node triangles: the corners come first, the rest is ignored; attributes are read and ignored.
  f.ele = "# quadratic\n2 6 1\n0 0 1 2 0 1 2 5\n1 1 3 2 3 2 1 6\n";
  CHECK(ruppert::parseMeshFiles(f).triangles == std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2});
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"2 3 0\n0 0 1 2\n1 1 3 9\n", "<ele>:3: triangle 1: node 9 is not a point"},
      {"2 3 0\n0 0 1 2\n", "<ele>:2: expected triangle 1 (2 declared), found end of file"},
      {"1 3 0\n0 0 1 x\n", "<ele>:2: triangle 0: node 'x' is not an integer"},
      {"1 3 0\n0 0 1\n", "<ele>:2: triangle 0: expected 4 fields"},
      {"1 2 0\n0 0 1\n", "<ele>:1: nodes per triangle must be 3 or more"},
      {"1 3 0\n0 0 1 2\n1 1 3 2\n", "<ele>:3: unexpected '1' after the triangles"},
  };
  for (const auto& [ele, message] : bad) {
    f.ele = ele;
    f.hasArea = false;
    INFO(ele);
    CHECK_THROWS_WITH(ruppert::parseMeshFiles(f), Catch::Contains(message));
  }
  f.ele = "2 3 0\n0 0 1 2\n1 1 3 2\n";
  f.hasArea = true;
  f.area = "3\n0 1\n1 1\n2 1\n";
  CHECK_THROWS_WITH(ruppert::parseMeshFiles(f), Catch::Contains("<area>:1: declares 3 triangles, but the .ele has 2"));
  f.area = "2\n0 1\n1 abc\n";
  CHECK_THROWS_WITH(ruppert::parseMeshFiles(f), Catch::Contains("<area>:3: maximum area 'abc' is not a number"));
  f.hasArea = false;
  f.hasPoly = true;
  f.poly = "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n0 0\n0\n";
  CHECK_THROWS_WITH(ruppert::parseMeshFiles(f), Catch::Contains("<poly>: declares 3 points, but <node> has 4"));
  f.poly = "0 2 0 0\n1 0\n0 0 1\n1\n0 0.5 0.5\n";
  plc = ruppert::parseMeshFiles(f);
  CHECK(plc.segments == std::vector<std::uint32_t>{0, 1});
  CHECK(plc.holes.size() == 2);
}

namespace {

std::string cliPath() {
#ifdef RUPPERT_CLI
  return RUPPERT_CLI;
#else
  return "";
#endif
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int runCli(const std::string& args, const fs::path& dir) {
  const std::string command = "'" + cliPath() + "' " + args + " >'" + (dir / "out").string() + "' 2>'" + (dir / "err").string() + "'";
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

}  // namespace

TEST_CASE("refining a mesh: the CLI reads BASE.ele with BASE.node and BASE.area", "[refine-mesh][cli]") {
  if (cliPath().empty() || !fs::exists(cliPath())) {
    WARN("ruppert executable not found: skipping the CLI refinement test");
    return;
  }
  const fs::path dir = fs::temp_directory_path() / ("ruppert-refine-mesh-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto gen = ruppert_test::randomStarPolygon(5, 30, 1);
  ruppert::Options options;
  options.minAngle = 25;
  const Mesh old = ruppert::triangulate(gen.plc, options);
  const std::vector<double> bounds = randomBounds(old, 5);
  std::ofstream(dir / "old.node") << ruppert::toNode(old);
  std::ofstream(dir / "old.ele") << ruppert::toEle(old);
  {
    std::ofstream area(dir / "old.area");
    area << bounds.size() << "\n";
    char line[64];
    for (std::size_t t = 0; t < bounds.size(); ++t) {
      std::snprintf(line, sizeof line, "%zu %.17g\n", t, bounds[t]);
      area << line;
    }
  }
  REQUIRE(runCli("--min-angle 25 -o '" + (dir / "new").string() + "' '" + (dir / "old.ele").string() + "'", dir) == 0);
  ruppert::MeshFiles files;
  files.node = slurp(dir / "new.node");
  files.ele = slurp(dir / "new.ele");
  const Plc back = ruppert::parseMeshFiles(files);
  Mesh mesh;
  mesh.points = back.points;
  mesh.triangles = back.triangles;
  CHECK(mesh.triangles.size() > old.triangles.size());
  CHECK(ruppert_test::meshArea(mesh) == Approx(ruppert_test::meshArea(old)).epsilon(1e-12));
  CHECK(checkBoundsKept(old, bounds, mesh) > old.triangles.size() / 4);
  // A missing .node is named.
  fs::copy_file(dir / "old.ele", dir / "lonely.ele");
  CHECK(runCli("'" + (dir / "lonely.ele").string() + "'", dir) == 1);
  CHECK_THAT(slurp(dir / "err"), Catch::Contains("lonely.node: cannot open for reading"));
  fs::remove_all(dir);
}
