// What refinement computes once before it starts.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh_state.h"

namespace ruppert::detail {

// Per vertex: 1 at an acute input corner, an input or intersection vertex where two constrained
// edges meet at less than 90 degrees (concentric-shell splitting applies there, §6.6).
std::vector<std::uint8_t> acuteCorners(const MeshState& m);

// The sum of area / bound over the triangles that have an area bound (a region's or the global
// one): about twice the vertices those bounds ask for. Both the budget and the reservation use it.
double areaDemand(const MeshState& m);

// The automatic Steiner budget (Options::maxSteiner's default), whatever Options::maxSteiner says:
// the first checkpoint of the guard below. `demand` is areaDemand(m), computed once by the caller
// (it is a pass over every triangle).
std::uint64_t automaticSteinerBudget(const MeshState& m, double demand);

// The automatic budget is a checkpoint, not a stop. A refinement that reaches it (after `steps`
// steps) goes on while its steps stay within the automatic budget plus kGuardStepsPerLfsUnit per
// unit of the chapter's size measure (§6.5: a size-optimal mesh has O(integral of 1/lfs^2)
// triangles), estimated on the mesh as it stands, so that only a refinement that is not converging
// (ever smaller edges in a corner it cannot fix) is stopped. Returns the next checkpoint, at most
// twice `steps` (the estimate sharpens as the mesh refines), or 0 to stop; `integral` gets the
// estimate.
inline constexpr double kGuardStepsPerLfsUnit = 64;
std::uint64_t nextGuardCheckpoint(const MeshState& m, std::uint64_t automatic, std::uint64_t steps, double& integral);

// Room for the vertices and triangles that area bounds will make (at most `budget` more vertices),
// reserved before refinement starts, so the mesh's arrays do not grow by copying as it runs.
void reserveForAreaBounds(MeshState& m, std::uint64_t budget, double demand);

}  // namespace ruppert::detail
