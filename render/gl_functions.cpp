#include "render/gl_functions.hpp"

#include <GL/osmesa.h>

#include "core/util/error.hpp"

namespace facadeslam::render {

GlFunctions GlFunctions::load() {
  GlFunctions f;
#define FACADESLAM_GL_LOAD(name)                                                 \
  f.name = reinterpret_cast<decltype(f.name)>(OSMesaGetProcAddress("gl" #name)); \
  if (!f.name) throw Error("OSMesa does not provide gl" #name " (needs Mesa with OpenGL 4.5 core)");
  FACADESLAM_GL_FUNCTIONS(FACADESLAM_GL_LOAD)
#undef FACADESLAM_GL_LOAD
  return f;
}

}  // namespace facadeslam::render
