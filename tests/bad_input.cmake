# Bad input, end to end (issue 18): every reproducer that reaches a lesson program exits with the
# right code (2 bad input, 1 a bad or missing file) and one line naming the file:line or the
# parameter. The GL-free parsers' own cases run in the unit suite (and under ASan/UBSan there);
# their fuzz targets are tests/fuzz. Label gpu: these start lesson programs.
if(SHADOWLAB_UNIT_ONLY OR NOT TARGET lesson_01_lighting)
  return()
endif()

set(regressions ${CMAKE_CURRENT_SOURCE_DIR}/fuzz)
set(l01 $<TARGET_FILE:lesson_01_lighting>)
set(bad_input_tests)
# bad_input(NAME LESSON EXIT STDERR ARGS...): lesson_check LESSON --expect-exit EXIT --expect-stderr STDERR -- ARGS
function(bad_input name lesson code stderr)
  add_test(NAME bad_input.${name} COMMAND lesson_check ${lesson} --expect-exit ${code} --expect-stderr "${stderr}" ${ARGN})
  set_tests_properties(bad_input.${name} PROPERTIES LABELS gpu)
endfunction()

# A replayed key with the camera at its target aborted every lesson (exit 134): now exit 1, file:line.
foreach(lesson IN LISTS SHADOWLAB_LESSONS)
  string(REGEX REPLACE "^lesson_" "" name ${lesson})
  bad_input(${name}.replay_eye_at_target $<TARGET_FILE:${lesson}> 1
            "eye_at_target.path:2: the camera at (0, 0, 0) is at its target (0, 0, 0)"
            -- --headless --frames 1 --size 160x90 --replay ${regressions}/paths/regressions/eye_at_target.path)
  # Each plane in range, together degenerate (declareCamera's check): refused at start, naming both.
  bad_input(${name}.near_far_ratio $<TARGET_FILE:${lesson}> 2
            "camera.near = 0.0001, camera.far = 1e+07: far / near is 1e+11, at most 1e+06"
            -- --headless --frames 1 --size 160x90 --set camera.near=1e-4 --set camera.far=1e7)
endforeach()

# OBJ garbage (the issue's reproducers and the obj fuzz target's finding, tests/fuzz/obj/regressions)
# through --model: refused by Assimp or by the loader on what Assimp read, naming the line (exit 1).
set(obj_regressions ${regressions}/obj/regressions)
set(valid_numbers "(valid: numbers such as 2, -0.5 or 1.5e-3, a digit first)")
set(valid_range "(valid: magnitudes up to 3.4e38, exponents up to 38)")
bad_input(01_lighting.model_exponent_nan ${l01} 1 "exponent_nan.obj': line 1: '0e999999' is beyond a float's range ${valid_range}"
          -- --headless --frames 1 --size 160x90 --model ${obj_regressions}/exponent_nan.obj)
bad_input(01_lighting.model_float_overflow ${l01} 1 "float_overflow_inf.obj': line 1: '1e39' is beyond a float's range ${valid_range}"
          -- --headless --frames 1 --size 160x90 --model ${obj_regressions}/float_overflow_inf.obj)
bad_input(01_lighting.model_sign_sign ${l01} 1 "sign_sign.obj': line 1: '+-5' is not a number ${valid_numbers}"
          -- --headless --frames 1 --size 160x90 --model ${obj_regressions}/sign_sign.obj)
bad_input(01_lighting.model_leak_mesh_on_throw ${l01} 1
          "leak_mesh_on_throw.obj': line 3: a face with 1 corner (valid: f with 3 or more corners, l for lines, p for points)"
          -- --headless --frames 1 --size 160x90 --model ${obj_regressions}/leak_mesh_on_throw.obj)
# ...and the valid ones load (exit 0), stating what was generated: a trailing comment, a concave pentagon.
bad_input(01_lighting.model_trailing_comment ${l01} 0 "trailing_comment.obj': 1 meshes had no normals: generated"
          -- --headless --frames 1 --size 160x90 --model ${obj_regressions}/trailing_comment.obj)
bad_input(01_lighting.model_concave_pentagon ${l01} 0 "concave_pentagon.obj': 1 meshes had no normals: generated"
          -- --headless --frames 1 --size 160x90 --model ${obj_regressions}/concave_pentagon.obj)

