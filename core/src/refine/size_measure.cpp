// The chapter's size measure (§6.5): the number of triangles of a size-optimal mesh is within constant
// factors of the integral of 1/lfs(x)^2 over the domain, lfs being the local feature size (Def. 6.2:
// the radius of the smallest disk centered at x that meets two disjoint features of the PLC).
//
// lfs is computed from the input alone, at every mesh vertex: with the features (distinct input
// points, input segments) taken in order of distance from x, lfs(x) is the distance of the first
// feature that is disjoint from an earlier one. A uniform grid over the features gives them nearest
// first. The integral is then the sum over triangles of area / (mean lfs of its vertices)^2, a
// quadrature whose points come from the mesh but whose integrand does not.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "mesh/predicates.h"
#include "refine/refine.h"
#include "cold_code.h"

// The size measure, asked for with the statistics: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

namespace ruppert::detail {
namespace {

struct Feature {
  std::uint32_t a, b;  // internal vertices of input points; a == b for a point
};

class FeatureGrid {
 public:
  FeatureGrid(const MeshState& m) : xy_(m.tri.xy) {
    const Plc& plc = *m.plc;
    for (std::uint32_t v = 0; v < m.inputCount; ++v) features_.push_back({v, v});
    std::vector<std::uint64_t> seen;
    for (std::size_t s = 0; s < plc.segments.size() / 2; ++s) {
      std::uint32_t a = m.segmentEnd(s, 0), b = m.segmentEnd(s, 1);
      if (a == b) continue;
      if (a > b) std::swap(a, b);
      seen.push_back(std::uint64_t(a) << 32 | b);
    }
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    for (std::uint64_t k : seen) features_.push_back({std::uint32_t(k >> 32), std::uint32_t(k)});

    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
    for (std::uint32_t v = 0; v < m.inputCount; ++v)
      for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], xy_[2 * v + k]), hi[k] = std::max(hi[k], xy_[2 * v + k]);
    origin_[0] = lo[0], origin_[1] = lo[1];
    const double span = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-300});
    side_ = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::sqrt(double(features_.size()))));
    cell_ = span / side_ * (1 + 1e-9);
    cells_.assign(std::size_t(side_) * side_, {});
    stamp_.assign(features_.size(), 0);
    for (std::uint32_t f = 0; f < features_.size(); ++f) {
      const double* p = pt(features_[f].a);
      const double* q = pt(features_[f].b);
      const std::uint32_t x0 = clampCell(std::min(p[0], q[0]) - origin_[0]), x1 = clampCell(std::max(p[0], q[0]) - origin_[0]);
      const std::uint32_t y0 = clampCell(std::min(p[1], q[1]) - origin_[1]), y1 = clampCell(std::max(p[1], q[1]) - origin_[1]);
      for (std::uint32_t y = y0; y <= y1; ++y)
        for (std::uint32_t x = x0; x <= x1; ++x) cells_[std::size_t(y) * side_ + x].push_back(f);
    }
  }

  // lfs at point c (internal coordinates): grow square rings of cells around c; after ring r every
  // feature not yet seen is at least r cells away, so the candidates closer than that are final and
  // can be examined in order of distance.
  double lfs(const double* c) {
    ++query_;
    const std::int64_t cx = std::clamp<std::int64_t>(std::int64_t(std::floor((c[0] - origin_[0]) / cell_)), 0, side_ - 1);
    const std::int64_t cy = std::clamp<std::int64_t>(std::int64_t(std::floor((c[1] - origin_[1]) / cell_)), 0, side_ - 1);
    const double outside = std::max({origin_[0] - c[0], c[0] - (origin_[0] + side_ * cell_),
                                     origin_[1] - c[1], c[1] - (origin_[1] + side_ * cell_), 0.0});
    pending_.clear();
    done_.clear();
    auto visitCell = [&](std::int64_t x, std::int64_t y) {
      if (x < 0 || y < 0 || x >= side_ || y >= side_) return;
      for (std::uint32_t f : cells_[std::size_t(y) * side_ + x]) {
        if (stamp_[f] == query_) continue;
        stamp_[f] = query_;
        pending_.push_back({~bitsOf(distance(c, features_[f])), ~f});
      }
    };
    for (std::int64_t r = 0; r <= side_; ++r) {
      if (r == 0) {
        visitCell(cx, cy);
      } else {
        for (std::int64_t k = -r; k <= r; ++k) {
          visitCell(cx + k, cy - r), visitCell(cx + k, cy + r);
          if (k != -r && k != r) visitCell(cx - r, cy + k), visitCell(cx + r, cy + k);
        }
      }
      const double covered = r == side_ ? HUGE_VAL : outside + r * cell_;
      std::sort(pending_.begin(), pending_.end());  // nearest at the back
      while (!pending_.empty() && distanceOf(pending_.back()) <= covered) {
        const double d = distanceOf(pending_.back());
        const std::uint32_t f = ~pending_.back().second;
        pending_.pop_back();
        for (std::uint32_t earlier : done_)
          if (disjoint(features_[earlier], features_[f])) return d;
        done_.push_back(f);
      }
    }
    return HUGE_VAL;  // fewer than two disjoint features exist
  }

 private:
  const std::vector<double>& xy_;
  std::vector<Feature> features_;
  std::vector<std::vector<std::uint32_t>> cells_;
  // Per feature met: (~ the bits of its distance, ~ its index). A nonnegative double's bits order
  // as it does, so sorting these puts the farthest first and the nearest (lowest index first among
  // equals) at the back; the pair sort is the one the triangulation's edge keys instantiate.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> pending_;
  static std::uint64_t bitsOf(double distance) {
    std::uint64_t bits;
    std::memcpy(&bits, &distance, sizeof bits);
    return bits;
  }
  static double distanceOf(const std::pair<std::uint64_t, std::uint32_t>& item) {
    const std::uint64_t bits = ~item.first;
    double distance;
    std::memcpy(&distance, &bits, sizeof distance);
    return distance;
  }
  std::vector<std::uint32_t> done_, stamp_;
  std::uint32_t query_ = 0;
  double origin_[2] = {0, 0}, cell_ = 1;
  std::uint32_t side_ = 1;

  const double* pt(std::uint32_t v) const { return &xy_[2 * v]; }
  std::uint32_t clampCell(double offset) const {
    return static_cast<std::uint32_t>(std::clamp(offset / cell_, 0.0, double(side_ - 1)));
  }
  double distance(const double* c, const Feature& f) const {
    const double* a = pt(f.a);
    const double* b = pt(f.b);
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((c[0] - a[0]) * dx + (c[1] - a[1]) * dy) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(a[0] + t * dx - c[0], a[1] + t * dy - c[1]);
  }
  // Closed point / segment containment and segment intersection, with exact orientation.
  bool onSegment(std::uint32_t p, const Feature& s) const {
    if (p == s.a || p == s.b) return true;
    if (s.a == s.b || orient2d(pt(s.a), pt(s.b), pt(p)) != 0) return false;
    const double* a = pt(s.a);
    const double* b = pt(s.b);
    const double* q = pt(p);
    return (q[0] - a[0]) * (q[0] - b[0]) <= 0 && (q[1] - a[1]) * (q[1] - b[1]) <= 0;
  }
  bool disjoint(const Feature& f, const Feature& g) const {
    const bool fp = f.a == f.b, gp = g.a == g.b;
    if (fp && gp) return f.a != g.a;
    if (fp) return !onSegment(f.a, g);
    if (gp) return !onSegment(g.a, f);
    if (onSegment(f.a, g) || onSegment(f.b, g) || onSegment(g.a, f) || onSegment(g.b, f)) return false;
    const double o1 = orient2d(pt(f.a), pt(f.b), pt(g.a)), o2 = orient2d(pt(f.a), pt(f.b), pt(g.b));
    const double o3 = orient2d(pt(g.a), pt(g.b), pt(f.a)), o4 = orient2d(pt(g.a), pt(g.b), pt(f.b));
    return !((o1 > 0) != (o2 > 0) && (o3 > 0) != (o4 > 0));
  }
};

