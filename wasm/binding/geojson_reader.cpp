// The GeoJSON reader as an embind function: text in, a PLC object out (wasm/mesher.js's
// parseGeoJson). Apart from the other readers (text_formats.cpp) because it needs the mesher: the
// hole seeds of courtyards and inner rings come from a triangulation of the polygons' segments
// (core/src/io/read_geojson.cpp). So it lives in the mesher module, which has triangulate()
// anyway, and the text formats module stays without the mesher.
#include <emscripten/bind.h>

#include <string>

#include "binding_common.h"
#include "js_objects.h"
#include "ruppert/ruppert.h"

namespace ruppert_wasm {
namespace {

val readGeoJson(std::string text, std::string name) {
  return guarded([&] {
    val out = val::object();
    out.set("plc", plcToJs(ruppert::parseGeoJson(text, name)));
    return out;
  });
}

}  // namespace
}  // namespace ruppert_wasm

EMSCRIPTEN_BINDINGS(ruppert_geojson_reader) { emscripten::function("readGeoJson", &ruppert_wasm::readGeoJson); }
