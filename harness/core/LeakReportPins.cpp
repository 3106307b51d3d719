#include "core/LeakReportPins.h"

#include <dlfcn.h>
#include <link.h>

#include <string>
#include <vector>

#include "core/AddressSanitizer.h"

namespace shaderbed {

void pin_library_for_leak_reports(const char* soname) {
  if constexpr (address_sanitizer_build) (void)::dlopen(soname, RTLD_NOW | RTLD_NODELETE);
}

void pin_loaded_libraries_for_leak_reports() {
  if constexpr (address_sanitizer_build) {
    // Names first, dlopen after: dlopen inside dl_iterate_phdr's callback would run under its lock.
    std::vector<std::string> loaded;
    ::dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void* names) {
          if (info->dlpi_name && *info->dlpi_name) static_cast<std::vector<std::string>*>(names)->push_back(info->dlpi_name);
          return 0;
        },
        &loaded);
    for (const std::string& name : loaded) (void)::dlopen(name.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
  }
}

}  // namespace shaderbed