// area / (mean lfs of the corners)^2 is a fair quadrature only where the triangle is small beside
// lfs; a triangle longer than half its corners' smallest lfs (a coarse mesh, before refinement has
// reached the features) that is worth over a unit is cut in four at its edges' midpoints, up to
// `depth` times. Without this, long triangles of an early mesh whose corners sit near features
// counted a tiny lfs over their whole area: 40 times the integral of the refined mesh.
constexpr int kSubdivisions = 6;

double subdividedIntegral(FeatureGrid& grid, const double* const p[3], const double f[3], int depth) {
  double longest2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double dx = p[i][0] - p[(i + 1) % 3][0], dy = p[i][1] - p[(i + 1) % 3][1];
    longest2 = std::max(longest2, dx * dx + dy * dy);
  }
  const double least = std::min({f[0], f[1], f[2]});
  const double mean = (f[0] + f[1] + f[2]) / 3;
  const double area =
      0.5 * std::fabs((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]));
  const double estimate = mean > 0 && mean < HUGE_VAL ? area / (mean * mean) : 0;
  // A piece worth under a unit is kept as it is: the cuts are for the few large triangles whose
  // estimate could be far off, not for the slivers of a dense mesh (bounded work).
  if (depth == 0 || !(4 * longest2 > least * least) || !(estimate > 1)) return estimate;
  double mid[3][2], fm[3];
  for (int i = 0; i < 3; ++i) {
    const double* a = p[(i + 1) % 3];
    const double* b = p[(i + 2) % 3];
    mid[i][0] = 0.5 * (a[0] + b[0]), mid[i][1] = 0.5 * (a[1] + b[1]);  // opposite corner i
    fm[i] = grid.lfs(mid[i]);
  }
  double sum = 0;
  for (int i = 0; i < 3; ++i) {  // the corner triangles: corner i and the midpoints beside it
    const double* q[3] = {p[i], mid[(i + 2) % 3], mid[(i + 1) % 3]};
    const double g[3] = {f[i], fm[(i + 2) % 3], fm[(i + 1) % 3]};
    sum += subdividedIntegral(grid, q, g, depth - 1);
  }
  const double* q[3] = {mid[0], mid[1], mid[2]};
  return sum + subdividedIntegral(grid, q, fm, depth - 1);
}

}  // namespace

