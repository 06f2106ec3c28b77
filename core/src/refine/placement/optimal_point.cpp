#include "refine/placement/optimal_point.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "refine/placement/refine_geometry.h"

namespace ruppert::detail {

namespace {

// A pseudo-angle: a strictly increasing function of the angle from a to b (signed, in (-pi, pi]),
// computed from dot = |a||b| cos and cross = |a||b| sin without trigonometry, in [-2, 2]. The search
// only compares smallest angles, and min commutes with an increasing function, so it can compare
// these instead (several times cheaper than atan2).
double pseudoAngle(double dot, double cross) {
  const double s = std::fabs(cross), d = std::fabs(dot) + s;
  if (!(d > 0)) return -2;  // a zero vector: a degenerate triangle, worst of all
  const double upper = dot >= 0 ? s / d : 1 + (-dot) / d;
  return cross >= 0 ? upper : -upper;
}

double pseudoOf(double angle) { return pseudoAngle(std::cos(angle), std::sin(angle)); }

// How good the triangle (u, v, x) is, as the search sees it: left of u->v, its smallest angle as a
// pseudo-angle (apex receives the one at x); on or right of the line, minus x's distance from it in
// units of |uv|. Both parts have convex superlevel sets (the region R_a of the header for a >= 0, a
// half-plane below 0) and meet at 0 on the line, so the minimum over edges stays quasi-concave
// outside the feasible region too and the search climbs towards it from anywhere. (Signed angles
// would not: the set of directions from u within 90 degrees below uv and above it spans 270 degrees.)
double triangleTerm(const double* u, const double* v, const double* x, double& apex) {
  const double uvx = v[0] - u[0], uvy = v[1] - u[1];
  const double uxx = x[0] - u[0], uxy = x[1] - u[1];
  const double height = uvx * uxy - uvy * uxx;  // |uv| times x's distance, positive on the left
  apex = 0;
  if (!(height > 0)) return height / (uvx * uvx + uvy * uvy);
  const double vxx = x[0] - v[0], vxy = x[1] - v[1];
  const double atU = pseudoAngle(uvx * uxx + uvy * uxy, height);
  // At v: from v->x to v->u (= -uv); at x: from x->u to x->v.
  const double atV = pseudoAngle(-(vxx * uvx + vxy * uvy), uvx * vxy - uvy * vxx);
  apex = pseudoAngle(uxx * vxx + uxy * vxy, uxx * vxy - uxy * vxx);
  return std::min({atU, atV, apex});
}

// What the search maximises: the smallest pseudo-angle, or, for a point that encroaches a constrained
// edge, a value below every non-encroaching point's that grows as the excess apex angle shrinks.
//
// The search only asks whether a point beats the best so far, so a point is given up on as soon as
// one term shows it cannot: past a threshold t >= -10, a term <= t makes the score <= t (a
// non-encroaching point scores its smallest term; an encroaching one below -10). Terms are tried
// starting from the one that was smallest last time (neighboring points share their worst edge),
// which rules most losers out after one term. The answers, and so the points found, are the same
// as scoring every term (this cut the placement's refinement time by about half).
struct Scorer {
  const OptimalPointQuery& q;
  double maxApexPseudo;
  mutable std::size_t first = 0;  // the term that was smallest last time: 0 = the petal, i + 1 = edge i

  double term(std::size_t k, const double* x, double& apex, bool& constrained) const {
    if (k == 0) {
      constrained = false;
      return q.petal ? triangleTerm(q.p, q.q, x, apex) : (apex = 0, HUGE_VAL);
    }
    const CavityEdge& e = q.edges[k - 1];
    constrained = e.constrained;
    return triangleTerm(e.u, e.v, x, apex);
  }

  // The score of x, or any value <= beat when x's score is <= beat (beat = -HUGE_VAL: exact).
  double operator()(const double* x, double beat = -HUGE_VAL) const {
    const std::size_t n = q.edgeCount + 1;
    const bool prune = beat >= -10;
    double worst = HUGE_VAL, excess = 0;
    std::size_t worstAt = first;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = first + i < n ? first + i : first + i - n;  // (first + i) mod n, no division
      double apex = 0;
      bool constrained = false;
      const double t = term(k, x, apex, constrained);
      if (t < worst) worst = t, worstAt = k;
      if (constrained && apex >= maxApexPseudo) excess = std::max(excess, apex - maxApexPseudo + 1e-300);
      if (prune && worst <= beat) {
        first = worstAt;
        return worst;
      }
    }
    first = worstAt;
    return excess > 0 ? -10 - excess : worst;
  }
};

// Seeds of the search besides the caller's: points of pq's petal on circles through p and q from which
// pq is seen at 60, 45, 35 and 28 degrees, on the bisector and to either side (all with base angles of
// at least a third of what is left), to the left of p->q.
int petalSeeds(const double* p, const double* q, double* out) {
  static constexpr double kApex[] = {kPi / 3, kPi / 4, 35 * kPi / 180, 28 * kPi / 180};
  const double len = length(q[0] - p[0], q[1] - p[1]);
  const double dx = (q[0] - p[0]) / len, dy = (q[1] - p[1]) / len;
  const double mx = (p[0] + q[0]) / 2, my = (p[1] + q[1]) / 2;
  int n = 0;
  for (double alpha : kApex) {
    const double radius = len / (2 * std::sin(alpha)), center = len / (2 * std::tan(alpha));
    const double spread = (kPi - alpha) / 3;
    for (double phi : {0.0, spread, -spread}) {
      const double along = radius * std::sin(phi), across = center + radius * std::cos(phi);
      out[2 * n] = mx + along * dx - across * dy;
      out[2 * n + 1] = my + along * dy + across * dx;
      ++n;
    }
  }
  return n;
}

// The angles at u and at v of the triangle (u, v, x), signed (negative when x is right of u->v),
// and the one at x: the terms of evaluateSteinerPoint's exact minimum.
struct ExactCorners {
  double atU, atV, atX;
};
ExactCorners exactCorners(const double* u, const double* v, const double* x) {
  const double a[2] = {v[0] - u[0], v[1] - u[1]}, b[2] = {x[0] - u[0], x[1] - u[1]};
  const double c[2] = {x[0] - v[0], x[1] - v[1]};
  const double atU = std::atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]);
  const double atV = std::atan2(a[0] * c[1] - a[1] * c[0], -(a[0] * c[0] + a[1] * c[1]));
  // The angles sum to pi for a counter-clockwise triangle; clockwise ones are negative anyway.
  return {atU, atV, atU > 0 && atV > 0 ? kPi - atU - atV : std::min(atU, atV)};
}

}  // namespace

