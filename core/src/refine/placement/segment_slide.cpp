#include "refine/placement/segment_slide.h"

#include <algorithm>

#include "mesh/predicates.h"
#include "refine/placement/refine_geometry.h"
#include "mesh/triangle_shape.h"

namespace ruppert::detail {

namespace {

std::uint32_t cornerOf(const Triangulation& t, std::uint32_t s, std::uint32_t v) {
  for (std::uint32_t i = 0; i < 3; ++i)
    if (t.tv[3 * s + i] == v) return 3 * s + i;
  return kNone;
}

constexpr int kMaxFan = 64;
// The places tried, k = 0 .. kPlaces - 1: (kFirstPlace + k) / 40 of the way from u to w.
constexpr int kFirstPlace = 6, kPlaces = 29;

// Whether, with the vertex at p, the fan triangle (p, a, b) of outer edge h makes an encroachment:
// p of h when h is a subsegment, or a of the new subsegment (p, w) or b of (u, p). A fan whose
// triangles meet the bound encroaches nothing under diametral lenses, but can under closed
// diametral disks (an angle of 120 degrees at 30), and each encroachment splits a subsegment whose
// new vertices slide again, which can run down to the length floor and end incomplete
// (cdt_guitar.poly at 30 degrees with disks, without this check; docs/measurements.md).
bool encroachesAround(const Triangulation& t, std::uint32_t h, const double* a, const double* b, const double* u,
                      const double* w, const double* p, double lensCos2) {
  if (t.con[h] != kFree && encroaches(p, a, b, lensCos2)) return true;
  return (a != w && encroaches(a, p, w, lensCos2)) || (b != u && encroaches(b, u, p, lensCos2));
}

// The fan triangle with outer edge a-u has its corner at u between u->a and the segment, u->w,
// wherever along the segment the vertex goes; likewise at w. Where such a corner's sine is below the
// bound's (narrower than the bound, or so wide that the other two corners are), no slide helps: the
// usual case (a comb of 40 teeth 1/79 wide at 30 degrees: 2,281 of 4,333 tries, 621 of which
// succeed), told without trying the 29 places. The margin leaves a corner within rounding of the
// bound to the full test.
bool endAnglesAllow(const Triangulation& t, const std::vector<std::uint32_t>& star, const double* u, const double* w,
                    double sin2Bound) {
  const double limit = sin2Bound * (1 - 1e-9);
  auto allows = [&](const double* end, const double* other, const double* a) {
    const double ax = a[0] - end[0], ay = a[1] - end[1], sx = other[0] - end[0], sy = other[1] - end[1];
    const double cross = ax * sy - ay * sx, la = ax * ax + ay * ay, ls = sx * sx + sy * sy;
    return !(cross * cross < limit * la * ls);
  };
  for (std::uint32_t h : star) {
    const double* a = t.pt(t.origin(h));
    const double* b = t.pt(t.dest(h));
    if ((a == u && !allows(u, w, b)) || (b == u && !allows(u, w, a)) || (a == w && !allows(w, u, b)) ||
        (b == w && !allows(w, u, a)))
      return false;
  }
  return true;
}

void placeAt(const double* u, const double* w, int k, double p[2]) {
  const double along = (kFirstPlace + k) / 40.0;
  p[0] = u[0] + along * (w[0] - u[0]), p[1] = u[1] + along * (w[1] - u[1]);
}

// The skinny triangle alone, at every place in one tight loop, into open[]: where a slide fails past
// endAnglesAllow, it is mostly here (the comb: 950 of the other 2,052 tries; three meshes of it took
// 159.9 M instructions when each place tested the whole fan, 150.3 M with this, the same mesh).
// False when it meets the bound nowhere. (A skinny slot not in the star: its first triangle.)
bool skinnyMeetsBound(const Triangulation& t, const std::vector<std::uint32_t>& star, std::uint32_t skinny,
                      const double* u, const double* w, double sin2Bound, bool open[kPlaces]) {
  std::size_t lead = 0;
  while (lead + 1 < star.size() && star[lead] / 3 != skinny) ++lead;
  if (star[lead] / 3 != skinny) lead = 0;
  const double* a = t.pt(t.origin(star[lead]));
  const double* b = t.pt(t.dest(star[lead]));
  bool any = false;
  for (int k = 0; k < kPlaces; ++k) {
    double p[2];
    placeAt(u, w, k, p);
    open[k] = !(qualityOf(a, b, p).sin2MinAngle < sin2Bound);
    any = any || open[k];
  }
  return any;
}

// The fan's smallest sin^2 with its vertex at p, or -1 where p is of no use: a triangle below the
// bound or not above `best` (its smallest then cannot win), or clockwise, or an encroachment. The
// cheap measure first; the exact orientation and the encroachments only for triangles that pass it.
double fanQuality(const Triangulation& t, const std::vector<std::uint32_t>& star, const double* u, const double* w,
                  const double* p, double best, double sin2Bound, double lensCos2) {
  const double needed = std::max(best, sin2Bound);
  double worst = 1;
  for (std::uint32_t h : star) {
    const double* a = t.pt(t.origin(h));
    const double* b = t.pt(t.dest(h));
    const double quality = qualityOf(a, b, p).sin2MinAngle;
    if (quality < needed || (quality == needed && best >= sin2Bound) || !(orient2d(a, b, p) > 0) ||
        encroachesAround(t, h, a, b, u, w, p, lensCos2))
      return -1;
    worst = std::min(worst, quality);
  }
  return worst;
}

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
               std::uint32_t skinny, double sin2Bound, double lensCos2, double x[2]) {
  bool open[kPlaces];
  if (!endAnglesAllow(t, star, u, w, sin2Bound) || !skinnyMeetsBound(t, star, skinny, u, w, sin2Bound, open)) return false;
  double best = -1;
  for (int k = 0; k < kPlaces; ++k) {
    if (!open[k]) continue;
    double p[2];
    placeAt(u, w, k, p);
    const double worst = fanQuality(t, star, u, w, p, best, sin2Bound, lensCos2);
    if (worst > best) best = worst, x[0] = p[0], x[1] = p[1];
  }
  return best >= sin2Bound;
}

}  // namespace ruppert::detail
