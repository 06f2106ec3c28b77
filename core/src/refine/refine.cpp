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
// This file: refine() (direct, or staged above kStagedAboveDegrees) and Refiner's main loop and
// stages. The rest of Refiner (refiner.h) is in refine_checks.cpp, refine_split.cpp,
// refine_insert.cpp and refine_result.cpp.
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
      if (h == kNone || t_.con[h] == kFree || !isEncroached(h)) continue;
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

namespace {

bool completeOutcome(const RefineOutcome& r) {
  for (const Reason& reason : r.reasons)
    if (reason.kind != ReasonKind::SmallInputAngle && reason.kind != ReasonKind::SeditiousEdge) return false;
  return true;
}

std::uint64_t liveTriangles(const MeshState& m) { return m.tri.slotCount() - m.tri.freeSlots.size(); }

// The stages' plans, run once per call: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

// The triangles the output will hold: the bounding-box variant's outside leaves after refinement.
std::uint64_t domainTriangles(const MeshState& m) {
  if (m.inDomain.empty()) return liveTriangles(m);
  std::uint64_t n = 0;
  for (std::uint32_t s = 0; s < m.tri.slotCount(); ++s) n += m.tri.alive(s) && m.inDomain[s];
  return n;
}

// Which way refineStaged went, and what replaying its first steps needs.
struct StagedPath {
  enum Branch { AsAsked, Direct, Push } branch = AsAsked;
  int attempt = 0;               // Direct: which direct attempt (directPlan)
  std::uint64_t steps = 0;       // steps (insertions, moves) of the mesh returned
  std::uint64_t reachSteps = 0;  // of the 33-degree mesh (the push's first part)
  std::uint64_t base = 0;        // the 33-degree mesh's triangles (the caps' unit)
  std::uint64_t baseDomain = 0;  // ... inside the domain (the push's promise's unit)
};

// Direct attempt number `attempt` (0 to 3; bound_push.h): as without stages; then the largest skinny
// triangles first with the best points below the bound, those that beat the off-center's smallest
// new angle by kBelowBoundGain and then only those that beat it by kStrictBelowBoundGain (up to 128
// times the 33-degree mesh); last, smallest first again with the best points below the bound (what
// the second attempt was before largest first: 3 of the 300 generated PLCs at 38 degrees complete
// only this way, none at 40).
RefinePlan directPlan(double requested, std::uint64_t base, int attempt, std::uint64_t budget) {
  RefinePlan plan = RefinePlan::direct(requested, budget);
  plan.triangleCap = kDirectTriangleFactor * base;
  if (attempt == 0) return plan;
  if (attempt == 3) {
    plan.bestBelowBound = true, plan.belowBoundGain = kBelowBoundGain;
    return plan;
  }
  plan.triangleCap = std::min(kSecondDirectTriangleFactor * base, kSecondDirectTriangleCeiling);
  plan.bestBelowBound = plan.largestFirst = true;
  plan.belowBoundGain = attempt == 1 ? kBelowBoundGain : kStrictBelowBoundGain;
  return plan;
}

RefinePlan pushPlan(double requested, const StagedPath& path, std::uint64_t budget) {
  RefinePlan plan{requested, kReachableDegrees, true, kPushTriangleFactor * path.base, path.reachSteps};
  plan.domainCap = kPushTriangleFactor * path.baseDomain;
  plan.budget = budget;
  return plan;
}

// The push continues the 33-degree run: its trace and rejections come first.
RefineOutcome afterReach(RefineOutcome reach, RefineOutcome out) {
  reach.events.insert(reach.events.end(), out.events.begin(), out.events.end());
  out.events = std::move(reach.events);
  out.rejected += reach.rejected;
  return out;
}

// A request above kStagedAboveDegrees (bound_push.h), with a Steiner budget of `budget` steps: the
// 33-degree mesh first, for its size; then the requested bound directly, up to sixteen times that
// size, as without stages; with the optimal placement, where that fails, directly again (three more
// attempts, directPlan) with RefinePlan::bestBelowBound; else the push from the 33-degree mesh. The
// way taken goes to path.
RefineOutcome refineStaged(MeshState& m, std::uint64_t budget, StagedPath& path) {
  const double requested = m.options->minAngle;
  MeshState start = m;
  Refiner reachRun(m, RefinePlan::direct(kReachableDegrees, budget));
  RefineOutcome reach = reachRun.run();
  if (!completeOutcome(reach)) {  // not even 33 degrees: refine as asked, as without stages
    m = std::move(start);
    Refiner run(m, RefinePlan::direct(requested, budget));
    RefineOutcome out = run.run();
    path.branch = StagedPath::AsAsked, path.steps = run.steps();
    return out;
  }
  path.reachSteps = reachRun.steps();
  path.base = liveTriangles(m);
  path.baseDomain = domainTriangles(m);
  // True (and m the mesh) where a direct run from the unrefined mesh completes within the cap.
  auto direct = [&](MeshState from, int number, const RefinePlan& plan, RefineOutcome& out) {
    Refiner attempt(from, plan);
    out = attempt.run();
    if (attempt.capHit() || !completeOutcome(out)) return false;
    m = std::move(from);
    path.branch = StagedPath::Direct, path.attempt = number, path.steps = attempt.steps();
    return true;
  };
  RefineOutcome out;
  for (int number = 0; number < directAttempts(*m.options); ++number) {
    const RefinePlan plan = directPlan(requested, path.base, number, budget);
    if (plan.largestFirst && plan.triangleCap < kLargestFirstLeast * path.base) continue;  // too large an input
    if (direct(start, number, plan, out)) return out;
  }
  start = MeshState{};  // free it before the push
  Refiner push(m, pushPlan(requested, path, budget));
  out = push.run();
  path.branch = StagedPath::Push, path.steps = push.steps();
  return afterReach(std::move(reach), std::move(out));
}

// The first k steps of the way refineStaged went (with the automatic budget), from the unrefined
// mesh m: the same plans, stopped at k.
RefineOutcome replayStaged(MeshState& m, const StagedPath& path, std::uint64_t k) {
  const double requested = m.options->minAngle;
  switch (path.branch) {
    case StagedPath::AsAsked:
      return Refiner(m, RefinePlan::direct(requested, k)).run();
    case StagedPath::Direct:
      return Refiner(m, directPlan(requested, path.base, path.attempt, k)).run();
    case StagedPath::Push:
      break;
  }
  // The 33-degree run again, judged by the requested bound where it is the result (stopped at k
  // steps, it ends before the bound could be raised).
  RefinePlan first{requested, kReachableDegrees, false, 0, 0};
  first.budget = std::min(k, path.reachSteps);
  RefineOutcome reach = Refiner(m, first).run();
  if (k <= path.reachSteps) return reach;
  RefinePlan push = pushPlan(requested, path, k);
  push.prefix = true;
  return afterReach(std::move(reach), Refiner(m, push).run());
}

}  // namespace

