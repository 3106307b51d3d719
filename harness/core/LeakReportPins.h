#pragma once
// Sanitizer builds only: LeakSanitizer checks at exit, after GLFW, GLX and the Vulkan
// loader have dlclosed the drivers they loaded. A closed driver's globals are unmapped, so
// a block only they pointed to is reported as a leak from an "<unknown module>", and a
// closed driver's thread-local block left LeakSanitizer's tracer reading a stale range
// ("Tracer caught signal 11"). Pinned (RTLD_NODELETE), a driver stays mapped until exit.
// Both are no-ops in other builds.

namespace shaderbed {

// Keeps `soname` loaded until exit, loading it now if it is not loaded yet.
void pin_library_for_leak_reports(const char* soname);

// Keeps every shared object loaded now (e.g. the DRI driver behind a new GL window) until exit.
void pin_loaded_libraries_for_leak_reports();

}  // namespace shaderbed
