// Metamorphic tests: transform the input in ways whose effect on the mesh is known, and compare.
//
// Exact transformations (scaling by 2^k, translating dyadic coordinates by integers, rotating by 90
// degrees, relabelling) do not change any predicate's sign, so they cannot change the constrained
// Delaunay triangulation when it is unique. When it is not unique (four cocircular points across an
// unconstrained edge), only the triangle count is determined; scaling by 2^k must still give the very
// same triangles, because the mesher normalizes by a power of two itself and then sees identical bits.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "plc_generators.h"
#include "validator.h"

using namespace ruppert_test;
using ruppert::Mesh;
using ruppert::Plc;

namespace {

struct Case {
  std::string name;
  Plc plc;
  double area = -1;          // expected domain area, or -1 when unknown
  bool dyadic = false;       // coordinates are multiples of 2^-20 in [0, 1] (integer shifts are exact)
  bool enclosed = true;      // segments enclose the domain (a shifted copy stays a separate component)
  bool nearDegenerate = true;  // collinear or cocircular input points: inexact scaling may change counts
};

ruppert::Options cdtOptions() {
  ruppert::Options o;
  o.minAngle = 0;
  return o;
}

Mesh cdt(const Plc& plc) { return ruppert::triangulate(plc, cdtOptions()); }

using TriangleSet = std::set<std::array<std::uint32_t, 3>>;

// Triangles as vertex triples, each rotated to start at its smallest index (keeping orientation),
// optionally relabeled first.
TriangleSet triangleSet(const Mesh& m, const std::vector<std::uint32_t>* relabel = nullptr) {
  TriangleSet set;
  for (std::size_t t = 0; t < m.triangles.size() / 3; ++t) {
    std::array<std::uint32_t, 3> v{m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]};
    if (relabel)
      for (auto& x : v) x = x < relabel->size() ? (*relabel)[x] : x;
    while (v[0] > v[1] || v[0] > v[2]) v = {v[1], v[2], v[0]};
    set.insert(v);
  }
  return set;
}

// Triangles as coordinate triples (rotated to start at the smallest point, keeping orientation).
// New vertices (crossings) are numbered in creation order, which depends on the input's order, so
// reordering tests compare by coordinates.
using PointTriple = std::array<std::pair<double, double>, 3>;
std::set<PointTriple> geometricTriangleSet(const Mesh& m) {
  std::set<PointTriple> set;
  for (std::size_t t = 0; t < m.triangles.size() / 3; ++t) {
    PointTriple v;
    for (int i = 0; i < 3; ++i) v[i] = {m.points[2 * m.triangles[3 * t + i]], m.points[2 * m.triangles[3 * t + i] + 1]};
    while (v[0] > v[1] || v[0] > v[2]) v = {v[1], v[2], v[0]};
    set.insert(v);
  }
  return set;
}

std::vector<Case> generatedCases() {
  std::vector<Case> cases;
  for (std::uint64_t seed : {11u, 12u, 13u}) {
    const std::string s = std::to_string(seed);
    auto g = randomPointsInSquare(seed, 150);
    cases.push_back({"randomPointsInSquare seed " + s, g.plc, g.area, true, true, false});
    g = randomStarPolygon(seed, 40, 3);
    cases.push_back({"randomStarPolygon seed " + s, g.plc, g.area, true, true, false});
    g = randomNonCrossingSegments(seed, 80);
    cases.push_back({"randomNonCrossingSegments seed " + s, g.plc, g.area, true, true, false});
  }
  auto g = randomPointSet(5, 120);
  cases.push_back({"randomPointSet seed 5", g.plc, -1, true, false, false});
  g = gridPlc(12, 9, 0x1p-4, true);
  cases.push_back({"gridPlc 12x9 with cross lines", g.plc, g.area, true, true, true});
  return cases;
}

// A few small real PLCs (when the shared data is present) and the saved regression fixtures.
std::vector<Case> fixtureCases() {
  std::vector<Case> cases;
  const std::string dir = sharedDataDir();
  if (!dir.empty())
    for (const char* name : {"cdt_guitar.poly", "la.poly", "p2t_bird.poly", "double_hex.poly", "earcut_dude.poly",
                             "face.poly", "superior.poly", "cdt_square_crack.poly"}) {
      Case c;
      c.name = name;
      c.plc = ruppert::readFile(dir + "/" + name);
      cases.push_back(c);
    }
  for (const auto& file : polyFilesIn(fixturesDir())) {
    Case c;
    c.name = file;
    c.plc = ruppert::readFile(file);
    cases.push_back(c);
  }
  return cases;
}

std::vector<Case> allCases() {
  auto cases = generatedCases();
  auto fixtures = fixtureCases();
  cases.insert(cases.end(), fixtures.begin(), fixtures.end());
  return cases;
}

