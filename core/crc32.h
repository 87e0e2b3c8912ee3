// CRC-32 (IEEE 802.3, the zlib/PNG polynomial), used for the .vtree chunk checksums.
#pragma once

#include <cstddef>
#include <cstdint>

namespace voltree {

// Continues a running CRC: Crc32(b, Crc32(a)) == Crc32(a + b). Start with crc = 0.
uint32_t Crc32(const void* data, size_t size, uint32_t crc = 0);

}  // namespace voltree
