// Tests of the robust predicates against exact rational arithmetic (GMP). Every double converts exactly to
// an mpq_class, so the GMP determinant is the true value; each case compares signs.
//
// Families of hard inputs and where they come from:
//   * ulp-spaced grids near a line: the classic demonstration that naive floating-point orientation
//     tests give inconsistent answers (Kettner, Mehlhorn, Pion, Schirra, Yap, "Classroom examples of
//     robustness problems in geometric computations", 2008).
//   * integer points on circles with many lattice points (radii 5, 25, 65, 325, 1105, products of
//     primes 1 mod 4), scaled by powers of two and translated: exactly cocircular, so incircle must be 0,
//     and a one-ulp move of one point must give the exact nonzero sign.
//   * random, nearly collinear and nearly cocircular configurations, scaled by 2^k across the whole
//     safe range: scaling by a power of two is exact, so the sign must never change.
//   * extreme coordinates (0, 2^-128, 2^64 and their neighbors) mixed in one configuration, which is
//     where underflow or overflow would break the error-free transformations.

#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "mesh/predicates.h"

namespace {

using ruppert::detail::incircle;
using ruppert::detail::incircleExact;
using ruppert::detail::isSafeCoordinate;
using ruppert::detail::kSafeMaxMagnitude;
using ruppert::detail::kSafeMinMagnitude;
using ruppert::detail::orient2d;
using ruppert::detail::orient2dExact;

using Point = std::array<double, 2>;

int signOf(double v) { return (v > 0) - (v < 0); }

mpq_class exactOrient(const Point& a, const Point& b, const Point& c) {
  const mpq_class acx = mpq_class(a[0]) - mpq_class(c[0]), acy = mpq_class(a[1]) - mpq_class(c[1]);
  const mpq_class bcx = mpq_class(b[0]) - mpq_class(c[0]), bcy = mpq_class(b[1]) - mpq_class(c[1]);
  return mpq_class(acx * bcy - acy * bcx);
}

mpq_class exactIncircle(const Point& a, const Point& b, const Point& c, const Point& d) {
  const mpq_class adx = mpq_class(a[0]) - mpq_class(d[0]), ady = mpq_class(a[1]) - mpq_class(d[1]);
  const mpq_class bdx = mpq_class(b[0]) - mpq_class(d[0]), bdy = mpq_class(b[1]) - mpq_class(d[1]);
  const mpq_class cdx = mpq_class(c[0]) - mpq_class(d[0]), cdy = mpq_class(c[1]) - mpq_class(d[1]);
  const mpq_class aLift = adx * adx + ady * ady;
  const mpq_class bLift = bdx * bdx + bdy * bdy;
  const mpq_class cLift = cdx * cdx + cdy * cdy;
  return mpq_class(aLift * (bdx * cdy - cdx * bdy) + bLift * (cdx * ady - adx * cdy) +
                   cLift * (adx * bdy - bdx * ady));
}

int exactOrientSign(const Point& a, const Point& b, const Point& c) { return sgn(exactOrient(a, b, c)); }
int exactIncircleSign(const Point& a, const Point& b, const Point& c, const Point& d) {
  return sgn(exactIncircle(a, b, c, d));
}

int orientSign(const Point& a, const Point& b, const Point& c) {
  return signOf(orient2d(a.data(), b.data(), c.data()));
}
int incircleSign(const Point& a, const Point& b, const Point& c, const Point& d) {
  return signOf(incircle(a.data(), b.data(), c.data(), d.data()));
}

// The textbook formula in plain doubles, to show that a family of inputs is actually hard.
double naiveOrient(const Point& a, const Point& b, const Point& c) {
  return (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]);
}

Point scaled(const Point& p, int k) { return {std::ldexp(p[0], k), std::ldexp(p[1], k)}; }

bool allSafe(std::initializer_list<Point> points) {
  for (const Point& p : points)
    if (!isSafeCoordinate(p[0]) || !isSafeCoordinate(p[1])) return false;
  return true;
}

// Integer points (x, y) with x^2 + y^2 == r^2.
std::vector<std::array<std::int64_t, 2>> latticePointsOnCircle(std::int64_t r) {
  std::vector<std::array<std::int64_t, 2>> points;
  for (std::int64_t x = -r; x <= r; ++x) {
    const std::int64_t rest = r * r - x * x;
    auto y = static_cast<std::int64_t>(std::llround(std::sqrt(static_cast<double>(rest))));
    while (y * y > rest) --y;
    while ((y + 1) * (y + 1) <= rest) ++y;
    if (y * y != rest) continue;
    points.push_back({x, y});
    if (y != 0) points.push_back({x, -y});
  }
  return points;
}

