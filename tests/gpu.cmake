# GPU tests through headless EGL (Mesa's llvmpipe on CI): the GL layer itself (gpu_tests) and every
# lesson program run as users run it (lesson_check). Label gpu. Any GL error fails: lessons run
# with SHADOWLAB_STRICT_GL=1 (exit 3 on a GL error), and gpu_tests checks errorCount() per case.
if(SHADOWLAB_UNIT_ONLY)
  return()
endif()

file(GLOB GPU_TEST_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/gpu/test_*.cpp)
add_executable(gpu_tests ${GPU_TEST_SOURCES})
target_link_libraries(gpu_tests PRIVATE shadowlab_test_main shadowlab_app)
shadowlab_discover_tests(gpu_tests LABELS gpu)

add_executable(lesson_check ${CMAKE_CURRENT_SOURCE_DIR}/gpu/lesson_check.cpp)
target_link_libraries(lesson_check PRIVATE shadowlab_core)

find_program(XVFB_RUN xvfb-run)
set(shots ${CMAKE_BINARY_DIR}/test-screenshots)
file(MAKE_DIRECTORY ${shots})
foreach(lesson IN LISTS SHADOWLAB_LESSONS)
  string(REGEX REPLACE "^lesson_" "" name ${lesson})
  set(bin $<TARGET_FILE:${lesson}>)
  add_test(NAME gpu.${name}.headless COMMAND lesson_check ${bin} --png ${shots}/${name}.png
           -- --headless --frames 5 --screenshot ${shots}/${name}.png)
  add_test(NAME gpu.${name}.presets COMMAND lesson_check ${bin} --all-presets --png ${shots}/${name}_preset.png
           -- --headless --frames 2 --size 640x360 --screenshot ${shots}/${name}_preset.png)
  add_test(NAME gpu.${name}.ui COMMAND lesson_check ${bin} --png ${shots}/${name}_ui.png
           -- --headless --frames 3 --show-ui --screenshot ${shots}/${name}_ui.png)
  add_test(NAME gpu.${name}.bench COMMAND lesson_check ${bin}
           -- --headless --frames 10 --size 320x180 --bench ${shots}/${name}_bench.csv)
  # The framework's views on every lesson: the god view inset and the A/B split (B = first preset).
  add_test(NAME gpu.${name}.god_view COMMAND lesson_check ${bin} --png ${shots}/${name}_god.png
           -- --headless --frames 2 --size 640x360 --set view.god=true --screenshot ${shots}/${name}_god.png)
  add_test(NAME gpu.${name}.ab_split COMMAND lesson_check ${bin} --png ${shots}/${name}_ab.png
           -- --headless --frames 2 --size 640x360 --set ab.enabled=true --show-ui --screenshot ${shots}/${name}_ab.png)
  # make bench's floor (every shading fragment shader trivial) must still draw a frame: the lesson's
  # floor column is otherwise empty (lesson 07 once stopped there on garbage record counts).
  add_test(NAME gpu.${name}.floor COMMAND ${CMAKE_COMMAND} -E env SHADOWLAB_FLOOR_SHADER=1
           $<TARGET_FILE:lesson_check> ${bin} -- --headless --frames 3 --size 320x180 --bench ${shots}/${name}_floor.csv)
  set_tests_properties(gpu.${name}.headless gpu.${name}.presets gpu.${name}.ui gpu.${name}.bench
                       gpu.${name}.god_view gpu.${name}.ab_split gpu.${name}.floor PROPERTIES LABELS gpu)
  # Same pictures as before a refactor: every preset against the images recorded in
  # tests/data/golden/NAME (SHADOWLAB_RECORD_GOLDEN=1 ctest -R golden records them anew; =missing only
  # those of new presets).
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/data/golden/${name})
    add_test(NAME gpu.${name}.golden COMMAND lesson_check ${bin} --all-presets --png ${shots}/${name}_golden.png
             --golden ${CMAKE_CURRENT_SOURCE_DIR}/data/golden/${name}
             -- --headless --frames 2 --size 320x180 --screenshot ${shots}/${name}_golden.png)
    set_tests_properties(gpu.${name}.golden PROPERTIES LABELS gpu)
  endif()
  # Bad input: one-line errors naming the value and the choices (exit 2), missing files named (exit 1).
  add_test(NAME cli.${name}.unknown_flag COMMAND lesson_check ${bin} --expect-exit 2
           --expect-stderr "unknown flag '--frobnicate'; valid: --headless" -- --frobnicate)
  add_test(NAME cli.${name}.unknown_param COMMAND lesson_check ${bin} --expect-exit 2
           --expect-stderr "unknown parameter 'nonsense'; valid: " -- --headless --set nonsense=1)
  add_test(NAME cli.${name}.unknown_preset COMMAND lesson_check ${bin} --expect-exit 2
           --expect-stderr "unknown preset 'no_such_preset'" -- --headless --preset no_such_preset)
  add_test(NAME cli.${name}.list_params COMMAND lesson_check ${bin} -- --list-params)
  add_test(NAME cli.${name}.help COMMAND lesson_check ${bin} -- --help)
  set_tests_properties(cli.${name}.unknown_flag cli.${name}.unknown_param cli.${name}.unknown_preset
                       cli.${name}.list_params cli.${name}.help PROPERTIES LABELS gpu)
  if(XVFB_RUN)
    add_test(NAME gpu.${name}.window COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x720x24"
             $<TARGET_FILE:lesson_check> ${bin} --png ${shots}/${name}_window.png
             -- --frames 10 --screenshot ${shots}/${name}_window.png)
    set_tests_properties(gpu.${name}.window PROPERTIES LABELS gpu)
  endif()
