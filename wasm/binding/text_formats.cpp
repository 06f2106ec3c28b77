// The readers and writers of text formats, as embind functions: texts in, a PLC object or a text
// out (wasm/mesher.js's parse* and to* functions).
#include <emscripten/bind.h>

#include <string>

#include "binding_common.h"
#include "js_objects.h"
#include "ruppert/ruppert.h"

namespace ruppert_wasm {
namespace {

// format: "poly", "node" or "json" (GeoJSON is read by geojson_reader.cpp, in the mesher module).
// Plc::curves (only JSON has them) as { type, from, to, center | controls, marker }, added
// here rather than in plcToJs, which the mesher module links for GeoJSON.
val withCurves(val o, const ruppert::Plc& plc) {
  if (plc.curves.empty()) return o;  // the key only where a file has curves
  val curves = val::array();
  for (const ruppert::Curve& c : plc.curves) {
    val item = val::object();
    const bool arc = c.type == ruppert::CurveType::Arc;
    const double* values = arc ? c.center : c.controls;
    item.set("type", std::string(ruppert::enumName(c.type)));
    item.set("from", c.from);
    item.set("to", c.to);
    item.set(arc ? "center" : "controls", copyOut(std::vector<double>(values, values + (arc ? 2 : 4))));
    item.set("marker", c.marker);
    curves.call<void>("push", item);
  }
  o.set("curves", curves);
  return o;
}

val readPlc(std::string text, std::string format, std::string name) {
  return guarded([&] {
    ruppert::Plc plc;
    if (format == "poly") {
      plc = ruppert::parsePoly(text, name);
    } else if (format == "node") {
      plc = ruppert::parseNode(text, name);
    } else if (format == "json") {
      plc = ruppert::parseJson(text, name);
    } else {
      throw ruppert::Error(ruppert::ErrorCode::InvalidOption, "unknown input format '" + format + "'");
    }
    val out = val::object();
    out.set("plc", withCurves(plcToJs(plc), plc));
    return out;
  });
}

// A .poly declaring 0 points with the text of the .node file that holds them.
val readPolyWithNode(std::string polyText, std::string polyName, std::string nodeText, std::string nodeName) {
  return guarded([&] {
    val out = val::object();
    out.set("plc", plcToJs(ruppert::parsePolyWithNode(polyText, nodeText, polyName, nodeName)));
    return out;
  });
}

// format: "node", "ele", "poly", "json", "svg", "msh", "vtu" or "geojson". `input` may be null (no holes or regions).
// segmentCells: the .vtu's VtuOptions::segmentCells (the other formats ignore it).
val writeMesh(val meshJs, val inputJs, std::string format, bool segmentCells) {
  return guarded([&] {
    const ruppert::Mesh mesh = meshFromJs(meshJs);
    const ruppert::Plc input = inputJs.isNull() || inputJs.isUndefined() ? ruppert::Plc{} : plcFromJs(inputJs);
    std::string text;
    if (format == "node") {
      text = ruppert::toNode(mesh);
    } else if (format == "ele") {
      text = ruppert::toEle(mesh);
    } else if (format == "poly") {
      text = ruppert::toPoly(mesh, input);
    } else if (format == "json") {
      text = ruppert::toJson(mesh, input);
    } else if (format == "svg") {
      text = ruppert::toSvg(mesh);
    } else if (format == "msh") {
      text = ruppert::toMsh(mesh, input);
    } else if (format == "vtu") {
      text = ruppert::toVtu(mesh, ruppert::VtuOptions{segmentCells});
    } else if (format == "geojson") {
      text = ruppert::toGeoJson(mesh);
    } else if (format == "edge") {
      text = ruppert::toEdge(mesh);
    } else {
      throw ruppert::Error(ruppert::ErrorCode::InvalidOption, "unknown output format '" + format + "'");
    }
    val result = val::object();
    result.set("text", text);
    return result;
  });
}

// Triangle's .v.node ("node") or .v.edge ("edge") text of mesh.voronoi.
val writeVoronoi(val voronoiJs, int indexBase, std::string which) {
  return guarded([&] {
    const ruppert::Voronoi v = voronoiFromJs(voronoiJs);
    ruppert::Mesh mesh;
    mesh.indexBase = indexBase;
    val out = val::object();
    out.set("text", which == "node" ? ruppert::toVoronoiNode(v, mesh) : ruppert::toVoronoiEdge(v, mesh));
    return out;
  });
}

// BASE.ele with BASE.node, and BASE.poly and BASE.area when their texts are strings.
val readMeshFiles(val texts) {
  return guarded([&] {
    ruppert::MeshFiles f;
    f.ele = texts["ele"].as<std::string>(), f.node = texts["node"].as<std::string>();
    f.eleName = texts["eleName"].as<std::string>(), f.nodeName = texts["nodeName"].as<std::string>();
    f.hasPoly = texts["poly"].isString(), f.hasArea = texts["area"].isString();
    if (f.hasPoly) f.poly = texts["poly"].as<std::string>(), f.polyName = texts["polyName"].as<std::string>();
    if (f.hasArea) f.area = texts["area"].as<std::string>(), f.areaName = texts["areaName"].as<std::string>();
    const ruppert::Plc plc = ruppert::parseMeshFiles(f);
    val out = val::object();
    val js = plcToJs(plc);
    js.set("triangles", copyOut(plc.triangles));
    js.set("triangleMaxArea", copyOut(plc.triangleMaxArea));
    out.set("plc", js);
    return out;
  });
}

}  // namespace
}  // namespace ruppert_wasm

EMSCRIPTEN_BINDINGS(ruppert_text_formats) {
  using namespace ruppert_wasm;
  emscripten::function("readPlc", &readPlc);
  emscripten::function("readPolyWithNode", &readPolyWithNode);
  emscripten::function("writeMesh", &writeMesh);
  emscripten::function("readMeshFiles", &readMeshFiles);
  emscripten::function("writeVoronoi", &writeVoronoi);
}
