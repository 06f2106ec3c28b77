// Judging a mesh made from a PLC with given options, shared by fuzz_mesh and the hostile catalogue
// test (tests/core/test_hostile.cpp): the validator's structural and Delaunay checks, plus the
// bounds the options ask for when the mesh says it is complete.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <ruppert/ruppert.h>

#include "validator.h"

namespace ruppert_fuzz {

// §6.6: a triangle whose smallest angle sits between two subsegments meeting at a vertex is nestled
// in a small input angle (or a crossing) and may stay skinny. Judged from the output alone.
inline bool nestledInInputAngle(const ruppert::Mesh& m, std::uint32_t t) {
  double best = 1e9;
  int corner = 0;
  for (int i = 0; i < 3; ++i) {
    const double* o = &m.points[2 * m.triangles[3 * t + i]];
    const double* u = &m.points[2 * m.triangles[3 * t + (i + 1) % 3]];
    const double* w = &m.points[2 * m.triangles[3 * t + (i + 2) % 3]];
    const double ux = u[0] - o[0], uy = u[1] - o[1], wx = w[0] - o[0], wy = w[1] - o[1];
    const double a = std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy);
    if (a < best) best = a, corner = i;
  }
  auto isSubsegment = [&](std::uint32_t a, std::uint32_t b) {
    for (std::size_t k = 0; k < m.segmentIds.size(); ++k) {
      const std::uint32_t p = m.segments[2 * k], q = m.segments[2 * k + 1];
      if ((p == a && q == b) || (p == b && q == a)) return true;
    }
    return false;
  };
  const std::uint32_t z = m.triangles[3 * t + corner];
  return isSubsegment(z, m.triangles[3 * t + (corner + 1) % 3]) &&
         isSubsegment(z, m.triangles[3 * t + (corner + 2) % 3]);
}

// Plain CDT when nothing asks for refinement (ruppert.h, Options::minAngle).
inline bool isPlainCdt(const ruppert::Plc& plc, const ruppert::Options& o) {
  if (o.minAngle > 0 || o.maxArea > 0 || o.sizeFunction) return false;
  for (const ruppert::Region& r : plc.regions)
    if (r.maxArea > 0) return false;
  return true;
}

// Problems of `mesh` (empty: valid). Angle and area bounds are checked only when the mesh claims
// completeness; SeditiousEdge reasons exempt skinny triangles as test_refine.cpp does.
inline std::vector<std::string> judgeMesh(const ruppert::Mesh& mesh, const ruppert::Plc& plc,
                                          const ruppert::Options& o) {
  ruppert_test::ValidateOptions v;
  v.input = &plc;
  v.expectNoSteiner = isPlainCdt(plc, o);
  if (mesh.complete && o.minAngle > 0) {
    bool seditious = false;
    for (const ruppert::Reason& r : mesh.reasons) seditious = seditious || r.kind == ruppert::ReasonKind::SeditiousEdge;
    v.minAngle = o.minAngle;
    v.angleTolDeg = 1e-6;
    v.angleExempt = [seditious](const ruppert::Mesh& m, std::uint32_t t) {
      return seditious || nestledInInputAngle(m, t);
    };
  }
  if (mesh.complete && o.maxArea > 0) v.maxArea = o.maxArea;
  std::vector<std::string> problems = ruppert_test::validateMesh(mesh, v);
  if (mesh.stats.triangles != mesh.triangles.size() / 3) problems.push_back("stats.triangles disagrees with triangles");
  return problems;
}

}  // namespace ruppert_fuzz
