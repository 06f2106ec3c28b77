// Random and structured PLC generators (see plc_generators.h).
#include "plc_generators.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "mesh/predicates.h"

namespace ruppert_test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kGridBits = 20;  // coordinates in the unit square are multiples of 2^-20

// Platform-independent draws from mt19937_64 (see header).
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : rng_(seed) {}
  double unit() { return double(rng_() >> 11) * 0x1p-53; }  // [0, 1)
  // A multiple of 2^-20 strictly inside (0, 1).
  double gridCoordinate() {
    const std::uint64_t k = 1 + (rng_() >> (64 - kGridBits)) % ((std::uint64_t(1) << kGridBits) - 1);
    return std::ldexp(double(k), -kGridBits);
  }
  std::uint64_t below(std::uint64_t n) { return rng_() % n; }  // slight bias is irrelevant here

 private:
  std::mt19937_64 rng_;
};

double roundToGrid(double v) { return std::ldexp(std::nearbyint(std::ldexp(v, kGridBits)), -kGridBits); }

void addUnitSquareBoundary(ruppert::Plc& plc) {
  const std::uint32_t base = std::uint32_t(plc.points.size() / 2);
  plc.points.insert(plc.points.end(), {0, 0, 1, 0, 1, 1, 0, 1});
  for (std::uint32_t i = 0; i < 4; ++i) {
    plc.segments.push_back(base + i);
    plc.segments.push_back(base + (i + 1) % 4);
  }
}

const double* pointOf(const ruppert::Plc& plc, std::uint32_t i) { return &plc.points[2 * std::size_t(i)]; }

// Signed area of the closed ring through the given points (shoelace).
double ringArea(const std::vector<double>& xy) {
  const std::size_t n = xy.size() / 2;
  double twice = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    twice += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
  }
  return twice / 2;
}

}  // namespace

void addRing(ruppert::Plc& plc, const std::vector<double>& xy) {
  const std::uint32_t base = std::uint32_t(plc.points.size() / 2), n = std::uint32_t(xy.size() / 2);
  plc.points.insert(plc.points.end(), xy.begin(), xy.end());
  for (std::uint32_t i = 0; i < n; ++i) {
    plc.segments.push_back(base + i);
    plc.segments.push_back(base + (i + 1) % n);
  }
}

