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
namespace {

// Below this many points one comparison sort beats the radix passes, whose 256-entry counts cost
// about 1,500 instructions each whatever the number of points.
constexpr std::size_t kComparisonSortBelow = 64;

// The points of `keyed` (key << 32 | index) with their coordinates, as sortPoints takes them.
void keyedPoints(const std::vector<std::uint64_t>& keyed, std::size_t from, std::size_t to,
                 const std::vector<double>& xy, std::vector<KeyedPoint>& out) {
  out.clear();
  out.reserve(to - from);
  for (std::size_t i = from; i < to; ++i) {
    const std::uint32_t index = static_cast<std::uint32_t>(keyed[i]);
    out.push_back({static_cast<std::uint32_t>(keyed[i] >> 32), index, xy[2 * std::size_t(index)],
                   xy[2 * std::size_t(index) + 1]});
  }
}

}  // namespace

void sortByKey(std::vector<std::uint64_t>& keyed, const std::vector<double>& xy) {
  const std::size_t n = keyed.size();
  std::vector<KeyedPoint> run;
  if (n < kComparisonSortBelow) {
    keyedPoints(keyed, 0, n, xy, run);
    sortPoints(run);
    for (std::size_t i = 0; i < n; ++i) keyed[i] = std::uint64_t(run[i].key) << 32 | run[i].index;
    return;
  }
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
  for (std::size_t k = 0; k < n;) {
    std::size_t j = k + 1;
    while (j < n && keyed[j] >> 32 == keyed[k] >> 32) ++j;
    if (j - k > 1) {
      keyedPoints(keyed, k, j, xy, run);
      sortPoints(run);
      for (std::size_t i = k; i < j; ++i) keyed[i] = (keyed[i] >> 32 << 32) | run[i - k].index;
    }
    k = j;
  }
}

RUPPERT_COLD_END

}  // namespace ruppert::detail