endforeach()

# measure.light's range is the lesson's lights (three in lesson 03): a fourth is a bad value (exit 2),
# overlay or not, like any other.
if(TARGET lesson_03_shadow_quality)
  foreach(overlay none error)
    add_test(NAME cli.03_shadow_quality.measure_light_${overlay} COMMAND lesson_check
             $<TARGET_FILE:lesson_03_shadow_quality> --expect-exit 2
             --expect-stderr "bad value '3' for measure.light (int); valid: [0, 2]"
             -- --headless --frames 1 --set measure.light=3 --set measure.overlay=${overlay})
    set_tests_properties(cli.03_shadow_quality.measure_light_${overlay} PROPERTIES LABELS gpu)
  endforeach()
endif()

# Maps over the memory budget are refused up front (exit 2, the figure and what fits), not left to
# GL_OUT_OF_MEMORY (17 GB of many-lights maps exited 1 under --strict-gl).
if(TARGET lesson_05_soft_shadows)
  add_test(NAME cli.05_soft_shadows.map_budget COMMAND lesson_check $<TARGET_FILE:lesson_05_soft_shadows>
           --expect-exit 2 --expect-stderr "many.samples = 64 maps of many.map_size = 8192 take 16384 MiB a light, over the 4096 MiB budget of one light's maps: at 8192 at most 16 samples, or 64 samples at 4096 texels"
           -- --headless --strict-gl --frames 1 --set technique=many --set many.samples=64 --set many.map_size=8192)
  set_tests_properties(cli.05_soft_shadows.map_budget PROPERTIES LABELS gpu)
endif()

# A camera that sees none of the scene says so (banner; stderr headless), exit 0: beyond the far
# plane, and wholly nearer than the near plane.
if(TARGET lesson_03_shadow_quality)
  add_test(NAME gpu.03_shadow_quality.sees_nothing_far COMMAND lesson_check $<TARGET_FILE:lesson_03_shadow_quality>
           --expect-stderr "The camera sees none of the scene: the scene is beyond the far plane"
           -- --headless --frames 1 --size 320x180 --set camera.distance=500)
  add_test(NAME gpu.03_shadow_quality.sees_nothing_near COMMAND lesson_check $<TARGET_FILE:lesson_03_shadow_quality>
           --expect-stderr "The camera sees none of the scene: the scene is nearer than the near plane"
           -- --headless --frames 1 --size 320x180 --set camera.near=100 --set camera.distance=5 --set camera.pitch=1.4)
  set_tests_properties(gpu.03_shadow_quality.sees_nothing_far gpu.03_shadow_quality.sees_nothing_near
                       PROPERTIES LABELS gpu)
endif()

