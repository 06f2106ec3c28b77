#include "message.h"

namespace ruppert::detail {

std::string message(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts) out.append(p);
  return out;
}

}  // namespace ruppert::detail
