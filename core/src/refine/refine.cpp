// refine() (refine.h): the chapter's loop (refiner.h) once, at the bound asked for; above
// kSearchAboveDegrees, where the bound may be out of reach (§6.8), the bound search around it
// (bound_search/).
#include "refine/refine.h"

#include "refine/bound_search/bound_search.h"
#include "refine/refiner.h"

namespace ruppert::detail {

RefineOutcome refine(MeshState& m) {
  if (m.options->minAngle > kSearchAboveDegrees) {
    // The search may put back an earlier mesh after its last census.
    RefineOutcome outcome = searchBound(m);
    outcome.angles.reset();
    return outcome;
  }
  return Refiner(m, RefinePlan::direct(m.options->minAngle, m.options->maxSteiner)).run();
}

}  // namespace ruppert::detail
