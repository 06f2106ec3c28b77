// The messages' number formatting (decimal_text.h) against the C library's printf, which it stands
// in for in the WebAssembly module: the same characters for every kind of double.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "decimal_text.h"
#include "message.h"

namespace {

using ruppert::detail::formatFixed;
using ruppert::detail::formatSignificant;

std::string printfText(const char* format, int precision, double v) {
  char buf[512];
  std::snprintf(buf, sizeof buf, format, precision, v);
  return buf;
}

// Doubles of every kind: random bit patterns (every exponent, subnormals), short decimals, exact
// halves that round to even, values that carry to a new digit, and the edges of the range.
std::vector<double> samples() {
  std::vector<double> out = {0.0, -0.0, 1, -1, 0.5, 1.5, 2.5, 0.125, 9.5, 99.5, 999999.5, 0.0001, 0.00001, 1e15,
                             1e16, 1e17, 123456789012345678.0, 0.1, 0.2, 0.3, 1.0 / 3, 2.0 / 3, 33.275, 34.999999,
                             std::numeric_limits<double>::max(), std::numeric_limits<double>::min(),
                             std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::epsilon()};
  std::mt19937_64 random(20261207);
  for (int i = 0; i < 3000; ++i) {
    const std::uint64_t bits = random() & ~(std::uint64_t(0x7FF) << 52) | (random() % 0x7FF) << 52;
    double v;
    std::memcpy(&v, &bits, sizeof v);
    out.push_back(v);
  }
  std::uniform_real_distribution<double> unit(0, 1000);
  for (int i = 0; i < 2000; ++i) out.push_back(std::round(unit(random) * 1000) / 1000);
  for (int i = 0; i < 500; ++i) out.push_back(std::ldexp(double(random() % 4096), -int(random() % 12)));
  return out;
}

}  // namespace

TEST_CASE("formatSignificant writes what printf's %.*g writes", "[messages]") {
  for (double v : samples())
    for (int precision : {1, 2, 3, 4, 6, 10, 15, 16, 17, 25}) {
      INFO("v " << printfText("%.*a", 13, v) << " precision " << precision);
      REQUIRE(formatSignificant(v, precision) == printfText("%.*g", precision, v));
    }
}

TEST_CASE("formatFixed writes what printf's %.*f writes", "[messages]") {
  for (double v : samples()) {
    if (std::fabs(v) > 1e30) continue;  // hundreds of integer digits: the same code, a long string
    for (int decimals : {0, 1, 2, 3, 6, 12}) {
      INFO("v " << printfText("%.*a", 13, v) << " decimals " << decimals);
      REQUIRE(formatFixed(v, decimals) == printfText("%.*f", decimals, v));
    }
  }
}

TEST_CASE("special values are written as printf writes them", "[messages]") {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(formatSignificant(inf, 6) == "inf");
  CHECK(formatSignificant(-inf, 6) == "-inf");
  CHECK(formatSignificant(nan, 6) == "nan");
  CHECK(formatFixed(-inf, 2) == "-inf");
  CHECK(ruppert::detail::formatNumber(0.1) == "0.1");
  CHECK(ruppert::detail::formatNumber(1.0 / 3) == "0.3333333333333333");
  CHECK(ruppert::detail::formatNumber(-2.5e-300) == "-2.5e-300");
}

namespace {

// Numbers as text of every kind strtod reads: random digits and exponents across the whole range
// (subnormals, overflow), long digit strings, and the exact halfway points between neighboring
// doubles (from long double, which holds them exactly on x86) and a hair either side of them.
std::vector<std::string> decimalTexts() {
  std::vector<std::string> out = {"0", "-0", "0.0", "1", "-1", "0.1", "1e22", "1e23", "9007199254740993", "123456789012345678",
                                  "2.2250738585072011e-308", "2.2250738585072014e-308", "4.9406564584124654e-324",
                                  "2.4703282292062327e-324", "2.4703282292062328e-324", "1.7976931348623157e308",
                                  "1.7976931348623158e308", "1.7976931348623159e308", "1e309", "1e-400", "00012.5000",
                                  "0.000000000000000000000000000000001", "1E+5", "1e-5", "-7.25E-3"};
  std::mt19937_64 random(71203);
  for (int i = 0; i < 4000; ++i) {
    std::string text = random() % 2 ? "-" : "";
    const int digits = 1 + int(random() % (i % 4 == 0 ? 40 : 17));
    for (int k = 0; k < digits; ++k) text.push_back(char('0' + random() % 10));
    if (random() % 2) text.insert(text.size() - std::size_t(random() % digits), ".");
    if (text.back() == '.' || text[text.size() - 1 - (text[0] == '-')] == '.') text += "5";
    if (random() % 2) text += "e" + std::to_string(int(random() % 660) - 340);
    out.push_back(text);
  }
  for (int i = 0; i < 1500; ++i) {
    const std::uint64_t bits = random() & ~(std::uint64_t(0x7FF) << 52) | (random() % 0x7FE) << 52;
    double a;
    std::memcpy(&a, &bits, sizeof a);
    const double b = std::nextafter(a, std::numeric_limits<double>::infinity());
    char buf[2000];
    std::snprintf(buf, sizeof buf, "%.1100Lg", (static_cast<long double>(a) + b) / 2);
    out.push_back(buf);
    std::string text(buf);
    if (text.find('e') == std::string::npos) {
      out.push_back(text + "0000000000000000000000000000001");
      std::snprintf(buf, sizeof buf, "%.60Lg", (static_cast<long double>(a) + b) / 2);
      out.push_back(buf);
    }
  }
  return out;
}

}  // namespace

TEST_CASE("parseDecimal reads what strtod reads", "[messages]") {
  for (const std::string& text : decimalTexts()) {
    INFO(text);
    const double expected = std::strtod(text.c_str(), nullptr), got = ruppert::detail::parseDecimal(text);
    REQUIRE(std::memcmp(&expected, &got, sizeof got) == 0);
  }
}
