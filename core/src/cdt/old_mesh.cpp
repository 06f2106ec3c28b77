#include "cdt/old_mesh.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "cold_code.h"
#include "mesh_state.h"
#include "message.h"
#include "cdt/classify.h"
#include "mesh/predicates.h"

// The checks, the boundary and the grid's build run once per call: compiled for size (cold_code.h);
// the grid's lookups (boundFor, overlapsAny), asked per new triangle, are not.
RUPPERT_COLD_BEGIN

namespace ruppert::detail {
namespace {

[[noreturn]] void fail(ErrorCode code, const std::string& message) { throw Error(code, message); }

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

// Checks the shape of triangles and triangleMaxArea, naming the first bad item.
void checkTriangleArrays(const Plc& plc) {
  const std::size_t n = plc.points.size() / 2;
  if (plc.triangles.size() % 3 != 0)
    fail(ErrorCode::MalformedInput, message({"triangles has length ", std::to_string(plc.triangles.size()), ": a triangle is three point indices"}));
  for (std::size_t k = 0; k < plc.triangles.size(); ++k)
    if (plc.triangles[k] >= n)
      fail(ErrorCode::IndexOutOfRange, message({"triangles[", std::to_string(k), "] = ", std::to_string(plc.triangles[k]), " (corner ",
                                                std::to_string(k % 3), " of triangle ", std::to_string(k / 3), ") refers to point ",
                                                std::to_string(plc.triangles[k]), ", but there are only ", std::to_string(n)}));
  const std::size_t count = plc.triangles.size() / 3;
  if (!plc.triangleMaxArea.empty() && plc.triangleMaxArea.size() != count)
    fail(ErrorCode::MalformedInput, message({"triangleMaxArea has ", std::to_string(plc.triangleMaxArea.size()), " entries for ",
                                             std::to_string(count), " triangles (one per triangle, or none)"}));
  for (std::size_t t = 0; t < plc.triangleMaxArea.size(); ++t)
    if (std::isnan(plc.triangleMaxArea[t]))
      fail(ErrorCode::MalformedInput, message({"triangleMaxArea[", std::to_string(t), "] is NaN (<= 0: no bound)"}));
}

// Whether every vertex of q lies in the closed half-plane right of a -> b: then the line ab separates
// q from a counter-clockwise triangle that has ab as an edge (their interiors are disjoint).
bool separates(const double* a, const double* b, const double* const q[3]) {
  for (int i = 0; i < 3; ++i)
    if (orient2d(a, b, q[i]) > 0) return false;
  return true;
}

// Two counter-clockwise triangles' interiors meet unless a line through an edge of one separates
// them (the separating axis theorem for convex polygons: such a line exists whenever the interiors
// are disjoint, touching included). Exact, through orient2d.
bool interiorsMeet(const double* const p[3], const double* const q[3]) {
  for (int i = 0; i < 3; ++i) {
    if (separates(p[i], p[(i + 1) % 3], q)) return false;
    if (separates(q[i], q[(i + 1) % 3], p)) return false;
  }
  return true;
}

}  // namespace

Plc withOldMeshBoundary(const Plc& plc) {
  checkTriangleArrays(plc);
  const std::vector<std::uint32_t>& tri = plc.triangles;
  std::vector<std::uint64_t> keys;
  keys.reserve(tri.size());
  for (std::size_t t = 0; 3 * t < tri.size(); ++t)
    for (int i = 0; i < 3; ++i) keys.push_back(edgeKey(tri[3 * t + i], tri[3 * t + (i + 1) % 3]));
  std::vector<std::uint64_t> sorted = keys;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::uint64_t> existing;
  for (std::size_t s = 0; 2 * s + 1 < plc.segments.size(); ++s)
    existing.push_back(edgeKey(plc.segments[2 * s], plc.segments[2 * s + 1]));
  std::sort(existing.begin(), existing.end());
  Plc out = plc;
  const bool markers = !plc.segmentMarkers.empty();
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const auto range = std::equal_range(sorted.begin(), sorted.end(), keys[k]);
    const std::uint32_t a = static_cast<std::uint32_t>(keys[k] >> 32), b = static_cast<std::uint32_t>(keys[k]);
    if (range.second - range.first != 1 || a == b) continue;  // interior (or degenerate) edge
    if (std::binary_search(existing.begin(), existing.end(), keys[k])) continue;
    out.segments.push_back(tri[k]);
    out.segments.push_back(tri[3 * (k / 3) + (k % 3 + 1) % 3]);
    if (markers) out.segmentMarkers.push_back(1);
  }
  return out;
}

