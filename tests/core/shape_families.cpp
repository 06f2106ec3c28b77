// Shape families (see shape_families.h). Each generator builds rings (closed polygons), chains and
// free points through PlcBuilder, which rounds every coordinate to the 2^-20 grid; each keeps its
// features far coarser than that grid (at least ~1e-4), so rounding cannot make two segments touch.
#include "shape_families.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <utility>

namespace ruppert_test {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Pt {
  double x, y;
};

double snap(double v) { return std::ldexp(std::nearbyint(std::ldexp(v, 20)), -20); }

// SplitMix64 (Steele, Lea & Flood 2014): a fixed integer recipe, the same on every platform.
class Random {
 public:
  Random(std::uint64_t seed, std::uint64_t stream) : state_(seed * 0x9E3779B97F4A7C15ull ^ (stream + 0x632BE59BD9B4E019ull)) {
    next();
  }
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double unit() { return double(next() >> 11) * 0x1p-53; }  // [0, 1)
  double range(double lo, double hi) { return lo + (hi - lo) * unit(); }
  int integer(int lo, int hi) { return lo + int(((next() >> 32) * std::uint64_t(hi - lo + 1)) >> 32); }  // [lo, hi]
  bool chance(double p) { return unit() < p; }

 private:
  std::uint64_t state_;
};

Pt polar(Pt c, double r, double angle) { return {c.x + r * std::cos(angle), c.y + r * std::sin(angle)}; }

// A regular polygon of n sides and circumradius r, first vertex at angle phase.
std::vector<Pt> regularPolygon(Pt c, double r, int n, double phase) {
  std::vector<Pt> ring;
  for (int k = 0; k < n; ++k) ring.push_back(polar(c, r, phase + 2 * kPi * k / n));
  return ring;
}

class PlcBuilder {
 public:
  std::uint32_t point(Pt p) {
    plc_.points.push_back(snap(p.x));
    plc_.points.push_back(snap(p.y));
    return std::uint32_t(plc_.points.size() / 2 - 1);
  }
  void segment(std::uint32_t a, std::uint32_t b) { plc_.segments.insert(plc_.segments.end(), {a, b}); }
  // A closed polygon; returns the absolute area of its snapped vertices (shoelace).
  double ring(const std::vector<Pt>& ring) {
    const std::uint32_t first = std::uint32_t(plc_.points.size() / 2);
    const std::uint32_t n = std::uint32_t(ring.size());
    for (const Pt& p : ring) point(p);
    double twice = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t j = (i + 1) % n;
      segment(first + i, first + j);
      const double* p = &plc_.points[2 * (first + i)];
      const double* q = &plc_.points[2 * (first + j)];
      twice += p[0] * q[1] - q[0] * p[1];
    }
    return std::fabs(twice) / 2;
  }
  void hole(Pt p) { plc_.holes.insert(plc_.holes.end(), {snap(p.x), snap(p.y)}); }
  void region(Pt p, double attribute) {
    ruppert::Region r;
    r.x = snap(p.x);
    r.y = snap(p.y);
    r.attribute = attribute;
    plc_.regions.push_back(r);
  }
  GeneratedPlc done(double area) { return GeneratedPlc{std::move(plc_), area}; }

 private:
  ruppert::Plc plc_;
};

// A PLC of one closed polygon, its inside the domain.
GeneratedPlc simplePolygon(const std::vector<Pt>& ring) {
  PlcBuilder b;
  const double area = b.ring(ring);
  return b.done(area);
}

double distance(Pt a, Pt b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Places up to `count` disks of radius drawn by radius() with centers drawn by center(), each at
// least `clearance` from every disk kept before (a bounded number of attempts).
template <class Radius, class Center>
std::vector<std::pair<Pt, double>> scatterDisks(int count, double clearance, Radius radius, Center center) {
  std::vector<std::pair<Pt, double>> disks;
  for (int attempt = 0; attempt < 60 * count && int(disks.size()) < count; ++attempt) {
    const double r = radius();
    const Pt c = center(r);
    bool free = true;
    for (const auto& d : disks) free = free && distance(c, d.first) > r + d.second + clearance;
    if (free) disks.emplace_back(c, r);
  }
  return disks;
}

// A hole in every disk: a regular polygon of minSides..maxSides sides inscribed in it, turned at
// random, with its seed at the center. Returns the holes' total area.
double punchHoles(PlcBuilder& b, Random& random, const std::vector<std::pair<Pt, double>>& disks, int minSides, int maxSides) {
  double area = 0;
  for (const auto& [c, r] : disks) {
    const int sides = random.integer(minSides, maxSides);
    area += b.ring(regularPolygon(c, r, sides, random.range(0, kPi)));
    b.hole(c);
  }
  return area;
}

}  // namespace

