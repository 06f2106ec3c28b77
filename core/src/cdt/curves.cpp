// Curved boundaries (curves.h): the input checks naming the curve, the cutting into initial pieces
// (the shapes' geometry: curve_pieces.cpp), and the check that no repair touched a piece.
#include "cdt/curves.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "cdt/prepare_input.h"
#include "cold_code.h"
#include "message.h"
#include "mesh/predicates.h"

// Curves are rare and their pieces few: the whole file is compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

namespace ruppert::detail {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;
constexpr std::size_t kMaxPieces = std::size_t(1) << 22;
constexpr int kMaxBisections = 40;
// Halvings of a piece for the input points inside its hull: a point on the curve itself stays inside
// every piece that holds it, so this bounds the pieces such a point costs.
constexpr int kMaxPointHalvings = 30;

[[noreturn]] void fail(ErrorCode code, std::size_t curve, const std::string& what) {
  throw Error(code, "curve " + std::to_string(curve) + ": " + what);
}

// Curve i's shape in user coordinates, after checking what it refers to.
CurveShape shapeOf(const Plc& plc, std::size_t i) {
  const Curve& cv = plc.curves[i];
  const std::size_t n = plc.points.size() / 2;
  if (cv.type != CurveType::Arc && cv.type != CurveType::Bezier) fail(ErrorCode::MalformedInput, i, "unknown type (not 'arc' or 'bezier')");
  for (auto [name, index] : {std::pair{"from", cv.from}, std::pair{"to", cv.to}})
    if (index >= n)
      fail(ErrorCode::IndexOutOfRange, i, std::string(name) + " = " + std::to_string(index) + " is not a point index (the input has " + std::to_string(n) + " points)");
  if (cv.from == cv.to) fail(ErrorCode::MalformedInput, i, "from and to are the same point; a closed curve is two curves");
  const double* a = &plc.points[2 * std::size_t(cv.from)];
  const double* b = &plc.points[2 * std::size_t(cv.to)];
  // Duplicates are merged before meshing: two points at one place are one point.
  if (a[0] == b[0] && a[1] == b[1])
    fail(ErrorCode::MalformedInput, i, "from = " + std::to_string(cv.from) + " and to = " + std::to_string(cv.to) + " lie at the same place (" +
         formatNumber(a[0]) + ", " + formatNumber(a[1]) + "); a closed curve is two curves");
  CurveShape s;
  s.type = cv.type;
  if (cv.type == CurveType::Bezier) {
    for (double v : cv.controls)
      if (!std::isfinite(v)) fail(ErrorCode::NonFiniteCoordinate, i, "a control coordinate is " + formatNumber(v));
    const double c[8] = {a[0], a[1], cv.controls[0], cv.controls[1], cv.controls[2], cv.controls[3], b[0], b[1]};
    std::copy(c, c + 8, s.c);
    return s;
  }
  const double cx = cv.center[0], cy = cv.center[1];
  if (!std::isfinite(cx) || !std::isfinite(cy)) fail(ErrorCode::NonFiniteCoordinate, i, "the center is not finite");
  const double r0 = std::hypot(a[0] - cx, a[1] - cy), r1 = std::hypot(b[0] - cx, b[1] - cy);
  if (!(r0 > 0) || !std::isfinite(r0) || std::fabs(r0 - r1) > 1e-9 * std::max(r0, r1))
    fail(ErrorCode::MalformedInput, i, "from and to lie at distances " + formatNumber(r0) + " and " + formatNumber(r1) +
                                           " from the center, which differ beyond rounding");
  const double start = std::atan2(a[1] - cy, a[0] - cx);
  double sweep = std::atan2(b[1] - cy, b[0] - cx) - start;
  if (sweep <= 0) sweep += kTwoPi;
  const double c[5] = {cx, cy, r0, start, sweep};
  std::copy(c, c + 5, s.c);
  return s;
}

// The parameters cutting curve s into pieces within `tolerance` and their chords' disks.
std::vector<double> cutPoints(const CurveShape& s, double tolerance, std::size_t i) {
  std::vector<double> t{0};
  if (s.type == CurveType::Arc) {
    const double r = s.c[2], sweep = s.c[4];
    // The turn whose sagitta r (1 - cos(turn / 2)) is the tolerance (atan2, which the core links
    // already, for acos).
    const double c = 1 - tolerance / r;
    const double turnWithin = tolerance < 2 * r ? 2 * std::atan2(std::sqrt(1 - c * c), c) : kTwoPi;
    const double n = std::ceil(std::max(sweep / kArcPieceTurn, sweep / turnWithin) * (1 + 1e-12));
    if (!(n <= double(kMaxPieces))) fail(ErrorCode::TooLarge, i, "the curve tolerance asks for more than 2^22 pieces");
    for (double k = 1; k < n; ++k) t.push_back(k / n);
    t.push_back(1);
    return t;
  }
  // Bisection, depth first from the start: the parameters come out in order.
  std::vector<std::pair<double, int>> ends{{1.0, 0}};
  double from = 0;
  while (!ends.empty()) {
    const auto [to, depth] = ends.back();
    if (s.chordError(from, to) <= tolerance && s.withinDisk(from, to)) {
      t.push_back(to), from = to, ends.pop_back();
      continue;
    }
    if (depth == kMaxBisections || t.size() + ends.size() > kMaxPieces)
      fail(ErrorCode::MalformedInput, i, "its pieces do not flatten (a cusp, or a tolerance too small for it)");
    ends.back().second = depth + 1;
    ends.push_back({(from + to) / 2, depth + 1});
  }
  return t;
}

// Whether p lies strictly inside the convex hull of the four points q: inside one of the triangles
// three of them make (a hull's corners and edges, a piece's ends among them, are not inside).
bool strictlyInside(const double q[8], const double p[2]) {
  static constexpr int kTriangles[4][3] = {{0, 1, 3}, {0, 2, 3}, {0, 1, 2}, {1, 2, 3}};
  for (const auto& t : kTriangles) {
    const double* a = q + 2 * t[0];
    const double* b = q + 2 * t[1];
    const double* c = q + 2 * t[2];
    const double o1 = orient2d(a, b, p), o2 = orient2d(b, c, p), o3 = orient2d(c, a, p);
    if ((o1 > 0 && o2 > 0 && o3 > 0) || (o1 < 0 && o2 < 0 && o3 < 0)) return true;
  }
  return false;
}

// The input's finite points bucketed on a grid over their bounding box (a counting sort: no
// comparison sort, whose code the size-compiled wasm would carry), for the pieces' hull tests.
class PointGrid {
 public:
  explicit PointGrid(const Plc& plc) : xy_(plc.points) {
    const std::size_t n = xy_.size() / 2;
    double hi[2] = {-HUGE_VAL, -HUGE_VAL}, largest = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (finite(i))
        for (int k = 0; k < 2; ++k) {
          const double v = xy_[2 * i + k];
          lo_[k] = std::fmin(lo_[k], v), hi[k] = std::fmax(hi[k], v), largest = std::fmax(largest, std::fabs(v));
        }
    // 2^-40 of the largest magnitude: what the validator calls near-duplicates.
    nearby = 0x1p-40 * largest;
    side_ = std::uint32_t(std::fmin(1024, std::ceil(std::sqrt(double(n)))));
    if (side_ == 0) return;
    cell_ = std::fmax(hi[0] - lo_[0], hi[1] - lo_[1]) / side_;
    if (!(cell_ > 0 && std::isfinite(cell_))) cell_ = 1;
    // Counts, then their running sums (each cell's end), then each point placed before its cell's
    // end, which leaves start_[c] at cell c's first entry.
    start_.assign(std::size_t(side_) * side_ + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
      if (finite(i)) ++start_[cellOf(i)];
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    order_.resize(start_.back());
    for (std::size_t i = 0; i < n; ++i)
      if (finite(i)) order_[--start_[cellOf(i)]] = std::uint32_t(i);
  }

  // The first input point in the box [lo, hi] strictly inside the convex hull of the four points
  // `hull` (strictlyInside), or in it at all without one; UINT32_MAX if none.
  std::uint32_t find(const double lo[2], const double hi[2], const double* hull) const {
    if (side_ == 0) return UINT32_MAX;
    const std::uint32_t x0 = coordinate(lo[0], 0), x1 = coordinate(hi[0], 0), y0 = coordinate(lo[1], 1), y1 = coordinate(hi[1], 1);
    for (std::uint32_t y = y0; y <= y1; ++y)
      for (std::uint32_t x = x0; x <= x1; ++x)
        for (std::uint32_t k = start_[y * side_ + x]; k < start_[y * side_ + x + 1]; ++k) {
          const double* p = &xy_[2 * std::size_t(order_[k])];
          if (p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1] && (!hull || strictlyInside(hull, p))) return order_[k];
        }
    return UINT32_MAX;
  }

