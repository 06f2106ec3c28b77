// Judging a mesh made from a PLC with given options, shared by fuzz_mesh and the hostile catalogue
// test (tests/core/test_hostile.cpp): the validator's structural and Delaunay checks, plus the
// bounds the options ask for when the mesh says it is complete.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <ruppert/ruppert.h>

#include "validator.h"

namespace ruppert_fuzz {

// Plain CDT when nothing asks for refinement (ruppert.h, Options::minAngle).
inline bool isPlainCdt(const ruppert::Plc& plc, const ruppert::Options& o) {
  if (o.minAngle > 0 || o.maxArea > 0 || o.sizeFunction) return false;
  for (const ruppert::Region& r : plc.regions)
    if (r.maxArea > 0) return false;
  return true;
}

// Multiplies every coordinate (and area) by 2^shift: exact, and it leaves angles and topology alone.
// Meshes of inputs near 1e-300 are judged on a copy brought near 1, because the angle helpers
// (validator.cpp's triangleMinAngleDeg and nestledInInputAngle) multiply coordinate differences
// and would underflow to a "0 degree" angle there.
inline int unitScaleShift(const ruppert::Mesh& mesh) {
  double maxAbs = 0;
  for (double v : mesh.points) maxAbs = std::fmax(maxAbs, std::fabs(v));
  if (!(maxAbs > 0) || !std::isfinite(maxAbs)) return 0;
  int e = 0;
  std::frexp(maxAbs, &e);  // maxAbs = m * 2^e, m in [0.5, 1)
  return 1 - e;            // largest magnitude lands in [1, 2), as in the validator's own frame
}

inline void scaleBy(int shift, ruppert::Mesh& mesh, ruppert::Plc& plc, ruppert::Options& o) {
  for (double& v : mesh.points) v = std::ldexp(v, shift);
  for (double& v : plc.points) v = std::ldexp(v, shift);
  for (double& v : plc.holes) v = std::ldexp(v, shift);
  for (ruppert::Region& r : plc.regions) {
    r.x = std::ldexp(r.x, shift), r.y = std::ldexp(r.y, shift);
    r.maxArea = std::ldexp(r.maxArea, 2 * shift);
  }
  o.maxArea = std::ldexp(o.maxArea, 2 * shift);
}

// The validator's near-duplicate rule (added vertices within nearDuplicateRelTol of another used
// vertex, in the frame where the largest coordinate is in [1, 2)), checked first and alone: a
// mesh with such a cluster is reported at once, with the cluster named, before the full validation.
inline std::vector<std::string> nearDuplicateClusters(const ruppert::Mesh& scaled, std::size_t inputPoints,
                                                      double eps, std::size_t maxProblems) {
  std::vector<bool> used(scaled.points.size() / 2, false);
  for (std::uint32_t v : scaled.triangles)
    if (v < used.size()) used[v] = true;
  std::vector<std::uint32_t> order;
  for (std::uint32_t v = 0; v < used.size(); ++v)
    if (used[v]) order.push_back(v);
  const auto x = [&](std::uint32_t v) { return scaled.points[2 * v]; };
  const auto y = [&](std::uint32_t v) { return scaled.points[2 * v + 1]; };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return x(a) < x(b); });
  std::vector<std::string> problems;
  for (std::size_t i = 0; i < order.size() && problems.size() < maxProblems; ++i)
    for (std::size_t j = i + 1; j < order.size() && x(order[j]) - x(order[i]) <= eps; ++j) {
      const std::uint32_t a = order[i], b = order[j];
      if ((a < inputPoints && b < inputPoints) || std::fabs(y(a) - y(b)) > eps) continue;
      problems.push_back("vertices " + std::to_string(a) + " and " + std::to_string(b) +
                         " are near-duplicates (closer than nearDuplicateRelTol relative to the largest coordinate)");
      if (problems.size() >= maxProblems) break;
    }
  if (!problems.empty())
    problems.push_back("(full validation not run: the mesh already fails, and its vertex clusters make it slow)");
  return problems;
}

// Problems of `mesh` (empty: valid). Angle and area bounds are checked only when the mesh claims
// completeness; SeditiousEdge reasons exempt skinny triangles as test_refine.cpp does.
inline std::vector<std::string> judgeMesh(const ruppert::Mesh& original, const ruppert::Plc& input,
                                          const ruppert::Options& options) {
  ruppert::Mesh mesh = original;
  ruppert::Plc plc = input;
  ruppert::Options o;
  o.minAngle = options.minAngle, o.maxArea = options.maxArea;
  scaleBy(unitScaleShift(mesh), mesh, plc, o);
  ruppert_test::ValidateOptions v;
  std::vector<std::string> problems =
      nearDuplicateClusters(mesh, plc.points.size() / 2, v.nearDuplicateRelTol, v.maxProblems);
  if (!problems.empty()) return problems;
  v.input = &plc;
  v.expectNoSteiner = isPlainCdt(plc, options);
  if (mesh.complete && o.minAngle > 0) {
    // The chapter's exemptions, each judged per triangle from the mesh and the input.
    const auto seditious = ruppert_test::seditiousTest(mesh, plc);
    v.minAngle = o.minAngle;
    v.angleTolDeg = 1e-6;
    v.angleExempt = [seditious](const ruppert::Mesh& m, std::uint32_t t) {
      return ruppert_test::nestledInInputAngle(m, t) || seditious(m, t);
    };
  }
  if (mesh.complete && o.maxArea > 0) v.maxArea = o.maxArea;
  problems = ruppert_test::validateMesh(mesh, v);
  if (mesh.stats.triangles != mesh.triangles.size() / 3) problems.push_back("stats.triangles disagrees with triangles");
  return problems;
}

}  // namespace ruppert_fuzz
