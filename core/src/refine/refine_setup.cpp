#include "refine/refine_setup.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>

#include "cdt/old_mesh.h"
#include "refine/refine.h"
#include "refine/placement/refine_geometry.h"
#include "mesh/triangle_shape.h"
#include "cold_code.h"

// Runs once per refinement: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

namespace ruppert::detail {

// A corner is acute when two constrained edges at an input or intersection vertex are less than
// 90 degrees apart with the domain between them: a small gap outside the domain (the valley between
// two spikes of a star, the mouth of a slot) has no triangles in it, so no shells are needed there,
// and marking it would put the splits of a spike's side at midpoints instead of on its tip's shells
// (stars: Triangle's 1.5x the boundary vertices). The value is 0 for none, else 1 + 254 cos(the
// smallest gap) (1..255: sharper is larger), so that a split between two corners can favor the
// sharper (refine_split.cpp). The directions are gathered per vertex in one flat array (counting
// sort by vertex), and the gaps are between neighbors in angular order: sorted, O(d log d) for a
// vertex of degree d.
namespace {

// A double's bits as an integer that orders as the double does (the sign bit flipped for
// nonnegatives, every bit for negatives): sorting these pairs shares the sort instantiated for edge
// keys, where one of (double, bool) pairs would be a copy of its own in the WebAssembly module.
std::uint64_t orderedBits(double x) {
  x += 0.0;  // -0 as +0: they compare equal as doubles
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits >> 63 ? ~bits : bits | std::uint64_t(1) << 63;
}

double fromOrderedBits(std::uint64_t key) {
  const std::uint64_t bits = key >> 63 ? key & ~(std::uint64_t(1) << 63) : ~key;
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

}  // namespace

std::vector<std::uint8_t> acuteCorners(const MeshState& m, double* inverseGaps) {
  const Triangulation& t = m.tri;
  const std::uint32_t n = t.vertexCount();
  std::vector<std::uint8_t> corner(n, 0);
  auto counted = [&](std::uint32_t v) {
    return m.kind[v] == VertexKind::Input || m.kind[v] == VertexKind::Intersection;
  };
  std::vector<std::uint32_t> start(n + 1, 0);
  // visit(v, w, domainAfter): the constrained edge from v to w, and whether the domain lies
  // counterclockwise of it at v (a triangle on the left of v -> w: the half-edge's own for its
  // origin, its twin's for its destination; removeOutside leaves no twin outside the domain).
  auto forEachEnd = [&](auto&& visit) {
    for (std::uint32_t h = 0; h < 3 * t.slotCount(); ++h) {
      if (!t.alive(h / 3) || t.con[h] == kFree) continue;
      if (t.twin[h] != kNone && t.twin[h] < h) continue;  // each edge once
      const std::uint32_t a = t.origin(h), b = t.dest(h);
      if (counted(a)) visit(a, b, true);
      if (counted(b)) visit(b, a, t.twin[h] != kNone);
    }
  };
  forEachEnd([&](std::uint32_t v, std::uint32_t, bool) { ++start[v + 1]; });
  for (std::uint32_t v = 0; v < n; ++v) start[v + 1] += start[v];
  // Per end: its direction's angle (as orderedBits), and whether the domain follows it
  // counterclockwise.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> ends(start[n]);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  forEachEnd([&](std::uint32_t v, std::uint32_t w, bool domainAfter) {
    const double dx = t.xy[2 * w] - t.xy[2 * v], dy = t.xy[2 * w + 1] - t.xy[2 * v + 1];
    ends[fill[v]++] = {orderedBits(std::atan2(dy, dx)), domainAfter};
  });
  for (std::uint32_t v = 0; v < n; ++v) {
    if (start[v + 1] - start[v] < 2) continue;
    const auto first = ends.begin() + start[v], last = ends.begin() + start[v + 1];
    std::sort(first, last);
    double gap = 2 * kPi;
    for (auto e = first; e != last; ++e) {
      const double next = e + 1 != last ? fromOrderedBits((e + 1)->first) : fromOrderedBits(first->first) + 2 * kPi;
      if (e->second) gap = std::min(gap, next - fromOrderedBits(e->first));
    }
    // cos(gap) > sin(1e-12): the gap is below 90 degrees by more than rounding (a reflex gap of the
    // domain, past 270 degrees, has a positive cosine too).
    const double cosine = std::cos(gap);
    if (gap < kPi && cosine > 1e-12) {
      corner[v] = static_cast<std::uint8_t>(1 + std::min(254.0, 254 * cosine));
      // Counted down to 5e-5 rad (hanging3's 1.5e-4 in full): a narrower corner is left to §6.6 and
      // the precision floor, not met by more triangles (near-overlaps 1e-12 rad apart ran away).
      if (inverseGaps != nullptr) *inverseGaps += 1 / std::max(gap, 5e-5);
    }
  }
  return corner;
}

