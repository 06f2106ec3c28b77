// The layout of the tables through which triangulate() passes its input and mesh
// (heap_triangulate.cpp), written once: the binding exports these lists (describe.cpp) and
// wasm/heap-call.js reads the tables by them, so neither side copies an offset or a count.
//
// A table is a run of doubles. A field "name:type" is an array: its address (in the input tables),
// or its (address, length) pair (in the output tables), with the element type f64, u32, i32 or u8. A
// field "name" without a type is one number. "stats.vertices" goes to mesh.stats.vertices.
//
// An output table's arrays are packed (heap_triangulate.cpp's packTable): copied, in the table's order
// and each at an 8-byte-aligned offset, into one block, whose size the table's number "packedBytes"
// gives (0: too large to pack, each array stays where it is), so that JavaScript copies the mesh out
// of the heap in one piece. A field "name:type:heap" stays where it is (JavaScript reads it in place).
#pragma once

#include <cstddef>

#include "ruppert/ruppert.h"

namespace ruppert_wasm {

// An option's field: its key (ruppert/option_table.h), a number.
#define RUPPERT_WASM_FIELD_(KEY, ...) #KEY,

// rp_stage_input's arrays (it takes their lengths in this order), then the options of the option
// table's RUPPERT_MESH_OPTIONS, in its order (optionsFromTable reads them through the same list).
inline constexpr const char* kInputFields[] = {
    "points:f64", "segments:u32", "holes:f64", "regions:f64", "pointMarkers:i32", "segmentMarkers:i32",
    "pointAttributes:f64", "curves:f64", RUPPERT_MESH_OPTIONS(RUPPERT_WASM_FIELD_)};
// "curves": kCurveValues doubles per Plc::curves item: the type's number, from, to, the center (arc,
// then two zeros) or the controls (Bézier), the marker.
inline constexpr std::size_t kCurveValues = 8;

// writeOutputTable()'s order. Reasons and notices come as numbers per item (the kind's number first)
// and a UTF-8 text of "message\0" per item.
inline constexpr const char* kOutputFields[] = {
    "points:f64", "triangles:u32", "neighbors:i32", "segments:u32", "segmentIds:i32", "vertexKinds:u8",
    "triangleAttributes:f64", "pointMarkers:i32", "reasonNumbers:f64:heap", "reasonText:u8:heap",
    "noticeNumbers:f64:heap", "noticeText:u8:heap", "segmentMarkers:i32", "edges:u32", "edgeMarkers:i32", "pointAttributes:f64",
    "inputToOutput:i32", "indexBase", "complete", "reasonCount", "noticeCount", "eventCount",
    "stats.vertices", "stats.triangles", "stats.minAngle", "stats.maxAngle", "stats.angleHistogram:f64",
    "stats.inputVertices", "stats.segmentVertices", "stats.interiorVertices", "stats.offCenterVertices",
    "stats.intersectionVertices", "stats.rejectedCircumcenters", "stats.lfsIntegral",
    "stats.trianglesPerLfsIntegral", "stats.milliseconds", "stats.reachedAngle", "attributesPerPoint",
    "triangleExemptions:u8", "packedBytes"};

// Derived outputs: rp_stage_derived's table (the old mesh to refine, then order and voronoi) and
// rp_derived_table's.
inline constexpr const char* kDerivedInputFields[] = {"triangles:u32", "triangleMaxArea:f64",
                                                      RUPPERT_DERIVED_OPTIONS(RUPPERT_WASM_FIELD_)};
#undef RUPPERT_WASM_FIELD_
inline constexpr const char* kDerivedOutputFields[] = {"triangles6:u32", "voronoi.points:f64", "voronoi.edges:i32",
                                                       "voronoi.rayDirections:f64", "voronoi.meshEdges:u32", "packedBytes"};

// How many bytes one element of the array field `field` takes ("name:f64" 8, u32 and i32 4, u8 1); 0
// for a number.
constexpr std::size_t elementBytes(const char* field) {
  while (*field != '\0' && *field != ':') ++field;
  if (*field == '\0') return 0;
  return field[1] == 'f' ? 8 : field[1] == 'u' && field[2] == '8' ? 1 : 4;
}

// Whether the array field `field` stays in place ("name:type:heap") instead of being packed.
constexpr bool staysInHeap(const char* field) {
  int colons = 0;
  for (; *field != '\0'; ++field) colons += *field == ':';
  return colons == 2;
}

template <std::size_t N>
constexpr std::size_t fieldCount(const char* const (&)[N]) { return N; }

// How many of `fields` are arrays ("name:type").
template <std::size_t N>
constexpr std::size_t arrayCount(const char* const (&fields)[N]) {
  std::size_t arrays = 0;
  for (const char* field : fields) arrays += elementBytes(field) != 0;
  return arrays;
}

// Doubles in a table where an array takes `slotsPerArray` of them and a number one.
template <std::size_t N>
constexpr std::size_t tableSize(const char* const (&fields)[N], std::size_t slotsPerArray) {
  return N + arrayCount(fields) * (slotsPerArray - 1);
}

// The slot of the field `name` in an input table (where every field takes one), by name, so that no
// code counts positions; fieldCount(fields) when there is none.
template <std::size_t N>
constexpr std::size_t slotOf(const char* const (&fields)[N], const char* name) {
  for (std::size_t i = 0; i < N; ++i) {
    const char *a = fields[i], *b = name;
    while (*a != '\0' && *a == *b) ++a, ++b;
    if (*a == *b) return i;
  }
  return N;
}

inline constexpr std::size_t kInputArrays = arrayCount(kInputFields);  // they come first
inline constexpr std::size_t kInputTableSize = tableSize(kInputFields, 1);
inline constexpr std::size_t kOutputTableSize = tableSize(kOutputFields, 2);
inline constexpr std::size_t kDerivedInputTableSize = tableSize(kDerivedInputFields, 1);
inline constexpr std::size_t kDerivedOutputTableSize = tableSize(kDerivedOutputFields, 2);

}  // namespace ruppert_wasm
