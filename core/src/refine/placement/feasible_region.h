// A quick test of whether a locally optimal Steiner point (optimal_point.h) can meet the bound at
// all, run before the search, which on most calls ends in a decline.
//
// A point x makes triangle (u, v, x) with all angles >= theta only in R_theta(uv): left of the ray
// from u at theta above uv, left of the ray from v at theta above vu (two half-planes), and in the
// disk whose arc through u and v sees uv at theta. The point searched for lies in the intersection
// of these regions over the petal edge and every cavity edge. This test intersects the half-planes
// exactly (a convex polygon) and asks whether each disk reaches that polygon: a necessary condition
// only, so a "no" is certain and a "yes" leaves the answer to the search.
#pragma once

#include <cmath>

#include "refine/placement/optimal_point.h"

namespace ruppert::detail {

// The bound theta (radians, in (0, pi/3]) with its cosine and sine, computed once per bound instead
// of once per screen (two library calls, 0.7% of a cloud of points' mesh natively).
struct BoundAngle {
  double cos, sin;
  explicit BoundAngle(double theta) : cos(std::cos(theta)), sin(std::sin(theta)) {}
};

// False when no point gives every triangle of the query all angles >= theta, with a margin of about
// 1e-9 relative to the edges' lengths on the side of answering true. `candidate`, when given,
// receives a point to try first where the answer is true (the mean of the half-planes' polygon's
// vertices: it often lies in every disk too), else NaN.
bool mayMeetBound(const OptimalPointQuery& query, const BoundAngle& bound, double* candidate = nullptr);

}  // namespace ruppert::detail