// Which corner is the smallest is decided on pseudo-angles, and only that corner's angle is then
// computed with atan2: two atan2 calls per edge are a visible share of a whole mesh's time. The
// value is the exact minimum's unless two corners differ by rounding only.
// Constrained edges, which decide encroachment at the encroachment angle, keep exact angles.
OptimalPoint evaluateSteinerPoint(const OptimalPointQuery& query, const double* x) {
  OptimalPoint r{{x[0], x[1]}, HUGE_VAL, false};
  double least = HUGE_VAL;
  const double* leastU = nullptr;
  const double* leastV = nullptr;
  int leastCorner = 0;  // 0: at u, 1: at v, 2: at x
  auto update = [&](const double* u, const double* v, bool constrained) {
    if (constrained) {
      const ExactCorners e = exactCorners(u, v, x);
      if (e.atU > 0 && e.atV > 0 && e.atX >= query.maxApex) r.encroaches = true;
    }
    const double ax = v[0] - u[0], ay = v[1] - u[1], bx = x[0] - u[0], by = x[1] - u[1];
    const double cx = x[0] - v[0], cy = x[1] - v[1];
    const double atU = pseudoAngle(ax * bx + ay * by, ax * by - ay * bx);
    const double atV = pseudoAngle(-(ax * cx + ay * cy), ax * cy - ay * cx);
    const double atX = atU > 0 && atV > 0 ? pseudoAngle(bx * cx + by * cy, bx * cy - by * cx) : HUGE_VAL;
    const double corners[3] = {atU, atV, atX};
    for (int k = 0; k < 3; ++k)
      if (corners[k] < least) least = corners[k], leastU = u, leastV = v, leastCorner = k;
  };
  if (query.petal) update(query.p, query.q, false);
  for (std::size_t i = 0; i < query.edgeCount; ++i)
    update(query.edges[i].u, query.edges[i].v, query.edges[i].constrained);
  if (leastU) {
    const ExactCorners e = exactCorners(leastU, leastV, x);
    r.minAngle = leastCorner == 0 ? e.atU : leastCorner == 1 ? e.atV : e.atX;
  }
  return r;
}

// Compass search: from the best seed, try steps in eight directions (turned by 22.5 degrees at every
// other level, so that a ridge between two active angles is not missed by a fixed lattice), move to
// the best improvement, halve the step when none improves. The step starts at a fifth of |pq| and
// stops below 1e-3 |pq| (angles then change by about 1e-3 radians, 0.06 degrees), or after 160
// evaluations: most searches end in a decline, and their cost is most of this placement's.
OptimalPoint optimalSteinerPoint(const OptimalPointQuery& query, const double* seeds, std::size_t seedCount) {
  static const auto kDirections = [] {
    std::array<double, 32> d{};
    for (int k = 0; k < 16; ++k) d[2 * k] = std::cos(k * kPi / 8), d[2 * k + 1] = std::sin(k * kPi / 8);
    return d;
  }();
  const Scorer score{query, pseudoOf(query.maxApex)};
  double own[2 * 12];
  const int ownCount = petalSeeds(query.p, query.q, own);
  double best[2] = {own[0], own[1]};
  double bestScore = score(best);
  auto consider = [&](const double* x) {
    const double s = score(x, bestScore);
    if (s > bestScore) bestScore = s, best[0] = x[0], best[1] = x[1];
  };
  for (int i = 1; i < ownCount; ++i) consider(own + 2 * i);
  for (std::size_t i = 0; i < seedCount; ++i) consider(seeds + 2 * i);
  const double len = length(query.q[0] - query.p[0], query.q[1] - query.p[1]);
  double step = 0.2 * len;
  int level = 0, evaluations = 0;
  // A non-encroaching point's score is its smallest pseudo-angle, so beating `enough` is meeting it.
  const double enough = std::isfinite(query.goodEnough) ? pseudoOf(query.goodEnough) : HUGE_VAL;
  while (step > 1e-3 * len && evaluations < 160 && !(bestScore > enough)) {
    double move[2] = {best[0], best[1]};
    double moveScore = bestScore;
    for (int k = level & 1; k < 16; k += 2) {  // the odd directions at odd levels
      const double x[2] = {best[0] + step * kDirections[2 * k], best[1] + step * kDirections[2 * k + 1]};
      const double s = score(x, moveScore);
      ++evaluations;
      if (s > moveScore) moveScore = s, move[0] = x[0], move[1] = x[1];
    }
    if (moveScore > bestScore) {
      bestScore = moveScore, best[0] = move[0], best[1] = move[1];
    } else {
      step /= 2;
      ++level;
    }
  }
  return evaluateSteinerPoint(query, best);
}

}  // namespace ruppert::detail