# Missing files: lesson 01's shader and a texture, removed from a copy of the tree.
if(TARGET lesson_01_lighting)
  add_test(NAME gpu.01_lighting.missing_shader COMMAND lesson_check $<TARGET_FILE:lesson_01_lighting>
           --without shaders/01_lighting/scene.frag --expect-exit 1 --expect-stderr "shaders/01_lighting/scene.frag"
           -- --headless --frames 1)
  add_test(NAME gpu.01_lighting.missing_texture COMMAND lesson_check $<TARGET_FILE:lesson_01_lighting>
           --without textures/checker.png --expect-exit 1 --expect-stderr "textures/checker.png"
           -- --headless --frames 1)
  # A malformed preset file: the error names the file and the line (exit 2), whatever preset is asked for.
  add_test(NAME gpu.01_lighting.malformed_presets COMMAND lesson_check $<TARGET_FILE:lesson_01_lighting>
           --write lessons/01_lighting/presets.txt "[ok]\nambient = 0.5\n\n[broken]\nambient 0.5\n"
           --expect-exit 2 --expect-stderr "lessons/01_lighting/presets.txt:5: expected 'name = value'"
           -- --headless --frames 1)
  add_test(NAME gpu.01_lighting.preset_bad_value COMMAND lesson_check $<TARGET_FILE:lesson_01_lighting>
           --write lessons/01_lighting/presets.txt "[loud]\nambient = 7\n"
           --expect-exit 2 --expect-stderr "presets.txt:2: in preset 'loud': bad value '7' for ambient (float); valid: [0, 1]"
           -- --headless --frames 1)
  set_tests_properties(gpu.01_lighting.missing_shader gpu.01_lighting.missing_texture
                       gpu.01_lighting.malformed_presets gpu.01_lighting.preset_bad_value PROPERTIES LABELS gpu)
endif()

# Measurement against ground truth (issue: reference visibility): lesson 01's errors are all leaks.
if(TARGET lesson_01_lighting)
  add_test(NAME gpu.01_lighting.measure COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_01_lighting>
           -DOUT=${shots}/01_lighting_measure.json -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_measure.cmake)
  add_test(NAME gpu.01_lighting.measure_overlay COMMAND lesson_check $<TARGET_FILE:lesson_01_lighting>
           --png ${shots}/01_lighting_overlay.png
           -- --headless --frames 3 --size 640x360 --set measure.overlay=error --screenshot ${shots}/01_lighting_overlay.png)
  set_tests_properties(gpu.01_lighting.measure gpu.01_lighting.measure_overlay PROPERTIES LABELS gpu)
endif()
# Shimmer: the temporal figures of --measure under a turning sun (and none with the sun still).
if(TARGET lesson_09_psm_fixes)
  add_test(NAME gpu.measure.shimmer COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_09_psm_fixes>
           -DPATH_FILE=${CMAKE_SOURCE_DIR}/bench/paths/sun_turn.path -DOUT_DIR=${shots}
           -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_shimmer.cmake)
  set_tests_properties(gpu.measure.shimmer PROPERTIES LABELS gpu TIMEOUT 300)
endif()

if(TARGET lesson_01_lighting AND TARGET lesson_02_shadow_maps AND TARGET lesson_03_shadow_quality
   AND TARGET lesson_04_shadow_volumes AND TARGET lesson_10_showdown)
  add_test(NAME gpu.measure.shimmer_drift
           COMMAND ${CMAKE_COMMAND} -DLESSON01=$<TARGET_FILE:lesson_01_lighting>
                   -DLESSON02=$<TARGET_FILE:lesson_02_shadow_maps> -DLESSON03=$<TARGET_FILE:lesson_03_shadow_quality>
                   -DLESSON04=$<TARGET_FILE:lesson_04_shadow_volumes> -DLESSON10=$<TARGET_FILE:lesson_10_showdown>
                   -DDRIFT=${CMAKE_SOURCE_DIR}/bench/paths/city_drift.path -DOUT_DIR=${shots}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_shimmer_drift.cmake)
  set_tests_properties(gpu.measure.shimmer_drift PROPERTIES LABELS gpu TIMEOUT 300)
endif()

