// Refiner (refiner.h): the point for a wide triangle, one whose largest angle exceeds
// Options::maxAngle while its smallest meets minAngle.
//
// Its circumcenter O lies just beyond its longest edge AB, inside the triangle ABD across it, so
// inserting O replaces both: O sees the two shorter edges of ABC at twice the angles at A and B
// (under the bound), but the two edges of ABD at angles that add up to twice the wide angle C, so
// one of them is over the bound again and the fix cascades. A point nearer AB's midpoint, or
// across it towards D, splits the 360 degrees around it more evenly. The candidates below lie on
// AB's perpendicular bisector and between C and D; the one whose new triangles all meet both
// bounds, with the largest smallest angle, is taken; where none does, the circumcenter goes ahead
// (rejected for an encroached subsegment as usual, §6.2).
#include "refine/refiner.h"

#include <algorithm>
#include <cmath>

#include "cold_code.h"
#include "mesh/predicates.h"
#include "point_attributes.h"
#include "refine/placement/segment_slide.h"

// Once per wide triangle, not per insertion: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

namespace ruppert::detail {

// The smallest angle the fixes below accept for the triangles they make: minAngle, and at least
// 20 degrees, so that with minAngle 0 they do not trade a wide triangle for a needle (which is wide
// too, and whose fix makes more).
double Refiner::sin2WideFloor() const { return std::max(sin2Theta_, kSin2WideFloor); }

bool Refiner::wideCandidate(const BadTriangle& bt, const double* x, double& minSin2, double& maxCos) {
  if (!mesh_.representable(x)) return false;
  std::uint32_t blocked;
  const Location loc = mesh_.walk(bt.slot, x, blocked);
  if (blocked != kNone || loc.kind != Location::InTriangle) return false;
  t_.cavity(x, loc, cavityTris_, cavityBoundary_);
  if (std::find(cavityTris_.begin(), cavityTris_.end(), bt.slot) == cavityTris_.end()) return false;
  if (mesh_.tooCloseToCavity(x, cavityBoundary_)) return false;
  minSin2 = 1, maxCos = 1;
  for (std::uint32_t h : cavityBoundary_) {
    const double* a = t_.pt(t_.origin(h));
    const double* b = t_.pt(t_.dest(h));
    if (t_.con[h] != kFree && mesh_.encroachesEdge(x, h)) return false;
    minSin2 = std::min(minSin2, qualityOf(a, b, x).sin2MinAngle);
    maxCos = std::min(maxCos, largestAngleCos(a, b, x));
  }
  return true;
}

int Refiner::wideCorner(const double* const* p) {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (sq(p[(i + 1) % 3], p[(i + 2) % 3]) > sq(p[(k + 1) % 3], p[(k + 2) % 3])) k = i;
  return k;
}

bool Refiner::pushWideCorner(const BadTriangle& bt, const double* const* p, int k) {
  const std::uint32_t corners[3] = {bt.a, bt.b, bt.c};
  const std::uint32_t v = corners[k];
  if (v < m_.inputCount || (m_.kind[v] != VertexKind::Interior && m_.kind[v] != VertexKind::OffCenter)) return false;
  if (!optimal_.freeFan(t_, v)) return false;
  const std::vector<std::uint32_t>& star = optimal_.star();
  const double* a = p[(k + 1) % 3];
  const double* b = p[(k + 2) % 3];
  const double from[2] = {p[k][0], p[k][1]};
  const double out[2] = {from[0] - (a[0] + b[0]) / 2, from[1] - (a[1] + b[1]) / 2};
  for (double step : {0.15, 0.3, 0.5}) {
    const double x[2] = {from[0] + step * out[0], from[1] + step * out[1]};
    bool good = mesh_.representable(x) && !mesh_.tooCloseToCavity(x, star);
    for (std::size_t i = 0; good && i < star.size(); ++i) {
      const double* u = t_.pt(t_.origin(star[i]));
      const double* w = t_.pt(t_.dest(star[i]));
      good = orient2d(u, w, x) > 0 && qualityOf(u, w, x).sin2MinAngle >= sin2WideFloor() && largestAngleCos(u, w, x) >= cosMaxAngle_;
    }
    if (!good || !mayMove(v)) continue;
    if (m_.attributeCount) reinterpolateMoved(v, x);
    t_.xy[2 * v] = x[0], t_.xy[2 * v + 1] = x[1];
    afterMove(v, from, bt, star);
    return true;
  }
  return false;
}

bool Refiner::slideWideCorner(std::uint32_t v, const BadTriangle& bt) {
  if (v < m_.inputCount || m_.kind[v] != VertexKind::SegmentSplit || m_.onSegment[v] >= mesh_.curveFirst) return false;
  std::uint32_t ends[2];
  if (!segmentVertexFan(t_, v, slideStar_, ends)) return false;
  const double* u = t_.pt(ends[0]);
  const double* w = t_.pt(ends[1]);
  double best[2] = {0, 0}, bestSin2 = -1;
  for (double f = 0.15; f < 0.86; f += 0.05) {
    const double x[2] = {u[0] + f * (w[0] - u[0]), u[1] + f * (w[1] - u[1])};
    double worst = 1;
    for (std::size_t i = 0; worst >= sin2WideFloor() && i < slideStar_.size(); ++i) {
      const std::uint32_t o = t_.origin(slideStar_[i]), d = t_.dest(slideStar_[i]);
      const double* po = t_.pt(o);
      const double* pd = t_.pt(d);
      // A fan triangle on one of v's two subsegments: its apex must not encroach the piece.
      const bool onPiece = o == ends[0] || o == ends[1] || d == ends[0] || d == ends[1];
      const double* apex = o == ends[0] || o == ends[1] ? pd : po;
      const double* end = apex == pd ? po : pd;
      if (!(orient2d(po, pd, x) > 0) || largestAngleCos(po, pd, x) < cosMaxAngle_ ||
          (onPiece && encroaches(apex, x, end, mesh_.lensCos2)))
        worst = -1;
      else
        worst = std::min(worst, qualityOf(po, pd, x).sin2MinAngle);
    }
    if (worst >= sin2WideFloor() && worst > bestSin2 && mesh_.representable(x)) bestSin2 = worst, best[0] = x[0], best[1] = x[1];
  }
  if (bestSin2 < 0 || !mayMove(v)) return false;
  const double from[2] = {t_.xy[2 * v], t_.xy[2 * v + 1]};
  t_.xy[2 * v] = best[0], t_.xy[2 * v + 1] = best[1];
  interpolateOnSegment(m_, v, ends[0], ends[1]);
  afterMove(v, from, bt, slideStar_);
  return true;
}

bool Refiner::widePoint(const BadTriangle& bt, const double* const* p, int k, double target[2]) {
  // The wide corner k faces the longest edge a-b; c is that corner, d the apex across a-b (if any).
  const double* a = p[(k + 1) % 3];
  const double* b = p[(k + 2) % 3];
  const double* c = p[k];
  const std::uint32_t across = t_.twin[3 * bt.slot + static_cast<std::uint32_t>(k)];
  const double* d = across != kNone ? t_.pt(t_.apex(across)) : nullptr;
  const double mid[2] = {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2};
  // Away from c, half the edge long: c lies left of a -> b (counter-clockwise corners).
  const double away[2] = {(b[1] - a[1]) / 2, (a[0] - b[0]) / 2};
  double candidates[16][2];
  int count = 0;
  for (double u : {-0.2, 0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 1.3, 1.6})
    candidates[count][0] = mid[0] + u * away[0], candidates[count][1] = mid[1] + u * away[1], ++count;
  if (d != nullptr) {
    for (double f : {0.25, 0.5, 0.75})
      candidates[count][0] = c[0] + f * (d[0] - c[0]), candidates[count][1] = c[1] + f * (d[1] - c[1]), ++count;
    candidates[count][0] = (a[0] + b[0] + c[0] + d[0]) / 4, candidates[count][1] = (a[1] + b[1] + c[1] + d[1]) / 4, ++count;
  }
  // Best: every new triangle meets both bounds, the largest smallest angle; else (minAngle met)
  // the smallest largest angle, which leaves the least to fix next.
  double bestSin2 = -1, bestCos = -2;
  bool found = false;
  for (int i = 0; i < count; ++i) {
    double minSin2, maxCos;
    if (!wideCandidate(bt, candidates[i], minSin2, maxCos) || minSin2 < sin2WideFloor()) continue;
    const bool both = maxCos >= cosMaxAngle_;
    if (bestCos >= cosMaxAngle_ ? !(both && minSin2 > bestSin2) : !(both || maxCos > bestCos)) continue;
    bestSin2 = minSin2, bestCos = maxCos, found = true;
    target[0] = candidates[i][0], target[1] = candidates[i][1];
  }
  return found;
}

}  // namespace ruppert::detail

RUPPERT_COLD_END
