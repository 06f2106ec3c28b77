// Deciding which triangles form the domain (§6.7: the mesh stores no triangles outside it).
//
// Flood fills that never cross a constrained edge:
//   exterior  from the triangles touching the bounding-box corners;
//   holes     from the triangle containing each hole seed;
//   autoHoles (no seeds given): nesting depth = number of constrained edges crossed from the exterior
//             (a 0-1 breadth-first search); odd depth is domain, even depth is a hole;
//   regions   from each region seed: attribute and max area for every triangle reached.
// findDomain reports segments that enclose nothing; the pipeline (triangulate.cpp) then meshes the
// convex hull instead and asks again. classifyTriangles records the result (MeshState::inDomain,
// attribute, maxArea); removeOutside deletes the triangles outside the domain and clears their
// neighbors' twins, so every boundary edge of what remains is a constrained edge.
#include "cdt/classify.h"

#include <algorithm>
#include <string>

#include "cold_code.h"
#include "message.h"
#include "mesh_state.h"
#include "mesh/predicates.h"

// Once per call, a pass or two over the triangles: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

namespace ruppert::detail {
namespace {

// Marks the triangles reachable from seed without crossing a constrained edge (those with the seed's
// current mark) with `value`; returns how many.
template <class Mark>
std::size_t flood(Triangulation& t, std::uint32_t seed, std::vector<Mark>& out, typename std::vector<Mark>::value_type value) {
  std::vector<std::uint32_t> stack;
  stack.reserve(kScratchReserve);
  stack.push_back(seed);
  const Mark before = out[seed];
  out[seed] = value;
  std::size_t count = 1;
  while (!stack.empty()) {
    const std::uint32_t u = stack.back();
    stack.pop_back();
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = 3 * u + i;
      if (t.con[h] != kFree || t.twin[h] == kNone) continue;
      const std::uint32_t w = t.twin[h] / 3;
      if (out[w] != before) continue;
      out[w] = value;
      stack.push_back(w);
      ++count;
    }
  }
  return count;
}

// The triangle containing a seed, or an error if the seed sits on a constrained edge or a vertex.
// Names a hole or region seed in messages, e.g. "holes[2] at (0.5, 1)". Built only when a message
// needs it: formatting the shortest round-trip decimal of each coordinate costs more than meshing a
// small input.
struct SeedName {
  const MeshState& m;
  const char* list;
  std::size_t index;
  double x, y;
  std::string text() const;
};

// `hint`: where the walk starts (the previous seed's triangle: seeds in a list tend to be near each
// other); kNone for any triangle.
std::uint32_t seedTriangle(MeshState& m, double x, double y, ErrorCode code, const SeedName& what,
                           std::uint32_t& hint) {
  Triangulation& t = m.tri;
  const double p[2] = {x, y};
  if (hint == kNone || !t.alive(hint)) {
    hint = 0;
    while (hint < t.slotCount() && !t.alive(hint)) ++hint;
  }
  const Location loc = t.locate(p, hint);
  if (loc.kind == Location::InTriangle || loc.kind == Location::OnEdge) hint = loc.tri;
  switch (loc.kind) {
    case Location::InTriangle:
      return loc.tri;
    case Location::OnEdge:
      if (t.con[loc.edge] == kFree) return loc.tri;
      throw Error(code, what.text() + " lies exactly on a segment; move it inside the region it should mark");
    case Location::OnVertex:
      throw Error(code, what.text() + " lies exactly on points[" + std::to_string(loc.vertex) + "]");
    default:
      return kNone;  // outside the box: certainly outside the domain
  }
}

std::string at(const MeshState& m, double x, double y) {
  return "(" + formatNumber(m.input.toUser(x)) + ", " + formatNumber(m.input.toUser(y)) + ")";
}

std::string SeedName::text() const { return std::string(list) + "[" + std::to_string(index) + "] at " + at(m, x, y); }

}  // namespace

enum : std::uint8_t { kUnknown = 0, kOutside = 1 };

