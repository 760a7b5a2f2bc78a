#include "render/osmesa_context.hpp"

#include <GL/osmesa.h>

#include "core/util/error.hpp"

namespace facadeslam::render {
namespace {

constexpr int kTokenSize = 16;

}  // namespace

OsMesaContext::OsMesaContext() : token_buffer_(kTokenSize * kTokenSize * 4, 0) {
  // No depth/stencil on OSMesa's own buffer: the framebuffer objects carry
  // their own depth attachment.
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_ACCUM_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            4,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            5,
                            0};
  context_ = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!context_)
    throw Error("OSMesa: cannot create an OpenGL 4.5 core context (is libosmesa6 from Mesa >= 20 installed?)");
  make_current();
  try {
    gl_ = GlFunctions::load();
  } catch (...) {
    OSMesaDestroyContext(context_);
    throw;
  }
}

OsMesaContext::~OsMesaContext() {
  if (context_) OSMesaDestroyContext(context_);
}

void OsMesaContext::make_current() {
  if (!OSMesaMakeCurrent(context_, token_buffer_.data(), GL_UNSIGNED_BYTE, kTokenSize, kTokenSize))
    throw Error("OSMesa: cannot make the rendering context current");
}

std::string OsMesaContext::renderer() {
  make_current();
  const GLubyte* text = gl_.GetString(GL_RENDERER);
  return text ? reinterpret_cast<const char*>(text) : std::string();
}

std::string OsMesaContext::version() {
  make_current();
  const GLubyte* text = gl_.GetString(GL_VERSION);
  return text ? reinterpret_cast<const char*>(text) : std::string();
}

}  // namespace facadeslam::render