// A double with a random 53-bit significand and magnitude in [2^lo, 2^hi), random sign.
double randomDouble(std::mt19937_64& rng, int lo, int hi) {
  const double significand = 1.0 + std::ldexp(static_cast<double>(rng() >> 12), -52);  // [1, 2)
  const int exponent = lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo));
  const double v = std::ldexp(significand, exponent);
  return (rng() & 1) ? v : -v;
}

}  // namespace

TEST_CASE("isSafeCoordinate accepts exactly the documented range", "[predicates]") {
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_FALSE(isSafeCoordinate(std::numeric_limits<double>::quiet_NaN()));
  CHECK_FALSE(isSafeCoordinate(inf));
  CHECK_FALSE(isSafeCoordinate(-inf));
  CHECK_FALSE(isSafeCoordinate(1e300));
  CHECK_FALSE(isSafeCoordinate(-1e300));
  CHECK_FALSE(isSafeCoordinate(1e-300));
  CHECK_FALSE(isSafeCoordinate(std::numeric_limits<double>::denorm_min()));
  CHECK_FALSE(isSafeCoordinate(std::nextafter(kSafeMaxMagnitude, inf)));
  CHECK_FALSE(isSafeCoordinate(std::nextafter(kSafeMinMagnitude, 0.0)));
  CHECK_FALSE(isSafeCoordinate(-std::nextafter(kSafeMinMagnitude, 0.0)));

  CHECK(isSafeCoordinate(0.0));
  CHECK(isSafeCoordinate(-0.0));
  CHECK(isSafeCoordinate(1.0));
  CHECK(isSafeCoordinate(-1.0));
  CHECK(isSafeCoordinate(0x1p64));
  CHECK(isSafeCoordinate(-0x1p64));
  CHECK(isSafeCoordinate(0x1p-128));
  CHECK(isSafeCoordinate(-0x1p-128));
  CHECK(kSafeMaxMagnitude == 0x1p64);
  CHECK(kSafeMinMagnitude == 0x1p-128);
}

TEST_CASE("orient2d and incircle on simple configurations", "[predicates]") {
  const Point o{0, 0}, x{1, 0}, y{0, 1};
  // Twice the signed area of a unit right triangle is exactly 1.
  CHECK(orient2d(o.data(), x.data(), y.data()) == 1.0);
  CHECK(orient2d(o.data(), y.data(), x.data()) == -1.0);
  CHECK(orient2d(0, 0, 1, 0, 0, 1) == 1.0);
  CHECK(orient2d(0, 0, 1, 1, 3, 3) == 0.0);
  CHECK(orient2d(o.data(), o.data(), x.data()) == 0.0);

  // Circle through (1,0), (0,1), (-1,0): the center is inside, (2,2) outside, (0,-1) on it.
  const Point a{1, 0}, b{0, 1}, c{-1, 0};
  const Point inside{0, 0}, outside{2, 2}, on{0, -1};
  CHECK(incircle(a.data(), b.data(), c.data(), inside.data()) > 0);
  CHECK(incircle(a.data(), b.data(), c.data(), outside.data()) < 0);
  CHECK(incircle(a.data(), b.data(), c.data(), on.data()) == 0.0);
  // A clockwise triangle flips the sign.
  CHECK(incircle(c.data(), b.data(), a.data(), inside.data()) < 0);
  // A repeated point is on every circle through it.
  CHECK(incircle(a.data(), b.data(), c.data(), a.data()) == 0.0);
}

