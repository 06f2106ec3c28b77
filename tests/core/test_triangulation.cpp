// The two ways Triangulation inserts a vertex: Bowyer-Watson (insertVertex, the usual one) and
// splitting plus Lawson flips (insertVertexByFlips, the fallback where a cavity would wrap around a
// vertex at which the domain touches itself). Meshes rarely take the fallback, so it is tested here
// directly: on points in general position the Delaunay triangulation is unique, so both must build
// the same triangles, and every edge must end locally Delaunay.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <vector>

#include "mesh/predicates.h"
#include "mesh/triangulation.h"

namespace {

using ruppert::detail::incircle;
using ruppert::detail::kNone;
using ruppert::detail::Location;
using ruppert::detail::Triangulation;

// A big counter-clockwise triangle around [0, 1]^2, then the points inserted one way or the other.
Triangulation build(const std::vector<std::array<double, 2>>& points, bool byFlips) {
  Triangulation t;
  t.addVertex(-10, -10), t.addVertex(10, -10), t.addVertex(0, 10);
  t.newTriangle(0, 1, 2);
  std::uint32_t hint = 0;
  for (const auto& p : points) {
    const std::uint32_t v = t.addVertex(p[0], p[1]);
    const Location loc = t.locate(t.pt(v), hint);
    REQUIRE((loc.kind == Location::InTriangle || loc.kind == Location::OnEdge));
    REQUIRE((byFlips ? t.insertVertexByFlips(v, loc) : t.insertVertex(v, loc)));
    hint = t.vtri[v];
  }
  return t;
}

std::set<std::array<std::uint32_t, 3>> triangles(const Triangulation& t) {
  std::set<std::array<std::uint32_t, 3>> out;
  for (std::uint32_t s = 0; s < t.slotCount(); ++s) {
    if (!t.alive(s)) continue;
    std::array<std::uint32_t, 3> v{t.tv[3 * s], t.tv[3 * s + 1], t.tv[3 * s + 2]};
    std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());  // same orientation kept
    out.insert(v);
  }
  return out;
}

int nonDelaunayEdges(const Triangulation& t) {
  int bad = 0;
  for (std::uint32_t h = 0; h < 3 * t.slotCount(); ++h) {
    const std::uint32_t s = h / 3, g = t.twin[h];
    if (!t.alive(s) || g == kNone) continue;
    if (incircle(t.pt(t.tv[3 * s]), t.pt(t.tv[3 * s + 1]), t.pt(t.tv[3 * s + 2]), t.pt(t.apex(g))) > 0) ++bad;
  }
  return bad;
}

}  // namespace

TEST_CASE("insertion by flips builds the Delaunay triangulation Bowyer-Watson builds", "[triangulation]") {
  std::mt19937_64 rng(8128);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n : {1, 2, 10, 100, 2000}) {
    std::vector<std::array<double, 2>> points(n);
    for (auto& p : points) p = {unit(rng), unit(rng)};
    const Triangulation cavities = build(points, false), flips = build(points, true);
    INFO(n << " points");
    CHECK(nonDelaunayEdges(flips) == 0);
    CHECK(nonDelaunayEdges(cavities) == 0);
    CHECK(triangles(flips) == triangles(cavities));
    CHECK(triangles(flips).size() == static_cast<std::size_t>(2 * n + 1));
  }
}

TEST_CASE("insertion by flips on a grid (cocircular points, points on edges) stays Delaunay", "[triangulation]") {
  // Ties make the triangulation not unique, so only the property is checked; grid points land on
  // existing edges too (OnEdge insertion).
  std::vector<std::array<double, 2>> points;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) points.push_back({i / 20.0, j / 20.0});
  std::shuffle(points.begin(), points.end(), std::mt19937_64(496));
  const Triangulation flips = build(points, true);
  CHECK(nonDelaunayEdges(flips) == 0);
  CHECK(triangles(flips).size() == 2 * points.size() + 1);
}
