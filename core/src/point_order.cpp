#include "point_order.h"

#include <algorithm>

namespace ruppert::detail {

void sortPoints(std::vector<KeyedPoint>& points) {
  std::sort(points.begin(), points.end(), [](const KeyedPoint& a, const KeyedPoint& b) {
    if (a.key != b.key) return a.key < b.key;
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.index < b.index;
  });
}

}  // namespace ruppert::detail