TEST_CASE("orient2d on an ulp-spaced grid near the line y = x", "[predicates]") {
  // p = (0.5 + i u, 0.5 + j u) with u = 2^-53, the spacing of doubles at 0.5; q and r are on y = x.
  const Point q{12, 12}, r{24, 24};
  int checked = 0, naiveWrong = 0, zeros = 0;
  for (int i = 0; i < 256; ++i) {
    for (int j = 0; j < 256; ++j) {
      const Point p{0.5 + std::ldexp(i, -53), 0.5 + std::ldexp(j, -53)};
      const int expected = exactOrientSign(p, q, r);
      // The three rotations give the same determinant but round differently.
      REQUIRE(orientSign(p, q, r) == expected);
      REQUIRE(orientSign(q, r, p) == expected);
      REQUIRE(orientSign(r, p, q) == expected);
      REQUIRE(orientSign(q, p, r) == -expected);
      if (signOf(naiveOrient(p, q, r)) != expected) ++naiveWrong;
      if (expected == 0) ++zeros;
      checked += 4;
    }
  }
  // The family is only a meaningful test if plain doubles get it wrong somewhere.
  CHECK(naiveWrong > 1000);
  CHECK(zeros == 256);  // exactly the diagonal i == j is collinear
  CHECK(checked == 4 * 65536);
}

TEST_CASE("orient2d on grids near lines of general slope", "[predicates]") {
  std::mt19937_64 rng(20240601);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0), along(-0.5, 1.5);
  int checked = 0, naiveWrong = 0;
  for (int line = 0; line < 24; ++line) {
    const Point q{coordinate(rng), coordinate(rng)}, r{coordinate(rng), coordinate(rng)};
    const double t = along(rng);
    const Point base{q[0] + t * (r[0] - q[0]), q[1] + t * (r[1] - q[1])};  // rounded: near the line
    // Spacings of 1 ulp of the base point and 2^13 ulps (2^-40 for coordinates in [0.5, 1)).
    for (int spacingLog : {0, 13}) {
      const double hx = std::ldexp(std::nextafter(std::fabs(base[0]), 1e9) - std::fabs(base[0]), spacingLog);
      const double hy = std::ldexp(std::nextafter(std::fabs(base[1]), 1e9) - std::fabs(base[1]), spacingLog);
      for (int i = -16; i <= 16; ++i) {
        for (int j = -16; j <= 16; ++j) {
          const Point p{base[0] + i * hx, base[1] + j * hy};  // exact: small multiples of the ulp
          const int expected = exactOrientSign(p, q, r);
          REQUIRE(orientSign(p, q, r) == expected);
          REQUIRE(orientSign(r, p, q) == expected);
          REQUIRE(orientSign(p, r, q) == -expected);
          if (signOf(naiveOrient(p, q, r)) != expected) ++naiveWrong;
          checked += 3;
        }
      }
    }
  }
  CHECK(naiveWrong > 0);
  CHECK(checked == 24 * 2 * 33 * 33 * 3);
}

TEST_CASE("orient2d is exactly zero on exactly collinear points at every scale", "[predicates]") {
  std::mt19937_64 rng(7);
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // p + m * step with small integers m and a step of 20 significant bits: every point is exact.
    const Point p{randomDouble(rng, -2, 2), randomDouble(rng, -2, 2)};
    const double stepX = std::ldexp(static_cast<double>(rng() % (1u << 20)), -20);
    const double stepY = std::ldexp(static_cast<double>(rng() % (1u << 20)), -20);
    const Point a{p[0] + 3 * stepX, p[1] + 3 * stepY};
    const Point b{p[0] - 5 * stepX, p[1] - 5 * stepY};
    const Point c{p[0] + 11 * stepX, p[1] + 11 * stepY};
    if (exactOrientSign(a, b, c) != 0) continue;  // a rounding occurred: not this test's business
    for (int k = -100; k <= 60; k += 8) {
      const Point sa = scaled(a, k), sb = scaled(b, k), sc = scaled(c, k);
      if (!allSafe({sa, sb, sc})) continue;
      REQUIRE(orient2d(sa.data(), sb.data(), sc.data()) == 0.0);
      REQUIRE(orient2dExact(sa.data(), sb.data(), sc.data()) == 0.0);
      // One ulp off the line is never collinear and must get the exact sign.
      const Point moved{sc[0], std::nextafter(sc[1], (trial & 1) ? 1e300 : -1e300)};
      if (!allSafe({moved})) continue;
      const int expected = exactOrientSign(sa, sb, moved);
      REQUIRE(expected != 0);
      REQUIRE(orientSign(sa, sb, moved) == expected);
      checked += 3;
    }
  }
  CHECK(checked > 3000);
}

