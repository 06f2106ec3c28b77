// The `ruppert` CLI's usage line and --help: the option table's flags and help (option_table.h),
// then the CLI's own options, each wrapped to 80 columns.
#include <algorithm>
#include <cstdio>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "cli_args.h"
#include "cli_options.h"

namespace ruppert::cli {

std::vector<std::string> spellingsOf(const char* flag) {
  const std::string spellings = std::string(flag).substr(0, std::string(flag).find(' '));
  std::vector<std::string> out;
  for (std::size_t start = 0; start <= spellings.size();) {
    const std::size_t bar = std::min(spellings.find('|', start), spellings.size());
    out.push_back(spellings.substr(start, bar - start));
    start = bar + 1;
  }
  return out;
}

std::string valueNameOf(const char* flag) {
  const std::string text = flag;
  const std::size_t space = text.find(' ');
  return space == std::string::npos ? std::string() : text.substr(space + 1);
}

std::string numberText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", value);
  return text;
}

namespace {

constexpr std::size_t kWidth = 80;
constexpr std::size_t kUsageIndent = 15;  // under the first item, after "usage: ruppert "
constexpr std::size_t kHelpIndent = 23;   // the help's text column

// `tokens` after `first`, as many to a line as fit in kWidth, the next lines indented by `indent`.
std::string wrap(const std::string& first, const std::vector<std::string>& tokens, std::size_t indent) {
  std::string out = first, line = first;
  bool lineHasToken = false;
  for (const std::string& token : tokens) {
    if (lineHasToken && line.size() + 1 + token.size() > kWidth) {
      out += "\n" + std::string(indent, ' ');
      line = std::string(indent, ' ');
      lineHasToken = false;
    }
    const std::string piece = (lineHasToken ? " " : "") + token;
    out += piece, line += piece;
    lineHasToken = true;
  }
  return out;
}

std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find(' ', start), text.size());
    if (end > start) out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

// "{min}", "{max}" and "{default}" in an option's help, replaced by its numbers.
template <class Spec>
std::string helpOf() {
  std::string text = Spec::help;
  double fallback = 0;  // an enum's default is a name, which its help writes as such
  if constexpr (!std::is_enum_v<decltype(Spec::fallback)>) fallback = static_cast<double>(Spec::fallback);
  const std::pair<const char*, double> numbers[] = {{"{min}", Spec::low}, {"{max}", Spec::high}, {"{default}", fallback}};
  for (const auto& [placeholder, value] : numbers)
    for (std::size_t at = text.find(placeholder); at != std::string::npos; at = text.find(placeholder))
      text.replace(at, std::string(placeholder).size(), numberText(value));
  return text;
}

// A usage item's value: an enum option's names, else the flag's value name.
template <class Spec, class T = decltype(Spec::fallback)>
std::string usageValueOf() {
  if constexpr (std::is_enum_v<T>) {
    std::string names;
    for (const std::string& name : choicesOf(Spec::fallback)) names += (names.empty() ? "" : "|") + name;
    return names;
  } else {
    return valueNameOf(Spec::flag);
  }
}

// One option: its usage items ("[--min-angle DEG]") and its help entry (flag column, text).
struct Entry {
  std::vector<std::string> usage;
  std::string column, help;
};

template <class Spec>
void addEntry(std::vector<Entry>& entries) {
  if (*Spec::flag == '\0') return;
  std::string bars, commas;
  for (const std::string& spelling : spellingsOf(Spec::flag)) {
    bars += (bars.empty() ? "" : "|") + spelling;
    commas += (commas.empty() ? "" : ", ") + spelling;
  }
  const std::string value = valueNameOf(Spec::flag);
  const std::string usageValue = usageValueOf<Spec>();
  entries.push_back({{"[" + bars + (usageValue.empty() ? "" : " " + usageValue) + "]"},
                     commas + (value.empty() ? "" : " " + value), helpOf<Spec>()});
}

