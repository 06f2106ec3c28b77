#include "refine/placement/optimal_placement.h"

#include <algorithm>
#include <cmath>

#include "refine/placement/feasible_region.h"
#include "mesh/predicates.h"

namespace ruppert::detail {

namespace {

double dist2(const double* a, const double* b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1];
  return dx * dx + dy * dy;
}

}  // namespace

void OptimalPlacement::reserveScratch() {
  for (auto* list : {&cavity_, &candidateTris_, &candidateBoundary_, &star_, &firstTris_, &firstBoundary_})
    list->reserve(kScratchReserve);
  edges_.reserve(kScratchReserve);
}

void OptimalPlacement::edgesOf(const Triangulation& t, const std::vector<std::uint32_t>& boundary) {
  edges_.resize(boundary.size());
  CavityEdge* e = edges_.data();
  for (std::uint32_t h : boundary) {
    const std::uint32_t s = h / 3, i = h - 3 * s;
    const TriangleSlot& r = t.slot(s);
    const double* a = t.pt(r.tv[i == 2 ? 0 : i + 1]);
    const double* b = t.pt(r.tv[i == 0 ? 2 : i - 1]);
    *e++ = {{a[0], a[1]}, {b[0], b[1]}, r.con[i] != kFree};
  }
}

// A point that meets the bound, if one is found: the screen's candidate when it does (two thirds of
// the time on a cloud of points at 30 degrees), else the search's first point past the bound.
// Maximising the smallest angle further made no fewer triangles and cost about a sixth of a mesh.
OptimalPoint OptimalPlacement::pointMeeting(OptimalPointQuery& query, const double* guess, const double* seeds,
                                            std::size_t seedCount) const {
  if (std::isfinite(guess[0])) {
    const OptimalPoint r = evaluateSteinerPoint(query, guess);
    if (!r.encroaches && r.minAngle > theta_) return r;
  }
  query.goodEnough = theta_;
  return optimalSteinerPoint(query, seeds, seedCount);
}

// Whether x can be inserted for skinny triangle s: in a triangle of the domain, destroying s (in
// its circumcircle, so in its cavity), not within the length floor of a vertex, encroaching no
// subsegment of its cavity. Its cavity is left in candidateTris_ / candidateBoundary_, and the
// smallest sin^2 angle of the triangles it would make in minSin2.
bool OptimalPlacement::fits(const MeshAccess& mesh, std::uint32_t s, const double* x, Location& loc, double& minSin2) {
  if (!mesh.representable(x)) return false;
  std::uint32_t blocked;
  loc = mesh.walk(s, x, blocked);
  if (blocked != kNone || loc.kind != Location::InTriangle) return false;
  mesh.tri.cavity(x, loc, candidateTris_, candidateBoundary_);
  if (std::find(candidateTris_.begin(), candidateTris_.end(), s) == candidateTris_.end()) return false;
  const CavityVerdict verdict = mesh.judgeCavity(x, candidateBoundary_, true);
  minSin2 = verdict.minSin2;
  return !verdict.tooClose && !verdict.encroaches;
}

// The prediction needs the new vertex's cavity, which depends on the point: it starts from the first
// choice's cavity (else, when that lies beyond a subsegment, the cavity of s's centroid), and each
// point found is checked against its own cavity; where that cavity makes a skinny triangle after
// all, the search runs again on it (three rounds at most).
OptimalPlacement::Result OptimalPlacement::propose(const MeshAccess& mesh, const SkinnyTriangle& st, const double* cc,
                                                   double target[2], Location& loc) {
  const Triangulation& t = mesh.tri;
  double sin2 = -1;
  firstFits_ = fits(mesh, st.slot, st.first, loc, sin2);
  firstSin2_ = -1;
  if (firstFits_) {
    // Kept for takeFirst by swapping; the boundary is copied only for a search.
    firstLoc_ = loc, firstSin2_ = sin2;
    firstTris_.swap(candidateTris_), firstBoundary_.swap(candidateBoundary_);
    if (firstSin2_ >= mesh.sin2Theta) return Result::UseFirst;
    candidateBoundary_ = firstBoundary_;
  } else if (theta_ < kSplitBeforeSearchBelowDegrees * kPi / 180) {
    return Result::UseFirst;
  } else {
    const double centroid[2] = {(st.p[0][0] + st.p[1][0] + st.p[2][0]) / 3, (st.p[0][1] + st.p[1][1] + st.p[2][1]) / 3};
    Location inside;
    inside.kind = Location::InTriangle, inside.tri = st.slot;
    t.cavity(centroid, inside, candidateTris_, candidateBoundary_);
  }
  cavity_.swap(candidateBoundary_);
  const int e = st.shape.shortestEdge;
  OptimalPointQuery query;
  query.p = st.p[(e + 1) % 3], query.q = st.p[(e + 2) % 3];
  query.maxApex = mesh.lensCos2 == 0 ? kPi / 2 : kPi - 2 * theta_;
  double seeds[6] = {st.first[0], st.first[1], cc[0], cc[1], 0, 0};
  std::size_t seedCount = 2;
  for (int round = 0; round < 3; ++round) {
    edgesOf(t, cavity_);
    query.edges = edges_.data(), query.edgeCount = edges_.size();
    // Most searches would end in a decline (star-1 at 30 degrees: 2,993 of 3,075), which the
    // screen foresees in 99% of cases at a small part of a search's cost.
    double guess[2];
    lastQuery_ = query, lastSeedCount_ = seedCount;
    std::copy(seeds, seeds + 6, lastSeeds_);
    if (!mayMeetBound(query, bound_, guess)) return Result::None;
    const OptimalPoint r = pointMeeting(query, guess, seeds, seedCount);
    Location l;
    if (r.encroaches || !(r.minAngle > theta_) || !fits(mesh, st.slot, r.x, l, sin2)) return Result::None;
    if (sin2 >= mesh.sin2Theta) {
      target[0] = r.x[0], target[1] = r.x[1], loc = l;
      return Result::Found;
    }
    seeds[4] = r.x[0], seeds[5] = r.x[1], seedCount = 3;
    cavity_.swap(candidateBoundary_);
  }
  return Result::None;
}

