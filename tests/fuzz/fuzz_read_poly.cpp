// libFuzzer target: Triangle .poly and .node text from arbitrary bytes.
// Every input must either be read into a Plc that keeps the reader's promises (plc_invariants.h) or
// be rejected with a ruppert::Error; crashes, sanitizer reports, hangs and huge allocations
// (a declared count of 10^12 must fail before allocating) are findings.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "plc_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // The same bytes as both formats: a .node is the first section of a .poly.
  for (bool asPoly : {true, false}) {
    std::istringstream in(text);
    try {
      const ruppert::Plc plc = asPoly ? ruppert::readPoly(in, "fuzz.poly") : ruppert::readNode(in, "fuzz.node");
      ruppert_fuzz::checkPlcInvariants(plc);
      if (!asPoly && !plc.segments.empty()) ruppert_fuzz::finding("a .node produced segments");
    } catch (const ruppert::Error& e) {
      ruppert_fuzz::checkReaderError(e);
    }
  }
  return 0;
}