# Path files: out of range, bad headers, times after '@'.
bad_input(01_lighting.replay_1e300 ${l01} 1 "coordinate_1e300.path:2: camera position (1e+300, 2, 8) is outside +-1000000"
          -- --headless --frames 1 --size 160x90 --replay ${regressions}/paths/regressions/coordinate_1e300.path)
bad_input(01_lighting.replay_header_1_5 ${l01} 1 "header_1_5.path:1: unsupported path version '1.5'"
          -- --headless --frames 1 --size 160x90 --replay ${regressions}/paths/regressions/header_1_5.path)
bad_input(01_lighting.replay_header_junk ${l01} 1 "header_junk.path:1: expected 'shadowlab-path 1', got 'shadowlab-path 1 junk'"
          -- --headless --frames 1 --size 160x90 --replay ${regressions}/paths/regressions/header_junk.path)
bad_input(01_lighting.replay_at_inf ${l01} 2 "'inf' after '@' is not a time >= 0 in seconds"
          -- --headless --frames 1 --size 160x90 --replay ${CMAKE_SOURCE_DIR}/bench/paths/walk.path@inf)
bad_input(01_lighting.replay_missing ${l01} 1 "--replay: /nonexistent/walk.path: cannot open for reading"
          -- --headless --frames 1 --size 160x90 --replay /nonexistent/walk.path)

# The light rig's checks (declareLight), on every lesson with the rig (light0 is lesson 03's sun:
# its "sun.direction 1e-45 0 0" of the issue is light0.direction now).
foreach(lesson IN ITEMS lesson_01_lighting lesson_02_shadow_maps lesson_03_shadow_quality lesson_04_shadow_volumes
                       lesson_05_soft_shadows)
  if(NOT TARGET ${lesson})
    continue()
  endif()
  string(REGEX REPLACE "^lesson_" "" name ${lesson})
  bad_input(${name}.light_direction_zero $<TARGET_FILE:${lesson}> 2
            "light0.direction = 0 0 0 is not a direction: it needs a length of at least 1e-06"
            -- --headless --frames 1 --size 160x90 "--set=light0.direction=0 0 0")
  bad_input(${name}.light_direction_denormal $<TARGET_FILE:${lesson}> 2
            "light0.direction = 1.4013e-45 0 0 is not a direction"
            -- --headless --frames 1 --size 160x90 "--set=light0.direction=1e-45 0 0")
  bad_input(${name}.attenuation_zero $<TARGET_FILE:${lesson}> 2
            "light0.attenuation = 0 0 0 divides by zero"
            -- --headless --frames 1 --size 160x90 "--set=light0.attenuation=0 0 0")
  bad_input(${name}.near_beyond_far $<TARGET_FILE:${lesson}> 2
            "camera.near = 5, camera.far = 2: the near plane must lie before the far plane"
            -- --headless --frames 1 --size 160x90 --set camera.far=2 --set camera.near=5)
endforeach()
# ...in presets too, naming the line that set the value, after comments and blank lines.
bad_input(01_lighting.preset_degenerate ${l01} 2
          "presets.txt:5: in preset 'dark': light0.direction = 0 0 0 is not a direction"
          --write lessons/01_lighting/presets.txt "[ok]\nambient = 0.5\n[dark]\n# nowhere\nlight0.direction = 0 0 0\n"
          -- --headless --frames 1 --size 160x90)
bad_input(01_lighting.preset_line_after_comments ${l01} 2
          "presets.txt:6: in preset 'loud': bad value '7' for ambient (float); valid: [0, 1]"
          --write lessons/01_lighting/presets.txt "[loud]\n# a comment\n\n# another\n\nambient = 7\n"
          -- --headless --frames 1 --size 160x90)

# Empty values and sizes.
bad_input(01_lighting.screenshot_empty ${l01} 2 "--screenshot needs a value, got an empty one: --screenshot FILE"
          -- --headless --frames 1 --screenshot=)
bad_input(01_lighting.preset_empty ${l01} 2 "--preset needs a value, got an empty one: --preset NAME"
          -- --headless --frames 1 --preset=)
bad_input(01_lighting.size_16384 ${l01} 2 "--size: '16384' is not a whole number in [16, 8192]"
          -- --headless --frames 1 --size 16384x16384)