// Buildings of random widths and heights on a baseline: steps, some very narrow buildings, some
// with pointed roofs.
GeneratedPlc skyline(std::uint64_t seed, int buildings) {
  Random random(seed, 1);
  std::vector<Pt> ring{{0, 0}};
  double x = 0, previous = 0;
  for (int i = 0; i < buildings; ++i) {
    double h = random.range(0.2, 2.0);
    while (std::fabs(h - previous) < 0.05) h = random.range(0.2, 2.0);  // a real step: no collinear triple
    const double w = random.chance(0.2) ? random.range(0.02, 0.08) : random.range(0.15, 0.9);
    ring.push_back({x, h});
    if (w > 0.3 && random.chance(0.25)) ring.push_back({x + w / 2, h + random.range(0.1, 0.8)});  // a spire
    ring.push_back({x + w, h});
    x += w;
    previous = h;
  }
  ring.push_back({x, 0});
  return simplePolygon(ring);
}

// A bar whose top is cut by narrow rectangular slots of random depths and widths.
GeneratedPlc combOfSlots(std::uint64_t seed, int slots) {
  Random random(seed, 2);
  const double pitch = 1.0 / slots, height = 0.5;
  std::vector<Pt> ring{{0, 0}, {1, 0}, {1, height}};
  for (int i = slots - 1; i >= 0; --i) {
    const double width = pitch * random.range(0.05, 0.35);
    const double left = pitch * (i + 0.5) - width / 2;
    const double bottom = height * random.range(0.1, 0.7);
    ring.insert(ring.end(), {{left + width, height}, {left + width, bottom}, {left, bottom}, {left, height}});
  }
  ring.push_back({0, height});
  return simplePolygon(ring);
}

// A star with hundreds of spikes of random lengths: sharp tips (small input angles) and reflex
// vertices between them.
GeneratedPlc spikyStar(std::uint64_t seed, int spikes) {
  Random random(seed, 3);
  std::vector<Pt> ring;
  for (int k = 0; k < spikes; ++k) {
    const double step = 2 * kPi / spikes;
    const double tip = random.range(0.75, 1.0), shift = random.range(-0.15, 0.15);  // drawn in this order
    ring.push_back(polar({0, 0}, tip, step * (k + shift)));
    ring.push_back(polar({0, 0}, random.range(0.55, 0.7), step * (k + 0.5)));
  }
  return simplePolygon(ring);
}

// A long rectangular channel with round obstacles (polygonal holes), some of them close to each
// other or to the walls.
GeneratedPlc channelWithObstacles(std::uint64_t seed, int obstacles) {
  Random random(seed, 4);
  const double length = random.range(3, 6);
  const double clearance = random.range(0.005, 0.04);
  auto radius = [&] { return random.range(0.04, 0.2); };
  auto center = [&](double r) {
    const double margin = r + clearance;
    return Pt{random.range(margin, length - margin), random.range(margin, 1 - margin)};
  };
  PlcBuilder b;
  const double area = b.ring({{0, 0}, {length, 0}, {length, 1}, {0, 1}});
  return b.done(area - punchHoles(b, random, scatterDisks(obstacles, clearance, radius, center), 12, 40));
}

namespace {

// NACA 4-digit section with a closed trailing edge: camber m at p (fractions of the chord),
// thickness t. Returns the point at chord station x on the upper (side = 1) or lower (-1) surface.
Pt nacaPoint(double m, double p, double t, double x, int side) {
  const double yt = 5 * t * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1036 * x * x * x * x);
  double yc, slope;
  if (x < p) {
    yc = m / (p * p) * (2 * p * x - x * x);
    slope = 2 * m / (p * p) * (p - x);
  } else {
    yc = m / ((1 - p) * (1 - p)) * (1 - 2 * p + 2 * p * x - x * x);
    slope = 2 * m / ((1 - p) * (1 - p)) * (p - x);
  }
  const double theta = std::atan(slope);
  return {x - side * yt * std::sin(theta), yc + side * yt * std::cos(theta)};
}

