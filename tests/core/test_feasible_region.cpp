// The screen before the optimal-point search (feasible_region.h): a "no" must be certain, so it is
// checked against a brute-force grid on many irregular cavities, at several bounds; and it must say
// "no" often enough to be worth running, on cavities where no point meets the bound.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "refine/placement/feasible_region.h"

namespace {

using ruppert::detail::BoundAngle;
using ruppert::detail::CavityEdge;
using ruppert::detail::evaluateSteinerPoint;
using ruppert::detail::mayMeetBound;
using ruppert::detail::OptimalPointQuery;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180;

// A star-shaped polygon around (0.5, 0.5) whose first edge is (0,0)-(1,0), with n - 2 more vertices
// at random radii and angles: the boundary of a cavity, counter-clockwise.
std::vector<CavityEdge> randomCavity(std::mt19937& rng, int n, double spread) {
  std::uniform_real_distribution<double> jitter(-1, 1);
  std::vector<double> xy = {0, 0, 1, 0};
  for (int k = 1; k <= n - 2; ++k) {
    const double a = -0.25 * kPi + k * 1.5 * kPi / (n - 1) + 0.2 * jitter(rng) / n;
    const double radius = 0.75 * (1 + spread * jitter(rng));
    xy.push_back(0.5 + radius * std::cos(a)), xy.push_back(0.5 + radius * std::sin(a));
  }
  std::vector<CavityEdge> edges;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    edges.push_back({{xy[2 * i], xy[2 * i + 1]}, {xy[2 * j], xy[2 * j + 1]}, false});
  }
  return edges;
}

// Whether some point of a grid over the cavity's box gives every triangle all angles > theta.
bool gridMeets(const OptimalPointQuery& query, double theta) {
  for (double x = -1.0; x <= 2.0; x += 0.01)
    for (double y = -1.0; y <= 2.0; y += 0.01) {
      const double pt[2] = {x, y};
      if (evaluateSteinerPoint(query, pt).minAngle > theta) return true;
    }
  return false;
}

}  // namespace

TEST_CASE("feasible region: a no is never wrong, and comes on most cavities where the grid finds nothing", "[optimal]") {
  std::mt19937 rng(20261202);
  const double p[2] = {0, 0}, q[2] = {1, 0};
  int grids = 0, screened = 0, infeasible = 0;
  for (int trial = 0; trial < 240; ++trial) {
    const auto edges = randomCavity(rng, 4 + trial % 6, 0.15 + 0.1 * (trial % 5));
    const double theta = (25 + 5 * (trial % 4)) * kDeg;
    for (bool petal : {true, false}) {
      OptimalPointQuery query;
      query.p = p, query.q = q, query.edges = edges.data(), query.edgeCount = edges.size();
      query.maxApex = kPi, query.petal = petal;
      const bool may = mayMeetBound(query, BoundAngle(theta));
      const bool meets = gridMeets(query, theta);
      INFO("trial " << trial << (petal ? " with" : " without") << " the petal at " << theta / kDeg << " degrees");
      if (meets) CHECK(may);  // the certain part
      ++grids;
      if (!meets) ++infeasible;
      if (!may) ++screened;
    }
  }
  INFO(grids << " cavities, " << infeasible << " with no grid point meeting the bound, " << screened << " screened out");
  CHECK(infeasible >= 40);               // the sample holds both kinds
  CHECK(screened >= infeasible * 7 / 10);
}

TEST_CASE("feasible region: a regular hexagon meets 59 degrees, and a needle's cavity not 30", "[optimal]") {
  std::vector<CavityEdge> hex;
  for (int k = 0; k < 6; ++k)
    hex.push_back({{std::cos(k * kPi / 3), std::sin(k * kPi / 3)}, {std::cos((k + 1) * kPi / 3), std::sin((k + 1) * kPi / 3)}, false});
  OptimalPointQuery query;
  query.p = hex[0].u, query.q = hex[0].v, query.edges = hex.data(), query.edgeCount = hex.size(), query.maxApex = kPi;
  CHECK(mayMeetBound(query, BoundAngle(59.9 * kDeg)));
  // A cavity with an edge a hundred times the petal edge: its triangle with any point near p-q is flat.
  const std::vector<CavityEdge> needle = {{{0, 0}, {1, 0}, false}, {{1, 0}, {50, 1}, false}, {{50, 1}, {0, 0}, false}};
  const double p[2] = {0, 0}, q[2] = {1, 0};
  query.p = p, query.q = q, query.edges = needle.data(), query.edgeCount = needle.size();
  CHECK_FALSE(mayMeetBound(query, BoundAngle(30 * kDeg)));
}

TEST_CASE("feasible region: the largest stars fit, and beyond the cap the answer is left to the search", "[optimal]") {
  // Around any point inside a regular n-gon the apex angles sum to 360 degrees, so with 64 edges
  // one of them is under 6: no point meets 30 degrees.
  for (int n : {64, 65}) {
    std::vector<CavityEdge> ring;
    for (int k = 0; k < n; ++k)
      ring.push_back({{std::cos(2 * kPi * k / n), std::sin(2 * kPi * k / n)},
                      {std::cos(2 * kPi * (k + 1) / n), std::sin(2 * kPi * (k + 1) / n)}, false});
    OptimalPointQuery query;
    query.p = ring[0].u, query.q = ring[0].v, query.edges = ring.data(), query.edgeCount = ring.size();
    query.maxApex = kPi, query.petal = false;
    INFO(n << " edges");
    CHECK(mayMeetBound(query, BoundAngle(30 * kDeg)) == (n > 64));
  }
}

