#include "cdt/prepare_input.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

#include "cold_code.h"
#include "message.h"
#include "mesh/huge_pages.h"
#include "mesh/point_order.h"
#include "mesh/predicates.h"

// Once per call, linear in the input (a sort aside): compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

namespace ruppert::detail {

namespace {

[[noreturn]] void fail(ErrorCode code, const std::string& message) { throw Error(code, message); }

void checkOptions(const Options& o) {
  // The range is the option table's. The message writes it out: formatting it from the table cost
  // the mesher 87 bytes gzipped; tests/core/test_input_repair.cpp checks that the two agree.
  using Angle = option::minAngle;
  if (!(o.minAngle >= Angle::low && o.minAngle <= Angle::high))
    fail(ErrorCode::InvalidOption, "minAngle = " + formatNumber(o.minAngle) + " is outside [0, 60] degrees");
  // Any maxAngle above 60 degrees is compatible with any minAngle up to 60: the equilateral
  // triangle meets both. At or below 60 only equilateral triangles would do, which no domain with
  // another angle can be cut into.
  if (!(o.maxAngle == 0 || (o.maxAngle > 60 && o.maxAngle < 180)))
    fail(ErrorCode::InvalidOption,
         "maxAngle = " + formatNumber(o.maxAngle) + " must be above 60 and below 180 degrees (or 0 for no bound)");
  if (std::isnan(o.maxArea) || o.maxArea < 0)
    fail(ErrorCode::InvalidOption,
         "maxArea = " + formatNumber(o.maxArea) + " must be a positive area (or 0 for no bound)");
}

// Hilbert index of (x, y) on a 2^16 x 2^16 grid: consecutive points in this order are close,
// which keeps point-location walks short.
std::uint32_t hilbertKey(std::uint32_t x, std::uint32_t y) {
  std::uint32_t d = 0;
  for (std::uint32_t s = 1u << 15; s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += s * s * ((3 * rx) ^ ry);
    if (ry == 0) {  // rotate the quadrant so the curve stays continuous
      if (rx == 1) {
        x = s - 1 - (x & (s - 1)) + (x & ~(s - 1));
        y = s - 1 - (y & (s - 1)) + (y & ~(s - 1));
      }
      std::swap(x, y);
    }
  }
  return d;
}

// "points[i] duplicates points[rep]; merged", written into one buffer: there is one per merged point.
std::string duplicateMessage(std::uint32_t i, std::uint32_t rep) {
  char buf[64];  // 7 + 10 + 20 + 10 + 9 characters at most
  char* p = buf;
  const auto put = [&p](const char* text) {
    while (*text) *p++ = *text++;
  };
  put("points[");
  p = std::to_chars(p, buf + sizeof buf, i).ptr;
  put("] duplicates points[");
  p = std::to_chars(p, buf + sizeof buf, rep).ptr;
  put("]; merged");
  return std::string(buf, p);
}

}  // namespace

// Plc::pointAttributes: attributesPerPoint finite values per point, or none.
void checkAttributes(const Plc& plc, std::size_t n) {
  const std::vector<double>& a = plc.pointAttributes;
  if (a.empty()) return;
  if (plc.attributesPerPoint == 0 || a.size() != std::size_t(plc.attributesPerPoint) * n)
    fail(ErrorCode::MalformedInput, "pointAttributes has " + std::to_string(a.size()) + " values for " +
                                        std::to_string(n) + " points with attributesPerPoint = " +
                                        std::to_string(plc.attributesPerPoint));
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!std::isfinite(a[i]))
      fail(ErrorCode::NonFiniteCoordinate, "pointAttributes[" + std::to_string(i) + "] (point " +
                                               std::to_string(i / plc.attributesPerPoint) + ") = " +
                                               formatNumber(a[i]) + " is not finite");
}

