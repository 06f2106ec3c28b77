// What JavaScript reads from the binding instead of keeping copies: the names of the core's enums
// (ruppert.h's k...Names), the options (ruppert/option_table.h: key, type, default, range) and the
// layout of the heap tables (heap_layout.h), as one JSON text. wasm/build-wasm.mjs writes the names
// and the options into wasm/dist/names.js for the package's constants and option checks;
// wasm/heap-call.js reads the layout from each instance. Only ruppert-cli.wasm describes the
// options (RUPPERT_WASM_DESCRIBE_OPTIONS): they are read once, at build time, and the mesher that
// pages download stays 0.5 KB (gzipped) smaller without them.
#include <emscripten/emscripten.h>

#include <cstddef>
#include <cstdio>
#include <iterator>
#include <string>
#include <type_traits>

#include "heap_layout.h"
#include "ruppert/ruppert.h"

namespace {

// "key":["a","b",...]  (the names are plain identifiers: nothing to escape)
void appendList(std::string& json, const char* key, const char* const* items, std::size_t count) {
  json.append("\"").append(key).append("\":[");
  for (std::size_t i = 0; i < count; ++i) json.append(i ? ",\"" : "\"").append(items[i]).append("\"");
  json.append("]");
}

template <std::size_t N>
void list(std::string& json, const char* key, const char* const (&items)[N], const char* after = ",") {
  appendList(json, key, items, N);
  json.append(after);
}

#ifdef RUPPERT_WASM_DESCRIBE_OPTIONS
// A number in JSON: infinity (no bound) and the automatic Steiner budget are null.
void appendNumber(std::string& json, double value) {
  char text[32] = "null";
  if (value < ruppert::kUnbounded) std::snprintf(text, sizeof text, "%.15g", value);
  json.append(text);
}

// One option: {"name":..,"type":..,"default":..} and, by type, "min", "max" and "unit" (number,
// integer, count) or "values" (choice, in the enum's order); "whenTrue" where an integer option
// also takes true (that many) and false (0). Types: number (double), integer (int),
// count (an integer or null: automatic), boolean, choice (one of values) and function.
template <class Spec>
void appendOption(std::string& json) {
  using T = std::decay_t<decltype(Spec::fallback)>;
  json.append("{\"name\":\"").append(Spec::key).append("\",\"type\":\"");
  if constexpr (std::is_enum_v<T>) {
    json.append("choice\",\"default\":\"").append(ruppert::enumName(Spec::fallback)).append("\",");
    appendList(json, "values", ruppert::valueNames(Spec::fallback), std::size(ruppert::valueNames(Spec::fallback)));
  } else if constexpr (std::is_same_v<T, bool>) {
    json.append(Spec::fallback ? "boolean\",\"default\":true" : "boolean\",\"default\":false");
  } else if constexpr (std::is_same_v<T, std::nullptr_t>) {
    json.append("function\",\"default\":null");
  } else {
    json.append(std::is_same_v<T, double> ? "number" : std::is_same_v<T, int> ? "integer" : "count");
    json.append("\",\"default\":");
    double fallback = static_cast<double>(Spec::fallback);
    if constexpr (std::is_same_v<T, std::uint64_t>) {
      if (Spec::fallback == ruppert::kAutoSteinerBudget) fallback = ruppert::kUnbounded;
    }
    appendNumber(json, fallback);
    json.append(",\"min\":"), appendNumber(json, Spec::low);
    json.append(",\"max\":"), appendNumber(json, Spec::high);
    json.append(",\"unit\":\"").append(Spec::unit).append("\"");
    // smooth: true stands for the usual passes (false for none).
    if constexpr (std::is_same_v<Spec, ruppert::option::smooth>)
      json.append(",\"whenTrue\":").append(std::to_string(ruppert::kSmoothPassesWhenOn));
  }
  json.append("},");
}
#endif

std::string description() {
  std::string json = "{\"names\":{";
  list(json, "errorCodes", ruppert::kErrorCodeNames);
  list(json, "reasons", ruppert::kReasonKindNames);
  list(json, "notices", ruppert::kNoticeKindNames);
  list(json, "events", ruppert::kEventKindNames);
  list(json, "vertexKinds", ruppert::kVertexKindNames);
  list(json, "placements", ruppert::kPlacementNames);
  list(json, "encroachments", ruppert::kEncroachmentNames);
  list(json, "variants", ruppert::kVariantNames);
  list(json, "curveTypes", ruppert::kCurveTypeNames, "},");
#ifdef RUPPERT_WASM_DESCRIBE_OPTIONS
  json.append("\"options\":[");
#define RUPPERT_WASM_DESCRIBE_OPTION_(KEY, ...) appendOption<ruppert::option::KEY>(json);
  RUPPERT_ALL_OPTIONS(RUPPERT_WASM_DESCRIBE_OPTION_)
#undef RUPPERT_WASM_DESCRIBE_OPTION_
  json.back() = ']';  // the last option's ','
  json.append(",");
#endif
  json.append("\"layout\":{");
  list(json, "input", ruppert_wasm::kInputFields);
  list(json, "output", ruppert_wasm::kOutputFields);
  list(json, "derivedInput", ruppert_wasm::kDerivedInputFields);
  list(json, "derivedOutput", ruppert_wasm::kDerivedOutputFields, "}}");
  return json;
}

}  // namespace

// The JSON text, NUL-terminated (wasm/describe.js reads it).
extern "C" EMSCRIPTEN_KEEPALIVE const char* rp_describe() {
  static const std::string json = description();
  return json.c_str();
}