// Triangle (u, v, x)'s angles at u and at v, in radians (negative when x is right of u->v).
double baseAngle(const double* u, const double* v, const double* x) {
  const double ex = v[0] - u[0], ey = v[1] - u[1], fx = x[0] - u[0], fy = x[1] - u[1];
  return std::atan2(ex * fy - ey * fx, ex * fx + ey * fy);
}

TEST_CASE("feasible region: the candidate lies in every half-plane, and meets the bound on most feasible cavities", "[optimal]") {
  std::mt19937 rng(20261203);
  const double p[2] = {0, 0}, q[2] = {1, 0};
  int feasible = 0, candidates = 0, meeting = 0;
  for (int trial = 0; trial < 160; ++trial) {
    const auto edges = randomCavity(rng, 4 + trial % 6, 0.15 + 0.1 * (trial % 5));
    const double theta = (25 + 5 * (trial % 4)) * kDeg;
    OptimalPointQuery query;
    query.p = p, query.q = q, query.edges = edges.data(), query.edgeCount = edges.size(), query.maxApex = kPi;
    double candidate[2];
    const bool may = mayMeetBound(query, BoundAngle(theta), candidate);
    INFO("trial " << trial << " at " << theta / kDeg << " degrees");
    if (!may) CHECK(std::isnan(candidate[0]));
    if (!gridMeets(query, theta)) continue;
    ++feasible;
    if (std::isnan(candidate[0])) continue;
    ++candidates;
    // Left of the rays at theta from both ends of the petal edge and of every cavity edge.
    CHECK(baseAngle(p, q, candidate) >= theta - 1e-9);
    CHECK(-baseAngle(q, p, candidate) >= theta - 1e-9);
    for (const CavityEdge& e : edges) {
      CHECK(baseAngle(e.u, e.v, candidate) >= theta - 1e-9);
      CHECK(-baseAngle(e.v, e.u, candidate) >= theta - 1e-9);
    }
    if (evaluateSteinerPoint(query, candidate).minAngle > theta) ++meeting;
  }
  INFO(feasible << " feasible cavities, " << candidates << " candidates, " << meeting << " meeting the bound");
  CHECK(feasible >= 30);
  CHECK(candidates == feasible);  // the screen says yes on every feasible cavity, with its polygon
  CHECK(meeting * 2 >= feasible);
}

TEST_CASE("feasible region: a search told what is good enough stops past it, on the same path", "[optimal]") {
  std::mt19937 rng(20261204);
  const double p[2] = {0, 0}, q[2] = {1, 0};
  int passed = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const auto edges = randomCavity(rng, 4 + trial % 6, 0.15 + 0.1 * (trial % 5));
    const double theta = (25 + 5 * (trial % 4)) * kDeg;
    OptimalPointQuery query;
    query.p = p, query.q = q, query.edges = edges.data(), query.edgeCount = edges.size(), query.maxApex = kPi;
    const double seed[2] = {0.5, 0.3};
    const auto best = ruppert::detail::optimalSteinerPoint(query, seed, 1);
    query.goodEnough = theta;
    const auto early = ruppert::detail::optimalSteinerPoint(query, seed, 1);
    INFO("trial " << trial << ": maximised " << best.minAngle / kDeg << ", early " << early.minAngle / kDeg);
    CHECK(early.minAngle <= best.minAngle + 1e-12);
    if (best.minAngle > theta) {
      ++passed;
      CHECK(early.minAngle > theta);
    }
  }
  CHECK(passed >= 30);
}

TEST_CASE("feasible region: a corner narrower than twice the bound rules a cavity out, in any edge order", "[optimal]") {
  // A kite around the petal edge (0,0)-(1,0) whose top corner opens at `top` degrees: a point inside
  // splits that corner between two triangles, so below 2 theta one of them is under theta.
  auto kite = [](double top) {
    const double half = top / 2 * kDeg, h = 1.2;  // the top at (0.5, h), the sides reaching out
    const double w = h * std::tan(half) * 0.9;
    const std::vector<double> xy = {0, 0, 1, 0, 0.5 + w, h * 0.1, 0.5, h, 0.5 - w, h * 0.1};
    std::vector<CavityEdge> edges;
    for (int i = 0; i < 5; ++i) {
      const int j = (i + 1) % 5;
      edges.push_back({{xy[2 * i], xy[2 * i + 1]}, {xy[2 * j], xy[2 * j + 1]}, false});
    }
    return edges;
  };
  const double p[2] = {0, 0}, q[2] = {1, 0};
  for (double top : {40.0, 49.0, 51.0, 70.0, 100.0}) {
    auto edges = kite(top);
    OptimalPointQuery query;
    query.p = p, query.q = q, query.edges = edges.data(), query.edgeCount = edges.size(), query.maxApex = kPi;
    const double theta = 25 * kDeg;
    const bool may = mayMeetBound(query, BoundAngle(theta));
    INFO("top corner " << top << " degrees");
    if (top < 50) CHECK_FALSE(may);
    if (gridMeets(query, theta)) CHECK(may);
    // The cavity's edges come in no particular order (a breadth-first search finds them): reversed
    // and rotated, the answer is the same.
    std::reverse(edges.begin(), edges.end());
    std::rotate(edges.begin(), edges.begin() + 2, edges.end());
    query.edges = edges.data();
    CHECK(mayMeetBound(query, BoundAngle(theta)) == may);
  }
}