namespace {

// Even lengths of points and segments, and the segments' indices in range.
void checkIndices(const Plc& plc) {
  if (plc.points.size() % 2 != 0)
    fail(ErrorCode::MalformedInput,
         "points has odd length " + std::to_string(plc.points.size()) + " (expected x0, y0, x1, y1, ...)");
  if (plc.segments.size() % 2 != 0)
    fail(ErrorCode::MalformedInput, "segments has odd length " + std::to_string(plc.segments.size()) +
                                        " (expected a0, b0, a1, b1, ...)");
  const std::size_t n = plc.points.size() / 2;
  for (std::size_t k = 0; k < plc.segments.size(); ++k) {
    if (plc.segments[k] >= n)
      fail(ErrorCode::IndexOutOfRange, "segments[" + std::to_string(k / 2) + "] refers to point " +
                                           std::to_string(plc.segments[k]) + " but there are " +
                                           std::to_string(n) + " points");
  }
}

}  // namespace

void checkShape(const Plc& plc) {
  checkIndices(plc);
  const std::size_t n = plc.points.size() / 2;
  auto checkMarkers = [](const std::vector<std::int32_t>& markers, const char* name, std::size_t items, const char* what) {
    if (!markers.empty() && markers.size() != items)
      fail(ErrorCode::MalformedInput, std::string(name) + " has length " + std::to_string(markers.size()) + " for " +
                                          std::to_string(items) + what + " (one each, or none)");
  };
  checkMarkers(plc.pointMarkers, "pointMarkers", n, " points");
  checkMarkers(plc.segmentMarkers, "segmentMarkers", plc.segments.size() / 2, " segments");
}