  double nearby = 0;  // closer than this, a new point would duplicate an input point

 private:
  bool finite(std::size_t i) const { return std::isfinite(xy_[2 * i]) && std::isfinite(xy_[2 * i + 1]); }
  std::uint32_t coordinate(double v, int k) const {
    const double c = std::floor((v - lo_[k]) / cell_);
    return c > 0 ? std::uint32_t(std::fmin(c, side_ - 1)) : 0;  // NaN and below go to 0
  }
  std::size_t cellOf(std::size_t i) const { return std::size_t(coordinate(xy_[2 * i + 1], 1)) * side_ + coordinate(xy_[2 * i], 0); }

  const std::vector<double>& xy_;
  double lo_[2] = {HUGE_VAL, HUGE_VAL}, cell_ = 1;
  std::uint32_t side_ = 0;
  std::vector<std::uint32_t> start_, order_;  // per cell, its first entry in order_; point indices by cell
};

bool hullHoldsPoint(const CurveShape& s, double t0, double t1, const PointGrid& points) {
  double q[8];
  s.hull(t0, t1, q);
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for (int k = 0; k < 8; ++k) lo[k % 2] = std::fmin(lo[k % 2], q[k]), hi[k % 2] = std::fmax(hi[k % 2], q[k]);
  return points.find(lo, hi, q) != UINT32_MAX;
}

// The input point within `nearby` of the curve's point at t, if any: a point on the curve there.
std::uint32_t inputPointAt(const CurveShape& s, double t, const PointGrid& points) {
  double c[2];
  s.point(t, c);
  const double lo[2] = {c[0] - points.nearby, c[1] - points.nearby}, hi[2] = {c[0] + points.nearby, c[1] + points.nearby};
  return points.find(lo, hi, nullptr);
}

// A curve's cut: the parameters of its pieces' ends, and per inner end the input point that is
// there (on the curve to rounding) or UINT32_MAX for a new point.
struct Cut {
  std::vector<double> t;
  std::vector<std::uint32_t> inputPoint;
};

// The cut t with every piece halved while an input point lies strictly inside its hull (curves.h).
// A halving that lands on an input point ends its pieces there instead of duplicating it.
Cut clearOfPoints(const CurveShape& s, const std::vector<double>& t, const PointGrid& points, std::size_t i) {
  Cut out{{t.front()}, {UINT32_MAX}};
  for (std::size_t j = 1; j < t.size(); ++j) {
    // Depth first, as cutPoints: (parameter, halvings) of the ends still ahead, and their points.
    std::vector<std::pair<double, int>> ends{{t[j], 0}};
    std::vector<std::uint32_t> there{inputPointAt(s, t[j], points)};
    double from = t[j - 1];
    while (!ends.empty()) {
      const auto [to, depth] = ends.back();
      if (depth == kMaxPointHalvings || !hullHoldsPoint(s, from, to, points)) {
        out.t.push_back(to), out.inputPoint.push_back(there.back()), from = to, ends.pop_back(), there.pop_back();
        continue;
      }
      if (out.t.size() + ends.size() + t.size() > kMaxPieces) fail(ErrorCode::TooLarge, i, "the points near it ask for more than 2^22 pieces");
      const double mid = (from + to) / 2;
      ends.back().second = depth + 1;
      ends.push_back({mid, depth + 1}), there.push_back(inputPointAt(s, mid, points));
    }
  }
  out.inputPoint.back() = UINT32_MAX;  // the curve's own end
  return out;
}

double defaultTolerance(const Plc& plc) {
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for (std::size_t k = 0; k < plc.points.size(); ++k)
    lo[k % 2] = std::min(lo[k % 2], plc.points[k]), hi[k % 2] = std::max(hi[k % 2], plc.points[k]);
  return 1e-3 * std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
}

// Curve i's pieces into out (points and segments) and pieces.
void addPieces(Plc& out, const CurveShape& s, const Cut& cut, std::size_t i, CurvePieces& pieces) {
  const Curve& cv = out.curves[i];
  const std::uint32_t k = out.attributesPerPoint;
  const std::vector<double>& t = cut.t;
  std::uint32_t previous = cv.from;
  for (std::size_t j = 1; j < t.size(); ++j) {
    std::uint32_t next = cv.to;
    const std::uint32_t there = cut.inputPoint[j];
    if (j + 1 < t.size() && there != UINT32_MAX && there != previous && there != cv.from && there != cv.to) {
      next = there;
    } else if (j + 1 < t.size()) {
      double p[2];
      s.point(t[j], p);
      next = static_cast<std::uint32_t>(out.points.size() / 2);
      out.points.push_back(p[0]), out.points.push_back(p[1]);
      if (!out.pointMarkers.empty()) out.pointMarkers.push_back(cv.marker);
      // Attributes vary linearly in the parameter between the curve's ends.
      for (std::uint32_t a = 0; a < k && !out.pointAttributes.empty(); ++a)
        out.pointAttributes.push_back((1 - t[j]) * out.pointAttributes[std::size_t(cv.from) * k + a] +
                                      t[j] * out.pointAttributes[std::size_t(cv.to) * k + a]);
    }
    out.segments.push_back(previous), out.segments.push_back(next);
    pieces.curveOf.push_back(static_cast<std::uint32_t>(i));
    pieces.t0.push_back(t[j - 1]), pieces.t1.push_back(t[j]);
    previous = next;
  }
}

}  // namespace