TEST_CASE("incircle on cocircular lattice points, scaled and translated", "[predicates]") {
  std::mt19937_64 rng(65);
  int zerosChecked = 0, perturbedChecked = 0;
  for (std::int64_t radius : {5, 25, 65, 325, 1105}) {
    const auto lattice = latticePointsOnCircle(radius);
    REQUIRE(lattice.size() >= 12);
    for (int k : {-128, -100, -64, -20, -1, 0, 1, 12, 23, 50}) {
      for (std::int64_t shift : {std::int64_t{0}, std::int64_t{3}, std::int64_t{-1000003},
                                 (std::int64_t{1} << 40) - 7}) {
        // (x + shift) 2^k is an integer of < 42 bits times a power of two: exactly representable.
        const double bound = std::ldexp(static_cast<double>(radius + std::llabs(shift)), k);
        if (bound > kSafeMaxMagnitude) continue;
        auto toPoint = [&](std::size_t index) {
          return Point{std::ldexp(static_cast<double>(lattice[index][0] + shift), k),
                       std::ldexp(static_cast<double>(lattice[index][1] - shift), k)};
        };
        for (int sample = 0; sample < 40; ++sample) {
          std::size_t ia = rng() % lattice.size(), ib = rng() % lattice.size(),
                      ic = rng() % lattice.size(), id = rng() % lattice.size();
          if (ia == ib || ia == ic || ib == ic) continue;
          const Point a = toPoint(ia), b = toPoint(ib), c = toPoint(ic), d = toPoint(id);
          REQUIRE(allSafe({a, b, c, d}));
          REQUIRE(exactIncircleSign(a, b, c, d) == 0);  // the fixture itself
          REQUIRE(incircle(a.data(), b.data(), c.data(), d.data()) == 0.0);
          REQUIRE(incircle(b.data(), c.data(), a.data(), d.data()) == 0.0);
          REQUIRE(incircle(a.data(), c.data(), d.data(), b.data()) == 0.0);
          zerosChecked += 3;

          // Move d, then a, by one ulp in each axis direction: the exact sign is never 0.
          const double inf = std::numeric_limits<double>::infinity();
          for (int axis = 0; axis < 2; ++axis) {
            for (double toward : {inf, -inf}) {
              Point dMoved = d;
              dMoved[axis] = std::nextafter(d[axis], toward);
              Point aMoved = a;
              aMoved[axis] = std::nextafter(a[axis], toward);
              if (!allSafe({dMoved, aMoved})) continue;  // 0 moves to a denormal
              const int expectedD = exactIncircleSign(a, b, c, dMoved);
              REQUIRE(expectedD != 0);
              REQUIRE(incircleSign(a, b, c, dMoved) == expectedD);
              REQUIRE(incircleSign(b, a, c, dMoved) == -expectedD);

              const int expectedA = exactIncircleSign(aMoved, b, c, d);
              REQUIRE(incircleSign(aMoved, b, c, d) == expectedA);
              perturbedChecked += 3;
            }
          }
        }
      }
    }
  }
  CHECK(zerosChecked > 3000);
  CHECK(perturbedChecked > 10000);
}

// Points of a grid k 2^e with |k| up to a little past 2^12 (and then 2^13 with 2^12 + 1 odd steps):
// incircle decides most of them in plain doubles when every difference is such a multiple below
// 2^12, and must hand the others on. Many quadruples are cocircular (sign 0); each sign against GMP.
TEST_CASE("incircle on random points of small grids, where plain doubles can be exact", "[predicates]") {
  std::mt19937_64 rng(4097);
  int zeros = 0, checked = 0;
  for (int e : {-70, -30, -12, -1, 0, 3, 40}) {
    for (std::int64_t span : {std::int64_t{3}, std::int64_t{16}, std::int64_t{2047}, std::int64_t{2049},
                              std::int64_t{4096}, std::int64_t{8193}}) {
      for (std::int64_t offset : {std::int64_t{0}, std::int64_t{-5}, std::int64_t{1} << 30}) {
        auto coordinate = [&] {
          const std::int64_t k = static_cast<std::int64_t>(rng() % (2 * span + 1)) - span;
          return std::ldexp(static_cast<double>(k + offset), e);
        };
        for (int sample = 0; sample < 300; ++sample) {
          Point p[4];
          for (Point& q : p) q = Point{coordinate(), coordinate()};
          if (!allSafe({p[0], p[1], p[2], p[3]})) continue;
          const int expected = exactIncircleSign(p[0], p[1], p[2], p[3]);
          REQUIRE(incircleSign(p[0], p[1], p[2], p[3]) == expected);
          REQUIRE(incircleSign(p[1], p[0], p[2], p[3]) == -expected);
          zeros += expected == 0;
          ++checked;
        }
      }
    }
  }
  CHECK(checked > 30000);
  CHECK(zeros > 500);
  // Cocircular lattice points whose differences are multiples of 2^e below 2^12 (radius 1105) and
  // past it (5525 to 160,225: there plain doubles round, and must not be trusted).
  int cocircular = 0;
  for (std::int64_t radius : {1105, 5525, 27625, 160225}) {
    const auto lattice = latticePointsOnCircle(radius);
    for (int e : {-40, 0, 7}) {
      auto toPoint = [&](std::size_t i) {
        return Point{std::ldexp(static_cast<double>(lattice[i][0]), e), std::ldexp(static_cast<double>(lattice[i][1]), e)};
      };
      for (int sample = 0; sample < 2000; ++sample) {
        const std::size_t ia = rng() % lattice.size(), ib = rng() % lattice.size(), ic = rng() % lattice.size(),
                          id = rng() % lattice.size();
        if (ia == ib || ia == ic || ib == ic) continue;
        REQUIRE(incircle(toPoint(ia).data(), toPoint(ib).data(), toPoint(ic).data(), toPoint(id).data()) == 0.0);
        ++cocircular;
      }
    }
  }
  CHECK(cocircular > 10000);
}

