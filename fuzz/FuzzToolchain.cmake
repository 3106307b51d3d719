# Included by the top-level CMakeLists.txt when SHADERBED_FUZZ is on, before any target:
# libFuzzer needs clang, and the code under test needs coverage instrumentation.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "SHADERBED_FUZZ needs clang (scripts/fuzz configures clang-14)")
endif()
add_compile_options(-fsanitize=fuzzer-no-link)
# clang 14 lacks what libstdc++ 12 needs to enable std::expected: a stand-in (compat/expected).
include_directories(BEFORE SYSTEM ${CMAKE_CURRENT_LIST_DIR}/compat)
# clang's -Wall says more than GCC's about code that GCC builds warning-free; this build is
# judged by its sanitizers, not its warnings.
add_compile_options(-Wno-unknown-warning-option -Wno-unused-private-field -Wno-unused-lambda-capture -Wno-deprecated-declarations)