# Write errors: a full disk is an error naming the file, and nothing lands beside it.
bad_input(01_lighting.screenshot_full_disk ${l01} 1 "cannot write PNG '/dev/full': No space left on device"
          -- --headless --frames 1 --size 160x90 --screenshot /dev/full)
bad_input(01_lighting.measure_full_disk ${l01} 1 "--measure: cannot write /dev/full: No space left on device"
          -- --headless --frames 1 --size 160x90 --measure /dev/full)
bad_input(01_lighting.bench_full_disk ${l01} 1 "--bench: cannot write /dev/full: No space left on device"
          -- --headless --frames 1 --size 160x90 --bench /dev/full)

# A texture that is no PNG (a 0x0 PNM named .png loaded as an empty image): exit 1, named.
bad_input(01_lighting.texture_not_png ${l01} 1 "textures/checker.png': a PNM file (11 bytes); the course reads PNG only"
          --write textures/checker.png "P6\n0 0\n255\n" -- --headless --frames 1 --size 160x90)

# A compile error on a 30,000-character line segfaulted the log mapping (std::regex): exit 1, file:line.
file(READ ${CMAKE_SOURCE_DIR}/shaders/01_lighting/scene.frag scene_frag)
string(REPEAT "x" 30000 long_identifier)
string(REPLACE "void main() {" "void main() {\n  float broken = ${long_identifier};" long_line_frag "${scene_frag}")
# The broken line's number in the edited file (the line after `void main() {`), so the test keeps
# checking the mapped line as the shader grows.
string(FIND "${scene_frag}" "void main() {" main_at)
string(SUBSTRING "${scene_frag}" 0 ${main_at} before_main)
string(REGEX MATCHALL "\n" newlines "${before_main}")
list(LENGTH newlines broken_line)
math(EXPR broken_line "${broken_line} + 2")
add_test(NAME bad_input.01_lighting.shader_error_long_line COMMAND lesson_check ${l01} --expect-exit 1
         --expect-stderr "shaders/01_lighting/scene.frag:${broken_line}: error:" --write shaders/01_lighting/scene.frag
         "${long_line_frag}" -- --headless --frames 1 --size 160x90)  # the text holds ';': no function
set_tests_properties(bad_input.01_lighting.shader_error_long_line PROPERTIES LABELS gpu)

# Hotkeys (issue 19): every lesson's bindings pass the checks (no key twice, none of the framework's,
# none on a kind a key cannot drive) and --list-hotkeys prints the table with the framework's keys.
foreach(lesson IN LISTS SHADOWLAB_LESSONS)
  string(REGEX REPLACE "^lesson_" "" name ${lesson})
  add_test(NAME hotkeys.${name} COMMAND $<TARGET_FILE:${lesson}> --list-hotkeys)
  set_tests_properties(hotkeys.${name} PROPERTIES LABELS unit
                       PASS_REGULAR_EXPRESSION "R  \\(framework\\)  reload shaders.*H  \\(framework\\)  hide the panels \\(labels and legends stay\\), then all UI"
                       FAIL_REGULAR_EXPRESSION "hotkeys: ")
endforeach()

# The launcher's --help names every flag it accepts; a bad --frames is refused with the valid range.
if(TARGET shadowlab)
  add_test(NAME launcher.help COMMAND $<TARGET_FILE:shadowlab> --help)
  set_tests_properties(launcher.help PROPERTIES LABELS unit
                       PASS_REGULAR_EXPRESSION "--tour DIR.*--frames N.*--screenshot FILE.*--help")
  bad_input(launcher.frames_not_a_number $<TARGET_FILE:shadowlab> 2
            "--frames: 'ten' is not a whole number in [1, 100000000]" -- --frames ten)
endif()

# The UI's rectangles (--ui-layout): --show-help draws the help; at --ui-scale 2 header and panel do
# not overlap; neither covers the A/B split's labels, the god view or lesson 02's map inset.
add_test(NAME gpu.framework.ui_layout COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_03_shadow_quality>
         -DLESSON02=$<TARGET_FILE:lesson_02_shadow_maps>
         -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_ui_layout.cmake)