Pt rotateAbout(Pt p, Pt c, double angle) {
  const double s = std::sin(angle), co = std::cos(angle);
  return {c.x + co * (p.x - c.x) - s * (p.y - c.y), c.y + s * (p.x - c.x) + co * (p.y - c.y)};
}

}  // namespace

// A NACA-style airfoil (random camber, thickness, angle of attack; cosine spacing, sharp trailing
// edge) as a hole in a box.
GeneratedPlc airfoilInBox(std::uint64_t seed, int pointsPerSurface) {
  Random random(seed, 5);
  const double m = random.range(0, 0.06), p = random.range(0.3, 0.5), t = random.range(0.08, 0.2);
  const double attack = random.range(-10, 15) * kPi / 180;
  const int n = pointsPerSurface;
  std::vector<Pt> foil;
  for (int i = n; i >= 0; --i) foil.push_back(nacaPoint(m, p, t, (1 - std::cos(kPi * i / n)) / 2, 1));
  for (int i = 1; i < n; ++i) foil.push_back(nacaPoint(m, p, t, (1 - std::cos(kPi * i / n)) / 2, -1));
  const Pt pivot{0.25, 0};
  for (Pt& q : foil) q = rotateAbout(q, pivot, -attack);
  PlcBuilder b;
  double area = b.ring({{-1.5, -1.2}, {2.5, -1.2}, {2.5, 1.2}, {-1.5, 1.2}});
  area -= b.ring(foil);
  const Pt camber = nacaPoint(m, p, 0, 0.3, 1);  // on the camber line at 30% chord: inside the foil
  b.hole(rotateAbout(camber, pivot, -attack));
  return b.done(area);
}

// A box divided by walls of random thickness that rise alternately from the bottom and hang from
// the top, leaving one winding corridor of varying width.
GeneratedPlc serpentineCorridor(std::uint64_t seed, int walls) {
  Random random(seed, 6);
  const double height = random.range(2, 5), gap = random.range(0.15, 0.6);
  std::vector<std::pair<double, double>> spans;  // each wall's [left, right]
  double x = 0;
  for (int i = 0; i < walls; ++i) {
    x += random.range(0.25, 1.0);  // corridor width before this wall
    const double thickness = random.range(0.03, 0.3);
    spans.emplace_back(x, x + thickness);
    x += thickness;
  }
  const double width = x + random.range(0.25, 1.0);
  std::vector<Pt> ring{{0, 0}};
  for (int i = 0; i < walls; i += 2)
    ring.insert(ring.end(), {{spans[i].first, 0}, {spans[i].first, height - gap}, {spans[i].second, height - gap}, {spans[i].second, 0}});
  ring.insert(ring.end(), {{width, 0}, {width, height}});
  for (int i = walls - 1; i >= 1; --i) {
    if (i % 2 == 0) continue;  // bottom walls are done
    ring.insert(ring.end(), {{spans[i].second, height}, {spans[i].second, gap}, {spans[i].first, gap}, {spans[i].first, height}});
  }
  ring.push_back({0, height});
  return simplePolygon(ring);
}

namespace {

// Grid vertex (i, j) of a k x k jittered grid on the unit square: interior vertices move up to
// 0.22 of a cell in each direction, boundary vertices only along their side, corners not at all.
// Each edge then stays within 0.22 cells of its grid line, so no two edges cross and every cell's
// nominal center stays inside its cell.
Pt jitteredVertex(Random& random, int i, int j, int k) {
  const double cell = 1.0 / k;
  const double dx = (i == 0 || i == k) ? 0 : random.range(-0.22, 0.22) * cell;
  const double dy = (j == 0 || j == k) ? 0 : random.range(-0.22, 0.22) * cell;
  return {i * cell + dx, j * cell + dy};
}

}  // namespace

