// The one place that includes the OpenGL headers: desktop GL with prototypes, no loader
// (libOpenGL from GLVND exports every core entry point).
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
