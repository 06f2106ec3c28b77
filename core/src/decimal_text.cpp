#include "decimal_text.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
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

// A nonnegative big integer, 32-bit limbs, least significant first, no leading zero limbs.
using Big = std::vector<std::uint32_t>;

void trim(Big& a) {
  while (!a.empty() && a.back() == 0) a.pop_back();
}

// a = a * factor + add.
void multiplyAdd(Big& a, std::uint32_t factor, std::uint32_t add) {
  std::uint64_t carry = add;
  for (std::uint32_t& limb : a) {
    const std::uint64_t x = std::uint64_t(limb) * factor + carry;
    limb = static_cast<std::uint32_t>(x);
    carry = x >> 32;
  }
  if (carry > 0) a.push_back(static_cast<std::uint32_t>(carry));
}

// a 10^exponent, for exponent >= 0.
Big timesPowerOfTen(Big a, int exponent) {
  for (; exponent > 0; exponent -= std::min(exponent, 9)) {
    std::uint32_t factor = 1;
    for (int i = 0; i < std::min(exponent, 9); ++i) factor *= 10;
    multiplyAdd(a, factor, 0);
  }
  return a;
}

Big shiftedLeft(const Big& a, int bits) {
  Big out(static_cast<std::size_t>(bits / 32), 0);
  const int part = bits % 32;
  std::uint32_t carry = 0;
  for (std::uint32_t limb : a) {
    out.push_back(part == 0 ? limb : limb << part | carry);
    carry = part == 0 ? 0 : limb >> (32 - part);
  }
  if (carry > 0) out.push_back(carry);
  trim(out);
  return out;
}

int bitLength(const Big& a) {
  if (a.empty()) return 0;
  int bits = 32 * static_cast<int>(a.size() - 1);
  for (std::uint32_t top = a.back(); top > 0; top >>= 1) ++bits;
  return bits;
}

int compare(const Big& a, const Big& b) {
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  for (std::size_t i = a.size(); i-- > 0;)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}

// a -= b, for a >= b.
void subtract(Big& a, const Big& b) {
  std::int64_t borrow = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::int64_t x = std::int64_t(a[i]) - borrow - (i < b.size() ? std::int64_t(b[i]) : 0);
    borrow = x < 0;
    a[i] = static_cast<std::uint32_t>(x + (borrow << 32));
  }
  trim(a);
}

// The double nearest to numerator / denominator (both positive), ties to even: the quotient
// numerator / (denominator 2^k) taken to 53 bits (fewer below the normal range), then rounded by
// comparing twice the remainder with the divisor.
double nearestQuotient(const Big& numerator, const Big& denominator) {
  int k = bitLength(numerator) - bitLength(denominator) - 53;
  for (;;) {
    const int exponent = std::max(k, -1074);
    Big remainder = exponent < 0 ? shiftedLeft(numerator, -exponent) : numerator;
    const Big divisor = exponent > 0 ? shiftedLeft(denominator, exponent) : denominator;
    // The quotient has at most 54 bits (the bit lengths put it in [2^51, 2^54)).
    std::uint64_t q = 0;
    for (int bit = 54; bit >= 0; --bit) {
      const Big step = shiftedLeft(divisor, bit);
      if (compare(remainder, step) >= 0) subtract(remainder, step), q |= std::uint64_t(1) << bit;
    }
    if (q >= (std::uint64_t(1) << 53) && exponent == k) {
      ++k;
      continue;
    }
    if (q < (std::uint64_t(1) << 52) && exponent == k) {
      --k;
      continue;
    }
    const int half = compare(shiftedLeft(remainder, 1), divisor);
    if (half > 0 || (half == 0 && (q & 1) == 1)) ++q;
    return std::ldexp(static_cast<double>(q), exponent);
  }
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

double parseDecimal(std::string_view text) {
  std::size_t i = 0;
  const bool negative = !text.empty() && text[0] == '-';
  if (negative) ++i;
  const double sign = negative ? -1 : 1;
  if (text.substr(i) == "inf") return sign * std::numeric_limits<double>::infinity();
  if (text.substr(i) == "nan") return std::numeric_limits<double>::quiet_NaN();
  // The significant digits (no leading zeros) and the power of ten they are scaled by. Past 800
  // digits the rest only decides ties, which a nonzero rest breaks upwards: a trailing 1 stands
  // in for it (a double's halfway points have under 800 significant digits).
  std::string digits;
  int exponent10 = 0;
  bool rest = false;
  auto take = [&](char c, bool fraction) {
    if (digits.empty() && c == '0') {
      exponent10 -= fraction;
    } else if (digits.size() < 800) {
      digits.push_back(c);
      exponent10 -= fraction;
    } else {
      rest |= c != '0';
      exponent10 += !fraction;
    }
  };
  for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) take(text[i], false);
  if (i < text.size() && text[i] == '.')
    for (++i; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) take(text[i], true);
  if (rest) digits.push_back('1'), --exponent10;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    const bool down = i < text.size() && text[i] == '-';
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
    int e = 0;
    for (; i < text.size(); ++i) e = std::min(e * 10 + (text[i] - '0'), 100000);
    exponent10 += down ? -e : e;
  }
  if (digits.empty()) return sign * 0.0;
  const int magnitude = static_cast<int>(digits.size()) + exponent10;  // 10^(magnitude-1) <= |value|
  if (magnitude > 310) return sign * std::numeric_limits<double>::infinity();
  if (magnitude < -330) return sign * 0.0;
  // Up to 15 digits are exact in a double, as are the powers of ten to 10^22: one rounding.
  if (digits.size() <= 15 && std::abs(exponent10) <= 22) {
    double value = 0, power = 1;
    for (char c : digits) value = value * 10 + (c - '0');
    for (int k = 0; k < std::abs(exponent10); ++k) power *= 10;
    return sign * (exponent10 < 0 ? value / power : value * power);
  }
  Big numerator;
  for (std::size_t k = 0; k < digits.size(); k += 9) {
    std::uint32_t chunk = 0, factor = 1;
    for (std::size_t j = k; j < std::min(digits.size(), k + 9); ++j) chunk = chunk * 10 + (digits[j] - '0'), factor *= 10;
    multiplyAdd(numerator, factor, chunk);
  }
  if (exponent10 >= 0) return sign * nearestQuotient(timesPowerOfTen(numerator, exponent10), Big{1});
  return sign * nearestQuotient(numerator, timesPowerOfTen(Big{1}, -exponent10));
}

}  // namespace ruppert::detail
RUPPERT_COLD_END
