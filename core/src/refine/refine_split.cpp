// Refiner (refiner.h): splitting. Where a subsegment is split (midpoints, concentric shells, §6.6),
// which point a bad triangle gets (circumcenter, off-center, placements, §6.8), and the rejection of
// points that encroach a subsegment, which is split instead (§6.2, 6.3).
#include "refine/refiner.h"

#include <algorithm>
#include <cmath>

#include "point_attributes.h"
#include "mesh/predicates.h"
#include "refine/placement/segment_slide.h"

namespace ruppert::detail {

// The fallback of a triangle whose point was refused (see above): between the point and the
// triangle's centroid, the first of three points that lies in the domain on this side and
// encroaches no subsegment. The centroid, the last, may encroach a subsegment that can be split
// (one inside the domain, under noBoundarySteiner): that one is split, as for any rejected point
// (§6.3), and the triangle comes back; where none can be (the length floor), the centroid goes in
// all the same. (Before, it was left out, and the triangle stayed over its area bound: a sweep of
// generated PLCs found 8 such meshes in 1,636 runs with noBoundarySteiner.) False if nothing changed.
bool Refiner::placeAwayFromForbidden(const BadTriangle& bt, const double* const* p, const double* refused) {
  const double g[2] = {(p[0][0] + p[1][0] + p[2][0]) / 3, (p[0][1] + p[1][1] + p[2][1]) / 3};
  for (double lambda : {0.5, 0.25, 0.0}) {
    const double q[2] = {g[0] + lambda * (refused[0] - g[0]), g[1] + lambda * (refused[1] - g[1])};
    std::uint32_t blocked;
    const Location loc = mesh_.walk(bt.slot, q, blocked);
    if (blocked != kNone || loc.kind == Location::Lost || loc.kind == Location::OnVertex) continue;
    if (loc.kind == Location::OnEdge && t_.con[loc.edge] != kFree) continue;
    t_.cavity(q, loc, cavityTris_, cavityBoundary_);
    if (mesh_.tooCloseToCavity(q, cavityBoundary_) || !mesh_.representable(q)) continue;
    // The centroid, the last resort, may encroach a forbidden subsegment: a triangle over its area
    // bound always holds it, so the bound is met in the end (its distance to the triangle's
    // corners, at least 2/3 of its smallest altitude, 4 A / (3 longest edge), keeps the splits finite).
    if (collectEncroached(q, lambda == 0)) {
      if (lambda > 0) {
        rejectPairs_.clear();
        continue;
      }
      if (splitRejected(bt, q)) return true;
    }
    insertSteiner(bt, q, loc, VertexKind::Interior, {&cavityTris_, &cavityBoundary_});
    return true;
  }
  return false;
}

void Refiner::measureCorners() const {
  if (cornersMeasured_) return;
  corner_ = acuteCorners(m_, &inverseGaps_);
  cornersMeasured_ = true;
}

// Where along subsegment a-b of length len it is split, as a fraction from a (§6.2, §6.6).
double Refiner::splitFraction(std::uint32_t a, std::uint32_t b, double len) const {
  // Concentric shells: measured from an acute corner, the piece next to it gets a power-of-two
  // length in (len/3, 2len/3], so equal pieces on neighboring segments do not encroach each other.
  // Between two corners, one under kSeditiousAngle and sharper than the other, the shells are
  // measured from the sharper, at the power of two nearest half the length: every later split
  // near that corner then lies on one of its shells on both of its segments, where seditious
  // edges stop the refinement (§6.6); a midpoint there starts the two sides off different shells
  // and a cascade of splits towards the corner (the spikes of stars: 15% fewer triangles, 0.86x;
  // shape families 0.99x, corpus triangles 0.99x in sum).
  double f = 0.5;
  const std::uint8_t corA = cornerOf(a), corB = cornerOf(b);
  const bool ca = corA != 0, cb = corB != 0;
  if (ca && cb && corA != corB && std::max(corA, corB) >= kSeditiousCorner) {
    const double d = std::exp2(std::round(std::log2(len / 2)));
    f = corA > corB ? d / len : 1.0 - d / len;
  } else if (ca != cb) {
    const double d = std::exp2(std::floor(std::log2(2.0 * len / 3.0)));
    f = ca ? d / len : 1.0 - d / len;
  }
  return f;
}

// Where subsegment h from pa to pb is split (§6.2, §6.6), into xy; false if no point can be kept.
bool Refiner::subsegmentSplitPoint(std::uint32_t h, const double* pa, const double* pb, std::uint32_t a, std::uint32_t b, double xy[2]) const {
  const double len = dist(pa, pb), f = splitFraction(a, b, len);
  double x = pa[0] + f * (pb[0] - pa[0]), y = pa[1] + f * (pb[1] - pa[1]);
  // On a subsegment with no triangle beyond it, a split point rounded to the outside can land in
  // another part of the domain across an exterior sliver thinner than the rounding (found by
  // fuzzing, tests/hostile/boundary-split-rounded-across-an-exterior-sliver.poly: two segments
  // 1e-7 rad apart bounding a hole). Move it onto the domain's side, the left of a -> b, along the
  // normal by 2^-53 to 2^-48 of the segment's length or its endpoints' magnitude, whichever is
  // larger (that magnitude bounds the rounding), doubling per try. Never by an ulp of the point's
  // own coordinates: a midpoint of (c, y1)-(-c, y2) has x = 0, whose ulp is a subnormal that no
  // output can hold, and the split would be refused.
  if (t_.twin[h] == kNone) {
    const double nx = pa[1] - pb[1], ny = pb[0] - pa[0];  // length len, pointing left
    const double reach = std::max({std::fabs(pa[0]), std::fabs(pa[1]), std::fabs(pb[0]), std::fabs(pb[1])});
    const double x0 = x, y0 = y;
    double t = 0x1p-53 * std::max(1.0, reach / len);
    for (int step = 0;; ++step, t *= 2) {
      const double p[2] = {x, y};
      if (orient2d(pa, pb, p) >= 0) break;
      if (step == 6) return false;
      x = x0 + t * nx, y = y0 + t * ny;
    }
  }
  xy[0] = x, xy[1] = y;
  return mesh_.representable(xy);
}

// The onSegment code of a split of subsegment a-b of a hull edge: its ends' code where one is a
// split already, else a new hull edge with a and b as its ends.
std::int32_t Refiner::hullEdgeOf(std::uint32_t a, std::uint32_t b) {
  if (m_.onSegment[a] <= -2) return m_.onSegment[a];
  if (m_.onSegment[b] <= -2) return m_.onSegment[b];
  m_.hullEdgeEnds.push_back({a, b});
  return -1 - static_cast<std::int32_t>(m_.hullEdgeEnds.size());
}

// Split subsegment h (§6.2, §6.6). `bt` and `rejected`: the triangle whose point was rejected
// and that point, if that is why, for the trace. False if it cannot be split (precision floor).
bool Refiner::splitSubsegment(std::uint32_t h, const BadTriangle* bt, const double* rejected) {
  if (splitForbidden(h)) {
    ++forbiddenHits_;
    refusedSplit_ = true;
    return false;
  }
  if (t_.con[h] >= mesh_.curveFirst) return splitCurvePiece(h, bt, rejected);
  const std::uint32_t a = t_.origin(h), b = t_.dest(h);
  // Copies: adding a vertex below may reallocate the coordinate array.
  const double pa[2] = {t_.xy[2 * a], t_.xy[2 * a + 1]};
  const double pb[2] = {t_.xy[2 * b], t_.xy[2 * b + 1]};
  double split[2];
  if (dist(pa, pb) < 3 * kLengthFloor || !subsegmentSplitPoint(h, pa, pb, a, b, split)) {
    ++floorHits_;
    return false;
  }
  const std::int32_t segment = t_.con[h] >= 0 ? t_.con[h] : t_.con[h] == kHullEdge ? hullEdgeOf(a, b) : -1;
  return insertOnSubsegment(h, split, segment, bt, rejected) != kNone;
}

// Insert a vertex at `split`, on subsegment h or within rounding of it, with onSegment code
// `segment`; the trace as splitSubsegment's. Its id, or kNone if it cannot be placed.
std::uint32_t Refiner::insertOnSubsegment(std::uint32_t h, const double* split, std::int32_t segment, const BadTriangle* bt,
                                          const double* rejected) {
  const std::uint32_t a = t_.origin(h), b = t_.dest(h);
  const double pa[2] = {t_.xy[2 * a], t_.xy[2 * a + 1]};
  const double pb[2] = {t_.xy[2 * b], t_.xy[2 * b + 1]};
  Location loc;
  loc.kind = Location::OnEdge;
  loc.tri = h / 3;
  loc.edge = h;
  // The new vertex's nearest neighbor is on its cavity's boundary: the vertices facing the
  // subsegment (an encroacher 1e-15 above the midpoint, say), or, when two segments meet at a tiny
  // angle, a shell split at the same distance from their common vertex on the other segment, closer
  // than doubles can keep apart (found by fuzzing, tests/hostile/shell-splits-closer-than-doubles-resolve.poly).
  // Refuse those, as the length floor does.
  t_.cavity(split, loc, splitTris_, splitBoundary_);
  if (mesh_.tooCloseToCavity(split, splitBoundary_)) {
    ++floorHits_;
    return kNone;
  }
  if (!mayInsert()) return kNone;
  const double x = split[0], y = split[1];
  const std::uint32_t v = m_.addVertex(x, y, VertexKind::SegmentSplit, segment);
  cornerForNewVertex();
  if ((x == pa[0] && y == pa[1]) || (x == pb[0] && y == pb[1]) || !insertAt(v, loc, {&splitTris_, &splitBoundary_})) {
    // Not placeable: the new vertex stays unused (kind Unused) so output stays consistent.
    m_.kind[v] = VertexKind::Unused;
    ++floorHits_;
    return kNone;
  }
  traceSplit(v, a, b, bt, rejected);
  return v;
}

void Refiner::traceSplit(std::uint32_t v, std::uint32_t a, std::uint32_t b, const BadTriangle* bt, const double* rejected) {
  if (!o_.trace) return;
  Event e;
  e.kind = rejected ? EventKind::Rejected : EventKind::SegmentSplit;
  e.vertex = v, e.x = t_.xy[2 * v], e.y = t_.xy[2 * v + 1], e.a = a, e.b = b;
  if (rejected && bt) e.t0 = bt->a, e.t1 = bt->b, e.t2 = bt->c, e.cx = rejected[0], e.cy = rejected[1];
  out_.events.push_back(e);
}

// The first choice of point for a bad triangle: its circumcenter, or (unless
// Placement::Circumcenter) for a skinny one the off-center when that is nearer, for one that only
// exceeds its area bound `overBound` (> 0) the size off-center when there is one. False: no point to
// trust.
bool Refiner::firstChoice(const double* const* p, const TriangleShape& sh, bool skinny, double overBound,
                          double target[2], VertexKind& kind) const {
  double cc[2];
  if (!circumcenter(p, cc)) return false;
  target[0] = cc[0], target[1] = cc[1];
  kind = VertexKind::Interior;
  if (o_.placement != Placement::Circumcenter) {
    const int e = sh.shortestEdge;
    const double* u = p[(e + 1) % 3];
    const double* w = p[(e + 2) % 3];
    double x[2];
    if (skinny ? offCenter(u, w, sh.shortest, cc, theta_, x)
               : overBound > 0 && isAcute(p) && sizeOffCenter(u, w, cc, overBound, theta_, x)) {
      // Out of range, a skinny triangle's off-center is refused below; a size off-center gives way
      // to the circumcenter.
      if (skinny || mesh_.representable(x)) target[0] = x[0], target[1] = x[1], kind = VertexKind::OffCenter;
    }
  }
  return mesh_.representable(target);
}

// A better point than the first choice from the configured placement, if it has one (placement.h).
bool Refiner::improvePlacement(const SkinnyTriangle& st, double target[2], Location& loc) {
  switch (o_.placement) {
    case Placement::Petal:
      // Only where no area bound applies: with one, the bound sets the size and the search buys
      // little (unit square, max area 1e-6: 794.6 k vertices with it, 794.7 k without, at 4x the time).
      return !(maxAreaAt(st.slot) > 0) && petal_.propose(mesh_, st, target, loc);
    default:
      return false;
  }
}

void Refiner::splitTriangle(const BadTriangle& bt) {
  const std::uint32_t s = bt.slot;
  const double* p[3] = {t_.pt(bt.a), t_.pt(bt.b), t_.pt(bt.c)};
  const TriangleShape sh = shapeOf(p[0], p[1], p[2]);
  const TriangleQuality q = qualityOf(p[0], p[1], p[2]);
  const bool skinny = isSkinny(q);
  // Over maxAngle only (a skinny triangle is fixed as skinny): its circumcenter, which lies beyond
  // its longest edge, at distance R from its corners and in the cavity of the triangle across that
  // edge. The fans it makes with the two shorter edges have apex angles twice the angles at the
  // longest edge's ends, under maxAngle when those are, and it is rejected for an encroached
  // subsegment (and a subsegment as longest edge) like a skinny triangle's (§6.2).
  const bool wide = !skinny && isWide(p[0], p[1], p[2]);
  // A moved vertex (relocate) leaves its old triangles' entries current (same vertices) though
  // their shape has changed: such a triangle may now meet the bounds.
  if (!relocations_.empty() && !skinny && !wide && !(maxAreaAt(s) > 0 && q.area > maxAreaAt(s))) return;
  if ((skinny || wide) && (nestledInInputAngle(s, sh) || seditious(s, sh))) {
    const double bound = maxAreaAt(s);
    if (!(bound > 0 && q.area > bound)) return;  // left alone on purpose; counted in finish()
  }
  double target[2];
  VertexKind kind;
  const double overBound = !skinny && !wide && maxAreaAt(s) > 0 && q.area > maxAreaAt(s) ? maxAreaAt(s) : 0;
  if (sh.shortest < 2 * kLengthFloor || !firstChoice(p, sh, skinny, overBound, target, kind)) {
    ++floorHits_;
    return;
  }
  if (wide) {
    // First a move of a free corner (no new triangle), the wide one first; else a better point.
    const int k = wideCorner(p);
    const std::uint32_t corners[3] = {bt.a, bt.b, bt.c};
    if (relocate(corners[k], bt) || pushWideCorner(bt, p, k) || slideWideCorner(corners[k], bt)) return;
    for (int i = 1; i < 3; ++i)
      if (relocate(corners[(k + i) % 3], bt) || slideWideCorner(corners[(k + i) % 3], bt)) return;
    widePoint(bt, p, k, target);
  }
  Location loc;
  bool located = false;
  // Under an area bound too, skinny triangles over it included: with max area = bounding box / 3000
  // the 300 generated PLCs made 1.006x Triangle's triangles at 30 degrees and 1.071x at 33 with
  // off-centers there, 0.951x and 0.897x this way (with the size classes of bad_triangle_queue.h).
  if (skinny && o_.placement == Placement::Optimal) {
    if (optimalOrRelocate(bt, p, sh, target)) return;
    // Nothing changed since the placement looked at the first choice: its cavity is known.
    located = optimal_.takeFirst(loc, cavityTris_, cavityBoundary_);
  }
  refusedSplit_ = false;
  const std::uint64_t before = inserted_;
  if (!located && !locateOrReject(bt, target, loc)) {
    // (Only when nothing was inserted meanwhile: p points into the coordinates, which may move.)
    // Only for triangles over their area bound: for skinny ones, centroids cascade into ever
    // smaller skinny triangles along the forbidden subsegment (measured: A.poly at 30 degrees ran
    // to the Steiner budget, 15 829 vertices, where it needs 78 without the option).
    if (refusedSplit_ && inserted_ == before && isCurrent(t_, bt) && maxAreaAt(s) > 0 && q.area > maxAreaAt(s))
      placeAwayFromForbidden(bt, p, target);
    return;
  }
  CavityRef known{&cavityTris_, &cavityBoundary_};
  const SkinnyTriangle st{s, p, sh, target, &cavityBoundary_};
  double better[2];
  Location betterLoc;
  if (skinny && improvePlacement(st, better, betterLoc)) {
    // A proposed point has a cavity of its own: insertAt computes it.
    target[0] = better[0], target[1] = better[1], loc = betterLoc;
    kind = VertexKind::OffCenter, known = {};
    insertSteiner(bt, target, loc, kind, known, EventKind::PetalPoint);
    return;
  }
  insertSteiner(bt, target, loc, kind, known);
}

// Placement::Optimal (optimal_placement.h): slide an endpoint of the shortest edge that lies on a
// segment along it (first with plan_.slideFirst, else after the search), insert the locally optimal
// point if one meets the bound, else move a free endpoint of the shortest edge. With
// plan_.bestBelowBound, any free corner may move, and before the search; where nothing meets the
// bound, the best point below it goes in if one qualifies. False: none of these; the first choice
// goes ahead.
bool Refiner::optimalOrRelocate(const BadTriangle& bt, const double* const* p, const TriangleShape& sh, const double* first) {
  double cc[2], x[2];
  optimal_.forget();
  if (!circumcenter(p, cc)) return false;
  const SkinnyTriangle st{bt.slot, p, sh, first, nullptr};
  const std::uint32_t corners[3] = {bt.a, bt.b, bt.c};
  if (plan_.bestBelowBound)
    for (std::uint32_t v : corners)
      if (relocate(v, bt)) return true;
  const std::uint32_t ends[2] = {t_.tv[3 * bt.slot + (sh.shortestEdge + 1) % 3], t_.tv[3 * bt.slot + (sh.shortestEdge + 2) % 3]};
  auto slideAnEnd = [&] { return slideOnSegment(ends[0], bt) || slideOnSegment(ends[1], bt); };
  if (plan_.slideFirst && slideAnEnd()) return true;
  Location loc;
  switch (optimal_.propose(mesh_, st, cc, x, loc)) {
    case OptimalPlacement::Result::Found:
      insertChosenPoint(bt, x, loc);
      return true;
    case OptimalPlacement::Result::UseFirst:
      return false;
    case OptimalPlacement::Result::None:
      break;
  }
  if (!plan_.slideFirst && slideAnEnd()) return true;
  if (!plan_.bestBelowBound) {
    for (std::uint32_t v : ends)
      if (relocate(v, bt)) return true;
    return false;
  }
  if (!optimal_.bestBelowBound(mesh_, st, x, loc)) return false;
  insertChosenPoint(bt, x, loc);
  return true;
}

void Refiner::insertChosenPoint(const BadTriangle& bt, const double* x, const Location& loc) {
  optimal_.takeCandidate(cavityTris_, cavityBoundary_);
  insertSteiner(bt, x, loc, VertexKind::OffCenter, {&cavityTris_, &cavityBoundary_}, EventKind::OptimalPoint);
}

bool Refiner::relocate(std::uint32_t v, const BadTriangle& bt) {
  if (v < m_.inputCount || (m_.kind[v] != VertexKind::Interior && m_.kind[v] != VertexKind::OffCenter)) return false;
  double x[2];
  if (!mayMove(v) || !optimal_.relocation(mesh_, v, x)) return false;
  // Under maxAngle, a move that would make a wide triangle is refused.
  if (cosMaxAngle_ > -1)
    for (std::uint32_t h : optimal_.star())
      if (largestAngleCos(t_.pt(t_.origin(h)), t_.pt(t_.dest(h)), x) < cosMaxAngle_ ||
          qualityOf(t_.pt(t_.origin(h)), t_.pt(t_.dest(h)), x).sin2MinAngle < sin2WideFloor())
        return false;
  if (m_.attributeCount) reinterpolateMoved(v, x);
  const double from[2] = {t_.xy[2 * v], t_.xy[2 * v + 1]};
  t_.xy[2 * v] = x[0], t_.xy[2 * v + 1] = x[1];
  afterMove(v, from, bt, optimal_.star());
  return true;
}

bool Refiner::mayMove(std::uint32_t v) {
  if (relocations_.size() <= v) relocations_.resize(t_.vertexCount(), 0);
  return relocations_[v] < kMaxRelocations && mayInsert();
}

bool Refiner::slideOnSegment(std::uint32_t v, const BadTriangle& bt) {
  // A vertex on a curve stays where it is: sliding moves along a chord, off the curve.
  if (!plan_.slide || v < m_.inputCount || m_.kind[v] != VertexKind::SegmentSplit || m_.onSegment[v] >= mesh_.curveFirst)
    return false;
  std::uint32_t ends[2];
  double x[2];
  if (!mayMove(v) || !segmentVertexFan(t_, v, slideStar_, ends) ||
      !bestSlide(t_, slideStar_, t_.pt(ends[0]), t_.pt(ends[1]), bt.slot, sin2Theta_, mesh_.lensCos2, x) || !mesh_.representable(x))
    return false;
  const double from[2] = {t_.xy[2 * v], t_.xy[2 * v + 1]};
  t_.xy[2 * v] = x[0], t_.xy[2 * v + 1] = x[1];
  interpolateOnSegment(m_, v, ends[0], ends[1]);
  afterMove(v, from, bt, slideStar_);
  return true;
}

void Refiner::afterMove(std::uint32_t v, const double* from, const BadTriangle& bt, const std::vector<std::uint32_t>& star) {
  if (o_.trace) {
    Event e;
    e.kind = EventKind::Relocated;
    e.vertex = v, e.x = t_.xy[2 * v], e.y = t_.xy[2 * v + 1], e.cx = from[0], e.cy = from[1];
    e.t0 = bt.a, e.t1 = bt.b, e.t2 = bt.c;
    out_.events.push_back(e);
  }
  ++relocations_[v], ++inserted_;
  // The star's edges, and those of the triangles beyond it, may no longer be locally Delaunay.
  mendStack_.clear();
  flipped_.clear();
  for (std::uint32_t h : star)
    for (std::uint32_t k = 0; k < 3; ++k) mendStack_.push_back(3 * (h / 3) + k);
  t_.legalize(mendStack_, &flipped_);
  for (std::uint32_t h : star) flipped_.push_back(h / 3);
  std::sort(flipped_.begin(), flipped_.end());
  flipped_.erase(std::unique(flipped_.begin(), flipped_.end()), flipped_.end());
  recheckFlipped();
}

// Locate target for bad triangle bt. Where it lies beyond or on a subsegment, or encroaches one on
// its cavity's boundary (§6.2, §6.3), it is rejected and those subsegments are split instead;
// false then, and false at the precision limit. True: loc and cavityTris_ / cavityBoundary_ hold
// its location and cavity.
bool Refiner::locateOrReject(const BadTriangle& bt, const double* target, Location& loc) {
  std::uint32_t blocked;
  loc = mesh_.walk(bt.slot, target, blocked);
  if (blocked != kNone) {
    // The new vertex would lie beyond a subsegment: that subsegment is encroached (Prop. 6.2).
    reject(bt, blocked, target);
    return false;
  }
  if (loc.kind == Location::Lost || loc.kind == Location::OnVertex) {
    ++floorHits_;
    return false;
  }
  if (loc.kind == Location::OnEdge && t_.con[loc.edge] != kFree) {
    reject(bt, loc.edge, target);
    return false;
  }
  t_.cavity(target, loc, cavityTris_, cavityBoundary_);
  const CavityVerdict verdict = mesh_.judgeCavity(target, cavityBoundary_, false);
  if (verdict.tooClose) {
    ++floorHits_;
    return false;
  }
  if (!verdict.encroaches) return true;
  collectEncroached(target, false);
  splitRejected(bt, target);
  return false;
}

// The subsegments on the cavity's boundary (cavityBoundary_) that `target` encroaches, into
// rejectPairs_ (those whose split is forbidden left out if `splittableOnly`); true if any.
bool Refiner::collectEncroached(const double* target, bool splittableOnly) {
  for (std::uint32_t h : cavityBoundary_)
    if (t_.con[h] != kFree && !(splittableOnly && splitForbidden(h)) && mesh_.encroachesEdge(target, h))
      rejectPairs_.push_back({t_.origin(h), t_.dest(h), h});
  return !rejectPairs_.empty();
}

// The point `target` of bt is rejected: split the subsegments in rejectPairs_ (§6.3) and keep bt
// queued if any was split; true if any was.
bool Refiner::splitRejected(const BadTriangle& bt, const double* target) {
  ++out_.rejected;
  bool splitSome = false;
  for (const EdgeRef& e : rejectPairs_) {
    const std::uint32_t h = edgeOf(e);
    if (h != kNone && t_.con[h] != kFree) splitSome = splitSubsegment(h, &bt, target) || splitSome;
  }
  rejectPairs_.clear();
  if (splitSome) requeue(bt);
  return splitSome;
}

void Refiner::reject(const BadTriangle& bt, std::uint32_t h, const double* target) {
  ++out_.rejected;
  if (splitSubsegment(h, &bt, target)) requeue(bt);
}

}  // namespace ruppert::detail
