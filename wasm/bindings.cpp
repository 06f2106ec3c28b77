// Embind layer between wasm/index.js and the ruppert core.
//
// Only conversions live here; every check of user input that JavaScript can make happens in
// wasm/validate.js before anything crosses into wasm, and every mesh rule lives in the core.
//
// Contract with the JavaScript side (wasm/mesher.js):
//   * Inputs arrive already normalised: typed arrays of the exact element type, numbers, booleans.
//   * No C++ exception ever escapes a binding. Emscripten 3.1.6 would hand JavaScript a bare
//     number for it, and skipping our catch would also skip the destructors (a leak per call).
//     Instead every entry point returns a plain object; on failure it is
//     { errorCode: "INDEX_OUT_OF_RANGE", errorMessage: "...", reset?: true } and index.js turns it
//     into a MeshError.
//   * Results are copies (TypedArray.prototype.slice of a view), never views into the heap,
//     which would go stale the moment the heap grows.
//   * triangulate() goes through the heap (wasm/heap-call.js and "triangulate() through the heap"
//     below); readers, writers and the CLI parser use embind objects.
#include <emscripten/bind.h>
#include <emscripten/emscripten.h>
#include <emscripten/val.h>
#include <malloc.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "cli_args.h"    // core/cli: the native CLI's parser, reused by wasm/cli.js
#include "cli_report.h"  // core/cli: its summary, --stats and --trace printers
#include "ruppert/ruppert.h"

using emscripten::val;