double areaDemand(const MeshState& m) {
  const Triangulation& t = m.tri;
  double sum = 0;
  for (std::uint32_t s = 0; s < t.slotCount(); ++s) {
    if (!t.alive(s) || !(m.maxAreaOf(s) > 0)) continue;
    sum += qualityOf(t.pt(t.tv[3 * s]), t.pt(t.tv[3 * s + 1]), t.pt(t.tv[3 * s + 2])).area / m.maxAreaOf(s);
  }
  return sum;
}

// The automatic budget, the guard's first checkpoint: ten thousand, plus 200 per input vertex (of
// the 61 shared PLCs, the complete meshes at 33 and 35 degrees use at most 40 Steiner vertices per
// input vertex once past the first ten thousand), plus 100 per crossing of two segments (stars of
// 80 to 300 chords through a disk's center, 3,160 to 44,850 crossings at small angles, use 30-63
// Steiner vertices per crossing at 30 and 33 degrees; 40 per crossing stopped several of them incomplete), plus eight per unit of area
// bound (area A with triangles of area a needs about A / (2 a) vertices). Most inputs finish within
// it, so the guard's size measure is seldom computed.
std::uint64_t automaticSteinerBudget(const MeshState& m, double demand) {
  const Options& o = *m.options;
  const auto crossings = std::count(m.kind.begin(), m.kind.end(), VertexKind::Intersection);
  double estimate = 1e4 + 200.0 * m.inputCount + 100.0 * static_cast<double>(crossings) + 8 * demand;
  if (o.sizeFunction) estimate += 1e8;
  if (m.oldMesh != nullptr) estimate += m.oldMesh->budgetEstimate();
  return static_cast<std::uint64_t>(std::min(estimate, 4e9));
}

// Triangles per unit of the size measure in complete meshes at 33 degrees: at most 3.6 over the
// shared PLCs, 7.5 on three nearly collinear hull edges (artem-ogre/CDT's hanging3, 56,847
// triangles); about half as many vertices. A refinement into a corner it cannot fix went past
// 20,000 triangles per unit before it stopped at the precision floor. The estimate reuses a
// neighbor's lfs within a quarter of it (25% at worst, against the factor of 15 kept in hand).
std::uint64_t nextGuardCheckpoint(const MeshState& m, double base, std::uint64_t steps, double& integral) {
  integral = estimateLfsIntegral(m, 0.25);
  const double allowance = std::min(base + kGuardStepsPerLfsUnit * integral, 4e9);
  const double done = static_cast<double>(steps);
  if (!(done + 1 < allowance)) return 0;
  return static_cast<std::uint64_t>(std::min(allowance, 2 * done + 1));
}

// Triangles meeting area bounds a have a mean area of about 0.63 a at 30 degrees (the unit square
// at max area 1e-6: 1,595,671 triangles), so an area A asks for about 0.8 A / a vertices. Growing
// the arrays by doubling instead copied each of them again at every doubling and touched their old
// and new pages: one call for the unit square at max area 1e-6 in a fresh process made 56,740 page
// faults with this instead of 76,130 (perf stat; task clock 1.78-1.87 s against 1.56-2.18 s on a
// noisy machine). Below ten thousand vertices growth costs too little to matter. The reservation is
// only a hint: where memory is short, the arrays grow as they would have.
void reserveForAreaBounds(MeshState& m, std::uint64_t budget, double demand) {
  const Triangulation& t = m.tri;
  const double extra = std::min(0.8 * demand, static_cast<double>(budget));
  if (!(extra >= 1e4) || extra > 1e9) return;
  const std::size_t vertices = t.vertexCount() + static_cast<std::size_t>(extra);
  const std::size_t slots = t.slotCount() + 2 * static_cast<std::size_t>(extra);
  try {
    m.reserve(vertices, slots);  // (per-slot region arrays and point attributes, rarer, still grow)
  } catch (const std::bad_alloc&) {
  }
}

}  // namespace ruppert::detail

RUPPERT_COLD_END
