// Conversions between the JavaScript objects of the package's API and the core's structs, for the
// readers, the writers and traces (triangulate()'s input and mesh go through the heap instead:
// heap_tables.cpp).
#include "js_objects.h"

#include <cstdint>
#include <string>

namespace ruppert_wasm {

// ---------------------------------------------------------------------------------------------
// JavaScript -> C++
// ---------------------------------------------------------------------------------------------
ruppert::Plc plcFromJs(const val& js) {
  ruppert::Plc plc;
  plc.points = copyIn<double>(js["points"]);
  plc.segments = copyIn<std::uint32_t>(js["segments"]);
  plc.holes = copyIn<double>(js["holes"]);
  // Regions arrive flattened: x, y, attribute, maxArea per region.
  const std::vector<double> regions = copyIn<double>(js["regions"]);
  for (std::size_t i = 0; i + 3 < regions.size(); i += 4) {
    ruppert::Region r;
    r.x = regions[i];
    r.y = regions[i + 1];
    r.attribute = regions[i + 2];
    r.maxArea = regions[i + 3];
    plc.regions.push_back(r);
  }
  plc.pointMarkers = copyIn<std::int32_t>(js["pointMarkers"]);
  plc.segmentMarkers = copyIn<std::int32_t>(js["segmentMarkers"]);
  plc.indexBase = js["indexBase"].isNumber() ? js["indexBase"].as<int>() : 0;
  plc.pointAttributes = copyIn<double>(js["pointAttributes"]);
  plc.attributesPerPoint = js["attributesPerPoint"].isNumber() ? js["attributesPerPoint"].as<std::uint32_t>() : 0;
  return plc;
}

ruppert::Mesh meshFromJs(const val& js) {
  ruppert::Mesh m;
  m.points = copyIn<double>(js["points"]);
  m.triangles = copyIn<std::uint32_t>(js["triangles"]);
  m.neighbors = copyIn<std::int32_t>(js["neighbors"]);
  m.segments = copyIn<std::uint32_t>(js["segments"]);
  m.segmentIds = copyIn<std::int32_t>(js["segmentIds"]);
  m.vertexKinds = copyIn<std::uint8_t>(js["vertexKinds"]);
  m.triangleAttributes = copyIn<double>(js["triangleAttributes"]);
  m.pointMarkers = copyIn<std::int32_t>(js["pointMarkers"]);
  m.segmentMarkers = copyIn<std::int32_t>(js["segmentMarkers"]);
  m.edges = copyIn<std::uint32_t>(js["edges"]);
  m.edgeMarkers = copyIn<std::int32_t>(js["edgeMarkers"]);
  m.pointAttributes = copyIn<double>(js["pointAttributes"]);
  m.attributesPerPoint = js["attributesPerPoint"].isNumber() ? js["attributesPerPoint"].as<std::uint32_t>() : 0;
  m.indexBase = js["indexBase"].isNumber() ? js["indexBase"].as<int>() : 0;
  m.triangles6 = copyIn<std::uint32_t>(js["triangles6"]);  // order 2
  m.stats.vertices = m.points.size() / 2;
  m.stats.triangles = m.triangles.size() / 3;
  return m;
}

ruppert::Voronoi voronoiFromJs(const val& js) {
  ruppert::Voronoi v;
  v.points = copyIn<double>(js["points"]);
  v.edges = copyIn<std::int32_t>(js["edges"]);
  v.rayDirections = copyIn<double>(js["rayDirections"]);
  v.meshEdges = copyIn<std::uint32_t>(js["meshEdges"]);
  if (v.rayDirections.size() != v.edges.size())
    throw ruppert::Error(ruppert::ErrorCode::MalformedInput, "voronoi.rayDirections must have two entries per edge");
  for (std::size_t i = 0; i < v.edges.size(); ++i)
    if (v.edges[i] >= static_cast<std::int64_t>(v.points.size() / 2) || (v.edges[i] < 0 && (i % 2 == 0 || v.edges[i] != -1)))
      throw ruppert::Error(ruppert::ErrorCode::IndexOutOfRange, "voronoi.edges[" + std::to_string(i) + "] = " +
                                                                   std::to_string(v.edges[i]) + " is not a Voronoi vertex");
  return v;
}

// ---------------------------------------------------------------------------------------------
// C++ -> JavaScript
// ---------------------------------------------------------------------------------------------
// Events as a structure of arrays: a trace can hold millions of them, and typed arrays are both
// smaller than objects and transferable from a worker.
val eventsToJs(const std::vector<ruppert::Event>& events) {
  const std::size_t n = events.size();
  std::vector<std::uint8_t> kind(n);
  std::vector<std::uint32_t> vertex(n), a(n), b(n), tri(3 * n);
  std::vector<std::int32_t> by(n);
  std::vector<double> xy(2 * n), cxy(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const ruppert::Event& e = events[i];
    kind[i] = static_cast<std::uint8_t>(e.kind);
    vertex[i] = e.vertex;
    xy[2 * i] = e.x;
    xy[2 * i + 1] = e.y;
    a[i] = e.a;
    b[i] = e.b;
    by[i] = static_cast<std::int32_t>(e.by);
    tri[3 * i] = e.t0;
    tri[3 * i + 1] = e.t1;
    tri[3 * i + 2] = e.t2;
    cxy[2 * i] = e.cx;
    cxy[2 * i + 1] = e.cy;
  }
  val o = val::object();
  o.set("count", static_cast<double>(n));
  o.set("kind", copyOut(kind));
  o.set("vertex", copyOut(vertex));
  o.set("xy", copyOut(xy));
  o.set("a", copyOut(a));
  o.set("b", copyOut(b));
  o.set("by", copyOut(by));
  o.set("triangle", copyOut(tri));
  o.set("circumcenter", copyOut(cxy));
  return o;
}

val plcToJs(const ruppert::Plc& plc) {
  val o = val::object();
  o.set("points", copyOut(plc.points));
  o.set("segments", copyOut(plc.segments));
  o.set("holes", copyOut(plc.holes));
  val regions = val::array();
  for (const ruppert::Region& r : plc.regions) {
    val item = val::object();
    item.set("x", r.x);
    item.set("y", r.y);
    item.set("attribute", r.attribute);
    item.set("maxArea", r.maxArea);
    regions.call<void>("push", item);
  }
  o.set("regions", regions);
  o.set("pointMarkers", copyOut(plc.pointMarkers));
  o.set("segmentMarkers", copyOut(plc.segmentMarkers));
  o.set("indexBase", plc.indexBase);
  o.set("pointAttributes", copyOut(plc.pointAttributes));
  o.set("attributesPerPoint", plc.attributesPerPoint);
  return o;
}

}  // namespace ruppert_wasm
