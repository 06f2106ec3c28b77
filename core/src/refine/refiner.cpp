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
// This file: Refiner's main loop, and what it offers a control around it (loop_control.h). The
// rest of Refiner (refiner.h) is in refine_checks.cpp, refine_split.cpp, refine_insert.cpp,
// refine_curve.cpp, refine_wide.cpp and refine_result.cpp.
#include "refine/refiner.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "cold_code.h"
#include "refine/refine_setup.h"

namespace ruppert::detail {

Refiner::Refiner(MeshState& m, const RefinePlan& plan, LoopControl* control)
    : m_(m),
      t_(m.tri),
      o_(*m.options),
      plan_(plan),
      stageDegrees_(plan.first),
      theta_(radians(plan.first)),
      sin2Theta_(sin2Bound(theta_)),
      cosMaxAngle_(m.options->maxAngle > 0 ? std::cos(radians(m.options->maxAngle)) - 1e-12 : -2),
      mesh_(m.tri, m.input, sin2Theta_, lensCos2For(o_, theta_)),
      petal_(o_.placement == Placement::Petal ? theta_ : 0),
      optimal_(theta_, plan.belowBoundGain),
      control_(control) {
  mesh_.curveFirst = m.curves->first;
  bad_.setLargestFirst(plan.largestFirst);
}

// §6.2-6.3: split encroached subsegments first; then the bad triangle with the smallest shortest
// edge (or as BadTriangleQueue orders them), whose point may be rejected for splits instead. A
// control (loop_control.h) may raise the bound when the queues run dry, stop the loop, and put an
// earlier mesh of the run in place of the last.
RefineOutcome Refiner::run() {
  const double demand = areaDemand(m_);
  const std::uint64_t budget = plan_.budget != kAutoSteinerBudget ? plan_.budget : automaticSteinerBudget(m_, demand);
  budget_ = budget > plan_.used ? budget - plan_.used : 0;
  guarded_ = plan_.budget == kAutoSteinerBudget;
  guardBase_ = static_cast<double>(budget);
  reserveForAreaBounds(m_, budget_, demand);
  queueEverything();
  bool stop = false;
  while (!stop) {
    while (!encroached_.empty() && !stop) {
      const EdgeRef e = encroached_.back();
      encroached_.pop_back();
      const std::uint32_t h = edgeOf(e);
      if (h == kNone || t_.con[h] == kFree) continue;
      if (!isEncroached(h) && !(t_.con[h] >= mesh_.curveFirst && curvePieceTooCoarse(h))) continue;
      if (!scratchReserved_) reserveScratch();
      splitSubsegment(h, nullptr, nullptr);
      stop = outOfBudget();
    }
    if (stop) break;
    BadTriangle bt;
    if (!bad_.pop(bt)) {
      const LoopControl::Next next = control_ ? control_->queuesEmpty(*this) : LoopControl::Next::Done;
      if (next == LoopControl::Next::Done) break;
      stop = next == LoopControl::Next::Stop;
      continue;
    }
    if (!isCurrent(t_, bt)) continue;  // stale entry: the triangle is gone
    if (!scratchReserved_) reserveScratch();
    splitTriangle(bt);
    stop = outOfBudget() || (control_ && control_->stopAfterStep(*this));
  }
  steps_ = inserted_;
  if (control_) control_->ended(*this, stop);
  finish();
  return std::move(out_);
}

// The initial queues (§6.3): every subsegment and every triangle, linear in the mesh size.
void Refiner::queueEverything() {
  for (std::uint32_t s = 0; s < t_.slotCount(); ++s) {
    if (!t_.alive(s)) continue;
    checkTriangle(s);
    for (std::uint32_t i = 0; i < 3; ++i) checkSubsegment(3 * s + i);
  }
}

// ---- for the control (loop_control.h) -------------------------------------------------------------
// Once per stage or per score of the mesh: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

void Refiner::reserveScratch() {
  scratchReserved_ = true;
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

void Refiner::raiseBound(double degrees) {
  setBound(degrees);
  queueEverything();
}

MeshScore Refiner::survey(double sin2Requested) const {
  MeshScore sc;
  for (std::uint32_t s = 0; s < t_.slotCount(); ++s) {
    t_.prefetchCorners(s + Triangulation::kScanAhead);
    if (!t_.alive(s)) continue;
    ++sc.triangles;
    sc.domainTriangles += m_.inDomain.empty() || m_.inDomain[s];
    const TriangleQuality q = qualityAt(s);
    const double bound = maxAreaAt(s);
    if (bound > 0 && q.area > bound * (1 + 1e-9)) ++sc.large;
    if (q.sin2MinAngle < sin2Requested) {
      const TriangleShape sh = shapeOf(t_.pt(t_.tv[3 * s]), t_.pt(t_.tv[3 * s + 1]), t_.pt(t_.tv[3 * s + 2]));
      if (nestledInInputAngle(s, sh) || seditious(s, sh)) continue;
      ++sc.belowRequested;
      if (q.sin2MinAngle < sin2Theta_) ++sc.belowStage;
    }
    sc.minSin2 = std::min(sc.minSin2, q.sin2MinAngle);
  }
  return sc;
}

void Refiner::returnEarlier(MeshState&& mesh, std::uint64_t steps, std::size_t events, std::uint64_t rejected) {
  steps_ = steps;
  m_ = std::move(mesh);
  out_.events.resize(events);
  out_.rejected = rejected;
}

RUPPERT_COLD_END

}  // namespace ruppert::detail
