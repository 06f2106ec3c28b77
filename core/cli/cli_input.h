// Reading the CLI's INPUT: a file by its extension, or "-" for standard input, in the format
// --input-format names or, for standard input without one, the format its text shows.
#pragma once

#include <string>

#include "ruppert/ruppert.h"

namespace ruppert::cli {

// format: "", "poly", "node", "json" or "geojson". Throws ruppert::Error as the readers do.
Plc readInput(const std::string& input, const std::string& format);

// The format of a text without a name: "json" or "geojson" for a JSON object (GeoJSON has a "type"
// and no "points"), else "triangle" (.poly or .node; readInput tells them apart by parsing).
std::string sniffFormat(const std::string& text);

}  // namespace ruppert::cli