// A planar subdivision of the unit square: a jittered grid whose interior edges are segments
// (about a quarter of them removed, leaving dangling ends), with a region seed per cell.
GeneratedPlc jitteredSubdivision(std::uint64_t seed, int cellsPerSide) {
  Random random(seed, 7);
  const int k = cellsPerSide;
  PlcBuilder b;
  std::vector<std::uint32_t> id;
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) id.push_back(b.point(jitteredVertex(random, i, j, k)));
  auto at = [&](int i, int j) { return id[std::size_t(j) * (k + 1) + i]; };
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) {
      const bool boundaryRow = j == 0 || j == k, boundaryColumn = i == 0 || i == k;
      if (i < k && (boundaryRow || !random.chance(0.25))) b.segment(at(i, j), at(i + 1, j));
      if (j < k && (boundaryColumn || !random.chance(0.25))) b.segment(at(i, j), at(i, j + 1));
    }
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) b.region({(i + 0.5) / k, (j + 0.5) / k}, random.integer(1, 6));
  return b.done(1.0);
}

// A disk (polygon of many sides) perforated by small polygons of 3 to 8 sides, each a hole.
GeneratedPlc perforatedDisk(std::uint64_t seed, int holes) {
  Random random(seed, 8);
  const int sides = random.integer(64, 160);
  const double clearance = random.range(0.005, 0.03);
  auto radius = [&] { return random.range(0.02, 0.09); };
  auto center = [&](double r) {
    const double reach = 0.99 - r - clearance;  // the outer polygon's edges are >= cos(pi/64) > 0.998 out
    for (;;) {
      const Pt c{random.range(-reach, reach), random.range(-reach, reach)};
      if (std::hypot(c.x, c.y) < reach) return c;
    }
  };
  PlcBuilder b;
  const double area = b.ring(regularPolygon({0, 0}, 1, sides, 0));
  return b.done(area - punchHoles(b, random, scatterDisks(holes, clearance, radius, center), 3, 8));
}

// An ellipse whose boundary is cut by sharp radial V notches (opening 3 to 25 degrees, depth 15%
// to 60% of the radius): two boundary segments close together near every tip.
GeneratedPlc vNotchedOutline(std::uint64_t seed, int notches) {
  Random random(seed, 9);
  const double ry = random.range(0.5, 1.0);
  auto onEllipse = [&](double a) { return Pt{std::cos(a), ry * std::sin(a)}; };
  const double step = 2 * kPi / notches;
  const int arcPoints = std::max(1, 96 / notches);  // boundary points between two notches
  std::vector<Pt> ring;
  for (int k = 0; k < notches; ++k) {
    const double center = step * (k + random.range(-0.2, 0.2));
    const double depth = random.range(0.15, 0.6), opening = random.range(3, 25) * kPi / 180;
    const double halfWidth = std::min(depth * std::tan(opening / 2), 0.25 * step);  // as an angle on the unit circle
    const Pt mouth = onEllipse(center);
    ring.push_back(onEllipse(center - halfWidth));
    ring.push_back({mouth.x * (1 - depth), mouth.y * (1 - depth)});
    ring.push_back(onEllipse(center + halfWidth));
    const double next = step * (k + 1) - 0.45 * step;  // arc points stay clear of the next notch
    for (int a = 1; a <= arcPoints; ++a) {
      const double from = center + 0.3 * step, to = std::max(from, next);
      ring.push_back(onEllipse(from + (to - from) * a / (arcPoints + 1)));
    }
  }
  return simplePolygon(ring);
}