// The option table's options that have flags, then the CLI's own (no usage item where another
// entry's covers it).
const std::vector<Entry>& entries() {
  static const std::vector<Entry> all = [] {
    std::vector<Entry> out;
#define RUPPERT_CLI_HELP_ENTRY_(KEY, ...) addEntry<option::KEY>(out);
    RUPPERT_MESH_OPTIONS(RUPPERT_CLI_HELP_ENTRY_)
    RUPPERT_DERIVED_OPTIONS(RUPPERT_CLI_HELP_ENTRY_)
#undef RUPPERT_CLI_HELP_ENTRY_
    const std::vector<Entry> own = {
        {{"[-o BASE|-]"}, "-o BASE",
         "write the mesh: BASE.node, BASE.ele, BASE.poly (triangle format), BASE.json (json) or BASE.svg "
         "(svg); without -o only the summary is printed"},
        {{}, "-o -",
         "write the one file of --format (not triangle: three files) to standard output; the summary and "
         "--stats then go to standard error"},
        {{"[--format triangle|json|svg|msh|vtu|geojson]"}, "--format F",
         "triangle (default), json, svg, msh (Gmsh 4.1: BASE.msh), vtu (VTK XML: BASE.vtu) or geojson (a "
         "FeatureCollection of triangles: BASE.geojson)"},
        {{"[--input-format poly|node|json|geojson]"}, "--input-format F",
         "poly, node, json or geojson: how to read INPUT (default: its extension; for - the text decides: "
         "'{' is json or geojson, else .poly or .node)"},
        {{"[--quiet]"}, "--quiet", "no summary and no warnings (errors and --stats still print)"},
        {{"[--stats]"}, "--stats", "print statistics (vertex kinds, angle histogram, size optimality)"},
        {{"[--trace FILE]"}, "--trace FILE", "write every step (insertion, or move of a free vertex) as JSON lines to FILE"},
        {{"[--help]", "[--version]"}, "--help, --version", ""},
    };
    out.insert(out.end(), own.begin(), own.end());
    return out;
  }();
  return all;
}

// Each example runs as written from the top of a source tree (tests/readme checks them), the
// inputs being the ones in docs/examples.
const char* const kExamplesHelp =
    "Examples, run where docs/examples is: the top of the source tree, or\n"
    "node_modules/ruppert in a project that installed the npm package:\n"
    "  ruppert docs/examples/lake.poly\n"
    "      the summary of a 30-degree mesh; nothing written\n"
    "  ruppert --min-angle 33 --max-area 0.5 -o lake docs/examples/lake.poly\n"
    "      lake.node, lake.ele and lake.poly\n"
    "  ruppert --format vtu --stats -o plate docs/examples/plate.json\n"
    "      plate.vtu for ParaView, and the statistics\n"
    "  ruppert --format msh -o - - < docs/examples/park.geojson > park.msh\n"
    "      GeoJSON from standard input, Gmsh's .msh to standard output\n";

std::string optionsHelp() {
  std::string out;
  for (const Entry& entry : entries()) {
    std::string column = "  " + entry.column;
    // The text starts in its column, or two spaces after a longer flag.
    column += std::string(column.size() + 2 <= kHelpIndent ? kHelpIndent - column.size() : 2, ' ');
    out += wrap(column, words(entry.help), kHelpIndent);
    out.erase(out.find_last_not_of(' ') + 1);  // "--help, --version" has no text
    out += "\n";
  }
  return out;
}

}  // namespace

const char* usageLine() {
  static const std::string line = [] {
    std::vector<std::string> items;
    for (const Entry& entry : entries()) items.insert(items.end(), entry.usage.begin(), entry.usage.end());
    items.emplace_back("INPUT");
    return wrap("usage: ruppert ", items, kUsageIndent);
  }();
  return line.c_str();
}

std::string helpText() {
  return std::string(usageLine()) +
         "\n\n"
         "Quality triangle mesh of a planar straight-line graph by Delaunay refinement\n"
         "(Ruppert). INPUT is a Triangle .poly or .node file, a .json file\n"
         "{\"points\": [...], \"segments\": [...], ...}, a .geojson file (Polygon and\n"
         "MultiPolygon features; inner rings are holes), or - for standard input.\n"
         "INPUT BASE.ele refines that mesh (with BASE.node, and BASE.poly and BASE.area\n"
         "when present: a maximum area per triangle, -1 for none, kept by every new\n"
         "triangle within an old one).\n"
         "\n" +
         optionsHelp() + "\n" + kExamplesHelp +
         "\n"
         "Exit status: 0 success, 1 invalid input, 2 usage error, 3 output could not be\n"
         "written.\n";
}

}  // namespace ruppert::cli
