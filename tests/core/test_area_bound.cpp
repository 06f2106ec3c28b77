// Refinement under an area bound (Options::maxArea): the too-large triangles are split largest
// first (bad_triangle_queue.h), and skinny triangles within their area bound get the locally
// optimal point as they do without one (refine_split.cpp). Both lower the triangle count where
// the bound decides the mesh: tests/bench/results/area-bound.md has the measurements.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "refine/placement/refine_geometry.h"
#include "shape_families.h"
#include "validator.h"

using ruppert::Mesh;
using ruppert::Options;
using ruppert::Placement;
using ruppert::Plc;

namespace {

Plc unitSquare() {
  Plc plc;
  plc.points = {0, 0, 1, 0, 1, 1, 0, 1};
  plc.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  return plc;
}

double bboxArea(const Plc& plc) {
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for (std::size_t i = 0; i < plc.points.size(); ++i) {
    lo[i % 2] = std::min(lo[i % 2], plc.points[i]);
    hi[i % 2] = std::max(hi[i % 2], plc.points[i]);
  }
  return (hi[0] - lo[0]) * (hi[1] - lo[1]);
}

ruppert_test::ValidateOptions bounded(const Plc& plc, const Mesh& mesh, double area, double angle, double maxArea) {
  ruppert_test::ValidateOptions v;
  v.input = &plc;
  v.expectedArea = area;
  v.minAngle = angle;
  v.angleTolDeg = 1e-6;
  v.maxArea = maxArea;
  v.angleExempt = ruppert_test::chapterExemptions(mesh, plc);
  return v;
}

}  // namespace

TEST_CASE("a square under an area bound alone is split largest first into a grid of right triangles", "[refine][area]") {
  // Each split of the largest right isosceles triangle at its circumcenter (its hypotenuse's
  // midpoint) halves it: largest first, every triangle reaches the bound at the same depth, 2^k
  // congruent triangles with the largest k whose area 2^-k is within the bound. Splitting the
  // newest first (the queue's order before) left pieces at several depths: 1,565 triangles.
  for (const auto& [maxArea, expected] : std::vector<std::pair<double, std::size_t>>{{1e-3, 1024}, {0.01, 128}, {3e-4, 4096}}) {
    Options o;
    o.minAngle = 30;
    o.maxArea = maxArea;
    const Plc plc = unitSquare();
    const Mesh mesh = ruppert::triangulate(plc, o);
    INFO("max area " << maxArea);
    CHECK(mesh.complete);
    CHECK(mesh.triangles.size() / 3 == expected);
    CHECK_VALID(mesh, bounded(plc, mesh, 1.0, 30, maxArea));
  }
}

TEST_CASE("a size off-center makes the triangle on the shortest edge as large as the bound allows", "[refine][area]") {
  using ruppert::detail::sizeOffCenter;
  const double theta = 30 * 3.14159265358979323846 / 180;
  // A tall acute triangle on u-w: its circumcenter lies 1.5 above the edge's midpoint (1, 0).
  const double u[2] = {0, 0}, w[2] = {2, 0}, cc[2] = {1, 1.5};
  double x[2];
  REQUIRE(sizeOffCenter(u, w, cc, 1.0, theta, x));
  CHECK(x[0] == Approx(1));
  // Area of u-w-x: |uw| * height / 2 = 0.98 of the bound.
  CHECK(x[1] == Approx(ruppert::detail::kSizeFill * 1.0));
  // A bound so large the circumcenter is nearer: none.
  CHECK_FALSE(sizeOffCenter(u, w, cc, 2.0, theta, x));
  // A bound so small the angles at u and w would be under theta (height < tan(30) = 0.577): none.
  CHECK_FALSE(sizeOffCenter(u, w, cc, 0.5, theta, x));
  const double right[3][2] = {{0, 0}, {1, 0}, {0, 1}}, acute[3][2] = {{0, 0}, {1, 0}, {0.4, 1}};
  const double* r[3] = {right[0], right[1], right[2]};
  const double* a[3] = {acute[0], acute[1], acute[2]};
  CHECK_FALSE(ruppert::detail::isAcute(r));
  CHECK(ruppert::detail::isAcute(a));
}

TEST_CASE("with an area bound the default placement makes fewer triangles than off-centers", "[refine][area]") {
  // The locally optimal point is used for skinny triangles within their area bound (before, any
  // area bound turned it off and the default made exactly the off-centers' mesh). Three members of
  // every shape family at 33 degrees, max area = bounding box / 3000.
  double logRatio = 0;
  int count = 0;
  for (const auto& family : ruppert_test::shapeFamilies()) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const auto g = ruppert_test::familyMember(family, seed);
      Options o;
      o.minAngle = 33;
      o.maxArea = bboxArea(g.plc) / 3000;
      const Mesh optimal = ruppert::triangulate(g.plc, o);
      o.placement = Placement::OffCenter;
      const Mesh offCenter = ruppert::triangulate(g.plc, o);
      INFO(family.name << "-" << seed);
      REQUIRE(optimal.complete);
      CHECK_VALID(optimal, bounded(g.plc, optimal, g.area, 33, o.maxArea));
      logRatio += std::log(double(optimal.triangles.size()) / double(offCenter.triangles.size()));
      ++count;
    }
  }
  const double geometricMean = std::exp(logRatio / count);
  INFO("default / off-centers, geometric mean over " << count << " PLCs: " << geometricMean);
  CHECK(geometricMean < 0.97);
}
