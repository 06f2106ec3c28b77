// PLCs with curved boundaries and their exact areas (curve_shapes.h).
#include "curve_shapes.h"

#include <cmath>
#include <random>

namespace ruppert_test {

namespace {

constexpr double kPi = 3.14159265358979323846;

using ruppert::Curve;
using ruppert::CurveType;
using ruppert::Plc;

std::uint32_t addPoint(Plc& plc, double x, double y) {
  plc.points.push_back(x), plc.points.push_back(y);
  return static_cast<std::uint32_t>(plc.points.size() / 2 - 1);
}

void addArc(Plc& plc, std::uint32_t from, std::uint32_t to, double cx, double cy) {
  Curve c;
  c.type = CurveType::Arc, c.from = from, c.to = to, c.center[0] = cx, c.center[1] = cy;
  plc.curves.push_back(c);
}

// The area of the intersection of disks of radii r1 and r2 whose centers lie d apart (crossing circles).
double intersectionArea(double r1, double r2, double d) {
  const double d1 = (d * d + r1 * r1 - r2 * r2) / (2 * d), d2 = d - d1;
  return r1 * r1 * std::acos(d1 / r1) - d1 * std::sqrt(r1 * r1 - d1 * d1) + r2 * r2 * std::acos(d2 / r2) -
         d2 * std::sqrt(r2 * r2 - d2 * d2);
}

}  // namespace

void addCircle(Plc& plc, double cx, double cy, double r) {
  const std::uint32_t right = addPoint(plc, cx + r, cy), left = addPoint(plc, cx - r, cy);
  addArc(plc, right, left, cx, cy), addArc(plc, left, right, cx, cy);
}

CurvedShape squareWithRoundHole(double r) {
  CurvedShape s;
  s.plc.points = {0, 0, 1, 0, 1, 1, 0, 1};
  s.plc.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  addCircle(s.plc, 0.5, 0.5, r);
  s.plc.holes = {0.5, 0.5};
  s.area = 1 - kPi * r * r;
  return s;
}

CurvedShape quarterDisk() {
  CurvedShape s;
  s.plc.points = {0, 0, 1, 0, 0, 1};
  s.plc.segments = {0, 1, 2, 0};
  addArc(s.plc, 1, 2, 0, 0);
  s.area = kPi / 4;
  return s;
}

CurvedShape underBezier(double h) {
  CurvedShape s;
  s.plc.points = {0, 0, 1, 0};
  s.plc.segments = {0, 1};
  Curve c;
  c.type = CurveType::Bezier, c.from = 1, c.to = 0;
  const double controls[4] = {1, h, 0, h};
  for (int i = 0; i < 4; ++i) c.controls[i] = controls[i];
  s.plc.curves.push_back(c);
  // y(t) = 3 h t (1 - t) over x from 1 to 0: the area is the integral of y dx, by the exact 5-point Gauss rule.
  const double nodes[5] = {0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640, 0.9061798459386640};
  const double weights[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891, 0.2369268850561891};
  double area = 0;
  for (int i = 0; i < 5; ++i) {
    const double t = (nodes[i] + 1) / 2, u = 1 - t;
    const double y = 3 * h * t * u, dx = 3 * (u * u * (1 - 1) + 2 * u * t * (0 - 1) + t * t * (0 - 0));
    area -= weights[i] / 2 * y * dx;
  }
  s.area = area;
  return s;
}

CurvedShape diskWithHoles(int holes, std::uint32_t seed) {
  CurvedShape s;
  addCircle(s.plc, 0, 0, 1);
  s.area = kPi;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  // Holes in a ring of sectors, one per sector, so none touch.
  for (int k = 0; k < holes; ++k) {
    const double angle = 2 * kPi * (k + 0.5) / holes, radius = 0.45 + 0.1 * unit(rng);
    const double r = std::min(0.2, 0.35 * std::sin(kPi / holes)) * (0.5 + 0.5 * unit(rng));
    const double cx = radius * std::cos(angle), cy = radius * std::sin(angle);
    addCircle(s.plc, cx, cy, r);
    s.plc.holes.push_back(cx), s.plc.holes.push_back(cy);
    s.area -= kPi * r * r;
  }
  return s;
}

CurvedShape roundedRectangle(double w, double h, double r) {
  CurvedShape s;
  const double p[16] = {r, 0, w - r, 0, w, r, w, h - r, w - r, h, r, h, 0, h - r, 0, r};
  for (int i = 0; i < 8; ++i) addPoint(s.plc, p[2 * i], p[2 * i + 1]);
  s.plc.segments = {0, 1, 2, 3, 4, 5, 6, 7};
  addArc(s.plc, 1, 2, w - r, r), addArc(s.plc, 3, 4, w - r, h - r);
  addArc(s.plc, 5, 6, r, h - r), addArc(s.plc, 7, 0, r, r);
  s.area = w * h - (4 - kPi) * r * r;
  return s;
}

CurvedShape lens(double d) {
  CurvedShape s;
  const double a = std::sqrt(1 - d * d);
  addPoint(s.plc, a, 0), addPoint(s.plc, -a, 0);
  addArc(s.plc, 0, 1, 0, -d), addArc(s.plc, 1, 0, 0, d);
  s.area = intersectionArea(1, 1, 2 * d);
  return s;
}

CurvedShape crescent(double d, double r2) {
  CurvedShape s;
  const double x = (1 - r2 * r2 + d * d) / (2 * d), y = std::sqrt(1 - x * x);
  addPoint(s.plc, x, y), addPoint(s.plc, x, -y);
  addArc(s.plc, 0, 1, 0, 0), addArc(s.plc, 0, 1, d, 0);
  s.area = kPi - intersectionArea(1, r2, d);
  return s;
}

CurvedShape gear(int teeth, double inner) {
  // Per tooth, counter-clockwise: an arc of the outer circle (radius 1) over the tooth's top, a
  // segment down to the root circle (radius inner), an arc of it over the gap, a segment up. The
  // area: the polygon of those points plus, per arc, its circular segment r^2 / 2 (phi - sin phi).
  CurvedShape s;
  const double step = 2 * kPi / teeth, top = 0.4 * step, flank = 0.1 * step;
  double area = 0;
  auto segmentArea = [](double r, double phi) { return r * r / 2 * (phi - std::sin(phi)); };
  for (int k = 0; k < teeth; ++k) {
    const double a = k * step;
    addPoint(s.plc, std::cos(a), std::sin(a));
    addPoint(s.plc, std::cos(a + top), std::sin(a + top));
    addPoint(s.plc, inner * std::cos(a + top + flank), inner * std::sin(a + top + flank));
    addPoint(s.plc, inner * std::cos(a + step - flank), inner * std::sin(a + step - flank));
    area += segmentArea(1, top) + segmentArea(inner, step - top - 2 * flank);
  }
  const std::uint32_t n = static_cast<std::uint32_t>(s.plc.points.size() / 2);
  for (std::uint32_t k = 0; k < n; k += 4) {
    addArc(s.plc, k, k + 1, 0, 0);
    s.plc.segments.insert(s.plc.segments.end(), {k + 1, k + 2, k + 3, (k + 4) % n});
    addArc(s.plc, k + 2, k + 3, 0, 0);
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const double* p = &s.plc.points[2 * i];
    const double* q = &s.plc.points[2 * ((i + 1) % n)];
    area += (p[0] * q[1] - q[0] * p[1]) / 2;
  }
  s.area = area;
  return s;
}

}  // namespace ruppert_test
