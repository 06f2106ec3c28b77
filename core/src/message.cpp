#include "message.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "cold_code.h"

// Messages are built on error and notice paths only: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

namespace ruppert::detail {

std::string message(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts) out.append(p);
  return out;
}

std::string formatNumber(double v) {
  char buf[40];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v || std::isnan(v)) break;
  }
  return buf;
}

}  // namespace ruppert::detail
RUPPERT_COLD_END
