// smoothMesh (smooth.h): ODT moves of free vertices, each checked after the flips it causes and
// undone exactly when it would break a bound.
#include "smooth/smooth.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "cdt/old_mesh.h"
#include "mesh/predicates.h"
#include "mesh/triangle_shape.h"
#include "point_attributes.h"
#include "refine/placement/refine_geometry.h"
#include "refine/placement/segment_slide.h"
#include "cold_code.h"

namespace ruppert::detail {

// Compiled for size (cold_code.h): an option, off by default, that should cost pages which never
// ask for it few bytes of the module; it runs a few passes once per call.
RUPPERT_COLD_BEGIN

namespace {

// Stars with more triangles are left alone: refinement makes few vertices of such degree, and a
// move's checks grow with it.
constexpr std::size_t kMaxStar = 24;
// Fractions of the step to the ODT point tried in turn: where the whole step fails a check, a
// shorter one often passes and still gains.
constexpr double kSteps[] = {1.0, 0.5, 0.25};
// The least gain in the star's mean smallest angle (radians) a move must bring: below it a move
// is noise, and the passes would trade rounding for flips.
constexpr double kMinGain = 1e-9;
// Compass-search rounds after the ODT step: each tries eight points around the best so far and
// halves its step when none gains.
constexpr int kSearchRounds = 12;
// A slide stays this share of the interval between its neighbors on the segment away from them.
constexpr double kSlideMargin = 0.1;
// The star's score per triangle (starQuality): its smallest angle, less kObtuseExcessWeight times
// how far its largest angle exceeds 90 degrees and kObtuseCost (radians) if it does at all. The
// flat cost is what turns slightly obtuse triangles acute; the weights trade that against the
// smallest angles (docs/measurements.md, "Smoothing", has the measured trade-off).
constexpr double kObtuseExcessWeight = 0.25;
constexpr double kObtuseCost = 2 * kPi / 180;

struct StarQuality {
  double minSin2 = 1;      // sin^2 of the star's smallest angle
  double meanAngle = 0;    // mean over the star's triangles of their score (starQuality), radians
};

class Smoother {
 public:
  explicit Smoother(MeshState& m) : m_(m), t_(m.tri) {
    const double s = std::sin(m.options->minAngle * (kPi / 180));
    sin2Bound_ = s * s;
    // The same slack as refinement's test of a wide triangle, so that a triangle refinement left
    // at the bound is not refused here as over it.
    cosMaxAngle_ = m.options->maxAngle > 0 ? std::cos(m.options->maxAngle * (kPi / 180)) - 1e-12 : -2;
  }
  bool tryMove(std::uint32_t v);
  bool trySlide(std::uint32_t v);

 private:
  MeshState& m_;
  Triangulation& t_;
  double sin2Bound_;
  double cosMaxAngle_;  // cosine of Options::maxAngle less a rounding slack; -2: no bound
  std::vector<std::uint32_t> ring_;     // the star: per triangle, its half-edge opposite v
  std::vector<std::uint32_t> stack_;    // edges to test for the Delaunay property
  std::vector<std::uint32_t> flips_;    // every flip's new diagonal, in order: its two vertices
  std::vector<std::uint32_t> changed_;  // slots whose triangle changed (repeats allowed)
  std::vector<double> savedAttributes_;