# The benchmark runner on lesson 01: two configurations along a recorded path, two repeats; the
# report's files, its numbers against the CSV, and the page in headless Chromium.
if(TARGET lesson_01_lighting AND TARGET shadowlab_bench)
  set(bench_dir ${CMAKE_BINARY_DIR}/test-bench)
  add_test(NAME bench.01_lighting.record COMMAND lesson_check $<TARGET_FILE:lesson_01_lighting>
           -- --headless --frames 3 --size 160x90 --record ${bench_dir}/path.txt)
  add_test(NAME bench.01_lighting.run COMMAND shadowlab_bench $<TARGET_FILE:lesson_01_lighting> --out ${bench_dir}
           --config "sun only: light1.enabled=false" --preset three_lights --path ${bench_dir}/path.txt
           --path-samples 2 --repeat 2 --frames 2 --size 320x180)
  add_test(NAME bench.01_lighting.report COMMAND ${CMAKE_COMMAND} -DDIR=${bench_dir} -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_bench_report.cmake)
  set_tests_properties(bench.01_lighting.record PROPERTIES FIXTURES_SETUP bench_path LABELS gpu)
  set_tests_properties(bench.01_lighting.run PROPERTIES FIXTURES_REQUIRED bench_path FIXTURES_SETUP bench_report LABELS gpu)
  set_tests_properties(bench.01_lighting.report PROPERTIES FIXTURES_REQUIRED bench_report LABELS gpu)
  find_program(NODE node)
  if(NODE)
    add_test(NAME bench.01_lighting.page COMMAND ${NODE} ${CMAKE_SOURCE_DIR}/tools/web/check-page.mjs ${bench_dir}/report.html)
    set_tests_properties(bench.01_lighting.page PROPERTIES FIXTURES_REQUIRED bench_report LABELS web)
  endif()
endif()

# The insets a lesson draws (map views, the post-projective view, the god view) stay clear of the UI.
foreach(spec "08_psm|--set;view=map;--set;view.post=inset;--set;view.god=true|3"
             "09_psm_fixes|--set;view=maps;--set;view.post=inset|2"
             "10_showdown|--set;technique=psm;--set;view=maps;--set;view.post=inset|2")
  string(REPLACE "|" ";" spec "${spec}")
  list(GET spec 0 name)
  list(GET spec -1 expect)
  list(SUBLIST spec 1 -1 args)
  list(REMOVE_AT args -1)
  if(TARGET lesson_${name})
    add_test(NAME gpu.${name}.ui_insets COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_${name}> -DNAME=${name}
             "-DARGS=${args}" -DEXPECT=${expect} -DOUT_DIR=${shots} -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_ui_insets.cmake)
    set_tests_properties(gpu.${name}.ui_insets PROPERTIES LABELS gpu)
  endif()
endforeach()

# The launcher: its window under Xvfb lists the lessons; headless it renders the tour.
if(TARGET shadowlab)
  if(XVFB_RUN)
    add_test(NAME gpu.launcher.window COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x720x24"
             $<TARGET_FILE:lesson_check> $<TARGET_FILE:shadowlab> --png ${shots}/launcher.png
             -- --frames 5 --screenshot ${shots}/launcher.png)
    set_tests_properties(gpu.launcher.window PROPERTIES LABELS gpu)
  endif()
  set(launcher_lessons ${SHADOWLAB_LESSONS})
  list(TRANSFORM launcher_lessons REPLACE "^lesson_" "")
  add_test(NAME gpu.launcher.list COMMAND ${CMAKE_COMMAND} -DLAUNCHER=$<TARGET_FILE:shadowlab>
           -DROOT=${CMAKE_SOURCE_DIR} "-DLESSONS=${launcher_lessons}" -P ${CMAKE_CURRENT_LIST_DIR}/gpu/check_launcher_list.cmake)
  set_tests_properties(gpu.launcher.list PROPERTIES LABELS gpu)
endif()

# The picture first: every lesson's UI, as it starts, leaves at least 75 % of the window to the 3D
# view at 1280x720 and 1920x1080, UI scales 1 and 2 (check_ui_coverage.cmake).
foreach(name 01_lighting 02_shadow_maps 03_shadow_quality 04_shadow_volumes 05_soft_shadows 06_texture_filtering
             07_hybrid_maps 08_psm 09_psm_fixes 10_showdown)
  if(TARGET lesson_${name})
    add_test(NAME gpu.${name}.ui_coverage COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_${name}>
             -DOUT_DIR=${shots} -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_ui_coverage.cmake)
    set_tests_properties(gpu.${name}.ui_coverage PROPERTIES LABELS gpu TIMEOUT 300)
  endif()
endforeach()

# Lesson 03's point_light preset skips cube faces, more or fewer as the camera turns.
if(TARGET lesson_03_shadow_quality)
  add_test(NAME gpu.03_shadow_quality.skipped_faces COMMAND ${CMAKE_COMMAND}
           -DLESSON=$<TARGET_FILE:lesson_03_shadow_quality> -DOUT_DIR=${shots}/skipped_faces
           -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_skipped_faces.cmake)
  set_tests_properties(gpu.03_shadow_quality.skipped_faces PROPERTIES LABELS gpu)
endif()