OldMesh::OldMesh(const Plc& plc, const PreparedInput& input) {
  const std::size_t count = plc.triangles.size() / 3;
  xy_.resize(6 * count);
  bound_.assign(count, 0);
  std::vector<std::uint32_t> all, bounded;
  for (std::size_t t = 0; t < count; ++t) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = input.representative[plc.triangles[3 * t + i]];
      xy_[6 * t + 2 * i] = input.xy[2 * std::size_t(v)];
      xy_[6 * t + 2 * i + 1] = input.xy[2 * std::size_t(v) + 1];
    }
    double* c = &xy_[6 * t];
    const double turn = orient2d(c, c + 2, c + 4);
    if (turn == 0)
      fail(ErrorCode::DegenerateInput, message({"triangles[", std::to_string(t), "] = (", std::to_string(plc.triangles[3 * t]), ", ",
                                                std::to_string(plc.triangles[3 * t + 1]), ", ", std::to_string(plc.triangles[3 * t + 2]),
                                                ") has zero area"}));
    if (turn < 0) std::swap_ranges(c + 2, c + 4, c + 4);  // clockwise: turn it over
    all.push_back(static_cast<std::uint32_t>(t));
    const double user = plc.triangleMaxArea.empty() ? 0 : plc.triangleMaxArea[t];
    if (user > 0 && std::isfinite(user)) {
      bound_[t] = input.areaToInternal(user) * (1 - 1e-9);
      bounded.push_back(static_cast<std::uint32_t>(t));
      budget_ += 8 * 0.5 * std::fabs(turn) / bound_[t];
    }
    for (int i = 0; i < 3; ++i) {
      const double x = c[2 * i], y = c[2 * i + 1];
      if (t == 0 && i == 0) minX_ = maxX_ = x, minY_ = maxY_ = y;
      minX_ = std::min(minX_, x), maxX_ = std::max(maxX_, x);
      minY_ = std::min(minY_, y), maxY_ = std::max(maxY_, y);
    }
  }
  seen_.assign(count, 0);
  all_.build(*this, all);
  bounded_.build(*this, bounded);
}

// About one cell per triangle over the old mesh's bounding box, at most 2048 cells a side; every
// triangle is listed in each cell its bounding box meets (a counting sort by cell).
void OldMesh::Grid::build(const OldMesh& mesh, const std::vector<std::uint32_t>& triangles) {
  if (triangles.empty()) return;
  const double w = mesh.maxX_ - mesh.minX_, h = mesh.maxY_ - mesh.minY_;
  const double cell = std::max(std::sqrt(w * h / double(triangles.size())), std::max(w, h) / 2048);
  x0 = mesh.minX_, y0 = mesh.minY_, inverseCell = 1 / cell;
  nx = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::min(2048.0, std::ceil(w / cell))));
  ny = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::min(2048.0, std::ceil(h / cell))));
  start.assign(std::size_t(nx) * ny + 1, 0);
  auto forEachCell = [&](std::uint32_t t, auto&& visit) {
    const double* c = mesh.corner(t, 0);
    const std::uint32_t c0 = column(std::min({c[0], c[2], c[4]})), c1 = column(std::max({c[0], c[2], c[4]}));
    const std::uint32_t r0 = row(std::min({c[1], c[3], c[5]})), r1 = row(std::max({c[1], c[3], c[5]}));
    for (std::uint32_t r = r0; r <= r1; ++r)
      for (std::uint32_t q = c0; q <= c1; ++q) visit(std::size_t(r) * nx + q);
  };
  for (std::uint32_t t : triangles) forEachCell(t, [&](std::size_t k) { ++start[k + 1]; });
  for (std::size_t k = 0; k + 1 < start.size(); ++k) start[k + 1] += start[k];
  items.resize(start.back());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t t : triangles) forEachCell(t, [&](std::size_t k) { items[fill[k]++] = t; });
}

RUPPERT_COLD_END

