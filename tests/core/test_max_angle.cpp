// Options::maxAngle: its validation, the bound it sets on the largest angle (outside the chapter's
// exemptions) together with minAngle, and that it changes nothing where minAngle already implies it.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "shape_families.h"
#include "validator.h"

using ruppert::ErrorCode;
using ruppert::Mesh;
using ruppert::Options;
using ruppert::Plc;

namespace {

Options bounds(double minAngle, double maxAngle) {
  Options o;
  o.minAngle = minAngle;
  o.maxAngle = maxAngle;
  return o;
}

Plc polygon(const std::vector<double>& ring) {
  Plc plc;
  plc.points = ring;
  const std::uint32_t n = static_cast<std::uint32_t>(ring.size() / 2);
  for (std::uint32_t i = 0; i < n; ++i) plc.segments.insert(plc.segments.end(), {i, (i + 1) % n});
  return plc;
}

// Valid, and both angle bounds held outside the exemptions (checked only when the mesh is complete:
// an incomplete one says what remains instead).
ruppert_test::ValidateOptions checked(const Plc& plc, const Mesh& mesh, const Options& o) {
  ruppert_test::ValidateOptions v;
  v.input = &plc;
  if (mesh.complete) {
    v.minAngle = o.minAngle, v.maxAngle = o.maxAngle;
    v.angleTolDeg = 1e-6;
    v.angleExempt = ruppert_test::chapterExemptions(mesh, plc);
  }
  return v;
}

double largestAngle(const Mesh& mesh) {
  double largest = 0;
  for (std::uint32_t t = 0; t < mesh.triangles.size() / 3; ++t)
    largest = std::max(largest, ruppert_test::triangleMaxAngleDeg(mesh, t));
  return largest;
}

}  // namespace

TEST_CASE("maxAngle outside (60, 180), other than 0, is rejected naming its value", "[max-angle]") {
  const Plc plc = polygon({0, 0, 1, 0, 1, 1, 0, 1});
  for (double bad : {60.0, 45.0, 1.0, -5.0, 180.0, 200.0, std::numeric_limits<double>::quiet_NaN()}) {
    INFO("maxAngle " << bad);
    try {
      ruppert::triangulate(plc, bounds(30, bad));
      FAIL("no error");
    } catch (const ruppert::Error& e) {
      CHECK(e.code() == ErrorCode::InvalidOption);
      CHECK(std::string(e.what()).rfind("maxAngle = ", 0) == 0);
      CHECK(std::string(e.what()).find("above 60 and below 180") != std::string::npos);
    }
  }
  CHECK_NOTHROW(ruppert::triangulate(plc, bounds(30, 60.5)));
  CHECK_NOTHROW(ruppert::triangulate(plc, bounds(30, 179.5)));
}

TEST_CASE("maxAngle bounds the largest angle, minAngle kept", "[max-angle]") {
  struct Case {
    const char* name;
    Plc plc;
  };
  const std::vector<Case> cases = {
      {"square", polygon({0, 0, 1, 0, 1, 1, 0, 1})},
      {"thin rectangle", polygon({0, 0, 10, 0, 10, 0.3, 0, 0.3})},
      {"L shape", polygon({0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2})},
      // A 10-degree spike: triangles nestled in it are exempt.
      {"spike", polygon({0, 0, 4, 0, 4, 4 * std::tan(10 * 3.14159265358979 / 180), 2, 1.2, 0, 1.5})},
      {"flat obtuse triangle", polygon({0, 0, 10, 0, 5, 0.8})},
  };
  for (const Case& c : cases)
    for (double maxAngle : {90.0, 100.0, 120.0})
      for (double minAngle : {0.0, 20.0, 30.0}) {
        INFO(c.name << " at minAngle " << minAngle << ", maxAngle " << maxAngle);
        const Options o = bounds(minAngle, maxAngle);
        const Mesh mesh = ruppert::triangulate(c.plc, o);
        CHECK(mesh.complete);
        CHECK_VALID(mesh, checked(c.plc, mesh, o));
      }
}

TEST_CASE("a maxAngle that minAngle implies changes nothing", "[max-angle]") {
  // Every triangle with all angles >= 30 has none above 120: 125 leaves the mesh as it was.
  const Plc plc = polygon({0, 0, 3, 0, 3, 1, 2, 0.4, 1, 1.7, 0, 1});
  const Mesh plain = ruppert::triangulate(plc, bounds(30, 0));
  const Mesh bounded = ruppert::triangulate(plc, bounds(30, 125));
  CHECK(bounded.points == plain.points);
  CHECK(bounded.triangles == plain.triangles);
}

TEST_CASE("maxAngle with minAngle 30 on the shape families: complete, valid, both bounds", "[max-angle][families]") {
  std::uint64_t complete = 0, runs = 0;
  for (const auto& family : ruppert_test::shapeFamilies())
    for (std::uint64_t seed : {1, 2}) {
      INFO("family " << family.name << " seed " << seed);
      const auto g = ruppert_test::familyMember(family, seed);
      const Options o = bounds(30, 100);
      const Mesh mesh = ruppert::triangulate(g.plc, o);
      ++runs, complete += mesh.complete;
      CHECK_VALID(mesh, checked(g.plc, mesh, o));
      // An incomplete mesh says why.
      if (!mesh.complete) CHECK_FALSE(mesh.reasons.empty());
    }
  INFO(complete << " of " << runs << " complete");
  CHECK(complete >= runs * 95 / 100);
}

TEST_CASE("maxAngle alone (minAngle 0) refines only what is too wide", "[max-angle]") {
  const Plc plc = polygon({0, 0, 10, 0, 10, 1, 5, 1.4, 0, 1});
  const Options o = bounds(0, 100);
  const Mesh cdt = ruppert::triangulate(plc, bounds(0, 0));
  REQUIRE(largestAngle(cdt) > 100);
  const Mesh mesh = ruppert::triangulate(plc, o);
  CHECK(mesh.complete);
  CHECK_VALID(mesh, checked(plc, mesh, o));
  CHECK(largestAngle(mesh) <= 100 + 1e-6);
}
