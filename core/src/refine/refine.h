// Delaunay refinement of a classified constrained Delaunay triangulation (§6.2-6.6, 6.8).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "mesh/angle_stats.h"
#include "mesh_state.h"

namespace ruppert::detail {

struct RefineOutcome {
  std::vector<Reason> reasons;       // empty: every bound met (up to the chapter's exemptions)
  std::vector<Event> events;         // internal vertex ids and scaled coordinates until mapped
  std::uint64_t rejected = 0;        // rejected circumcenters / off-centers
  double lfsIntegral = 0;
  double reachedAngle = -1;          // degrees: smallest angle the bound applies to; -1: not refined
  // The angle statistics of the mesh as refinement left it, gathered by the last census of its
  // triangles (which reads every corner anyway) so that output assembly need not read them all
  // again; empty where something may change the mesh afterwards.
  std::optional<AngleStats> angles;
};

// True when the options ask for any refinement (angle, area or size function).
RefineOutcome refine(MeshState& m);

// Estimate of the integral of 1/lfs^2 over the meshed domain (§6.5), by quadrature on the mesh as it
// stands; a vertex's lfs is taken from a neighbor's where their triangle's longest edge is under
// reuseBelow times it (the statistics: 0.02, within 2%; the termination guard: coarser and cheaper).
double estimateLfsIntegral(const MeshState& m, double reuseBelow = 0.02);

}  // namespace ruppert::detail
