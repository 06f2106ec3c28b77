// Point geometry that refinement and its placements share: lengths, the encroachment test, the
// circumcenter and the off-center of a triangle. Free functions of coordinates only.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/triangle_shape.h"  // kPi

namespace ruppert::detail {

// Plain sqrt(x^2 + y^2) rather than hypot (several times slower, and a library call in WebAssembly):
// internal coordinates lie within (-2, 2), so no square overflows, and every length refinement
// compares or divides by is at least its length floor (2^-38), whose square is far above underflow.
inline double length(double x, double y) { return std::sqrt(x * x + y * y); }
inline double dist(const double* p, const double* q) { return length(p[0] - q[0], p[1] - q[1]); }
inline double sq(const double* p, const double* q) {
  return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]);
}

// v encroaches (a, b) iff the angle avb is at least 90 degrees (closed diametral disk) or, with
// lenses, at least 180 - 2 theta degrees when that is larger: cos(avb) <= lensCos, i.e.
// dot <= 0 and dot^2 >= lensCos2 |va|^2 |vb|^2 (lensCos2 = 0: the disk).
inline bool encroaches(const double* v, const double* a, const double* b, double lensCos2) {
  const double ax = a[0] - v[0], ay = a[1] - v[1], bx = b[0] - v[0], by = b[1] - v[1];
  const double dot = ax * bx + ay * by;
  if (dot > 0) return false;
  return lensCos2 == 0 || dot * dot >= lensCos2 * (ax * ax + ay * ay) * (bx * bx + by * by);
}

// Circumcenter of the counter-clockwise triangle p, computed relative to p[0] for accuracy. False
// when the triangle is not strictly counter-clockwise in doubles (no circumcenter to trust).
inline bool circumcenter(const double* const* p, double cc[2]) {
  const double bx = p[1][0] - p[0][0], by = p[1][1] - p[0][1];
  const double cx = p[2][0] - p[0][0], cy = p[2][1] - p[0][1];
  const double d = 2 * (bx * cy - by * cx);
  if (!(d > 0)) return false;
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  cc[0] = p[0][0] + (cy * b2 - by * c2) / d, cc[1] = p[0][1] + (bx * c2 - cx * b2) / d;
  return true;
}

// Off-center (Üngör, §6.8) of a triangle whose shortest edge u-w has length `shortest` and whose
// circumcenter is cc: on the edge's bisector, where the isosceles triangle on u-w has apex angle
// theta (so it just meets the bound). False, leaving out alone, when that point is not nearer than
// the circumcenter (the circumcenter is then the placement).
//
// The new vertex is rounded to doubles, up to an ulp of its coordinates from where it is aimed; seen
// from an edge of length l that turns the apex angle by up to ulp / l radians, so a triangle built
// to meet the bound exactly can miss it, and its circumcenter then adds a vertex no farther away
// than l: no gain in size, and at small scales a runaway (300 chords crossing at 30 degrees: half of
// one's insertions split triangles 1e-9 to 1e-6 degrees short of 30). Aim past the bound by several
// times that turn: 4e-12 rad for l = 1e-3, 1e-3 rad at the length floor.
inline bool offCenter(const double* u, const double* w, double shortest, const double* cc, double theta,
                      double out[2]) {
  const double mx = (u[0] + w[0]) / 2, my = (u[1] + w[1]) / 2;
  const double toC = length(cc[0] - mx, cc[1] - my);
  const double reach = std::max({std::fabs(u[0]), std::fabs(u[1]), std::fabs(w[0]), std::fabs(w[1])});
  const double margin = 16 * std::numeric_limits<double>::epsilon() * reach / shortest;
  const double hOff = (shortest / 2) / std::tan((theta + margin) / 2);
  if (!(hOff < toC && toC > 0)) return false;
  out[0] = mx + (cc[0] - mx) * (hOff / toC);
  out[1] = my + (cc[1] - my) * (hOff / toC);
  return true;
}

