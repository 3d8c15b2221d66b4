# Lesson 10, the showdown (label gpu). The lesson's own headless, preset, UI, god-view, A/B, golden
# and bad-input tests come from tests/gpu.cmake; this file adds
#   gpu.showdown.TECH            every hard technique through lesson 10's --set interface at equal
#                                texels (check_psm_case.cmake: no GL error, nothing non-finite, the
#                                misclassified and leaked shares within the PSM cases' bounds)
#   gpu.showdown.csm_*           the cascades' switches through the same check
#   gpu.showdown.*_as_lessonNN   lesson 10 holds PSM and the hybrid maps as lessons 09 and 07 do: same figures
#   gpu.showdown.control.*       broken set-ups the same check must reject
#   gpu.showdown.cascades_alias  four cascades alias less than one at the same total texels
#   gpu.showdown.cascades_warp   the warp inside each cascade (csm.warp) aliases less than without it
#   gpu.showdown.sdsm_against_csm the sample-distribution cascades: the depth range from the GPU's tiles,
#                                less aliasing and fewer misclassified pixels than the practical cascades
#   gpu.showdown.csm_cull_*      caster culling per cascade: the same picture, fewer triangles
#   gpu.showdown.four_up*        each quarter of the four-up view is its technique's own picture, and
#                                that picture's ground-truth figures are within the bounds
#   bench.10_showdown.quick      tools/showdown_bench.sh --quick: the reports, the summary, the plot
# The bounds are the PSM cases' (tests/psm_lessons.cmake explains them): 1.5 % of the facing
# pixels misclassified, 5 % of the truly shadowed pixels leaked, on lesson 10's default view (the
# city from 45 m, the sun behind the camera, 480x270).
if(SHADOWLAB_UNIT_ONLY OR NOT TARGET lesson_10_showdown)
  return()
endif()
set(showdown_out ${CMAKE_BINARY_DIR}/test-screenshots/showdown)
file(MAKE_DIRECTORY ${showdown_out})

function(showdown_case name expect)
  add_test(NAME gpu.showdown.${name} COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_10_showdown>
           -DOUT=${showdown_out}/${name}.json -DNAME=${name} -DEXPECT=${expect} -DMAX_BP=150 -DMAX_LEAK_BP=500
           "-DARGS=${ARGN}" -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_psm_case.cmake)
  set_tests_properties(gpu.showdown.${name} PROPERTIES LABELS gpu TIMEOUT 300)
endfunction()

foreach(t uniform psm lispsm csm sdsm volumes)
  showdown_case(${t} ok --set technique=${t})
endforeach()
# The hybrid maps within the bounds under lesson 07's own sun. Under the showdown's low sun behind
# the camera they are not (2.1 % misclassified, nearly all false shadows, against 0.55 % for the
# standard map they start from, hybrid.levels=0): a finding of lesson 10, not a fault of holding
# them, as gpu.showdown.hybrid_as_lesson07 shows (the same figures as lesson 07 at that light).
showdown_case(hybrid_lesson07_sun ok --set technique=hybrid "--set;light0.direction=-0.45 -1 -0.3")
showdown_case(hybrid_standard ok --set technique=hybrid --set hybrid.levels=0)
if(TARGET lesson_07_hybrid_maps)
  add_test(NAME gpu.showdown.hybrid_as_lesson07 COMMAND ${CMAKE_COMMAND} -DSHOWDOWN=$<TARGET_FILE:lesson_10_showdown>
           "-DSHOWDOWN_ARGS=--set;technique=hybrid" -DLESSON=$<TARGET_FILE:lesson_07_hybrid_maps>
           "-DLESSON_ARGS=--set;light0.direction=-0.5 -0.45 -0.7;--set;camera.near=1" -DOUT_DIR=${showdown_out}
           -DNAME=hybrid_as_lesson07 -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_showdown_same.cmake)
  set_tests_properties(gpu.showdown.hybrid_as_lesson07 PROPERTIES LABELS gpu TIMEOUT 300)
endif()
if(TARGET lesson_09_psm_fixes)
  add_test(NAME gpu.showdown.psm_as_lesson09 COMMAND ${CMAKE_COMMAND} -DSHOWDOWN=$<TARGET_FILE:lesson_10_showdown>
           "-DSHOWDOWN_ARGS=--set;technique=psm" -DLESSON=$<TARGET_FILE:lesson_09_psm_fixes> "-DLESSON_ARGS="
           -DOUT_DIR=${showdown_out} -DNAME=psm_as_lesson09 -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_showdown_same.cmake)
  set_tests_properties(gpu.showdown.psm_as_lesson09 PROPERTIES LABELS gpu TIMEOUT 300)
endif()
showdown_case(csm_two ok --set technique=csm --set csm.cascades=2)
showdown_case(csm_three ok --set technique=csm --set csm.cascades=3)
showdown_case(csm_uniform_splits ok --set technique=csm --set csm.lambda=0)
showdown_case(csm_no_band ok --set technique=csm --set csm.band=0)
showdown_case(csm_wide_band ok --set technique=csm --set csm.band=0.5)
showdown_case(csm_constant_bias ok --set technique=csm --set csm.bias=constant)
showdown_case(csm_warp ok --set technique=csm --set csm.warp=true)
# Controls: no bias at all (acne over the lit faces), and cascades that end 5 m from the eye (every
# shadow beyond them is lost: leaks).
showdown_case(control.csm_no_bias fail --set technique=csm --set csm.bias=constant --set csm.bias.constant=0
              --set csm.bias.normal_offset=0 --set csm.offset.factor=0)
