// RUPPERT_COLD_BEGIN / RUPPERT_COLD_END around a file's own functions: readers and writers run once
// per file, not per insertion, so under clang (the WebAssembly build) they are compiled for size
// (minsize), which keeps the wasm module small. Only functions declared between the two markers are
// affected: templates from headers included before them (vector growth, sorting, shared with the hot
// refinement code) keep the build's optimization, so no slow copy of them can be linked into it.
#pragma once

#if defined(__clang__)
#define RUPPERT_COLD_BEGIN _Pragma("clang attribute push (__attribute__((minsize)), apply_to = function)")
#define RUPPERT_COLD_END _Pragma("clang attribute pop")
#else
#define RUPPERT_COLD_BEGIN
#define RUPPERT_COLD_END
#endif
