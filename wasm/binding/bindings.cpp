// The embind layer between the npm package's JavaScript (wasm/mesher.js, wasm/heap-call.js) and the
// ruppert core. Only conversions live in it; every check of user input that JavaScript can make
// happens in wasm/input-checks.js before anything crosses into wasm, and every mesh rule lives in
// the core. Its files, by concern:
//   binding_common.h/.cpp   copies in and out, and the one try/catch (the contract with JavaScript)
//   js_objects.h/.cpp       JavaScript objects <-> the core's Plc, Mesh, Voronoi and events
//   heap_layout.h           the layout of triangulate()'s tables through the heap
//   heap_triangulate.cpp    triangulate() through those tables (Module._rp_*, the hot path)
//   text_formats.cpp        the readers and writers of text formats (ruppert-formats.wasm)
//   geojson_reader.cpp      the GeoJSON reader, which needs the mesher (ruppert.wasm)
//   cli_texts.h/.cpp        the native CLI's parser and texts, for wasm/cli.js (ruppert-cli.wasm)
//   describe.cpp            the enums' names and the tables' layout, exported to JavaScript
//   free_list_allocator.cpp operator new and delete over free lists of small blocks
//   bindings.cpp            this file: test hooks
// Each file registers its own embind functions; wasm/CMakeLists.txt says which module links which.
#include <emscripten/bind.h>
#include <malloc.h>

#include <cstdlib>

namespace {

// Bytes currently allocated by malloc: lets tests prove that repeated calls do not leak.
double allocatedBytes() { return static_cast<double>(mallinfo().uordblks); }

// Lets the package tests prove that a wasm abort does not leave the module unusable.
void abortForTesting() { std::abort(); }

}  // namespace

EMSCRIPTEN_BINDINGS(ruppert) {
  emscripten::function("allocatedBytes", &allocatedBytes);
  emscripten::function("abortForTesting", &abortForTesting);
}
