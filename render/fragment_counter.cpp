#include "render/fragment_counter.h"

#include <cstring>

#include "core/error.h"
#include "render/gl.h"
#include "render/gl_context.h"

namespace voltree {

bool FragmentCounter::Available() {
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major > 4 || (major == 4 && minor >= 6)) return true;
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
    if (name && std::strcmp(name, "GL_ARB_pipeline_statistics_query") == 0) return true;
  }
  return false;
}

FragmentCounter::FragmentCounter() : query_(GlQueryName::Create()) {
  CheckGl("render: making a fragment counting query");
}

void FragmentCounter::Begin() { glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, query_.id()); }

uint64_t FragmentCounter::End() {
  glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
  GLuint64 fragments = 0;
  glGetQueryObjectui64v(query_.id(), GL_QUERY_RESULT, &fragments);
  CheckGl("render: counting fragments");
  return uint64_t(fragments);
}

}  // namespace voltree
