#include "decimal_text.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "cold_code.h"

// Messages only: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

namespace ruppert::detail {
namespace {

// A nonnegative number 0.digits x 10^point; digits has no leading or trailing zeros (empty: zero).
struct Decimal {
  std::string digits;
  int point = 0;
};

constexpr std::uint32_t kLimb = 1000000000;  // base of the big integer's limbs

// big *= factor (factor * limb + carry fits 64 bits for factor < 2^32).
void multiply(std::vector<std::uint32_t>& big, std::uint64_t factor) {
  std::uint64_t carry = 0;
  for (std::uint32_t& limb : big) {
    const std::uint64_t x = limb * factor + carry;
    limb = static_cast<std::uint32_t>(x % kLimb);
    carry = x / kLimb;
  }
  for (; carry > 0; carry /= kLimb) big.push_back(static_cast<std::uint32_t>(carry % kLimb));
}

// |v|'s exact decimal expansion: a finite double is m 2^e with an integer m < 2^53, which is
// m 2^e (e >= 0) or m 5^-e x 10^e (e < 0), both integers times a power of ten.
Decimal exactDecimal(double v) {
  Decimal d;
  if (v == 0) return d;
  int e = 0;
  const double fraction = std::frexp(std::fabs(v), &e);
  std::uint64_t m = static_cast<std::uint64_t>(std::ldexp(fraction, 53));
  e -= 53;
  std::vector<std::uint32_t> big;
  for (; m > 0; m /= kLimb) big.push_back(static_cast<std::uint32_t>(m % kLimb));
  int exponent10 = 0;
  for (; e > 0; e -= std::min(e, 29)) multiply(big, std::uint64_t(1) << std::min(e, 29));
  for (; e < 0; e += std::min(-e, 13)) {
    const int k = std::min(-e, 13);
    std::uint64_t power = 1;
    for (int i = 0; i < k; ++i) power *= 5;
    multiply(big, power);
    exponent10 -= k;
  }
  d.digits = std::to_string(big.back());
  for (std::size_t i = big.size() - 1; i-- > 0;) {
    const std::string limb = std::to_string(big[i]);
    d.digits.append(9 - limb.size(), '0').append(limb);
  }
  std::size_t end = d.digits.size();
  while (d.digits[end - 1] == '0') --end;
  d.point = static_cast<int>(d.digits.size()) + exponent10;
  d.digits.resize(end);
  return d;
}

// d rounded to its first `keep` digits (keep may be zero or negative: digits before the first),
// half to even.
Decimal rounded(Decimal d, int keep) {
  if (keep >= static_cast<int>(d.digits.size())) return d;
  if (keep < 0) return Decimal{};
  const std::size_t k = static_cast<std::size_t>(keep);
  const char next = d.digits[k];
  const bool beyond = d.digits.size() > k + 1;  // trailing zeros are stripped: a nonzero digit follows
  const bool odd = k > 0 && (d.digits[k - 1] - '0') % 2 == 1;
  const bool up = next > '5' || (next == '5' && (beyond || odd));
  d.digits.resize(k);
  if (up) {
    std::size_t i = k;
    while (i > 0 && d.digits[i - 1] == '9') --i;
    d.digits.resize(i);
    if (i == 0) {
      d.digits = "1";
      ++d.point;
    } else {
      ++d.digits[i - 1];
    }
  }
  while (!d.digits.empty() && d.digits.back() == '0') d.digits.pop_back();
  if (d.digits.empty()) d.point = 0;
  return d;
}

// NaN and infinities as printf writes them; empty for a finite v.
std::string special(double v) {
  if (std::isnan(v)) return std::signbit(v) ? "-nan" : "nan";
  if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
  return {};
}

// Digits [from, to) of d, zeros where d has none.
std::string digitRange(const Decimal& d, int from, int to) {
  std::string out;
  for (int i = from; i < to; ++i)
    out.push_back(i >= 0 && i < static_cast<int>(d.digits.size()) ? d.digits[static_cast<std::size_t>(i)] : '0');
  return out;
}

}  // namespace

std::string formatSignificant(double v, int significant) {
  std::string out = special(v);
  if (!out.empty()) return out;
  if (std::signbit(v)) out = "-";
  const Decimal d = rounded(exactDecimal(v), significant);
  if (d.digits.empty()) return out + "0";
  const int exponent = d.point - 1, count = static_cast<int>(d.digits.size());
  if (exponent < -4 || exponent >= significant) {
    out += d.digits.substr(0, 1);
    if (count > 1) out += "." + d.digits.substr(1);
    const int magnitude = std::abs(exponent);
    out += exponent < 0 ? "e-" : "e+";
    if (magnitude < 10) out += "0";
    return out + std::to_string(magnitude);
  }
  out += exponent < 0 ? "0" : digitRange(d, 0, d.point);
  if (count > d.point) out += "." + digitRange(d, d.point, count);
  return out;
}

std::string formatFixed(double v, int decimals) {
  std::string out = special(v);
  if (!out.empty()) return out;
  if (std::signbit(v)) out = "-";
  Decimal d = exactDecimal(v);
  d = rounded(d, d.point + decimals);
  out += d.point > 0 && !d.digits.empty() ? digitRange(d, 0, d.point) : "0";
  if (decimals > 0) out += "." + digitRange(d, d.point, d.point + decimals);
  return out;
}

}  // namespace ruppert::detail
RUPPERT_COLD_END
