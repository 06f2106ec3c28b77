// triangulate() through the heap (wasm/heap-call.js): the input arrays and the options are written
// by JavaScript straight into a staged Plc and a table of numbers, and the output arrays (reasons and
// notices included) are read back from a table of addresses, both laid out as heap_layout.h says. A
// small mesh otherwise spends most of its call in embind, one JavaScript round trip per object field.
// Without callbacks the call goes through plain exported functions (rp_*), which cost no more than
// any wasm call; embind is left for callbacks, failures, traces and the CLI's texts.
#include <emscripten/bind.h>
#include <emscripten/emscripten.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "binding_common.h"
#include "cli_texts.h"
#include "heap_layout.h"
#include "js_objects.h"
#include "ruppert/ruppert.h"

namespace ruppert_wasm {
namespace {

// One option from its double in the table, as heap-call.js wrote it: a number as itself, a flag as
// 0 or 1, an integer (smooth's passes, checked) as itself, an enum as the core's value, and maxSteiner -1 for "automatic" (else a checked count).
void fromTable(double v, double& option) { option = v; }
void fromTable(double v, bool& option) { option = v != 0; }
void fromTable(double v, int& option) { option = static_cast<int>(v); }
void fromTable(double v, std::uint64_t& option) {
  option = v < 0 ? ruppert::kAutoSteinerBudget : static_cast<std::uint64_t>(v);
}
template <class Enum, class = std::enable_if_t<std::is_enum_v<Enum>>>
void fromTable(double v, Enum& option) {
  option = static_cast<Enum>(static_cast<int>(v));
}

// The options as heap-call.js writes them after the input arrays' addresses, one double each, in
// the option table's order, which kInputFields lists by the same macro: reading them as embind
// properties cost a JavaScript round trip per field and per call.
ruppert::Options optionsFromTable(const double* v) {
  ruppert::Options o;
#define RUPPERT_WASM_READ_OPTION_(KEY, ...) fromTable(*v++, o.KEY);
  RUPPERT_MESH_OPTIONS(RUPPERT_WASM_READ_OPTION_)
#undef RUPPERT_WASM_READ_OPTION_
  return o;
}

// Plc::curves from their flat form (heap_layout.h's kCurveValues per curve).
void curvesFromTable(const std::vector<double>& v, std::vector<ruppert::Curve>& out) {
  for (std::size_t i = 0; i + kCurveValues <= v.size(); i += kCurveValues) {
    ruppert::Curve c;
    c.type = static_cast<ruppert::CurveType>(static_cast<int>(v[i]));
    c.from = static_cast<std::uint32_t>(v[i + 1]), c.to = static_cast<std::uint32_t>(v[i + 2]);
    c.center[0] = v[i + 3], c.center[1] = v[i + 4];
    for (int k = 0; k < 4; ++k) c.controls[k] = v[i + 3 + k];
    c.marker = static_cast<std::int32_t>(v[i + 7]);
    out.push_back(c);
  }
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

// Reasons and notices: numbers per item (the kind's number first; JavaScript names the kinds from
// the core's tables, which describe.cpp exports) and one UTF-8 text of "message\0" per item. An
// input with 10^5 duplicate points has 10^5 notices; an object built field by field through embind
// cost microseconds each.
void appendMessage(std::string& text, const std::string& message) {
  const std::size_t start = text.size();
  text.append(message).push_back('\0');
  // A message never holds a NUL (the core writes them from numbers and names); were one to, it
  // would shift every later item, so it is replaced.
  const std::size_t end = text.size() - 1;  // the message's own terminator
  for (std::size_t i = text.find('\0', start); i < end; i = text.find('\0', i + 1)) text[i] = ' ';
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

// Writes a table field by field: arrays as (address, length), numbers as themselves.
struct TableWriter {
  double* t;
  template <class V>
  TableWriter& array(const V& v) {
    *t++ = static_cast<double>(reinterpret_cast<std::uintptr_t>(v.data()));
    *t++ = static_cast<double>(v.size());
    return *this;
  }
  TableWriter& number(double v) {
    *t++ = v;
    return *this;
  }
  // A writer that wrote other than the layout's count of doubles is out of step with heap_layout.h.
  void end(const double* table, std::size_t size) const {
    if (t != table + size) throw ruppert::Error(ruppert::ErrorCode::Internal, "heap table out of step with its layout");
  }
};

// A table's arrays copied into one block (heap_layout.h), so that JavaScript copies the result out of
// the heap in one piece into one ArrayBuffer instead of array by array: a small mesh's call spent more
// on that than on meshing. The block is kept between calls while it is small, so that packing
// allocates nothing; larger outputs stay where they are (packedBytes 0), as a copy of them would
// cost memory and save nothing measurable.
constexpr std::size_t kPackLimit = std::size_t(1) << 20;  // bytes
constexpr std::size_t kKeptBlock = std::size_t(64) << 10;  // bytes

static_assert(slotOf(kOutputFields, "packedBytes") == fieldCount(kOutputFields) - 1 &&
                  slotOf(kDerivedOutputFields, "packedBytes") == fieldCount(kDerivedOutputFields) - 1,
              "packedBytes is an output table's last field");

// Where a table's packed arrays are: their (address, length) slots and element sizes, found from the
// layout at compile time, not per call.
template <std::size_t N>
struct PackedSlots {
  std::size_t count = 0, slot[N] = {}, elementBytes[N] = {}, packedBytesSlot = 0;
};

template <std::size_t N>
constexpr PackedSlots<N> packedSlots(const char* const (&fields)[N]) {
  PackedSlots<N> out;
  std::size_t slot = 0;
  for (const char* field : fields) {
    const std::size_t bytes = elementBytes(field);
    if (bytes != 0 && !staysInHeap(field)) out.slot[out.count] = slot, out.elementBytes[out.count++] = bytes;
    slot += bytes == 0 ? 1 : 2;
  }
  out.packedBytesSlot = slot - 1;  // the last field
  return out;
}

template <std::size_t N>
void packTable(double* table, const PackedSlots<N>& packed, std::vector<std::uint64_t>& block) {
  const auto aligned = [](std::size_t bytes) { return (bytes + 7) & ~std::size_t(7); };
  std::size_t total = 0;
  for (std::size_t i = 0; i < packed.count; ++i)
    total += aligned(packed.elementBytes[i] * static_cast<std::size_t>(table[packed.slot[i] + 1]));
  table[packed.packedBytesSlot] = 0;
  if (total > kPackLimit) return;
  block.resize(total / 8);
  auto* out = reinterpret_cast<unsigned char*>(block.data());
  for (std::size_t i = 0; i < packed.count; ++i) {
    double* slot = table + packed.slot[i];
    const std::size_t size = packed.elementBytes[i] * static_cast<std::size_t>(slot[1]);
    if (size > 0) std::memcpy(out, reinterpret_cast<const void*>(static_cast<std::uintptr_t>(slot[0])), size);
    slot[0] = static_cast<double>(reinterpret_cast<std::uintptr_t>(out));
    out += aligned(size);
  }
  table[packed.packedBytesSlot] = static_cast<double>(total);
}

constexpr auto kPackedOutput = packedSlots(kOutputFields);
constexpr auto kPackedDerived = packedSlots(kDerivedOutputFields);

// After JavaScript has copied a packed table out.
void releaseBlock(std::vector<std::uint64_t>& block) {
  if (block.capacity() * sizeof(std::uint64_t) > kKeptBlock) block = {};
  else block.clear();
}

// ---------------------------------------------------------------------------------------------
// Derived outputs: refining a mesh (Plc::triangles, triangleMaxArea), quadratic nodes (order 2) and
// the Voronoi dual (voronoi), staged in tables of their own (kDerivedInputFields, kDerivedOutputFields).
// ---------------------------------------------------------------------------------------------
// Where the derived table holds order and voronoi, found by their keys.
constexpr std::size_t kOrderSlot = slotOf(kDerivedInputFields, ruppert::option::order::key);
constexpr std::size_t kVoronoiSlot = slotOf(kDerivedInputFields, ruppert::option::voronoi::key);
static_assert(kOrderSlot < fieldCount(kDerivedInputFields) && kVoronoiSlot < fieldCount(kDerivedInputFields));

struct DerivedStaged {
  std::vector<std::uint32_t> triangles;
  std::vector<double> triangleMaxArea;
  double inputTable[kDerivedInputTableSize] = {};
  ruppert::Voronoi voronoi;
  double outputTable[kDerivedOutputTableSize] = {};
  std::vector<std::uint64_t> block;  // packTable's
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
  d.voronoi = d.inputTable[kVoronoiSlot] != 0 ? ruppert::voronoiDiagram(mesh) : ruppert::Voronoi{};
  if (d.inputTable[kOrderSlot] == 2) ruppert::addQuadraticNodes(mesh);
  TableWriter w{d.outputTable};
  w.array(mesh.triangles6).array(d.voronoi.points).array(d.voronoi.edges).array(d.voronoi.rayDirections);
  w.array(d.voronoi.meshEdges).number(0).end(d.outputTable, kDerivedOutputTableSize);
  packTable(d.outputTable, kPackedDerived, d.block);
}

// Also what a call that stages nothing derived finds (heap-call.js skips rp_stage_derived then).
void releaseDerived() {
  DerivedStaged& d = derivedStaged();
  d.triangles = {}, d.triangleMaxArea = {}, d.voronoi = {};
  releaseBlock(d.block);
  d.inputTable[kOrderSlot] = 1, d.inputTable[kVoronoiSlot] = 0;
}

// ---------------------------------------------------------------------------------------------
// The main tables (kInputFields, kOutputFields)
// ---------------------------------------------------------------------------------------------
struct Staged {
  ruppert::Plc plc;
  std::vector<double> regions;  // x, y, attribute, maxArea per region
  std::vector<double> curves;   // kCurveValues per curve
  double inputTable[kInputTableSize] = {};
  ruppert::Mesh mesh;
  std::vector<double> histogram, reasonNumbers, noticeNumbers;
  std::string reasonText, noticeText;
  double outputTable[kOutputTableSize] = {};
  std::vector<std::uint64_t> block;  // packTable's
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

// In kOutputFields's order.
void writeOutputTable(Staged& s) {
  const ruppert::Mesh& m = s.mesh;
  const ruppert::Stats& st = m.stats;
  // A plain loop through int64 (counts are far below 2^53, so exact) rather than assign() from the
  // uint64 iterators, whose template and unsigned conversions weigh more in the module.
  s.histogram.resize(st.angleHistogram.size());
  for (std::size_t k = 0; k < st.angleHistogram.size(); ++k)
    s.histogram[k] = static_cast<double>(static_cast<std::int64_t>(st.angleHistogram[k]));
  reasonsToTable(m.reasons, s.reasonNumbers, s.reasonText);
  noticesToTable(m.notices, s.noticeNumbers, s.noticeText);
  TableWriter w{s.outputTable};
  w.array(m.points).array(m.triangles).array(m.neighbors).array(m.segments).array(m.segmentIds);
  w.array(m.vertexKinds).array(m.triangleAttributes).array(m.pointMarkers);
  w.array(s.reasonNumbers).array(s.reasonText).array(s.noticeNumbers).array(s.noticeText);
  // Boundary markers, edges, attributes, jettison's numbering.
  w.array(m.segmentMarkers).array(m.edges).array(m.edgeMarkers).array(m.pointAttributes).array(m.inputToOutput);
  w.number(m.indexBase).number(m.complete ? 1 : 0).number(double(m.reasons.size()));
  w.number(double(m.notices.size())).number(double(m.events.size()));
  w.number(double(st.vertices)).number(double(st.triangles)).number(st.minAngle).number(st.maxAngle);
  w.array(s.histogram).number(double(st.inputVertices)).number(double(st.segmentVertices));
  w.number(double(st.interiorVertices)).number(double(st.offCenterVertices)).number(double(st.intersectionVertices));
  w.number(double(st.rejectedCircumcenters)).number(st.lfsIntegral).number(st.trianglesPerLfsIntegral);
  w.number(st.milliseconds).number(st.reachedAngle).number(double(m.attributesPerPoint));
  w.array(m.triangleExemptions).number(0);
  w.end(s.outputTable, kOutputTableSize);
  packTable(s.outputTable, kPackedOutput, s.block);
}

// Meshes the staged input with the staged options (plus callbacks, if any); true on success, else the
// failure is in staged().failed.
bool runStaged(const val* sizeFunction, const val* onProgress) {
  Staged& s = staged();
  // Moved out, so that the input is freed however this call ends.
  ruppert::Plc plc = std::move(s.plc);
  const std::vector<double> regions = std::move(s.regions), curves = std::move(s.curves);
  s.plc = ruppert::Plc{}, s.regions = {}, s.curves = {};
  return attempt(
      [&] {
        for (std::size_t i = 0; i + 3 < regions.size(); i += 4)
          plc.regions.push_back(ruppert::Region{regions[i], regions[i + 1], regions[i + 2], regions[i + 3]});
        curvesFromTable(curves, plc.curves);
        ruppert::Options options = optionsFromTable(s.inputTable + kInputArrays);
        if (sizeFunction != nullptr) addCallbacks(options, *sizeFunction, *onProgress);
        takeDerivedInput(plc);
        s.mesh = ruppert::triangulate(plc, options);
        deriveOutputs(s.mesh);
        writeOutputTable(s);
      },
      s.failed);
}

// Meshes the staged input with callbacks (JavaScript functions, or null). Returns null on success,
// else a failure object.
val triangulateStaged(val sizeFunction, val onProgress) {
  if (runStaged(&sizeFunction, &onProgress)) return val::null();
  return failureToJs(staged().failed);
}

// The failure of the last rp_triangulate().
val stagedFailure() { return failureToJs(staged().failed); }

// The staged mesh's events when traced, and the CLI's texts when `report` is not null (see
// reportToJs).
val stagedExtras(val report, bool trace) {
  return guarded([&] {
    const ruppert::Mesh& mesh = staged().mesh;
    val out = val::object();
    if (trace) out.set("events", eventsToJs(mesh.events));
#ifdef RUPPERT_WASM_CLI_TEXTS
    if (!report.isNull() && !report.isUndefined()) out.set("report", reportToJs(mesh, report));
#else
    (void)report;  // the mesher module has no CLI texts (ruppert-cli.wasm has them)
#endif
    return out;
  });
}

}  // namespace
}  // namespace ruppert_wasm

using namespace ruppert_wasm;

// The plain exports of the hot path (Module._rp_*, no embind).
extern "C" {

// Sizes the staged input arrays (lengths in elements, in kInputFields's order) and returns the address
// of the input table, where JavaScript writes the arrays' addresses and then the options. 0 if they do
// not fit in memory.
EMSCRIPTEN_KEEPALIVE std::uintptr_t rp_stage_input(double points, double segments, double holes, double regions,
                                                   double pointMarkers, double segmentMarkers, double pointAttributes,
                                                   double curves, int indexBase, int attributesPerPoint) {
  static_assert(kInputArrays == 8, "rp_stage_input takes one length per input array");
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
    s.inputTable[7] = sized(s.curves, curves);
    s.plc.indexBase = indexBase;
    s.plc.attributesPerPoint = static_cast<std::uint32_t>(attributesPerPoint);
  } catch (const std::bad_alloc&) {
    s.plc = ruppert::Plc{};
    s.regions = {}, s.curves = {};
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
  releaseBlock(s.block);
  s.failed = {};
  releaseDerived();
}

// Derived outputs: sizes the old mesh's arrays (lengths in elements), sets order and voronoi, and
// returns the address of the derived input table (kDerivedInputFields). 0 if they do not fit.
EMSCRIPTEN_KEEPALIVE std::uintptr_t rp_stage_derived(double triangles, double triangleMaxArea, double order, double voronoi) {
  DerivedStaged& d = derivedStaged();
  try {
    d.inputTable[0] = sized(d.triangles, triangles);
    d.inputTable[1] = sized(d.triangleMaxArea, triangleMaxArea);
  } catch (const std::bad_alloc&) {
    releaseDerived();
    return 0;
  }
  d.inputTable[kOrderSlot] = order, d.inputTable[kVoronoiSlot] = voronoi;
  return reinterpret_cast<std::uintptr_t>(d.inputTable);
}

EMSCRIPTEN_KEEPALIVE std::uintptr_t rp_derived_table() { return reinterpret_cast<std::uintptr_t>(derivedStaged().outputTable); }

}  // extern "C"

EMSCRIPTEN_BINDINGS(ruppert_heap) {
  emscripten::function("triangulateStaged", &triangulateStaged);
  emscripten::function("stagedFailure", &stagedFailure);
  emscripten::function("stagedExtras", &stagedExtras);
}
