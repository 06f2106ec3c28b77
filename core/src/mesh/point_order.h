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

// Sorts `keyed` (key << 32 | index, one per point; xy holds point index's coordinates at 2 index)
// into the same order as sortPoints: a radix sort on the keys, then runs of one key by x, y and
// index. A comparison sort of 10^6 KeyedPoints costs a twentieth of a CDT's whole process, and
// 24 bytes per point.
void sortByKey(std::vector<std::uint64_t>& keyed, const std::vector<double>& xy);

}  // namespace ruppert::detail
