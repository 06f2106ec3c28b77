// The chapter's exemptions (§6.6), see exemptions.h.
#include "refine/exemptions.h"

#include <algorithm>
#include <cmath>

#include "refine/refiner.h"
#include "cold_code.h"

namespace ruppert::detail {

// The triangle's smallest angle is an input angle: both edges at that corner are subsegments.
bool nestledInInputAngle(const MeshState& m, std::uint32_t s, const TriangleShape& sh) {
  const std::uint32_t i = static_cast<std::uint32_t>(sh.shortestEdge);  // the smallest angle's corner
  return m.tri.con[3 * s + (i + 1) % 3] != kFree && m.tri.con[3 * s + (i + 2) % 3] != kFree;
}

// Asked only of skinny (or wide) triangles that are not nestled, and most leave at the first test
// (u and w not both split vertices): compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN
// Shortest edge u-w is seditious: u and w split two different segments that meet at a vertex z at
// less than kSeditiousAngle, at the same distance from z (the same concentric shell). z is an
// endpoint the segments share, or the point where they cross (an intersection vertex: shells are
// measured from it too).
bool seditiousShortestEdge(const MeshState& m, std::uint32_t s, const TriangleShape& sh) {
  const std::uint32_t h = 3 * s + static_cast<std::uint32_t>(sh.shortestEdge);
  const std::uint32_t u = m.tri.origin(h), w = m.tri.dest(h);
  if (m.kind[u] != VertexKind::SegmentSplit || m.kind[w] != VertexKind::SegmentSplit) return false;
  // Pieces of one curve count as one segment (CurvePieces::outputId numbers curves after segments).
  const std::int32_t su = m.curves->outputId(m.onSegment[u]), sw = m.curves->outputId(m.onSegment[w]);
  if (su == -1 || sw == -1 || su == sw) return false;
  // An input segment's ends, a curve's, or a hull edge's (which stands for a segment: --convex-hull).
  auto end = [&](std::int32_t code, int e) {
    if (code >= m.curves->first) {
      const Curve& c = m.plc->curves[static_cast<std::size_t>(code - m.curves->first)];
      return m.input.representative[e == 0 ? c.from : c.to];
    }
    return code >= 0 ? m.segmentEnd(static_cast<std::size_t>(code), e) : m.hullEdgeEnds[static_cast<std::size_t>(-2 - code)][e];
  };
  const std::uint32_t a0 = end(su, 0), a1 = end(su, 1);
  const std::uint32_t b0 = end(sw, 0), b1 = end(sw, 1);
  double z[2];
  // Two pieces may share both ends (a curve and a segment or curve between the same points): the
  // shells are those of the end nearer u. From the far end, two vertices near this one lie at
  // nearly equal distances and would pass for one shell.
  const bool shares0 = a0 == b0 || a0 == b1, shares1 = a1 == b0 || a1 == b1;
  if (shares0 || shares1) {
    const std::uint32_t apex = !shares1 || (shares0 && sq(m.tri.pt(u), m.tri.pt(a0)) <= sq(m.tri.pt(u), m.tri.pt(a1))) ? a0 : a1;
    z[0] = m.tri.xy[2 * apex], z[1] = m.tri.xy[2 * apex + 1];
  } else if (!segmentsMeet(m.tri.pt(a0), m.tri.pt(a1), m.tri.pt(b0), m.tri.pt(b1), z)) {
    return false;
  }
  const double ux = m.tri.xy[2 * u] - z[0], uy = m.tri.xy[2 * u + 1] - z[1];
  const double wx = m.tri.xy[2 * w] - z[0], wy = m.tri.xy[2 * w + 1] - z[1];
  if (std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) >= kSeditiousAngle) return false;
  const double du = length(ux, uy), dw = length(wx, wy);
  return std::fabs(du - dw) <= 1e-6 * std::max(du, dw);
}
RUPPERT_COLD_END

// Called once per triangle of the output, only when Options::exemptions asks: compiled for size.
RUPPERT_COLD_BEGIN
ExemptionBounds exemptionBounds(const Options& options) {
  ExemptionBounds b;
  if (options.minAngle > 0) b.sin2Min = sin2Bound(radians(options.minAngle));
  if (options.maxAngle > 0) b.cosMax = std::cos(radians(options.maxAngle)) - 1e-12;  // as Refiner's cosMaxAngle_
  return b;
}

std::uint8_t exemptionOf(const MeshState& m, std::uint32_t s, const ExemptionBounds& bounds) {
  const Triangulation& t = m.tri;
  const double* p[3] = {t.pt(t.tv[3 * s]), t.pt(t.tv[3 * s + 1]), t.pt(t.tv[3 * s + 2])};
  // The refinement's own tests (Refiner::isSkinny, isWide) with the bounds asked for.
  const bool skinny = qualityOf(p[0], p[1], p[2]).sin2MinAngle < bounds.sin2Min;
  if (!skinny && !(bounds.cosMax > -1 && largestAngleCos(p[0], p[1], p[2]) < bounds.cosMax)) return kNotExempt;
  const TriangleShape sh = shapeOf(p[0], p[1], p[2]);
  if (nestledInInputAngle(m, s, sh)) return kExemptSmallInputAngle;
  return seditiousShortestEdge(m, s, sh) ? kExemptSeditiousEdge : kNotExempt;
}
RUPPERT_COLD_END

}  // namespace ruppert::detail