namespace {

// Thrown by the C++ side of a JavaScript callback when the callback failed (threw, or returned
// something that is not a number). It is an exception so that it unwinds through the core and
// runs its destructors; the JavaScript wrapper keeps the original error and rethrows it.
struct CallbackFailed {};

template <class T>
val copyOut(const std::vector<T>& v) {
  return val(emscripten::typed_memory_view(v.size(), v.data())).call<val>("slice");
}

template <class T>
std::vector<T> copyIn(const val& typedArray) {
  if (typedArray.isUndefined() || typedArray.isNull()) return {};
  return emscripten::convertJSArrayToNumberVector<T>(typedArray);
}

val failure(const char* code, const std::string& message, bool reset = false) {
  val out = val::object();
  out.set("errorCode", std::string(code));
  out.set("errorMessage", message);
  if (reset) out.set("reset", true);
  return out;
}

// How a call failed: an ErrorCode name (or CALLBACK_FAILED, TOO_LARGE, INTERNAL), the message, and
// whether JavaScript should start a fresh instance.
struct Failure {
  const char* code = "";
  std::string message;
  bool reset = false;
};

// Runs `body` and turns every way it can fail into `failed`; true if it succeeded.
template <class Body>
bool attempt(Body&& body, Failure& failed) {
  try {
    body();
    return true;
  } catch (const ruppert::Error& e) {
    failed = {ruppert::errorCodeName(e.code()), e.what(), false};
  } catch (const CallbackFailed&) {
    failed = {"CALLBACK_FAILED", "a JavaScript callback failed", false};
  } catch (const std::bad_alloc&) {
    // The heap may now be grown to its 4 GB ceiling: ask JavaScript for a fresh instance.
    failed = {"TOO_LARGE", "out of memory: the mesh does not fit in 4 GB of WebAssembly memory", true};
  } catch (const std::exception& e) {
    failed = {"INTERNAL", std::string("internal error: ") + e.what(), true};
  } catch (...) {
    failed = {"INTERNAL", "internal error: unknown exception", true};
  }
  return false;
}

// Runs `body` and turns every way it can fail into a failure object.
template <class Body>
val guarded(Body&& body) {
  val out = val::undefined();
  Failure failed;
  if (attempt([&] { out = body(); }, failed)) return out;
  return failure(failed.code, failed.message, failed.reset);
}

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

// Options as wasm/heap-call.js writes them into the input table (OPTION_FIELDS there), one double
// each: reading them as embind properties cost a JavaScript round trip per field and per call.
constexpr int kOptionCount = 14;

ruppert::Options optionsFromTable(const double* v) {
  ruppert::Options o;
  o.minAngle = v[0];
  o.maxArea = v[1];
  // heap-call.js sends -1 for "automatic"; anything else is a validated non-negative integer.
  o.maxSteiner = v[2] < 0 ? ruppert::kAutoSteinerBudget : static_cast<std::uint64_t>(v[2]);
  o.placement = static_cast<ruppert::Placement>(static_cast<int>(v[3]));
  o.encroachment = static_cast<ruppert::Encroachment>(static_cast<int>(v[4]));
  o.variant = static_cast<ruppert::Variant>(static_cast<int>(v[5]));
  o.convexHull = v[6] != 0;
  o.autoHoles = v[7] != 0;
  o.trace = v[8] != 0;
  o.sizeMeasure = v[9] != 0;
  o.edges = v[10] != 0;
  o.noBoundarySteiner = v[11] != 0;
  o.noSegmentSteiner = v[12] != 0;
  o.jettison = v[13] != 0;
  return o;
}

// The JavaScript wrappers never throw: they return NaN (size) or -1 (progress) after storing
// the user's error, and we unwind with CallbackFailed.
void addCallbacks(ruppert::Options& o, const val& size, const val& progress) {
  if (!size.isUndefined() && !size.isNull()) {
    o.sizeFunction = [size](double x, double y) {
      const double area = size(x, y).as<double>();
      if (std::isnan(area)) throw CallbackFailed{};
      return area;
    };
  }
  if (!progress.isUndefined() && !progress.isNull()) {
    o.onProgress = [progress](const ruppert::Progress& p) {
      const int verdict = progress(static_cast<double>(p.insertedVertices),
                                   static_cast<double>(p.triangles), p.worstAngle)
                              .as<int>();
      if (verdict < 0) throw CallbackFailed{};
      return verdict != 0;
    };
  }
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
  m.triangles6 = copyIn<std::uint32_t>(js["triangles6"]);  // issue 16: order 2
  m.stats.vertices = m.points.size() / 2;
  m.stats.triangles = m.triangles.size() / 3;
  return m;
}

// ---------------------------------------------------------------------------------------------
// C++ -> JavaScript
// ---------------------------------------------------------------------------------------------
const char* noticeKindName(ruppert::NoticeKind k) {
  switch (k) {
    case ruppert::NoticeKind::DuplicatePoint: return "DUPLICATE_POINT";
    case ruppert::NoticeKind::ZeroLengthSegment: return "ZERO_LENGTH_SEGMENT";
    case ruppert::NoticeKind::DuplicateSegment: return "DUPLICATE_SEGMENT";
    case ruppert::NoticeKind::VertexOnSegment: return "VERTEX_ON_SEGMENT";
    case ruppert::NoticeKind::SegmentsCross: return "SEGMENTS_CROSS";
    case ruppert::NoticeKind::SegmentsOverlap: return "SEGMENTS_OVERLAP";
    case ruppert::NoticeKind::HoleOutsideDomain: return "HOLE_OUTSIDE_DOMAIN";
    case ruppert::NoticeKind::RegionOutsideDomain: return "REGION_OUTSIDE_DOMAIN";
    case ruppert::NoticeKind::NothingEnclosed: return "NOTHING_ENCLOSED";
  }
  return "UNKNOWN";
}

const char* reasonKindName(ruppert::ReasonKind k) {
  switch (k) {
    case ruppert::ReasonKind::SmallInputAngle: return "SMALL_INPUT_ANGLE";
    case ruppert::ReasonKind::SeditiousEdge: return "SEDITIOUS_EDGE";
    case ruppert::ReasonKind::SteinerBudget: return "STEINER_BUDGET";
    case ruppert::ReasonKind::PrecisionFloor: return "PRECISION_FLOOR";
    case ruppert::ReasonKind::Cancelled: return "CANCELLED";
    case ruppert::ReasonKind::AngleUnreachable: return "ANGLE_UNREACHABLE";
    case ruppert::ReasonKind::SegmentSplitForbidden: return "SEGMENT_SPLIT_FORBIDDEN";
  }
  return "UNKNOWN";
}

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

// Reasons and notices go through the heap too (see wasm/heap-call.js): numbers per item (the kind's
// number first), one UTF-8 text of "message\0" per item, and the kinds' names, which JavaScript
// decodes at once. An input with 10^5 duplicate points has 10^5 notices; an object built field by
// field through embind cost microseconds each.
void appendMessage(std::string& text, const std::string& message) {
  const std::size_t start = text.size();
  text.append(message).push_back('\0');
  // A message never holds a NUL (the core writes them from numbers and names); were one to, it
  // would shift every later item, so it is replaced.
  const std::size_t end = text.size() - 1;  // the message's own terminator
  for (std::size_t i = text.find('\0', start); i < end; i = text.find('\0', i + 1)) text[i] = ' ';
}

// "NAME0\0NAME1\0...": the name of every kind, in the enum's order.
template <class Kind>
const std::string& kindNames(const char* (*name)(Kind)) {
  static const std::string names = [name] {
    std::string text;
    for (int k = 0; std::string(name(static_cast<Kind>(k))) != "UNKNOWN"; ++k) text.append(name(static_cast<Kind>(k))).push_back('\0');
    return text;
  }();
  return names;
}

// numbers: kind, count per reason.
void reasonsToTable(const std::vector<ruppert::Reason>& list, std::vector<double>& numbers, std::string& text) {
  numbers.clear(), text.clear();
  for (const ruppert::Reason& r : list) {
    numbers.insert(numbers.end(), {static_cast<double>(r.kind), static_cast<double>(r.count)});
    appendMessage(text, r.message);
  }
}

// numbers: kind, a, b, x, y per notice.
void noticesToTable(const std::vector<ruppert::Notice>& list, std::vector<double>& numbers, std::string& text) {
  numbers.clear(), text.clear();
  numbers.reserve(5 * list.size());
  text.reserve(48 * list.size());  // "points[i] duplicates points[j]; merged"
  for (const ruppert::Notice& n : list) {
    numbers.insert(numbers.end(),
                   {static_cast<double>(n.kind), static_cast<double>(n.a), static_cast<double>(n.b), n.x, n.y});
    appendMessage(text, n.message);
  }
}

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

// ---------------------------------------------------------------------------------------------
// Entry points
// ---------------------------------------------------------------------------------------------
// The native CLI's argument parser. Returns { usageLine, helpText, usageError? } plus, on success,
// the parsed fields with options in index.js's vocabulary.
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
    options.set("placement", std::string(o.placement == ruppert::Placement::Circumcenter ? "circumcenter"
                                         : o.placement == ruppert::Placement::Petal   ? "petal"
                                         : o.placement == ruppert::Placement::Optimal ? "optimal"
                                                                                      : "offcenter"));
    options.set("encroachment", std::string(o.encroachment == ruppert::Encroachment::DiametralDisk ? "disk" : "lens"));
    options.set("variant", std::string(o.variant == ruppert::Variant::BoundingBox ? "box" : "cdt"));
    options.set("convexHull", o.convexHull);
    options.set("autoHoles", o.autoHoles);
    options.set("trace", !args.tracePath.empty());
    options.set("sizeMeasure", o.sizeMeasure);
    options.set("order", args.order);      // issue 16, derived
    options.set("voronoi", args.voronoi);
    options.set("edges", o.edges);
    options.set("noBoundarySteiner", o.noBoundarySteiner);
    options.set("noSegmentSteiner", o.noSegmentSteiner);
    options.set("jettison", o.jettison);
    out.set("options", options);
    return out;
  });
}

