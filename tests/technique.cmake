# The technique layer (common/technique) through the lessons that compose it (label gpu):
#   gpu.technique.ab_versus  lesson 03's A/B split of the uniform map against lesson 04's stencil
#                            volumes: each half measures what its own lesson measures
#   gpu.technique.none       the smallest technique (V = 1): every error is a leak, and there are leaks
#   gpu.technique.generic    the lit pass's generic shaders (SHADOWLAB_SPECIALISE=0: no #defines, every
#                            feature a uniform) draw the golden pictures of the specialised ones on a
#                            preset of each light kind and filter: the fallback a window shows while a
#                            specialised program compiles
#   gpu.technique.map_reuse  static lights over a static scene: every map drawn once, then reused, and
#                            the picture equals the one redrawn every frame
#   registry: ...            the showdown's registry of techniques: names, prefixes, presets, golden
#                            images and benchmark rows (gpu/registry_test.cpp)
if(SHADOWLAB_UNIT_ONLY OR NOT TARGET lesson_03_shadow_quality OR NOT TARGET lesson_04_shadow_volumes)
  return()
endif()
add_test(NAME gpu.technique.ab_versus COMMAND ${CMAKE_COMMAND}
         -DLESSON03=$<TARGET_FILE:lesson_03_shadow_quality> -DLESSON04=$<TARGET_FILE:lesson_04_shadow_volumes>
         -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_ab_versus.cmake)
set_tests_properties(gpu.technique.ab_versus PROPERTIES LABELS gpu TIMEOUT 300)
add_test(NAME gpu.technique.none COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_03_shadow_quality>
         -DOUT=${CMAKE_BINARY_DIR}/test-screenshots/technique_none.json -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_no_shadows.cmake)
set_tests_properties(gpu.technique.none PROPERTIES LABELS gpu TIMEOUT 300)
add_test(NAME gpu.technique.generic COMMAND lesson_check $<TARGET_FILE:lesson_03_shadow_quality>
         --presets default,several_lights,receiver_plane,poisson,point_light,versus_volumes
         --png ${CMAKE_BINARY_DIR}/test-screenshots/technique_generic.png
         --golden ${CMAKE_CURRENT_SOURCE_DIR}/data/golden/03_shadow_quality
         -- --headless --frames 2 --size 320x180 --screenshot ${CMAKE_BINARY_DIR}/test-screenshots/technique_generic.png)
set_tests_properties(gpu.technique.generic PROPERTIES LABELS gpu TIMEOUT 600 ENVIRONMENT SHADOWLAB_SPECIALISE=0)
add_test(NAME gpu.technique.map_reuse COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_03_shadow_quality>
         -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_map_reuse.cmake)
set_tests_properties(gpu.technique.map_reuse PROPERTIES LABELS gpu TIMEOUT 300)
# The hybrid map (lesson 07) too: its depth pass, index, merge and records all skipped after frame 0.
add_test(NAME gpu.technique.hybrid_map_reuse COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_07_hybrid_maps>
         -DNAME=hybrid_reuse -DPRESET=default -DMAPS=1 -DPASSES=4
         -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_map_reuse.cmake)
set_tests_properties(gpu.technique.hybrid_map_reuse PROPERTIES LABELS gpu TIMEOUT 300)
# The projective maps under a still camera: PSM with the fixes (lesson 09) and the cascades (lesson 10).
add_test(NAME gpu.technique.psm_map_reuse COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_09_psm_fixes>
         -DNAME=psm_reuse -DPRESET=default -DMAPS=1 -DPASSES=1
         -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_map_reuse.cmake)
add_test(NAME gpu.technique.cascades_map_reuse COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_10_showdown>
         -DNAME=csm_reuse -DPRESET=default -DMAPS=1 -DPASSES=1 -DREUSE=csm.reuse_maps
         -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_map_reuse.cmake)
set_tests_properties(gpu.technique.psm_map_reuse gpu.technique.cascades_map_reuse PROPERTIES LABELS gpu TIMEOUT 300)
# Lesson 05's soft maps under a still spherical light: PCSS's one map, and the four maps of four
# point lights on the sphere (one timed pass for the light's four).
add_test(NAME gpu.technique.soft_map_reuse COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_05_soft_shadows>
         -DNAME=soft_reuse -DPRESET=contact_hardening -DMAPS=1 -DPASSES=1 -DREUSE=pcss.reuse_maps
         -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_map_reuse.cmake)
add_test(NAME gpu.technique.many_map_reuse COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_05_soft_shadows>
         -DNAME=many_reuse -DPRESET=many_4 -DMAPS=4 -DROWS=1 -DREUSE=many.reuse_maps
         -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_map_reuse.cmake)
