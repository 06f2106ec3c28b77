// The one mesh validator every core test reuses.
//
// validateMesh() checks a ruppert::Mesh against the contract of ruppert.h and, when given the input
// PLC, against the input. It returns readable problem strings naming triangle / vertex / segment
// indices; an empty vector means the mesh is valid. Geometric checks use the library's exact
// predicates on a power-of-two scaled copy of the coordinates (scaling by 2^k is exact, so meshes of
// inputs at 1e-200 or 1e200 are judged exactly too).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <ruppert/ruppert.h>

namespace ruppert_test {

struct ValidateOptions {
  // The PLC the mesh was made from. When set, every input segment must be covered by a chain of
  // subsegments (or be reported dropped by a notice, or lie outside the meshed domain), and every
  // input point must be used, merged (DuplicatePoint notice) or lie outside the domain.
  const ruppert::Plc* input = nullptr;
  // How far a vertex of a segment's chain may be from its line (intersection vertices are rounded):
  // collinearRelTol of the segment's length plus collinearUlpTol of its endpoints' magnitude. The
  // second is a few dozen ulps, not more: a segment 1e-14 long at coordinates near 1 has neighbors
  // 1e-14 away, which a looser tolerance would count as on it.
  double collinearRelTol = 1e-9;
  double collinearUlpTol = 0x1p-46;

  // Total triangle area must equal this (relative tolerance areaRelTol) when >= 0.
  double expectedArea = -1;
  double areaRelTol = 1e-9;

  // Every interior edge that is not a subsegment must be locally Delaunay (exact incircle <= 0).
  bool checkDelaunay = true;

  // When > 0: every triangle's smallest angle must be >= minAngle degrees (minus angleTolDeg),
  // unless angleExempt(mesh, t) says the triangle is allowed to be worse (small input angles, ...).
  double minAngle = 0;
  double angleTolDeg = 1e-7;
  std::function<bool(const ruppert::Mesh&, std::uint32_t triangle)> angleExempt;
  // When > 0: every triangle's largest angle must be <= maxAngle degrees (plus angleTolDeg), unless
  // angleExempt(mesh, t) says so (the same exemptions as for minAngle).
  double maxAngle = 0;

  // When > 0: every triangle's area must be <= maxArea * (1 + areaRelTol), unless areaExempt says so.
  double maxArea = 0;
  std::function<bool(const ruppert::Mesh&, std::uint32_t triangle)> areaExempt;

  // Vertices the mesher added (not input points) must be farther than this, relative to the largest
  // coordinate magnitude, from every other used vertex: closer ones are near-duplicates born of
  // rounding (e.g. one crossing computed twice) and make needle triangles. 0 disables the check.
  double nearDuplicateRelTol = 0x1p-40;

  // Plain CDT: the only vertices are input points and intersection vertices of crossing segments.
  bool expectNoSteiner = false;

  // Stop collecting after this many problems (the first ones are the informative ones).
  std::size_t maxProblems = 50;
};

std::vector<std::string> validateMesh(const ruppert::Mesh& mesh, const ValidateOptions& options = {});

// The near-duplicate check of validateMesh() alone (with the size and index checks it needs): cheap
// where the full validation is slow, on meshes with vertex clusters.
std::vector<std::string> findNearDuplicates(const ruppert::Mesh& mesh, const ValidateOptions& options = {});

// Helpers used by tests.
double meshArea(const ruppert::Mesh& mesh);                           // sum of triangle areas
double triangleMinAngleDeg(const ruppert::Mesh& mesh, std::uint32_t t);  // smallest angle of t
double triangleMaxAngleDeg(const ruppert::Mesh& mesh, std::uint32_t t);  // largest angle of t
// §6.6, judged from the output alone: t's smallest angle sits between two subsegments meeting at
// its vertex (an input angle or a crossing), so no Steiner point can improve it.
bool nestledInInputAngle(const ruppert::Mesh& mesh, std::uint32_t t);
// §6.6, judged from the output and the input: t's shortest edge joins vertices inserted on two
// different input segments (or convex-hull edges, which stand for segments) that meet (at a shared
// endpoint, or where they cross) at less than 45 degrees, at the same distance from where they meet
// (the same concentric shell). The returned test is for `mesh` only (it indexes the mesh's vertices
// by input segment once).
std::function<bool(const ruppert::Mesh&, std::uint32_t)> seditiousTest(const ruppert::Mesh& mesh,
                                                                       const ruppert::Plc& input);
// The chapter's exemptions from the angle bound, for ValidateOptions::angleExempt: nestled in a
// small input angle, or a seditious shortest edge (both above), each judged on its own.
std::function<bool(const ruppert::Mesh&, std::uint32_t)> chapterExemptions(const ruppert::Mesh& mesh,
                                                                           const ruppert::Plc& input);
// Options that check a refined mesh of `input` at its bound: the domain's area, the smallest angle
// outside the chapter's exemptions (within 1e-6 degrees).
ValidateOptions boundChecked(const ruppert::Plc& input, const ruppert::Mesh& mesh, double area, double angle);
std::string describeProblems(const std::vector<std::string>& problems, std::size_t max = 12);
// True when every interior non-subsegment edge is strictly Delaunay (incircle < 0), i.e. the CDT of
// this vertex set and these subsegments is unique. Metamorphic tests compare topology only then.
bool hasUniqueCdt(const ruppert::Mesh& mesh);

}  // namespace ruppert_test

// Catch2 helpers: REQUIRE_VALID(mesh) or REQUIRE_VALID(mesh, options) (and CHECK_VALID) print the
// first problems. Include <catch2/catch.hpp> first. Pass options as a variable or a function call, not
// as a braced initializer: the preprocessor would split its commas into macro arguments.
#define RUPPERT_VALID_SELECT(_1, _2, NAME, ...) NAME
#define RUPPERT_REQUIRE_VALID_1(mesh) RUPPERT_REQUIRE_VALID_2(mesh, ::ruppert_test::ValidateOptions{})
#define RUPPERT_REQUIRE_VALID_2(mesh, options)                                              \
  do {                                                                                      \
    const auto ruppertProblems_ = ::ruppert_test::validateMesh((mesh), (options));          \
    INFO(::ruppert_test::describeProblems(ruppertProblems_));                               \
    REQUIRE(ruppertProblems_.empty());                                                      \
  } while (false)
#define RUPPERT_CHECK_VALID_2(mesh, options)                                                \
  do {                                                                                      \
    const auto ruppertProblems_ = ::ruppert_test::validateMesh((mesh), (options));          \
    INFO(::ruppert_test::describeProblems(ruppertProblems_));                               \
    CHECK(ruppertProblems_.empty());                                                        \
  } while (false)
#define REQUIRE_VALID(...) \
  RUPPERT_VALID_SELECT(__VA_ARGS__, RUPPERT_REQUIRE_VALID_2, RUPPERT_REQUIRE_VALID_1, unused)(__VA_ARGS__)
#define CHECK_VALID(...) \
  RUPPERT_VALID_SELECT(__VA_ARGS__, RUPPERT_CHECK_VALID_2, RUPPERT_CHECK_VALID_1, unused)(__VA_ARGS__)
#define RUPPERT_CHECK_VALID_1(mesh) RUPPERT_CHECK_VALID_2(mesh, ::ruppert_test::ValidateOptions{})
