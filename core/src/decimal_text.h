// Doubles to decimal text and back, exactly as the C library does it: text with printf's %.*g and
// %.*f rules (round half to even on the exact value), written from the double's exact decimal
// expansion; numbers read to the nearest double (ties to even), as strtod reads them. printf and
// strtod would do it, but they (with the long-double arithmetic they bring) are several KB of the
// WebAssembly module, whose only uses for them are messages and the JSON numbers of GeoJSON.
#pragma once

#include <string>
#include <string_view>

namespace ruppert::detail {

// printf's "%.*g" with `significant` digits (at least 1).
std::string formatSignificant(double v, int significant);

// printf's "%.*f" with `decimals` digits after the point.
std::string formatFixed(double v, int decimals);

// The double nearest to `text` (ties to even; +-infinity past the largest double), which must be a
// number in JSON's grammar (an optional '-', digits, an optional fraction, an optional exponent whose
// sign may be '+'), or "inf"/"nan" with an optional '-', as formatSignificant writes them.
double parseDecimal(std::string_view text);

}  // namespace ruppert::detail
