// What wasm/cli.js borrows from the native CLI (core/cli): its argument parser and the texts it
// prints, so that both CLIs accept the same options and print the same things.
#include "cli_texts.h"

#include <emscripten/bind.h>

#include <cstdint>
#include <string>
#include <type_traits>

#include "cli_args.h"    // core/cli: the native CLI's parser
#include "cli_report.h"  // core/cli: its summary, --stats and --trace printers

namespace ruppert_wasm {

// `report` (used by wasm/cli.js) is { summary, stats, trace } booleans: the native CLI's texts for
// this mesh, printed by the same C++ code so that both CLIs print the same thing.
val reportToJs(const ruppert::Mesh& mesh, const val& report) {
  val texts = val::object();
  const auto text = [&](const char* key, auto&& print) {
    if (report[key].as<bool>()) texts.set(key, print());
  };
  text("summary", [&] { return ruppert::cli::summaryText(mesh); });
  text("stats", [&] { return ruppert::cli::statsText(mesh.stats); });
  text("trace", [&] { return ruppert::cli::traceText(mesh); });
  return texts;
}

namespace {

// One parsed option as checkOptions() takes it.
template <class T>
void setOption(val& options, const char* key, const T& value) {
  if constexpr (std::is_enum_v<T>) {
    options.set(key, std::string(ruppert::enumName(value)));
  } else if constexpr (std::is_same_v<T, std::uint64_t>) {
    if (value != ruppert::kAutoSteinerBudget) options.set(key, static_cast<double>(value));
  } else {
    options.set(key, value);
  }
}

// The native CLI's argument parser. Returns { usageLine, helpText, usageError? } plus, on success,
// the parsed fields with options in the vocabulary of wasm/input-checks.js's checkOptions().
val parseCliArgs(val argsJs) {
  return guarded([&] {
    val out = val::object();
    out.set("usageLine", std::string(ruppert::cli::usageLine()));
    out.set("helpText", ruppert::cli::helpText());
    ruppert::cli::CliArgs args;
    try {
      args = ruppert::cli::parseArgs(emscripten::vecFromJSArray<std::string>(argsJs));
    } catch (const ruppert::cli::UsageError& e) {
      out.set("usageError", std::string(e.what()));
      return out;
    }
    out.set("input", args.input);
    out.set("outputBase", args.outputBase);
    out.set("tracePath", args.tracePath);
    out.set("inputFormat", args.inputFormat);
    using ruppert::cli::OutputFormat;
    out.set("format", std::string(args.format == OutputFormat::Json      ? "json"
                                  : args.format == OutputFormat::Svg     ? "svg"
                                  : args.format == OutputFormat::Msh     ? "msh"
                                  : args.format == OutputFormat::Vtu     ? "vtu"
                                  : args.format == OutputFormat::GeoJson ? "geojson"
                                                                     : "triangle"));
    out.set("quiet", args.quiet);
    out.set("stats", args.stats);
    out.set("help", args.help);
    out.set("version", args.version);
    // Every option of the table by its key, in the vocabulary of checkOptions(): the enums by the
    // core's names, maxSteiner absent for automatic.
    const ruppert::Options& o = args.options;
    val options = val::object();
#define RUPPERT_WASM_CLI_OPTION_(KEY, ...) setOption(options, #KEY, o.KEY);
    RUPPERT_MESH_OPTIONS(RUPPERT_WASM_CLI_OPTION_)
#undef RUPPERT_WASM_CLI_OPTION_
#define RUPPERT_WASM_CLI_OPTION_(KEY, ...) setOption(options, #KEY, args.KEY);
    RUPPERT_DERIVED_OPTIONS(RUPPERT_WASM_CLI_OPTION_)
#undef RUPPERT_WASM_CLI_OPTION_
    out.set("options", options);
    return out;
  });
}

}  // namespace
}  // namespace ruppert_wasm

EMSCRIPTEN_BINDINGS(ruppert_cli) { emscripten::function("parseCliArgs", &ruppert_wasm::parseCliArgs); }
