#include "render/gl_context.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "render/gl.h"

namespace voltree {
namespace {

TEST(GlContext, CreatesCoreProfileWithoutDisplay) {
  GlContext context;
  EXPECT_FALSE(context.renderer().empty());
  EXPECT_FALSE(context.version().empty());
  // Mesa llvmpipe gives 4.5; 4.3 is the fallback the renderer accepts.
  EXPECT_TRUE(context.major() > 4 || (context.major() == 4 && context.minor() >= 3)) << context.Describe();
  GLint profile = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
  EXPECT_NE(context.Describe().find(context.renderer()), std::string::npos);
}

TEST(GlContext, TwoContextsInSequenceAndTogether) {
  { GlContext first; }
  GlContext second;
  GlContext third;
  second.MakeCurrent();
  EXPECT_FALSE(second.renderer().empty());
  third.MakeCurrent();
  CheckGl("switching contexts");
}

TEST(GlContext, RejectsAncientVersion) {
  GlContextOptions options;
  options.major = 2;
  options.minor = 1;
  EXPECT_THROW(GlContext{options}, Error);
}

TEST(GlContext, CheckGlReportsErrors) {
  GlContext context;
  glEnable(GL_INVALID_ENUM == 0 ? 1 : 0xFFFFu);  // invalid capability -> GL_INVALID_ENUM
  try {
    CheckGl("a test");
    FAIL() << "expected an Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("a test"), std::string::npos);
  }
}

}  // namespace
}  // namespace voltree
