// Refiner (refiner.h): splitting curve pieces on their curves (cdt/curves.h). A piece a-b is split
// at the curve's point p of the parameter the segment rule gives (the midpoint, or a concentric
// shell measured in the parameter), so that every vertex on a curve lies on it. p lies a sagitta off
// the chord: where the chord is the domain's edge on p's side (the domain bulges, as a quarter disk's
// arc does), there is no triangle there, and the triangle (a, p, b) is added beyond the chord; where
// p's side has a triangle, p lies in it (below), and inserting p there makes the triangle (a, b, p).
// Either way that triangle then joins the chord's other side (or goes, where the other side is
// outside), a-p and p-b become the piece's subsegments, and flips restore the Delaunay property.
//
// Why p lies in the triangle on its side: the piece lies in its chord's closed diametral disk
// (curves.h), so the sliver between chord and curve does too, and a vertex there would encroach the
// piece, which is split (encroached subsegments come first) before any triangle's point goes in.
// Where that fails all the same (a vertex placed there by a move, at the precision limit), the split
// is refused like one below the length floor.
#include <cmath>

#include "mesh/predicates.h"
#include "point_attributes.h"
#include "refine/refiner.h"
#include "cold_code.h"

// Only inputs with curves come here: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

namespace ruppert::detail {

double Refiner::curveParam(std::uint32_t v, std::int32_t segment) const {
  const std::size_t piece = std::size_t(segment - m_.curves->first);
  if (v == m_.segmentEnd(std::size_t(segment), 0)) return m_.curves->t0[piece];
  if (v == m_.segmentEnd(std::size_t(segment), 1)) return m_.curves->t1[piece];
  return v < m_.curveT.size() ? m_.curveT[v] : NAN;
}

bool Refiner::curvePieceTooCoarse(std::uint32_t h) const {
  const std::int32_t k = t_.con[h];
  const double ta = curveParam(t_.origin(h), k), tb = curveParam(t_.dest(h), k);
  if (!(std::isfinite(ta) && std::isfinite(tb)) || dist(t_.pt(t_.origin(h)), t_.pt(t_.dest(h))) < 3 * kLengthFloor) return false;
  const CurveShape& s = m_.curves->shapeOf(k);
  const double lo = std::fmin(ta, tb), hi = std::fmax(ta, tb);
  return s.chordError(lo, hi) > m_.curves->tolerance || !s.withinDisk(lo, hi);
}

bool Refiner::splitCurvePiece(std::uint32_t h, const BadTriangle* bt, const double* rejected) {
  const std::int32_t k = t_.con[h];
  const std::uint32_t a = t_.origin(h), b = t_.dest(h);
  const double pa[2] = {t_.xy[2 * a], t_.xy[2 * a + 1]};
  const double pb[2] = {t_.xy[2 * b], t_.xy[2 * b + 1]};
  const double ta = curveParam(a, k), tb = curveParam(b, k), len = dist(pa, pb);
  const double t = ta + splitFraction(a, b, len) * (tb - ta);
  double p[2] = {NAN, NAN};
  if (len >= 3 * kLengthFloor) m_.curves->shapeOf(k).point(t, p);
  if (!mesh_.representable(p) || (p[0] == pa[0] && p[1] == pa[1]) || (p[0] == pb[0] && p[1] == pb[1])) {
    ++floorHits_;
    return false;
  }
  const double side = orient2d(pa, pb, p);
  std::uint32_t v;
  if (side == 0) {  // on the chord: an ordinary split
    v = insertOnSubsegment(h, p, k, bt, rejected);
    if (v == kNone) return false;
  } else {
    if (!mayInsert()) return false;
    // p left of a-b lies on h's triangle's side, right of it on its twin's (if any).
    const std::uint32_t u = side > 0 ? a : b, w = side > 0 ? b : a;
    const std::uint32_t hs = side > 0 ? h : t_.twin[h], ho = side > 0 ? t_.twin[h] : h;
    v = m_.addVertex(p[0], p[1], VertexKind::SegmentSplit, k);
    cornerForNewVertex();
    if (!insertBesideChord(v, u, w, hs, ho)) {
      m_.kind[v] = VertexKind::Unused;
      ++floorHits_;
      return false;
    }
    traceSplit(v, a, b, bt, rejected);
  }
  if (m_.curveT.size() <= v) m_.curveT.resize(std::size_t(v) + 1, NAN);
  m_.curveT[v] = t;
  return true;
}

bool Refiner::insertBesideChord(std::uint32_t v, std::uint32_t u, std::uint32_t w, std::uint32_t hs, std::uint32_t ho) {
  const std::int32_t k = t_.con[hs != kNone ? hs : ho];
  const double p[2] = {t_.xy[2 * v], t_.xy[2 * v + 1]};
  std::uint32_t x;  // the half-edge u -> w of the triangle (u, w, p)
  if (hs != kNone) {
    const double* c = t_.pt(t_.apex(hs));
    if (!(orient2d(t_.pt(w), c, p) > 0 && orient2d(c, t_.pt(u), p) > 0)) return false;
    Location loc;
    loc.kind = Location::InTriangle, loc.tri = hs / 3;
    t_.cavity(p, loc, splitTris_, splitBoundary_);
    if (mesh_.tooCloseToCavity(p, splitBoundary_) || !insertAt(v, loc, {&splitTris_, &splitBoundary_})) return false;
    // u-w is a constraint, so it bounds the cavity, and the fan over it is (u, w, p): a new triangle.
    x = kNone;
    for (std::uint32_t s : newTris_)
      for (std::uint32_t h = 3 * s; h < 3 * s + 3; ++h)
        if (t_.origin(h) == u && t_.dest(h) == w) x = h;
    if (x == kNone || t_.apex(x) != v) throw Error(ErrorCode::Internal, "a curve split lost its chord");
  } else {
    const std::uint32_t s = t_.newTriangle(u, w, v);
    x = 3 * s + 2;
    t_.link(x, ho);
    ++inserted_;
  }
  if (m_.attributeCount) interpolateOnSegment(m_, v, u, w);
  moveBoundaryToCurve(x, k, ho);
  return true;
}

void Refiner::moveBoundaryToCurve(std::uint32_t x, std::int32_t segment, std::uint32_t ho) {
  const std::uint32_t s = x / 3, wp = next3(x), pu = prev3(x);
  flipped_.clear();
  if (ho != kNone) {
    // Between chord and curve: the other side's region from now on; the chord becomes free.
    copyRegionData(ho / 3, s);
    t_.con[x] = t_.con[ho] = kFree;
    for (std::uint32_t e : {wp, pu}) {
      t_.con[e] = segment;
      if (t_.twin[e] != kNone) t_.con[t_.twin[e]] = segment;
    }
    mendStack_.assign(1, x);
    t_.legalize(mendStack_, &flipped_);
    flipped_.push_back(s), flipped_.push_back(ho / 3);
  } else {
    // Beyond the curve: outside the domain. The fan's triangles across u-p and p-w hold the boundary.
    const std::uint32_t gwp = t_.twin[wp], gpu = t_.twin[pu];
    const std::uint32_t u = t_.origin(x), w = t_.dest(x), v = t_.apex(x);
    for (std::uint32_t g : {gwp, gpu}) t_.con[g] = segment, t_.twin[g] = kNone, flipped_.push_back(g / 3);
    t_.killTriangle(s);
    t_.vtri[u] = gpu / 3, t_.vtri[v] = gpu / 3, t_.vtri[w] = gwp / 3;
  }
  recheckFlipped();
}

void Refiner::copyRegionData(std::uint32_t from, std::uint32_t to) {
  if (!regionDataCoversSlots()) return;
  m_.attribute[to] = m_.attribute[from], m_.maxArea[to] = m_.maxArea[from];
  if (!m_.inDomain.empty()) m_.inDomain[to] = m_.inDomain[from];
}

}  // namespace ruppert::detail

RUPPERT_COLD_END
