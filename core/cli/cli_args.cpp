// Parsing of the `ruppert` command line. See helpText() for the options.
#include "cli_args.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <initializer_list>

namespace ruppert::cli {

bool parseStrictDouble(const std::string& text, double& value) {
  // strtod skips leading blanks and stops at junk; insisting on the whole string rejects both.
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(value);
}

bool parseStrictCount(const std::string& text, std::uint64_t& value) {
  if (text.empty()) return false;
  for (char c : text) {
    if (c < '0' || c > '9') return false;
  }
  errno = 0;
  value = std::strtoull(text.c_str(), nullptr, 10);
  return errno != ERANGE;
}

const char* usageLine() {
  // Wrapped to 80 columns; the error path prints it after the message.
  return "usage: ruppert [--min-angle DEG] [--max-area A] [--max-steiner N] [-o BASE|-]\n"
         "               [--format triangle|json|svg|msh|vtu|geojson]\n"
         "               [--input-format poly|node|json|geojson] [--quiet] [--stats]\n"
         "               [--trace FILE] [--placement optimal|offcenter|circumcenter|petal]\n"
         "               [--encroachment lens|disk] [--variant cdt|box] [--convex-hull]\n"
         "               [--auto-holes] [--order 1|2] [--voronoi] [-e|--edges]\n"
         "               [--no-boundary-steiner] [--no-segment-steiner] [-j|--jettison]\n"
         "               [--curve-tolerance T]\n"
         "               [--help] [--version] INPUT";
}

namespace {

// The options and what they do, in columns that fit 80 characters.
const char* const kOptionsHelp =
    "  --min-angle DEG      smallest angle to reach, 0..60 (default 30); above 34,\n"
    "                       where out of reach: the best mesh reached (at least 33\n"
    "                       degrees), marked incomplete\n"
    "  --max-area A         largest triangle area (default: no bound); --min-angle 0\n"
    "                       without --max-area gives the plain constrained Delaunay\n"
    "                       triangulation\n"
    "  --max-steiner N      at most N new vertices (default: automatic)\n"
    "  --curve-tolerance T  largest distance from a boundary edge to the curve it\n"
    "                       follows (JSON \"curves\"; default 1e-3 of the diagonal)\n"
    "  -o BASE              write the mesh: BASE.node, BASE.ele, BASE.poly (triangle\n"
    "                       format), BASE.json (json) or BASE.svg (svg); without -o\n"
    "                       only the summary is printed\n"
    "  -o -                 write the one file of --format (not triangle: three\n"
    "                       files) to standard output; the summary and --stats then\n"
    "                       go to standard error\n"
    "  --format F           triangle (default), json, svg, msh (Gmsh 4.1: BASE.msh),\n"
    "                       vtu (VTK XML: BASE.vtu) or geojson (a FeatureCollection\n"
    "                       of triangles: BASE.geojson)\n"
    "  --input-format F     poly, node, json or geojson: how to read INPUT (default:\n"
    "                       its extension; for - the text decides: '{' is json or\n"
    "                       geojson, else .poly or .node)\n"
    "  --placement P        optimal (default: off-centers, but where one would make a\n"
    "                       skinny triangle the point maximising the smallest new\n"
    "                       angle; the fewest triangles, and 35-40 degrees),\n"
    "                       offcenter (faster), circumcenter, or petal (a point of\n"
    "                       the shortest edge's petal there)\n"
    "  --encroachment E     lens (default: diametral lenses) or disk (closed\n"
    "                       diametral disks)\n"
    "  --variant V          cdt (default: constrained, no triangles outside the\n"
    "                       domain) or box (Ruppert's original: conforming mesh of\n"
    "                       an enclosing box)\n"
    "  --convex-hull        mesh the whole convex hull, not only what segments\n"
    "                       enclose\n"
    "  --auto-holes         without hole seeds: regions at even nesting depth become\n"
    "                       holes\n"
    "  --order 2            quadratic triangles: .ele gets 6 nodes per triangle\n"
    "                       (corners, then the midpoints of the edges opposite them),\n"
    "                       .node the midpoints after the corners\n"
    "  --voronoi            also write the dual: BASE.v.node (circumcentres) and\n"
    "                       BASE.v.edge\n"
    "  -e, --edges          also write BASE.edge: every edge once, with its boundary\n"
    "                       marker (triangle format only)\n"
    "  --no-boundary-steiner  no new vertex on the domain's boundary (Triangle's -Y);\n"
    "                       what quality that leaves unreachable is reported, not\n"
    "                       looped over\n"
    "  --no-segment-steiner   no new vertex on any segment (Triangle's -YY)\n"
    "  -j, --jettison       leave unused input points (merged duplicates, points\n"
    "                       outside the domain) out of the output; the others are\n"
    "                       renumbered in order\n"
    "  --stats              print statistics (vertex kinds, angle histogram, size\n"
    "                       optimality)\n"
    "  --trace FILE         write every step (insertion, or move of a free vertex) as\n"
    "                       JSON lines to FILE\n"
    "  --quiet              no summary and no warnings (errors and --stats still\n"
    "                       print)\n"
    "  --help, --version\n";

// Each example runs as written from the top of a source tree (tests/readme checks them), the
// inputs being the ones in docs/examples.
const char* const kExamplesHelp =
    "Examples (the inputs ship in the source tree's docs/examples):\n"
    "  ruppert docs/examples/lake.poly\n"
    "      the summary of a 30-degree mesh; nothing written\n"
    "  ruppert --min-angle 33 --max-area 0.5 -o lake docs/examples/lake.poly\n"
    "      lake.node, lake.ele and lake.poly\n"
    "  ruppert --format vtu --stats -o plate docs/examples/plate.json\n"
    "      plate.vtu for ParaView, and the statistics\n"
    "  ruppert --format msh -o - - < docs/examples/park.geojson > park.msh\n"
    "      GeoJSON from standard input, Gmsh's .msh to standard output\n";

}  // namespace

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
         kOptionsHelp + "\n" + kExamplesHelp +
         "\n"
         "Exit status: 0 success, 1 invalid input, 2 usage error, 3 output could not be\n"
         "written.\n";
}

