// Packs unsigned values of a few bits each into bytes and back, least significant bit first: bit p
// of the stream is bit p % 8 of byte p / 8. The narrow fields of .vtree (view masks, codeword
// indices) use it; web/page/voltree.js reads the same order.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace voltree {

class BitWriter {
 public:
  // Appends the low `bits` (0..32) bits of `value`.
  void Put(uint32_t value, int bits) {
    for (int i = 0; i < bits; ++i) {
      if (used_ % 8 == 0) out_.push_back('\0');
      if ((value >> i) & 1u) out_.back() = char(uint8_t(out_.back()) | (1u << (used_ % 8)));
      ++used_;
    }
  }
  // The bytes, the last one padded with zero bits.
  std::string Take() {
    used_ = 0;
    return std::move(out_);
  }

 private:
  std::string out_;
  uint64_t used_ = 0;
};

// The caller checks the stream's length before reading (BitStreamBytes); Get never reads past it.
class BitReader {
 public:
  explicit BitReader(std::string_view bytes) : bytes_(bytes) {}
  uint32_t Get(int bits) {
    uint32_t value = 0;
    for (int i = 0; i < bits && next_ / 8 < bytes_.size(); ++i, ++next_)
      value |= uint32_t((uint8_t(bytes_[next_ / 8]) >> (next_ % 8)) & 1u) << i;
    return value;
  }
  bool Bit() { return Get(1) != 0; }

 private:
  std::string_view bytes_;
  uint64_t next_ = 0;
};

// Bytes that `count` values of `bits` bits take, padded to a whole byte.
constexpr uint64_t BitStreamBytes(uint64_t count, int bits) { return (count * uint64_t(bits) + 7) / 8; }

}  // namespace voltree