// A long thin strip (length 5-12, height 0.05-0.2) with bumps on both long sides: triangles,
// rectangles and polygonal half-disks.
GeneratedPlc stripWithBumps(std::uint64_t seed, int bumps) {
  Random random(seed, 10);
  const double length = random.range(5, 12), h = random.range(0.05, 0.2);
  auto side = [&](double y, double outward) {  // bumps left to right along the line at height y
    std::vector<Pt> pts;
    const double slot = length / bumps;
    for (int i = 0; i < bumps; ++i) {
      if (random.chance(0.3)) continue;
      const double w = slot * random.range(0.1, 0.7), left = slot * i + random.range(0.05, 0.9 - w / slot) * slot;
      const double tall = outward * h * random.range(0.2, 1.5);
      const int shape = random.integer(0, 2);
      pts.push_back({left, y});
      if (shape == 0) pts.push_back({left + w * random.range(0.2, 0.8), y + tall});
      if (shape == 1) pts.insert(pts.end(), {{left, y + tall}, {left + w, y + tall}});
      for (int a = 1; shape == 2 && a < 8; ++a)
        pts.push_back({left + w / 2 - w / 2 * std::cos(kPi * a / 8), y + tall * std::sin(kPi * a / 8)});
      pts.push_back({left + w, y});
    }
    return pts;
  };
  std::vector<Pt> ring{{0, 0}};
  for (const Pt& p : side(0, -1)) ring.push_back(p);
  ring.insert(ring.end(), {{length, 0}, {length, h}});
  std::vector<Pt> top = side(h, 1);
  ring.insert(ring.end(), top.rbegin(), top.rend());
  ring.push_back({0, h});
  return simplePolygon(ring);
}

namespace {

// Roughly normal on [-1.5, 1.5]: the sum of three uniforms, each drawn in its own statement.
double bellCurve(Random& random) {
  double sum = random.unit();
  sum += random.unit();
  sum += random.unit();
  return sum - 1.5;
}

}  // namespace