namespace {

// Splits "--name=value" so both "--min-angle 20" and "--min-angle=20" work.
struct Arg {
  std::string name;
  std::string inlineValue;
  bool hasInlineValue = false;
};

Arg split(const std::string& text) {
  Arg arg;
  const std::size_t eq = text.find('=');
  if (text.rfind("--", 0) == 0 && eq != std::string::npos) {
    arg.name = text.substr(0, eq);
    arg.inlineValue = text.substr(eq + 1);
    arg.hasInlineValue = true;
  } else {
    arg.name = text;
  }
  return arg;
}

}  // namespace

namespace {

// One argument's value, read as its option needs it: the text after '=', or the next argument.
class OptionValue {
 public:
  OptionValue(const Arg& arg, const std::vector<std::string>& args, std::size_t& i) : arg_(arg), args_(args), i_(i) {}
  const std::string& name() const { return arg_.name; }
  std::string text() {
    if (arg_.hasInlineValue) return arg_.inlineValue;
    if (i_ + 1 >= args_.size()) throw UsageError(name() + " needs a value");
    return args_[++i_];
  }
  double number() {
    const std::string v = text();
    double d = 0;
    if (!parseStrictDouble(v, d)) throw UsageError(name() + ": '" + v + "' is not a number");
    return d;
  }
  bool flag() const {
    if (arg_.hasInlineValue) throw UsageError(name() + " takes no value");
    return true;
  }
  // One of the named choices; the message lists them in order.
  template <class T>
  T choice(std::initializer_list<std::pair<const char*, T>> choices) {
    const std::string v = text();
    std::string names;
    for (const auto& [word, value] : choices) {
      if (v == word) return value;
      names += (names.empty() ? "" : ", ") + std::string(word);
    }
    throw UsageError(name() + ": '" + v + "' is not one of " + names);
  }