ValidateOptions against(const Plc& plc, double area) {
  ValidateOptions v;
  v.input = &plc;
  v.expectedArea = area;
  return v;
}

std::vector<std::uint32_t> subsegmentSet(const Mesh& m) {
  std::vector<std::uint32_t> keys;
  for (std::size_t k = 0; k < m.segmentIds.size(); ++k) {
    const std::uint32_t a = m.segments[2 * k], b = m.segments[2 * k + 1];
    keys.push_back(std::min(a, b));
    keys.push_back(std::max(a, b));
  }
  // Sort pairs as units.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::size_t i = 0; i < keys.size(); i += 2) pairs.emplace_back(keys[i], keys[i + 1]);
  std::sort(pairs.begin(), pairs.end());
  keys.clear();
  for (const auto& p : pairs) keys.insert(keys.end(), {p.first, p.second});
  return keys;
}

// True when adding (dx, dy) to every coordinate of plc is exact (so the transform changes no sign).
bool translationIsExact(const Plc& plc, double dx, double dy) {
  for (std::size_t i = 0; i + 1 < plc.points.size(); i += 2)
    if ((plc.points[i] + dx) - dx != plc.points[i] || (plc.points[i + 1] + dy) - dy != plc.points[i + 1]) return false;
  return true;
}

// The same CDT when it is unique; otherwise at least the same number of triangles.
void checkSameTopology(const Mesh& base, const Mesh& other, const std::vector<std::uint32_t>* relabel = nullptr) {
  CHECK(other.triangles.size() == base.triangles.size());
  if (hasUniqueCdt(base)) CHECK(triangleSet(base, relabel) == triangleSet(other));
}

// The untransformed mesh, or false (with a warning) when it is already invalid: then the input is a
// known failure that the [cdt] tests report, and comparing transformed meshes with it means nothing.
bool baseMesh(const Case& c, Mesh& mesh) {
  std::vector<std::string> problems;
  try {
    mesh = cdt(c.plc);
    problems = validateMesh(mesh, against(c.plc, c.area));
  } catch (const std::exception& e) {
    problems.push_back(std::string("threw: ") + e.what());
  }
  if (problems.empty()) return true;
  WARN("skipping " << c.name << ": its untransformed mesh already fails (" << problems[0] << ")");
  return false;
}

}  // namespace

TEST_CASE("scaling by powers of two gives the very same triangles", "[metamorphic]") {
  for (const Case& c : allCases()) {
    INFO("input: " << c.name);
    Mesh base;
    if (!baseMesh(c, base)) continue;
    const TriangleSet expected = triangleSet(base);
    std::vector<int> exponents;
    for (int k = -30; k <= 30; ++k) exponents.push_back(k);
    exponents.insert(exponents.end(), {-500, 500});
    for (int k : exponents) {
      INFO("scale 2^" << k);
      const double factor = std::ldexp(1.0, k);
      const Plc plc = scaled(c.plc, factor);
      const Mesh mesh = cdt(plc);
      const bool areaRepresentable = std::abs(k) <= 200;
      CHECK_VALID(mesh, against(plc, areaRepresentable && c.area >= 0 ? c.area * factor * factor : -1));
      CHECK(triangleSet(mesh) == expected);
      CHECK(subsegmentSet(mesh) == subsegmentSet(base));
      // New vertices (intersections) scale exactly too.
      REQUIRE(mesh.points.size() == base.points.size());
      bool pointsScaled = true;
      for (std::size_t i = 0; i < mesh.points.size(); ++i) pointsScaled = pointsScaled && mesh.points[i] == base.points[i] * factor;
      CHECK(pointsScaled);
    }
  }
}

TEST_CASE("scaling by 1e-9 and 1e9 keeps meshes valid", "[metamorphic]") {
  for (const Case& c : allCases()) {
    INFO("input: " << c.name);
    Mesh base;
    if (!baseMesh(c, base)) continue;
    for (double factor : {1e-9, 1e9}) {
      INFO("scale " << factor);
      const Plc plc = scaled(c.plc, factor);
      const Mesh mesh = cdt(plc);
      // Inexact scaling moves points by an ulp: the area check needs a looser tolerance.
      ValidateOptions v = against(plc, c.area >= 0 ? c.area * factor * factor : -1);
      v.areaRelTol = 1e-6;
      CHECK_VALID(mesh, v);
      if (!c.nearDegenerate) CHECK(mesh.triangles.size() == base.triangles.size());
    }
  }
}

TEST_CASE("extreme scales 1e-200 and 1e200 still mesh validly", "[metamorphic]") {
  for (const Case& c : allCases()) {
    INFO("input: " << c.name);
    Mesh base;
    if (!baseMesh(c, base)) continue;
    for (double factor : {1e-200, 1e200}) {
      INFO("scale " << factor);
      const Plc plc = scaled(c.plc, factor);
      const Mesh mesh = cdt(plc);
      CHECK_VALID(mesh, against(plc, -1));  // areas of 1e-400 / 1e400 are not representable
      if (!c.nearDegenerate) CHECK(mesh.triangles.size() == base.triangles.size());
    }
  }
}

