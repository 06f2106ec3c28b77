#include "mesh/angle_stats.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "mesh/triangle_shape.h"  // kPi

namespace ruppert::detail {

namespace {

constexpr int kBins = 180;
// q's index: kIndex buckets of width 2 / kIndex over [-1, 1], narrower than the closest two bin
// edges (sin^2(1 degree) = 3.05e-4 apart, at 0, 90 and 180 degrees), so a bucket holds at most one
// edge and the bin is the bucket's first bin or the next.
constexpr int kIndex = 8192;
// q carries a relative rounding error of a few ulps; within this of a bin's edge, atan2 decides.
constexpr double kEdgeMargin = 1e-12;

struct Tables {
  std::array<double, kBins + 1> edge;            // q at k degrees: strictly decreasing from 1 to -1
  std::array<std::int16_t, kIndex + 1> start;    // the bin of the largest q in bucket b
  Tables() {
    for (int k = 0; k <= kBins; ++k) {
      const double c = std::cos(k * kPi / 180);
      edge[k] = c * std::fabs(c);
    }
    edge[0] = 1, edge[90] = 0, edge[kBins] = -1;
    // top falls as b rises, so each bucket's bin is at or after the previous one's: one sweep.
    // (Searching from bin 0 for each bucket cost 5.3 M instructions, most of a small CLI run.)
    int k = 0;
    for (int b = 0; b <= kIndex; ++b) {
      const double top = 1 - b * (2.0 / kIndex);
      while (k + 1 < kBins && edge[k + 1] >= top) ++k;
      start[b] = static_cast<std::int16_t>(k);
    }
  }
};

const Tables& tables() {
  static const Tables t;
  return t;
}

// The bin of an angle with q = cos|cos| (q in [-1, 1]), and how far q is from that bin's edges.
int binOf(const Tables& t, double q, double& clearance) {
  const int b = static_cast<int>((1 - q) * (kIndex / 2));  // 0 <= b <= kIndex
  int k = t.start[b];
  k += (k + 1 < kBins) & (t.edge[k + 1] >= q);
  clearance = std::min(t.edge[k] - q, q - t.edge[k + 1]);
  return k;
}

// Whether the largest angle with sine^2 s and obtuseness `obtuse` beats the one with (s0, obtuse0).
bool larger(bool obtuse, double s, bool obtuse0, double s0) {
  if (obtuse != obtuse0) return obtuse;
  return obtuse ? s < s0 : s > s0;
}

double degrees(double radians) { return radians * (180 / kPi); }

}  // namespace

void triangleAngles(const double* const* p, double angle[3]) {
  for (int i = 0; i < 2; ++i) {
    const double* o = p[i];
    const double* u = p[(i + 1) % 3];
    const double* w = p[(i + 2) % 3];
    const double ux = u[0] - o[0], uy = u[1] - o[1], wx = w[0] - o[0], wy = w[1] - o[1];
    angle[i] = std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy);
  }
  angle[2] = std::max(0.0, kPi - angle[0] - angle[1]);
}

AngleStats::AngleStats() : histogram_(kBins, 0) { tables(); }

