// Smoothing (Options::smooth): valid, constrained Delaunay meshes at the bound, with the same
// triangle count, every area bound kept, attributes still interpolated, and rounder triangles.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "shape_families.h"
#include "validator.h"

using ruppert::Mesh;
using ruppert::Options;
using ruppert::Plc;
using ruppert_test::familyMember;
using ruppert_test::findShapeFamily;
using ruppert_test::shapeFamilies;

namespace {

Options smoothed(double angle, int passes) {
  Options o;
  o.minAngle = angle;
  o.smooth = passes;
  return o;
}

double cornerDegrees(const double* p, const double* q, const double* r) {
  const double ux = q[0] - p[0], uy = q[1] - p[1], vx = r[0] - p[0], vy = r[1] - p[1];
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / 3.14159265358979323846;
}

struct Shapes {
  double sumOfSmallest = 0;  // degrees, summed over triangles
  std::size_t obtuse = 0;
};

Shapes shapesOf(const Mesh& mesh) {
  Shapes s;
  for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
    const double* p[3];
    for (int i = 0; i < 3; ++i) p[i] = &mesh.points[2 * mesh.triangles[t + i]];
    const double a[3] = {cornerDegrees(p[0], p[1], p[2]), cornerDegrees(p[1], p[2], p[0]), cornerDegrees(p[2], p[0], p[1])};
    s.sumOfSmallest += std::min({a[0], a[1], a[2]});
    if (std::max({a[0], a[1], a[2]}) > 90) ++s.obtuse;
  }
  return s;
}

double triangleArea(const Mesh& mesh, std::size_t t) {
  const double* a = &mesh.points[2 * mesh.triangles[3 * t]];
  const double* b = &mesh.points[2 * mesh.triangles[3 * t + 1]];
  const double* c = &mesh.points[2 * mesh.triangles[3 * t + 2]];
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

}  // namespace

TEST_CASE("smoothing keeps every family's mesh valid, constrained Delaunay, at 30 degrees, same count", "[smooth][families]") {
  for (const auto& family : shapeFamilies())
    for (std::uint64_t seed : {1, 2}) {
      INFO("family " << family.name << " seed " << seed);
      const auto g = familyMember(family, seed);
      const Mesh plain = ruppert::triangulate(g.plc, smoothed(30, 0));
      const Mesh mesh = ruppert::triangulate(g.plc, smoothed(30, ruppert::kSmoothPassesWhenOn));
      CHECK(mesh.complete == plain.complete);
      CHECK(mesh.triangles.size() == plain.triangles.size());
      CHECK(mesh.points.size() == plain.points.size());
      CHECK(mesh.segments.size() == plain.segments.size());
      CHECK_VALID(mesh, ruppert_test::boundChecked(g.plc, mesh, g.area, 30));
    }
}

TEST_CASE("smoothing makes triangles rounder: larger smallest angles, fewer obtuse triangles", "[smooth][families]") {
  Shapes before, after;
  std::size_t triangles = 0;
  for (const char* name : {"airfoil", "perforated", "notched", "cloud"})
    for (std::uint64_t seed : {1, 2, 3}) {
      const auto g = familyMember(*findShapeFamily(name), seed);
      const Mesh plain = ruppert::triangulate(g.plc, smoothed(30, 0));
      const Mesh mesh = ruppert::triangulate(g.plc, smoothed(30, ruppert::kSmoothPassesWhenOn));
      const Shapes a = shapesOf(plain), b = shapesOf(mesh);
      INFO(name << " seed " << seed);
      CHECK(b.sumOfSmallest > a.sumOfSmallest);
      before.sumOfSmallest += a.sumOfSmallest, before.obtuse += a.obtuse;
      after.sumOfSmallest += b.sumOfSmallest, after.obtuse += b.obtuse;
      triangles += plain.triangles.size() / 3;
    }
  const double gain = (after.sumOfSmallest - before.sumOfSmallest) / static_cast<double>(triangles);
  INFO("mean smallest angle gain " << gain << " degrees; obtuse " << before.obtuse << " -> " << after.obtuse);
  CHECK(gain > 2);
  CHECK(static_cast<double>(after.obtuse) < 0.75 * static_cast<double>(before.obtuse));
}

// A move the smoother takes back (here: one that would make a triangle wider than maxAngle) must
// leave the mesh exactly as it was, constrained Delaunay; star seed 2 caught undo flipping edges
// named by slots that had traded triangles.
TEST_CASE("smoothing keeps maxAngle too, and a move taken back leaves the mesh Delaunay", "[smooth][max-angle]") {
  for (const char* name : {"star", "cracks", "notched", "airfoil"})
    for (std::uint64_t seed : {1, 2}) {
      INFO(name << " seed " << seed);
      const auto g = familyMember(*findShapeFamily(name), seed);
      Options o = smoothed(30, ruppert::kSmoothPassesWhenOn);
      o.maxAngle = 100;
      Options plainOptions = o;
      plainOptions.smooth = 0;
      const Mesh plain = ruppert::triangulate(g.plc, plainOptions);
      const Mesh mesh = ruppert::triangulate(g.plc, o);
      CHECK(mesh.complete == plain.complete);
      CHECK(mesh.triangles.size() == plain.triangles.size());
      ruppert_test::ValidateOptions v = ruppert_test::boundChecked(g.plc, mesh, g.area, 30);
      v.maxAngle = 100;
      CHECK_VALID(mesh, v);
    }
}

