// Refining an existing mesh (Plc::triangles): the old triangles, located through a uniform grid, give
// the domain (the union of the old triangles) and the per-triangle area bounds
// (Plc::triangleMaxArea). The rule for a triangle t of the refinement: its bound is the smallest
// bound among the old triangles whose interiors meet t's interior (exact orient2d tests), so a
// triangle lying within an old triangle T always meets T's bound, whatever else it overlaps.
#pragma once

#include <cstdint>
#include <vector>

#include "prepared_input.h"
#include "ruppert/ruppert.h"

namespace ruppert::detail {

// The PLC to mesh when refining `plc`'s triangles: its segments, then every boundary edge of the old
// mesh (an edge of one old triangle only) that is not already a segment, with marker 1 when the input
// has segment markers. Throws on a malformed triangles / triangleMaxArea array (index, value).
Plc withOldMeshBoundary(const Plc& plc);

// The PLC triangulate() meshes: `userPlc` itself, or when it has triangles (refining a mesh) its
// withOldMeshBoundary, kept in `storage`. Throws for what refining a mesh rules out (the box
// variant) and for area bounds without triangles.
const Plc& plcToMesh(const Plc& userPlc, const Options& options, Plc& storage);

struct MeshState;
// Removes the triangles of the constrained triangulation that lie outside every old triangle (the
// old mesh's holes and concavities, which its boundary edges enclose as segments).
void keepOldMeshDomain(MeshState& m);

class OldMesh {
 public:
  // Internal (scaled) coordinates come from `input`; throws DegenerateInput for a triangle of zero
  // area and MalformedInput for a bound that is not a number. Clockwise triangles are turned over.
  OldMesh(const Plc& plc, const PreparedInput& input);

  bool hasBounds() const { return !bounded_.items.empty(); }
  // The area bound (internal units) for the triangle p0 p1 p2, or 0 for none. Lowered by a relative
  // 1e-9 so that a triangle the refinement accepts (its area computed in doubles) never exceeds the
  // bound by rounding.
  double boundFor(const double* p0, const double* p1, const double* p2) const;
  // True when the interior of p0 p1 p2 meets the interior of some old triangle.
  bool overlapsAny(const double* p0, const double* p1, const double* p2) const;
  // About how many vertices the bounds call for (eight per unit of area / bound, as automaticSteinerBudget).
  double budgetEstimate() const { return budget_; }

 private:
  struct Grid {
    double x0 = 0, y0 = 0, inverseCell = 1;
    std::uint32_t nx = 1, ny = 1;
    std::vector<std::uint32_t> start, items;  // per cell: old triangles whose bounding boxes meet it
    void build(const OldMesh& mesh, const std::vector<std::uint32_t>& triangles);
    std::uint32_t column(double x) const;
    std::uint32_t row(double y) const;
  };
  template <class Visit>
  void forEachOverlapping(const Grid& grid, const double* p0, const double* p1, const double* p2, Visit&& visit) const;
  const double* corner(std::uint32_t t, int i) const { return &xy_[6 * std::size_t(t) + 2 * i]; }

  std::vector<double> xy_;      // 6 per old triangle: its corners, counter-clockwise, internal
  std::vector<double> bound_;   // per old triangle: internal area bound, 0 = none
  double minX_ = 0, minY_ = 0, maxX_ = 0, maxY_ = 0;
  Grid all_, bounded_;
  double budget_ = 0;
  mutable std::vector<std::uint32_t> seen_;  // per old triangle: the query that last visited it
  mutable std::uint32_t query_ = 0;
};

}  // namespace ruppert::detail
