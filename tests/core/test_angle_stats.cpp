// AngleStats bins every angle without an arctangent; these tests hold it to what atan2 gives.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "mesh/angle_stats.h"
#include "ruppert/ruppert.h"
#include "shape_families.h"

namespace {

using ruppert::detail::AngleStats;
using ruppert::detail::triangleAngles;
using ruppert_test::GeneratedPlc;
using ruppert_test::ShapeFamily;
using ruppert_test::familyMember;
using ruppert_test::shapeFamilies;

// The reference: three atan2-based angles per triangle, floored to whole degrees.
struct Reference {
  std::vector<std::uint64_t> histogram = std::vector<std::uint64_t>(180, 0);
  double minAngle = 180, maxAngle = 0;
  void add(const double* p0, const double* p1, const double* p2) {
    const double* p[3] = {p0, p1, p2};
    double angle[3];
    triangleAngles(p, angle);
    for (double a : angle) {
      const double d = a * (180 / 3.14159265358979323846);  // as the library converts
      ++histogram[std::min<std::size_t>(179, static_cast<std::size_t>(d))];
      minAngle = std::min(minAngle, d), maxAngle = std::max(maxAngle, d);
    }
  }
};

double orientation(const std::vector<double>& t) {
  return (t[2] - t[0]) * (t[5] - t[1]) - (t[3] - t[1]) * (t[4] - t[0]);
}

void addBoth(AngleStats& fast, Reference& ref, const std::vector<double>& t) {
  fast.add(&t[0], &t[2], &t[4]);
  ref.add(&t[0], &t[2], &t[4]);
}

}  // namespace

TEST_CASE("AngleStats bins exactly as atan2 on random, needle, flat and whole-degree triangles", "[stats]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> scale(-40, 40);
  AngleStats fast;
  Reference ref;
  for (int k = 0; k < 200000; ++k) {
    const double s = std::ldexp(1.0, scale(rng));
    std::vector<double> t(6);
    for (double& c : t) c = s * unit(rng);
    if (k % 4 == 1) t[5] = t[1] + (t[3] - t[1]) * 0.37 + s * 1e-9 * unit(rng);  // near-collinear
    if (k % 4 == 2) t[4] = t[0] + s * 1e-7 * unit(rng), t[5] = t[1] + s * 1e-7 * unit(rng);  // needle
    if (orientation(t) < 0) std::swap(t[2], t[4]), std::swap(t[3], t[5]);
    addBoth(fast, ref, t);
  }
  // Angles of exactly (or within rounding of) whole degrees: isosceles triangles with apex angle k.
  for (int k = 1; k < 180; ++k) {
    const double half = k * 3.14159265358979323846 / 360;
    addBoth(fast, ref, {0, 0, std::sin(half), -std::cos(half), -std::sin(half), -std::cos(half)});
    addBoth(fast, ref, {0, 0, 1, 0, std::cos(2 * half), std::sin(2 * half)});
  }
  addBoth(fast, ref, {0, 0, 1, 0, 0, 1});                  // 90, 45, 45
  addBoth(fast, ref, {0, 0, std::sqrt(3.0), 0, 0, 1});     // 90, 30, 60 up to rounding
  addBoth(fast, ref, {0, 0, 1, 0, 0.5, 1e-13});            // a needle flat to 1e-13
  CHECK(fast.histogram() == ref.histogram);
  CHECK(fast.minAngle() == Approx(ref.minAngle).epsilon(1e-12).margin(0));
  CHECK(fast.maxAngle() == Approx(ref.maxAngle).epsilon(1e-12));
  CHECK(fast.minAngle() < 1e-10);
}

TEST_CASE("AngleStats extremes are exact for the smallest needles", "[stats]") {
  AngleStats fast;
  Reference ref;
  for (double h : {1e-3, 1e-9, 3e-15, 1e-15}) addBoth(fast, ref, {0, 0, 1, 0, 0.5, h});
  CHECK(fast.minAngle() == ref.minAngle);
  CHECK(fast.maxAngle() == ref.maxAngle);
  AngleStats none;
  CHECK(none.minAngle() == 0);
  CHECK(none.maxAngle() == 0);
  CHECK(std::count(none.histogram().begin(), none.histogram().end(), 0u) == 180);
}

// Refinement's last census gathers the statistics the mesh reports (output assembly measures only
// where refinement did not run, or where the mesh changed after it): whichever measured them, they
// must be the statistics of the triangles returned. Output coordinates are the internal ones
// scaled by a power of two, so recomputing from them gives the same bits.
TEST_CASE("reported angle statistics are those of the returned triangles", "[stats]") {
  struct Case {
    const char* name;
    double minAngle;
    ruppert::Variant variant;
    int smooth;
    double maxArea;
  };
  const Case cases[] = {{"default", 30, ruppert::Variant::Constrained, 0, 0},
                        {"cdt", 0, ruppert::Variant::Constrained, 0, 0},
                        {"area", 25, ruppert::Variant::Constrained, 0, 0.01},
                        {"box", 30, ruppert::Variant::BoundingBox, 0, 0},
                        {"smooth", 30, ruppert::Variant::Constrained, 2, 0},
                        {"search", 36, ruppert::Variant::Constrained, 0, 0}};
  int checked = 0;
  for (const ShapeFamily& family : shapeFamilies()) {
    const GeneratedPlc g = familyMember(family, 3);
    for (const Case& c : cases) {
      ruppert::Options o;
      o.minAngle = c.minAngle, o.variant = c.variant, o.smooth = c.smooth;
      if (c.maxArea > 0) o.maxArea = c.maxArea * g.area;
      const ruppert::Mesh mesh = ruppert::triangulate(g.plc, o);
      AngleStats again;
      for (std::size_t t = 0; 3 * t < mesh.triangles.size(); ++t)
        again.add(&mesh.points[2 * std::size_t(mesh.triangles[3 * t])], &mesh.points[2 * std::size_t(mesh.triangles[3 * t + 1])],
                  &mesh.points[2 * std::size_t(mesh.triangles[3 * t + 2])]);
      INFO(family.name << " " << c.name);
      CHECK(mesh.stats.angleHistogram == again.histogram());
      double lo, hi;
      again.extremes(lo, hi);
      CHECK(mesh.stats.minAngle == lo);
      CHECK(mesh.stats.maxAngle == hi);
      ++checked;
    }
  }
  CHECK(checked >= 15 * 6);
}
