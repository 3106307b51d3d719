#include "backends/gl/EglDevices.h"

#include "backends/DeviceChoice.h"
#include "backends/gl/EglLibrary.h"

namespace shaderbed::gl {
namespace {

std::string device_string(const EglLibrary& egl, EGLDeviceEXT device, EGLint name) {
  const char* text = egl.query_device_string(device, name);
  return text ? text : "";
}

// A name a person recognises: EGL_EXT_device_query_name's renderer (newer drivers), the
// DRM render node or card, or Mesa's software device.
std::string device_name(const EglLibrary& egl, EGLDeviceEXT device, const std::string& extensions) {
  if (has_egl_extension(extensions, "EGL_EXT_device_query_name"))
    if (std::string renderer = device_string(egl, device, EGL_RENDERER_EXT); !renderer.empty()) return renderer;
  std::string node;
  if (has_egl_extension(extensions, "EGL_EXT_device_drm_render_node"))
    node = device_string(egl, device, EGL_DRM_RENDER_NODE_FILE_EXT);
  if (node.empty() && has_egl_extension(extensions, "EGL_EXT_device_drm"))
    node = device_string(egl, device, EGL_DRM_DEVICE_FILE_EXT);
  if (!node.empty()) return node;
  if (has_egl_extension(extensions, "EGL_MESA_device_software")) return "software (Mesa llvmpipe)";
  return "unnamed";
}

}  // namespace

Result<std::vector<EglDeviceInfo>> list_egl_devices() {
  const EglLibrary& egl = egl_library();
  if (!egl.error.empty()) return fail(ErrorStage::gl, egl.error);
  if (!egl.query_devices || !egl.query_device_string ||
      !has_egl_extension(egl.client_extensions, "EGL_EXT_device_enumeration"))
    return fail(ErrorStage::gl, "this libEGL cannot enumerate devices (no EGL_EXT_device_enumeration)");
  EGLint count = 0;
  if (!egl.query_devices(0, nullptr, &count))
    return fail(ErrorStage::gl, "eglQueryDevicesEXT failed: " + egl_error_text(egl));
  std::vector<EGLDeviceEXT> devices(size_t(count > 0 ? count : 0));
  if (count > 0 && !egl.query_devices(count, devices.data(), &count))
    return fail(ErrorStage::gl, "eglQueryDevicesEXT failed: " + egl_error_text(egl));
  devices.resize(size_t(count));
  std::vector<EglDeviceInfo> out;
  for (size_t i = 0; i < devices.size(); ++i) {
    const std::string extensions = device_string(egl, devices[i], EGL_EXTENSIONS);
    out.push_back({i, device_name(egl, devices[i], extensions), extensions, devices[i]});
  }
  return out;
}

Result<EglDeviceInfo> find_egl_device(const std::string& choice) {
  auto devices = list_egl_devices();
  if (!devices) return std::unexpected(devices.error());
  std::vector<std::string> names;
  for (const EglDeviceInfo& d : *devices) names.push_back(d.name);
  auto index = match_device(names, choice, "--gl-device", "EGL devices");
  if (!index) return std::unexpected(index.error());
  return (*devices)[*index];
}

}  // namespace shaderbed::gl
