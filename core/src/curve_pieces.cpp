// Geometry of a curve's shape (curve_pieces.h): points, a piece's control points and hull, its
// distance from its chord and whether it stays in the chord's diametral disk.
#include "curve_pieces.h"

#include <algorithm>
#include <cmath>

#include "cold_code.h"

// Curves are rare and their pieces few: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

namespace ruppert::detail {

namespace {

// Bernstein form of a cubic's coordinate k (0: x, 1: y) at t.
double cubic(const double* p, int k, double t) {
  const double s = 1 - t;
  return s * s * s * p[k] + 3 * s * s * t * p[2 + k] + 3 * s * t * t * p[4 + k] + t * t * t * p[6 + k];
}

double cubicDerivative(const double* p, int k, double t) {
  const double s = 1 - t;
  return 3 * (s * s * (p[2 + k] - p[k]) + 2 * s * t * (p[4 + k] - p[2 + k]) + t * t * (p[6 + k] - p[4 + k]));
}

// Distance of q from the line through a and b (from a when they coincide).
double distanceToChord(const double* a, const double* b, const double* q) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], len = std::sqrt(dx * dx + dy * dy);
  if (len == 0) return std::sqrt((q[0] - a[0]) * (q[0] - a[0]) + (q[1] - a[1]) * (q[1] - a[1]));
  return std::fabs(dx * (q[1] - a[1]) - dy * (q[0] - a[0])) / len;
}

}  // namespace

void CurveShape::point(double t, double out[2]) const {
  if (type == CurveType::Arc) {
    const double angle = c[3] + t * c[4];
    out[0] = c[0] + c[2] * std::cos(angle), out[1] = c[1] + c[2] * std::sin(angle);
    return;
  }
  out[0] = cubic(c, 0, t), out[1] = cubic(c, 1, t);
}

void CurveShape::pieceControls(double t0, double t1, double q[8]) const {
  const double third = (t1 - t0) / 3;
  point(t0, q), point(t1, q + 6);
  q[2] = q[0] + third * cubicDerivative(c, 0, t0), q[3] = q[1] + third * cubicDerivative(c, 1, t0);
  q[4] = q[6] - third * cubicDerivative(c, 0, t1), q[5] = q[7] - third * cubicDerivative(c, 1, t1);
}

double CurveShape::chordError(double t0, double t1) const {
  if (type == CurveType::Arc) return c[2] * (1 - std::cos(std::fabs(t1 - t0) * c[4] / 2));
  double q[8];
  pieceControls(t0, t1, q);
  return std::max(distanceToChord(q, q + 6, q + 2), distanceToChord(q, q + 6, q + 4));
}

bool CurveShape::withinDisk(double t0, double t1) const {
  if (type == CurveType::Arc) return std::fabs(t1 - t0) * c[4] <= kArcPieceTurn * (1 + 1e-9);
  double q[8];
  pieceControls(t0, t1, q);
  // A control point sees the chord at 90 degrees or more.
  auto inDisk = [&](const double* p) { return (q[0] - p[0]) * (q[6] - p[0]) + (q[1] - p[1]) * (q[7] - p[1]) <= 0; };
  return inDisk(q + 2) && inDisk(q + 4);
}

void CurveShape::hull(double t0, double t1, double q[8]) const {
  if (type == CurveType::Bezier) {
    pieceControls(t0, t1, q);
    return;
  }
  point(t0, q), point(t1, q + 6);
  // The end tangents meet on the bisector at r / cos(half the turn); a piece turns by at most 60
  // degrees, so the cosine is at least 0.866.
  const double half = (t1 - t0) * c[4] / 2, mid = c[3] + t0 * c[4] + half, d = c[2] / std::cos(half);
  q[2] = q[4] = c[0] + d * std::cos(mid), q[3] = q[5] = c[1] + d * std::sin(mid);
}

void CurveShape::scale(double factor) {
  if (type == CurveType::Arc) {
    c[0] *= factor, c[1] *= factor, c[2] *= factor;
    return;
  }
  for (double& v : c) v *= factor;
}

}  // namespace ruppert::detail
RUPPERT_COLD_END