TEST_CASE("random and near-degenerate configurations keep their exact sign at every scale",
          "[predicates]") {
  std::mt19937_64 rng(1997);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Base coordinates are 0 or have magnitude in [2^-8, 2^1), so scaling by 2^k for k in [-120, 62]
  // stays inside the safe range.
  auto usable = [](const Point& p) {
    for (double v : p)
      if (v != 0 && (std::fabs(v) < 0x1p-8 || std::fabs(v) >= 2.0)) return false;
    return true;
  };
  auto randomPoint = [&] { return Point{randomDouble(rng, -8, 1), randomDouble(rng, -8, 1)}; };

  int configurations = 0, attempts = 0, checked = 0, nearZeroOrient = 0, nearZeroIncircle = 0;
  while (configurations < 1500) {
    REQUIRE(++attempts < 100000);  // the generators below must not reject almost everything
    Point a = randomPoint(), b = randomPoint(), c = randomPoint(), d = randomPoint();
    const int kind = configurations % 5;
    if (kind == 1 || kind == 3) {
      // c rounded onto the line ab, optionally nudged by one ulp.
      const double t = unit(rng) * 3 - 1;
      c = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
      if (kind == 3) {
        const int axis = static_cast<int>(rng() & 1);
        c[axis] = std::nextafter(c[axis], (rng() & 1) ? 4.0 : -4.0);
      }
    }
    if (kind == 2) {
      // d rounded onto the circumcircle of a, b, c, sometimes nudged by one more ulp.
      const double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
      const double den = 2 * (bx * cy - by * cx);
      if (den == 0) continue;
      const double ux = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / den;
      const double uy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / den;
      const double angle = unit(rng) * 6.283185307179586;
      const double rad = std::hypot(ux, uy);
      d = {a[0] + ux + rad * std::cos(angle), a[1] + uy + rad * std::sin(angle)};
      if (rng() & 1) {
        const int axis = static_cast<int>(rng() & 1);
        d[axis] = std::nextafter(d[axis], (rng() & 1) ? 4.0 : -4.0);
      }
    }
    if (kind == 4) {
      d = (rng() & 1) ? a : b;  // repeated points: exactly zero
      c = {a[0], std::nextafter(a[1], 4.0)};
    }
    if (!usable(a) || !usable(b) || !usable(c) || !usable(d)) continue;
    ++configurations;

    const int orientExpected = exactOrientSign(a, b, c);
    const int incircleExpected = exactIncircleSign(a, b, c, d);
    const double naive = naiveOrient(a, b, c);
    if (std::fabs(naive) < 1e-12) ++nearZeroOrient;
    if (kind == 2 || kind == 4) ++nearZeroIncircle;

    for (int k = -120; k <= 62; k += 7) {
      const Point sa = scaled(a, k), sb = scaled(b, k), sc = scaled(c, k), sd = scaled(d, k);
      REQUIRE(allSafe({sa, sb, sc, sd}));
      REQUIRE(orientSign(sa, sb, sc) == orientExpected);
      REQUIRE(signOf(orient2dExact(sa.data(), sb.data(), sc.data())) == orientExpected);
      REQUIRE(incircleSign(sa, sb, sc, sd) == incircleExpected);
      REQUIRE(signOf(incircleExact(sa.data(), sb.data(), sc.data(), sd.data())) == incircleExpected);
      checked += 4;
    }
  }
  CHECK(nearZeroOrient > 100);
  CHECK(nearZeroIncircle > 400);
  CHECK(checked == 1500 * 27 * 4);
}

