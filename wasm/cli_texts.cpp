// What wasm/cli.js borrows from the native CLI (core/cli): its argument parser and the texts it
// prints, so that both CLIs accept the same options and print the same things.
#include "cli_texts.h"

#include <emscripten/bind.h>

#include <string>

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
    const ruppert::Options& o = args.options;
    val options = val::object();
    options.set("minAngle", o.minAngle);
    options.set("maxArea", o.maxArea);
    if (o.maxSteiner != ruppert::kAutoSteinerBudget) options.set("maxSteiner", static_cast<double>(o.maxSteiner));
    // The names are the core's (ruppert.h), which wasm/input-checks.js accepts.
    options.set("placement", std::string(ruppert::enumName(o.placement)));
    options.set("encroachment", std::string(ruppert::enumName(o.encroachment)));
    options.set("variant", std::string(ruppert::enumName(o.variant)));
    options.set("convexHull", o.convexHull);
    options.set("autoHoles", o.autoHoles);
    options.set("trace", !args.tracePath.empty());
    options.set("sizeMeasure", o.sizeMeasure);
    options.set("order", args.order);      // issue 16, derived
    options.set("voronoi", args.voronoi);
    options.set("edges", o.edges);
    options.set("noBoundarySteiner", o.noBoundarySteiner);
    options.set("noSegmentSteiner", o.noSegmentSteiner);
    if (o.curveTolerance > 0) options.set("curveTolerance", o.curveTolerance);
    options.set("jettison", o.jettison);
    out.set("options", options);
    return out;
  });
}

}  // namespace
}  // namespace ruppert_wasm

EMSCRIPTEN_BINDINGS(ruppert_cli) { emscripten::function("parseCliArgs", &ruppert_wasm::parseCliArgs); }
