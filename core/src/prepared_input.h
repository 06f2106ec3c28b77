// The input as the stages see it: scaled by one power of two, duplicates merged, points in
// insertion order. cdt/prepare_input.h makes it; every later stage reads it through MeshState.
//
// The whole input is scaled by one power of two so that the largest coordinate magnitude lies in
// [1, 2): exact (no rounding), so output coordinates of input points come back bit-identical, and
// the robust predicates then work in their safe range whatever the user's units (1e-200 or 1e200).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "ruppert/ruppert.h"

namespace ruppert::detail {

struct PreparedInput {
  // internal coordinate = input coordinate * 2^exponent (exact; ldexp reaches factors beyond the
  // range of a double, which subnormal inputs need). Where 2^exponent and 2^-exponent are both
  // normal doubles a multiplication gives the same correctly rounded result as ldexp, which is a
  // library call (in WebAssembly too) on paths that run per candidate point.
  void setExponent(int e) {
    exponent_ = e;
    const bool normal = e >= -1022 && e <= 1022;
    up_ = normal ? std::ldexp(1.0, e) : 0, down_ = normal ? std::ldexp(1.0, -e) : 0;
  }
  double toInternal(double v) const { return up_ != 0 ? v * up_ : std::ldexp(v, exponent_); }
  double toUser(double v) const { return down_ != 0 ? v * down_ : std::ldexp(v, -exponent_); }
  // Areas scale by 2^(2 exponent); a positive bound never rounds to 0 ("none").
  double areaToInternal(double a) const {
    const double s = std::ldexp(a, 2 * exponent_);
    return a > 0 && s == 0 ? std::numeric_limits<double>::denorm_min() : s;
  }
  // Internal vertices 0 .. distinctCount()-1 are the distinct input points, numbered in insertion
  // order (a spatially coherent random order): the triangulation then touches memory in the order it
  // inserts, which matters more than instructions at 10^6 points.
  std::vector<double> xy;                     // per internal vertex, scaled (until buildDelaunay takes it)
  std::vector<std::uint32_t> inputIndex;      // per internal vertex: the lowest input index at its place
  std::vector<std::uint32_t> representative;  // per input point: the internal vertex it became
  std::uint32_t distinctCount() const { return static_cast<std::uint32_t>(inputIndex.size()); }
  std::vector<double> holes;               // scaled
  std::vector<Region> regions;             // scaled seeds (maxArea scaled by scale^2)
  double maxArea = 0;                      // scaled; 0 = none

 private:
  int exponent_ = 0;           // set only through setExponent, which keeps the two factors in step
  double up_ = 1, down_ = 1;  // 2^exponent and 2^-exponent, or 0 where ldexp must be used
};

}  // namespace ruppert::detail
