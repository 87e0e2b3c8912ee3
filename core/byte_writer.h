// Appends little-endian values to a byte string, whatever the host's byte order: the writer
// behind .vtree and volume.bin, the mirror of ByteReader.
#pragma once

#include <bit>
#include <concepts>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

namespace voltree {

class ByteWriter {
 public:
  void Bytes(std::string_view bytes) { out_.append(bytes); }
  void Bytes(const void* data, size_t size) { out_.append(static_cast<const char*>(data), size); }

  template <std::integral T>
  void Le(T value) {
    using Unsigned = std::make_unsigned_t<T>;
    const auto bits = static_cast<Unsigned>(value);
    for (size_t i = 0; i < sizeof(T); ++i) out_.push_back(static_cast<char>((bits >> (8 * i)) & 0xFF));
  }
  void F32(float value) { Le(std::bit_cast<uint32_t>(value)); }
  void F64(double value) { Le(std::bit_cast<uint64_t>(value)); }

  template <typename T>
  requires std::integral<T> || std::floating_point<T>
  void Array(std::span<const T> values) {
    if constexpr (std::endian::native == std::endian::little) {
      Bytes(values.data(), values.size_bytes());
    } else {
      for (const T& value : values) {
        if constexpr (std::integral<T>)
          Le(value);
        else if constexpr (sizeof(T) == 4)
          F32(value);
        else
          F64(value);
      }
    }
  }

  const std::string& bytes() const { return out_; }
  size_t size() const { return out_.size(); }
  // The bytes written, leaving the writer empty.
  std::string Take() { return std::move(out_); }

 private:
  std::string out_;
};

}  // namespace voltree
