#include "point_attributes.h"

#include <vector>

namespace ruppert::detail {

void initAttributes(MeshState& m) {
  const Plc& plc = *m.plc;
  const std::uint32_t k = plc.attributesPerPoint;
  m.attributeCount = plc.pointAttributes.empty() ? 0 : k;
  m.attributes.assign(std::size_t(m.attributeCount) * m.tri.vertexCount(), 0.0);
  for (std::uint32_t v = 0; v < m.inputCount && m.attributeCount; ++v) {
    const std::size_t from = std::size_t(m.input.inputIndex[v]) * k;
    for (std::uint32_t j = 0; j < k; ++j) m.attributes[std::size_t(v) * k + j] = plc.pointAttributes[from + j];
  }
}

void interpolateOnSegment(MeshState& m, std::uint32_t v, std::uint32_t a, std::uint32_t b) {
  const std::uint32_t k = m.attributeCount;
  if (k == 0) return;
  const double* pa = m.tri.pt(a), *pb = m.tri.pt(b), *pv = m.tri.pt(v);
  const double dx = pb[0] - pa[0], dy = pb[1] - pa[1], len2 = dx * dx + dy * dy;
  const double t = len2 > 0 ? ((pv[0] - pa[0]) * dx + (pv[1] - pa[1]) * dy) / len2 : 0.5;
  for (std::uint32_t j = 0; j < k; ++j) {
    const double fa = m.attributes[std::size_t(a) * k + j], fb = m.attributes[std::size_t(b) * k + j];
    m.attributes[std::size_t(v) * k + j] = fa + t * (fb - fa);
  }
}

void interpolateInTriangle(MeshState& m, std::uint32_t v, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                           const double* p) {
  const std::uint32_t k = m.attributeCount;
  if (k == 0) return;
  const double* pa = m.tri.pt(a), *pb = m.tri.pt(b), *pc = m.tri.pt(c);
  const double x = p ? p[0] : m.tri.pt(v)[0], y = p ? p[1] : m.tri.pt(v)[1];
  // Barycentric coordinates from signed areas (the triangle is counter-clockwise and not flat).
  const double area = (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pb[1] - pa[1]) * (pc[0] - pa[0]);
  if (!(area != 0)) return interpolateOnSegment(m, v, a, b);
  const double wa = ((pb[0] - x) * (pc[1] - y) - (pb[1] - y) * (pc[0] - x)) / area;
  const double wb = ((pc[0] - x) * (pa[1] - y) - (pc[1] - y) * (pa[0] - x)) / area;
  const double wc = 1 - wa - wb;
  std::vector<double> values(k);
  for (std::uint32_t j = 0; j < k; ++j)
    values[j] = wa * m.attributes[std::size_t(a) * k + j] + wb * m.attributes[std::size_t(b) * k + j] +
                wc * m.attributes[std::size_t(c) * k + j];
  for (std::uint32_t j = 0; j < k; ++j) m.attributes[std::size_t(v) * k + j] = values[j];
}

}  // namespace ruppert::detail