bool segmentsTouch(const double* p, const double* q, const double* r, const double* s) {
  using ruppert::detail::orient2d;
  const double o1 = orient2d(p, q, r), o2 = orient2d(p, q, s), o3 = orient2d(r, s, p), o4 = orient2d(r, s, q);
  auto sign = [](double v) { return (v > 0) - (v < 0); };
  if (sign(o1) * sign(o2) < 0 && sign(o3) * sign(o4) < 0) return true;  // proper crossing
  // Collinear triple: touching iff the point lies within the other segment's bounding box.
  auto within = [](const double* a, const double* b, const double* c) {
    return std::min(a[0], b[0]) <= c[0] && c[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= c[1] &&
           c[1] <= std::max(a[1], b[1]);
  };
  return (o1 == 0 && within(p, q, r)) || (o2 == 0 && within(p, q, s)) || (o3 == 0 && within(r, s, p)) ||
         (o4 == 0 && within(r, s, q));
}

GeneratedPlc randomPointsInSquare(std::uint64_t seed, std::size_t n) {
  Draw draw(seed);
  GeneratedPlc g;
  addUnitSquareBoundary(g.plc);
  for (std::size_t i = 0; i < n; ++i) {
    g.plc.points.push_back(draw.gridCoordinate());
    g.plc.points.push_back(draw.gridCoordinate());
  }
  g.area = 1;
  return g;
}

GeneratedPlc randomPointSet(std::uint64_t seed, std::size_t n) {
  Draw draw(seed);
  GeneratedPlc g;
  for (std::size_t i = 0; i < 2 * n; ++i) g.plc.points.push_back(draw.gridCoordinate());
  return g;
}

GeneratedPlc randomStarPolygon(std::uint64_t seed, std::size_t n, std::size_t holes) {
  Draw draw(seed);
  n = std::max<std::size_t>(n, 8);  // the hole placement below relies on n >= 8 (see comment there)
  GeneratedPlc g;
  std::vector<double> ring;
  for (int attempt = 0;; ++attempt) {
    // Stratified angles keep neighboring vertices at least 0.2 * 2 pi / n apart, so rounding to the
    // grid cannot reorder them; the simplicity check below still guards against surprises.
    ring.clear();
    for (std::size_t k = 0; k < n; ++k) {
      const double angle = 2 * kPi * (double(k) + 0.1 + 0.8 * draw.unit()) / double(n);
      const double radius = 0.25 + 0.2 * draw.unit();
      ring.push_back(roundToGrid(0.5 + radius * std::cos(angle)));
      ring.push_back(roundToGrid(0.5 + radius * std::sin(angle)));
    }
    bool simple = true;
    for (std::size_t i = 0; i < n && simple; ++i)
      for (std::size_t j = i + 2; j < n && simple; ++j) {
        if (i == 0 && j == n - 1) continue;  // adjacent through the wrap-around
        simple = !segmentsTouch(&ring[2 * i], &ring[2 * ((i + 1) % n)], &ring[2 * j], &ring[2 * ((j + 1) % n)]);
      }
    if (simple || attempt > 100) break;
  }
  g.plc.points = ring;
  for (std::uint32_t i = 0; i < n; ++i) {
    g.plc.segments.push_back(i);
    g.plc.segments.push_back(std::uint32_t((i + 1) % n));
  }
  g.area = ringArea(ring);

  // Square holes of half-size 2^-6 centered within 0.1 of the center. The polygon contains the disk
  // of radius 0.25 * cos(max angular gap / 2) >= 0.19 for n >= 8, so such holes fit; holes are kept
  // only when they do not touch each other or the boundary.
  const double h = 0x1p-6;
  std::vector<std::pair<double, double>> centers;
  for (std::size_t attempt = 0; attempt < 20 * holes && centers.size() < holes; ++attempt) {
    const double cx = roundToGrid(0.4 + 0.2 * draw.unit()), cy = roundToGrid(0.4 + 0.2 * draw.unit());
    if (std::hypot(cx - 0.5, cy - 0.5) > 0.1) continue;
    bool clear = true;
    for (const auto& c : centers) clear = clear && (std::fabs(c.first - cx) > 2.5 * h || std::fabs(c.second - cy) > 2.5 * h);
    const double square[8] = {cx - h, cy - h, cx + h, cy - h, cx + h, cy + h, cx - h, cy + h};
    for (std::size_t i = 0; i < n && clear; ++i)
      for (int k = 0; k < 4 && clear; ++k)
        clear = !segmentsTouch(&ring[2 * i], &ring[2 * ((i + 1) % n)], &square[2 * k], &square[2 * ((k + 1) % 4)]);
    if (!clear) continue;
    centers.emplace_back(cx, cy);
    const std::uint32_t base = std::uint32_t(g.plc.points.size() / 2);
    g.plc.points.insert(g.plc.points.end(), square, square + 8);
    for (std::uint32_t k = 0; k < 4; ++k) {
      g.plc.segments.push_back(base + k);
      g.plc.segments.push_back(base + (k + 1) % 4);
    }
    g.plc.holes.push_back(cx);
    g.plc.holes.push_back(cy);
    g.area -= 4 * h * h;
  }
  return g;
}

namespace {

// A star-shaped ring of n vertices (n a multiple of 4) around the origin: vertex k in the k-th of
// n equal sectors, so the axes are sector boundaries and the edges across them are known.
std::vector<double> centeredRing(Draw& draw, std::size_t n, double rMin, double rMax) {
  std::vector<double> ring;
  for (std::size_t k = 0; k < n; ++k) {
    // A direction in the quarter of the circle that s (a fraction of the turn) lies in:
    // (1 - t^2, 2t) / (1 + t^2), at angle 2 atan(t) into that quarter, for t in [0, 1).
    const double s = (double(k) + 0.1 + 0.8 * draw.unit()) / double(n);
    const std::size_t quarter = std::size_t(4 * s);
    const double t = 4 * s - double(quarter);
    const double c = (1 - t * t) / (1 + t * t), si = 2 * t / (1 + t * t);
    const double r = rMin + (rMax - rMin) * draw.unit();
    const double dx[4] = {c, -si, -c, si}, dy[4] = {si, c, -si, -c};
    ring.push_back(r * dx[quarter]);
    ring.push_back(r * dy[quarter]);
  }
  // The four edges across the axes: from vertex k - 1 to k where k = 0, n/4, n/2, 3n/4. Moving
  // both ends' crossing coordinate to the smaller magnitude keeps each vertex in its sector.
  for (std::size_t q = 0; q < 4; ++q) {
    const std::size_t k = q * n / 4, j = (k + n - 1) % n;
    const std::size_t axis = q % 2 == 0 ? 1 : 0;  // y crosses 0 at k = 0 and n/2, x at n/4, 3n/4
    const double m = std::min(std::fabs(ring[2 * j + axis]), std::fabs(ring[2 * k + axis]));
    ring[2 * j + axis] = std::copysign(m, ring[2 * j + axis]);
    ring[2 * k + axis] = std::copysign(m, ring[2 * k + axis]);
  }
  return ring;
}

}  // namespace

GeneratedPlc originCenteredOutline(std::uint64_t seed, std::size_t n, bool hole) {
  Draw draw(seed);
  n = std::max<std::size_t>((n + 3) / 4 * 4, 8);
  GeneratedPlc g;
  const std::vector<double> outer = centeredRing(draw, n, 0.7, 1.3);
  addRing(g.plc, outer);
  g.area = ringArea(outer);
  if (hole) {
    const std::vector<double> inner = centeredRing(draw, 8, 0.1, 0.2);
    addRing(g.plc, inner);
    g.plc.holes = {0, 0};
    g.area -= ringArea(inner);
  }
  return g;
}

GeneratedPlc randomNonCrossingSegments(std::uint64_t seed, std::size_t attempts) {
  Draw draw(seed);
  GeneratedPlc g;
  addUnitSquareBoundary(g.plc);
  const std::size_t firstInner = g.plc.segments.size() / 2;
  for (std::size_t attempt = 0; attempt < attempts; ++attempt) {
    const double p[2] = {draw.gridCoordinate(), draw.gridCoordinate()};
    // The second endpoint lies within 0.15 of the first (short segments keep more of them), inside.
    double q[2];
    for (int k = 0; k < 2; ++k)
      q[k] = std::min(1 - 0x1p-20, std::max(0x1p-20, roundToGrid(p[k] + 0.3 * (draw.unit() - 0.5))));
    if (p[0] == q[0] && p[1] == q[1]) continue;
    bool clear = true;
    for (std::size_t s = firstInner; s < g.plc.segments.size() / 2 && clear; ++s)
      clear = !segmentsTouch(p, q, pointOf(g.plc, g.plc.segments[2 * s]), pointOf(g.plc, g.plc.segments[2 * s + 1]));
    if (!clear) continue;
    const std::uint32_t base = std::uint32_t(g.plc.points.size() / 2);
    g.plc.points.insert(g.plc.points.end(), {p[0], p[1], q[0], q[1]});
    g.plc.segments.push_back(base);
    g.plc.segments.push_back(base + 1);
  }
  g.area = 1;
  return g;
}

GeneratedPlc randomCrossingSegments(std::uint64_t seed, std::size_t n) {
  Draw draw(seed);
  GeneratedPlc g;
  addUnitSquareBoundary(g.plc);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t base = std::uint32_t(g.plc.points.size() / 2);
    for (int k = 0; k < 4; ++k) g.plc.points.push_back(draw.gridCoordinate());
    g.plc.segments.push_back(base);
    g.plc.segments.push_back(base + 1);
  }
  g.area = 1;
  return g;
}

