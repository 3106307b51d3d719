# shaderbed_add_cases(): a project's own case files as ctest tests (docs/install.md).
#
#   shaderbed_add_cases(<name> CASES_DIR <dir>
#                       [BACKENDS vulkan gl]          default: both
#                       [LANGUAGES glsl hlsl cg]      default: all three
#                       [SIZE <n>]                    default: 64
#                       [SHAPES sphere cube ...]      default: every shape
#                       [EXPECTATIONS <file>]         known failures (`run --expectations`)
#                       [ARGS <more run arguments>...])
#
# (`NAME <name>` is accepted for the name too, as add_test() spells it.)
# One test per case file (<dir>/*.toml) x backend x language, named
# <name>.<case>.<backend>.<language> and labelled shaderbed, the backend and the language,
# so `ctest -L vulkan -L glsl` selects them. Each runs
#   shaderbed run --cases-dir <dir> --case <case> --backend <b> --lang <l> --size <n> --repeat 0 -q
# and passes when every cell it draws passes. A case gets a test only for the languages it
# has shaders in: a line `glsl = ...`, `hlsl = ...` or `cg = ...` of its file (its variants'
# shader pairs), read at configure time, so a GLSL-only case never makes a failing HLSL test.
# The folder is globbed with CONFIGURE_DEPENDS: a new case file is picked up by the next build.

# OUT = GIVEN, or every one of ALLOWED when none is given; a value not in ALLOWED is a
# configure error naming WHAT ("backend", "language").
function(_shaderbed_choose out given allowed what name)
  set(chosen ${allowed})
  if(given)
    set(chosen ${given})
  endif()
  foreach(value IN LISTS chosen)
    if(NOT value IN_LIST allowed)
      string(REPLACE ";" ", " expected "${allowed}")
      message(FATAL_ERROR "shaderbed_add_cases(${name}): unknown ${what} '${value}' (expected one of ${expected})")
    endif()
  endforeach()
  set(${out} ${chosen} PARENT_SCOPE)
endfunction()

function(shaderbed_add_cases)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "NAME;CASES_DIR;SIZE;EXPECTATIONS"
                        "BACKENDS;LANGUAGES;SHAPES;ARGS")
  set(name "${arg_NAME}")
  if(NOT name AND arg_UNPARSED_ARGUMENTS)
    list(POP_FRONT arg_UNPARSED_ARGUMENTS name)
  endif()
  if(NOT name)
    message(FATAL_ERROR "shaderbed_add_cases: give a name: shaderbed_add_cases(<name> CASES_DIR <dir> ...)")
  endif()
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "shaderbed_add_cases(${name}): unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_CASES_DIR)
    message(FATAL_ERROR "shaderbed_add_cases(${name}): CASES_DIR <folder of case files> is required")
  endif()
  if(NOT TARGET shaderbed::shaderbed)
    message(FATAL_ERROR "shaderbed_add_cases(${name}): call find_package(shaderbed) first")
  endif()
  cmake_path(ABSOLUTE_PATH arg_CASES_DIR BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE OUTPUT_VARIABLE cases_dir)
  if(NOT IS_DIRECTORY "${cases_dir}")
    message(FATAL_ERROR "shaderbed_add_cases(${name}): CASES_DIR '${cases_dir}' is not a folder")
  endif()

  _shaderbed_choose(backends "${arg_BACKENDS}" "vulkan;gl" backend "${name}")
  _shaderbed_choose(languages "${arg_LANGUAGES}" "glsl;hlsl;cg" language "${name}")
  set(size 64)
  if(arg_SIZE)
    set(size ${arg_SIZE})
  endif()
  if(NOT size MATCHES "^[1-9][0-9]*$")
    message(FATAL_ERROR "shaderbed_add_cases(${name}): SIZE '${size}' is not a whole number of pixels")
  endif()

  set(common --size ${size} --repeat 0 -q)
  if(arg_SHAPES)
    list(JOIN arg_SHAPES "," shapes)
    list(APPEND common --shape ${shapes})
  endif()
  if(arg_EXPECTATIONS)
    cmake_path(ABSOLUTE_PATH arg_EXPECTATIONS BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE
               OUTPUT_VARIABLE expectations)
    list(APPEND common --expectations "${expectations}")
  endif()

  file(GLOB case_files CONFIGURE_DEPENDS "${cases_dir}/*.toml")
  if(NOT case_files)
    message(WARNING "shaderbed_add_cases(${name}): no case files (*.toml) in '${cases_dir}'")
  endif()
  foreach(case_file IN LISTS case_files)
    cmake_path(GET case_file STEM case)
    # The languages the case has shaders in: its `<language> = { vertex = ..., ... }` lines.
    file(STRINGS "${case_file}" shader_lines REGEX "^[ \t]*(glsl|hlsl|cg)[ \t]*=")
    set(case_languages)
    foreach(line IN LISTS shader_lines)
      string(REGEX MATCH "(glsl|hlsl|cg)" language "${line}")
      list(APPEND case_languages ${language})
    endforeach()
    set(registered 0)
    foreach(backend IN LISTS backends)
      foreach(language IN LISTS languages)
        if(NOT language IN_LIST case_languages)
          continue()
        endif()
        set(test ${name}.${case}.${backend}.${language})
        # Each test its own --out, so tests run in parallel (ctest -j) keep their images apart.
        add_test(NAME ${test}
                 COMMAND shaderbed::shaderbed run --cases-dir "${cases_dir}" --case ${case} --backend ${backend}
                         --lang ${language} ${common} --out "${CMAKE_CURRENT_BINARY_DIR}/shaderbed/${test}" ${arg_ARGS})
        set_tests_properties(${test} PROPERTIES LABELS "shaderbed;${backend};${language}")
        math(EXPR registered "${registered} + 1")
      endforeach()
    endforeach()
    if(registered EQUAL 0)
      list(JOIN languages ", " wanted)
      message(STATUS "shaderbed_add_cases(${name}): ${case} has no shaders in ${wanted}: no test")
    endif()
  endforeach()
endfunction()
