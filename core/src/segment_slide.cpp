#include "segment_slide.h"

#include <algorithm>

#include "predicates.h"
#include "triangle_shape.h"

namespace ruppert::detail {

namespace {

std::uint32_t cornerOf(const Triangulation& t, std::uint32_t s, std::uint32_t v) {
  for (std::uint32_t i = 0; i < 3; ++i)
    if (t.tv[3 * s + i] == v) return 3 * s + i;
  return kNone;
}

constexpr int kMaxFan = 64;

}  // namespace

bool segmentVertexFan(const Triangulation& t, std::uint32_t v, std::vector<std::uint32_t>& star, std::uint32_t ends[2]) {
  const std::uint32_t start = t.vtri[v];
  if (start == kNone || !t.alive(start)) return false;
  // Back to the fan's first triangle (across next3(h), the edge into v), or once round.
  std::uint32_t first = start;
  for (int n = 0; n < kMaxFan; ++n) {
    const std::uint32_t h = cornerOf(t, first, v);
    if (h == kNone) return false;
    const std::uint32_t g = t.twin[next3(h)];
    if (g == kNone || g / 3 == start) break;
    first = g / 3;
  }
  // Forward across prev3(h), the edge out of v, collecting the fan.
  star.clear();
  for (std::uint32_t s = first;;) {
    const std::uint32_t h = cornerOf(t, s, v);
    if (h == kNone || star.size() >= std::size_t(kMaxFan)) return false;
    star.push_back(h);
    const std::uint32_t g = t.twin[prev3(h)];
    if (g == kNone || g / 3 == first) break;
    s = g / 3;
  }
  // The constrained edges at v: exactly two other ends, on one constraint.
  int found = 0;
  std::int32_t con = kFree;
  for (std::uint32_t h : star)
    for (std::uint32_t e : {prev3(h), next3(h)}) {
      if (t.con[e] == kFree) continue;
      const std::uint32_t other = t.origin(e) == v ? t.dest(e) : t.origin(e);
      if ((found > 0 && ends[0] == other) || (found > 1 && ends[1] == other)) continue;
      if (found == 2 || (found > 0 && t.con[e] != con)) return false;
      con = t.con[e];
      ends[found++] = other;
    }
  return found == 2;
}

bool bestSlide(const Triangulation& t, const std::vector<std::uint32_t>& star, const double* u, const double* w,
               double sin2Bound, double x[2]) {
  double best = -1;
  for (int k = 6; k <= 34; ++k) {
    const double along = k / 40.0;
    const double p[2] = {u[0] + along * (w[0] - u[0]), u[1] + along * (w[1] - u[1])};
    double worst = 1;
    for (std::uint32_t h : star) {
      const double* a = t.pt(t.origin(h));
      const double* b = t.pt(t.dest(h));
      if (!(orient2d(a, b, p) > 0)) {
        worst = -1;
        break;
      }
      worst = std::min(worst, qualityOf(a, b, p).sin2MinAngle);
    }
    if (worst > best) best = worst, x[0] = p[0], x[1] = p[1];
  }
  return best >= sin2Bound;
}

}  // namespace ruppert::detail