GeneratedPlc chordStar(std::uint64_t seed, std::size_t n) {
  Draw draw(seed);
  GeneratedPlc g;
  for (std::uint32_t k = 0; k < n; ++k) {
    const double a = draw.unit() * 3.14159265358979323846, jitter = (draw.unit() - 0.5) * 0.02;
    g.plc.points.insert(g.plc.points.end(), {std::cos(a), std::sin(a), -std::cos(a) + jitter, -std::sin(a)});
    g.plc.segments.insert(g.plc.segments.end(), {2 * k, 2 * k + 1});
  }
  return g;
}

GeneratedPlc crossingClusters(std::uint64_t seed, double decades) {
  Draw draw(seed);
  GeneratedPlc g;
  auto point = [&](double x, double y) {
    g.plc.points.insert(g.plc.points.end(), {x, y});
    return std::uint32_t(g.plc.points.size() / 2 - 1);
  };
  auto segment = [&](std::uint32_t a, std::uint32_t b) { g.plc.segments.insert(g.plc.segments.end(), {a, b}); };
  const double sx = draw.unit() < 0.5 ? 0 : draw.unit() * 4 - 2, sy = draw.unit() < 0.5 ? 0 : draw.unit() * 4 - 2;
  const std::uint32_t corner = point(-1 + sx, -1 + sy);
  point(1 + sx, -1 + sy), point(1 + sx, 1 + sy), point(-1 + sx, 1 + sy);
  for (std::uint32_t k = 0; k < 4; ++k) segment(corner + k, corner + (k + 1) % 4);
  for (std::uint64_t c = 0, clusters = 1 + draw.below(3); c < clusters; ++c) {
    double cx = draw.unit() < 0.4 ? 0 : draw.unit() * 1.8 - 0.9 + sx;
    double cy = draw.unit() < 0.4 ? 0 : draw.unit() * 1.8 - 0.9 + sy;
    if (draw.unit() < 0.2) cx = sx + 1, cy = sy + draw.unit() * 1.8 - 0.9;  // on the right edge
    const double size = std::pow(10.0, -1 - draw.unit() * decades);
    const bool nearlyParallel = draw.unit() < 0.3;
    const double base = draw.unit() * 3.14159265358979323846;
    for (std::uint64_t k = 0, n = 2 + draw.below(6); k < n; ++k) {
      const double a = nearlyParallel ? base + (draw.unit() - 0.5) * std::pow(10.0, -draw.unit() * 12)
                                      : draw.unit() * 3.14159265358979323846;
      const double len = size * (0.2 + draw.unit()), ox = (draw.unit() - 0.5) * size, oy = (draw.unit() - 0.5) * size;
      const std::uint32_t p = point(cx + ox - len * std::cos(a), cy + oy - len * std::sin(a));
      const std::uint32_t q = point(cx + ox + len * std::cos(a), cy + oy + len * std::sin(a));
      segment(p, q);
      if (draw.unit() < 0.2) segment(p, corner + std::uint32_t(draw.below(4)));
    }
  }
  return g;
}

