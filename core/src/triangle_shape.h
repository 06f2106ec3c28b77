// The shape measures of one triangle that output statistics and refinement both need.
#pragma once

#include <algorithm>
#include <cmath>

namespace ruppert::detail {

// Which edge is shortest (numbered by its opposite corner) and how long. The smallest angle lies
// opposite the shortest edge, so shortestEdge is also the corner with the smallest angle.
struct TriangleShape {
  int shortestEdge;
  double shortest;
};

inline TriangleShape shapeOf(const double* p0, const double* p1, const double* p2) {
  const double* p[3] = {p0, p1, p2};
  TriangleShape s{0, HUGE_VAL};
  for (int i = 0; i < 3; ++i) {
    const double* u = p[(i + 1) % 3];
    const double* w = p[(i + 2) % 3];
    const double len2 = (u[0] - w[0]) * (u[0] - w[0]) + (u[1] - w[1]) * (u[1] - w[1]);
    if (len2 < s.shortest) s.shortest = len2, s.shortestEdge = i;
  }
  s.shortest = std::sqrt(s.shortest);
  return s;
}

// What the refinement queue needs for every new triangle, without square roots or arctangents:
// the sine of the smallest angle, squared (it lies opposite the shortest edge, between the two
// longer ones: sin = |cross| / (product of their lengths)), and the area.
struct TriangleQuality {
  double sin2MinAngle;
  double area;
};

inline TriangleQuality qualityOf(const double* p0, const double* p1, const double* p2) {
  const double ax = p1[0] - p0[0], ay = p1[1] - p0[1];  // edge opposite p2
  const double bx = p2[0] - p0[0], by = p2[1] - p0[1];  // edge opposite p1
  const double cx = p2[0] - p1[0], cy = p2[1] - p1[1];  // edge opposite p0
  const double e2 = ax * ax + ay * ay, e1 = bx * bx + by * by, e0 = cx * cx + cy * cy;
  const double cross = ax * by - ay * bx;
  const double longerPair = e0 <= e1 && e0 <= e2 ? e1 * e2 : e1 <= e2 ? e0 * e2 : e0 * e1;
  return {longerPair > 0 ? cross * cross / longerPair : 0.0, 0.5 * std::fabs(cross)};
}

// The angle (radians, in [0, pi]) between vectors u and w, within 1e-9 of atan2(|u x w|, u . w).
// For the angle histogram of every output triangle: two library arctangents per triangle cost about
// a tenth of meshing a small input. The quotient is reduced to |r| <= tan(pi/12) by
// atan(t) = pi/6 + atan((sqrt(3) t - 1) / (t + sqrt(3))), where the series up to r^13 errs by under
// r^15 / 15 < 3e-10.
inline double angleBetween(double ux, double uy, double wx, double wy) {
  constexpr double kPi = 3.14159265358979323846, kSqrt3 = 1.73205080756887729353;
  constexpr double kTanPi12 = 0.26794919243112270647;
  const double y = std::fabs(ux * wy - uy * wx), x = ux * wx + uy * wy, ax = std::fabs(x);
  const double big = std::max(y, ax);
  if (!(big > 0)) return 0;
  double t = std::min(y, ax) / big, a = 0;
  if (t > kTanPi12) t = (kSqrt3 * t - 1) / (t + kSqrt3), a = kPi / 6;
  const double t2 = t * t;
  a += t * (1 + t2 * (-1.0 / 3 + t2 * (1.0 / 5 + t2 * (-1.0 / 7 + t2 * (1.0 / 9 + t2 * (-1.0 / 11 + t2 / 13))))));
  if (y > ax) a = kPi / 2 - a;
  return x < 0 ? kPi - a : a;
}

// The angle at corner i of triangle (p[0], p[1], p[2]), exactly as the library computes it.
inline double cornerAngle(const double* const* p, int i) {
  const double* o = p[i];
  const double* u = p[(i + 1) % 3];
  const double* w = p[(i + 2) % 3];
  const double ux = u[0] - o[0], uy = u[1] - o[1], wx = w[0] - o[0], wy = w[1] - o[1];
  return std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy);
}

// The three angles (radians) with angleBetween, for statistics over every output triangle; the third
// is what remains of pi.
inline void triangleAngles(const double* const* p, double angle[3]) {
  for (int i = 0; i < 2; ++i) {
    const double* o = p[i];
    const double* u = p[(i + 1) % 3];
    const double* w = p[(i + 2) % 3];
    angle[i] = angleBetween(u[0] - o[0], u[1] - o[1], w[0] - o[0], w[1] - o[1]);
  }
  angle[2] = std::max(0.0, 3.14159265358979323846 - angle[0] - angle[1]);
}

}  // namespace ruppert::detail
