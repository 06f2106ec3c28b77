// Conversions between the package's JavaScript objects and the core's structs (js_objects.cpp).
#pragma once

#include <vector>

#include "binding_common.h"
#include "ruppert/ruppert.h"

namespace ruppert_wasm {

ruppert::Plc plcFromJs(const val& js);  // a PLC as wasm/input-checks.js's checkPlc() returns it
ruppert::Mesh meshFromJs(const val& js);  // a mesh as checkMesh() returns it
ruppert::Voronoi voronoiFromJs(const val& js);  // mesh.voronoi, with its indices checked
val plcToJs(const ruppert::Plc& plc);
val eventsToJs(const std::vector<ruppert::Event>& events);  // mesh.events, a structure of arrays

}  // namespace ruppert_wasm
