// Parsing of the `ruppert` command line. See helpText() for the options.
#include "cli_args.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <iterator>
#include <type_traits>

#include "cli_options.h"

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
  // An optional value: the text after '=', or the next argument if it is a count; false for none.
  bool optionalCount(std::string& value) {
    if (arg_.hasInlineValue) return value = arg_.inlineValue, true;
    std::uint64_t ignored = 0;
    if (i_ + 1 >= args_.size() || !parseStrictCount(args_[i_ + 1], ignored)) return false;
    return value = args_[++i_], true;
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

 private:
  const Arg& arg_;
  const std::vector<std::string>& args_;
  std::size_t& i_;
};

using Handler = void (*)(OptionValue&, CliArgs&);

// An option of the table, read as its type says and checked against its range: Spec is its
// option:: type, `target` where it goes.
template <class Spec>
void read(OptionValue& v, double& target) {
  target = v.number();
  if (target >= Spec::low && target <= Spec::high) return;
  if (Spec::low == 0 && Spec::high == kUnbounded) throw UsageError(v.name() + " must not be negative");
  throw UsageError(v.name() + " must be between " + numberText(Spec::low) + " and " + numberText(Spec::high) + " " +
                   Spec::unit);
}

template <class Spec>
void read(OptionValue& v, std::uint64_t& target) {
  const std::string text = v.text();
  if (!parseStrictCount(text, target)) throw UsageError(v.name() + ": '" + text + "' is not a non-negative integer");
}

template <class Spec>
void read(OptionValue& v, int& target) {
  std::string text;
  // --smooth alone asks for the usual passes; --smooth N or --smooth=N for N.
  if constexpr (std::is_same_v<Spec, option::smooth>) {
    if (!v.optionalCount(text)) return void(target = kSmoothPassesWhenOn);
  } else {
    text = v.text();
  }
  std::uint64_t value = 0;
  if (parseStrictCount(text, value) && value >= Spec::low && value <= Spec::high) {
    target = static_cast<int>(value);
    return;
  }
  if (Spec::high - Spec::low > 3)
    throw UsageError(v.name() + ": '" + text + "' is not an integer from " + numberText(Spec::low) + " to " +
                     numberText(Spec::high));
  std::string values;  // "1 or 2", "1, 2 or 3"
  for (int i = static_cast<int>(Spec::low); i <= static_cast<int>(Spec::high); ++i)
    values += (i == Spec::low ? "" : i == Spec::high ? " or " : ", ") + std::to_string(i);
  throw UsageError(v.name() + ": '" + text + "' is not " + values);
}

template <class Spec>
void read(OptionValue& v, bool& target) {
  target = v.flag();
}

// An enum option: one of its values' names, listed in the message as in the usage line.
template <class Spec, class Enum, class = std::enable_if_t<std::is_enum_v<Enum>>>
void read(OptionValue& v, Enum& target) {
  const std::string text = v.text();
  const auto& known = valueNames(target);  // in the enum's order: a name's index is its value
  for (std::size_t i = 0; i < std::size(known); ++i) {
    if (text != known[i]) continue;
    target = static_cast<Enum>(i);
    return;
  }
  std::string names;
  for (const std::string& name : choicesOf(Spec::fallback)) names += (names.empty() ? "" : ", ") + name;
  throw UsageError(v.name() + ": '" + text + "' is not one of " + names);
}

// The CLI's own options: files, formats and what it prints.
std::vector<std::pair<std::vector<std::string>, Handler>> cliOnlyOptions() {
  return {
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
      {{"--trace"}, [](OptionValue& v, CliArgs& out) {
         out.tracePath = v.text();
         if (out.tracePath.empty()) throw UsageError("--trace needs a non-empty FILE");
         out.options.trace = true;
       }},
      {{"--quiet", "-q"}, [](OptionValue& v, CliArgs& out) { out.quiet = v.flag(); }},
      {{"--stats"}, [](OptionValue& v, CliArgs& out) { out.options.sizeMeasure = out.stats = v.flag(); }},
      {{"--help", "-h"}, [](OptionValue& v, CliArgs& out) { out.help = v.flag(); }},
      {{"--version"}, [](OptionValue& v, CliArgs& out) { out.version = v.flag(); }},
  };
}

// Every option: its spellings and what it sets. First those of the option table that have a flag
// (the others are set by the CLI's own options below, or have no CLI form).
const std::vector<std::pair<std::vector<std::string>, Handler>>& optionTable() {
  static const std::vector<std::pair<std::vector<std::string>, Handler>> table = [] {
    std::vector<std::pair<std::vector<std::string>, Handler>> t;
    const auto add = [&](const char* flag, Handler handler) {
      if (*flag != '\0') t.emplace_back(spellingsOf(flag), handler);
    };
#define RUPPERT_CLI_MESH_OPTION_(KEY, ...) \
  add(option::KEY::flag, [](OptionValue& v, CliArgs& out) { read<option::KEY>(v, out.options.KEY); });
#define RUPPERT_CLI_DERIVED_OPTION_(KEY, ...) \
  add(option::KEY::flag, [](OptionValue& v, CliArgs& out) { read<option::KEY>(v, out.KEY); });
    RUPPERT_MESH_OPTIONS(RUPPERT_CLI_MESH_OPTION_)
    RUPPERT_DERIVED_OPTIONS(RUPPERT_CLI_DERIVED_OPTION_)
#undef RUPPERT_CLI_MESH_OPTION_
#undef RUPPERT_CLI_DERIVED_OPTION_
    for (auto& entry : cliOnlyOptions()) t.push_back(entry);
    return t;
  }();
  return table;
}

Handler handlerOf(const std::string& name) {
  for (const auto& [spellings, handler] : optionTable())
    if (std::find(spellings.begin(), spellings.end(), name) != spellings.end()) return handler;
  return nullptr;
}

// Edits between a and b: insertions, deletions, substitutions and swaps of two neighboring
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
