// Per-point attributes (Plc::pointAttributes) carried onto every vertex refinement adds: linear
// interpolation from the triangle a vertex is inserted in, or from the ends of the subsegment or
// segment it lies on. Interpolation of interpolated values stays linear, so a field a x + b y + c
// given at the input points is reproduced, to rounding, at every vertex.
#pragma once

#include <cstdint>

#include "mesh_state.h"

namespace ruppert::detail {

// Sets m.attributes for the input vertices (after buildDelaunay); the box corners get 0.
void initAttributes(MeshState& m);

// Vertex v's attributes: at its point, on the line a-b (projected onto it), from a's and b's.
void interpolateOnSegment(MeshState& m, std::uint32_t v, std::uint32_t a, std::uint32_t b);

// Vertex v's attributes at point p (v's own point if p is null), barycentric in triangle (a, b, c).
// v may be one of a, b, c (a moved vertex: its values before the move are used).
void interpolateInTriangle(MeshState& m, std::uint32_t v, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                           const double* p = nullptr);

}  // namespace ruppert::detail