TEST_CASE("exact stages match GMP on inputs whose differences are not representable", "[predicates]") {
  // Coordinates of very different magnitudes make every subtraction inexact, so the exact stages work
  // on two-component differences and long expansions; their estimate must also be close in value.
  std::mt19937_64 rng(4242);
  int checked = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int lo = -60 + static_cast<int>(rng() % 60);
    const Point a{randomDouble(rng, lo, 60), randomDouble(rng, lo, 60)};
    const Point b{randomDouble(rng, lo, 60), randomDouble(rng, lo, 60)};
    const Point c{randomDouble(rng, lo, 60), randomDouble(rng, lo, 60)};
    const Point d{randomDouble(rng, lo, 60), randomDouble(rng, lo, 60)};

    const mpq_class orientValue = exactOrient(a, b, c);
    const double orientEstimate = orient2dExact(a.data(), b.data(), c.data());
    REQUIRE(signOf(orientEstimate) == sgn(orientValue));
    REQUIRE(abs(mpq_class(orientEstimate) - orientValue) <= abs(orientValue) * mpq_class(0x1p-45));
    REQUIRE(signOf(orient2d(a.data(), b.data(), c.data())) == sgn(orientValue));

    const mpq_class incircleValue = exactIncircle(a, b, c, d);
    const double incircleEstimate = incircleExact(a.data(), b.data(), c.data(), d.data());
    REQUIRE(signOf(incircleEstimate) == sgn(incircleValue));
    REQUIRE(abs(mpq_class(incircleEstimate) - incircleValue) <= abs(incircleValue) * mpq_class(0x1p-45));
    REQUIRE(signOf(incircle(a.data(), b.data(), c.data(), d.data())) == sgn(incircleValue));
    checked += 6;
  }
  CHECK(checked == 24000);
}

TEST_CASE("incircle on points rounded onto one circle, where the filter fails", "[predicates]") {
  // Points of stars, gears and arcs: four points on one circle, each rounded to doubles, so the
  // determinant is tiny but rarely zero. The filter gives up on them and the double-double stage
  // decides most; every sign must be GMP's. Offsets far from the origin make the differences
  // inexact (two-component) as well.
  std::mt19937_64 rng(31415);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int filterFailed = 0, nonzeroAmongThose = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const int k = -30 + static_cast<int>(rng() % 60);
    const double radius = std::ldexp(0.5 + unit(rng), k);
    const double offset = (trial % 3 == 0) ? 0.0 : std::ldexp(unit(rng), k + static_cast<int>(rng() % 30));
    const double cx = offset * (unit(rng) - 0.5), cy = offset * (unit(rng) - 0.5);
    std::array<double, 4> angles{};
    for (double& t : angles) t = unit(rng) * 6.283185307179586;
    std::sort(angles.begin(), angles.end());  // counter-clockwise a, b, c
    std::array<Point, 4> p{};
    for (int i = 0; i < 4; ++i) p[i] = {cx + radius * std::cos(angles[i]), cy + radius * std::sin(angles[i])};
    const Point &a = p[0], &b = p[1], &c = p[2], &d = p[3];
    if (!allSafe({a, b, c, d})) continue;
    const int expected = exactIncircleSign(a, b, c, d);
    REQUIRE(incircleSign(a, b, c, d) == expected);
    // Whether the filter failed here: the same test as incircle()'s first stage.
    const double adx = a[0] - d[0], ady = a[1] - d[1], bdx = b[0] - d[0], bdy = b[1] - d[1];
    const double qdx = c[0] - d[0], qdy = c[1] - d[1];
    const double al = adx * adx + ady * ady, bl = bdx * bdx + bdy * bdy, cl = qdx * qdx + qdy * qdy;
    const double det = al * (bdx * qdy - qdx * bdy) + bl * (qdx * ady - adx * qdy) + cl * (adx * bdy - bdx * ady);
    const double permanent = (std::fabs(bdx * qdy) + std::fabs(qdx * bdy)) * al +
                             (std::fabs(qdx * ady) + std::fabs(adx * qdy)) * bl +
                             (std::fabs(adx * bdy) + std::fabs(bdx * ady)) * cl;
    if (std::fabs(det) <= 0x1p-49 * permanent) {
      ++filterFailed;
      if (expected != 0) ++nonzeroAmongThose;
    }
  }
  // The family does reach the later stages, mostly with a nonzero answer.
  CHECK(filterFailed > 2000);
  CHECK(nonzeroAmongThose > filterFailed / 2);
}