TEST_CASE("exact integer translations keep the topology", "[metamorphic]") {
  const double offsets[][2] = {{3, -7}, {1024, -4096}, {-0x1p30, 0x1p31}};
  for (const Case& c : allCases()) {
    INFO("input: " << c.name);
    Mesh base;
    if (!baseMesh(c, base)) continue;
    for (const auto& d : offsets) {
      if (!translationIsExact(c.plc, d[0], d[1])) continue;  // only exact shifts are comparable
      INFO("offset (" << d[0] << ", " << d[1] << ")");
      const Plc plc = translated(c.plc, d[0], d[1]);
      const Mesh mesh = cdt(plc);
      ValidateOptions v = against(plc, c.area);
      v.areaRelTol = 1e-6;  // triangle areas are computed from large coordinates: cancellation
      CHECK_VALID(mesh, v);
      checkSameTopology(base, mesh);
    }
  }
}

TEST_CASE("rotating by 90 degrees keeps the topology", "[metamorphic]") {
  for (const Case& c : allCases()) {
    INFO("input: " << c.name);
    Mesh base;
    if (!baseMesh(c, base)) continue;
    Plc plc = c.plc;
    for (int quarter = 1; quarter <= 4; ++quarter) {
      INFO("rotated " << quarter << " quarter turns");
      plc = rotated90(plc);
      const Mesh mesh = cdt(plc);
      CHECK_VALID(mesh, against(plc, c.area));
      checkSameTopology(base, mesh);
    }
  }
}

TEST_CASE("reordering points and segments only relabels the mesh", "[metamorphic]") {
  for (const Case& c : allCases()) {
    INFO("input: " << c.name);
    Mesh base;
    if (!baseMesh(c, base)) continue;
    for (std::uint64_t seed : {1u, 2u}) {
      INFO("permutation seed " << seed);
      std::vector<std::uint32_t> newIndex;
      const Plc plc = permuted(c.plc, seed, &newIndex);
      const Mesh mesh = cdt(plc);
      CHECK_VALID(mesh, against(plc, c.area));
      CHECK(mesh.triangles.size() == base.triangles.size());
      if (hasUniqueCdt(base)) CHECK(geometricTriangleSet(base) == geometricTriangleSet(mesh));
      (void)newIndex;
    }
  }
}

TEST_CASE("a disjoint shifted copy doubles the triangles", "[metamorphic]") {
  for (const Case& c : allCases()) {
    if (!c.enclosed) continue;  // a point set's convex hull would join the copies
    INFO("input: " << c.name);
    Mesh base;
    if (!baseMesh(c, base)) continue;
    // Shift by a power of two at least twice the extent, so the copies are far apart.
    double extent = 0;
    for (double v : c.plc.points) extent = std::max(extent, std::fabs(v));
    const double dx = std::ldexp(1.0, std::ilogb(std::max(extent, 1e-300)) + 3);
    const Plc plc = withShiftedCopy(c.plc, dx);
    const Mesh mesh = cdt(plc);
    const bool exact = translationIsExact(c.plc, dx, 0);
    ValidateOptions v = against(plc, c.area >= 0 ? 2 * c.area : -1);
    v.areaRelTol = 1e-6;
    CHECK_VALID(mesh, v);
    if (exact || !c.nearDegenerate) CHECK(mesh.triangles.size() == 2 * base.triangles.size());
  }
}

// The core keeps no per-triangle region data when no region seed lies in the domain (every triangle
// then has attribute 0 and the global area bound). A seed in every part of the domain that restates
// exactly that makes it keep the arrays: the refined meshes must be the same, triangle for triangle.
TEST_CASE("a region seed that restates the global bound changes nothing", "[metamorphic][attributes]") {
  int compared = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const GeneratedPlc g = randomStarPolygon(seed, 12 + 4 * seed, 0);
    Plc plc = g.plc;
    ruppert::Options o;
    o.minAngle = seed % 2 ? 30 : 33;
    o.maxArea = g.area / 300;
    const Mesh plain = triangulate(plc, o);
    ruppert::Region r;
    r.x = 0.5, r.y = 0.5, r.maxArea = o.maxArea;  // the star's center is inside it; attribute 0
    plc.regions.push_back(r);
    const Mesh restated = triangulate(plc, o);
    INFO("seed " << seed);
    REQUIRE(plain.complete);
    CHECK(plain.triangles.size() / 3 > 200);
    CHECK(restated.points == plain.points);
    CHECK(restated.triangles == plain.triangles);
    CHECK(restated.triangleAttributes == plain.triangleAttributes);
    ++compared;
  }
  CHECK(compared == 6);
}
