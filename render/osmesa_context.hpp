#pragma once
// An OSMesa OpenGL 4.5 core-profile context (Mesa's llvmpipe on a machine
// without a GPU). Rendering goes to framebuffer objects; OSMesa's own colour
// buffer is a token 16x16 one that is never read.
//
// A context is current on one thread at a time: make_current() before any GL
// call, from the thread that renders. Internal to render/.
#include <cstdint>
#include <string>
#include <vector>

#include "render/gl_functions.hpp"

struct osmesa_context;

namespace facadeslam::render {

class OsMesaContext {
 public:
  // Throws Error when OSMesa cannot create a 4.5 core context or lacks an
  // entry point the renderer needs.
  OsMesaContext();
  ~OsMesaContext();
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  void make_current();
  const GlFunctions& gl() const { return gl_; }

  // GL_RENDERER / GL_VERSION strings ("llvmpipe (LLVM 15.0.6, 256 bits)",
  // "4.5 (Core Profile) Mesa 22.3.6"); empty if GL returned NULL.
  std::string renderer();
  std::string version();

 private:
  osmesa_context* context_ = nullptr;
  std::vector<std::uint8_t> token_buffer_;
  GlFunctions gl_;
};

}  // namespace facadeslam::render
