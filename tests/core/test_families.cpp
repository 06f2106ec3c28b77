// The shape families (shape_families.h): every family is valid input, refines validly and completely
// at 30 and 33 degrees (the chapter's exemptions only), and meshes the same after exact transforms.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "shape_families.h"
#include "validator.h"

using ruppert::Mesh;
using ruppert::Options;
using ruppert::Plc;
using ruppert_test::boundChecked;
using ruppert_test::familyMember;
using ruppert_test::shapeFamilies;

namespace {

const std::uint64_t kSeeds[] = {1, 2, 3};

Options atAngle(double angle) {
  Options o;
  o.minAngle = angle;
  return o;
}

// True when two segments that share no endpoint index touch, or two that share one overlap: checked
// with the exact predicates, independently of the library's input repair.
std::string firstTouchingPair(const Plc& plc) {
  const auto& s = plc.segments;
  const double* p = plc.points.data();
  for (std::size_t i = 0; i < s.size(); i += 2)
    for (std::size_t j = i + 2; j < s.size(); j += 2) {
      const bool shared = s[i] == s[j] || s[i] == s[j + 1] || s[i + 1] == s[j] || s[i + 1] == s[j + 1];
      if (shared) continue;  // adjacent: an overlap would show as a repair notice (checked too)
      if (ruppert_test::segmentsTouch(p + 2 * s[i], p + 2 * s[i + 1], p + 2 * s[j], p + 2 * s[j + 1]))
        return "segments " + std::to_string(i / 2) + " and " + std::to_string(j / 2) + " touch";
    }
  return "";
}

}  // namespace

TEST_CASE("shape families are deterministic, sized within their range and distinct per seed", "[families]") {
  REQUIRE(shapeFamilies().size() >= 12);
  for (const auto& family : shapeFamilies()) {
    INFO("family " << family.name);
    REQUIRE(ruppert_test::findShapeFamily(family.name) == &family);
    std::vector<int> sizes;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const int size = ruppert_test::familySize(family, seed);
      CHECK(size >= family.minSize);
      CHECK(size <= family.maxSize);
      sizes.push_back(size);
    }
    CHECK(*std::min_element(sizes.begin(), sizes.end()) < *std::max_element(sizes.begin(), sizes.end()));
    const auto a = familyMember(family, 7), b = familyMember(family, 7), c = familyMember(family, 8);
    CHECK(a.plc.points == b.plc.points);
    CHECK(a.plc.segments == b.plc.segments);
    CHECK(a.plc.holes == b.plc.holes);
    CHECK(a.plc.points != c.plc.points);
    CHECK(ruppert_test::plcToPolyText(a.plc, "x") == ruppert_test::plcToPolyText(b.plc, "x"));
  }
}

// The benchmark's numbers (tests/bench/results/families-*.md) are only comparable while the files
// are the same: these FNV-1a hashes of each family's seed-1 .poly text were measured with GCC 12 and
// Clang 14 (-O0 and -O2), which agree. A generator changed on purpose updates them (and re-runs the
// benchmark); a platform that disagrees has found an order of evaluation or a libm difference.
TEST_CASE("shape families are the same files on every compiler", "[families]") {
  const std::pair<const char*, std::uint64_t> expected[] = {
      {"skyline", 0x235003ecdc60af73ull},
      {"comb", 0x803e1c7d80c019c6ull},
      {"star", 0xebdcc88faef9447cull},
      {"channel", 0x03e14369161f5559ull},
      {"airfoil", 0x674c1bd50eae6364ull},
      {"serpentine", 0xd86a9eff3e6f9762ull},
      {"subdivision", 0xb97962c20f92390aull},
      {"perforated", 0x3fddcfd41c1040a9ull},
      {"notched", 0x27ca261f9a6f64c3ull},
      {"strip", 0xbad566675d1f4ec6ull},
      {"cloud", 0x4556db75adbd7049ull},
      {"rings", 0x38de99d6f7c8321eull},
      {"letters", 0xd80c958a9c1b9ca9ull},
      {"gear", 0x80a1bb31a6f9e12bull},
      {"cracks", 0x3e0384c3c97730b4ull},
  };
  for (const auto& [name, hash] : expected) {
    INFO("family " << name << " seed 1");
    const auto* family = ruppert_test::findShapeFamily(name);
    REQUIRE(family != nullptr);
    const std::string text = ruppert_test::plcToPolyText(familyMember(*family, 1).plc, "");
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned char c : text) h = (h ^ c) * 0x100000001b3ull;
    CHECK(h == hash);
  }
  CHECK(std::size(expected) == shapeFamilies().size());
}

