// One ordering of points, shared by the stages that sort them (duplicate merging in prepare_input,
// the hull in segment_insertion): by a key, then x, then y, then index. One std::sort instantiation
// for both instead of one each (5 KB of the wasm module).
#pragma once

#include <cstdint>
#include <vector>

namespace ruppert::detail {

struct KeyedPoint {
  std::uint32_t key, index;
  double x, y;
};

// Sorts by key, then x, then y, then index: identical points end up adjacent, lowest index first.
void sortPoints(std::vector<KeyedPoint>& points);

}  // namespace ruppert::detail
