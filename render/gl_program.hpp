#pragma once
// A linked GLSL program (vertex + fragment shader). Compile and link errors
// throw Error with the driver's log: they mean a bug in render/, not bad
// user input, but the log is what one needs to fix it. Internal to render/.
#include <string>

#include "render/gl_functions.hpp"

namespace facadeslam::render {

class GlProgram {
 public:
  GlProgram() = default;
  GlProgram(const GlFunctions& gl, const std::string& name, const char* vertex_source, const char* fragment_source);
  ~GlProgram();
  GlProgram(GlProgram&& other) noexcept;
  GlProgram& operator=(GlProgram&& other) noexcept;
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  GLuint id() const { return id_; }
  // Location of a uniform; throws Error if the program has no such active
  // uniform (a typo would otherwise silently set nothing).
  GLint uniform(const char* name) const;

 private:
  const GlFunctions* gl_ = nullptr;
  std::string name_;
  GLuint id_ = 0;
};

}  // namespace facadeslam::render
