// searchBound (bound_search.h): the 33-degree mesh first, then direct attempts at the requested
// bound (directPlan), else the push from the 33-degree mesh (pushPlan); searchOnce takes that way,
// replaySearch replays its first k steps under a smaller Steiner budget. Each run is the chapter's
// loop (refine/refiner.h) under a StageControl (stage_control.h).
#include "refine/bound_search/bound_search.h"

#include <algorithm>
#include <utility>

#include "cold_code.h"
#include "refine/bound_search/stage_control.h"
#include "refine/refine_setup.h"
#include "refine/refiner.h"

namespace ruppert::detail {

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

// Which way searchOnce went, and what replaying its first steps needs.
struct SearchPath {
  enum Branch { AsAsked, Direct, Push } branch = AsAsked;
  int attempt = 0;               // Direct: which direct attempt (directPlan)
  std::uint64_t steps = 0;       // steps (insertions, moves) of the mesh returned
  std::uint64_t reachSteps = 0;  // of the 33-degree mesh (the push's first part)
  std::uint64_t base = 0;        // the 33-degree mesh's triangles (the caps' unit)
  std::uint64_t baseDomain = 0;  // ... inside the domain (the push's promise's unit)
};

// The best complete direct attempt so far (searchOnce).
struct DirectBest {
  bool found = false;
  std::uint64_t triangles = 0;  // live triangles
  int attempt = 0;
  std::uint64_t steps = 0;
  MeshState mesh;
  RefineOutcome out;
};

// One run of the loop within the search: the loop's plan and the control's rules.
struct SearchRun {
  RefinePlan loop;
  StageRules rules;
};

struct RunResult {
  RefineOutcome out;
  std::uint64_t steps = 0;  // Refiner::steps()
  bool capHit = false;
};

RunResult runLoop(MeshState& m, const SearchRun& run) {
  StageControl control(*m.options, run.loop.requested, run.rules);
  Refiner loop(m, run.loop, &control);
  RunResult r;
  r.out = loop.run();
  r.steps = loop.steps(), r.capHit = control.capHit();
  return r;
}

// Direct attempt number `attempt` (0 to 3; bound_push.h): as without stages; then the largest skinny
// triangles first with the best points below the bound, those that beat the off-center's smallest
// new angle by kBelowBoundGain and then only those that beat it by kStrictBelowBoundGain (up to 128
// times the 33-degree mesh); last, smallest first again with the best points below the bound (what
// the second attempt was before largest first: 3 of the 300 generated PLCs at 38 degrees complete
// only this way, none at 40).
SearchRun directPlan(double requested, std::uint64_t base, int attempt, std::uint64_t budget) {
  SearchRun run{RefinePlan::direct(requested, budget), {}};
  RefinePlan& plan = run.loop;
  run.rules.triangleCap = kDirectTriangleFactor * base;
  if (attempt == 0) return run;
  if (attempt == 3) {
    plan.bestBelowBound = true, plan.belowBoundGain = kBelowBoundGain;
    return run;
  }
  run.rules.triangleCap = std::min(kSecondDirectTriangleFactor * base, kSecondDirectTriangleCeiling);
  plan.bestBelowBound = plan.largestFirst = true;
  plan.belowBoundGain = attempt == 1 ? kBelowBoundGain : kStrictBelowBoundGain;
  return run;
}

// The push: from the 33-degree mesh (its steps already used), the bound raised stage by stage.
SearchRun pushPlan(double requested, const SearchPath& path, std::uint64_t budget) {
  SearchRun run;
  run.loop.requested = requested, run.loop.first = kReachableDegrees;
  run.loop.used = path.reachSteps, run.loop.budget = budget;
  run.rules.track = true;
  run.rules.triangleCap = kPushTriangleFactor * path.base;
  run.rules.domainCap = kPushTriangleFactor * path.baseDomain;
  return run;
}

// The push continues the 33-degree run: its trace and rejections come first.
RefineOutcome afterReach(RefineOutcome reach, RefineOutcome out) {
  reach.events.insert(reach.events.end(), out.events.begin(), out.events.end());
  out.events = std::move(reach.events);
  out.rejected += reach.rejected;
  return out;
}

// A request above kSearchAboveDegrees (bound_push.h), with a Steiner budget of `budget` steps: the
// 33-degree mesh first, for its size; then the requested bound directly, up to sixteen times that
// size, as without stages; with the optimal placement, where that fails, directly again (three more
// attempts, directPlan) with RefinePlan::bestBelowBound; else the push from the 33-degree mesh. The
// way taken goes to path.
RefineOutcome searchOnce(MeshState& m, std::uint64_t budget, SearchPath& path) {
  const double requested = m.options->minAngle;
  MeshState start = m;
  Refiner reachRun(m, RefinePlan::direct(kReachableDegrees, budget));
  RefineOutcome reach = reachRun.run();
  if (!completeOutcome(reach)) {  // not even 33 degrees: refine as asked, as without stages
    m = std::move(start);
    Refiner run(m, RefinePlan::direct(requested, budget));
    RefineOutcome out = run.run();
    path.branch = SearchPath::AsAsked, path.steps = run.steps();
    return out;
  }
  path.reachSteps = reachRun.steps();
  path.base = liveTriangles(m);
  path.baseDomain = domainTriangles(m);
  // The smallest mesh of the direct attempts that complete: each later attempt is capped at the
  // best one's triangles, so it stops as soon as it cannot win; none runs after a mesh within
  // kDirectEnoughFactor of the 33-degree one.
  DirectBest best;
  for (int number = 0; number < directAttempts(*m.options); ++number) {
    SearchRun run = directPlan(requested, path.base, number, budget);
    std::uint64_t& cap = run.rules.triangleCap;
    if (run.loop.largestFirst && cap < kLargestFirstLeast * path.base) continue;  // too large an input
    if (best.found) cap = std::min(cap, best.triangles);
    MeshState from = start;
    RunResult attempt = runLoop(from, run);
    if (attempt.capHit || !completeOutcome(attempt.out)) continue;
    const std::uint64_t triangles = liveTriangles(from);
    if (best.found && triangles >= best.triangles) continue;
    best.found = true, best.triangles = triangles, best.attempt = number, best.steps = attempt.steps;
    best.mesh = std::move(from), best.out = std::move(attempt.out);
    if (triangles <= kDirectEnoughFactor * static_cast<double>(path.base)) break;
  }
  if (best.found) {
    m = std::move(best.mesh);
    path.branch = SearchPath::Direct, path.attempt = best.attempt, path.steps = best.steps;
    return std::move(best.out);
  }
  start = MeshState{};  // free it before the push
  RunResult push = runLoop(m, pushPlan(requested, path, budget));
  path.branch = SearchPath::Push, path.steps = push.steps;
  return afterReach(std::move(reach), std::move(push.out));
}

// The first k steps of the way searchOnce went (with the automatic budget), from the unrefined
// mesh m: the same plans, stopped at k.
RefineOutcome replaySearch(MeshState& m, const SearchPath& path, std::uint64_t k) {
  const double requested = m.options->minAngle;
  switch (path.branch) {
    case SearchPath::AsAsked:
      return Refiner(m, RefinePlan::direct(requested, k)).run();
    case SearchPath::Direct:
      return runLoop(m, directPlan(requested, path.base, path.attempt, k)).out;
    case SearchPath::Push:
      break;
  }
  // The 33-degree run again, judged by the requested bound where it is the result (stopped at k
  // steps, it ends before the bound could be raised).
  SearchRun first;
  first.loop.requested = requested, first.loop.first = kReachableDegrees;
  first.loop.budget = std::min(k, path.reachSteps);
  RefineOutcome reach = runLoop(m, first).out;
  if (k <= path.reachSteps) return reach;
  SearchRun push = pushPlan(requested, path, k);
  push.rules.prefix = true;
  return afterReach(std::move(reach), runLoop(m, push).out);
}

}  // namespace

// With a budget k under the automatic one, the result is the first k steps of the automatic run's
// (what maxSteiner gives below kSearchAboveDegrees by itself, and what the page's replay of a run
// step by step relies on): that run first, and where it took more than k steps, its way again from
// the start, stopped at k. (Budgeting each stage instead would take another way: a 33-degree mesh
// done within k steps and a direct attempt cut short by the budget lead to the push.)
RefineOutcome searchBound(MeshState& m) {
  const double demand = areaDemand(m);
  const std::uint64_t automatic = automaticSteinerBudget(m, demand);
  const std::uint64_t k = std::min(m.options->maxSteiner, automatic);
  SearchPath path;
  if (k == automatic) return searchOnce(m, m.options->maxSteiner, path);  // automatic: guarded
  // A budget of 0 inserts nothing, on every way: no need to know which.
  if (k == 0) return Refiner(m, RefinePlan::direct(m.options->minAngle, 0)).run();
  MeshState start = m;
  RefineOutcome out = searchOnce(m, kAutoSteinerBudget, path);
  if (path.steps <= k) return out;
  m = std::move(start);
  return replaySearch(m, path, k);
}

RUPPERT_COLD_END

}  // namespace ruppert::detail
