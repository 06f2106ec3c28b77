#include "message.h"

#include <cmath>

#include "cold_code.h"
#include "decimal_text.h"

// Messages are built on error and notice paths only: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

namespace ruppert::detail {

std::string message(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts) out.append(p);
  return out;
}

std::string formatNumber(double v) {
  std::string text;
  for (int digits = 6; digits <= 17; ++digits) {
    text = formatSignificant(v, digits);
    if (std::isnan(v) || parseDecimal(text) == v) break;
  }
  return text;
}

}  // namespace ruppert::detail
RUPPERT_COLD_END
