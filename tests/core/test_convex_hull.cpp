// --convex-hull (Options::convexHull): the hull's edges bound the domain as segments do, and the
// chapter's exemptions treat them as segments: a hull edge meeting a segment at a tiny angle makes
// seditious edges between their concentric shells (§6.6) that are left alone, as between two
// segments. Before, splits on hull edges were on no segment, the seditious rule never applied there,
// and refinement ran into the sliver between a long segment and nearly collinear hull edges until
// its guard stopped it (16 of 16 of the PLCs below, at 30 and 33 degrees).
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <vector>

#include "validator.h"

using ruppert::Mesh;
using ruppert::Options;
using ruppert::Plc;

namespace {

// One long, slightly tilted segment; one to three points a hair above it (1e-5 to 1e-3 of its
// length), which make the hull's upper side a chain nearly collinear with the segment; and a few
// points well below it. Only the segment is given: the hull closes the domain.
Plc segmentUnderHullSliver(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  const double half = 1000 * uniform(0.5, 2), slope = uniform(-1e-3, 1e-3);
  Plc plc;
  plc.points = {half, 0, -half, 2 * half * slope};
  auto onLine = [&](double x) { return (x - half) * -slope; };
  const int above = 1 + static_cast<int>(rng() % 3), below = 2 + static_cast<int>(rng() % 3);
  for (int k = 0; k < above; ++k) {
    const double x = uniform(-0.8 * half, 0.8 * half);
    plc.points.insert(plc.points.end(), {x, onLine(x) + uniform(1e-5, 1e-3) * half});
  }
  for (int k = 0; k < below; ++k) plc.points.insert(plc.points.end(), {uniform(-0.5 * half, 0.5 * half), -uniform(0.1, 0.3) * half});
  plc.segments = {0, 1};
  return plc;
}

}  // namespace

TEST_CASE("a segment under nearly collinear hull edges refines completely with --convex-hull", "[refine][hull]") {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    for (double angle : {30.0, 33.0}) {
      const Plc plc = segmentUnderHullSliver(seed);
      Options o;
      o.minAngle = angle;
      o.convexHull = true;
      const Mesh mesh = ruppert::triangulate(plc, o);
      INFO("seed " << seed << ", " << angle << " degrees: " << mesh.triangles.size() / 3 << " triangles");
      CHECK(mesh.complete);
      ruppert_test::ValidateOptions v;
      v.input = &plc;
      v.minAngle = angle;
      v.angleTolDeg = 1e-6;
      v.angleExempt = ruppert_test::chapterExemptions(mesh, plc);
      CHECK_VALID(mesh, v);
    }
  }
}
