// libFuzzer target: the JSON reader on arbitrary bytes. Every input must either be read into a Plc
// that keeps the reader's promises (plc_invariants.h) or be rejected with a ruppert::Error;
// crashes, sanitizer reports, hangs (deep nesting, long strings) and huge allocations are findings.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "plc_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const ruppert::Plc plc = ruppert::readJson(in, "fuzz.json");
    ruppert_fuzz::checkPlcInvariants(plc);
    if (plc.indexBase != 0) ruppert_fuzz::finding("JSON indices are 0-based");
  } catch (const ruppert::Error& e) {
    ruppert_fuzz::checkReaderError(e);
  }
  return 0;
}
