// StageControl (stage_control.h): the caps, stages and best mesh of one run of the loop within the
// bound search. Once per stage or per score of the mesh: compiled for size (cold_code.h).
#include "refine/bound_search/stage_control.h"

#include <algorithm>
#include <string>
#include <utility>

#include "cold_code.h"
#include "decimal_text.h"
#include "refine/refiner.h"

namespace ruppert::detail {

RUPPERT_COLD_BEGIN

StageControl::StageControl(const Options& o, double requested, const StageRules& rules)
    : o_(o), requested_(requested), sin2Requested_(sin2Bound(radians(requested))), rules_(rules) {}

// The queues are empty: if a stage below the requested bound just completed, raise the bound by a
// step and queue what the new bound makes bad. The new stage's first score may find the mesh over
// the push's cap.
LoopControl::Next StageControl::queuesEmpty(Refiner& loop) {
  if (!(loop.bound() < requested_)) return Next::Done;
  if (rules_.track) {
    if (!pushing_) push_.setBase(loop.liveTriangles());
    observe(loop);
  }
  pushing_ = true;
  loop.raiseBound(std::min(requested_, loop.bound() + kStageStepDegrees));
  push_.newStage(loop.inserted());
  return overCap(loop) ? Next::Stop : Next::GoOn;
}

bool StageControl::stopAfterStep(Refiner& loop) { return overCap(loop) || pushStopped(loop); }

// The push's domain cap (observe) or the live-triangle cap of the push or a direct attempt.
bool StageControl::overCap(const Refiner& loop) {
  if (!overDomainCap_ && (!rules_.triangleCap || loop.liveTriangles() <= rules_.triangleCap)) return false;
  capHit_ = true;
  pushStop_ = "the mesh reached four times the 33-degree mesh's triangles";
  return true;
}

// Scores the mesh and, if it is the best so far, keeps a copy. A mesh over the push's domain cap is
// never kept, and stops the push (overCap).
void StageControl::observe(const Refiner& loop) {
  const MeshScore sc = loop.survey(sin2Requested_);
  if (rules_.domainCap && sc.domainTriangles > rules_.domainCap) {
    overDomainCap_ = true;
    return;
  }
  if (!push_.observe(sc, loop.inserted())) return;
  best_.mesh = MeshState(loop.mesh());  // a copy moved in: MeshState's copy assignment, 2 KB of wasm, is not needed
  best_.events = loop.eventCount(), best_.rejected = loop.rejectedCount();
}

// During a push: scores the mesh every so often (every quarter of its size in insertions, so
// scores and copies cost a fraction of the refinement) and stops when a stage stops reducing its
// bad triangles.
bool StageControl::pushStopped(const Refiner& loop) {
  if (!rules_.track || !pushing_ || loop.inserted() < nextScoreAt_) return false;
  nextScoreAt_ = loop.inserted() + std::max<std::uint64_t>(2048, loop.liveTriangles() / 4);
  observe(loop);
  if (overDomainCap_) return overCap(loop);
  if (!push_.stalled(loop.inserted())) return false;
  pushStop_ = "a stage stopped reducing its skinny triangles";
  return true;
}

// A push that stopped short of the requested bound (not cancelled, and not a replay's prefix cut
// at its budget): the result is its best mesh.
void StageControl::ended(Refiner& loop, bool stopped) {
  if (!pushing_ || !stopped || loop.cancelled() || (rules_.prefix && loop.budgetHit())) return;
  if (!rules_.track) return;
  if (loop.budgetHit()) pushStop_ = "the Steiner budget was reached";
  if (!capHit_) observe(loop);  // a mesh over the cap is never the result
  loop.markUnreachable();
  if (push_.bestStep() == loop.inserted()) return;
  loop.returnEarlier(std::move(best_.mesh), push_.bestStep(), best_.events, best_.rejected);
}

std::string StageControl::unreachableMessage(std::uint64_t unmet, double reached) const {
  const std::string angles = formatSignificant(requested_, 6) +
                             " degrees is out of reach; the smallest angle reached is " + formatFixed(reached, 2);
  // The direct attempts (bound_search.cpp's directPlan) and their caps.
  const char* direct =
      secondDirectAttempt(o_)
          ? " did not complete within sixteen times the triangles of the 33-degree mesh, nor, the second and third "
            "times (the largest skinny triangles first, and where no point meets the bound the best point below it "
            "if it beats the off-center by enough), within 128 times (no more than about half a million triangles; "
            "not tried where that is under twice), nor the fourth time (the best points below the bound, the smallest "
            "skinny triangles first) within sixteen times"
          : " did not complete within sixteen times the triangles of the 33-degree mesh";
  static_assert(kDirectTriangleFactor == 16 && kSecondDirectTriangleFactor == 128 &&
                    kSecondDirectTriangleCeiling == (1u << 19) && kLargestFirstLeast == 2,
                "the message names these caps");
  return std::string("a minimum angle of ") + angles + " degrees (section 6.6's exemptions aside): refining to it directly" + direct + ", and from the 33-degree mesh "
         "refinement raised the bound a degree at a time until " + pushStop_ + "; this is the best mesh it reached; " + std::to_string(unmet) +
         " triangle(s) are below the bound";
}

RUPPERT_COLD_END

}  // namespace ruppert::detail
