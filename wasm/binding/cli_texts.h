// The native CLI's texts for a mesh (cli_texts.cpp).
#pragma once

#include "binding_common.h"
#include "ruppert/ruppert.h"

namespace ruppert_wasm {

// `report` (from wasm/cli.js) is { summary, stats, trace } booleans; returns those texts.
val reportToJs(const ruppert::Mesh& mesh, const val& report);

}  // namespace ruppert_wasm
