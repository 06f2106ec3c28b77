// Angle statistics over every output triangle: the smallest and largest angle and a histogram of
// one-degree bins, as if every angle were computed with atan2, without an arctangent per angle.
//
// Each angle is binned by q = cos|cos| = (u.w)|u.w| / (|u|^2 |w|^2), which falls strictly as the
// angle grows from 0 to 180 degrees: a table of q at every whole degree, entered through a coarse
// index over q, gives the bin in a step or two. Where q lies within rounding of a bin's edge (an angle
// of exactly 30 degrees is common: off-centers make them) the triangle's angles are computed with
// atan2 as before, so the bins are the ones atan2 gives. The extremes are chosen by sin^2 (precise
// for needles and flat triangles alike, where cos^2 rounds to 1) and then computed with atan2.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace ruppert::detail {

// The three angles (radians) of triangle (p[0], p[1], p[2]): two arctangents, the third is what
// remains of pi (its rounding error is ~1e-16 rad).
void triangleAngles(const double* const* p, double angle[3]);

class AngleStats {
 public:
  AngleStats();
  // One copy for its two callers (refinement's census, output assembly): the module stays small.
  [[gnu::noinline]] void add(const double* p0, const double* p1, const double* p2);
  // 180 counts; an angle of exactly 180 degrees counts in the last bin.
  const std::vector<std::uint64_t>& histogram() const { return histogram_; }
  // The histogram moved out (no copy), once every angle is in.
  std::vector<std::uint64_t> takeHistogram() { return std::move(histogram_); }
  // Degrees; 0 when nothing was added.
  double minAngle() const;
  double maxAngle() const;
  // Both, as minAngle() and maxAngle() give them.
  void extremes(double& minAngle, double& maxAngle) const;

 private:
  void addExact(const double* const* p);
  std::vector<std::uint64_t> histogram_;
  // The triangles holding the extremes (copied: the caller's arrays may move).
  double smallest_[6] = {}, largest_[6] = {};
  double smallestKey_ = 0, largestKey_ = 0;  // sine^2 of each extreme angle
  bool largestObtuse_ = false;
  bool any_ = false;
};

}  // namespace ruppert::detail
