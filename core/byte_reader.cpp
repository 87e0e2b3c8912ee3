#include "core/byte_reader.h"

namespace voltree {

std::string_view ByteReader::UntilNul(const char* what) {
  const size_t end = bytes_.find('\0', offset_);
  if (end == std::string_view::npos) Fail("truncated at byte ", offset_, ": ", what, " has no terminating NUL");
  const std::string_view text = bytes_.substr(offset_, end - offset_);
  offset_ = end + 1;
  return text;
}

void ByteReader::Truncated(const char* what, uint64_t count, size_t size) const {
  const std::string needed = count == 1 ? Str(size, " bytes") : Str(count, " x ", size, " bytes");
  Fail("truncated at byte ", offset_, ": ", what, " needs ", needed, ", only ", remaining(), " left");
}

}  // namespace voltree