// Marks every triangle outside what the segments enclose (exterior, even nesting depth) as kOutside.
std::vector<std::uint8_t> outsideTriangles(MeshState& m) {
  Triangulation& t = m.tri;
  const std::uint32_t slots = t.slotCount();
  std::vector<std::uint8_t> state(slots, kUnknown);
  for (std::uint32_t s = 0; s < slots; ++s)
    if (!t.alive(s)) state[s] = kOutside;
  for (std::uint32_t s = 0; s < slots; ++s) {
    if (!t.alive(s) || state[s] != kUnknown) continue;
    for (int i = 0; i < 3; ++i)
      if (t.tv[3 * s + i] >= m.boxFirst && t.tv[3 * s + i] < m.boxFirst + 4) {
        flood(t, s, state, kOutside);
        break;
      }
  }
  const auto& holes = m.input.holes;
  if (holes.empty() && m.options->autoHoles) {
    // Depth from the exterior, one level at a time: a flood through free edges spreads a level,
    // whose constrained edges seed the next (crossing one costs one).
    std::vector<std::uint32_t> depth(slots, kNone), level, next;
    for (std::uint32_t s = 0; s < slots; ++s)
      if (t.alive(s) && state[s] == kOutside) depth[s] = 0, level.push_back(s);
    for (std::uint32_t d = 0; !level.empty(); ++d, level.swap(next)) {
      next.clear();
      for (std::size_t k = 0; k < level.size(); ++k) {
        const std::uint32_t u = level[k];
        if (depth[u] != d) continue;  // reached at a smaller depth meanwhile
        for (std::uint32_t i = 0; i < 3; ++i) {
          const std::uint32_t h = 3 * u + i;
          if (t.twin[h] == kNone) continue;
          const std::uint32_t w = t.twin[h] / 3;
          if (t.con[h] == kFree && depth[w] > d) depth[w] = d, level.push_back(w);
          else if (t.con[h] != kFree && depth[w] > d + 1) depth[w] = d + 1, next.push_back(w);
        }
      }
    }
    for (std::uint32_t s = 0; s < slots; ++s)
      if (t.alive(s) && state[s] == kUnknown && depth[s] % 2 == 0) state[s] = kOutside;
  }
  return state;
}

// Removes what the hole seeds reach; a seed outside the domain is reported and ignored. Returns the
// index of the seed that removed the last triangle, or -1 while something remains.
std::int64_t eatHoles(MeshState& m, std::vector<std::uint8_t>& state) {
  Triangulation& t = m.tri;
  const Plc& plc = *m.plc;
  std::size_t remaining = static_cast<std::size_t>(std::count(state.begin(), state.end(), kUnknown));
  const auto& holes = m.input.holes;
  std::uint32_t hint = kNone;
  for (std::size_t k = 0; k < holes.size() / 2; ++k) {
    const SeedName what{m, "holes", k, holes[2 * k], holes[2 * k + 1]};
    const std::uint32_t s = seedTriangle(m, holes[2 * k], holes[2 * k + 1], ErrorCode::HoleOnSegment, what, hint);
    if (s == kNone || state[s] == kOutside) {
      Notice n{NoticeKind::HoleOutsideDomain, static_cast<std::int64_t>(k), -1, plc.holes[2 * k], plc.holes[2 * k + 1], ""};
      n.message = what.text() + " is outside the domain; it removes nothing";
      m.notices.push_back(std::move(n));
      continue;
    }
    remaining -= flood(t, s, state, kOutside);
    if (remaining == 0) return static_cast<std::int64_t>(k);
  }
  return -1;
}

Domain findDomain(MeshState& m, bool hullStandsIn) {
  Domain d;
  d.noticesBefore = m.notices.size();
  d.outside = outsideTriangles(m);
  const bool nothingEnclosed = std::find(d.outside.begin(), d.outside.end(), kUnknown) == d.outside.end();
  // With the hull standing in, the holes apply even if it encloses nothing either (they are then
  // all reported as outside the domain).
  d.emptiedBy = nothingEnclosed && !hullStandsIn ? -1 : eatHoles(m, d.outside);
  d.segmentsEncloseNothing = nothingEnclosed;
  return d;
}

