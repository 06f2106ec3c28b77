#include "mesh/point_order.h"

#include <algorithm>
#include <cstddef>

#include "cold_code.h"
#include "mesh/huge_pages.h"

namespace ruppert::detail {

void sortPoints(std::vector<KeyedPoint>& points) {
  std::sort(points.begin(), points.end(), [](const KeyedPoint& a, const KeyedPoint& b) {
    if (a.key != b.key) return a.key < b.key;
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.index < b.index;
  });
}

// Once per call, linear in the points: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN
void sortByKey(std::vector<std::uint64_t>& keyed, const std::vector<double>& xy) {
  const std::size_t n = keyed.size();
  // Least significant byte of the key first: each pass is stable, so after the fourth the keys are
  // in order and, the index being the low word, each key's points in input order.
  std::vector<std::uint64_t> buffer;
  reserveHuge(buffer, n);
  buffer.resize(n);
  for (int shift = 32; shift < 64; shift += 8) {
    std::size_t start[257] = {};
    for (std::uint64_t k : keyed) ++start[((k >> shift) & 0xFF) + 1];
    if (start[1] == n) continue;  // one value of this byte throughout
    for (int b = 0; b < 256; ++b) start[b + 1] += start[b];
    for (std::uint64_t k : keyed) buffer[start[(k >> shift) & 0xFF]++] = k;
    keyed.swap(buffer);
  }
  // Runs of one key (one cell of the grid, short unless points repeat) by x, y, then index.
  std::vector<KeyedPoint> run;
  for (std::size_t k = 0; k < n;) {
    std::size_t j = k + 1;
    while (j < n && keyed[j] >> 32 == keyed[k] >> 32) ++j;
    if (j - k > 1) {
      run.clear();
      for (std::size_t i = k; i < j; ++i) {
        const std::uint32_t index = static_cast<std::uint32_t>(keyed[i]);
        run.push_back({0, index, xy[2 * std::size_t(index)], xy[2 * std::size_t(index) + 1]});
      }
      sortPoints(run);
      for (std::size_t i = k; i < j; ++i) keyed[i] = (keyed[i] >> 32 << 32) | run[i - k].index;
    }
    k = j;
  }
}

RUPPERT_COLD_END

}  // namespace ruppert::detail
