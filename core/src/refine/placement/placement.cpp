#include "refine/placement/placement.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "mesh/predicates.h"

namespace ruppert::detail {

namespace {
constexpr double kPetalReach = 4;  // see PetalPlacement::mayHelp
}  // namespace

namespace {
// Whether the line through o and p separates u from w (or passes through one of them).
bool separates(const double* o, const double* p, const double* u, const double* w) {
  const double su = orient2d(o, p, u), sw = orient2d(o, p, w);
  return (su >= 0 && sw <= 0) || (su <= 0 && sw >= 0);
}
}  // namespace

// The triangle entered through one of its edges already has p strictly beyond that edge's far side
// (orient2d's sign is exact and changes with the edge's direction), so that edge is not tested again.
// Of the other edges, p lies right of one or two; only with two does the straight line from the
// centroid decide which one the walk leaves by (the first whose ends it separates, else the first).
Location MeshAccess::walk(std::uint32_t s, const double* p, std::uint32_t& blocked) const {
  blocked = kNone;
  const TriangleSlot& first = tri.slot(s);
  const double* q0 = tri.pt(first.tv[0]);
  const double* q1 = tri.pt(first.tv[1]);
  const double* q2 = tri.pt(first.tv[2]);
  const double o[2] = {(q0[0] + q1[0] + q2[0]) / 3, (q0[1] + q1[1] + q2[1]) / 3};
  std::uint32_t t = s, entry = 3;
  for (std::uint32_t step = 0; step < 100000; ++step) {
    const TriangleSlot& r = tri.slot(t);
    const double* c[3] = {tri.pt(r.tv[0]), tri.pt(r.tv[1]), tri.pt(r.tv[2])};
    double ori[3];
    std::uint32_t negative[3], negatives = 0;
    for (std::uint32_t i = 0; i < 3; ++i) {
      ori[i] = i == entry ? 1 : orient2d(c[i == 2 ? 0 : i + 1], c[i == 0 ? 2 : i - 1], p);
      if (ori[i] < 0) negative[negatives++] = i;
    }
    if (negatives == 0) return tri.locationInside(t, ori);
    std::uint32_t exit = negative[0];
    if (negatives == 2 && !separates(o, p, c[exit == 2 ? 0 : exit + 1], c[exit == 0 ? 2 : exit - 1])) {
      const std::uint32_t other = negative[1];
      if (separates(o, p, c[other == 2 ? 0 : other + 1], c[other == 0 ? 2 : other - 1])) exit = other;
    }
    if (r.con[exit] != kFree || r.twin[exit] == kNone) {
      blocked = 3 * t + exit;
      return Location{};
    }
    const std::uint32_t g = r.twin[exit];
    t = g / 3, entry = g - 3 * t;
  }
  return Location{};
}

// A coordinate can fall below the exact predicates' range without any input doing so (found by
// fuzzing, tests/hostile/hull-splits-below-the-predicates-range.poly): splits of a hull edge from
// (0, 0) to (1.5, 3e-39) have y coordinates under 2^-128. And on inputs near the subnormal range,
// the output's user units cannot hold a new vertex's coordinates (found by fuzzing again,
// tests/hostile/steiner-vertices-rounded-to-subnormal-user-units.poly: with coordinates near
// 1e-312 the mesh returned had clockwise triangles though the internal one was valid). Such a vertex is refused like one under the length floor.
bool MeshAccess::representable(const double* p) const {
  for (int k = 0; k < 2; ++k)
    if (!isSafeCoordinate(p[k]) || (p[k] != 0 && !(std::fabs(input.toUser(p[k])) >= DBL_MIN))) return false;
  return true;
}

bool MeshAccess::tooCloseToCavity(const double* x, const std::vector<std::uint32_t>& boundary) const {
  for (std::uint32_t h : boundary)
    if (sq(x, tri.pt(tri.origin(h))) < kLengthFloor * kLengthFloor) return true;
  return false;
}

double MeshAccess::newMinSin2(const double* x, const std::vector<std::uint32_t>& boundary) const {
  double worst = 1;
  for (std::uint32_t h : boundary)
    worst = std::min(worst, qualityOf(tri.pt(tri.origin(h)), tri.pt(tri.dest(h)), x).sin2MinAngle);
  return worst;
}

// Each boundary edge's record is read once for its ends and its constraint.
CavityVerdict MeshAccess::judgeCavity(const double* x, const std::vector<std::uint32_t>& boundary, bool quality) const {
  CavityVerdict v;
  for (std::uint32_t h : boundary) {
    const std::uint32_t t = h / 3, i = h - 3 * t;
    const TriangleSlot& r = tri.slot(t);
    const double* a = tri.pt(r.tv[i == 2 ? 0 : i + 1]);
    const double* b = tri.pt(r.tv[i == 0 ? 2 : i - 1]);
    if (sq(x, a) < kLengthFloor * kLengthFloor) v.tooClose = true;
    const std::int32_t c = r.con[i];
    if (c != kFree && encroaches(x, a, b, c >= curveFirst ? 0 : lensCos2)) v.encroaches = true;
    if (quality) v.minSin2 = std::min(v.minSin2, qualityOf(a, b, x).sin2MinAngle);
  }
  return v;
}

// The petal of edge uw: points x with angle uxw >= theta and both base angles >= theta. Candidates
// lie on the arcs where angle uxw = alpha for alpha = theta .. theta + 0.3 rad: on such an arc, at
// central angle phi from its top, the base angles are (pi - alpha - phi) / 2 and
// (pi - alpha + phi) / 2, so |phi| <= pi - alpha - 2 theta keeps both >= theta.
PetalPlacement::PetalPlacement(double theta) {
  if (!(theta > 0)) return;
  static constexpr double kFractions[] = {0, 0.125, -0.125, 0.25, -0.25, 0.375, -0.375, 0.5, -0.5, 0.75, -0.75, 1, -1};
  for (double extra = 0; extra < 0.35; extra += 0.1) {
    const double alpha = theta + extra;
    const double phiMax = kPi - alpha - 2 * theta;
    if (phiMax < 0) break;
    const double radius = 1 / (2 * std::sin(alpha)), center = 0.5 / std::tan(alpha);
    for (double f : kFractions) {
      const double along = radius * std::sin(f * phiMax), across = center + radius * std::cos(f * phiMax);
      petal_.push_back({along, across, std::hypot(std::fabs(along) - 0.5, across)});
    }
  }
  // At most 52 points, once per bound: an insertion sort (stable: a point and its mirror image, whose
  // bounds tie, keep their order) rather than a std::sort instantiation of its own, which would add
  // several KB to the wasm module.
  for (std::size_t i = 1; i < petal_.size(); ++i)
    for (std::size_t j = i; j > 0 && petal_[j].bound > petal_[j - 1].bound; --j) std::swap(petal_[j], petal_[j - 1]);
}

// Whether searching the petal can pay: the first choice makes a skinny triangle, and every such
// triangle stands on a cavity edge less than kPetalReach times the shortest edge. A longer edge
// makes a flat triangle with the first choice; the petal's points all lie within about one shortest
// edge of it, so they make the same flat triangle: searches past such an edge almost never find a
// point, and skipping them is most of petal's time (docs/measurements.md, "petal reach").
bool PetalPlacement::mayHelp(const MeshAccess& mesh, const SkinnyTriangle& st) const {
  const Triangulation& t = mesh.tri;
  bool skinny = false;
  for (std::uint32_t h : *st.firstCavity) {
    const double* a = t.pt(t.origin(h));
    const double* b = t.pt(t.dest(h));
    if (qualityOf(a, b, st.first).sin2MinAngle >= mesh.sin2Theta) continue;
    if (dist(a, b) > kPetalReach * st.shape.shortest) return false;
    skinny = true;
  }
  return skinny;
}

// Fewer triangles than off-centers at about twice the refinement time without an area bound: most
// searches that mayHelp lets through still find no such point (docs/measurements.md, "petal reach").
bool PetalPlacement::propose(const MeshAccess& mesh, const SkinnyTriangle& st, double target[2], Location& loc) {
  if (!mayHelp(mesh, st)) return false;
  const Triangulation& t = mesh.tri;
  const int e = st.shape.shortestEdge;
  const double* u = st.p[(e + 1) % 3];
  const double* w = st.p[(e + 2) % 3];
  const double len = st.shape.shortest;
  const double dx = (w[0] - u[0]) / len, dy = (w[1] - u[1]) / len;
  const double nx = -dy, ny = dx;  // towards the triangle's side of u->w (counter-clockwise)
  const double mx = (u[0] + w[0]) / 2, my = (u[1] + w[1]) / 2;
  double bestRadius = 0, best[2] = {0, 0};
  Location bestLoc;
  for (const PetalPoint& c : petal_) {
    if (c.bound * len <= bestRadius) break;
    const double x[2] = {mx + len * (c.along * dx + c.across * nx), my + len * (c.along * dy + c.across * ny)};
    if (!mesh.representable(x)) continue;
    std::uint32_t blocked;
    const Location l = mesh.walk(st.slot, x, blocked);
    if (blocked != kNone || l.kind != Location::InTriangle) continue;
    t.cavity(x, l, candidateTris_, candidateBoundary_);
    // x must destroy the skinny triangle (lie in its circumcircle), and make nothing skinny.
    if (std::find(candidateTris_.begin(), candidateTris_.end(), st.slot) == candidateTris_.end() ||
        mesh.newMinSin2(x, candidateBoundary_) < mesh.sin2Theta)
      continue;
    bool encroaching = false;
    double nearest = HUGE_VAL;
    for (std::uint32_t h : candidateBoundary_) {
      nearest = std::min(nearest, dist(x, t.pt(t.origin(h))));
      if (t.con[h] != kFree && mesh.encroachesEdge(x, h)) encroaching = true;
    }
    if (encroaching || nearest <= bestRadius) continue;
    bestRadius = nearest, best[0] = x[0], best[1] = x[1], bestLoc = l;
  }
  if (bestRadius == 0) return false;
  target[0] = best[0], target[1] = best[1];
  loc = bestLoc;
  return true;
}

}  // namespace ruppert::detail