// The unit square with points inside it: uniform ones and tight clusters.
GeneratedPlc pointCloudInSquare(std::uint64_t seed, int points) {
  Random random(seed, 11);
  PlcBuilder b;
  b.ring({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  std::vector<Pt> centers;
  for (int c = random.integer(1, 5); c > 0; --c) centers.push_back({random.range(0.1, 0.9), random.range(0.1, 0.9)});
  const double spread = random.range(0.005, 0.06);
  std::map<std::pair<double, double>, bool> taken;  // snapped positions: no duplicate points
  for (int placed = 0; placed < points;) {
    Pt p{random.range(0.001, 0.999), random.range(0.001, 0.999)};
    if (random.chance(0.6)) {  // a cluster point: sum of three uniforms, roughly normal
      const Pt& c = centers[std::size_t(random.integer(0, int(centers.size()) - 1))];
      const double dx = bellCurve(random), dy = bellCurve(random);
      p = {c.x + spread * dx, c.y + spread * dy};
      if (p.x <= 0.001 || p.x >= 0.999 || p.y <= 0.001 || p.y >= 0.999) continue;
    }
    if (!taken.emplace(std::make_pair(snap(p.x), snap(p.y)), true).second) continue;
    b.point(p);
    ++placed;
  }
  return b.done(1.0);
}

// Polygonal circles nested inside each other, off-center; the annuli are domain and hole in turn
// (outermost annulus domain), each hole annulus with a seed.
GeneratedPlc nestedRings(std::uint64_t seed, int rings) {
  Random random(seed, 12);
  PlcBuilder b;
  Pt c{0, 0};
  double r = 1, area = 0;
  for (int i = 0; i < rings; ++i) {
    const int sides = random.integer(24, 96);
    const double ringArea = b.ring(regularPolygon(c, r, sides, random.range(0, kPi)));
    area += (i % 2 == 0 ? 1 : -1) * ringArea;  // ring i bounds domain inside it when i is even
    if (i + 1 == rings) {
      if (i % 2 == 1) b.hole(c);  // the innermost disk is a hole
      break;
    }
    const double inner = r * random.range(0.55, 0.85);
    const double room = r * std::cos(kPi / sides) - inner;  // what the next ring may move
    const double offset = room * random.range(0, 0.4), direction = random.range(0, 2 * kPi);
    const Pt next = polar(c, offset, direction);
    if (i % 2 == 1) {
      // A hole annulus: its seed on the ray from the inner center, between the two rings.
      const double outerReach = r * std::cos(kPi / sides) - distance(next, c);
      b.hole({next.x + (inner + outerReach) / 2, next.y});
    }
    c = next;
    r = inner;
  }
  return b.done(area);
}

namespace {

// 5 x 7 block letters, drawn for this file ('#' filled).
const char* const kLetters[][7] = {
    {".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"},  // A
    {"####.", "#...#", "#...#", "####.", "#...#", "#...#", "####."},  // B
    {"#####", "#....", "#....", "####.", "#....", "#....", "#####"},  // E
    {"#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"},  // H
    {"#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#"},  // K
    {"#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#"},  // M
    {"#...#", "##..#", "#.#.#", "#..##", "#...#", "#...#", "#...#"},  // N
    {".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."},  // O
    {"####.", "#...#", "#...#", "####.", "#....", "#....", "#...."},  // P
    {"####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#"},  // R
    {".####", "#....", "#....", ".###.", "....#", "....#", "####."},  // S
    {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."},  // T
    {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"},  // X
    {"#####", "....#", "...#.", "..#..", ".#...", "#....", "#####"},  // Z
    {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."},  // 8
};

// A bitmap of filled pixels, with a one-pixel empty border; (x, y) with y up.
struct Bitmap {
  int width = 0, height = 0;
  std::vector<char> filled;
  bool at(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height && filled[std::size_t(y) * width + x]; }
};

Bitmap wordBitmap(Random& random, int letters) {
  Bitmap bitmap;
  bitmap.width = 6 * letters + 1;
  bitmap.height = 9;
  bitmap.filled.assign(std::size_t(bitmap.width) * bitmap.height, 0);
  const int count = int(sizeof kLetters / sizeof kLetters[0]);
  for (int l = 0; l < letters; ++l) {
    const auto& glyph = kLetters[random.integer(0, count - 1)];
    for (int row = 0; row < 7; ++row)
      for (int col = 0; col < 5; ++col)
        if (glyph[row][col] == '#') bitmap.filled[std::size_t(7 - row) * bitmap.width + 1 + 6 * l + col] = 1;
  }
  return bitmap;
}

// Empty pixels not reachable (4-connected) from the border: one seed pixel per enclosed component.
std::vector<std::pair<int, int>> enclosedEmptyPixels(const Bitmap& bm) {
  std::vector<int> label(bm.filled.size(), 0);  // 0 unvisited, 1 outside, 2+ enclosed components
  std::vector<std::pair<int, int>> seeds;
  auto flood = [&](int x0, int y0, int mark) {
    std::vector<std::pair<int, int>> stack{{x0, y0}};
    label[std::size_t(y0) * bm.width + x0] = mark;
    while (!stack.empty()) {
      const auto [x, y] = stack.back();
      stack.pop_back();
      const int around[4][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}};
      for (const auto& n : around) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= bm.width || n[1] >= bm.height || bm.at(n[0], n[1])) continue;
        int& l = label[std::size_t(n[1]) * bm.width + n[0]];
        if (l == 0) l = mark, stack.push_back({n[0], n[1]});
      }
    }
  };
  flood(0, 0, 1);
  for (int y = 0; y < bm.height; ++y)
    for (int x = 0; x < bm.width; ++x)
      if (!bm.at(x, y) && label[std::size_t(y) * bm.width + x] == 0) {
        flood(x, y, int(seeds.size()) + 2);
        seeds.emplace_back(x, y);
      }
  return seeds;
}

// The outline of the filled pixels as maximal straight segments: a run of unit boundary edges on one
// grid line is broken only where another boundary edge meets it (a pinch where pixels touch at a
// corner), so every segment meets the others at endpoints only.
void addOutline(const Bitmap& bm, double shear, PlcBuilder& b) {
  std::map<std::pair<int, int>, std::uint32_t> ids;
  auto vertex = [&](int x, int y) {
    auto it = ids.find({x, y});
    if (it != ids.end()) return it->second;
    const std::uint32_t id = b.point({(x + shear * y) / 8, double(y) / 8});  // 1/8 and shear k/16: dyadic
    ids[{x, y}] = id;
    return id;
  };
  // Horizontal edges on the line y (between rows y-1 and y); vertical ones on the line x.
  auto horizontal = [&](int x, int y) { return bm.at(x, y - 1) != bm.at(x, y); };
  auto vertical = [&](int x, int y) { return bm.at(x - 1, y) != bm.at(x, y); };
  for (int pass = 0; pass < 2; ++pass) {
    const int lines = pass == 0 ? bm.height + 1 : bm.width + 1, along = pass == 0 ? bm.width : bm.height;
    for (int line = 0; line < lines; ++line)
      for (int s = 0; s < along;) {
        auto edge = [&](int t) { return pass == 0 ? horizontal(t, line) : vertical(line, t); };
        auto crossed = [&](int t) {  // a boundary edge of the other direction meets this line at t
          return pass == 0 ? (vertical(t, line) || vertical(t, line - 1)) : (horizontal(line, t) || horizontal(line - 1, t));
        };
        if (!edge(s)) { ++s; continue; }
        int e = s + 1;
        while (e < along && edge(e) && !crossed(e)) ++e;
        const std::uint32_t from = pass == 0 ? vertex(s, line) : vertex(line, s);  // numbered in this order
        const std::uint32_t to = pass == 0 ? vertex(e, line) : vertex(line, e);
        b.segment(from, to);
        s = e;
      }
  }
}

}  // namespace

// A word of 5 x 7 block letters (outlines with enclosed holes, pinch points where pixels touch at a
// corner), possibly slanted.
GeneratedPlc blockLetters(std::uint64_t seed, int letters) {
  Random random(seed, 13);
  const Bitmap bitmap = wordBitmap(random, letters);
  const double shear = random.integer(0, 4) / 16.0;
  PlcBuilder b;
  addOutline(bitmap, shear, b);
  for (const auto& [x, y] : enclosedEmptyPixels(bitmap)) b.hole({(x + 0.5 + shear * (y + 0.5)) / 8, (y + 0.5) / 8});
  const double pixels = double(std::count(bitmap.filled.begin(), bitmap.filled.end(), 1));
  return b.done(pixels / 64);
}

// A gear: trapezoidal teeth on a root circle, a hub hole and a ring of bolt holes.
GeneratedPlc gearWithHoles(std::uint64_t seed, int teeth) {
  Random random(seed, 14);
  const double root = 1, tip = 1 + random.range(0.04, 0.15), step = 2 * kPi / teeth;
  const double flank = random.range(0.05, 0.2), land = random.range(0.15, 0.35);  // fractions of a tooth's step
  std::vector<Pt> outline;
  for (int k = 0; k < teeth; ++k) {
    const double a = step * k;
    outline.push_back(polar({0, 0}, root, a));
    outline.push_back(polar({0, 0}, tip, a + step * flank));
    outline.push_back(polar({0, 0}, tip, a + step * (flank + land)));
    outline.push_back(polar({0, 0}, root, a + step * (2 * flank + land)));
  }
  PlcBuilder b;
  double area = b.ring(outline);
  const double hub = random.range(0.15, 0.3);
  area -= b.ring(regularPolygon({0, 0}, hub, random.integer(16, 48), 0));
  b.hole({0, 0});
  const int bolts = random.integer(3, 8);
  const double boltRadius = random.range(0.03, 0.08), boltCircle = (hub + root) / 2, phase = random.range(0, step);
  for (int k = 0; k < bolts; ++k) {
    const Pt c = polar({0, 0}, boltCircle, phase + 2 * kPi * k / bolts);
    area -= b.ring(regularPolygon(c, boltRadius, random.integer(8, 20), 0));
    b.hole(c);
  }
  return b.done(area);
}

namespace {

double pointSegmentDistance(Pt p, Pt a, Pt b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return distance(p, {a.x + t * dx, a.y + t * dy});
}

// Distance between two segments, given that they do not cross (checked by the caller through the
// sign test below).
bool segmentsClear(Pt a, Pt b, Pt c, Pt d, double clearance) {
  auto side = [](Pt p, Pt q, Pt r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); };
  if (side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0) return false;  // they cross
  return std::min({pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d), pointSegmentDistance(c, a, b),
                   pointSegmentDistance(d, a, b)}) > clearance;
}

}  // namespace

