// Robust orient2d / incircle: a floating-point filter with a forward error bound, and an exact fallback
// on floating-point expansions. See predicates.h for the contract and the reference (Shewchuk 1997).
//
// Terminology used below:
//   u          unit roundoff of IEEE double with round-to-nearest: 2^-53. Every +, -, * whose exact
//              result lies in the normal range returns x(1 + d) with |d| <= u.
//   theta_k    a product of k factors (1 + d_i)^(+-1), |d_i| <= u; |theta_k - 1| <= gamma_k = k u / (1 - k u).
//   expansion  an array of doubles whose exact sum is the value, ordered by increasing magnitude, with no
//              zero components, and nonoverlapping (the lowest set bit of each component lies above the
//              highest set bit of the previous one). Its sign is the sign of its last component; an
//              empty expansion is zero.
//
// Why the safe range (predicates.h) makes everything exact: every coordinate is 0 or a multiple of
// 2^-180 (the ulp of 2^-128) of magnitude <= 2^64. All quantities below are polynomials of degree <= 4 in
// coordinate differences, so every nonzero intermediate is a multiple of 2^-720 (far above the smallest
// normal double, 2^-1022) and below 2^270 (far below overflow). Hence no operation underflows or
// overflows, the relative rounding model holds for the filters, and the error-free transformations are
// exact.

#include "mesh/predicates.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

// The error-free transformations need every operation rounded separately: a fused multiply-add formed
// by the compiler would silently break twoProduct and split. The build passes -ffp-contract=off; clang
// also honors the standard pragma, which guards builds that forget the flag.
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

// Each double operation must be rounded to double once; x87 extended-precision evaluation
// (FLT_EVAL_METHOD != 0, e.g. 32-bit x86 without SSE2) would round twice.
#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD != 0
#error "predicates.cpp needs double arithmetic evaluated in double precision (FLT_EVAL_METHOD == 0)"
#endif

#if defined(__FAST_MATH__)
#error "predicates.cpp needs strict IEEE arithmetic: do not compile it with -ffast-math"
#endif

#if defined(__GNUC__)
#define RUPPERT_NOINLINE __attribute__((noinline))
#define RUPPERT_LIKELY(x) __builtin_expect(!!(x), 1)
#else
#define RUPPERT_NOINLINE
#define RUPPERT_LIKELY(x) (x)
#endif

