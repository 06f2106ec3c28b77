// Segments that nearly overlap: pairs and fans meeting at 1e-3 to 1e-12 rad, sharing an
// apex or starting and ending a hair apart, crossed by others (nearOverlaps in plc_generators.h),
// and the three careless inputs that an independent checker flagged (tests/hostile/). The rule
// (ruppert.h, "Segments that nearly overlap"): each stays its own constrained chain all the way,
// the sliver between them meshed; they share a piece only where one's vertex lies on the other
// within rounding (a VertexOnSegment, SegmentsCross or SegmentsOverlap notice names them).
#include <catch2/catch.hpp>

#include "../fuzz/mesh_judge.h"
#include "plc_generators.h"
#include "validator.h"

using namespace ruppert_test;

namespace {

// Meshes plc at the angle and returns the judge's problems (empty: valid). Refinement in angles of
// 1e-3 rad and less runs to its budget (each side's vertices encroach the other's subsegments);
// 1,000 vertices keep the slivers' validation fast.
std::vector<std::string> problemsAt(const ruppert::Plc& plc, double minAngle) {
  ruppert::Options o;
  o.minAngle = minAngle;
  o.maxSteiner = 1000;
  const ruppert::Mesh mesh = ruppert::triangulate(plc, o);
  return ruppert_fuzz::judgeMesh(mesh, plc, o);
}

}  // namespace

TEST_CASE("pairs and fans of nearly overlapping segments are meshed validly at 0, 20 and 33 degrees",
          "[repair][near-overlap]") {
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    const ruppert::Plc plc = nearOverlaps(seed).plc;
    for (const double angle : {0.0, 20.0, 33.0}) {
      INFO("seed " << seed << ", min angle " << angle);
      std::vector<std::string> problems;
      REQUIRE_NOTHROW(problems = problemsAt(plc, angle));
      INFO(describeProblems(problems));
      REQUIRE(problems.empty());
    }
  }
}

// The validator must see a stretch of such a segment that is not a chain of mesh edges: on meshes of
// the three inputs the outside checker flagged, every subsegment removed in turn is reported. Not on
// chains-1e-4-rad-apart-merged-near-their-shared-end.poly: there coordinates near 2e15 span 5e5,
// the validator's tolerance (64 ulps of the coordinates) is 30 units wide, and a stretch of one
// chain removed is still covered, within it, by the other chain 1e-4 rad away (9 of its subsegments).
TEST_CASE("the validator reports any subsegment removed from meshes of segments 3e-7 rad apart",
          "[near-overlap][validator]") {
  const std::string dir = fixturesDir() + "/../hostile/";
  const std::vector<std::pair<std::string, double>> inputs = {
      {"segment-from-a-point-a-hair-outside-the-domain.poly", 0},
      {"segment-3e-7-rad-from-a-boundary-outside-the-domain.poly", 33},
      {"segments-3e-7-rad-apart-crossed-by-a-boundary.poly", 0}};
  for (const auto& [file, angle] : inputs) {
    const ruppert::Plc plc = ruppert::readFile(dir + file);
    ruppert::Options o;
    o.minAngle = angle;
    const ruppert::Mesh mesh = ruppert::triangulate(plc, o);
    ValidateOptions v;
    v.input = &plc;
    v.checkDelaunay = false;  // a removed subsegment may leave its edge not Delaunay; not the point here
    INFO(file);
    REQUIRE(validateMesh(mesh, v).empty());
    for (std::size_t k = 0; k < mesh.segmentIds.size(); ++k) {
      if (mesh.segmentIds[k] == ruppert::kNoInputSegment) continue;
      ruppert::Mesh broken = mesh;
      broken.segments.erase(broken.segments.begin() + std::ptrdiff_t(2 * k), broken.segments.begin() + std::ptrdiff_t(2 * k + 2));
      broken.segmentIds.erase(broken.segmentIds.begin() + std::ptrdiff_t(k));
      const auto problems = validateMesh(broken, v);
      INFO("subsegment " << k << " of input segment " << mesh.segmentIds[k] << " removed");
      bool named = false;
      for (const auto& p : problems)
        named = named || p.find("is not covered by subsegments") != std::string::npos ||
                p.find("is not a subsegment") != std::string::npos;
      CHECK(named);
    }
  }
}
