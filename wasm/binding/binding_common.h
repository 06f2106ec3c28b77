// What every file of the embind layer shares: copies between typed arrays and vectors, and the one
// way a binding reports failure.
//
// Contract with the JavaScript side (wasm/mesher.js):
//   * Inputs arrive already checked and converted (wasm/input-checks.js): typed arrays of the exact
//     element type, numbers, booleans.
//   * No C++ exception ever escapes a binding. Emscripten 3.1.6 would hand JavaScript a bare number
//     for it, and skipping our catch would also skip the destructors (a leak per call). Instead
//     every entry point returns a plain object; on failure it is
//     { errorCode: "INDEX_OUT_OF_RANGE", errorMessage: "...", reset?: true } and mesher.js turns it
//     into a MeshError.
//   * Results are copies (TypedArray.prototype.slice of a view), never views into the heap, which
//     would go stale the moment the heap grows.
#pragma once

#include <emscripten/val.h>

#include <string>
#include <type_traits>
#include <vector>

namespace ruppert_wasm {

using emscripten::val;

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

// How a call failed: an ErrorCode name (or CALLBACK_FAILED, TOO_LARGE, INTERNAL), the message, and
// whether JavaScript should start a fresh instance.
struct Failure {
  const char* code = "";
  std::string message;
  bool reset = false;
};

// { errorCode, errorMessage, reset? }
val failureToJs(const Failure& failed);

// Runs `body` and turns every way it can fail into `failed`; true if it succeeded.
bool attemptCall(void (*body)(void*), void* context, Failure& failed);

template <class Body>
bool attempt(Body&& body, Failure& failed) {
  using B = std::remove_reference_t<Body>;
  return attemptCall([](void* b) { (*static_cast<B*>(b))(); }, &body, failed);
}

// Runs `body` and turns every way it can fail into a failure object.
template <class Body>
val guarded(Body&& body) {
  val out = val::undefined();
  Failure failed;
  if (attempt([&] { out = body(); }, failed)) return out;
  return failureToJs(failed);
}

}  // namespace ruppert_wasm
