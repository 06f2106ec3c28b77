// The one try/catch of the embind layer (see binding_common.h).
#include "binding_common.h"

#include <exception>
#include <new>

#include "ruppert/ruppert.h"

namespace ruppert_wasm {

val failureToJs(const Failure& failed) {
  val out = val::object();
  out.set("errorCode", std::string(failed.code));
  out.set("errorMessage", failed.message);
  if (failed.reset) out.set("reset", true);
  return out;
}

bool attemptCall(void (*body)(void*), void* context, Failure& failed) {
  try {
    body(context);
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

}  // namespace ruppert_wasm
