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
execute_process(COMMAND "${SHADER_CHECK}" ${ARGS}
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

# shader_check reports canonical paths, so the expectations resolve symlinks too. `args`: the
# shader, or a ;-list of shader_check's arguments.
function(shadowlab_expect_shader_rejected name args errorFile line message)
  file(REAL_PATH ${errorFile} realErrorFile)
  add_test(NAME shader.${name} COMMAND ${CMAKE_COMMAND}
    -DSHADER_CHECK=$<TARGET_FILE:shader_check> "-DARGS=${args}"
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

# Every variant the C++ asks for, #ifdef branches included (shader_check --variants): the lessons
# record the programs they compile (SHADOWLAB_SHADER_VARIANTS, gl/program.cpp) over their default
# view and every preset, one fixture test per lesson (label gpu: it renders; ctest -j runs them side
# by side), and shader.variants validates each (stage file, define set) at `#version 410 core` and
# fails on any name a shader's #if tests that no recorded variant of a stage including it defines.
set(variants ${PROJECT_SOURCE_DIR}/tests/data/shader_variants)
add_test(NAME shader.variants.fixture COMMAND shader_check --variants ${variants}/good.log --root ${variants}/good)
set_tests_properties(shader.variants.fixture PROPERTIES LABELS unit)
# A define set that breaks a shader: the error names the file, the line and the define set.
shadowlab_expect_shader_rejected(variants.rejects_broken "--variants;${variants}/broken.log;--root;${variants}/broken"
  ${variants}/broken/broken_variant.frag 8 "error: 'undefinedInVariant' : undeclared identifier [with defines {BROKEN}]")
# A log that never defines SOFT, which an include tests: the coverage gap is named where it is tested.
shadowlab_expect_shader_rejected(variants.rejects_coverage_gap "--variants;${variants}/gap.log;--root;${variants}/good"
  ${variants}/good/include/shadow.glsl 4 "error: SOFT is tested here")
# An allowlisted name that every variant covers is stale: the allowlist must not outlive its reason.
add_test(NAME shader.variants.rejects_stale_allow COMMAND ${CMAKE_COMMAND} -DSHADER_CHECK=$<TARGET_FILE:shader_check>
  "-DARGS=--variants;${variants}/good.log;--root;${variants}/good;--allow;TINT"
  "-DEXPECT=error: --allow TINT: no uncovered test of it is left" -P ${CMAKE_CURRENT_BINARY_DIR}/expect_shader_rejected.cmake)
set_tests_properties(shader.variants.rejects_stale_allow PROPERTIES LABELS unit)

if(NOT SHADOWLAB_UNIT_ONLY AND SHADOWLAB_LESSONS)
  # Runs that reach a variant no preset does (space-separated arguments, '|' between runs).
  set(variant_runs_08_psm "--set bias.receiver_plane=true|--set bias.receiver_plane=true --set filter=nearest")
  set(variant_runs_10_showdown "--preset csm --set measure.overlay=aliasing")  # MEASURED_FRAME
  # Names no program defines, each with the reason it may go unrecorded.
  set(variant_names_allowed
    SOFT_MAX_SAMPLES  # soft_maps.glsl's own array size (#ifndef: 64, SoftMaps::kMaxSamples), never overridden
    SOFT_MAX_TAPS     # the same for the tap arrays
    SHADOWLAB_NO_BORDER_CLAMP   # gl::Program's, where caps() has no border clamp: WebGL2 (the web tests)
    SHADOWLAB_NO_CLIP_DISTANCE  # the same without gl_ClipDistance
    SHADOWLAB_NO_DEPTH_CLAMP    # the same without GL_DEPTH_CLAMP
    CLIP_DISTANCE0              # lines_quad.vert's: the post-projective lines without a geometry shader
                                # (WebGL2: web.shaders_es_fallbacks validates that variant)
    SHADOWLAB_GLES)             # core/glsl_es's, in the browser build (shader.variants.es checks those)
  set(variant_logs "")
  foreach(lesson IN LISTS SHADOWLAB_LESSONS)
    string(REGEX REPLACE "^lesson_" "" name ${lesson})
    set(log ${CMAKE_CURRENT_BINARY_DIR}/shader_variants/${name}.log)
    # The GLSL exercises' student build (tests/grading_glsl.cmake, included before this file: the
    # modules go in name order) records the SHADOWLAB_STUDENT_* variants; without it they show as gaps.
    set(student "")
    if(TARGET glsl_${lesson})
      set(student $<TARGET_FILE:glsl_${lesson}>)
    endif()
    add_test(NAME shader.variants.record.${name} COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:${lesson}>
             -DLOG=${log} "-DEXTRA=${variant_runs_${name}}" -DSTUDENT=${student}
             -P ${CMAKE_CURRENT_SOURCE_DIR}/support/record_shader_variants.cmake)
    set_tests_properties(shader.variants.record.${name} PROPERTIES LABELS gpu FIXTURES_SETUP shader_variants)
    list(APPEND variant_logs --variants ${log})
  endforeach()
  list(TRANSFORM variant_names_allowed PREPEND "--allow;")
  add_test(NAME shader.variants COMMAND shader_check ${variant_logs} ${variant_names_allowed})
  set_tests_properties(shader.variants PROPERTIES LABELS gpu FIXTURES_REQUIRED shader_variants)
endif()