GeneratedPlc nearCollinearSliver(std::uint64_t seed) {
  Draw draw(seed);
  GeneratedPlc g;
  const double sx = roundToGrid(draw.unit() * 4 - 2), sy = roundToGrid(draw.unit() * 4 - 2);
  const double width = 1e-4 + 2e-4 * draw.unit();
  const std::uint64_t inner = 1 + draw.below(3);
  // Points: the left end, the chain's inner points from left to right, the right end, the apex.
  g.plc.points = {-1 + sx, sy};
  for (std::uint64_t k = 0; k < inner; ++k) {
    const double x = -1 + 2 * (k + 0.25 + 0.5 * draw.unit()) / double(inner);
    g.plc.points.insert(g.plc.points.end(), {x + sx, width * (0.7 + 0.6 * draw.unit()) + sy});
  }
  g.plc.points.insert(g.plc.points.end(), {1 + sx, sy, sx, -0.3 - 0.4 * draw.unit() + sy});
  const std::uint32_t right = std::uint32_t(inner + 1), apex = right + 1;
  for (std::uint32_t v = 0; v < right; ++v) g.plc.segments.insert(g.plc.segments.end(), {v, v + 1});
  g.plc.segments.insert(g.plc.segments.end(), {right, apex, apex, 0, 0, right});
  return g;
}