// format: "poly", "node", "json" or "geojson".
val readPlc(std::string text, std::string format, std::string name) {
  return guarded([&] {
    ruppert::Plc plc;
    if (format == "poly") {
      plc = ruppert::parsePoly(text, name);
    } else if (format == "node") {
      plc = ruppert::parseNode(text, name);
    } else if (format == "json") {
      plc = ruppert::parseJson(text, name);
    } else if (format == "geojson") {
      plc = ruppert::parseGeoJson(text, name);
    } else {
      throw ruppert::Error(ruppert::ErrorCode::InvalidOption, "unknown input format '" + format + "'");
    }
    val out = val::object();
    out.set("plc", plcToJs(plc));
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
val writeMesh(val meshJs, val inputJs, std::string format) {
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
      text = ruppert::toVtu(mesh);
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

// ---------------------------------------------------------------------------------------------
// Issue 16, derived: refining a mesh (Plc::triangles, triangleMaxArea), quadratic nodes (order 2) and
// the Voronoi dual (voronoi), staged in a table of their own (wasm/heap-call.js, DERIVED_*): its
// input is two (address) slots then order and voronoi; its output five (address, length) pairs.
// ---------------------------------------------------------------------------------------------
struct DerivedStaged {
  std::vector<std::uint32_t> triangles;
  std::vector<double> triangleMaxArea;
  double inputTable[4] = {};  // triangles, triangleMaxArea addresses; order; voronoi
  ruppert::Voronoi voronoi;
  double outputTable[10] = {};  // triangles6, voronoi points, edges, rayDirections, meshEdges
};

DerivedStaged& derivedStaged() {
  static DerivedStaged d;
  return d;
}

// Before triangulate(): the staged old mesh moves into the PLC.
void takeDerivedInput(ruppert::Plc& plc) {
  DerivedStaged& d = derivedStaged();
  plc.triangles = std::move(d.triangles), plc.triangleMaxArea = std::move(d.triangleMaxArea);
  d.triangles = {}, d.triangleMaxArea = {};
}

// After triangulate(): midpoint nodes (into mesh.points and pointMarkers, so the main table carries
// them) and the dual, then the table of the derived arrays.
void deriveOutputs(ruppert::Mesh& mesh) {
  DerivedStaged& d = derivedStaged();
  d.voronoi = d.inputTable[3] != 0 ? ruppert::voronoiDiagram(mesh) : ruppert::Voronoi{};
  if (d.inputTable[2] == 2) ruppert::addQuadraticNodes(mesh);
  double* t = d.outputTable;
  auto array = [&t](const auto& v) {
    *t++ = static_cast<double>(reinterpret_cast<std::uintptr_t>(v.data()));
    *t++ = static_cast<double>(v.size());
  };
  array(mesh.triangles6), array(d.voronoi.points), array(d.voronoi.edges), array(d.voronoi.rayDirections);
  array(d.voronoi.meshEdges);
}

void releaseDerived() {
  DerivedStaged& d = derivedStaged();
  d.triangles = {}, d.triangleMaxArea = {}, d.voronoi = {};
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

// ---------------------------------------------------------------------------------------------
// triangulate() through the heap (wasm/heap-call.js): the input arrays and the options are written
// by JavaScript straight into a staged Plc and a table of numbers, and the output arrays (reasons and
// notices included) are read back from a table of addresses. A small mesh otherwise spends most of
// its call in embind, one JavaScript round trip per object field. Without callbacks the call goes
// through plain exported functions (rp_*), which cost no more than any wasm call; embind is left for
// callbacks, failures, traces and the CLI's texts.
// ---------------------------------------------------------------------------------------------
// Layout of the output table, read by wasm/heap-call.js (ARRAYS, then the scalars): twenty
// (address, length) pairs, then scalars.
constexpr int kOutputArrays = 20;
constexpr int kOutputTableSize = 2 * kOutputArrays + 20;
constexpr int kInputArrays = 7;

struct Staged {
  ruppert::Plc plc;
  std::vector<double> regions;  // x, y, attribute, maxArea per region
  // Addresses of the seven input arrays (as doubles), then the options (optionsFromTable).
  double inputTable[kInputArrays + kOptionCount] = {};
  ruppert::Mesh mesh;
  std::vector<double> histogram, reasonNumbers, noticeNumbers;
  std::string reasonText, noticeText;
  double outputTable[kOutputTableSize] = {};
  Failure failed;
};

Staged& staged() {
  static Staged s;
  return s;
}

template <class T>
double sized(std::vector<T>& v, double length) {
  v.assign(static_cast<std::size_t>(length), T{});
  v.shrink_to_fit();  // the previous call's capacity is not kept
  return static_cast<double>(reinterpret_cast<std::uintptr_t>(v.data()));
}

void writeOutputTable(Staged& s) {
  const ruppert::Mesh& m = s.mesh;
  const ruppert::Stats& st = m.stats;
  s.histogram.assign(st.angleHistogram.begin(), st.angleHistogram.end());
  reasonsToTable(m.reasons, s.reasonNumbers, s.reasonText);
  noticesToTable(m.notices, s.noticeNumbers, s.noticeText);
  double* t = s.outputTable;
  auto array = [&t](const auto& v) {
    *t++ = static_cast<double>(reinterpret_cast<std::uintptr_t>(v.data()));
    *t++ = static_cast<double>(v.size());
  };
  array(m.points), array(m.triangles), array(m.neighbors), array(m.segments), array(m.segmentIds);
  array(m.vertexKinds), array(m.triangleAttributes), array(m.pointMarkers), array(s.histogram);
  array(s.reasonNumbers), array(s.reasonText), array(kindNames(&reasonKindName));
  array(s.noticeNumbers), array(s.noticeText), array(kindNames(&noticeKindName));
  // Issue 16: boundary markers, edges, attributes, jettison's numbering.
  array(m.segmentMarkers), array(m.edges), array(m.edgeMarkers), array(m.pointAttributes), array(m.inputToOutput);
  for (double v : {double(m.indexBase), m.complete ? 1.0 : 0.0, double(m.reasons.size()), double(m.notices.size()),
                   double(m.events.size()), double(st.vertices), double(st.triangles), st.minAngle, st.maxAngle,
                   double(st.inputVertices), double(st.segmentVertices), double(st.interiorVertices),
                   double(st.offCenterVertices), double(st.intersectionVertices), double(st.rejectedCircumcenters),
                   st.lfsIntegral, st.trianglesPerLfsIntegral, st.milliseconds, st.reachedAngle,
                   double(m.attributesPerPoint)})
    *t++ = v;
}

// Meshes the staged input with the staged options (plus callbacks, if any); true on success, else the
// failure is in staged().failed.
bool runStaged(const val* sizeFunction, const val* onProgress) {
  Staged& s = staged();
  // Moved out, so that the input is freed however this call ends.
  ruppert::Plc plc = std::move(s.plc);
  const std::vector<double> regions = std::move(s.regions);
  s.plc = ruppert::Plc{}, s.regions = {};
  return attempt(
      [&] {
        for (std::size_t i = 0; i + 3 < regions.size(); i += 4)
          plc.regions.push_back(ruppert::Region{regions[i], regions[i + 1], regions[i + 2], regions[i + 3]});
        ruppert::Options options = optionsFromTable(s.inputTable + kInputArrays);
        if (sizeFunction != nullptr) addCallbacks(options, *sizeFunction, *onProgress);
        takeDerivedInput(plc);  // issue 16, derived
        s.mesh = ruppert::triangulate(plc, options);
        deriveOutputs(s.mesh);  // issue 16, derived
        writeOutputTable(s);
      },
      s.failed);
}

// Meshes the staged input with callbacks (JavaScript functions, or null). Returns null on success,
// else a failure object.
val triangulateStaged(val sizeFunction, val onProgress) {
  if (runStaged(&sizeFunction, &onProgress)) return val::null();
  const Failure& f = staged().failed;
  return failure(f.code, f.message, f.reset);
}

// The failure of the last rp_triangulate().
val stagedFailure() {
  const Failure& f = staged().failed;
  return failure(f.code, f.message, f.reset);
}

// The staged mesh's events when traced, and the CLI's texts when `report` is not null (see
// reportToJs).
val stagedExtras(val report, bool trace) {
  return guarded([&] {
    const ruppert::Mesh& mesh = staged().mesh;
    val out = val::object();
    if (trace) out.set("events", eventsToJs(mesh.events));
    if (!report.isNull() && !report.isUndefined()) out.set("report", reportToJs(mesh, report));
    return out;
  });
}

}  // namespace

// The plain exports of the hot path (Module._rp_*, no embind).
extern "C" {

// Sizes the staged input arrays (lengths in elements) and returns the address of the input table:
// the addresses where JavaScript writes points (f64), segments (u32), holes (f64), regions (f64, 4 per
// region), pointMarkers (i32), segmentMarkers (i32), pointAttributes (f64), then the options. 0 if they
// do not fit in memory.
EMSCRIPTEN_KEEPALIVE std::uintptr_t rp_stage_input(double points, double segments, double holes, double regions,
                                                   double pointMarkers, double segmentMarkers, double pointAttributes,
                                                   int indexBase, int attributesPerPoint) {
  Staged& s = staged();
  try {
    s.mesh = ruppert::Mesh{};
    s.inputTable[0] = sized(s.plc.points, points);
    s.inputTable[1] = sized(s.plc.segments, segments);
    s.inputTable[2] = sized(s.plc.holes, holes);
    s.inputTable[3] = sized(s.regions, regions);
    s.inputTable[4] = sized(s.plc.pointMarkers, pointMarkers);
    s.inputTable[5] = sized(s.plc.segmentMarkers, segmentMarkers);
    s.inputTable[6] = sized(s.plc.pointAttributes, pointAttributes);
    s.plc.indexBase = indexBase;
    s.plc.attributesPerPoint = static_cast<std::uint32_t>(attributesPerPoint);
  } catch (const std::bad_alloc&) {
    s.plc = ruppert::Plc{};
    s.regions = {};
    return 0;
  }
  return reinterpret_cast<std::uintptr_t>(s.inputTable);
}

// Meshes the staged input without callbacks: 0 on success (the mesh is then described by the output
// table), 1 on failure (stagedFailure() says what).
EMSCRIPTEN_KEEPALIVE int rp_triangulate() { return runStaged(nullptr, nullptr) ? 0 : 1; }

EMSCRIPTEN_KEEPALIVE std::uintptr_t rp_output_table() { return reinterpret_cast<std::uintptr_t>(staged().outputTable); }

// Frees the staged mesh once JavaScript has copied it out.
EMSCRIPTEN_KEEPALIVE void rp_release_staged() {
  Staged& s = staged();
  s.mesh = ruppert::Mesh{};
  s.histogram = {}, s.reasonNumbers = {}, s.noticeNumbers = {};
  s.reasonText = {}, s.noticeText = {};
  s.failed = {};
  releaseDerived();  // issue 16, derived
}

// Issue 16, derived: sizes the old mesh's arrays (lengths in elements), sets order and voronoi, and
// returns the address of the derived input table (see DerivedStaged). 0 if they do not fit.
EMSCRIPTEN_KEEPALIVE std::uintptr_t rp_stage_derived(double triangles, double triangleMaxArea, double order, double voronoi) {
  DerivedStaged& d = derivedStaged();
  try {
    d.inputTable[0] = sized(d.triangles, triangles);
    d.inputTable[1] = sized(d.triangleMaxArea, triangleMaxArea);
  } catch (const std::bad_alloc&) {
    releaseDerived();
    return 0;
  }
  d.inputTable[2] = order, d.inputTable[3] = voronoi;
  return reinterpret_cast<std::uintptr_t>(d.inputTable);
}

EMSCRIPTEN_KEEPALIVE std::uintptr_t rp_derived_table() { return reinterpret_cast<std::uintptr_t>(derivedStaged().outputTable); }

}  // extern "C"

namespace {

// Bytes currently allocated by malloc: lets tests prove that repeated calls do not leak.
double allocatedBytes() { return static_cast<double>(mallinfo().uordblks); }

// Lets the package tests prove that a wasm abort does not leave the module unusable.
void abortForTesting() { std::abort(); }

}  // namespace

EMSCRIPTEN_BINDINGS(ruppert) {
  emscripten::function("triangulateStaged", &triangulateStaged);
  emscripten::function("stagedFailure", &stagedFailure);
  emscripten::function("stagedExtras", &stagedExtras);
  emscripten::function("readPlc", &readPlc);
  emscripten::function("readPolyWithNode", &readPolyWithNode);
  emscripten::function("writeMesh", &writeMesh);
  emscripten::function("parseCliArgs", &parseCliArgs);
  emscripten::function("readMeshFiles", &readMeshFiles);  // issue 16, derived
  emscripten::function("writeVoronoi", &writeVoronoi);
  emscripten::function("allocatedBytes", &allocatedBytes);
  emscripten::function("abortForTesting", &abortForTesting);
}
