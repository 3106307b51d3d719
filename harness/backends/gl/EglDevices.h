#pragma once
// The EGL devices (EGL_EXT_device_enumeration) as `shaderbed devices` lists them and
// --gl-device names them: a GPU's DRM node, or Mesa's software device (llvmpipe).
#include <string>
#include <vector>

#include "core/Error.h"

namespace shaderbed::gl {

struct EglDeviceInfo {
  size_t index = 0;     // what --gl-device takes, in eglQueryDevicesEXT's order
  std::string name;     // the renderer name when the driver says it, else its DRM node, else "software"
  std::string extensions;   // the device's own extensions (EGL_MESA_device_software, ...)
  void* handle = nullptr;   // the EGLDeviceEXT
};

// Every device libEGL enumerates; an error when libEGL or the extension is missing.
Result<std::vector<EglDeviceInfo>> list_egl_devices();

// The device a --gl-device choice names (its index, or a part of its name only it has); an
// error listing the devices there are otherwise.
Result<EglDeviceInfo> find_egl_device(const std::string& choice);

}  // namespace shaderbed::gl
