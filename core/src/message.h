// Messages built from pieces in one out-of-line call: a chain of std::string operator+ is inlined
// at every use, which costs kilobytes of WebAssembly across the readers' many messages.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

namespace ruppert::detail {

std::string message(std::initializer_list<std::string_view> parts);

// A number for messages, in its shortest form that reads back as the same double.
std::string formatNumber(double v);

}  // namespace ruppert::detail
