// Small terms the refinement loop's files share: the seditious angle (§6.6), bounds as sin^2,
// queued subsegments and known cavities.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "ruppert/ruppert.h"
#include "refine/placement/refine_geometry.h"

namespace ruppert::detail {

// Segments meeting below this angle can make seditious edges. Prop. 6.14 proves termination with
// 60 degrees; §6.6 advises a smaller angle in practice (fewer triangles left skinny), which threatens
// termination only well below 20 degrees, and the Steiner budget bounds the work regardless. 45
// degrees lets earcut_earcut.poly reach 30 degrees where 60 left a 26.96-degree triangle.
inline constexpr double kSeditiousAngle = kPi / 4;
// corner_ holds 1 + 254 cos(the corner's smallest gap) (refine_setup.cpp): at or above this value the
// gap is under kSeditiousAngle.
inline constexpr std::uint8_t kSeditiousCorner = 1 + 180;  // 254 cos(45 degrees) = 179.6

// A cavity already computed by Triangulation::cavity, handed to the insertion so it is not searched
// twice (both null: none).
struct CavityRef {
  const std::vector<std::uint32_t>* tris = nullptr;
  const std::vector<std::uint32_t>* boundary = nullptr;
};

// A subsegment remembered by its endpoints, with a half-edge that was the edge when queued.
struct EdgeRef {
  std::uint32_t a, b, hint;
};

inline double radians(double degrees) { return degrees * kPi / 180.0; }
// sin^2 of a bound, lowered by a relative 1e-12 against rounding.
inline double sin2Bound(double theta) { return std::sin(theta) * std::sin(theta) * (1 - 1e-12); }

// Lens apex angle 180 - 2 theta, never below the disk's 90 degrees: cos(180 - 2 theta) = -cos(2 theta).
inline double lensCos2For(const Options& o, double theta) {
  if (o.encroachment == Encroachment::DiametralLens && theta < kPi / 4) return std::cos(2 * theta) * std::cos(2 * theta);
  return 0;
}

}  // namespace ruppert::detail
