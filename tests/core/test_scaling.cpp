// The input's power-of-two scaling (prepare_input.h): PreparedInput multiplies by 2^e and 2^-e where
// both are normal doubles, and calls ldexp beyond. A product with a power of two is correctly rounded
// like ldexp's result, so the two must agree bit for bit at every exponent and every value, subnormal
// results included; this is what keeps input points' output coordinates bit-identical.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "prepared_input.h"

namespace {

std::uint64_t bits(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// Values across the whole range of a double: random significands at random binary exponents, the
// extremes and their neighbors, and both signs.
std::vector<double> samples() {
  std::mt19937_64 rng(20261204);
  std::vector<double> v = {0.0, 1.0, 1.5, std::numeric_limits<double>::min(), std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::max(), std::nextafter(1.0, 2.0), 0x1.fffffffffffffp-1};
  for (int k = 0; k < 400; ++k) {
    const double significand = 1 + static_cast<double>(rng() >> 12) * 0x1p-52;
    const int exponent = -1074 + static_cast<int>(rng() % 2098);
    v.push_back(std::ldexp(significand, exponent));
  }
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) v.push_back(-v[i]);
  return v;
}

}  // namespace

TEST_CASE("the input's scaling is ldexp's, bit for bit, at every exponent", "[scaling]") {
  const std::vector<double> values = samples();
  std::size_t compared = 0;
  // Every exponent near the ends of the range (where 2^e stops being a normal double), every 37th
  // in between.
  for (int e = -1100; e <= 1100; e += std::abs(e) < 1000 ? 37 : 1) {
    ruppert::detail::PreparedInput in;
    in.setExponent(e);
    for (double v : values) {
      if (bits(in.toInternal(v)) != bits(std::ldexp(v, e)) || bits(in.toUser(v)) != bits(std::ldexp(v, -e)))
        FAIL("exponent " << e << ", value " << v << ": " << in.toInternal(v) << " / " << in.toUser(v)
                         << " where ldexp gives " << std::ldexp(v, e) << " / " << std::ldexp(v, -e));
      ++compared;
    }
  }
  CHECK(compared > 100000);
}