GeneratedPlc nearOverlaps(std::uint64_t seed) {
  Draw draw(seed);
  GeneratedPlc g;
  auto point = [&](double x, double y) {
    g.plc.points.insert(g.plc.points.end(), {x, y});
    return std::uint32_t(g.plc.points.size() / 2 - 1);
  };
  auto segment = [&](std::uint32_t a, std::uint32_t b) { g.plc.segments.insert(g.plc.segments.end(), {a, b}); };
  auto hair = [&](int from, int to) { return std::ldexp(draw.unit() < 0.5 ? 1.0 : -1.0, -from - int(draw.below(std::uint64_t(to - from + 1)))); };
  const double sx = draw.unit() < 0.5 ? 0 : roundToGrid(draw.unit() * 4 - 2);
  const double sy = draw.unit() < 0.5 ? 0 : roundToGrid(draw.unit() * 4 - 2);
  const std::uint32_t corner = point(-1 + sx, -1 + sy);
  point(1 + sx, -1 + sy), point(1 + sx, 1 + sy), point(-1 + sx, 1 + sy);
  for (std::uint32_t k = 0; k < 4; ++k) segment(corner + k, corner + (k + 1) % 4);
  for (std::uint64_t b = 0, bundles = 1 + draw.below(3); b < bundles; ++b) {
    const std::uint64_t where = draw.below(4);  // inside, inside, a corner, the right edge
    double ax = roundToGrid(draw.unit() * 1.6 - 0.8) + sx, ay = roundToGrid(draw.unit() * 1.6 - 0.8) + sy;
    if (where == 2) ax = sx + (draw.unit() < 0.5 ? -1 : 1), ay = sy + (draw.unit() < 0.5 ? -1 : 1);
    if (where == 3) ax = sx + 1;
    const std::uint32_t apex = point(ax, ay);
    const double base = draw.unit() * 2 * kPi, len = 0.2 + draw.unit() * 1.5;
    const bool fan = draw.unit() < 0.5;
    std::uint32_t firstEnd = 0;
    for (std::uint64_t k = 0, n = 2 + draw.below(4); k < n; ++k) {
      const double angle = k == 0 ? base : base + (draw.unit() < 0.5 ? 1 : -1) * std::pow(10.0, -3 - 9 * draw.unit());
      const double l = draw.unit() < 0.3 ? len : len * (0.5 + draw.unit());
      // From the apex, or from a point a hair beside it; to the far end, a point a hair beside the
      // first segment's far end, or beside it on the line.
      const std::uint32_t from = fan || k == 0 ? apex : point(ax + hair(20, 45), ay + hair(20, 45));
      std::uint32_t to = point(ax + l * std::cos(angle), ay + l * std::sin(angle));
      if (k == 0) firstEnd = to;
      if (k > 0 && draw.unit() < 0.3)
        to = point(g.plc.points[2 * firstEnd] + hair(20, 45), g.plc.points[2 * firstEnd + 1] + hair(20, 45));
      segment(from, to);
    }
    const double mx = ax + 0.5 * len * std::cos(base), my = ay + 0.5 * len * std::sin(base);
    for (std::uint64_t k = 0, n = draw.below(4); k < n; ++k) {  // segments across the bundle
      const double across = base + kPi / 2 + (draw.unit() - 0.5) * 2.5, reach = 0.05 + draw.unit() * 0.5;
      const double t = (draw.unit() - 0.5) * len;
      const double cx = mx + t * std::cos(base), cy = my + t * std::sin(base);
      segment(point(cx - reach * std::cos(across), cy - reach * std::sin(across)),
              point(cx + reach * std::cos(across), cy + reach * std::sin(across)));
    }
  }
  return g;
}

GeneratedPlc randomGridSegments(std::uint64_t seed, std::size_t n, std::uint32_t size) {
  Draw draw(seed);
  GeneratedPlc g;
  const double s = double(size);
  g.plc.points = {0, 0, s, 0, s, s, 0, s};
  g.plc.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t base = std::uint32_t(g.plc.points.size() / 2);
    for (int k = 0; k < 4; ++k) g.plc.points.push_back(double(draw.below(size + 1)));
    g.plc.segments.push_back(base);
    g.plc.segments.push_back(base + 1);
  }
  g.area = s * s;
  return g;
}

GeneratedPlc gridPlc(std::size_t nx, std::size_t ny, double step, bool crossLines) {
  GeneratedPlc g;
  auto id = [&](std::size_t i, std::size_t j) { return std::uint32_t(j * nx + i); };
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      g.plc.points.push_back(double(i) * step);
      g.plc.points.push_back(double(j) * step);
    }
  auto chain = [&](std::size_t i0, std::size_t j0, std::size_t di, std::size_t dj, std::size_t count) {
    for (std::size_t k = 0; k + 1 < count; ++k) {
      g.plc.segments.push_back(id(i0 + k * di, j0 + k * dj));
      g.plc.segments.push_back(id(i0 + (k + 1) * di, j0 + (k + 1) * dj));
    }
  };
  chain(0, 0, 1, 0, nx);
  chain(0, ny - 1, 1, 0, nx);
  chain(0, 0, 0, 1, ny);
  chain(nx - 1, 0, 0, 1, ny);
  if (crossLines && nx > 2 && ny > 2) {
    chain(0, ny / 2, 1, 0, nx);
    chain(nx / 2, 0, 0, 1, ny);
  }
  g.area = double(nx - 1) * double(ny - 1) * step * step;
  return g;
}

// --- transformations ---------------------------------------------------------------------------

namespace {
template <typename Map>
ruppert::Plc mapped(const ruppert::Plc& plc, Map map) {
  ruppert::Plc out = plc;
  for (std::size_t i = 0; i + 1 < out.points.size(); i += 2) map(out.points[i], out.points[i + 1]);
  for (std::size_t i = 0; i + 1 < out.holes.size(); i += 2) map(out.holes[i], out.holes[i + 1]);
  for (auto& r : out.regions) map(r.x, r.y);
  return out;
}
}  // namespace