double estimateLfsIntegral(const MeshState& m, double reuseBelow) {
  const Triangulation& t = m.tri;
  FeatureGrid grid(m);
  // Per vertex: lfs, queried or passed on from a neighbor's, and how far it may be off (the length
  // of the edges it was passed along: lfs is 1-Lipschitz).
  std::vector<double> lfs(t.vertexCount(), -1), slack(t.vertexCount(), 0);
  double integral = 0;
  for (std::uint32_t s = 0; s < t.slotCount(); ++s) {
    if (!t.alive(s)) continue;
    const double* p[3] = {t.pt(t.tv[3 * s]), t.pt(t.tv[3 * s + 1]), t.pt(t.tv[3 * s + 2])};
    double longest = 0;
    for (int i = 0; i < 3; ++i)
      longest = std::max(longest, std::hypot(p[i][0] - p[(i + 1) % 3][0], p[i][1] - p[(i + 1) % 3][1]));
    // A corner's value passes to the others (no costlier grid query) while the distance it has
    // come stays under reuseBelow times it: their lfs then differ from it by less than that fraction.
    int from = -1;
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = t.tv[3 * s + i];
      if (lfs[v] > 0 && slack[v] + longest < reuseBelow * lfs[v] && (from < 0 || slack[v] < slack[t.tv[3 * s + from]]))
        from = i;
    }
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = t.tv[3 * s + i];
      if (lfs[v] >= 0) continue;
      if (from >= 0) {
        const std::uint32_t u = t.tv[3 * s + from];
        lfs[v] = lfs[u], slack[v] = slack[u] + longest;
      } else {
        lfs[v] = grid.lfs(t.pt(v));
      }
    }
    const double f[3] = {lfs[t.tv[3 * s]], lfs[t.tv[3 * s + 1]], lfs[t.tv[3 * s + 2]]};
    integral += subdividedIntegral(grid, p, f, kSubdivisions);
  }
  return integral;
}

}  // namespace ruppert::detail

RUPPERT_COLD_END