showdown_case(control.csm_short fail --set technique=csm --set csm.far=5)
# Caster culling per cascade (check_cascade_culling.cmake): the city of the default view, and the
# forest (many small casters) with two cascades.
foreach(spec "city|" "forest|--set;scene=forest;--set;csm.cascades=2")
  string(REPLACE "|" ";" parts "${spec}")
  list(GET parts 0 name)
  string(REPLACE "${name}|" "" args "${spec}")
  add_test(NAME gpu.showdown.csm_cull_${name} COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_10_showdown>
           -DOUT_DIR=${showdown_out} -DNAME=csm_cull_${name} "-DARGS=${args}"
           -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_cascade_culling.cmake)
  set_tests_properties(gpu.showdown.csm_cull_${name} PROPERTIES LABELS gpu TIMEOUT 300)
endforeach()

add_test(NAME gpu.showdown.cascades_alias COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_10_showdown>
         -DOUT_DIR=${showdown_out} -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_showdown_cascades.cmake)
set_tests_properties(gpu.showdown.cascades_alias PROPERTIES LABELS gpu TIMEOUT 300)
add_test(NAME gpu.showdown.sdsm_against_csm COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_10_showdown>
         -DOUT_DIR=${showdown_out} -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_showdown_sdsm.cmake)
set_tests_properties(gpu.showdown.sdsm_against_csm PROPERTIES LABELS gpu TIMEOUT 300)
showdown_case(sdsm_two ok --set technique=sdsm --set sdsm.cascades=2)
showdown_case(sdsm_warp ok --set technique=sdsm --set sdsm.warp=true)
add_test(NAME gpu.showdown.cascades_warp COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_10_showdown>
         -DOUT_DIR=${showdown_out} -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_showdown_warp.cmake)
set_tests_properties(gpu.showdown.cascades_warp PROPERTIES LABELS gpu TIMEOUT 300)

if(TARGET shadowlab_bench)
  find_program(BASH bash)
  add_test(NAME bench.10_showdown.quick COMMAND ${CMAKE_COMMAND} -DBASH=${BASH}
           -DSCRIPT=${CMAKE_SOURCE_DIR}/tools/showdown_bench.sh -DBUILD=${CMAKE_BINARY_DIR}
           -DDIR=${CMAKE_BINARY_DIR}/test-bench-showdown -DCHECK=${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_bench_report.cmake
           -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_showdown_bench.cmake)
  set_tests_properties(bench.10_showdown.quick PROPERTIES LABELS "gpu;bench" TIMEOUT 600)
endif()

# The four-up view's quarters against ground truth (check_four_up.cmake). Bounds per quarter in
# hundredths of a percent: the PSM cases' 1.5 %, and 3 % for the hybrid maps under the showdown's low
# sun (2.1 % there, nearly all false shadows: see hybrid_lesson07_sun above).
add_executable(quarter_compare ${CMAKE_CURRENT_SOURCE_DIR}/gpu/quarter_compare.cpp)
target_link_libraries(quarter_compare PRIVATE shadowlab_core)
function(four_up_case name preset quarters bounds)
  add_test(NAME gpu.showdown.${name} COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_10_showdown>
           -DCOMPARE=$<TARGET_FILE:quarter_compare> -DOUT_DIR=${showdown_out} -DNAME=${name} -DPRESET=${preset}
           "-DQUARTERS=${quarters}" "-DBOUNDS=${bounds}" -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_four_up.cmake)
  set_tests_properties(gpu.showdown.${name} PROPERTIES LABELS gpu TIMEOUT 300)
endfunction()
four_up_case(four_up four_up "uniform;psm;lispsm;csm" "150;150;150;150")
four_up_case(four_up_mixed four_up_mixed "hybrid;volumes;csm;uniform" "300;150;150;150")

# Every frame of the views whose lit pass is not the lesson's own gets a --bench row (frame_bench
# found none for frames 1-3 of these: the four-up view switched the timers off, and the cascades'
# colouring pass drew untimed while their maps were kept): check_bench_frames.cmake.
function(bench_frames_case name preset passes)
  add_test(NAME gpu.10_showdown.bench_frames.${name} COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_10_showdown>
           -DPRESET=${preset} -DFRAMES=4 -DOUT=${showdown_out}/bench_frames_${name}.csv "-DPASSES=${passes}"
           -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_bench_frames.cmake)
  set_tests_properties(gpu.10_showdown.bench_frames.${name} PROPERTIES LABELS gpu TIMEOUT 120)
endfunction()
bench_frames_case(four_up four_up "^quarter 3: csm$")
bench_frames_case(four_up_mixed four_up_mixed "^quarter 1: volumes$")
bench_frames_case(csm_colours csm_colours "^scene$")

# The four-up view's labels and its refusal to be measured as one picture (check_four_up_ui.cmake).
if(TARGET lesson_10_showdown)
  add_test(NAME gpu.showdown.four_up_ui COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_10_showdown>
           -DOUT_DIR=${CMAKE_BINARY_DIR}/test-showdown/four_up_ui -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_four_up_ui.cmake)
  set_tests_properties(gpu.showdown.four_up_ui PROPERTIES LABELS gpu)
endif()