TEST_CASE("incircle on axis-aligned rectangles and grids of two by two values", "[predicates]") {
  // The exact stage answers zero at once when the x-coordinates form two equal pairs and the
  // y-coordinates do too. Every arrangement of such points (the four corners in any order, a query
  // point on a vertex, repeated points) must agree with GMP, and a corner moved by one ulp, which
  // leaves the pattern, must get its exact nonzero sign.
  std::mt19937_64 rng(2718);
  int zeros = 0, moved = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int lo = -40 + static_cast<int>(rng() % 80);
    const double x0 = randomDouble(rng, lo, lo + 3), x1 = randomDouble(rng, lo, lo + 3);
    const double y0 = randomDouble(rng, lo, lo + 3), y1 = randomDouble(rng, lo, lo + 3);
    const std::array<Point, 4> grid{Point{x0, y0}, Point{x1, y0}, Point{x1, y1}, Point{x0, y1}};
    // Four picks from the grid, with repetition: corners in every order, and repeated points.
    const Point a = grid[rng() % 4], b = grid[rng() % 4], c = grid[rng() % 4], d = grid[rng() % 4];
    REQUIRE(exactIncircleSign(a, b, c, d) == 0);
    REQUIRE(incircleSign(a, b, c, d) == 0);
    REQUIRE(incircleExact(a.data(), b.data(), c.data(), d.data()) == 0.0);
    ++zeros;

    Point e = d;
    const std::size_t axis = rng() % 2;
    e[axis] = std::nextafter(e[axis], (rng() & 1) ? 1e300 : -1e300);
    if (!allSafe({a, b, c, e})) continue;
    const int expected = exactIncircleSign(a, b, c, e);
    REQUIRE(incircleSign(a, b, c, e) == expected);
    REQUIRE(signOf(incircleExact(a.data(), b.data(), c.data(), e.data())) == expected);
    if (expected != 0) ++moved;
  }
  CHECK(zeros == 2000);
  CHECK(moved > 100);
}

TEST_CASE("extreme coordinates at both ends of the safe range", "[predicates]") {
  // Values at and next to 0, 2^-128 and 2^64 combined freely: the smallest differences are 2^-180 and
  // the largest products near 2^260, the limits the safe range is designed around.
  const double tiny = kSafeMinMagnitude, huge = kSafeMaxMagnitude;
  const std::vector<double> pool = {0.0,
                                    tiny,
                                    -tiny,
                                    std::nextafter(tiny, 1.0),
                                    -std::nextafter(tiny, 1.0),
                                    2 * tiny,
                                    huge,
                                    -huge,
                                    std::nextafter(huge, 0.0),
                                    -std::nextafter(huge, 0.0),
                                    0x1p63,
                                    1.0,
                                    std::nextafter(1.0, 2.0),
                                    std::nextafter(1.0, 0.0),
                                    -1.0,
                                    0x1p-64,
                                    0x1p32 + 1};
  for (double v : pool) REQUIRE(isSafeCoordinate(v));
  std::mt19937_64 rng(128);
  auto pick = [&] { return Point{pool[rng() % pool.size()], pool[rng() % pool.size()]}; };
  int checked = 0, zeros = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    const Point a = pick(), b = pick(), c = pick(), d = pick();
    const int orientExpected = exactOrientSign(a, b, c);
    const int incircleExpected = exactIncircleSign(a, b, c, d);
    REQUIRE(orientSign(a, b, c) == orientExpected);
    REQUIRE(signOf(orient2dExact(a.data(), b.data(), c.data())) == orientExpected);
    REQUIRE(incircleSign(a, b, c, d) == incircleExpected);
    REQUIRE(signOf(incircleExact(a.data(), b.data(), c.data(), d.data())) == incircleExpected);
    if (incircleExpected == 0) ++zeros;
    checked += 4;
  }
  CHECK(zeros > 0);
  CHECK(checked == 24000);
}