// Above kStagedAboveDegrees with a budget k under the automatic one, the result is the first k steps
// of the automatic run's (what maxSteiner gives below that by itself, and what the page's replay of
// a run step by step relies on): that run first, and where it took more than k steps, its way again
// from the start, stopped at k. (Budgeting each stage instead would take another way: a 33-degree
// mesh done within k steps and a direct attempt cut short by the budget lead to the push.)
RefineOutcome refine(MeshState& m) {
  if (!(m.options->minAngle > kStagedAboveDegrees))
    return Refiner(m, RefinePlan::direct(m.options->minAngle, m.options->maxSteiner)).run();
  const double demand = areaDemand(m);
  const std::uint64_t automatic = automaticSteinerBudget(m, demand);
  const std::uint64_t k = std::min(m.options->maxSteiner, automatic);
  StagedPath path;
  if (k == automatic) return refineStaged(m, m.options->maxSteiner, path);  // automatic: guarded
  // A budget of 0 inserts nothing, on every way: no need to know which.
  if (k == 0) return Refiner(m, RefinePlan::direct(m.options->minAngle, 0)).run();
  MeshState start = m;
  RefineOutcome out = refineStaged(m, kAutoSteinerBudget, path);
  if (path.steps <= k) return out;
  m = std::move(start);
  return replayStaged(m, path, k);
}

RUPPERT_COLD_END

}  // namespace ruppert::detail