TEST_CASE("smoothing with no passes changes nothing", "[smooth]") {
  const auto g = familyMember(*findShapeFamily("skyline"), 4);
  const Mesh a = ruppert::triangulate(g.plc, smoothed(30, 0));
  Options o;
  o.minAngle = 30;
  const Mesh b = ruppert::triangulate(g.plc, o);
  CHECK(a.points == b.points);
  CHECK(a.triangles == b.triangles);
}

TEST_CASE("smoothing keeps the global, the regions' and the size function's area bounds", "[smooth]") {
  const auto g = familyMember(*findShapeFamily("perforated"), 2);
  Plc plc = g.plc;
  Options o = smoothed(28, 6);
  o.maxArea = g.area / 800;
  // A size function that grades the mesh across the domain: smoothing must not undo it.
  o.sizeFunction = [&](double x, double) { return g.area / 4000 * (1 + 4 * std::fabs(x)); };
  const Mesh plain = ruppert::triangulate(plc, smoothed(28, 0));
  const Mesh mesh = ruppert::triangulate(plc, o);
  auto v = ruppert_test::boundChecked(plc, mesh, g.area, 28);
  v.maxArea = o.maxArea;
  CHECK_VALID(mesh, v);
  for (std::size_t t = 0; t < mesh.triangles.size() / 3; ++t) {
    double cx = 0, cy = 0;
    for (int i = 0; i < 3; ++i) cx += mesh.points[2 * mesh.triangles[3 * t + i]] / 3, cy += mesh.points[2 * mesh.triangles[3 * t + i] + 1] / 3;
    INFO("triangle " << t);
    CHECK(triangleArea(mesh, t) <= o.sizeFunction(cx, cy) * (1 + 1e-9));
  }
  CHECK(mesh.triangles.size() > plain.triangles.size());  // the bounds decided the size
}

TEST_CASE("smoothing keeps each region's own area bound and attribute", "[smooth]") {
  // The unit square split by a vertical segment: a fine region on the left, a coarse one on the right.
  Plc plc;
  plc.points = {0, 0, 0.5, 0, 1, 0, 1, 1, 0.5, 1, 0, 1};
  plc.segments = {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0, 1, 4};
  plc.regions = {{0.25, 0.5, 1, 0.001}, {0.75, 0.5, 2, 0.01}};
  const Mesh mesh = ruppert::triangulate(plc, smoothed(30, 5));
  CHECK_VALID(mesh, ruppert_test::boundChecked(plc, mesh, 1.0, 30));
  REQUIRE(mesh.triangleAttributes.size() == mesh.triangles.size() / 3);
  for (std::size_t t = 0; t < mesh.triangles.size() / 3; ++t) {
    double cx = 0;
    for (int i = 0; i < 3; ++i) cx += mesh.points[2 * mesh.triangles[3 * t + i]] / 3;
    const bool left = cx < 0.5;
    INFO("triangle " << t);
    CHECK(mesh.triangleAttributes[t] == (left ? 1 : 2));
    CHECK(triangleArea(mesh, t) <= (left ? 0.001 : 0.01) * (1 + 1e-9));
  }
}

TEST_CASE("smoothing carries point attributes to the moved vertices, linearly", "[smooth]") {
  const auto g = familyMember(*findShapeFamily("channel"), 3);
  Plc plc = g.plc;
  plc.attributesPerPoint = 1;
  for (std::size_t i = 0; i < plc.points.size(); i += 2) plc.pointAttributes.push_back(3 * plc.points[i] - 2 * plc.points[i + 1] + 1);
  const Mesh mesh = ruppert::triangulate(plc, smoothed(30, 4));
  REQUIRE(mesh.pointAttributes.size() == mesh.points.size() / 2);
  double worst = 0;
  for (std::size_t v = 0; v < mesh.points.size() / 2; ++v)
    worst = std::max(worst, std::fabs(mesh.pointAttributes[v] - (3 * mesh.points[2 * v] - 2 * mesh.points[2 * v + 1] + 1)));
  CHECK(worst < 1e-9);
}

TEST_CASE("smoothing in Ruppert's box variant and above 34 degrees stays valid", "[smooth]") {
  const auto g = familyMember(*findShapeFamily("gear"), 5);
  Options box = smoothed(30, 3);
  box.variant = ruppert::Variant::BoundingBox;
  const Mesh a = ruppert::triangulate(g.plc, box);
  CHECK_VALID(a, ruppert_test::boundChecked(g.plc, a, g.area, 30));
  const Mesh b = ruppert::triangulate(g.plc, smoothed(36, 3));
  const Mesh plain = ruppert::triangulate(g.plc, smoothed(36, 0));
  CHECK(b.triangles.size() == plain.triangles.size());
  CHECK_VALID(b, ruppert_test::boundChecked(g.plc, b, g.area, b.complete ? 36 : plain.stats.reachedAngle - 1e-6));
}