  // One of the core's enum values, by its name (ruppert.h's tables), listed in the message in this order.
  template <class T>
  T named(std::initializer_list<T> values) {
    const std::string v = text();
    std::string names;
    for (T value : values) {
      if (v == enumName(value)) return value;
      names += (names.empty() ? "" : ", ") + std::string(enumName(value));
    }
    throw UsageError(name() + ": '" + v + "' is not one of " + names);
  }

 private:
  const Arg& arg_;
  const std::vector<std::string>& args_;
  std::size_t& i_;
};

using Handler = void (*)(OptionValue&, CliArgs&);

// Every option: its spellings and what it sets.
const std::vector<std::pair<std::vector<std::string>, Handler>>& optionTable() {
  static const std::vector<std::pair<std::vector<std::string>, Handler>> table = {
      {{"--min-angle"}, [](OptionValue& v, CliArgs& out) {
         out.options.minAngle = v.number();
         if (out.options.minAngle < 0 || out.options.minAngle > 60)
           throw UsageError("--min-angle must be between 0 and 60 degrees");
       }},
      {{"--max-area"}, [](OptionValue& v, CliArgs& out) {
         out.options.maxArea = v.number();
         if (out.options.maxArea < 0) throw UsageError("--max-area must not be negative");
       }},
      {{"--curve-tolerance"}, [](OptionValue& v, CliArgs& out) {
         out.options.curveTolerance = v.number();
         if (!(out.options.curveTolerance > 0)) throw UsageError("--curve-tolerance must be positive");
       }},
      {{"--max-steiner"}, [](OptionValue& v, CliArgs& out) {
         const std::string text = v.text();
         if (!parseStrictCount(text, out.options.maxSteiner))
           throw UsageError("--max-steiner: '" + text + "' is not a non-negative integer");
       }},
      {{"-o", "--output"}, [](OptionValue& v, CliArgs& out) {
         out.outputBase = v.text();
         if (out.outputBase.empty()) throw UsageError(v.name() + " needs a non-empty BASE");
       }},
      {{"--format"}, [](OptionValue& v, CliArgs& out) {
         out.format = v.choice<OutputFormat>({{"triangle", OutputFormat::Triangle}, {"json", OutputFormat::Json},
                                             {"svg", OutputFormat::Svg}, {"msh", OutputFormat::Msh},
                                             {"vtu", OutputFormat::Vtu}, {"geojson", OutputFormat::GeoJson}});
       }},
      {{"--input-format"}, [](OptionValue& v, CliArgs& out) {
         out.inputFormat = v.choice<std::string>({{"poly", "poly"}, {"node", "node"}, {"json", "json"}, {"geojson", "geojson"}});
       }},
      {{"--encroachment"}, [](OptionValue& v, CliArgs& out) {
         out.options.encroachment = v.named({Encroachment::DiametralLens, Encroachment::DiametralDisk});
       }},
      {{"--placement"}, [](OptionValue& v, CliArgs& out) {
         out.options.placement =
             v.named({Placement::OffCenter, Placement::Circumcenter, Placement::Petal, Placement::Optimal});
       }},
      {{"--variant"}, [](OptionValue& v, CliArgs& out) {
         out.options.variant = v.named({Variant::Constrained, Variant::BoundingBox});
       }},
      {{"--trace"}, [](OptionValue& v, CliArgs& out) {
         out.tracePath = v.text();
         if (out.tracePath.empty()) throw UsageError("--trace needs a non-empty FILE");
         out.options.trace = true;
       }},
      {{"--quiet", "-q"}, [](OptionValue& v, CliArgs& out) { out.quiet = v.flag(); }},
      {{"--stats"}, [](OptionValue& v, CliArgs& out) { out.options.sizeMeasure = out.stats = v.flag(); }},
      {{"--convex-hull"}, [](OptionValue& v, CliArgs& out) { out.options.convexHull = v.flag(); }},
      {{"--auto-holes"}, [](OptionValue& v, CliArgs& out) { out.options.autoHoles = v.flag(); }},
      {{"--order"}, [](OptionValue& v, CliArgs& out) {
         const std::string text = v.text();
         if (text != "1" && text != "2") throw UsageError("--order: '" + text + "' is not 1 or 2");
         out.order = text == "2" ? 2 : 1;
       }},
      {{"--voronoi"}, [](OptionValue& v, CliArgs& out) { out.voronoi = v.flag(); }},
      {{"--edges", "-e"}, [](OptionValue& v, CliArgs& out) { out.options.edges = v.flag(); }},
      {{"--no-boundary-steiner"}, [](OptionValue& v, CliArgs& out) { out.options.noBoundarySteiner = v.flag(); }},
      {{"--no-segment-steiner"}, [](OptionValue& v, CliArgs& out) { out.options.noSegmentSteiner = v.flag(); }},
      {{"--jettison", "-j"}, [](OptionValue& v, CliArgs& out) { out.options.jettison = v.flag(); }},
      {{"--help", "-h"}, [](OptionValue& v, CliArgs& out) { out.help = v.flag(); }},
      {{"--version"}, [](OptionValue& v, CliArgs& out) { out.version = v.flag(); }},
  };
  return table;
}

Handler handlerOf(const std::string& name) {
  for (const auto& [spellings, handler] : optionTable())
    if (std::find(spellings.begin(), spellings.end(), name) != spellings.end()) return handler;
  return nullptr;
}

// Edits between a and b: insertions, deletions, substitutions and swaps of two neighbouring
// characters, each counting one (so "--min-angel" is one edit from "--min-angle").
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1, 0));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