ruppert::Plc scaled(const ruppert::Plc& plc, double factor) {
  ruppert::Plc out = mapped(plc, [factor](double& x, double& y) {
    x *= factor;
    y *= factor;
  });
  for (auto& r : out.regions)
    if (r.maxArea > 0) r.maxArea *= factor * factor;
  return out;
}

ruppert::Plc translated(const ruppert::Plc& plc, double dx, double dy) {
  return mapped(plc, [dx, dy](double& x, double& y) {
    x += dx;
    y += dy;
  });
}

ruppert::Plc rotated90(const ruppert::Plc& plc) {
  return mapped(plc, [](double& x, double& y) {
    const double oldX = x;
    x = -y;
    y = oldX;
  });
}

ruppert::Plc mirrored(const ruppert::Plc& plc, bool flipX, bool flipY) {
  return mapped(plc, [&](double& x, double& y) {
    if (flipX) x = -x;
    if (flipY) y = -y;
  });
}

ruppert::Plc permuted(const ruppert::Plc& plc, std::uint64_t seed, std::vector<std::uint32_t>* newIndexOut) {
  Draw draw(seed);
  const std::size_t n = plc.points.size() / 2;
  std::vector<std::uint32_t> newIndex(n);
  for (std::size_t i = 0; i < n; ++i) newIndex[i] = std::uint32_t(i);
  for (std::size_t i = n; i > 1; --i) std::swap(newIndex[i - 1], newIndex[draw.below(i)]);
  ruppert::Plc out = plc;
  for (std::size_t i = 0; i < n; ++i) {
    out.points[2 * newIndex[i]] = plc.points[2 * i];
    out.points[2 * newIndex[i] + 1] = plc.points[2 * i + 1];
    if (!plc.pointMarkers.empty()) out.pointMarkers[newIndex[i]] = plc.pointMarkers[i];
  }
  const std::size_t m = plc.segments.size() / 2;
  for (std::size_t s = 0; s < m; ++s) {
    // Reverse the segment order and flip every other segment's direction.
    const std::size_t t = m - 1 - s;
    const std::uint32_t a = plc.segments[2 * s], b = plc.segments[2 * s + 1];
    const bool flip = s % 2 == 1;
    out.segments[2 * t] = a < n ? newIndex[flip ? b : a] : a;
    out.segments[2 * t + 1] = b < n ? newIndex[flip ? a : b] : b;
    if (!plc.segmentMarkers.empty()) out.segmentMarkers[t] = plc.segmentMarkers[s];
  }
  if (newIndexOut) *newIndexOut = newIndex;
  return out;
}

ruppert::Plc withShiftedCopy(const ruppert::Plc& plc, double dx) {
  const ruppert::Plc copy = translated(plc, dx, 0);
  ruppert::Plc out = plc;
  const std::uint32_t base = std::uint32_t(plc.points.size() / 2);
  out.points.insert(out.points.end(), copy.points.begin(), copy.points.end());
  for (std::uint32_t v : plc.segments) out.segments.push_back(v + base);
  out.holes.insert(out.holes.end(), copy.holes.begin(), copy.holes.end());
  out.regions.insert(out.regions.end(), copy.regions.begin(), copy.regions.end());
  out.pointMarkers.insert(out.pointMarkers.end(), plc.pointMarkers.begin(), plc.pointMarkers.end());
  out.segmentMarkers.insert(out.segmentMarkers.end(), plc.segmentMarkers.begin(), plc.segmentMarkers.end());
  return out;
}

// --- real inputs ---------------------------------------------------------------------------------

std::string sharedDataDir() {
#ifdef RUPPERT_SHARED_DATA
  const std::string dir = RUPPERT_SHARED_DATA;
#else
  const std::string dir = "../shared/data";
#endif
  std::error_code error;
  return std::filesystem::is_directory(dir, error) ? dir : std::string();
}

std::string fixturesDir() {
#ifdef RUPPERT_FIXTURES
  return RUPPERT_FIXTURES;
#else
  return "tests/fixtures";
#endif
}

std::vector<std::string> polyFilesIn(const std::string& dir) {
  std::vector<std::string> files;
  std::error_code error;
  if (dir.empty() || !std::filesystem::is_directory(dir, error)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(dir, error))
    if (entry.is_regular_file() && entry.path().extension() == ".poly") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace ruppert_test
