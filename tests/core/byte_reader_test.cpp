// ByteReader and ByteWriter: little-endian whatever the host, every read bounds-checked, errors
// that name the source, the byte offset and what was being read.
#include "core/byte_reader.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "core/byte_writer.h"
#include "core/error.h"

namespace voltree {
namespace {

std::string Bytes(std::initializer_list<int> values) {
  std::string bytes;
  for (int v : values) bytes.push_back(char(v));
  return bytes;
}

template <typename Read>
std::string ErrorOf(Read read) {
  try {
    read();
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(ByteReader, ReadsLittleEndian) {
  const std::string bytes = Bytes({0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0xfe, 0xff, 0xff, 0xff,
                                   0x00, 0x00, 0x80, 0x3f, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xf0, 0xbf});
  ByteReader in(bytes, "values.bin");
  EXPECT_EQ(in.U64("a u64"), 0x0807060504030201ull);
  EXPECT_EQ(in.I32("an i32"), -2);
  EXPECT_EQ(in.F32("an f32"), 1.0f);
  EXPECT_EQ(in.F64("an f64"), -1.0);
  EXPECT_EQ(in.remaining(), 0u);

  ByteReader small(bytes, "values.bin");
  EXPECT_EQ(small.U8("a u8"), 0x01);
  EXPECT_EQ(small.U16("a u16"), 0x0302);
  EXPECT_EQ(small.U32("a u32"), 0x07060504u);
  EXPECT_EQ(small.offset(), 7u);
}

TEST(ByteReader, ReadsLittleEndianArrays) {
  const std::string bytes = Bytes({0x34, 0x12, 0x78, 0x56, 0x00, 0x00, 0x00, 0x40});
  ByteReader in(bytes, "values.bin");
  std::array<uint16_t, 2> pair{};
  in.Array<uint16_t>(pair, "a pair");
  EXPECT_EQ(pair[0], 0x1234);
  EXPECT_EQ(pair[1], 0x5678);
  std::vector<float> one(1);
  in.Array<float>(one, "a float");
  EXPECT_EQ(one[0], 2.0f);
  EXPECT_EQ(in.remaining(), 0u);
}

TEST(ByteReader, TruncationNamesSourceOffsetAndWhat) {
  const std::string bytes(6, '\0');
  ByteReader in(bytes, "cameras.bin");
  in.U32("the count");
  EXPECT_EQ(ErrorOf([&] { in.U32("the width"); }),
            "cameras.bin: truncated at byte 4: the width needs 4 bytes, only 2 left");
  EXPECT_EQ(in.offset(), 4u);  // a failed read consumes nothing
  EXPECT_EQ(ErrorOf([&] { in.Take(3, "the tag"); }),
            "cameras.bin: truncated at byte 4: the tag needs 3 bytes, only 2 left");
  std::array<uint32_t, 3> three{};
  ByteReader array(bytes, "cameras.bin");
  EXPECT_EQ(ErrorOf([&] { array.Array<uint32_t>(three, "the ids"); }),
            "cameras.bin: truncated at byte 0: the ids needs 3 x 4 bytes, only 6 left");
}

TEST(ByteReader, NulTerminatedText) {
  const std::string bytes("oak.png\0pin", 11);
  ByteReader in(bytes, "images.bin");
  EXPECT_EQ(in.UntilNul("an image name"), "oak.png");
  EXPECT_EQ(in.offset(), 8u);
  EXPECT_EQ(ErrorOf([&] { in.UntilNul("an image name"); }),
            "images.bin: truncated at byte 8: an image name has no terminating NUL");
}

TEST(ByteReader, FailuresNameTheSourceAndTheByte) {
  ByteReader in("", "tree.vtree: chunk CELL at byte 40");
  EXPECT_EQ(ErrorOf([&] { in.Fail("cell count ", 3, " too large"); }),
            "tree.vtree: chunk CELL at byte 40: cell count 3 too large");
  EXPECT_EQ(ErrorOf([&] { in.FailAt(12, "camera ", 2, " is odd"); }),
            "tree.vtree: chunk CELL at byte 40: byte 12: camera 2 is odd");
}

TEST(ByteWriter, WritesLittleEndianThatTheReaderReadsBack) {
  ByteWriter out;
  out.Le<uint32_t>(0x04030201u);
  out.Le<int16_t>(-2);
  out.F32(1.0f);
  const std::array<uint16_t, 2> pair = {0x1234, 0x5678};
  out.Array<uint16_t>(pair);
  out.F64(-1.0);
  out.Bytes("end");
  EXPECT_EQ(out.bytes(), Bytes({0x01, 0x02, 0x03, 0x04, 0xfe, 0xff, 0x00, 0x00, 0x80, 0x3f, 0x34, 0x12, 0x78,
                                0x56, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xf0, 0xbf, 'e',  'n',  'd'}));

  const std::string bytes = out.Take();
  EXPECT_EQ(out.size(), 0u);
  ByteReader in(bytes, "round trip");
  EXPECT_EQ(in.U32("u32"), 0x04030201u);
  EXPECT_EQ(in.Le<int16_t>("i16"), -2);
  EXPECT_EQ(in.F32("f32"), 1.0f);
  std::array<uint16_t, 2> read{};
  in.Array<uint16_t>(read, "pair");
  EXPECT_EQ(read, pair);
  EXPECT_EQ(in.F64("f64"), -1.0);
  EXPECT_EQ(in.Take(3, "end"), "end");
}

}  // namespace
}  // namespace voltree
