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

// The Steiner budget: Options::maxSteiner, or the automatic one for kAutoSteinerBudget. `demand` is
// areaDemand(m), computed once by the caller (it is a pass over every triangle).
std::uint64_t steinerBudget(const MeshState& m, double demand);
// The automatic one, whatever Options::maxSteiner says.
std::uint64_t automaticSteinerBudget(const MeshState& m, double demand);

// Room for the vertices and triangles that area bounds will make (at most `budget` more vertices),
// reserved before refinement starts, so the mesh's arrays do not grow by copying as it runs.
void reserveForAreaBounds(MeshState& m, std::uint64_t budget, double demand);

}  // namespace ruppert::detail
