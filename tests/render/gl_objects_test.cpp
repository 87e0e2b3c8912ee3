// The owners of OpenGL names: each name is deleted exactly once, moves hand it over, buffers hold
// what was uploaded (padded with zeros) and the stream buffer grows by doubling, never shrinking.
#include "render/gl_objects.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "render/gl_context.h"

namespace voltree {
namespace {

std::vector<uint32_t> ReadBuffer(GLuint id, size_t count) {
  std::vector<uint32_t> values(count);
  glGetNamedBufferSubData(id, 0, GLsizeiptr(count * sizeof(uint32_t)), values.data());
  return values;
}

TEST(GlObjects, NamesAreDeletedOnceAndHandedOverByMoves) {
  GlContext context;
  GLuint id = 0;
  {
    GlBufferName first = GlBufferName::Create();
    id = first.id();
    ASSERT_NE(id, 0u);
    GlBufferName second = std::move(first);
    EXPECT_EQ(first.id(), 0u);
    EXPECT_EQ(second.id(), id);
    EXPECT_TRUE(glIsBuffer(id));
  }
  EXPECT_FALSE(glIsBuffer(id));
}

TEST(GlObjects, QueryNamesAreDeletedByTheirOwner) {
  GlContext context;
  GLuint id = 0;
  {
    const GlQueryName query = GlQueryName::Create();
    id = query.id();
    ASSERT_NE(id, 0u);
    glBeginQuery(GL_SAMPLES_PASSED, id);  // a generated name becomes a query object when first begun
    glEndQuery(GL_SAMPLES_PASSED);
    EXPECT_TRUE(glIsQuery(id));
  }
  EXPECT_FALSE(glIsQuery(id));
}

TEST(GlObjects, BufferHoldsTheDataPaddedWithZeros) {
  GlContext context;
  const std::array<uint32_t, 2> data = {7, 9};
  const GlBuffer buffer(data.data(), sizeof(data), 16);
  EXPECT_EQ(buffer.bytes(), 16u);
  EXPECT_EQ(ReadBuffer(buffer.id(), 4), (std::vector<uint32_t>{7, 9, 0, 0}));
  EXPECT_EQ(GlBuffer(nullptr, 0).bytes(), 1u);
}

TEST(GlObjects, StreamBufferGrowsByDoublingAndKeepsItsSize) {
  GlContext context;
  GlStreamBuffer stream;
  EXPECT_EQ(stream.capacity(), 0u);
  const std::vector<uint32_t> frame = {1, 2, 3, 4, 5, 6};
  stream.Upload(frame.data(), 8);
  EXPECT_EQ(stream.capacity(), 8u);
  stream.Upload(frame.data(), 12);
  EXPECT_EQ(stream.capacity(), 16u);
  stream.Upload(frame.data(), 24);
  EXPECT_EQ(stream.capacity(), 32u);
  stream.Upload(frame.data(), 4);
  EXPECT_EQ(stream.capacity(), 32u);
  EXPECT_EQ(ReadBuffer(stream.id(), 6), frame);  // the last upload replaced only its first 4 bytes
}

TEST(GlObjects, StreamBufferDoublesNoFurtherThanItsOwnerSaysAFrameNeeds) {
  GlContext context;
  GlStreamBuffer stream(20);
  const std::vector<uint32_t> frame = {1, 2, 3, 4, 5, 6};
  stream.Upload(frame.data(), 8);
  stream.Upload(frame.data(), 12);
  EXPECT_EQ(stream.capacity(), 16u);
  stream.Upload(frame.data(), 18);
  EXPECT_EQ(stream.capacity(), 20u);  // the most, not 32
  stream.Upload(frame.data(), 24);    // a frame beyond the most still fits
  EXPECT_EQ(stream.capacity(), 24u);
  EXPECT_EQ(ReadBuffer(stream.id(), 6), frame);
}

}  // namespace
}  // namespace voltree