TEST_CASE("every shape family is valid input: no repairs, no touching segments, its area meshed", "[families]") {
  for (const auto& family : shapeFamilies())
    for (std::uint64_t seed : kSeeds) {
      INFO("family " << family.name << " seed " << seed);
      const auto g = familyMember(family, seed);
      CHECK(firstTouchingPair(g.plc) == "");
      const Mesh mesh = ruppert::triangulate(g.plc, atAngle(0));
      CHECK(mesh.notices.empty());
      ruppert_test::ValidateOptions v;
      v.input = &g.plc;
      v.expectedArea = g.area;
      v.expectNoSteiner = true;
      CHECK_VALID(mesh, v);
      // The .poly text reads back to the same PLC, bit for bit.
      const Plc back = ruppert::parsePoly(ruppert_test::plcToPolyText(g.plc, family.name));
      CHECK(back.points == g.plc.points);
      CHECK(back.segments == g.plc.segments);
      CHECK(back.holes == g.plc.holes);
      CHECK(back.regions.size() == g.plc.regions.size());
    }
}

TEST_CASE("every shape family refines completely and validly at 30 and 33 degrees", "[families]") {
  for (const auto& family : shapeFamilies())
    for (std::uint64_t seed : kSeeds)
      for (double angle : {30.0, 33.0}) {
        INFO("family " << family.name << " seed " << seed << " at " << angle << " degrees");
        const auto g = familyMember(family, seed);
        const Mesh mesh = ruppert::triangulate(g.plc, atAngle(angle));
        CHECK(mesh.complete);
        CHECK_VALID(mesh, boundChecked(g.plc, mesh, g.area, angle));
      }
}

TEST_CASE("shape families: scaling by 2^k gives the same mesh size, integer shifts nearly so", "[families]") {
  for (const auto& family : shapeFamilies()) {
    INFO("family " << family.name);
    const auto g = familyMember(family, 2);
    const Mesh base = ruppert::triangulate(g.plc, atAngle(30));
    for (int k : {-9, 3, 60}) {
      INFO("scaled by 2^" << k);
      const Mesh mesh = ruppert::triangulate(ruppert_test::scaled(g.plc, std::ldexp(1.0, k)), atAngle(30));
      CHECK(mesh.triangles.size() == base.triangles.size());  // the core normalizes by 2^k: same bits
    }
    // An integer shift is exact and changes no predicate on the input, but the core does not shift
    // back: Steiner points computed near 1024 round differently from those near 0 and steer later
    // decisions, so counts differ by a little (up to 1.8% measured on these members with the core of ca81a87).
    for (const auto& shift : {std::pair<double, double>{3, -7}, {1024, -4096}}) {
      INFO("shifted by (" << shift.first << ", " << shift.second << ")");
      const Plc plc = ruppert_test::translated(g.plc, shift.first, shift.second);
      const Mesh mesh = ruppert::triangulate(plc, atAngle(30));
      CHECK(mesh.complete);
      auto v = boundChecked(plc, mesh, g.area, 30);
      v.areaRelTol = 1e-6;  // triangle areas from coordinates near 4096: cancellation
      CHECK_VALID(mesh, v);
      const double ratio = double(mesh.triangles.size()) / double(base.triangles.size());
      CHECK(ratio > 0.97);
      CHECK(ratio < 1.03);
    }
  }
}

// The size yardstick at a small bound, on the family closest to parity: Triangle 1.6's triangle
// counts (triangle-wasm 1.0.0, switches -pzQq25) for serpentine corridors, seeds 1 to 20. Rejected
// first choices below 28 degrees split the subsegment they encroach
// (optimal_placement.h: kSplitBeforeSearchBelowDegrees), which keeps the default at or under them.
TEST_CASE("serpentine corridors at 25 degrees: no more triangles than Triangle makes", "[families]") {
  const double triangleCounts[] = {266, 308, 138, 128, 45, 366, 180, 216, 101, 323,
                                   117, 290, 104, 297, 216, 231, 358, 257, 280, 305};
  const auto* serpentine = ruppert_test::findShapeFamily("serpentine");
  REQUIRE(serpentine != nullptr);
  double logSum = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    INFO("seed " << seed);
    const auto g = familyMember(*serpentine, seed);
    const Mesh mesh = ruppert::triangulate(g.plc, atAngle(25));
    CHECK(mesh.complete);
    CHECK_VALID(mesh, boundChecked(g.plc, mesh, g.area, 25));
    logSum += std::log(double(mesh.triangles.size() / 3) / triangleCounts[seed - 1]);
  }
  const double geometricMean = std::exp(logSum / 20);
  INFO("ruppert / Triangle " << geometricMean);
  CHECK(geometricMean <= 1.0);
}
