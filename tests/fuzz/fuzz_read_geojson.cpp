// libFuzzer target: the GeoJSON reader on arbitrary bytes. Every input must either be
// read into a Plc that keeps the reader's promises (plc_invariants.h) or be rejected with a
// ruppert::Error; crashes, sanitizer reports, hangs (deep nesting, many rings: the reader meshes a
// CDT of the rings to place hole seeds) and huge allocations are findings.
#include <cstddef>
#include <cstdint>
#include <string>

#include "plc_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const ruppert::Plc plc =
        ruppert::parseGeoJson(std::string(reinterpret_cast<const char*>(data), size), "fuzz.geojson");
    ruppert_fuzz::checkPlcInvariants(plc);
    if (plc.indexBase != 0) ruppert_fuzz::finding("GeoJSON indices are 0-based");
  } catch (const ruppert::Error& e) {
    ruppert_fuzz::checkReaderError(e);
  }
  return 0;
}
