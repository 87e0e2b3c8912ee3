// Reads little-endian values from bytes in memory, whatever the host's byte order: the one reader
// behind .vtree, volume.bin and COLMAP's binary models. Every read is bounds-checked, and every
// error names the source, the byte offset and what was being read, so that a damaged file is an
// Error the user can act on, never a crash or a huge allocation.
#pragma once

#include <bit>
#include <concepts>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "core/error.h"

namespace voltree {

class ByteReader {
 public:
  // `name` starts every error message: a file, or a file and the part of it being read.
  ByteReader(std::string_view bytes, std::string name) : bytes_(bytes), name_(std::move(name)) {}

  template <std::integral T>
  T Le(const char* what) {
    Need(sizeof(T), what);
    const T value = Decode<T>(bytes_.data() + offset_);
    offset_ += sizeof(T);
    return value;
  }
  uint8_t U8(const char* what) { return Le<uint8_t>(what); }
  uint16_t U16(const char* what) { return Le<uint16_t>(what); }
  uint32_t U32(const char* what) { return Le<uint32_t>(what); }
  uint64_t U64(const char* what) { return Le<uint64_t>(what); }
  int32_t I32(const char* what) { return Le<int32_t>(what); }
  float F32(const char* what) { return std::bit_cast<float>(U32(what)); }
  double F64(const char* what) { return std::bit_cast<double>(U64(what)); }

  // Fills `values` with as many consecutive little-endian values; the bounds are checked once,
  // before anything is read.
  template <typename T>
  requires std::integral<T> || std::floating_point<T>
  void Array(std::span<T> values, const char* what) {
    if (values.size() > remaining() / sizeof(T)) Truncated(what, values.size(), sizeof(T));
    const char* data = bytes_.data() + offset_;
    if constexpr (std::endian::native == std::endian::little) {
      if (!values.empty()) std::memcpy(values.data(), data, values.size_bytes());
    } else {
      for (size_t i = 0; i < values.size(); ++i) values[i] = Decode<T>(data + i * sizeof(T));
    }
    offset_ += values.size_bytes();
  }

  std::string_view Take(size_t size, const char* what) {
    Need(size, what);
    const std::string_view taken = bytes_.substr(offset_, size);
    offset_ += size;
    return taken;
  }
  // The bytes up to the next NUL, which is consumed and not returned.
  std::string_view UntilNul(const char* what);

  size_t offset() const { return offset_; }
  size_t remaining() const { return bytes_.size() - offset_; }
  const std::string& name() const { return name_; }

  // Throws "NAME: message".
  template <typename... Args>
  [[noreturn]] void Fail(const Args&... args) const {
    voltree::Fail(name_, ": ", args...);
  }
  // Throws "NAME: byte AT: message", for a problem found in what starts at byte `at`.
  template <typename... Args>
  [[noreturn]] void FailAt(size_t at, const Args&... args) const {
    voltree::Fail(name_, ": byte ", at, ": ", args...);
  }

 private:
  template <typename T>
  static T Decode(const char* data) {
    using Bits = std::conditional_t<
        sizeof(T) == 8, uint64_t,
        std::conditional_t<sizeof(T) == 4, uint32_t, std::conditional_t<sizeof(T) == 2, uint16_t, uint8_t>>>;
    Bits bits = 0;
    for (size_t i = 0; i < sizeof(T); ++i) bits |= Bits(Bits(uint8_t(data[i])) << (8 * i));
    return std::bit_cast<T>(bits);
  }
  void Need(size_t size, const char* what) const {
    if (size > remaining()) Truncated(what, 1, size);
  }
  [[noreturn]] void Truncated(const char* what, uint64_t count, size_t size) const;

  std::string_view bytes_;
  std::string name_;
  size_t offset_ = 0;
};

}  // namespace voltree
