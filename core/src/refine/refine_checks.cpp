// Refiner (refiner.h): what is bad. Encroached subsegments (§6.2, 6.3), skinny and large triangles
// and their area bounds (§6.4), the Steiner budget, forbidden splits, and the exemptions of §6.6.
#include "refine/refiner.h"

#include <algorithm>
#include <cmath>

#include "cdt/old_mesh.h"
#include "mesh/predicates.h"
#include "refine/refine_setup.h"
#include "cold_code.h"

namespace ruppert::detail {

// ---- tests ---------------------------------------------------------------------------------
// O(1) test of Exercise 1: the subsegment h is encroached iff an apex on either side sees it at
// 90 degrees or more.
bool Refiner::isEncroached(std::uint32_t h) const {
  if (mesh_.encroachesEdge(t_.pt(t_.apex(h)), h)) return true;
  const std::uint32_t g = t_.twin[h];
  return g != kNone && mesh_.encroachesEdge(t_.pt(t_.apex(g)), h);
}

void Refiner::checkSubsegment(std::uint32_t h) {
  if (t_.con[h] == kFree) [[likely]] return;
  if (mesh_.encroachesEdge(t_.pt(t_.apex(h)), h) || (t_.con[h] >= mesh_.curveFirst && curvePieceTooCoarse(h)))
    encroached_.push_back({t_.origin(h), t_.dest(h), h});
}

// The half-edge for a queued edge: the remembered one if it still is that edge, else a search.
// (The search alone is not enough: at a vertex where the domain touches itself, rotating around
// the vertex cannot reach every triangle.)
std::uint32_t Refiner::edgeOf(const EdgeRef& e) const {
  const std::uint32_t t = e.hint / 3;
  if (t_.alive(t))
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = 3 * t + i;
      const std::uint32_t o = t_.origin(h), d = t_.dest(h);
      if ((o == e.a && d == e.b) || (o == e.b && d == e.a)) return h;
    }
  return t_.findEdge(e.a, e.b);
}

TriangleQuality Refiner::qualityAt(std::uint32_t s) const {
  const TriangleSlot& r = t_.slot(s);
  return qualityOf(t_.pt(r.tv[0]), t_.pt(r.tv[1]), t_.pt(r.tv[2]));
}

double Refiner::maxAreaFromEverySource(std::uint32_t s) const {
  double bound = m_.maxAreaOf(s);
  if (o_.sizeFunction) {
    const double* p0 = t_.pt(t_.tv[3 * s]);
    const double* p1 = t_.pt(t_.tv[3 * s + 1]);
    const double* p2 = t_.pt(t_.tv[3 * s + 2]);
    const double cx = m_.input.toUser((p0[0] + p1[0] + p2[0]) / 3);
    const double cy = m_.input.toUser((p0[1] + p1[1] + p2[1]) / 3);
    const double user = o_.sizeFunction(cx, cy);
    if (std::isfinite(user) && user > 0) {
      const double internal = m_.input.areaToInternal(user);
      bound = bound > 0 ? std::min(bound, internal) : internal;
    }
  }
  if (m_.oldMesh != nullptr) {
    const double old = oldMeshBound(s);
    if (old > 0) bound = bound > 0 ? std::min(bound, old) : old;
  }
  return bound;
}

// Refining a mesh: the old mesh's bound for slot s (old_mesh.h), remembered with the corner
// coordinates it was computed for (vertex ids would not do: Placement::Optimal moves vertices).
double Refiner::oldMeshBound(std::uint32_t s) const {
  if (oldBound_.size() < t_.slotCount()) oldBound_.resize(t_.slotCount(), 0), oldBoundAt_.resize(6 * std::size_t(t_.slotCount()), NAN);
  const double* p[3] = {t_.pt(t_.tv[3 * s]), t_.pt(t_.tv[3 * s + 1]), t_.pt(t_.tv[3 * s + 2])};
  double* at = &oldBoundAt_[6 * std::size_t(s)];
  bool same = true;
  for (int i = 0; i < 6; ++i) same = same && at[i] == p[i / 2][i % 2];
  if (!same) {
    oldBound_[s] = m_.oldMesh->boundFor(p[0], p[1], p[2]);
    for (int i = 0; i < 6; ++i) at[i] = p[i / 2][i % 2];
  }
  return oldBound_[s];
}