Plc withCurvePieces(const Plc& plc, const Options& options, CurvePieces& pieces) {
  if (!plc.triangles.empty()) throw Error(ErrorCode::MalformedInput, "curves cannot be given with triangles (refining a mesh)");
  if (std::isnan(options.curveTolerance) || std::isinf(options.curveTolerance))
    throw Error(ErrorCode::InvalidOption, "curveTolerance must be a finite number, not " + formatNumber(options.curveTolerance));
  const double tolerance = options.curveTolerance > 0 ? options.curveTolerance : defaultTolerance(plc);
  Plc out = plc;
  const std::size_t userSegments = plc.segments.size() / 2;
  pieces.first = static_cast<std::int32_t>(userSegments);
  pieces.firstPoint = static_cast<std::uint32_t>(plc.points.size() / 2);
  pieces.tolerance = tolerance;
  bool marked = false;
  const PointGrid points(plc);
  for (std::size_t i = 0; i < plc.curves.size(); ++i) {
    pieces.shapes.push_back(shapeOf(plc, i));
    const CurveShape& s = pieces.shapes.back();
    addPieces(out, s, clearOfPoints(s, cutPoints(s, tolerance, i), points, i), i, pieces);
    marked = marked || plc.curves[i].marker != 0;
  }
  if (marked || !plc.segmentMarkers.empty()) {
    out.segmentMarkers.resize(userSegments, 0);
    for (const Curve& cv : plc.curves) out.segmentMarkers.push_back(cv.marker);
  }
  return out;
}

