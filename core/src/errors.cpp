// Stable names for ErrorCode. JavaScript callers branch on these strings (MeshError.code), so a
// name, once published, never changes; new codes get new names. The names are ruppert.h's
// kErrorCodeNames.
#include "ruppert/ruppert.h"

namespace ruppert {

// A value outside the enum (a cast from a bad integer) gives "UNKNOWN": a valid C string, never null.
const char* errorCodeName(ErrorCode code) { return enumName(code); }

}  // namespace ruppert
