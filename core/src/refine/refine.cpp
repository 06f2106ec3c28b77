// Constrained Delaunay refinement: Ruppert's algorithm as in Cheng, Dey & Shewchuk, "Delaunay Mesh
// Generation", chapter 6, with
//   §6.2  encroachment = a vertex in a subsegment's closed diametral disk; encroached subsegments are
//         split first; a skinny triangle's circumcenter is rejected if it encroaches a subsegment,
//         which is split instead;
//   §6.3  a queue of encroached subsegments and bucketed bad-triangle queues (smallest shortest
//         edge first, see checkTriangle), both lazily invalidated; only new triangles and their edges are checked; O(1) encroachment test
//         (the angle opposite a subsegment is >= 90 degrees);
//   §6.4  size bounds: triangles larger than the region's / global / user-function area are split too;
//   §6.6  concentric-shell splitting of subsegments at acute input corners; triangles nestled in a
//         small input angle and triangles whose shortest edge is seditious are not split;
//   §6.7  the CDT holds only the domain, so refinement never leaves it;
//   §6.8  off-centers (Üngör): the new vertex sits on the shortest edge's bisector, no farther than
//         where the triangle it forms with that edge just meets the bound; Placement::Petal goes on
//         to search the shortest edge's petal for a point that makes no new skinny triangle;
//         Placement::Optimal takes Erten and Üngör's locally optimal point, or moves a free vertex
//         (optimal_placement.h).
// Termination for any input: besides §6.6, a Steiner budget and a floor on subsegment length below
// which doubles cannot place new points; hitting either ends refinement with complete = false.
//
// Terminology: "subsegment" = constrained edge (con != kFree); "corner" = an input or intersection
// vertex where two constrained edges meet at less than 90 degrees; rho = circumradius / shortest edge.
//
// This file: Refiner's main loop and stages. refine() itself (direct, or staged above
// kStagedAboveDegrees) is in refine/above34/staged.cpp. The rest of Refiner (refiner.h) is in
// refine_checks.cpp, refine_split.cpp, refine_insert.cpp and refine_result.cpp.
#include "refine/refine.h"

#include <algorithm>
#include <utility>

#include "cold_code.h"
#include "refine/refine_setup.h"
#include "refine/refiner.h"

