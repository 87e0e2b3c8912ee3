// Counts fragment shader invocations of the draws between Begin and End, with
// GL_ARB_pipeline_statistics_query (core in OpenGL 4.6): what a frame costs the fragment stage,
// discarded fragments included. Where the driver lacks it, Available() is false and nothing is
// counted; callers say "not available" rather than report a zero.
#pragma once

#include <cstdint>

#include "render/gl_objects.h"

namespace voltree {

class FragmentCounter {
 public:
  // Needs a current GL context.
  static bool Available();

  FragmentCounter();

  void Begin();
  // Ends the query and waits for its result.
  uint64_t End();

 private:
  GlQueryName query_;
};

}  // namespace voltree
