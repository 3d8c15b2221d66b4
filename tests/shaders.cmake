# Offline GLSL validation: every shader under shaders/ is expanded with the project's own include
# preprocessor (core/shader_source) and checked by glslangValidator, one ctest per shader, so a
# broken shader fails `ctest` on a machine without a GPU. Include-only files (*.glsl) are checked
# through the shaders that include them.

find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)

if(NOT TARGET shader_check)
  add_executable(shader_check ${PROJECT_SOURCE_DIR}/tools/shader_check.cpp)
  target_link_libraries(shader_check PRIVATE shadowlab_core)
  target_compile_definitions(shader_check PRIVATE SHADOWLAB_GLSLANG_VALIDATOR="${GLSLANG_VALIDATOR}")
endif()

# Compute shaders need GL 4.3, beyond the course's 4.1 core, so .comp is deliberately not globbed.
file(GLOB_RECURSE SHADOWLAB_SHADERS CONFIGURE_DEPENDS RELATIVE ${PROJECT_SOURCE_DIR}/shaders
  ${PROJECT_SOURCE_DIR}/shaders/*.vert ${PROJECT_SOURCE_DIR}/shaders/*.frag
  ${PROJECT_SOURCE_DIR}/shaders/*.geom ${PROJECT_SOURCE_DIR}/shaders/*.tesc
  ${PROJECT_SOURCE_DIR}/shaders/*.tese)
foreach(shader IN LISTS SHADOWLAB_SHADERS)
  add_test(NAME shader.${shader} COMMAND shader_check ${PROJECT_SOURCE_DIR}/shaders/${shader})
  set_tests_properties(shader.${shader} PROPERTIES LABELS unit)
endforeach()

# The pipeline's own fixtures: valid samples that exercise nested and repeated includes.
set(SHADER_FIXTURES ${CMAKE_CURRENT_SOURCE_DIR}/data/shaders)
foreach(sample IN ITEMS sample.vert sample.frag)
  add_test(NAME shader.fixture.${sample} COMMAND shader_check ${SHADER_FIXTURES}/${sample})
  set_tests_properties(shader.fixture.${sample} PROPERTIES LABELS unit)
endforeach()

# Negative tests. Each passes only if shader_check exits with exactly 1 (a crash, which CMake
# reports as a non-integer result or a different code, fails) AND its output names the original
# file and line of the error: WILL_FAIL alone would also pass on a crash, and
# PASS_REGULAR_EXPRESSION alone ignores the exit code.
file(CONFIGURE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/expect_shader_rejected.cmake CONTENT [[
execute_process(COMMAND "${SHADER_CHECK}" "${SHADER}"
  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(NOT result STREQUAL "1")
  message(FATAL_ERROR "expected shader_check to exit with 1, got '${result}'; output:\n${all}")
endif()
string(FIND "${all}" "${EXPECT}" found)
if(found EQUAL -1)
  message(FATAL_ERROR "expected the output to contain '${EXPECT}'; output:\n${all}")
endif()
message(STATUS "rejected as expected: ${EXPECT}")
]] @ONLY)

# shader_check reports canonical paths, so the expectations resolve symlinks too.
function(shadowlab_expect_shader_rejected name shader errorFile line message)
  file(REAL_PATH ${errorFile} realErrorFile)
  add_test(NAME shader.${name} COMMAND ${CMAKE_COMMAND}
    -DSHADER_CHECK=$<TARGET_FILE:shader_check> -DSHADER=${shader}
    "-DEXPECT=${realErrorFile}:${line}: ${message}"
    -P ${CMAKE_CURRENT_BINARY_DIR}/expect_shader_rejected.cmake)
  set_tests_properties(shader.${name} PROPERTIES LABELS unit)
endfunction()

# broken.frag line 8 uses an undeclared name after an include: the line is only right if the
# #line after the include boundary is.
shadowlab_expect_shader_rejected(rejects_broken ${SHADER_FIXTURES}/broken.frag
  ${SHADER_FIXTURES}/broken.frag 8 "error: 'undeclaredColor' : undeclared identifier")
# An error inside an included file is reported against that file (source-string mapping).
shadowlab_expect_shader_rejected(rejects_broken_include ${SHADER_FIXTURES}/broken_include.frag
  ${SHADER_FIXTURES}/include/broken_helper.glsl 3 "error: 'missingValue' : undeclared identifier")
# Only `#version 410 core` as the first line is accepted; this one is valid GLSL 3.30.
shadowlab_expect_shader_rejected(rejects_wrong_version ${SHADER_FIXTURES}/wrong_version.frag
  ${SHADER_FIXTURES}/wrong_version.frag 1 "error: the first line must be '#version 410 core'")