namespace {

// The input's shape and values: lengths, finite coordinates, indices in range, sane regions.
// Returns the largest coordinate magnitude, which sets the scale.
double checkInput(const Plc& plc, const Options& options) {
  checkOptions(options);
  checkIndices(plc);
  if (plc.holes.size() % 2 != 0)
    fail(ErrorCode::MalformedInput, "holes has odd length " + std::to_string(plc.holes.size()));
  const std::size_t n = plc.points.size() / 2;
  if (n == 0) fail(ErrorCode::EmptyInput, "the input has no points");
  if (n > 0x3FFFFFFFu) fail(ErrorCode::TooLarge, "too many points: " + std::to_string(n));

  double maxAbs = 0;
  // Item names like "points[12].x" are only built when something is wrong (this runs per point).
  auto name = [](const char* array, std::size_t i, const char* field) {
    return std::string(array) + "[" + std::to_string(i) + "]" + field;
  };
  auto checkFinite = [&](double v, const char* array, std::size_t i, const char* field) {
    if (!std::isfinite(v))
      fail(ErrorCode::NonFiniteCoordinate, name(array, i, field) + " = " + formatNumber(v) + " is not finite");
    maxAbs = std::max(maxAbs, std::fabs(v));
  };
  for (std::size_t i = 0; i < n; ++i) {
    checkFinite(plc.points[2 * i], "points", i, ".x");
    checkFinite(plc.points[2 * i + 1], "points", i, ".y");
  }
  checkAttributes(plc, n);
  for (std::size_t i = 0; i < plc.holes.size() / 2; ++i) {
    checkFinite(plc.holes[2 * i], "holes", i, ".x");
    checkFinite(plc.holes[2 * i + 1], "holes", i, ".y");
  }
  for (std::size_t i = 0; i < plc.regions.size(); ++i) {
    const Region& r = plc.regions[i];
    checkFinite(r.x, "regions", i, ".x");
    checkFinite(r.y, "regions", i, ".y");
    if (std::isnan(r.attribute))
      fail(ErrorCode::InvalidRegion, "regions[" + std::to_string(i) + "].attribute is NaN");
    if (std::isnan(r.maxArea) || r.maxArea < 0)
      fail(ErrorCode::InvalidRegion, "regions[" + std::to_string(i) + "].maxArea = " + formatNumber(r.maxArea) +
                                         " must be a positive area (or 0 for no bound)");
  }

  return maxAbs;
}

// Scales every coordinate by a power of two (exact) so that the largest magnitude lies in [1, 2):
// sets out's exponent, holes, regions and area bound, and returns every input point, scaled, in
// input order.
std::vector<double> scaleInput(const Plc& plc, const Options& options, double maxAbs, PreparedInput& out) {
  const std::size_t n = plc.points.size() / 2;
  auto name = [](const char* array, std::size_t i, const char* field) {
    return std::string(array) + "[" + std::to_string(i) + "]" + field;
  };
  // Scale by 2^(1-e) where maxAbs = m * 2^e, m in [0.5, 1): the largest magnitude lands in [1, 2).
  if (maxAbs > 0) {
    int e = 0;
    std::frexp(maxAbs, &e);
    out.setExponent(1 - e);
  }
  auto scaled = [&](double v, const char* array, std::size_t i, const char* field) {
    const double s = out.toInternal(v);
    // A nonzero value that scaling takes below the safe range (even down to 0) is an error too.
    if (!isSafeCoordinate(s) || (v != 0 && s == 0))
      fail(ErrorCode::CoordinateRange,
           name(array, i, field) + " = " + formatNumber(v) + " is nonzero but over 2^128 times smaller than the largest coordinate " +
               formatNumber(maxAbs) + "; exact arithmetic cannot resolve such a range");
    return s;
  };
  std::vector<double> xy;  // every input point, scaled, in input order
  reserveHuge(xy, 2 * n);
  xy.resize(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    xy[2 * i] = scaled(plc.points[2 * i], "points", i, ".x");
    xy[2 * i + 1] = scaled(plc.points[2 * i + 1], "points", i, ".y");
  }
  for (std::size_t i = 0; i < plc.holes.size(); ++i)
    out.holes.push_back(scaled(plc.holes[i], "holes", i / 2, ""));
  for (std::size_t i = 0; i < plc.regions.size(); ++i) {
    Region r = plc.regions[i];
    r.x = scaled(r.x, "regions", i, ".x");
    r.y = scaled(r.y, "regions", i, ".y");
    r.maxArea = out.areaToInternal(r.maxArea);
    out.regions.push_back(r);
  }
  out.maxArea = std::isinf(options.maxArea) ? 0 : out.areaToInternal(options.maxArea);

  return xy;
}

// Merges identical points: representative[i] is the input index of the lowest point identical to
// point i, `distinct` the representatives, one DuplicatePoint notice per merged point.
void mergeDuplicates(const Plc& plc, const std::vector<double>& xy, std::vector<std::uint32_t>& representative,
                     std::vector<std::uint32_t>& distinct, std::vector<Notice>& notices) {
  const std::size_t n = plc.points.size() / 2;
  // One sort along a Hilbert curve serves two purposes: identical points share a key, so duplicates
  // are found within runs of equal keys; and the curve order keeps point-location walks short.
  double minX = HUGE_VAL, minY = HUGE_VAL, maxX = -HUGE_VAL, maxY = -HUGE_VAL;
  for (std::size_t i = 0; i < n; ++i) {
    minX = std::min(minX, xy[2 * i]), maxX = std::max(maxX, xy[2 * i]);
    minY = std::min(minY, xy[2 * i + 1]), maxY = std::max(maxY, xy[2 * i + 1]);
  }
  const double span = std::max(maxX - minX, maxY - minY);
  const double toGrid = span > 0 ? 65535.0 / span : 0;
  std::vector<std::uint64_t> sorted;  // key << 32 | index
  reserveHuge(sorted, n);
  sorted.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = xy[2 * i], y = xy[2 * i + 1];
    const std::uint32_t key = hilbertKey(static_cast<std::uint32_t>((x - minX) * toGrid), static_cast<std::uint32_t>((y - minY) * toGrid));
    sorted[i] = std::uint64_t(key) << 32 | i;
  }
  // Within a key, by coordinates then index, so identical points are adjacent, lowest index first.
  sortByKey(sorted, xy);
  reserveHuge(representative, n);
  representative.assign(n, 0);
  distinct.clear();
  reserveHuge(distinct, n);
  std::size_t duplicateCount = 0;
  auto same = [&xy](std::uint64_t a, std::uint64_t b) {
    const std::size_t i = static_cast<std::uint32_t>(a), j = static_cast<std::uint32_t>(b);
    return xy[2 * i] == xy[2 * j] && xy[2 * i + 1] == xy[2 * j + 1];
  };
  for (std::size_t k = 0; k < n;) {
    std::size_t j = k + 1;
    while (j < n && same(sorted[j], sorted[k])) ++j;
    const std::uint32_t rep = static_cast<std::uint32_t>(sorted[k]);
    distinct.push_back(rep);
    for (std::size_t m = k; m < j; ++m) representative[static_cast<std::uint32_t>(sorted[m])] = rep;
    duplicateCount += j - k - 1;
    k = j;
  }
  // One notice per merged point, in input order. The message names the two indices only: the
  // coordinates are the notice's x and y, and printing them shortest-exact (formatNumber) cost
  // ~25 us per duplicate, which dominated whole meshes of inputs with many duplicates.
  notices.reserve(notices.size() + duplicateCount);
  for (std::size_t i = 0; i < n && duplicateCount > 0; ++i) {
    const std::uint32_t rep = representative[i];
    if (rep == i) continue;
    notices.push_back(Notice{NoticeKind::DuplicatePoint, static_cast<std::int64_t>(i), rep, plc.points[2 * rep],
                             plc.points[2 * rep + 1], duplicateMessage(static_cast<std::uint32_t>(i), rep)});
  }

}