void Refiner::checkTriangle(std::uint32_t s) {
  const TriangleSlot& r = t_.slot(s);
  const double* p0 = t_.pt(r.tv[0]);
  const double* p1 = t_.pt(r.tv[1]);
  const double* p2 = t_.pt(r.tv[2]);
  const TriangleQuality q = qualityOf(p0, p1, p2);
  const double bound = maxAreaAt(s);
  const bool large = bound > 0 && q.area > bound;
  const bool skinny = isSkinny(q);
  // A wide triangle (over maxAngle) is queued with the skinny ones: both are shape defects, fixed
  // smallest feature first, so that the mesh grades outwards from them.
  const bool wide = !skinny && isWide(p0, p1, p2);
  if (!skinny && !large && !wide) return;
  // The queue's key: the squared shortest edge of a skinny or wide triangle, the area of a too-large one.
  const double key = skinny || wide ? std::min({sq(p1, p2), sq(p2, p0), sq(p0, p1)}) : q.area;
  bad_.push(t_, s, skinny || wide, key, q.sin2MinAngle);
}

bool Refiner::isWide(const double* p0, const double* p1, const double* p2) const {
  return cosMaxAngle_ > -1 && largestAngleCos(p0, p1, p2) < cosMaxAngle_;
}

// Checked before every insertion, so that a budget of k inserts at most k vertices (0: none).
// The loop also stops once k are in (outOfBudget), so any k > 0 gives the first k insertions of
// the unbounded run.
bool Refiner::mayInsert() {
  if (inserted_ < budget_ || extendBudget()) return true;
  budgetHit_ = true;
  return false;
}

// Only at the automatic budget's checkpoints (a few per run that passes the first): compiled for
// size (cold_code.h).
RUPPERT_COLD_BEGIN
bool Refiner::extendBudget() {
  if (!guarded_ || guardStopped_) return false;
  const std::uint64_t steps = plan_.used + inserted_;
  measureCorners();
  const double base = guardBase_ + kGuardStepsPerInverseRadian * inverseGaps_;
  const std::uint64_t next = nextGuardCheckpoint(m_, base, steps, guardIntegral_);
  if (next == 0) {
    guardStopped_ = true;
    return false;
  }
  budget_ = next - plan_.used;
  return true;
}
RUPPERT_COLD_END

bool Refiner::outOfBudget() {
  if (inserted_ >= budget_ && !extendBudget()) {
    budgetHit_ = true;
    return true;
  }
  if (o_.onProgress && (inserted_ & 4095) == 0 && inserted_ > 0) {
    Progress p;
    p.insertedVertices = inserted_;
    p.triangles = t_.slotCount() - t_.freeSlots.size();
    p.worstAngle = bad_.worstQueuedAngle(o_.minAngle);
    if (!o_.onProgress(p)) {
      cancelled_ = true;
      return true;
    }
  }
  return false;
}

// ---- forbidden splits (Options::noBoundarySteiner, noSegmentSteiner) ---------------------------
// Such a subsegment is never split. A point that encroaches it, lies beyond it or on it is not
// inserted; instead a triangle over its area bound gets a point pulled back towards its centroid
// (halfway or a quarter of the way, if that encroaches no subsegment, else the centroid itself)
// (placeAwayFromForbidden); a triangle that is only skinny stays as it is.
// Only centroids of triangles over their area bound may lie in a forbidden subsegment's lens; what
// stays bad is reported as SegmentSplitForbidden. The Steiner budget and the length floor bound
// the work regardless.
bool Refiner::onDomainBoundary(std::uint32_t h) const {
  const std::uint32_t g = t_.twin[h];
  if (m_.inDomain.empty()) return g == kNone;
  // Bounding-box variant: the box's sides are not the domain's boundary.
  return g != kNone && m_.inDomain[h / 3] != m_.inDomain[g / 3];
}

bool Refiner::splitForbidden(std::uint32_t h) const {
  if (o_.noSegmentSteiner && (t_.con[h] >= 0 || onDomainBoundary(h))) return true;
  return o_.noBoundarySteiner && onDomainBoundary(h);
}

const char* Refiner::forbiddenRule() const {
  return o_.noSegmentSteiner ? "no new vertex may lie on a segment"
                             : "no new vertex may lie on the domain's boundary";
}

}  // namespace ruppert::detail