// The off-center of a triangle too large for its area bound (one that meets the angle bound): the
// point on the bisector of its shortest edge uw, towards the circumcenter cc, where the triangle on uw
// has kSizeFill of the bound's area, when that is nearer than cc and leaves uw's angles >= theta.
// The circumcenter makes triangles of any size below it; this one makes the triangle on uw about as
// large as the bound allows. Measured with max area = bounding box / 3000 on the 300 generated
// PLCs against Triangle: 0.951x -> 0.936x its triangles at 30 degrees, 0.897x -> 0.887x at 33
// (tests/bench/results/area-bound.md); at a fill of 1 rounding leaves that triangle just over the
// bound (0.944x), 0.94 0.938x, 0.97-0.995 0.936x. Only for acute triangles (isAcute): a right
// triangle's circumcenter halves it, which the largest-first order turns into a grid on a square
// (at max area 3e-4, 4,096 triangles against 5,056 with size off-centers there too, the same
// 0.936x on the families).
inline constexpr double kSizeFill = 0.98;

// Whether every angle of p[0] p[1] p[2] is under 90 degrees by more than rounding.
inline bool isAcute(const double* const* p) {
  for (int i = 0; i < 3; ++i) {
    const double* a = p[i];
    const double* b = p[(i + 1) % 3];
    const double* c = p[(i + 2) % 3];
    const double dot = (b[0] - a[0]) * (c[0] - a[0]) + (b[1] - a[1]) * (c[1] - a[1]);
    if (!(dot > 1e-9 * dist(a, b) * dist(a, c))) return false;
  }
  return true;
}
inline bool sizeOffCenter(const double* u, const double* w, const double* cc, double maxArea, double theta, double out[2]) {
  const double len = length(w[0] - u[0], w[1] - u[1]);
  const double mx = (u[0] + w[0]) / 2, my = (u[1] + w[1]) / 2;
  const double toC = length(cc[0] - mx, cc[1] - my);
  const double h = 2 * kSizeFill * maxArea / len;
  if (!(h < toC && h >= (len / 2) * std::tan(theta) && toC > 0)) return false;
  out[0] = mx + (cc[0] - mx) * (h / toC);
  out[1] = my + (cc[1] - my) * (h / toC);
  return true;
}

// The cosine of the triangle's largest angle, opposite its longest edge c: (a^2 + b^2 - c^2) / 2ab.
inline double largestAngleCos(const double* p0, const double* p1, const double* p2) {
  const double e0 = sq(p1, p2), e1 = sq(p2, p0), e2 = sq(p0, p1);
  const double longest = std::max({e0, e1, e2});
  const double shorterProduct = longest == e0 ? e1 * e2 : longest == e1 ? e0 * e2 : e0 * e1;
  return shorterProduct > 0 ? (e0 + e1 + e2 - 2 * longest) / (2 * std::sqrt(shorterProduct)) : -1;
}

// Where segments p0-p1 and q0-q1 meet (parameters within [0, 1] on both), into z; false if they
// are parallel in doubles or do not meet.
inline bool segmentsMeet(const double* p0, const double* p1, const double* q0, const double* q1, double z[2]) {
  const double ax = p1[0] - p0[0], ay = p1[1] - p0[1];
  const double bx = q1[0] - q0[0], by = q1[1] - q0[1];
  const double den = ax * by - ay * bx;
  if (den == 0) return false;
  const double ta = ((q0[0] - p0[0]) * by - (q0[1] - p0[1]) * bx) / den;
  const double tb = ((q0[0] - p0[0]) * ay - (q0[1] - p0[1]) * ax) / den;
  if (!(ta >= 0 && ta <= 1 && tb >= 0 && tb <= 1)) return false;
  z[0] = p0[0] + ta * ax, z[1] = p0[1] + ta * ay;
  return true;
}

}  // namespace ruppert::detail