namespace ruppert::detail {

namespace {

constexpr double kUnitRoundoff = 0x1p-53;

// orient2d filter. With L = (ax-cx)(by-cy), R = (ay-cy)(bx-cx) and primes for computed values:
// L' = L theta_3, R' = R theta_3, det' = (L' - R')(1 + d), so
//   |det' - det| <= u |L' - R'| + gamma_3 (|L| + |R|) <= (u + gamma_3 / (1 - gamma_3)) (|L'| + |R'|)
//                 = (4u + 18u^2 + O(u^3)) (|L'| + |R'|).
// The bound itself is computed with two roundings (the sum and the product by the constant), each
// losing a factor (1 - u) at worst; 4u + 32u^2 covers both: (4u + 32u^2)(1 - u)^2 = 4u + 24u^2 + O(u^3).
// The constant is exactly representable (2^-51 + 2^-101).
constexpr double kOrientBound = (4.0 + 32.0 * kUnitRoundoff) * kUnitRoundoff;

// incircle filter, with differences taken relative to d. Each lift adx^2 + ady^2 is a sum of
// nonnegative terms, so lift' = lift theta_4; each 2x2 minor is P theta_4 - Q theta_4; multiplying
// by the lift gives theta_9 on each monomial and the two final additions give theta_11. Hence
//   |det' - det| <= gamma_11 * permanent <= gamma_11 / (1 - gamma_11) * permanent'
// where the permanent (the same expression with absolute values of the products) is computed with the
// same operation count, i.e. permanent = permanent' theta_11. gamma_11 / (1 - gamma_11) / (1 - u)
// = 11u + 253u^2 + O(u^3) <= 11u + 256u^2, which is exactly representable.
constexpr double kIncircleBound = (11.0 + 256.0 * kUnitRoundoff) * kUnitRoundoff;

// ---- Error-free transformations -------------------------------------------------------------------

// a + b == sum + err exactly, for any a, b (Knuth's branch-free form, six operations).
inline void twoSum(double a, double b, double& sum, double& err) {
  sum = a + b;
  const double bVirtual = sum - a;
  const double aVirtual = sum - bVirtual;
  err = (a - aVirtual) + (b - bVirtual);
}

// a + b == sum + err exactly, provided |a| >= |b| or a == 0 (Dekker, three operations).
inline void fastTwoSum(double a, double b, double& sum, double& err) {
  sum = a + b;
  err = b - (sum - a);
}

// Veltkamp split: a == hi + lo with hi and lo each fitting in 26 bits of significand, so that the
// products of halves in twoProduct are exact. 2^27 + 1 splits a 53-bit significand.
inline void split(double a, double& hi, double& lo) {
  const double c = (0x1p27 + 1.0) * a;
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

// a * b == prod + err exactly (Dekker). Written without fma so that it is also fast under WebAssembly,
// where std::fma is a software routine; the build forbids fma contraction (-ffp-contract=off).
inline void twoProduct(double a, double b, double& prod, double& err) {
  prod = a * b;
  double aHi, aLo, bHi, bLo;
  split(a, aHi, aLo);
  split(b, bHi, bLo);
  err = aLo * bLo - (((prod - aHi * bHi) - aLo * bHi) - aHi * bLo);
}

// ---- Expansion arithmetic -------------------------------------------------------------------------
// All routines return the number of components written and never write zeros. The outputs of twoSum
// and twoProduct are nonadjacent under round-to-nearest-even, and the routines below preserve the
// "strongly nonoverlapping" property their correctness theorems require (Shewchuk, Theorems 13 and 19).

// The exact difference a - b as an expansion of at most 2 components.
inline int differenceExpansion(double a, double b, double* h) {
  double sum, err;
  twoSum(a, -b, sum, err);
  int n = 0;
  if (err != 0) h[n++] = err;
  if (sum != 0) h[n++] = sum;
  return n;
}

// h = e + f. h must have room for eLen + fLen components and must not alias e or f.
// Merge the components by magnitude, then carry a running sum Q upward: each step emits the exact
// roundoff of Q + g[i] as the next output component. Because the roundoff of step i is written at index
// < i, the carry pass can run in place over the merged array.
int sumExpansions(const double* e, int eLen, const double* f, int fLen, double* h) {
  int i = 0, j = 0, k = 0;
  while (i < eLen && j < fLen) h[k++] = (std::fabs(e[i]) <= std::fabs(f[j])) ? e[i++] : f[j++];
  while (i < eLen) h[k++] = e[i++];
  while (j < fLen) h[k++] = f[j++];
  if (k < 2) return k;  // 0 or 1 nonzero component: already an expansion

  int n = 0;
  double q, hh;
  fastTwoSum(h[1], h[0], q, hh);  // |h[1]| >= |h[0]| after the merge
  if (hh != 0) h[n++] = hh;
  for (int g = 2; g < k; ++g) {
    twoSum(q, h[g], q, hh);
    if (hh != 0) h[n++] = hh;
  }
  if (q != 0) h[n++] = q;
  return n;
}

// h = e * b. h must have room for 2 * eLen components.
// Each component e[i] * b is split exactly into product + roundoff; the running sum Q absorbs them
// from the smallest up, emitting two exact low-order components per step.
int scaleExpansion(const double* e, int eLen, double b, double* h) {
  if (eLen == 0 || b == 0) return 0;
  int n = 0;
  double q, hh;
  twoProduct(e[0], b, q, hh);
  if (hh != 0) h[n++] = hh;
  for (int i = 1; i < eLen; ++i) {
    double product, productErr, sum;
    twoProduct(e[i], b, product, productErr);
    twoSum(q, productErr, sum, hh);
    if (hh != 0) h[n++] = hh;
    fastTwoSum(product, sum, q, hh);  // |product| dominates the accumulated lower-order sum
    if (hh != 0) h[n++] = hh;
  }
  if (q != 0) h[n++] = q;
  return n;
}

// A stack-allocated expansion with a capacity known at compile time from the degree of the formula.
template <int Capacity>
struct Expansion {
  double c[Capacity];
  int n = 0;
};

template <int A, int B>
Expansion<A + B> operator+(const Expansion<A>& e, const Expansion<B>& f) {
  Expansion<A + B> h;
  h.n = sumExpansions(e.c, e.n, f.c, f.n, h.c);
  return h;
}

template <int A>
Expansion<A> operator-(const Expansion<A>& e) {
  // Negation is exact and keeps the ordering. Only the n components in use are copied: copying the
  // whole capacity (up to 4 KB) was a memcpy per call, which WebAssembly hands to JavaScript above
  // 512 bytes.
  Expansion<A> h;
  h.n = e.n;
  for (int i = 0; i < e.n; ++i) h.c[i] = -e.c[i];
  return h;
}

template <int A, int B>
Expansion<A + B> operator-(const Expansion<A>& e, const Expansion<B>& f) {
  return e + (-f);
}

// Product of two expansions: sum over the components of f of e scaled by that component. The partial
// sums alternate between two buffers (no copying per step).
template <int A, int B>
Expansion<2 * A * B> operator*(const Expansion<A>& e, const Expansion<B>& f) {
  Expansion<2 * A * B> result;
  double other[2 * A * B];
  double scaled[2 * A];
  // Started so that the last partial sum lands in result.c (f.n steps, one swap each): no copy.
  double* acc = f.n % 2 == 0 ? result.c : other;
  double* next = f.n % 2 == 0 ? other : result.c;
  int accLen = 0;
  for (int j = 0; j < f.n; ++j) {
    const int scaledLen = scaleExpansion(e.c, e.n, f.c[j], scaled);
    const int nextLen = sumExpansions(acc, accLen, scaled, scaledLen, next);
    std::swap(acc, next);
    accLen = nextLen;
  }
  if (acc != result.c) std::copy(acc, acc + accLen, result.c);
  result.n = accLen;
  return result;
}

inline Expansion<2> difference(double a, double b) {
  Expansion<2> h;
  h.n = differenceExpansion(a, b, h.c);
  return h;
}

// A double with the exact sign of the expansion and approximately its value: the components are summed
// from the smallest up; should rounding ever spoil the sign, the dominant component is returned instead.
template <int A>
double estimate(const Expansion<A>& e) {
  if (e.n == 0) return 0.0;
  double sum = 0.0;
  for (int i = 0; i < e.n; ++i) sum += e.c[i];
  const double top = e.c[e.n - 1];
  return ((sum > 0) == (top > 0) && sum != 0) ? sum : top;
}

}  // namespace

bool isSafeCoordinate(double v) {
  const double m = std::fabs(v);  // NaN fails both comparisons, +-Inf fails the upper one
  return v == 0 || (m >= kSafeMinMagnitude && m <= kSafeMaxMagnitude);
}

// ---- orient2d -------------------------------------------------------------------------------------

RUPPERT_NOINLINE double orient2dExact(const double* a, const double* b, const double* c) {
  const Expansion<2> acx = difference(a[0], c[0]), acy = difference(a[1], c[1]);
  const Expansion<2> bcx = difference(b[0], c[0]), bcy = difference(b[1], c[1]);
  // Usually every difference is exact (one component or none): then det = L - R with each product
  // split exactly in two, four components in all. Cheaper than the general products below (a
  // boundary subsegment's rounded midpoint, checked for the domain's side, comes here on most
  // splits that are not axis-aligned).
  if (acx.n < 2 && acy.n < 2 && bcx.n < 2 && bcy.n < 2) {
    auto value = [](const Expansion<2>& e) { return e.n == 0 ? 0.0 : e.c[0]; };
    double left[2], right[2];
    int leftLen = 0, rightLen = 0;
    double product, err;
    twoProduct(value(acx), value(bcy), product, err);
    if (err != 0) left[leftLen++] = err;
    if (product != 0) left[leftLen++] = product;
    twoProduct(-value(acy), value(bcx), product, err);
    if (err != 0) right[rightLen++] = err;
    if (product != 0) right[rightLen++] = product;
    Expansion<4> det;
    det.n = sumExpansions(left, leftLen, right, rightLen, det.c);
    return estimate(det);
  }
  return estimate(acx * bcy - acy * bcx);
}

double orient2d(const double* a, const double* b, const double* c) {
  const double detLeft = (a[0] - c[0]) * (b[1] - c[1]);
  const double detRight = (a[1] - c[1]) * (b[0] - c[0]);
  const double det = detLeft - detRight;

  const double errBound = kOrientBound * (std::fabs(detLeft) + std::fabs(detRight));
  // One well-predicted branch on |det| (testing det > bound || -det > bound would branch on the sign).
  if (RUPPERT_LIKELY(std::fabs(det) > errBound)) return det;
  // In the safe range a computed product is zero only when a difference is exactly zero, so a zero
  // bound means both products, and the determinant, are exactly zero (e.g. repeated points).
  if (errBound == 0) return 0.0;
  return orient2dExact(a, b, c);
}

double orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double a[2] = {ax, ay}, b[2] = {bx, by}, c[2] = {cx, cy};
  return orient2d(a, b, c);
}

// ---- incircle -------------------------------------------------------------------------------------
// With every point translated so that d is the origin (x' = x - dx, ...):
//   det = |ax' ay' ax'^2+ay'^2|
//         |bx' by' bx'^2+by'^2|  = alift (bx'cy' - cx'by') + blift (cx'ay' - ax'cy') + clift (ax'by' - bx'ay')
//         |cx' cy' cx'^2+cy'^2|
// which is positive when d is inside the circle through counter-clockwise a, b, c.

// True when the four values split into two equal pairs (all four equal included).
inline bool twoEqualPairs(double p, double q, double r, double s) {
  return (p == q && r == s) || (p == r && q == s) || (p == s && q == r);
}

// Four points whose x-coordinates form two equal pairs, and whose y-coordinates do too, all lie in a
// grid {x0, x1} x {y0, y1}. Either two of them coincide (two equal rows of the determinant, or a row
// of zero differences when d is one of a, b, c) or they are the four distinct corners of an
// axis-aligned rectangle, which are cocircular. Either way the determinant is exactly zero.
// Refining long straight strips (combs, slots, perforated plates, skylines) makes such rectangles
// all the time: 97% of the exact evaluations of a 200-tooth comb at 30 degrees were rectangles.
inline bool axisAlignedRectangle(const double* a, const double* b, const double* c, const double* d) {
  return twoEqualPairs(a[0], b[0], c[0], d[0]) && twoEqualPairs(a[1], b[1], c[1], d[1]);
}

RUPPERT_NOINLINE double incircleExact(const double* a, const double* b, const double* c,
                                      const double* d) {
  if (axisAlignedRectangle(a, b, c, d)) return 0.0;
  // Each difference is exact as an expansion of <= 2 components (a single one whenever the subtraction
  // happens to be exact, which zero elimination exploits automatically).
  const Expansion<2> adx = difference(a[0], d[0]), ady = difference(a[1], d[1]);
  const Expansion<2> bdx = difference(b[0], d[0]), bdy = difference(b[1], d[1]);
  const Expansion<2> cdx = difference(c[0], d[0]), cdy = difference(c[1], d[1]);

  const Expansion<16> aLift = adx * adx + ady * ady;
  const Expansion<16> bLift = bdx * bdx + bdy * bdy;
  const Expansion<16> cLift = cdx * cdx + cdy * cdy;
  const Expansion<16> bcMinor = bdx * cdy - cdx * bdy;
  const Expansion<16> caMinor = cdx * ady - adx * cdy;
  const Expansion<16> abMinor = adx * bdy - bdx * ady;

  return estimate(aLift * bcMinor + bLift * caMinor + cLift * abMinor);
}

// ---- incircle, second stage: double-double arithmetic -----------------------------------------
// When the filter fails, the points are nearly cocircular, but most such configurations (points on
// a circle, as stars, gears and arcs give) are still far from exactly cocircular at 106 bits. This
// stage evaluates the same formula on double-double values (h + l, |l| <= u|h|) built from the exact
// differences, in about 600 branch-free operations where the expansions take 3,000-8,000.
//
// Error analysis. Write |x| for |h + l|. The three operations used:
//   difference  twoSum(a, -b): exact.
//   product     twoProduct(ah, bh) = p + pe exactly; c = fl(fl(ah bl) + fl(al bh)); the result is
//               twoSum(p, fl(pe + c)), exact. Dropped: al bl <= u^2 |ah bh|; roundings: of ah bl and
//               al bh, u^2 |ah bh| each; of their sum, 2u^2 (1 + u) |ah bh|; of pe + c (|pe| <= u|p|,
//               |c| <= 2u(1 + u)^2 |ah bh|), 3u^2 (1 + u)^2 |ah bh|. In all <= 9u^2 |a| |b|.
//   sum         twoSum(ah, bh) = s + se exactly; the result is twoSum(s, fl(se + fl(al + bl))),
//               exact. Roundings: of al + bl, u^2 (|ah| + |bh|); of se + (al + bl), with |se| <= u|s|
//               <= u(1 + u)(|ah| + |bh|), 2u^2 (1 + u)^2 (|ah| + |bh|). In all <= 4u^2 (|a| + |b|).
// Let perm(q) be the sum of the absolute values of q's monomials in the exact differences, and
// suppose each computed q' has |q' - q| <= e_q perm(q), so |q'| <= (1 + e_q) perm(q). The products
// of two differences have e = 9u^2; the lifts and minors (a sum of two such) 9u^2 + 4u^2(1 + 9u^2)
// <= 13.1u^2; lift times minor 2(13.1u^2) + (13.1u^2)^2 + 9u^2(1 + 13.1u^2)^2 <= 35.3u^2, as
// perm(LM) = perm(L) perm(M); the two final sums add 4u^2(1 + e) each: e_det <= 43.4u^2.
// perm(det) uses the exact differences, each at most (1 + u) times the rounded one, so it is at
// most (1 + u)^4 (1 + gamma_11) times the filter's computed permanent P. Since |h + l| >= (1 - u)|h|,
// |h| > 64u^2 P (computed, one rounding) gives |h + l| > 43.4u^2 (1 + 16u) P >= |det' - det|: the
// sign of h is the sign of det.
// Underflow cannot spoil the products: in the safe range every quantity of degree k in coordinate
// differences, rounding errors included, is a multiple of 2^(-180k), and k <= 4 here.
namespace {

struct DoubleDouble {
  double h, l;
};

inline DoubleDouble exactDifference(double a, double b) {
  DoubleDouble r;
  twoSum(a, -b, r.h, r.l);
  return r;
}

inline DoubleDouble product(DoubleDouble a, DoubleDouble b) {
  double p, pe;
  twoProduct(a.h, b.h, p, pe);
  const double cross = a.h * b.l + a.l * b.h;
  DoubleDouble r;
  twoSum(p, pe + cross, r.h, r.l);
  return r;
}

inline DoubleDouble sum(DoubleDouble a, DoubleDouble b) {
  double s, se;
  twoSum(a.h, b.h, s, se);
  DoubleDouble r;
  twoSum(s, se + (a.l + b.l), r.h, r.l);
  return r;
}

inline DoubleDouble negated(DoubleDouble a) { return {-a.h, -a.l}; }

// The sign of the incircle determinant when double-double arithmetic settles it (returns true and
// sets `det`), given the filter's computed permanent.
inline bool incircleDoubleDouble(const double* a, const double* b, const double* c, const double* d,
                                 double permanent, double& det) {
  const DoubleDouble adx = exactDifference(a[0], d[0]), ady = exactDifference(a[1], d[1]);
  const DoubleDouble bdx = exactDifference(b[0], d[0]), bdy = exactDifference(b[1], d[1]);
  const DoubleDouble cdx = exactDifference(c[0], d[0]), cdy = exactDifference(c[1], d[1]);
  const DoubleDouble aLift = sum(product(adx, adx), product(ady, ady));
  const DoubleDouble bLift = sum(product(bdx, bdx), product(bdy, bdy));
  const DoubleDouble cLift = sum(product(cdx, cdx), product(cdy, cdy));
  const DoubleDouble bc = sum(product(bdx, cdy), negated(product(cdx, bdy)));
  const DoubleDouble ca = sum(product(cdx, ady), negated(product(adx, cdy)));
  const DoubleDouble ab = sum(product(adx, bdy), negated(product(bdx, ady)));
  const DoubleDouble value = sum(sum(product(aLift, bc), product(bLift, ca)), product(cLift, ab));
  constexpr double kDoubleDoubleBound = 64.0 * kUnitRoundoff * kUnitRoundoff;  // 2^-100, exact
  if (std::fabs(value.h) > kDoubleDoubleBound * permanent) {
    det = value.h;
    return true;
  }
  return false;
}

// Inputs on a grid (integer or few-bit coordinates: boxes, letters, rasters, and the midpoints their
// refinement adds) make many exactly cocircular quadruples that are not axis-aligned rectangles, and
// the double-double stage fails on every zero. Such a determinant is often exact in plain doubles: if
// the six differences are exact and each is k 2^e for one e with |k| <= 2^12, each lift and minor is
// an integer multiple of 2^2e below 2^25 in magnitude, each lift times minor one of 2^4e below 2^50,
// and the sum of the three below 2^52: no operation of the filter's formula rounds (e stays far from
// underflow and overflow). About 40 operations where the expansions take 3,000 (a tenth of a small grid
// mesh's instructions went to them).
RUPPERT_NOINLINE bool smallDyadicIncircle(const double* a, const double* b, const double* c, const double* d, double& det) {
  double diff[6], tail[6];
  twoSum(a[0], -d[0], diff[0], tail[0]), twoSum(a[1], -d[1], diff[1], tail[1]);
  twoSum(b[0], -d[0], diff[2], tail[2]), twoSum(b[1], -d[1], diff[3], tail[3]);
  twoSum(c[0], -d[0], diff[4], tail[4]), twoSum(c[1], -d[1], diff[5], tail[5]);
  double largest = 0;
  for (int i = 0; i < 6; ++i) {
    if (tail[i] != 0) return false;
    largest = std::max(largest, std::fabs(diff[i]));
  }
  int exponent;
  std::frexp(largest, &exponent);  // largest < 2^exponent
  if (exponent < -200 || exponent > 200) return false;
  // 2^(12 - exponent), |diff * scale| < 2^12, built from its bits (a normal double: the exponent
  // field is 1023 + 12 - exponent, within [835, 1235]).
  const std::uint64_t bits = static_cast<std::uint64_t>(1023 + 12 - exponent) << 52;
  double scale;
  std::memcpy(&scale, &bits, sizeof scale);
  for (double v : diff)
    if (v * scale != std::trunc(v * scale)) return false;
  const double adx = diff[0], ady = diff[1], bdx = diff[2], bdy = diff[3], cdx = diff[4], cdy = diff[5];
  det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
        (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
  return true;
}

// What the filter could not decide, cheapest test first. Out of line, so that the filter's hot path
// stays as small as it was with one call after it.
RUPPERT_NOINLINE double incircleAdaptive(const double* a, const double* b, const double* c, const double* d,
                                         double permanent) {
  if (axisAlignedRectangle(a, b, c, d)) return 0.0;  // cheaper than the second stage, which fails on zero
  double settled;
  if (smallDyadicIncircle(a, b, c, d, settled)) return settled;
  if (incircleDoubleDouble(a, b, c, d, permanent, settled)) return settled;
  return incircleExact(a, b, c, d);
}

}  // namespace

double incircle(const double* a, const double* b, const double* c, const double* d) {
  const double adx = a[0] - d[0], ady = a[1] - d[1];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1];

  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;

  const double aLift = adx * adx + ady * ady;
  const double bLift = bdx * bdx + bdy * bdy;
  const double cLift = cdx * cdx + cdy * cdy;

  const double det = aLift * (bdxcdy - cdxbdy) + bLift * (cdxady - adxcdy) + cLift * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * aLift +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * bLift +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * cLift;
  const double errBound = kIncircleBound * permanent;
  if (RUPPERT_LIKELY(std::fabs(det) > errBound)) return det;
  if (errBound == 0) return 0.0;  // every monomial of the determinant is exactly zero
  return incircleAdaptive(a, b, c, d, permanent);
}

}  // namespace ruppert::detail