// Measured at 38 degrees over the 300 generated PLCs of 15 families, as the second attempt: 278
// complete; with the edge floor at 1.3 times the shortest edge, 253 (the gain: optimal_placement.h).
// Without a floor the best point shrinks edges as the off-center does (a scratch build inserting it
// unfloored made 5.5 times Triangle's triangles at 33 degrees). As the only attempt it completed 255,
// none of them cracks: along interior segments it cascades even so, hence the second attempt
// (refine/bound_search/bound_search.cpp).
bool OptimalPlacement::bestBelowBound(const MeshAccess& mesh, const SkinnyTriangle& st, double target[2], Location& loc) {
  edgesOf(mesh.tri, cavity_);
  OptimalPointQuery query = lastQuery_;
  query.edges = edges_.data(), query.edgeCount = edges_.size(), query.goodEnough = HUGE_VAL;
  const OptimalPoint r = optimalSteinerPoint(query, lastSeeds_, lastSeedCount_);
  if (r.encroaches || !(r.minAngle > 0)) return false;
  Location l;
  double sin2;
  if (!fits(mesh, st.slot, r.x, l, sin2) || !(sin2 > firstSin2_ * (1 + gain_))) return false;
  const double shortest2 = dist2(query.p, query.q);
  for (std::uint32_t h : candidateBoundary_)
    if (dist2(mesh.tri.pt(mesh.tri.origin(h)), r.x) < shortest2) return false;
  target[0] = r.x[0], target[1] = r.x[1], loc = l;
  return true;
}

bool OptimalPlacement::takeFirst(Location& loc, std::vector<std::uint32_t>& tris, std::vector<std::uint32_t>& boundary) {
  if (!firstFits_) return false;
  firstFits_ = false;
  loc = firstLoc_;
  tris.swap(firstTris_), boundary.swap(firstBoundary_);
  return true;
}

// The triangles around v, by their edges opposite v (into star_), all of whose edges are free;
// false where the fan is open (v on the mesh boundary) or longer than 64.
bool OptimalPlacement::closedFreeFan(const Triangulation& t, std::uint32_t v) {
  star_.clear();
  const std::uint32_t start = t.vtri[v];
  if (start == kNone || !t.alive(start)) return false;
  std::uint32_t s = start;
  do {
    const TriangleSlot& r = t.slot(s);
    const std::uint32_t i = r.tv[0] == v ? 0 : r.tv[1] == v ? 1 : r.tv[2] == v ? 2 : 3;
    if (i == 3 || star_.size() > 64) return false;
    if (r.con[0] != kFree || r.con[1] != kFree || r.con[2] != kFree) return false;
    star_.push_back(3 * s + i);
    // The edge before the star's half-edge runs from v to its origin; the triangle across it is the
    // next one around v.
    const std::uint32_t g = r.twin[i == 0 ? 2 : i - 1];
    if (g == kNone) return false;
    s = g / 3;
  } while (s != start);
  return true;
}

// Moving v within the kernel of its star (the points left of every outer edge) keeps every triangle
// counter-clockwise; the new position is checked exactly for that, and for the bound with the
// queue's own test. (optimal_point.h's search without the petal term: v has no shortest edge to
// stay near; the first outer edge only places the search's own seeds.)
bool OptimalPlacement::relocation(const MeshAccess& mesh, std::uint32_t v, double x[2]) {
  const Triangulation& t = mesh.tri;
  if (!closedFreeFan(t, v)) return false;
  edgesOf(t, star_);
  double seeds[4] = {t.pt(v)[0], t.pt(v)[1], 0, 0};
  for (const CavityEdge& c : edges_) seeds[2] += c.u[0] / edges_.size(), seeds[3] += c.u[1] / edges_.size();
  OptimalPointQuery query;
  query.p = edges_[0].u, query.q = edges_[0].v, query.petal = false;
  query.edges = edges_.data(), query.edgeCount = edges_.size(), query.maxApex = kPi;
  double guess[2];
  if (!mayMeetBound(query, bound_, guess)) return false;
  const OptimalPoint r = pointMeeting(query, guess, seeds, 2);
  if (!(r.minAngle > theta_) || !mesh.representable(r.x) || mesh.tooCloseToCavity(r.x, star_)) return false;
  for (const CavityEdge& c : edges_)
    if (!(orient2d(c.u, c.v, r.x) > 0) || qualityOf(c.u, c.v, r.x).sin2MinAngle < mesh.sin2Theta) return false;
  x[0] = r.x[0], x[1] = r.x[1];
  return true;
}

}  // namespace ruppert::detail