// The option an unknown `name` was probably meant as: the one spelling nearest to it in lower case,
// at most a quarter of its length away (names under 4 characters: only a difference of case).
// Empty when none is that near, or when two spellings are equally near.
std::string nearestOption(const std::string& name) {
  std::string lower = name;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::size_t limit = lower.size() < 4 ? 0 : std::max<std::size_t>(1, lower.size() / 4);
  std::string best;
  std::size_t bestDistance = limit + 1;
  bool tie = false;
  for (const auto& entry : optionTable()) {
    for (const std::string& spelling : entry.first) {
      const std::size_t distance = editDistance(lower, spelling);
      if (distance < bestDistance) {
        best = spelling;
        bestDistance = distance;
        tie = false;
      } else if (distance == bestDistance) {
        tie = true;
      }
    }
  }
  return tie ? std::string() : best;
}

// Options that cannot go together, and a missing INPUT.
void checkCombination(const CliArgs& out) {
  if (out.input.empty() && !out.help && !out.version) throw UsageError("missing INPUT");
  if (out.outputBase == "-" && out.voronoi)
    throw UsageError("--voronoi writes two files (BASE.v.node, BASE.v.edge): give -o BASE, not -o -");
  if (out.outputBase == "-" && out.format == OutputFormat::Triangle) {
    throw UsageError("-o - writes one file to standard output, but --format triangle writes three (BASE.node, "
                     "BASE.ele, BASE.poly); choose --format json, svg, msh, vtu or geojson, or give -o BASE");
  }
  if (out.order == 2 && out.format != OutputFormat::Triangle)
    throw UsageError("--order 2 writes Triangle's .node and .ele: use --format triangle");
}

}  // namespace

CliArgs parseArgs(const std::vector<std::string>& args) {
  CliArgs out;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const Arg arg = split(args[i]);
    const std::string& name = arg.name;
    if (const Handler handler = handlerOf(name)) {
      OptionValue value(arg, args, i);
      handler(value, out);
    } else if (name.size() > 1 && name[0] == '-') {  // a lone "-" is INPUT: standard input
      const std::string near = nearestOption(name);
      throw UsageError("unknown option '" + name + "'" + (near.empty() ? "" : " (did you mean " + near + "?)"));
    } else {
      if (!out.input.empty()) throw UsageError("more than one INPUT ('" + out.input + "' and '" + name + "')");
      if (name.empty()) throw UsageError("INPUT must not be empty");
      out.input = args[i];
    }
  }
  checkCombination(out);
  return out;
}

}  // namespace ruppert::cli
