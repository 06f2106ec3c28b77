// The search for a minimum-angle bound above kSearchAboveDegrees (refine_plan.h), which may be out
// of reach (§6.8): a strategy around the refinement loop (bound_push.h says how it goes).
#pragma once

#include "mesh_state.h"
#include "refine/refine.h"

namespace ruppert::detail {

// m refined toward Options::minAngle (above kSearchAboveDegrees), within Options::maxSteiner.
RefineOutcome searchBound(MeshState& m);

}  // namespace ruppert::detail
