#include "refine_setup.h"

#include <algorithm>
#include <cmath>

#include "old_mesh.h"
#include "refine_geometry.h"
#include "triangle_shape.h"

namespace ruppert::detail {

// A corner is acute when two constrained edges at an input or intersection vertex are less than
// 90 degrees apart. The value is 0 for none, else 1 + 254 cos(the smallest gap) (1..255: sharper is
// larger), so that a split between two corners can favour the sharper (refine.cpp). The directions
// are gathered per vertex in one flat array (counting sort by vertex), and the smallest gap is
// between neighbours in angular order: sorted, O(d log d) for a vertex of degree d.
std::vector<std::uint8_t> acuteCorners(const MeshState& m) {
  const Triangulation& t = m.tri;
  const std::uint32_t n = t.vertexCount();
  std::vector<std::uint8_t> corner(n, 0);
  auto counted = [&](std::uint32_t v) {
    return m.kind[v] == VertexKind::Input || m.kind[v] == VertexKind::Intersection;
  };
  std::vector<std::uint32_t> start(n + 1, 0);
  auto forEachEnd = [&](auto&& visit) {
    for (std::uint32_t h = 0; h < t.tv.size(); ++h) {
      if (!t.alive(h / 3) || t.con[h] == kFree) continue;
      if (t.twin[h] != kNone && t.twin[h] < h) continue;  // each edge once
      const std::uint32_t a = t.origin(h), b = t.dest(h);
      if (counted(a)) visit(a, b);
      if (counted(b)) visit(b, a);
    }
  };
  forEachEnd([&](std::uint32_t v, std::uint32_t) { ++start[v + 1]; });
  for (std::uint32_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<double> dir(2 * std::size_t(start[n]));
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  forEachEnd([&](std::uint32_t v, std::uint32_t w) {
    const std::uint32_t k = fill[v]++;
    const double dx = t.xy[2 * w] - t.xy[2 * v], dy = t.xy[2 * w + 1] - t.xy[2 * v + 1];
    const double len = length(dx, dy);
    dir[2 * k] = dx / len, dir[2 * k + 1] = dy / len;
  });
  std::vector<double> angles;
  for (std::uint32_t v = 0; v < n; ++v) {
    if (start[v + 1] - start[v] < 2) continue;
    angles.clear();
    for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) angles.push_back(std::atan2(dir[2 * i + 1], dir[2 * i]));
    std::sort(angles.begin(), angles.end());
    double gap = angles.front() + 2 * kPi - angles.back();
    for (std::size_t i = 1; i < angles.size(); ++i) gap = std::min(gap, angles[i] - angles[i - 1]);
    // cos(gap) > sin(1e-12): the gap is below 90 degrees by more than rounding.
    const double cosine = std::cos(gap);
    if (cosine > 1e-12) corner[v] = static_cast<std::uint8_t>(1 + std::min(254.0, 254 * cosine));
  }
  return corner;
}

// Generous for any reasonable input, yet small enough that a runaway at an unreachable angle stops
// within seconds: ten thousand, plus 200 per input vertex (of the 61 shared PLCs, the complete meshes
// at 33 and 35 degrees use at most 40 Steiner vertices per input vertex once past the first ten
// thousand), plus 100 per crossing of two segments (stars of 80 to 300 chords through a disk's
// centre, 3,160 to 44,850 crossings at small angles, use 30-63 Steiner vertices per crossing at 30
// and 33 degrees; 40 per crossing stopped several of them incomplete), plus eight per unit of area
// bound (area A with triangles of area a needs about A / (2 a) vertices).
std::uint64_t steinerBudget(const MeshState& m) {
  const Options& o = *m.options;
  if (o.maxSteiner != kAutoSteinerBudget) return o.maxSteiner;
  const Triangulation& t = m.tri;
  const auto crossings = std::count(m.kind.begin(), m.kind.end(), VertexKind::Intersection);
  double estimate = 1e4 + 200.0 * m.inputCount + 100.0 * static_cast<double>(crossings);
  for (std::uint32_t s = 0; s < t.slotCount(); ++s) {
    if (!t.alive(s) || m.maxArea[s] <= 0) continue;
    estimate += 8 * qualityOf(t.pt(t.tv[3 * s]), t.pt(t.tv[3 * s + 1]), t.pt(t.tv[3 * s + 2])).area / m.maxArea[s];
  }
  if (o.sizeFunction) estimate += 1e8;
  if (m.oldMesh != nullptr) estimate += m.oldMesh->budgetEstimate();
  return static_cast<std::uint64_t>(std::min(estimate, 4e9));
}

}  // namespace ruppert::detail