# Both spherical lights (two PCSS maps), and ESM's moments with their blur.
add_test(NAME gpu.technique.two_soft_lights_map_reuse COMMAND ${CMAKE_COMMAND}
         -DLESSON=$<TARGET_FILE:lesson_05_soft_shadows> -DNAME=two_soft_reuse -DPRESET=two_lights -DMAPS=2
         -DREUSE=pcss.reuse_maps -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots
         -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_map_reuse.cmake)
add_test(NAME gpu.technique.esm_map_reuse COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_05_soft_shadows>
         -DNAME=esm_reuse -DPRESET=esm -DMAPS=1 -DREUSE=esm.reuse_maps
         -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_map_reuse.cmake)
set_tests_properties(gpu.technique.soft_map_reuse gpu.technique.many_map_reuse gpu.technique.two_soft_lights_map_reuse
                     gpu.technique.esm_map_reuse PROPERTIES LABELS gpu TIMEOUT 300)
# And under a light moving on every frame the soft maps and ESM's moments are drawn every frame.
foreach(t pcss many esm)
  add_test(NAME gpu.technique.${t}_maps_follow_the_light COMMAND ${CMAKE_COMMAND}
           -DLESSON=$<TARGET_FILE:lesson_05_soft_shadows> -DNAME=${t}_moving -DPRESET=default -DSET=technique=${t} -DMAPS=1
           "-DREPLAY=${CMAKE_CURRENT_SOURCE_DIR}/data/paths/soft_light_moves.path" -DREUSE=${t}.reuse_maps -DROWS=1
           -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_map_reuse.cmake)
  set_tests_properties(gpu.technique.${t}_maps_follow_the_light PROPERTIES LABELS gpu TIMEOUT 300)
endforeach()


# The frame budget on a software renderer (a window under Xvfb), lesson 03.
find_program(XVFB_RUN xvfb-run)
if(XVFB_RUN)
  add_test(NAME gpu.framework.frame_budget COMMAND ${CMAKE_COMMAND} -DXVFB_RUN=${XVFB_RUN}
           -DLESSON=$<TARGET_FILE:lesson_03_shadow_quality> -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots
           -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_frame_budget.cmake)
  set_tests_properties(gpu.framework.frame_budget PROPERTIES LABELS gpu TIMEOUT 300)
  # Lesson 02 skips its depth pre-pass while the budget draws at half size or less (depth_prepass=auto).
  add_test(NAME gpu.02_shadow_maps.prepass_under_budget COMMAND ${CMAKE_COMMAND} -DXVFB_RUN=${XVFB_RUN}
           -DLESSON=$<TARGET_FILE:lesson_02_shadow_maps> -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots
           -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_prepass_budget.cmake)
  set_tests_properties(gpu.02_shadow_maps.prepass_under_budget PROPERTIES LABELS gpu TIMEOUT 300)
endif()
# Without its pre-pass lesson 02 draws the picture it draws with it (depth ties between leaf cards
# aside: within the golden images' tolerance), and without a GL error.
add_test(NAME gpu.02_shadow_maps.prepass_off_golden
         COMMAND lesson_check $<TARGET_FILE:lesson_02_shadow_maps> --png ${CMAKE_BINARY_DIR}/test-screenshots/02_prepass_off.png
                 --golden ${CMAKE_CURRENT_SOURCE_DIR}/data/golden/02_shadow_maps
                 -- --headless --frames 2 --size 320x180 --set depth_prepass=off
                 --screenshot ${CMAKE_BINARY_DIR}/test-screenshots/02_prepass_off.png)
set_tests_properties(gpu.02_shadow_maps.prepass_off_golden PROPERTIES LABELS gpu)

# The frames table of `make bench` (tools/frame_bench), on one lesson's default view: it runs, and
# writes a row with a frame time and a floor.
if(TARGET frame_bench AND TARGET lesson_01_lighting)
  add_test(NAME bench.frames.smoke COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:frame_bench>
           -DBIN=$<TARGET_FILE_DIR:lesson_01_lighting> -DOUT=${CMAKE_BINARY_DIR}/test-bench/frames
           -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_frame_bench.cmake)
  set_tests_properties(bench.frames.smoke PROPERTIES LABELS gpu TIMEOUT 300)
endif()

if(TARGET shadowlab_10_showdown)
  add_executable(technique_registry_tests ${CMAKE_CURRENT_SOURCE_DIR}/gpu/registry_test.cpp)
  target_link_libraries(technique_registry_tests PRIVATE shadowlab_test_main shadowlab_10_showdown)
  shadowlab_discover_tests(technique_registry_tests LABELS gpu)
endif()
