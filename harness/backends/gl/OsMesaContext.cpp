#include "backends/gl/OsMesaContext.h"

#include <GL/osmesa.h>

#include <array>
#include <string>

namespace shaderbed::gl {

// The 1x1 default framebuffer only exists because OSMesaMakeCurrent needs one; all
// drawing goes to the renderer's own FBO.
struct OsMesaContext::Handle {
  OSMesaContext context = nullptr;
  std::array<unsigned char, 4 * 4 * 4> dummy_buffer{};
  ~Handle() {
    if (context) OSMesaDestroyContext(context);
  }
};

OsMesaContext::OsMesaContext(std::unique_ptr<Handle> handle) : handle_(std::move(handle)) {}
OsMesaContext::OsMesaContext(OsMesaContext&&) noexcept = default;
OsMesaContext& OsMesaContext::operator=(OsMesaContext&&) noexcept = default;
OsMesaContext::~OsMesaContext() = default;

Result<OsMesaContext> OsMesaContext::create(int major, int minor) {
  const int attributes[] = {OSMESA_FORMAT,        OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,    0,
                            OSMESA_STENCIL_BITS,  0,
                            OSMESA_PROFILE,       OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, major,
                            OSMESA_CONTEXT_MINOR_VERSION, minor,
                            0};
  auto handle = std::make_unique<Handle>();
  handle->context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!handle->context)
    return fail("gl", "OSMesa cannot create a " + std::to_string(major) + "." + std::to_string(minor) +
                          " core-profile context (is libOSMesa from Mesa >= 11.2 with llvmpipe installed?)");
  OsMesaContext created(std::move(handle));
  if (auto current = created.make_current(); !current) return std::unexpected(current.error());
  return created;
}

Result<void> OsMesaContext::make_current() const {
  if (!handle_ || !handle_->context) return fail("gl", "the OSMesa context was moved from");
  if (!OSMesaMakeCurrent(handle_->context, handle_->dummy_buffer.data(), GL_UNSIGNED_BYTE, 4, 4))
    return fail("gl", "OSMesaMakeCurrent failed");
  return {};
}

GlProcLoader OsMesaContext::proc_loader() {
  return [](const char* name) -> GlProc { return reinterpret_cast<GlProc>(OSMesaGetProcAddress(name)); };
}

}  // namespace shaderbed::gl