// The unit square with free cracks: segments inside the domain that end in it (dangling tips), at
// least 0.003 from each other and from the boundary.
GeneratedPlc squareWithCracks(std::uint64_t seed, int cracks) {
  Random random(seed, 15);
  std::vector<std::pair<Pt, Pt>> kept;
  for (int attempt = 0; attempt < 50 * cracks && int(kept.size()) < cracks; ++attempt) {
    const Pt c{random.range(0.05, 0.95), random.range(0.05, 0.95)};
    const double half = random.range(0.02, 0.2), angle = random.range(0, kPi);
    const Pt a = polar(c, half, angle), d = polar(c, -half, angle);
    const bool inside = std::min({a.x, a.y, d.x, d.y}) > 0.003 && std::max({a.x, a.y, d.x, d.y}) < 0.997;
    bool clear = inside;
    for (const auto& [p, q] : kept) clear = clear && segmentsClear(a, d, p, q, 0.003);
    if (clear) kept.emplace_back(a, d);
  }
  PlcBuilder b;
  b.ring({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  for (const auto& [p, q] : kept) {
    const std::uint32_t from = b.point(p);  // numbered in this order
    b.segment(from, b.point(q));
  }
  return b.done(1.0);
}

const std::vector<ShapeFamily>& shapeFamilies() {
  static const std::vector<ShapeFamily> families{
      {"skyline", "buildings of random widths and heights, spires", skyline, 8, 60},
      {"comb", "a bar cut by narrow slots", combOfSlots, 8, 60},
      {"star", "a star with hundreds of spikes", spikyStar, 100, 400},
      {"channel", "a channel with round obstacles (holes)", channelWithObstacles, 3, 25},
      {"airfoil", "a NACA-style airfoil (hole) in a box", airfoilInBox, 20, 120},
      {"serpentine", "a winding corridor between alternating walls", serpentineCorridor, 4, 24},
      {"subdivision", "a jittered planar subdivision with regions", jitteredSubdivision, 3, 12},
      {"perforated", "a disk perforated by small polygonal holes", perforatedDisk, 5, 60},
      {"notched", "an ellipse cut by sharp V notches", vNotchedOutline, 4, 30},
      {"strip", "a long thin strip with bumps", stripWithBumps, 5, 40},
      {"cloud", "points (uniform and clustered) in a square", pointCloudInSquare, 50, 800},
      {"rings", "nested off-center rings, domain and hole in turn", nestedRings, 2, 8},
      {"letters", "block-letter words (holes, pinch points, slant)", blockLetters, 2, 8},
      {"gear", "a gear with a hub hole and bolt holes", gearWithHoles, 12, 80},
      {"cracks", "a square with free dangling segments", squareWithCracks, 10, 60},
  };
  return families;
}

const ShapeFamily* findShapeFamily(const std::string& name) {
  for (const auto& f : shapeFamilies())
    if (name == f.name) return &f;
  return nullptr;
}

int familySize(const ShapeFamily& family, std::uint64_t seed) {
  Random random(seed, 0x5123);
  return random.integer(family.minSize, family.maxSize);
}

GeneratedPlc familyMember(const ShapeFamily& family, std::uint64_t seed) {
  return family.make(seed, familySize(family, seed));
}

std::string plcToPolyText(const ruppert::Plc& plc, const std::string& comment) {
  std::ostringstream out;
  char number[64];
  auto put = [&](double v) {
    std::snprintf(number, sizeof number, " %.17g", v);
    out << number;
  };
  out << "# " << comment << "\n";
  out << plc.points.size() / 2 << " 2 0 0\n";
  for (std::size_t i = 0; i < plc.points.size() / 2; ++i) {
    out << i;
    put(plc.points[2 * i]);
    put(plc.points[2 * i + 1]);
    out << "\n";
  }
  out << plc.segments.size() / 2 << " 0\n";
  for (std::size_t i = 0; i < plc.segments.size() / 2; ++i) out << i << " " << plc.segments[2 * i] << " " << plc.segments[2 * i + 1] << "\n";
  out << plc.holes.size() / 2 << "\n";
  for (std::size_t i = 0; i < plc.holes.size() / 2; ++i) {
    out << i;
    put(plc.holes[2 * i]);
    put(plc.holes[2 * i + 1]);
    out << "\n";
  }
  out << plc.regions.size() << "\n";
  for (std::size_t i = 0; i < plc.regions.size(); ++i) {
    out << i;
    for (double v : {plc.regions[i].x, plc.regions[i].y, plc.regions[i].attribute, plc.regions[i].maxArea}) put(v);
    out << "\n";
  }
  return out.str();
}

}  // namespace ruppert_test
