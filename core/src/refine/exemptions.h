// The chapter's exemptions (§6.6): triangles refinement leaves below the angle bound (or over the
// maxAngle bound) on purpose, because splitting them would never end. One source for the rules:
// refinement skips these triangles and reports them (refine_checks.cpp, refine_result.cpp), and
// the output marks them per triangle when Options::exemptions asks (output/assemble_output.cpp).
#pragma once

#include <cstdint>

#include "mesh/triangle_shape.h"
#include "mesh_state.h"

namespace ruppert::detail {

// Slot s's smallest angle is an input angle: both edges at that corner are subsegments.
bool nestledInInputAngle(const MeshState& m, std::uint32_t s, const TriangleShape& sh);

// Slot s's shortest edge u-w is seditious: u and w split two different segments that meet at a
// vertex z at less than kSeditiousAngle, at the same distance from z (the same concentric shell).
bool seditiousShortestEdge(const MeshState& m, std::uint32_t s, const TriangleShape& sh);

// The angle bounds the options ask for, as refinement tests them: the squared sine of the smallest
// angle allowed (0: none) and the cosine of the largest (-2: none), with refinement's tolerances.
struct ExemptionBounds {
  double sin2Min = 0, cosMax = -2;
};
ExemptionBounds exemptionBounds(const Options& options);

// Slot s's exemption (Mesh::triangleExemptions' values): kNotExempt when it meets the bounds or
// neither rule applies.
std::uint8_t exemptionOf(const MeshState& m, std::uint32_t s, const ExemptionBounds& bounds);

}  // namespace ruppert::detail
