// Doubles as decimal text with the C library's %.*g and %.*f rules (round half to even on the exact
// value), written from the double's exact decimal expansion. printf would do it, but its formatter
// (with the long-double arithmetic it brings) is several KB of the WebAssembly module, whose only
// use for it is the text of messages.
#pragma once

#include <string>

namespace ruppert::detail {

// printf's "%.*g" with `significant` digits (at least 1).
std::string formatSignificant(double v, int significant);

// printf's "%.*f" with `decimals` digits after the point.
std::string formatFixed(double v, int decimals);

}  // namespace ruppert::detail
