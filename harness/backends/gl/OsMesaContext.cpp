#include "backends/gl/OsMesaContext.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <array>
#include <mutex>
#include <string>

namespace shaderbed::gl {
namespace {

// libOSMesa is opened when the first GL context is made, not linked: it pulls in LLVM and
// Mesa's GL stack, which every command that never draws with GL (--help, eval, merge, a
// Vulkan-only run) would otherwise pay for at process start-up.
struct OsMesaLibrary {
  decltype(&OSMesaCreateContextAttribs) create_context_attribs = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaDestroyContext) destroy_context = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
  std::string error;   // why it could not be loaded; "" when loaded
};

const OsMesaLibrary& osmesa() {
  static OsMesaLibrary library;
  static std::once_flag once;
  std::call_once(once, [] {
    void* handle = ::dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      library.error = std::string("cannot load libOSMesa.so.8 (Debian: libosmesa6): ") + ::dlerror();
      return;
    }
    // Never dlclosed: contexts and their threads live until exit.
    const auto symbol = [&](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(::dlsym(handle, name));
      if (!fn && library.error.empty()) library.error = std::string("libOSMesa.so.8 has no ") + name;
    };
    symbol(library.create_context_attribs, "OSMesaCreateContextAttribs");
    symbol(library.make_current, "OSMesaMakeCurrent");
    symbol(library.destroy_context, "OSMesaDestroyContext");
    symbol(library.get_proc_address, "OSMesaGetProcAddress");
  });
  return library;
}

}  // namespace

// The 1x1 default framebuffer only exists because OSMesaMakeCurrent needs one; all
// drawing goes to the renderer's own FBO.
struct OsMesaContext::Handle {
  OSMesaContext context = nullptr;
  std::array<unsigned char, 4 * 4 * 4> dummy_buffer{};
  ~Handle() {
    if (context) osmesa().destroy_context(context);
  }
};

OsMesaContext::OsMesaContext(std::unique_ptr<Handle> handle) : handle_(std::move(handle)) {}
OsMesaContext::OsMesaContext(OsMesaContext&&) noexcept = default;
OsMesaContext& OsMesaContext::operator=(OsMesaContext&&) noexcept = default;
OsMesaContext::~OsMesaContext() {
  if (last_made_current() == this) last_made_current() = nullptr;
}

Result<OsMesaContext> OsMesaContext::create(int major, int minor, Profile profile) {
  const int attributes[] = {OSMESA_FORMAT,        OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,    0,
                            OSMESA_STENCIL_BITS,  0,
                            OSMESA_PROFILE,       profile == Profile::core ? OSMESA_CORE_PROFILE : OSMESA_COMPAT_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, major,
                            OSMESA_CONTEXT_MINOR_VERSION, minor,
                            0};
  if (!osmesa().error.empty()) return fail(ErrorStage::gl, osmesa().error);
  auto handle = std::make_unique<Handle>();
  handle->context = osmesa().create_context_attribs(attributes, nullptr);
  if (!handle->context)
    return fail(ErrorStage::gl, "OSMesa cannot create a " + std::to_string(major) + "." + std::to_string(minor) +
                          (profile == Profile::core ? " core" : " compatibility") +
                          "-profile context (is libOSMesa from Mesa >= 11.2 with llvmpipe installed?)");
  OsMesaContext created(std::move(handle));
  if (auto current = created.make_current(); !current) return std::unexpected(current.error());
  return created;
}

Result<void> OsMesaContext::make_current() const {
  if (!handle_ || !handle_->context) return fail(ErrorStage::gl, "the OSMesa context was moved from");
  if (!osmesa().make_current(handle_->context, handle_->dummy_buffer.data(), GL_UNSIGNED_BYTE, 4, 4))
    return fail(ErrorStage::gl, "OSMesaMakeCurrent failed");
  last_made_current() = this;
  return {};
}

GlProcLoader OsMesaContext::proc_loader() const {
  return [](const char* name) -> GlProc { return reinterpret_cast<GlProc>(osmesa().get_proc_address(name)); };
}

}  // namespace shaderbed::gl