set_tests_properties(gpu.framework.ui_layout PROPERTIES LABELS gpu)
# The last headless frame's UI laid out for its own content (the header not a frame behind).
add_test(NAME gpu.framework.ui_settled COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_07_hybrid_maps>
         -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_ui_settled.cmake)
set_tests_properties(gpu.framework.ui_settled PROPERTIES LABELS gpu)
set(panel_lessons)
foreach(lesson IN LISTS SHADOWLAB_LESSONS)
  list(APPEND panel_lessons $<TARGET_FILE:${lesson}>)
endforeach()
add_test(NAME gpu.framework.panel_labels
         COMMAND ${CMAKE_COMMAND} "-DLESSONS=${panel_lessons}" -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots/panel
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_panel_labels.cmake)
set_tests_properties(gpu.framework.panel_labels PROPERTIES LABELS gpu)

# An even PCF kernel was silently drawn as the next odd one (issue 19): refused, with the valid sizes.
bad_input(03_shadow_quality.pcf_size_even $<TARGET_FILE:lesson_03_shadow_quality> 2
          "pcf.size = 4: the N x N kernel needs an odd N; valid: 1, 3, 5, 7, 9"
          -- --headless --frames 1 --size 160x90 --set pcf.size=4)

# bench_psm_setup takes one CSV path: a flag or a second argument is refused, not written to.
if(NOT SHADOWLAB_UNIT_ONLY AND EXISTS ${CMAKE_SOURCE_DIR}/bench/CMakeLists.txt)  # added after tests/
  bad_input(bench_psm_setup.flag $<TARGET_FILE:bench_psm_setup> 2
            "bench_psm_setup: unexpected argument '--bogus'" -- --bogus)
  bad_input(bench_psm_setup.unwritable $<TARGET_FILE:bench_psm_setup> 2
            "bench_psm_setup: cannot write /nonexistent-dir/setup.csv" -- /nonexistent-dir/setup.csv)
endif()
# gen_textures takes the output directory: a flag is refused, not created as a directory.
if(TARGET gen_textures)
  bad_input(gen_textures.flag $<TARGET_FILE:gen_textures> 2
            "gen_textures: unexpected argument '--bogus'; usage: gen_textures OUTDIR" -- --bogus)
endif()

# Every tool's --help prints its usage on stdout and exits 0; a mistyped flag where a path belongs
# is refused with exit 2, naming it. Neither writes anything (check_cli.cmake runs each in an empty
# directory): measure_report_demo wrote a whole report into ./--help, psm_stress and lesson_check
# tried to run "--help" as the lesson, and filter_sweep and frame_bench answered --help with exit 2.
function(cli_check name program exit stdout stderr)
  add_test(NAME cli.${name}
           COMMAND ${CMAKE_COMMAND} -DPROGRAM=${program} "-DARGS=${ARGN}" -DEXIT=${exit} "-DSTDOUT=${stdout}"
                   "-DSTDERR=${stderr}" -DWORKDIR=${CMAKE_CURRENT_BINARY_DIR}/cli/${name}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/support/check_cli.cmake)
  set_tests_properties(cli.${name} PROPERTIES LABELS unit)