namespace {

// A hole took the whole domain: an error. Two different mistakes, told apart by whether the
// segments enclose anything at all: a hole seed inside the only closed boundary (the domain is that
// boundary's inside, and the hole takes all of it), or segments that close nothing, so the hull was
// meshed and the hole flooded it.
[[noreturn]] void throwEmptyDomain(const MeshState& m, const Domain& d) {
  const auto& h = m.input.holes;
  const std::int64_t k = d.emptiedBy;
  throw Error(ErrorCode::EmptyDomain,
              "holes[" + std::to_string(k) + "] at " + at(m, h[2 * k], h[2 * k + 1]) +
                  " removes the whole domain: " +
                  (d.segmentsEncloseNothing
                       ? std::string("the segments enclose no region, so the hole's region is the whole convex hull")
                       : std::string("it lies in the only region the segments enclose; a hole needs an outer "
                                     "boundary around its own")));
}

// Region attributes and area bounds (MeshState::attribute, maxArea) for every triangle. Each
// connected part of the domain between segments is flooded once, when its first seed is met, and
// the seeds' values are gathered per part: thousands of regions (or of seeds in one region) cost
// one pass over the triangles, not one per seed. Later seeds set the attribute; the smallest area
// bound applies.
void assignRegions(MeshState& m, const std::vector<std::uint8_t>& state) {
  Triangulation& t = m.tri;
  const std::uint32_t slots = t.slotCount();
  const Plc& plc = *m.plc;
  struct Part {
    double attribute = 0, maxArea = 0;
  };
  std::vector<Part> parts;
  std::vector<std::uint32_t> partOf(m.input.regions.empty() ? 0 : slots, kNone);
  std::uint32_t hint = kNone;
  for (std::size_t k = 0; k < m.input.regions.size(); ++k) {
    const Region& r = m.input.regions[k];
    const SeedName what{m, "regions", k, r.x, r.y};
    const std::uint32_t s = seedTriangle(m, r.x, r.y, ErrorCode::InvalidRegion, what, hint);
    if (s == kNone || state[s] == kOutside) {
      Notice n{NoticeKind::RegionOutsideDomain, static_cast<std::int64_t>(k), -1, plc.regions[k].x, plc.regions[k].y, ""};
      n.message = what.text() + " is outside the domain; it has no effect";
      m.notices.push_back(std::move(n));
      continue;
    }
    if (partOf[s] == kNone) {
      flood(t, s, partOf, static_cast<std::uint32_t>(parts.size()));
      parts.emplace_back();
    }
    Part& part = parts[partOf[s]];
    part.attribute = r.attribute;
    if (r.maxArea > 0) part.maxArea = part.maxArea > 0 ? std::min(part.maxArea, r.maxArea) : r.maxArea;
  }
  // Nothing per slot to remember: MeshState::maxAreaOf stands for the arrays, which are then never
  // filled (16 bytes per slot, 32 MB for a CDT of 10^6 points). The bounding-box variant's outside
  // triangles have no bound, so it keeps them.
  if (parts.empty() && m.options->variant != Variant::BoundingBox) {
    release(m.attribute), release(m.maxArea);
    return;
  }
  m.attribute.assign(slots, 0.0);
  m.maxArea.assign(slots, m.input.maxArea);
  if (parts.empty()) return;
  for (std::uint32_t u = 0; u < slots; ++u) {
    if (partOf[u] == kNone) continue;
    const Part& part = parts[partOf[u]];
    m.attribute[u] = part.attribute;
    if (part.maxArea > 0) m.maxArea[u] = m.maxArea[u] > 0 ? std::min(m.maxArea[u], part.maxArea) : part.maxArea;
  }
}

}  // namespace

void classifyTriangles(MeshState& m, const Domain& domain) {
  if (domain.emptiedBy >= 0) throwEmptyDomain(m, domain);
  const std::vector<std::uint8_t>& state = domain.outside;
  assignRegions(m, state);
  Triangulation& t = m.tri;
  const std::uint32_t slots = t.slotCount();
  m.inDomain.assign(slots, 0);
  for (std::uint32_t s = 0; s < slots; ++s) m.inDomain[s] = t.alive(s) && state[s] != kOutside;
  // Bounding-box variant: the triangles outside the domain stay until the end (the pipeline removes
  // them after refining), without region data.
  if (m.options->variant == Variant::BoundingBox)
    for (std::uint32_t s = 0; s < slots; ++s)
      if (!m.inDomain[s]) m.maxArea[s] = 0, m.attribute[s] = 0;
}

void removeOutside(MeshState& m) {
  // Delete every triangle outside the domain; the corners of the box go with them. Afterwards every
  // boundary edge of what remains is a constrained edge.
  Triangulation& t = m.tri;
  const std::uint32_t slots = t.slotCount();
  t.freeSlots.reserve(kScratchReserve);  // the killed slots' list, not grown from empty by a small mesh
  for (std::uint32_t s = 0; s < slots; ++s) {
    if (!t.alive(s) || m.inDomain[s]) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t g = t.twin[3 * s + i];
      if (g != kNone) t.twin[g] = kNone;
      t.twin[3 * s + i] = kNone;
    }
    t.killTriangle(s);
  }
  release(m.inDomain);
  for (std::uint32_t v = 0; v < t.vertexCount(); ++v) t.vtri[v] = kNone;
  for (std::uint32_t s = 0; s < slots; ++s)
    if (t.alive(s))
      for (int i = 0; i < 3; ++i) t.vtri[t.tv[3 * s + i]] = s;
}

}  // namespace ruppert::detail

RUPPERT_COLD_END
