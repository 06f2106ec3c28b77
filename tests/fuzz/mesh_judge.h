// Judging a mesh made from a PLC with given options, shared by fuzz_mesh and the hostile catalog
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

// Whether nothing asks for refinement (ruppert.h, Options::minAngle).
inline bool asksNoRefinement(const ruppert::Plc& plc, const ruppert::Options& o) {
  if (o.minAngle > 0 || o.maxAngle > 0 || o.maxArea > 0 || o.sizeFunction) return false;
  for (const ruppert::Region& r : plc.regions)
    if (r.maxArea > 0) return false;
  return true;
}

// Plain CDT: no refinement asked for, and no curves, whose pieces' ends are new vertices even then
// (fuzz_mesh checks that they all lie on curves).
inline bool isPlainCdt(const ruppert::Plc& plc, const ruppert::Options& o) {
  return asksNoRefinement(plc, o) && plc.curves.empty();
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

// Problems of `mesh` (empty: valid). Angle and area bounds are checked only when the mesh claims
// completeness; SeditiousEdge reasons exempt skinny triangles as test_refine.cpp does.
inline std::vector<std::string> judgeMesh(const ruppert::Mesh& original, const ruppert::Plc& input,
                                          const ruppert::Options& options) {
  ruppert::Mesh mesh = original;
  ruppert::Plc plc = input;
  ruppert::Options o;
  o.minAngle = options.minAngle, o.maxAngle = options.maxAngle, o.maxArea = options.maxArea;
  scaleBy(unitScaleShift(mesh), mesh, plc, o);
  ruppert_test::ValidateOptions v;
  v.input = &plc;
  // Near-duplicate clusters first and alone: they make the full validation slow.
  std::vector<std::string> problems = ruppert_test::findNearDuplicates(mesh, v);
  if (!problems.empty()) {
    problems.push_back("(full validation not run: the mesh already fails, and its vertex clusters make it slow)");
    return problems;
  }
  v.expectNoSteiner = isPlainCdt(plc, options);
  if (mesh.complete && (o.minAngle > 0 || o.maxAngle > 0)) {
    // The chapter's exemptions, each judged per triangle from the mesh and the input.
    const auto seditious = ruppert_test::seditiousTest(mesh, plc);
    v.minAngle = o.minAngle, v.maxAngle = o.maxAngle;
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