// Monotone in x (a subtraction, a product and a floor), so two bounding boxes that meet have cell
// ranges that meet: no overlap is missed however the coordinates round.
std::uint32_t OldMesh::Grid::column(double x) const {
  const double c = std::floor((x - x0) * inverseCell);
  return c <= 0 ? 0 : c >= nx - 1 ? nx - 1 : static_cast<std::uint32_t>(c);
}

std::uint32_t OldMesh::Grid::row(double y) const {
  const double r = std::floor((y - y0) * inverseCell);
  return r <= 0 ? 0 : r >= ny - 1 ? ny - 1 : static_cast<std::uint32_t>(r);
}

// Calls visit(t) for every old triangle t in `grid` whose interior meets that of p0 p1 p2, each
// once, until visit returns true.
template <class Visit>
void OldMesh::forEachOverlapping(const Grid& grid, const double* p0, const double* p1, const double* p2,
                                 Visit&& visit) const {
  if (grid.items.empty()) return;
  const double* q[3] = {p0, p1, p2};
  if (orient2d(p0, p1, p2) < 0) std::swap(q[1], q[2]);
  if (++query_ == 0) std::fill(seen_.begin(), seen_.end(), 0), query_ = 1;
  const double minX = std::min({p0[0], p1[0], p2[0]}), maxX = std::max({p0[0], p1[0], p2[0]});
  const double minY = std::min({p0[1], p1[1], p2[1]}), maxY = std::max({p0[1], p1[1], p2[1]});
  const std::uint32_t c0 = grid.column(minX), c1 = grid.column(maxX), r0 = grid.row(minY), r1 = grid.row(maxY);
  for (std::uint32_t r = r0; r <= r1; ++r)
    for (std::uint32_t c = c0; c <= c1; ++c) {
      const std::size_t k = std::size_t(r) * grid.nx + c;
      for (std::uint32_t i = grid.start[k]; i < grid.start[k + 1]; ++i) {
        const std::uint32_t t = grid.items[i];
        if (seen_[t] == query_) continue;
        seen_[t] = query_;
        const double* p[3] = {corner(t, 0), corner(t, 1), corner(t, 2)};
        // Bounding boxes that do not overlap (touching is not overlapping) keep the interiors apart:
        // a cheap exact test that spares most candidates the separating-axis test.
        if (std::max({p[0][0], p[1][0], p[2][0]}) <= minX || std::min({p[0][0], p[1][0], p[2][0]}) >= maxX ||
            std::max({p[0][1], p[1][1], p[2][1]}) <= minY || std::min({p[0][1], p[1][1], p[2][1]}) >= maxY)
          continue;
        if (interiorsMeet(p, q) && visit(t)) return;
      }
    }
}

double OldMesh::boundFor(const double* p0, const double* p1, const double* p2) const {
  double bound = 0;
  forEachOverlapping(bounded_, p0, p1, p2, [&](std::uint32_t t) {
    bound = bound > 0 ? std::min(bound, bound_[t]) : bound_[t];
    return false;
  });
  return bound;
}

bool OldMesh::overlapsAny(const double* p0, const double* p1, const double* p2) const {
  bool found = false;
  forEachOverlapping(all_, p0, p1, p2, [&](std::uint32_t) { return found = true; });
  return found;
}

RUPPERT_COLD_BEGIN

const Plc& plcToMesh(const Plc& userPlc, const Options& options, Plc& storage) {
  if (!userPlc.triangles.empty()) {
    if (options.variant == Variant::BoundingBox)
      throw Error(ErrorCode::InvalidOption, "refining a mesh (triangles in the input) needs the constrained variant, not 'box'");
    storage = withOldMeshBoundary(userPlc);
    return storage;
  }
  if (!userPlc.triangleMaxArea.empty())
    throw Error(ErrorCode::MalformedInput, "triangleMaxArea has " + std::to_string(userPlc.triangleMaxArea.size()) +
                                               " entries but the input has no triangles");
  return userPlc;
}

void keepOldMeshDomain(MeshState& m) {
  Triangulation& t = m.tri;
  m.inDomain.assign(t.slotCount(), 0);
  for (std::uint32_t s = 0; s < t.slotCount(); ++s)
    m.inDomain[s] = t.alive(s) && m.oldMesh->overlapsAny(t.pt(t.tv[3 * s]), t.pt(t.tv[3 * s + 1]), t.pt(t.tv[3 * s + 2]));
  removeOutside(m);
}

}  // namespace ruppert::detail

RUPPERT_COLD_END
