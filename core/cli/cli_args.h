// Command-line parsing for the `ruppert` executable: strict, with no global state, so every
// malformed argument becomes a UsageError (exit status 2) before any file is read.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "ruppert/ruppert.h"

namespace ruppert::cli {

enum class OutputFormat { Triangle, Json, Svg, Msh, Vtu, GeoJson };

struct CliArgs {
  Options options;
  std::string input;       // .poly, .node or .json
  std::string outputBase;  // -o BASE; empty: print the summary only
  std::string tracePath;   // --trace FILE; empty: no trace
  OutputFormat format = OutputFormat::Triangle;
  // --input-format poly|node|json|geojson; empty: by INPUT's extension, or for "-" (standard input)
  // sniffed from the text. outputBase "-" writes the one output file to standard output.
  std::string inputFormat;
  bool quiet = false;
  bool stats = false;
  bool help = false;
  bool version = false;
  // Derived outputs: --order 2 (6-node triangles in .node/.ele), --voronoi (BASE.v.node, BASE.v.edge).
  int order = option::order::fallback;
  bool voronoi = option::voronoi::fallback;
};

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// args excludes the program name. Throws UsageError naming the offending argument.
CliArgs parseArgs(const std::vector<std::string>& args);

// Whole-string number parsing: "5e-8" is a number; "", " 5", "1x", "nan" and "inf" are not.
bool parseStrictDouble(const std::string& text, double& value);
// Digits only, no sign, fits in 64 bits.
bool parseStrictCount(const std::string& text, std::uint64_t& value);

// The synopsis (wrapped to 80 columns) and the full --help text, made from the option table and the
// CLI's own options (cli_help.cpp).
const char* usageLine();
std::string helpText();

}  // namespace ruppert::cli
