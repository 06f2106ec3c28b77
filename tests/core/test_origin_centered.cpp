// Outlines centered on the origin: a boundary edge from (+c, y1) to (-c, y2) has its
// midpoint on x = 0, rounded in y to either side of the edge. Such shapes, their mirror images and
// their shifted copies must all refine completely and validly: a split point's nudge onto the
// domain's side must not depend on the ulp of a coordinate that is 0.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "plc_generators.h"
#include "validator.h"

using ruppert::Mesh;
using ruppert::Plc;
using namespace ruppert_test;

namespace {

struct Variant {
  const char* name;
  Plc plc;
};

// The outline of a seed: sizes from 40 to 1200 vertices, a hole around the origin on odd seeds.
GeneratedPlc outlineOf(std::uint64_t seed) {
  static const std::size_t kSizes[] = {40, 120, 400, 1200};
  return originCenteredOutline(seed, kSizes[seed % 4], seed % 2 == 1);
}

std::vector<Variant> variantsOf(const Plc& plc) {
  return {{"centered", plc},
          {"mirrored x -> -x", mirrored(plc, true, false)},
          {"mirrored y -> -y", mirrored(plc, false, true)},
          {"mirrored both", mirrored(plc, true, true)},
          {"shifted by (1000.5, 77.25)", translated(plc, 1000.5, 77.25)}};  // last
}

Mesh refined(const Plc& plc, double angle) {
  ruppert::Options o;
  o.minAngle = angle;
  return ruppert::triangulate(plc, o);
}

std::string reasonsOf(const Mesh& mesh) {
  std::string s;
  for (const auto& r : mesh.reasons) s += r.message + "; ";
  return s;
}

}  // namespace

TEST_CASE("outlines centered on the origin and their mirror images refine completely at 30 and 33 degrees",
          "[origin]") {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const GeneratedPlc g = outlineOf(seed);
    for (const Variant& v : variantsOf(g.plc))
      for (double angle : {30.0, 33.0}) {
        INFO("seed " << seed << ", " << v.name << ", " << angle << " degrees");
        const Mesh mesh = refined(v.plc, angle);
        INFO(reasonsOf(mesh));
        CHECK(mesh.complete);
        CHECK_VALID(mesh, boundChecked(v.plc, mesh, g.area, angle));
      }
  }
}

TEST_CASE("at 31, 32 and 35 degrees, origin-centered outlines and mirror images complete as shifted copies do",
          "[origin]") {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const GeneratedPlc g = outlineOf(seed);
    const std::vector<Variant> variants = variantsOf(g.plc);
    for (double angle : {31.0, 32.0, 35.0}) {
      const Mesh shifted = refined(variants.back().plc, angle);
      // Up to 34 degrees every input of this family must complete; above, only as the shifted copy does.
      if (angle < 34) CHECK(shifted.complete);
      for (std::size_t i = 0; i + 1 < variants.size(); ++i) {
        INFO("seed " << seed << ", " << variants[i].name << ", " << angle << " degrees");
        const Mesh mesh = refined(variants[i].plc, angle);
        INFO(reasonsOf(mesh));
        CHECK(mesh.complete == shifted.complete);
        if (mesh.complete) CHECK_VALID(mesh, boundChecked(variants[i].plc, mesh, g.area, angle));
      }
    }
  }
}