// Numbers the distinct points in insertion order (out.inputIndex, out.xy, out.representative).
void orderForInsertion(const std::vector<double>& xy, const std::vector<std::uint32_t>& representative,
                       const std::vector<std::uint32_t>& distinct, PreparedInput& out) {
  const std::size_t n = representative.size();
  // Biased randomised insertion order (BRIO): each point joins round k with probability 2^-(k+1),
  // rounds are inserted from the smallest (highest k) to the largest; a stable split keeps every round
  // in curve order. Randomness bounds the expected work; the curve keeps walks short.
  constexpr int kRounds = 24;
  // splitmix64: its 64 bits per step pass the usual tests, and seeding costs nothing, where a
  // Mersenne twister's seeding was an eighth of a small input's whole mesh.
  std::uint64_t state = 0x5EED5EEDull ^ distinct.size();
  auto rng = [&state] {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  };
  std::vector<std::uint8_t> round(distinct.size());
  std::vector<std::size_t> count(kRounds + 1, 0);
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    std::uint64_t r = rng() | (1ull << (kRounds - 1));
    int k = 0;
    while (!(r & 1)) r >>= 1, ++k;
    round[i] = static_cast<std::uint8_t>(kRounds - 1 - k);  // 0 = the first, smallest round
    ++count[round[i] + 1];
  }
  for (int k = 0; k < kRounds; ++k) count[k + 1] += count[k];
  std::vector<std::uint32_t> order;
  reserveHuge(order, distinct.size());
  order.resize(distinct.size());
  for (std::size_t i = 0; i < distinct.size(); ++i) order[count[round[i]]++] = distinct[i];
  // Renumber: internal vertex k is the k-th point inserted.
  out.inputIndex = std::move(order);
  const std::uint32_t d = out.distinctCount();
  // With room for a plain CDT's other vertices: buildDelaunay takes this array as it is.
  reserveHuge(out.xy, 2 * (std::size_t(d) + kCdtExtraVertices));
  out.xy.resize(2 * std::size_t(d));
  std::vector<std::uint32_t> internalOf;
  reserveHuge(internalOf, n);
  internalOf.resize(n);
  for (std::uint32_t k = 0; k < d; ++k) {
    const std::uint32_t i = out.inputIndex[k];
    internalOf[i] = k;
    out.xy[2 * std::size_t(k)] = xy[2 * std::size_t(i)];
    out.xy[2 * std::size_t(k) + 1] = xy[2 * std::size_t(i) + 1];
  }
  reserveHuge(out.representative, n);
  out.representative.resize(n);
  for (std::size_t i = 0; i < n; ++i) out.representative[i] = internalOf[representative[i]];
}

}  // namespace

PreparedInput prepareInput(const Plc& plc, const Options& options, std::vector<Notice>& notices) {
  const double maxAbs = checkInput(plc, options);
  PreparedInput out;
  const std::vector<double> xy = scaleInput(plc, options, maxAbs, out);
  std::vector<std::uint32_t> representative, distinct;
  mergeDuplicates(plc, xy, representative, distinct, notices);
  orderForInsertion(xy, representative, distinct, out);
  return out;
}

}  // namespace ruppert::detail

RUPPERT_COLD_END
