// What JavaScript reads from the binding instead of keeping copies: the names of the core's enums
// (ruppert.h's k...Names) and the layout of the heap tables (heap_layout.h), as one JSON text.
// wasm/build-wasm.mjs writes the names into wasm/dist/names.js for the package's constants and
// option checks; wasm/heap-call.js reads the layout from each instance.
#include <emscripten/emscripten.h>

#include <cstddef>
#include <string>

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
  list(json, "curveTypes", ruppert::kCurveTypeNames, "},\"layout\":{");
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
