// Refiner (refiner.h): inserting a vertex. Bowyer-Watson (or flips) at a located point, then the
// new triangles' region data and the vertex's attributes, flips that mend what rounding broke, and
// the checks of everything that changed.
#include "refine/refiner.h"

#include <algorithm>

#include "point_attributes.h"
#include "mesh/predicates.h"

namespace ruppert::detail {

// ---- insertion ---------------------------------------------------------------------------------
// Insert vertex v at `loc`; new triangles inherit region data and are checked; their
// subsegments are checked for encroachment. False (nothing changed) if the insertion would
// create an inverted triangle (rounding at the precision limit). `cavity`, if given, is the
// cavity of v's point at `loc` as Triangulation::cavity computed it, with nothing changed since.
bool Refiner::insertAt(std::uint32_t v, const Location& loc, const CavityRef& cavity) {
  const bool onSubsegment = loc.kind == Location::OnEdge && t_.con[loc.edge] != kFree;
  flipped_.clear();
  if (m_.attributeCount) interpolateAttributes(v, loc);
  // Bowyer-Watson first; where its cavity would wrap around a vertex at which the domain touches
  // itself, split and flip instead.
  const bool filled = cavity.tris ? t_.fillCavity(v, loc, *cavity.tris, *cavity.boundary, &newTris_, &parents_)
                                  : t_.insertVertex(v, loc, &newTris_, &parents_);
  if (!filled && !t_.insertVertexByFlips(v, loc, &newTris_, &parents_)) return false;
  ++inserted_;
  inheritRegionData();
  if (onSubsegment) mendDelaunay();
  for (std::uint32_t s : newTris_) {
    checkTriangle(s);
    const TriangleSlot& r = t_.slot(s);
    for (std::uint32_t i = 0; i < 3; ++i)
      if (r.con[i] != kFree) checkSubsegment(3 * s + i);
    // The outer edge's far side is an old triangle: its apex may now encroach nothing new, but a
    // split subsegment's halves need checking from both sides. (Both sides carry the same
    // constraint: a free edge, the common case, is settled without reading the old triangle.)
    if (r.twin[0] != kNone && r.con[0] != kFree) checkSubsegment(r.twin[0]);
  }
  recheckFlipped();
  return true;
}

// v's attributes from the edge or triangle it is about to be inserted in (point_attributes.h).
void Refiner::interpolateAttributes(std::uint32_t v, const Location& loc) {
  if (loc.kind == Location::OnEdge) return interpolateOnSegment(m_, v, t_.origin(loc.edge), t_.dest(loc.edge));
  const std::uint32_t* c = &t_.tv[3 * loc.tri];
  interpolateInTriangle(m_, v, c[0], c[1], c[2]);
}

// A vertex about to move to x: its attributes at x, from the triangle of its star that holds x.
void Refiner::reinterpolateMoved(std::uint32_t v, const double* x) {
  const std::vector<std::uint32_t>& star = optimal_.star();
  if (star.empty()) return;
  std::uint32_t pick = star.front();
  for (std::uint32_t h : star) {
    const double* o = t_.pt(t_.origin(h));
    const double* d = t_.pt(t_.dest(h));
    if (orient2d(o, d, x) >= 0 && orient2d(t_.pt(v), o, x) >= 0 && orient2d(d, t_.pt(v), x) >= 0) {
      pick = h;
      break;
    }
  }
  interpolateInTriangle(m_, v, v, t_.origin(pick), t_.dest(pick), x);
}

// Triangles changed by flips (in flipped_): queue them if bad, and their edges and the edges
// across them if encroached.
void Refiner::recheckFlipped() {
  for (std::uint32_t s : flipped_) {
    checkTriangle(s);
    for (std::uint32_t i = 0; i < 3; ++i) {
      checkSubsegment(3 * s + i);
      if (t_.twin[3 * s + i] != kNone) checkSubsegment(t_.twin[3 * s + i]);
    }
  }
}

// The new triangles take their parents' region data. Two passes: a new triangle may reuse the
// slot of another new triangle's parent.
// False where region data is uniform (MeshState::maxAreaOf); else grows the per-slot region arrays
// to cover every slot.
bool Refiner::regionDataCoversSlots() {
  const bool box = !m_.inDomain.empty();
  if (m_.maxArea.empty() && !box) return false;
  if (m_.attribute.size() < t_.slotCount()) {
    m_.attribute.resize(t_.slotCount(), 0);
    m_.maxArea.resize(t_.slotCount(), 0);
    if (box) m_.inDomain.resize(t_.slotCount(), 0);
  }
  return true;
}

void Refiner::inheritRegionData() {
  if (!regionDataCoversSlots()) return;
  const bool box = !m_.inDomain.empty();
  inherit_.resize(newTris_.size());
  for (std::size_t k = 0; k < newTris_.size(); ++k)
    inherit_[k] = {m_.attribute[parents_[k]], m_.maxArea[parents_[k]], box ? m_.inDomain[parents_[k]] : std::uint8_t(1)};
  for (std::size_t k = 0; k < newTris_.size(); ++k) {
    m_.attribute[newTris_[k]] = inherit_[k].attribute, m_.maxArea[newTris_[k]] = inherit_[k].maxArea;
    if (box) m_.inDomain[newTris_[k]] = inherit_[k].inDomain;
  }
}

// A subsegment's split point is rounded, so it lies a hair off the subsegment's line. Bowyer-Watson
// treats it as on the edge and joins it to the boundary of both sides' cavities; when it falls just
// outside one side's triangle, a free edge there can end up not locally Delaunay (found by fuzzing,
// tests/hostile/split-point-off-its-segment-broke-delaunay.poly: two segments meeting at 5e-8
// radians, split into pieces a million times longer than that offset). Lawson flips around the new triangles mend it; flip() keeps both slots, and the two
// triangles of a free edge share their region, so the slots' region data stays right. Slots that
// changed and are not new are left in flipped_ for re-checking.
void Refiner::mendDelaunay() {
  mendStack_.clear();
  for (std::uint32_t s : newTris_)
    for (std::uint32_t i = 0; i < 3; ++i) mendStack_.push_back(3 * s + i);
  t_.legalize(mendStack_, &flipped_);
  std::sort(flipped_.begin(), flipped_.end());
  flipped_.erase(std::unique(flipped_.begin(), flipped_.end()), flipped_.end());
  flipped_.erase(std::remove_if(flipped_.begin(), flipped_.end(),
                                [&](std::uint32_t s) {
                                  return std::find(newTris_.begin(), newTris_.end(), s) != newTris_.end();
                                }),
                 flipped_.end());
}

// `placed`: the event's kind when a placement other than the first choice chose the point.
void Refiner::insertSteiner(const BadTriangle& bt, const double* target, const Location& loc, VertexKind kind, const CavityRef& known, std::optional<EventKind> placed) {
  if (!mayInsert()) return;
  const std::uint32_t v = m_.addVertex(target[0], target[1], kind, -1);
  cornerForNewVertex();
  if (!insertAt(v, loc, known)) {
    m_.kind[v] = VertexKind::Unused;
    ++floorHits_;
    return;
  }
  if (o_.trace) {
    Event e;
    e.kind = placed ? *placed : kind == VertexKind::OffCenter ? EventKind::OffCenter : EventKind::Circumcenter;
    e.vertex = v, e.x = target[0], e.y = target[1], e.t0 = bt.a, e.t1 = bt.b, e.t2 = bt.c;
    out_.events.push_back(e);
  }
}

}  // namespace ruppert::detail