endfunction()
# Deferred to the end of tests/: some tools are defined by modules included after this one.
function(shadowlab_tool_cli_checks)
  foreach(tool lesson_check psm_stress frame_bench filter_sweep shadowlab_bench measure_report_demo gen_textures
               shadowlab grade_report grade_isolated)
    if(TARGET ${tool})
      cli_check(${tool}.help $<TARGET_FILE:${tool}> 0 "^usage: ${tool} " "" --help)
    endif()
  endforeach()
  set(flag_errors
      "lesson_check|^lesson_check: no program at '--bogus'"
      "psm_stress|^psm_stress: no program at '--bogus'"
      "shadowlab_bench|^shadowlab_bench: the first argument is the lesson program, not '--bogus'"
      "measure_report_demo|^measure_report_demo: unexpected argument '--bogus'; usage: measure_report_demo OUT_DIR"
      "frame_bench|^frame_bench: unknown argument '--bogus'; valid: --bin"
      "filter_sweep|^filter_sweep: unknown flag '--bogus'")
  foreach(entry IN LISTS flag_errors)
    string(FIND "${entry}" "|" bar)
    string(SUBSTRING "${entry}" 0 ${bar} tool)
    math(EXPR from "${bar} + 1")
    string(SUBSTRING "${entry}" ${from} -1 error)
    if(TARGET ${tool})
      cli_check(${tool}.flag $<TARGET_FILE:${tool}> 2 "" "${error}" --bogus)
    endif()
  endforeach()
  # shadowlab_bench --shimmer: a span of a path that exists, under a plain name
  if(TARGET shadowlab_bench AND TARGET lesson_01_lighting)
    set(walk ${CMAKE_SOURCE_DIR}/bench/paths/walk.path)
    set(bench $<TARGET_FILE:shadowlab_bench>)
    set(l01 $<TARGET_FILE:lesson_01_lighting> --out ${CMAKE_CURRENT_BINARY_DIR}/cli/shimmer_out)
    cli_check(shadowlab_bench.shimmer_held ${bench} 2 "" "--shimmer camera=.*walk.path@0.5: needs a span @T0..T1" ${l01}
              --shimmer camera=${walk}@0.5)
    cli_check(shadowlab_bench.shimmer_name ${bench} 2 "" "--shimmer '.*' is not NAME=FILE@T0..T1" ${l01}
              --shimmer Camera=${walk}@0..1)
    cli_check(shadowlab_bench.shimmer_file ${bench} 2 "" "--shimmer cam=nowhere.path@0..1: nowhere.path: cannot open" ${l01}
              --shimmer cam=nowhere.path@0..1)
    cli_check(shadowlab_bench.shimmer_span ${bench} 2 "" "is not a span T0..T1 of times" ${l01} --shimmer cam=${walk}@1..0.5)
    cli_check(shadowlab_bench.shimmer_frames ${bench} 2 "" "--shimmer-frames: '1' is not a whole number >= 2" ${l01}
              --shimmer-frames 1)
  endif()
endfunction()
cmake_language(DEFER CALL shadowlab_tool_cli_checks)
if(NOT SHADOWLAB_UNIT_ONLY AND EXISTS ${CMAKE_SOURCE_DIR}/bench/CMakeLists.txt)  # added after tests/
  cli_check(bench_psm_setup.help $<TARGET_FILE:bench_psm_setup> 0 "^usage: bench_psm_setup " "" --help)
endif()
# The same for the scripts (tools/script_args.sh): --help prints the header comment, a flag where
# BUILD_DIR belongs is refused (it was taken for a build directory: "--help/bin/... not built").
foreach(script psm_bench soft_bench shadow_bench hybrid_bench volume_bench showdown_bench fuzz)
  set(path ${CMAKE_SOURCE_DIR}/tools/${script}.sh)
  cli_check(${script}_sh.help bash 0 "tools/${script}\\.sh" "" ${path} --help)
  cli_check(${script}_sh.flag bash 2 "" "^${script}\\.sh: unknown flag '--bogus'" ${path} --bogus)
endforeach()
find_package(Python3 COMPONENTS Interpreter QUIET)
if(Python3_Interpreter_FOUND)
  set(summary ${CMAKE_SOURCE_DIR}/tools/showdown_summary.py)
  cli_check(showdown_summary.help ${Python3_EXECUTABLE} 0 "showdown_summary.py OUT_DIR SIZE REPEATS" "" ${summary}
            --help)
  cli_check(showdown_summary.flag ${Python3_EXECUTABLE} 2 "" "^showdown_summary.py: expected OUT_DIR SIZE REPEATS"
            ${summary} --bogus)
endif()
if(EXISTS ${CMAKE_SOURCE_DIR}/tools/grading/grade_submission.sh)  # the instructor's tree only
  cli_check(grade_submission_sh.missing bash 2 "" "^grade_submission.sh: no submission directory '/nonexistent-dir'"
            ${CMAKE_SOURCE_DIR}/tools/grading/grade_submission.sh /nonexistent-dir)
  # One week's assignment: LESSONS names lessons with exercises, or is refused naming the valid ones.
  cli_check(grade_submission_sh.lessons env 2 ""
            "^grade_submission.sh: LESSONS: '11' is not a lesson with exercises; valid: 01 02 03 04 05 06 07 08 09 10"
            LESSONS=03,11 bash ${CMAKE_SOURCE_DIR}/tools/grading/grade_submission.sh ${CMAKE_SOURCE_DIR}/lessons)
endif()