namespace ruppert::detail {

RefineOutcome Refiner::run() {
  double inverseGaps = 0;
  corner_ = acuteCorners(m_, &inverseGaps);
  const double demand = areaDemand(m_);
  const std::uint64_t budget = plan_.budget != kAutoSteinerBudget ? plan_.budget : automaticSteinerBudget(m_, demand);
  budget_ = budget > plan_.used ? budget - plan_.used : 0;
  guarded_ = plan_.budget == kAutoSteinerBudget;
  guardBase_ = static_cast<double>(budget) + kGuardStepsPerInverseRadian * inverseGaps;
  reserveForAreaBounds(m_, budget_, demand);
  // Initial queues: every subsegment and every triangle (linear in the mesh size, §6.3).
  for (std::uint32_t s = 0; s < t_.slotCount(); ++s) {
    if (!t_.alive(s)) continue;
    checkTriangle(s);
    for (std::uint32_t i = 0; i < 3; ++i) checkSubsegment(3 * s + i);
  }
  bool stop = false;
  while (!stop) {
    while (!encroached_.empty() && !stop) {
      const EdgeRef e = encroached_.back();
      encroached_.pop_back();
      const std::uint32_t h = edgeOf(e);
      if (h == kNone || t_.con[h] == kFree) continue;
      if (!isEncroached(h) && !(t_.con[h] >= mesh_.curveFirst && curvePieceTooCoarse(h))) continue;
      splitSubsegment(h, nullptr, nullptr);
      stop = outOfBudget();
    }
    if (stop) break;
    BadTriangle bt;
    if (!bad_.pop(bt)) {
      if (nextStage()) {
        stop = overCap();  // the new stage's first score may find the mesh over the push's cap
        continue;
      }
      break;
    }
    if (!isCurrent(t_, bt)) continue;  // stale entry: the triangle is gone
    splitTriangle(bt);
    stop = outOfBudget() || overCap() || pushStopped();
  }
  steps_ = inserted_;
  if (pushing_ && stop && !cancelled_ && !(plan_.prefix && budgetHit_)) endPush();
  finish();
  return std::move(out_);
}

// ---- stages (bound_push.h) -------------------------------------------------------------------
// Once per stage or per quarter of the mesh's size in insertions: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

void Refiner::reserveScratch() {
  for (auto* list : {&newTris_, &parents_, &flipped_, &mendStack_, &cavityTris_, &cavityBoundary_, &splitTris_, &splitBoundary_})
    list->reserve(kScratchReserve);
  encroached_.reserve(kScratchReserve), inherit_.reserve(kScratchReserve);
  if (o_.placement == Placement::Optimal) optimal_.reserveScratch();
}

void Refiner::setBound(double degrees) {
  stageDegrees_ = degrees;
  theta_ = radians(degrees);
  sin2Theta_ = sin2Bound(theta_);
  mesh_.sin2Theta = sin2Theta_;
  mesh_.lensCos2 = lensCos2For(o_, theta_);
  if (o_.placement == Placement::Petal) petal_ = PetalPlacement(theta_);
  if (o_.placement == Placement::Optimal) optimal_ = OptimalPlacement(theta_, plan_.belowBoundGain);
}

// The queue is empty: if a stage below the requested bound just completed, raise the bound by a
// step and queue what the new bound makes bad. False when there is no next stage.
bool Refiner::nextStage() {
  if (!(stageDegrees_ < plan_.requested)) return false;
  if (plan_.track) {
    if (!pushing_) push_.setBase(liveTriangles());
    observe();
  }
  pushing_ = true;
  setBound(std::min(plan_.requested, stageDegrees_ + kStageStepDegrees));
  push_.newStage(inserted_);
  for (std::uint32_t s = 0; s < t_.slotCount(); ++s) {
    if (!t_.alive(s)) continue;
    checkTriangle(s);
    for (std::uint32_t i = 0; i < 3; ++i) checkSubsegment(3 * s + i);
  }
  return true;
}

// The push's domain cap (observe) or the live-triangle cap of the push or a direct attempt.
bool Refiner::overCap() {
  if (!overDomainCap_ && (!plan_.triangleCap || liveTriangles() <= plan_.triangleCap)) return false;
  capHit_ = true;
  pushStop_ = "the mesh reached four times the 33-degree mesh's triangles";
  return true;
}

// Scores the mesh and, if it is the best so far, keeps a copy. A mesh over the push's domain cap is
// never kept, and stops the push (overCap).
void Refiner::observe() {
  const MeshScore sc = score();
  if (plan_.domainCap && sc.domainTriangles > plan_.domainCap) {
    overDomainCap_ = true;
    return;
  }
  if (!push_.observe(sc, inserted_)) return;
  best_.mesh = MeshState(m_);  // a copy moved in: MeshState's copy assignment, 2 KB of wasm, is not needed
  best_.events = out_.events.size(), best_.rejected = out_.rejected;
}

// During a push: scores the mesh every so often (every quarter of its size in insertions, so
// scores and copies cost a fraction of the refinement) and stops when a stage stops reducing its
// bad triangles.
bool Refiner::pushStopped() {
  if (!plan_.track || !pushing_ || inserted_ < nextScoreAt_) return false;
  nextScoreAt_ = inserted_ + std::max<std::uint64_t>(2048, liveTriangles() / 4);
  observe();
  if (overDomainCap_) return overCap();
  if (!push_.stalled(inserted_)) return false;
  pushStop_ = "a stage stopped reducing its skinny triangles";
  return true;
}

// The push stopped short of the requested bound: the result is its best mesh.
void Refiner::endPush() {
  if (!plan_.track) return;
  if (budgetHit_) pushStop_ = "the Steiner budget was reached";
  if (!capHit_) observe();  // a mesh over the cap is never the result
  unreachable_ = true;
  if (push_.bestStep() == inserted_) return;
  steps_ = push_.bestStep();
  m_ = std::move(best_.mesh);
  out_.events.resize(best_.events);
  out_.rejected = best_.rejected;
}

// The whole mesh against the requested bound and the current stage's.
MeshScore Refiner::score() const {
  MeshScore sc;
  for (std::uint32_t s = 0; s < t_.slotCount(); ++s) {
    t_.prefetchCorners(s + Triangulation::kScanAhead);
    if (!t_.alive(s)) continue;
    ++sc.triangles;
    sc.domainTriangles += m_.inDomain.empty() || m_.inDomain[s];
    const TriangleQuality q = qualityAt(s);
    const double bound = maxAreaAt(s);
    if (bound > 0 && q.area > bound * (1 + 1e-9)) ++sc.large;
    if (q.sin2MinAngle < sin2Requested_) {
      const TriangleShape sh = shapeOf(t_.pt(t_.tv[3 * s]), t_.pt(t_.tv[3 * s + 1]), t_.pt(t_.tv[3 * s + 2]));
      if (nestledInInputAngle(s, sh) || seditious(s, sh)) continue;
      ++sc.belowRequested;
      if (q.sin2MinAngle < sin2Theta_) ++sc.belowStage;
    }
    sc.minSin2 = std::min(sc.minSin2, q.sin2MinAngle);
  }
  return sc;
}

RUPPERT_COLD_END

}  // namespace ruppert::detail
