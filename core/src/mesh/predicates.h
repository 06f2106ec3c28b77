// Robust geometric predicates: orient2d and incircle with adaptive exact arithmetic.
//
// Method: a floating-point filter with a proven error bound, falling back to exact arithmetic on
// floating-point expansions (non-overlapping sums of doubles) when the filter cannot decide the sign.
// Reference for the mathematics: J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and
// Fast Robust Geometric Predicates", Discrete & Computational Geometry 18:305-363, 1997
// (error-free transformations two_sum / two_product, expansion sums and scaling, error bounds).
//
// Safe range: the result's sign is exact when every coordinate is 0 or has magnitude in
// [kSafeMinMagnitude, kSafeMaxMagnitude]. Outside that range products could overflow or underflow
// (losing the exactness of the error-free transformations). The mesher scales input by a power of two
// so that the largest coordinate lies in [1, 2) and rejects inputs whose dynamic range is larger.
#pragma once

namespace ruppert::detail {

inline constexpr double kSafeMaxMagnitude = 0x1p+64;
inline constexpr double kSafeMinMagnitude = 0x1p-128;

// True when v is finite and 0 or within [kSafeMinMagnitude, kSafeMaxMagnitude] in magnitude.
bool isSafeCoordinate(double v);

// Positive if a, b, c are in counter-clockwise order, negative if clockwise, zero if collinear.
// The sign is exact; the magnitude approximates twice the signed area.
double orient2d(const double* a, const double* b, const double* c);
double orient2d(double ax, double ay, double bx, double by, double cx, double cy);

// For a, b, c counter-clockwise: positive if d lies inside their circumcircle, negative if outside,
// zero if cocircular. (The sign flips if a, b, c are clockwise.) The sign is exact.
double incircle(const double* a, const double* b, const double* c, const double* d);

// The exact stages alone, without the floating-point filter: same sign contract as above. They are
// slower and exist so that tests can exercise the expansion arithmetic on inputs the filter would
// otherwise decide on its own.
double orient2dExact(const double* a, const double* b, const double* c);
double incircleExact(const double* a, const double* b, const double* c, const double* d);

}  // namespace ruppert::detail
