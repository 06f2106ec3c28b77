// Output assembly (assemble_output.cpp): the pipeline's last stage.
#pragma once

#include "mesh_state.h"
#include "refine/refine.h"
#include "ruppert/ruppert.h"

namespace ruppert::detail {

// The public Mesh of the final state (after removeOutside) and refinement's outcome. Builds
// m.outputMap, moves m.notices into the mesh and takes the triangulation apart (its arrays are
// moved into the mesh or freed as soon as they are read). Stats::milliseconds is left to the caller.
Mesh assembleOutput(MeshState& m, RefineOutcome outcome);

}  // namespace ruppert::detail
