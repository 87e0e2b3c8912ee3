// libFuzzer target for the .vtree reader: any input must either parse or throw voltree::Error;
// crashes, sanitizer reports, timeouts and absurd allocations are bugs.
// The first byte chooses the read options: bit 0 verifies checksums (with them off, mutations reach
// the chunk parsers behind the CRC instead of stopping at "checksum mismatch"), bit 1 allows a
// partial (truncated) file, bit 2 loads only level 0.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.h"
#include "core/vtree.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  voltree::VtreeReadOptions options;
  options.verify_checksums = (data[0] & 1) != 0;
  options.allow_partial = (data[0] & 2) != 0;
  options.max_level = (data[0] & 4) != 0 ? 0 : -1;
  voltree::VtreeLoadReport report;
  options.report = &report;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    const voltree::VtreeAsset asset = voltree::ParseAsset(bytes, "fuzz.vtree", options);
    // A parsed asset must be internally consistent enough to serialize again.
    (void)voltree::SerializeAsset(asset);
  } catch (const voltree::Error&) {}
  return 0;
}
