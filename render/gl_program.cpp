#include "render/gl_program.hpp"

#include <utility>
#include <vector>

#include "core/util/error.hpp"

namespace facadeslam::render {
namespace {

GLuint compile(const GlFunctions& gl, const std::string& name, GLenum type, const char* source) {
  const GLuint shader = gl.CreateShader(type);
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length) + 1, '\0');
    gl.GetShaderInfoLog(shader, length, nullptr, log.data());
    gl.DeleteShader(shader);
    throw Error("render: the " + name + (type == GL_VERTEX_SHADER ? " vertex" : " fragment") +
                " shader does not compile: " + log.data());
  }
  return shader;
}

}  // namespace

GlProgram::GlProgram(const GlFunctions& gl, const std::string& name, const char* vertex_source,
                     const char* fragment_source)
    : gl_(&gl), name_(name) {
  const GLuint vertex = compile(gl, name, GL_VERTEX_SHADER, vertex_source);
  GLuint fragment = 0;
  try {
    fragment = compile(gl, name, GL_FRAGMENT_SHADER, fragment_source);
  } catch (...) {
    gl.DeleteShader(vertex);
    throw;
  }
  id_ = gl.CreateProgram();
  gl.AttachShader(id_, vertex);
  gl.AttachShader(id_, fragment);
  gl.LinkProgram(id_);
  gl.DeleteShader(vertex);
  gl.DeleteShader(fragment);
  GLint ok = GL_FALSE;
  gl.GetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    gl.GetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length) + 1, '\0');
    gl.GetProgramInfoLog(id_, length, nullptr, log.data());
    gl.DeleteProgram(id_);
    id_ = 0;
    throw Error("render: the " + name + " program does not link: " + log.data());
  }
}

GlProgram::~GlProgram() {
  if (id_) gl_->DeleteProgram(id_);
}

GlProgram::GlProgram(GlProgram&& other) noexcept
    : gl_(other.gl_), name_(std::move(other.name_)), id_(std::exchange(other.id_, 0)) {}

GlProgram& GlProgram::operator=(GlProgram&& other) noexcept {
  if (this != &other) {
    if (id_) gl_->DeleteProgram(id_);
    gl_ = other.gl_;
    name_ = std::move(other.name_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

GLint GlProgram::uniform(const char* name) const {
  const GLint location = gl_->GetUniformLocation(id_, name);
  if (location < 0) throw Error("render: the " + name_ + " program has no uniform '" + name + "'");
  return location;
}

}  // namespace facadeslam::render
