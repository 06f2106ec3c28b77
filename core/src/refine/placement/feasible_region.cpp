#include "refine/placement/feasible_region.h"

#include <algorithm>
#include <cmath>

#include "refine/placement/refine_geometry.h"  // length: sqrt, not the slower hypot (a library call in WebAssembly)

namespace ruppert::detail {

namespace {

constexpr double kMargin = 1e-9;  // relative: half-planes are moved out and disks widened by this
constexpr double kQuickMargin = 1e-6;  // meetsFirstDisk's, relative to the disks' radii
constexpr int kMaxBases = 65;                  // the petal and up to 64 edges (a relocation's star)
constexpr int kMaxVertices = 4 + 2 * kMaxBases;  // each cut adds at most one vertex to a convex polygon

struct Polygon {
  double xy[2 * kMaxVertices];
  int n = 0;
};

// The part of `in` left of the line through (px, py) with unit direction (dx, dy), or within
// `slack` of it: one Sutherland-Hodgman step. False if the result would not fit, which rounding on
// a nearly degenerate polygon (more than two sign changes around it) could cause.
bool clipLeft(const Polygon& in, double px, double py, double dx, double dy, double slack, Polygon& out) {
  out.n = 0;
  auto side = [&](const double* a) { return dx * (a[1] - py) - dy * (a[0] - px) + slack; };
  // Each vertex's side once, carried to the next edge; the successor without a modulo (an integer
  // division per vertex was a fifth of this, the hottest loop of the screen).
  double sa = in.n > 0 ? side(in.xy) : 0;
  for (int i = 0; i < in.n; ++i) {
    if (out.n + 2 > kMaxVertices) return false;
    const double* a = in.xy + 2 * i;
    const double* b = i + 1 < in.n ? a + 2 : in.xy;
    const double sb = side(b);
    if (sa >= 0) out.xy[2 * out.n] = a[0], out.xy[2 * out.n + 1] = a[1], ++out.n;
    if ((sa >= 0) != (sb >= 0)) {
      const double t = sa / (sa - sb);
      out.xy[2 * out.n] = a[0] + t * (b[0] - a[0]), out.xy[2 * out.n + 1] = a[1] + t * (b[1] - a[1]), ++out.n;
    }
    sa = sb;
  }
  return true;
}

// Distance from c to the convex counter-clockwise polygon (0 inside).
double distanceTo(const Polygon& poly, const double* c) {
  bool inside = true;
  double best = HUGE_VAL;
  for (int i = 0; i < poly.n; ++i) {
    const double* a = poly.xy + 2 * i;
    const double* b = i + 1 < poly.n ? a + 2 : poly.xy;
    const double ex = b[0] - a[0], ey = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    if (ex * cy - ey * cx < 0) inside = false;
    const double len2 = ex * ex + ey * ey;
    const double t = len2 > 0 ? std::clamp((ex * cx + ey * cy) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, length(cx - t * ex, cy - t * ey));
  }
  return inside ? 0 : best;
}

struct Base {
  const double* u;
  const double* v;
};

// The center and radius of the disk of points left of uv from which uv is seen at theta or more.
void apexDisk(const Base& b, double cotTheta, double cscTheta, double center[2], double& radius) {
  const double ex = b.v[0] - b.u[0], ey = b.v[1] - b.u[1];
  center[0] = (b.u[0] + b.v[0]) / 2 - ey * cotTheta / 2;
  center[1] = (b.u[1] + b.v[1]) / 2 + ex * cotTheta / 2;
  radius = length(ex, ey) * cscTheta / 2;
}

// Signed distance from c to the line through p with unit direction (dx, dy), positive on its left.
double leftOf(const double* p, double dx, double dy, const double* c) {
  return dx * (c[1] - p[1]) - dy * (c[0] - p[0]);
}

// A cheaper necessary condition, tried before the clipping: every R_theta(e) must meet the first
// base's disk, so each base's disk must overlap that disk and so must its two half-planes. One pass
// against the first base, no polygon: a tenth of the clipping's cost, and it settles about half of
// the calls that end in "no" (a cloud of points at 30 degrees: 667 of 1,234). Its margin is wider
// than the clipping's, so that it never says no where that would say yes.
bool meetsFirstDisk(const Base* bases, int count, double c, double s, double cotTheta, double cscTheta) {
  double c0[2], r0;
  apexDisk(bases[0], cotTheta, cscTheta, c0, r0);
  for (int i = 1; i < count; ++i) {
    double ci[2], ri;
    apexDisk(bases[i], cotTheta, cscTheta, ci, ri);
    if (!(length(ci[0] - c0[0], ci[1] - c0[1]) <= (r0 + ri) * (1 + kQuickMargin))) return false;
    const double ex = bases[i].v[0] - bases[i].u[0], ey = bases[i].v[1] - bases[i].u[1];
    const double len = length(ex, ey);
    if (!(len > 0)) return true;  // the clipping decides
    const double dx = ex / len, dy = ey / len, reach = -(r0 + ri) * kQuickMargin - r0;
    if (!(leftOf(bases[i].u, c * dx - s * dy, s * dx + c * dy, c0) >= reach) ||
        !(leftOf(bases[i].v, c * dx + s * dy, c * dy - s * dx, c0) >= reach))
      return false;
  }
  return true;
}

// Cheaper still, and tried first: every corner of the cavity must be wide enough to split. A point
// left of every edge of the closed cavity boundary (which the half-planes imply) lies inside each
// convex corner w, so w's two new triangles share the corner's angle between them: a corner
// narrower than 2 theta leaves one of them below theta wherever x is. This settles about two thirds
// of all calls (the 45 family PLCs of seeds 1-3 at 30 degrees: 15,558 of 24,493). Corners come from
// matching one edge's end with the next edge's start, exactly (the coordinates are copies of the
// same vertex's), searching onwards from the edge itself (the cavity's breadth-first search lists
// its edges in no particular order). Where the boundary touches itself at w, two edges start there
// and the match may pair the wrong two; but no point is left of every edge of such a boundary (it
// would have to lie in two disjoint wedges at w), so a "no" is right there too. The margin
// (1e-6 radians) is far wider than rounding, so that a "no" here is a "no" of the search too.
bool cornersWideEnough(const CavityEdge* edges, std::size_t count, double c, double s) {
  // cos and sin of phi = 2 theta - 1e-6, from those of theta.
  const double c2 = c * c - s * s, s2 = 2 * s * c, cd = 1 - 5e-13, sd = 1e-6;
  const double cp = c2 * cd + s2 * sd, sp = s2 * cd - c2 * sd;
  for (std::size_t i = 0; i < count; ++i) {
    const double* w = edges[i].v;
    const CavityEdge* next = nullptr;
    for (std::size_t k = 1; k < count && !next; ++k) {
      const std::size_t j = i + k < count ? i + k : i + k - count;
      if (edges[j].u[0] == w[0] && edges[j].u[1] == w[1]) next = edges + j;
    }
    if (!next) continue;
    // The corner's angle, from w->next counter-clockwise to w->previous: below phi when its sine
    // relative to phi is negative (a reflex corner, cross < 0, is always wide enough).
    const double ax = next->v[0] - w[0], ay = next->v[1] - w[1];
    const double bx = edges[i].u[0] - w[0], by = edges[i].u[1] - w[1];
    const double cross = ax * by - ay * bx, dot = ax * bx + ay * by;
    if (cross >= 0 && cross * cp - dot * sp < 0) return false;
  }
  return true;
}

}  // namespace

bool mayMeetBound(const OptimalPointQuery& query, const BoundAngle& bound, double* candidate) {
  if (candidate) candidate[0] = candidate[1] = NAN;  // no candidate unless the polygon is complete
  Base bases[kMaxBases];
  int count = 0;
  if (query.petal) bases[count++] = {query.p, query.q};
  if (query.edgeCount + 1 > kMaxBases) return true;  // beyond the cap: leave it to the search
  for (std::size_t i = 0; i < query.edgeCount; ++i) bases[count++] = {query.edges[i].u, query.edges[i].v};
  if (count == 0) return true;
  const double c = bound.cos, s = bound.sin, cotTheta = c / s, cscTheta = 1 / s;
  if (!cornersWideEnough(query.edges, query.edgeCount, c, s)) return false;
  if (!meetsFirstDisk(bases, count, c, s, cotTheta, cscTheta)) return false;
  // Start from the square around the first base's disk, which holds every feasible point.
  double center[2], radius;
  apexDisk(bases[0], cotTheta, cscTheta, center, radius);
  radius *= 1 + kMargin;
  Polygon a, b;
  const double corners[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
  for (int k = 0; k < 4; ++k) a.xy[2 * k] = center[0] + radius * corners[2 * k], a.xy[2 * k + 1] = center[1] + radius * corners[2 * k + 1];
  a.n = 4;
  for (int i = 0; i < count; ++i) {
    const double ex = bases[i].v[0] - bases[i].u[0], ey = bases[i].v[1] - bases[i].u[1];
    const double len = length(ex, ey);
    if (!(len > 0)) return false;  // a degenerate edge makes a degenerate triangle
    const double dx = ex / len, dy = ey / len, slack = kMargin * len;
    // At u: uv turned counter-clockwise by theta; at v: uv turned clockwise by theta.
    if (!clipLeft(a, bases[i].u[0], bases[i].u[1], c * dx - s * dy, s * dx + c * dy, slack, b) ||
        !clipLeft(b, bases[i].v[0], bases[i].v[1], c * dx + s * dy, c * dy - s * dx, slack, a))
      return true;  // cannot tell: leave it to the search
    if (a.n == 0) return false;
  }
  for (int i = 0; i < count; ++i) {
    apexDisk(bases[i], cotTheta, cscTheta, center, radius);
    if (distanceTo(a, center) > radius * (1 + kMargin)) return false;
  }
  // The mean of the polygon's vertices lies inside it (it is convex), away from its sides: where
  // every disk reaches that deep, it is a point that meets the bound.
  if (candidate && a.n > 0) {
    double sx = 0, sy = 0;
    for (int k = 0; k < a.n; ++k) sx += a.xy[2 * k], sy += a.xy[2 * k + 1];
    candidate[0] = sx / a.n, candidate[1] = sy / a.n;
  }
  return true;
}

}  // namespace ruppert::detail