  bool gatherStar(std::uint32_t v);
  void odtPoint(std::uint32_t v, double x[2]) const;
  bool starFits(const double* x) const;
  StarQuality starQuality(const double* x) const;
  bool bestPoint(std::uint32_t v, const StarQuality& before, double best[2]) const;
  void saveAttributes(std::uint32_t v);
  void interpolateInStar(std::uint32_t v, const double* x);
  bool commit(std::uint32_t v, const double* from, const double* x);
  void legalizeLogged();
  void undo(std::uint32_t v, const double* from);
  bool changedTrianglesHold() const;
  double areaBound(std::uint32_t s) const;
};

// The closed fan around v, its edges all free; false (ring_ unspecified) for any other vertex.
bool Smoother::gatherStar(std::uint32_t v) {
  ring_.clear();
  const std::uint32_t start = t_.vtri[v];
  if (start == kNone) return false;
  std::uint32_t t = start;
  do {
    const std::uint32_t i = t_.tv[3 * t] == v ? 0u : t_.tv[3 * t + 1] == v ? 1u : 2u;
    const std::uint32_t in = 3 * t + (i + 1) % 3, out = 3 * t + (i + 2) % 3;  // the two spokes
    if (t_.con[in] != kFree || t_.con[out] != kFree || ring_.size() == kMaxStar) return false;
    ring_.push_back(3 * t + i);
    const std::uint32_t g = t_.twin[out];
    if (g == kNone) return false;
    t = g / 3;
  } while (t != start);
  return ring_.size() >= 3;
}

// x* = sum |T| c_T / sum |T| over the star. With v at the origin and a, b a ring edge, the
// circumcenter of (0, a, b) is n / d with d = 2 (a x b), and |T| = d / 4: so x* = sum n / sum d.
void Smoother::odtPoint(std::uint32_t v, double x[2]) const {
  const double* p = t_.pt(v);
  double nx = 0, ny = 0, dsum = 0;
  for (const std::uint32_t h : ring_) {
    const double* a = t_.pt(t_.origin(h));
    const double* b = t_.pt(t_.dest(h));
    const double ax = a[0] - p[0], ay = a[1] - p[1], bx = b[0] - p[0], by = b[1] - p[1];
    const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by;
    nx += by * a2 - ay * b2;
    ny += ax * b2 - bx * a2;
    dsum += 2 * (ax * by - ay * bx);
  }
  x[0] = p[0] + nx / dsum, x[1] = p[1] + ny / dsum;
}

// Every star triangle counter-clockwise with its center at x (exact predicates), x representable.
bool Smoother::starFits(const double* x) const {
  if (!isSafeCoordinate(x[0]) || !isSafeCoordinate(x[1])) return false;
  for (const std::uint32_t h : ring_)
    if (!(orient2d(t_.pt(t_.origin(h)), t_.pt(t_.dest(h)), x) > 0)) return false;
  return true;
}

// The star's smallest sin^2 and its mean score: per triangle its smallest angle, less a cost for an
// obtuse one (kObtuseCost, kObtuseExcessWeight).
StarQuality Smoother::starQuality(const double* x) const {
  StarQuality q;
  double sum = 0;
  for (const std::uint32_t h : ring_) {
    const double* p[3] = {x, t_.pt(t_.origin(h)), t_.pt(t_.dest(h))};
    q.minSin2 = std::min(q.minSin2, qualityOf(p[0], p[1], p[2]).sin2MinAngle);
    double smallest = kPi, largest = 0;
    for (int i = 0; i < 3; ++i) {
      const double* a = p[i];
      const double* b = p[(i + 1) % 3];
      const double* c = p[(i + 2) % 3];
      const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
      const double angle = std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
      smallest = std::min(smallest, angle), largest = std::max(largest, angle);
    }
    sum += smallest - kObtuseExcessWeight * std::max(0.0, largest - kPi / 2) - (largest > kPi / 2 ? kObtuseCost : 0.0);
  }
  q.meanAngle = sum / static_cast<double>(ring_.size());
  return q;
}

// The best point found for v: the ODT point (or part of the way to it), then a compass search
// around the best so far, every candidate keeping the star counter-clockwise and at the bound.
bool Smoother::bestPoint(std::uint32_t v, const StarQuality& before, double best[2]) const {
  const double* from = t_.pt(v);
  double target[2];
  odtPoint(v, target);
  best[0] = from[0], best[1] = from[1];
  double bestScore = before.meanAngle;
  const auto consider = [&](double x, double y) {
    const double c[2] = {x, y};
    if ((x == from[0] && y == from[1]) || !starFits(c)) return false;
    const StarQuality q = starQuality(c);
    if (q.minSin2 < sin2Bound_ || q.meanAngle < bestScore + kMinGain) return false;
    best[0] = x, best[1] = y, bestScore = q.meanAngle;
    return true;
  };
  for (const double step : kSteps)
    if (consider(from[0] + step * (target[0] - from[0]), from[1] + step * (target[1] - from[1]))) break;
  double h = 0.5 * std::hypot(target[0] - from[0], target[1] - from[1]);
  for (std::uint32_t r : ring_) h = std::max(h, 0.05 * std::hypot(t_.pt(t_.origin(r))[0] - from[0], t_.pt(t_.origin(r))[1] - from[1]));
  for (int round = 0; round < kSearchRounds; ++round) {
    const double cx = best[0], cy = best[1];
    const double d = 0.7071067811865476 * h;
    if (!(consider(cx + h, cy) || consider(cx - h, cy) || consider(cx, cy + h) || consider(cx, cy - h) ||
          consider(cx + d, cy + d) || consider(cx - d, cy - d) || consider(cx - d, cy + d) || consider(cx + d, cy - d)))
      h *= 0.5;
  }
  return best[0] != from[0] || best[1] != from[1];
}

bool Smoother::tryMove(std::uint32_t v) {
  if (!gatherStar(v)) return false;
  const double from[2] = {t_.xy[2 * v], t_.xy[2 * v + 1]};
  const StarQuality before = starQuality(from);
  // A star with a triangle under the bound holds one of the chapter's exemptions (or a triangle
  // refinement could not fix): it stays as it is, so that what is exempt stays exempt.
  double x[2];
  if (before.minSin2 < sin2Bound_ || !bestPoint(v, before, x)) return false;
  if (m_.attributeCount != 0) saveAttributes(v), interpolateInStar(v, x);
  return commit(v, from, x);
}

// A vertex refinement put on an input segment (not a curve, not a hull edge) slides along it,
// between its neighbors on the segment, by a compass search over the position along it.
bool Smoother::trySlide(std::uint32_t v) {
  const std::int32_t segment = m_.onSegment[v];
  std::uint32_t ends[2];
  if (segment < 0 || segment >= m_.curves->first || !segmentVertexFan(t_, v, ring_, ends)) return false;
  const double from[2] = {t_.xy[2 * v], t_.xy[2 * v + 1]};
  const StarQuality before = starQuality(from);
  if (before.minSin2 < sin2Bound_) return false;
  // Positions are taken on the input segment itself, so that slides never drift off it.
  const double* a = t_.pt(m_.segmentEnd(static_cast<std::size_t>(segment), 0));
  const double* b = t_.pt(m_.segmentEnd(static_cast<std::size_t>(segment), 1));
  const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
  const auto along = [&](const double* p) { return ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2; };
  const double s0 = along(from), s1 = along(t_.pt(ends[0])), s2 = along(t_.pt(ends[1]));
  const double low = std::min(s1, s2), high = std::max(s1, s2);
  double best = s0, bestScore = before.meanAngle, step = 0.25 * (high - low);
  for (int round = 0; round < kSearchRounds; ++round) {
    bool gained = false;
    for (const double s : {best + step, best - step}) {
      const double x[2] = {a[0] + s * dx, a[1] + s * dy};
      if (!(s > low + kSlideMargin * (high - low) && s < high - kSlideMargin * (high - low)) || !starFits(x)) continue;
      const StarQuality q = starQuality(x);
      if (q.minSin2 < sin2Bound_ || q.meanAngle < bestScore + kMinGain) continue;
      best = s, bestScore = q.meanAngle, gained = true;
    }
    if (!gained) step *= 0.5;
  }
  const double x[2] = {a[0] + best * dx, a[1] + best * dy};
  if (best == s0 || (x[0] == from[0] && x[1] == from[1])) return false;
  if (m_.attributeCount != 0) saveAttributes(v);
  t_.xy[2 * v] = x[0], t_.xy[2 * v + 1] = x[1];
  interpolateOnSegment(m_, v, ends[0], ends[1]);
  return commit(v, from, x);
}

void Smoother::saveAttributes(std::uint32_t v) {
  const auto first = m_.attributes.begin() + static_cast<std::ptrdiff_t>(m_.attributeCount * v);
  savedAttributes_.assign(first, first + static_cast<std::ptrdiff_t>(m_.attributeCount));
}

// v's values at x, from the star triangle (before the move) that holds x.
void Smoother::interpolateInStar(std::uint32_t v, const double* x) {
  const double* from = t_.pt(v);
  for (const std::uint32_t h : ring_) {
    const std::uint32_t a = t_.origin(h), b = t_.dest(h);
    if (orient2d(t_.pt(a), t_.pt(b), x) >= 0 && orient2d(from, t_.pt(a), x) >= 0 && orient2d(t_.pt(b), from, x) >= 0)
      return interpolateInTriangle(m_, v, v, a, b, x);
  }
}

// Moves v to x (attributes already set), restores the constrained Delaunay property, and keeps
// the result if every changed triangle holds the bounds; else puts everything back, false.
bool Smoother::commit(std::uint32_t v, const double* from, const double* x) {
  t_.xy[2 * v] = x[0], t_.xy[2 * v + 1] = x[1];
  stack_.clear(), flips_.clear(), changed_.clear();
  for (const std::uint32_t h : ring_) {
    const std::uint32_t t = h / 3;
    changed_.push_back(t);
    for (std::uint32_t k = 0; k < 3; ++k) stack_.push_back(3 * t + k);
  }
  legalizeLogged();
  if (changedTrianglesHold()) return true;
  undo(v, from);
  return false;
}

// Lawson flips (Triangulation::legalize), each flip's slot logged so that undo() can reverse it.
void Smoother::legalizeLogged() {
  while (!stack_.empty()) {
    const std::uint32_t h = stack_.back();
    stack_.pop_back();
    const std::uint32_t t = h / 3, g = t_.twin[h];
    if (t_.con[h] != kFree || g == kNone) continue;
    if (!(incircle(t_.pt(t_.tv[3 * t]), t_.pt(t_.tv[3 * t + 1]), t_.pt(t_.tv[3 * t + 2]), t_.pt(t_.apex(g))) > 0))
      continue;
    const std::uint32_t u = g / 3;
    t_.flip(h);
    // Slot t is now (apex(h), origin(h), d): the new diagonal joins its corners 0 and 2.
    flips_.push_back(t_.tv[3 * t]), flips_.push_back(t_.tv[3 * t + 2]);
    changed_.push_back(t), changed_.push_back(u);
    stack_.push_back(3 * t), stack_.push_back(3 * t + 2), stack_.push_back(3 * u), stack_.push_back(3 * u + 1);
  }
}

// Flipping a flip's new diagonal brings back the old one; in reverse order, with v still at its new
// place, that rebuilds the old triangles, which hold the old coordinates exactly. The diagonal is
// found by its vertices, not by the slot that took it: flipping back can leave each triangle in the
// other slot of its pair, and an earlier flip of that slot would then name another edge.
void Smoother::undo(std::uint32_t v, const double* from) {
  for (std::size_t k = flips_.size(); k >= 2; k -= 2) t_.flip(t_.findEdge(flips_[k - 2], flips_[k - 1]));
  t_.xy[2 * v] = from[0], t_.xy[2 * v + 1] = from[1];
  if (m_.attributeCount != 0)
    std::copy(savedAttributes_.begin(), savedAttributes_.end(),
              m_.attributes.begin() + static_cast<std::ptrdiff_t>(m_.attributeCount * v));
}

bool Smoother::changedTrianglesHold() const {
  for (const std::uint32_t s : changed_) {
    const double* p0 = t_.pt(t_.tv[3 * s]);
    const double* p1 = t_.pt(t_.tv[3 * s + 1]);
    const double* p2 = t_.pt(t_.tv[3 * s + 2]);
    if (!(orient2d(p0, p1, p2) > 0)) return false;
    const TriangleQuality q = qualityOf(p0, p1, p2);
    if (q.sin2MinAngle < sin2Bound_) return false;
    if (cosMaxAngle_ > -1 && largestAngleCos(p0, p1, p2) < cosMaxAngle_) return false;
    const double bound = areaBound(s);
    if (bound > 0 && q.area > bound) return false;
  }
  return true;
}

// The smallest area bound on slot s: the global one or its region's, the size function at its
// centroid, a refined mesh's (0: none), as refinement judges them.
double Smoother::areaBound(std::uint32_t s) const {
  double bound = m_.maxAreaOf(s);
  const double* p0 = t_.pt(t_.tv[3 * s]);
  const double* p1 = t_.pt(t_.tv[3 * s + 1]);
  const double* p2 = t_.pt(t_.tv[3 * s + 2]);
  const auto tighter = [&](double b) {
    if (b > 0) bound = bound > 0 ? std::min(bound, b) : b;
  };
  if (m_.options->sizeFunction) {
    const double cx = m_.input.toUser((p0[0] + p1[0] + p2[0]) / 3);
    const double cy = m_.input.toUser((p0[1] + p1[1] + p2[1]) / 3);
    const double user = m_.options->sizeFunction(cx, cy);
    if (std::isfinite(user) && user > 0) tighter(m_.input.areaToInternal(user));
  }
  if (m_.oldMesh != nullptr) tighter(m_.oldMesh->boundFor(p0, p1, p2));
  return bound;
}

}  // namespace

std::uint64_t smoothMesh(MeshState& m, int passes) {
  Smoother smoother(m);
  std::uint64_t moves = 0;
  for (int pass = 0; pass < passes; ++pass) {
    std::uint64_t moved = 0;
    for (std::uint32_t v = m.inputCount; v < m.tri.vertexCount(); ++v)
      if (m.kind[v] == VertexKind::Interior || m.kind[v] == VertexKind::OffCenter ? smoother.tryMove(v)
          : m.kind[v] == VertexKind::SegmentSplit && smoother.trySlide(v))
        ++moved;
    moves += moved;
    if (moved == 0) break;
  }
  return moves;
}

RUPPERT_COLD_END

}  // namespace ruppert::detail
