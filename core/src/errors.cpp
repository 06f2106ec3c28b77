// Stable names for ErrorCode. JavaScript callers branch on these strings (MeshError.code), so a
// name, once published, never changes; new codes get new names.
#include "ruppert/ruppert.h"

namespace ruppert {

const char* errorCodeName(ErrorCode code) {
  switch (code) {
    case ErrorCode::EmptyInput: return "EMPTY_INPUT";
    case ErrorCode::NonFiniteCoordinate: return "NON_FINITE_COORDINATE";
    case ErrorCode::CoordinateRange: return "COORDINATE_RANGE";
    case ErrorCode::IndexOutOfRange: return "INDEX_OUT_OF_RANGE";
    case ErrorCode::DegenerateInput: return "DEGENERATE_INPUT";
    case ErrorCode::HoleOnSegment: return "HOLE_ON_SEGMENT";
    case ErrorCode::InvalidRegion: return "INVALID_REGION";
    case ErrorCode::InvalidOption: return "INVALID_OPTION";
    case ErrorCode::ParseError: return "PARSE_ERROR";
    case ErrorCode::IoError: return "IO_ERROR";
    case ErrorCode::TooLarge: return "TOO_LARGE";
    case ErrorCode::Cancelled: return "CANCELLED";
    case ErrorCode::MalformedInput: return "MALFORMED_INPUT";
    case ErrorCode::EmptyDomain: return "EMPTY_DOMAIN";
    case ErrorCode::Internal: return "INTERNAL";
  }
  // A value outside the enum (a cast from a bad integer): still a valid C string, never null.
  return "UNKNOWN";
}

}  // namespace ruppert
