// The shape measures of one triangle that output statistics and refinement both need.
#pragma once

#include <algorithm>
#include <cmath>

namespace ruppert::detail {

inline constexpr double kPi = 3.14159265358979323846;

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

}  // namespace ruppert::detail
