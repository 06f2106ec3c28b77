// An independent check of meshes with curves (curve_checks.h): arcs by their radius and the sagitta
// of a chord (r - sqrt(r^2 - c^2 / 4)), Béziers by the nearest curve parameter (dense sampling, then
// Newton's method on the squared distance) and samples of the stretch between a piece's ends.
#include "curve_checks.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ruppert_test {

namespace {

using ruppert::Curve;
using ruppert::CurveType;

struct Point {
  double x, y;
};

Point bezierAt(const double* c, double t) {
  const double s = 1 - t;
  const double w[4] = {s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t};
  return {w[0] * c[0] + w[1] * c[2] + w[2] * c[4] + w[3] * c[6], w[0] * c[1] + w[1] * c[3] + w[2] * c[5] + w[3] * c[7]};
}

// The parameter of the curve point nearest p: golden-section search around every local minimum of
// the squared distance over 4096 samples (a curve that comes back near itself has several; the
// nearest sample alone could sit on the wrong stretch).
double nearestParameter(const double* c, Point p) {
  constexpr int kSamples = 4096;
  auto d2 = [&](double t) {
    const Point q = bezierAt(c, t);
    return (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y);
  };
  std::vector<double> sample(kSamples + 1);
  for (int i = 0; i <= kSamples; ++i) sample[i] = d2(double(i) / kSamples);
  double best = 0, bestD2 = sample[0];
  for (int i = 0; i <= kSamples; ++i) {
    if ((i > 0 && sample[i - 1] <= sample[i]) || (i < kSamples && sample[i + 1] < sample[i])) continue;
    double lo = std::max(0.0, double(i - 1) / kSamples), hi = std::min(1.0, double(i + 1) / kSamples);
    for (int k = 0; k < 100; ++k) {
      const double m1 = lo + (hi - lo) * 0.381966, m2 = hi - (hi - lo) * 0.381966;
      if (d2(m1) < d2(m2)) hi = m2;
      else lo = m1;
    }
    const double t = (lo + hi) / 2;
    if (sample[i] < bestD2) best = double(i) / kSamples, bestD2 = sample[i];
    if (d2(t) < bestD2) best = t, bestD2 = d2(t);
  }
  return best;
}

double distanceToSegment(Point a, Point b, Point q) {
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / l2, 0.0, 1.0) : 0;
  return std::hypot(q.x - a.x - t * dx, q.y - a.y - t * dy);
}

struct CurveGeometry {
  const Curve& curve;
  double c[8];   // Bézier control points, or the arc's center and radius in c[0..2]
  double size;   // radius, or the control polygon's extent
};

CurveGeometry geometryOf(const ruppert::Plc& in, const Curve& cv) {
  const double* a = &in.points[2 * std::size_t(cv.from)];
  const double* b = &in.points[2 * std::size_t(cv.to)];
  CurveGeometry g{cv, {a[0], a[1], cv.controls[0], cv.controls[1], cv.controls[2], cv.controls[3], b[0], b[1]}, 0};
  if (cv.type == CurveType::Arc) {
    g.c[0] = cv.center[0], g.c[1] = cv.center[1], g.c[2] = std::hypot(a[0] - cv.center[0], a[1] - cv.center[1]);
    g.size = g.c[2];
    return g;
  }
  for (int i = 2; i < 8; i += 2) g.size = std::max(g.size, std::hypot(g.c[i] - g.c[0], g.c[i + 1] - g.c[1]));
  return g;
}

// Distance from p to the curve; for a Bézier, t receives the nearest point's parameter.
double offCurve(const CurveGeometry& g, Point p, double& t) {
  if (g.curve.type == CurveType::Arc) return std::fabs(std::hypot(p.x - g.c[0], p.y - g.c[1]) - g.c[2]);
  t = nearestParameter(g.c, p);
  const Point q = bezierAt(g.c, t);
  return std::hypot(q.x - p.x, q.y - p.y);
}

// Largest distance from the curve between a and b (both on it, a Bézier's at parameters ta and tb)
// to the chord a-b.
double chordError(const CurveGeometry& g, Point a, Point b, double ta, double tb) {
  const double chord = std::hypot(b.x - a.x, b.y - a.y);
  if (g.curve.type == CurveType::Arc) {
    const double r = g.c[2];
    return r - std::sqrt(std::max(0.0, r * r - chord * chord / 4));
  }
  double worst = 0;
  for (int i = 1; i < 256; ++i) worst = std::max(worst, distanceToSegment(a, b, bezierAt(g.c, ta + (tb - ta) * i / 256.0)));
  return worst;
}

}  // namespace

CurveCheck checkCurves(const ruppert::Mesh& mesh, const ruppert::Plc& input, double tolerance, bool wholeChains) {
  CurveCheck out;
  const std::size_t segments = input.segments.size() / 2;
  out.pieces.assign(input.curves.size(), 0);
  std::vector<std::map<std::uint32_t, int>> degree(input.curves.size());
  auto at = [&](std::uint32_t v) { return Point{mesh.points[2 * std::size_t(v)], mesh.points[2 * std::size_t(v) + 1]}; };
  for (std::size_t k = 0; k < mesh.segmentIds.size(); ++k) {
    const std::int32_t id = mesh.segmentIds[k];
    if (id < 0 || std::size_t(id) < segments) continue;
    const std::size_t c = std::size_t(id) - segments;
    const CurveGeometry g = geometryOf(input, input.curves[c]);
    const std::uint32_t u = mesh.segments[2 * k], w = mesh.segments[2 * k + 1];
    ++out.pieces[c], ++degree[c][u], ++degree[c][w];
    double t[2] = {0, 0};
    for (int end = 0; end < 2; ++end) {
      const std::uint32_t v = end ? w : u;
      const double off = offCurve(g, at(v), t[end]) / g.size;
      out.worstOffCurve = std::max(out.worstOffCurve, off);
      if (off > 1e-12) out.problems.push_back("vertex " + std::to_string(v) + " of curve " + std::to_string(c) + " lies " + std::to_string(off) + " of its size off it");
    }
    const double error = chordError(g, at(u), at(w), t[0], t[1]);
    out.worstChordError = std::max(out.worstChordError, error);
    out.chordAreaBound += error * std::hypot(at(w).x - at(u).x, at(w).y - at(u).y);
    if (error > tolerance + 1e-12 * g.size)
      out.problems.push_back("piece " + std::to_string(k) + " of curve " + std::to_string(c) + " lies " + std::to_string(error) + " from its chord");
  }
  for (std::size_t c = 0; c < input.curves.size(); ++c) {
    const Curve& cv = input.curves[c];
    for (const auto& entry : degree[c]) {
      const std::uint32_t v = entry.first;
      const auto d = entry.second;
      // By coordinates: an end may have been merged with a duplicate point.
      auto same = [&](std::uint32_t i) { return at(v).x == input.points[2 * std::size_t(i)] && at(v).y == input.points[2 * std::size_t(i) + 1]; };
      const bool end = same(cv.from) || same(cv.to);
      if (wholeChains ? d != (end ? 1 : 2) : d > (end ? 1 : 2)) out.problems.push_back("curve " + std::to_string(c) + "'s pieces meet " + std::to_string(d) + " times at vertex " + std::to_string(v));
    }
    if (wholeChains && out.pieces[c] == 0) out.problems.push_back("curve " + std::to_string(c) + " has no pieces in the mesh");
  }
  return out;
}

}  // namespace ruppert_test