void AngleStats::add(const double* p0, const double* p1, const double* p2) {
  const double* p[3] = {p0, p1, p2};
  // l[i]: squared length of the edge opposite corner i; dot[i]: dot product of corner i's two edge
  // vectors. The product of corner i's two squared edge lengths is l0 l1 l2 / l[i].
  const double ax = p1[0] - p0[0], ay = p1[1] - p0[1];  // p0 -> p1
  const double bx = p2[0] - p0[0], by = p2[1] - p0[1];  // p0 -> p2
  const double cx = p2[0] - p1[0], cy = p2[1] - p1[1];  // p1 -> p2
  const double l[3] = {cx * cx + cy * cy, bx * bx + by * by, ax * ax + ay * ay};
  const double dot[3] = {ax * bx + ay * by, -(ax * cx + ay * cy), bx * cx + by * cy};
  const double cross = ax * by - ay * bx;
  const double inverse = 1 / (l[0] * l[1] * l[2]);
  if (!(inverse > 0 && inverse < HUGE_VAL)) {
    addExact(p);  // a repeated vertex (or squares out of range): atan2 decides
    return;
  }

  // Extremes: the smallest angle faces the shortest edge, the largest the longest; sin^2 of either
  // is cross^2 over its two edges' squared lengths.
  int shortest = 0, longest = 0;
  for (int i = 1; i < 3; ++i) {
    if (l[i] < l[shortest]) shortest = i;
    if (l[i] > l[longest]) longest = i;
  }
  const double smallS = cross * cross * l[shortest] * inverse, largeS = cross * cross * l[longest] * inverse;
  const bool obtuse = dot[longest] < 0;
  if (!any_ || smallS < smallestKey_) {
    smallestKey_ = smallS;
    std::copy(p0, p0 + 2, smallest_), std::copy(p1, p1 + 2, smallest_ + 2), std::copy(p2, p2 + 2, smallest_ + 4);
  }
  if (!any_ || larger(obtuse, largeS, largestObtuse_, largestKey_)) {
    largestKey_ = largeS, largestObtuse_ = obtuse;
    std::copy(p0, p0 + 2, largest_), std::copy(p1, p1 + 2, largest_ + 2), std::copy(p2, p2 + 2, largest_ + 4);
  }
  any_ = true;

  const Tables& t = tables();
  double clearance[3];
  int bin[3];
  for (int i = 0; i < 3; ++i)
    bin[i] = binOf(t, std::clamp(dot[i] * std::fabs(dot[i]) * l[i] * inverse, -1.0, 1.0), clearance[i]);
  if (std::min({clearance[0], clearance[1], clearance[2]}) < kEdgeMargin) {
    addExact(p);
    return;
  }
  for (int k : bin) ++histogram_[k];
}

void AngleStats::addExact(const double* const* p) {
  double angle[3];
  triangleAngles(p, angle);
  for (double a : angle) ++histogram_[std::min<std::size_t>(kBins - 1, static_cast<std::size_t>(degrees(a)))];
  if (!any_) {  // only degenerate triangles so far: they are the extremes
    std::copy(p[0], p[0] + 2, smallest_), std::copy(p[1], p[1] + 2, smallest_ + 2), std::copy(p[2], p[2] + 2, smallest_ + 4);
    std::copy(smallest_, smallest_ + 6, largest_);
    any_ = true, smallestKey_ = 0, largestKey_ = 0, largestObtuse_ = true;
  }
}

// The smallest or the largest angle, in degrees, of the triangle whose corners xy holds.
static double extremeAngle(const double* xy, bool largest) {
  const double* p[3] = {xy, xy + 2, xy + 4};
  double angle[3];
  triangleAngles(p, angle);
  return degrees(largest ? std::max({angle[0], angle[1], angle[2]}) : std::min({angle[0], angle[1], angle[2]}));
}

double AngleStats::minAngle() const { return any_ ? extremeAngle(smallest_, false) : 0; }
double AngleStats::maxAngle() const { return any_ ? extremeAngle(largest_, true) : 0; }

void AngleStats::extremes(double& minAngle, double& maxAngle) const {
  if (!any_ || !std::equal(smallest_, smallest_ + 6, largest_)) {
    minAngle = this->minAngle(), maxAngle = this->maxAngle();
    return;
  }
  // One triangle holds both (every triangle alike, as in a square's two): its angles once.
  const double* p[3] = {smallest_, smallest_ + 2, smallest_ + 4};
  double angle[3];
  triangleAngles(p, angle);
  minAngle = degrees(std::min({angle[0], angle[1], angle[2]}));
  maxAngle = degrees(std::max({angle[0], angle[1], angle[2]}));
}

}  // namespace ruppert::detail
