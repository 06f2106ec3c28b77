// The shape measures of one triangle that output statistics and refinement both need.
#pragma once

#include <cmath>

namespace ruppert::detail {

struct TriangleShape {
  double angle[3];   // radians, at each corner
  double minAngle;   // radians, the smallest of them
  int minCorner;     // corner (0..2) with the smallest angle
  int shortestEdge;  // edge (numbered by its opposite corner) that is shortest
  double shortest;   // its length
  double area;
};

// Angles via atan2(|cross|, dot): accurate for needles and near-straight angles alike.
inline TriangleShape shapeOf(const double* p0, const double* p1, const double* p2) {
  const double* p[3] = {p0, p1, p2};
  TriangleShape s{{0, 0, 0}, 10, 0, 0, HUGE_VAL, 0};
  for (int i = 0; i < 3; ++i) {
    const double* o = p[i];
    const double* u = p[(i + 1) % 3];
    const double* w = p[(i + 2) % 3];
    const double ux = u[0] - o[0], uy = u[1] - o[1], wx = w[0] - o[0], wy = w[1] - o[1];
    const double cross = ux * wy - uy * wx;
    s.angle[i] = std::atan2(std::fabs(cross), ux * wx + uy * wy);
    if (s.angle[i] < s.minAngle) s.minAngle = s.angle[i], s.minCorner = i;
    const double len = std::hypot(u[0] - w[0], u[1] - w[1]);
    if (len < s.shortest) s.shortest = len, s.shortestEdge = i;
    if (i == 0) s.area = 0.5 * std::fabs(cross);
  }
  return s;
}

}  // namespace ruppert::detail
