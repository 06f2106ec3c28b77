// What refinement computes once before it starts.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh_state.h"

namespace ruppert::detail {

// Per vertex: 1 at an acute input corner, an input or intersection vertex where two constrained
// edges meet at less than 90 degrees (concentric-shell splitting applies there, §6.6).
// inverseGaps, if given, gets the sum over those corners of 1 / their gap in radians (at most 2e4 each).
std::vector<std::uint8_t> acuteCorners(const MeshState& m, double* inverseGaps = nullptr);

// The sum of area / bound over the triangles that have an area bound (a region's or the global
// one): about twice the vertices those bounds ask for. Both the budget and the reservation use it.
double areaDemand(const MeshState& m);

// The automatic Steiner budget (Options::maxSteiner's default), whatever Options::maxSteiner says:
// the first checkpoint of the guard below. `demand` is areaDemand(m), computed once by the caller
// (it is a pass over every triangle).
std::uint64_t automaticSteinerBudget(const MeshState& m, double demand);

// The automatic budget is a checkpoint, not a stop. A refinement that reaches it (after `steps`
// steps) goes on while its steps stay within `base` (the automatic budget plus
// kGuardStepsPerInverseRadian per inverse radian of each acute input corner's gap: a corner of
// angle phi needs about 1 / phi triangles per shell before §6.6 leaves it alone, which the size
// measure, blind to angles between features that touch, does not count) plus kGuardStepsPerLfsUnit
// per unit of the chapter's size measure (§6.5: a size-optimal mesh has O(integral of 1/lfs^2)
// triangles), estimated on the mesh as it stands, so that only a refinement that is not converging
// (ever smaller edges in a corner it cannot fix) is stopped. Returns the next checkpoint, at most
// twice `steps` (the estimate sharpens as the mesh refines), or 0 to stop; `integral` gets the
// estimate.
inline constexpr double kGuardStepsPerLfsUnit = 64;
inline constexpr double kGuardStepsPerInverseRadian = 16;
std::uint64_t nextGuardCheckpoint(const MeshState& m, double base, std::uint64_t steps, double& integral);

// Room for the vertices and triangles that area bounds will make (at most `budget` more vertices),
// reserved before refinement starts, so the mesh's arrays do not grow by copying as it runs.
void reserveForAreaBounds(MeshState& m, std::uint64_t budget, double demand);

}  // namespace ruppert::detail