void scaleCurves(CurvePieces& pieces, const PreparedInput& input) {
  const double factor = input.toInternal(1.0);
  for (CurveShape& s : pieces.shapes) s.scale(factor);
  pieces.tolerance = input.toInternal(pieces.tolerance);
}

void rejectRepairedCurves(const std::vector<Notice>& notices, const CurvePieces& pieces) {
  auto name = [&](std::int64_t segment) {
    if (!pieces.isPiece(static_cast<std::int32_t>(segment))) return "segment " + std::to_string(segment);
    return "curve " + std::to_string(pieces.curveOf[std::size_t(segment - pieces.first)]);
  };
  for (const Notice& n : notices) {
    const bool a = n.a >= pieces.first, b = n.b >= pieces.first;
    const std::string at = " near (" + formatNumber(n.x) + ", " + formatNumber(n.y) + ")";
    switch (n.kind) {
      case NoticeKind::SegmentsCross:
      case NoticeKind::SegmentsOverlap:
        if (a || b) {
          const std::string first = a ? name(n.a) : name(n.b), second = a ? name(n.b) : name(n.a);
          throw Error(ErrorCode::MalformedInput, first + (first == second ? " crosses itself" : " crosses or touches " + second) +
                                                     at + " (its pieces' chords meet); curves are not repaired");
        }
        break;
      case NoticeKind::VertexOnSegment:
        if (a) throw Error(ErrorCode::MalformedInput, name(n.a) + ": point " + std::to_string(n.b) + " lies on a chord of its pieces; curves are not repaired");
        break;
      case NoticeKind::ZeroLengthSegment:
      case NoticeKind::DuplicateSegment:
        if (a || b) throw Error(ErrorCode::MalformedInput, name(a ? n.a : n.b) + ": a piece has zero length or repeats another edge");
        break;
      default:
        break;
    }
  }
}

}  // namespace ruppert::detail

RUPPERT_COLD_END
