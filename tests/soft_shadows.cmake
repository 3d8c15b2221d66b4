# Lesson 05 (soft shadows) and its techniques, against the Embree sphere-light reference (label gpu):
#   gpu.05_soft_shadows.accuracy  every technique's figures a correct implementation must reach,
#                                 each with a control (tests/gpu/check_soft_accuracy.cmake)
#   gpu.05_soft_shadows.forest    many point lights on the forest's leaf cards: the depth pass's
#                                 alpha and offset the README measured (check_soft_forest.cmake)
#   gpu.05_soft_shadows.quad_search  PCSS's search shared by a 2x2 quad: within 10 % of the per-pixel
#                                 search's error, its fallback without fine derivatives, and a
#                                 quad that does not share as the control (check_quad_search.cmake)
#   gpu.05_soft_shadows.point_light  a point light inside the scene: the sample-map techniques' cube
#                                 of six faces, against the spot and low among the casters, VSM's
#                                 "no cube form" as the control (check_soft_cube.cmake)
#   gpu.05_soft_shadows.theory    the predicted half-width, the A_frac figure, the student's code
#                                 driving them, the overlay drawn, the light mesh baked only when
#                                 something moved (tests/gpu/check_soft_theory.cmake)
#   bench.05_soft_shadows         the benchmark runner's soft columns along the committed path
# The unit tests of the maths (tests/unit/test_soft_*.cpp) are part of unit_tests.
if(SHADOWLAB_UNIT_ONLY OR NOT TARGET lesson_05_soft_shadows)
  return()
endif()
set(soft_out ${CMAKE_BINARY_DIR}/test-screenshots/soft)
add_test(NAME gpu.05_soft_shadows.accuracy COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_05_soft_shadows>
         -DOUT_DIR=${soft_out} -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_soft_accuracy.cmake)
add_test(NAME gpu.05_soft_shadows.forest COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_05_soft_shadows>
         -DOUT_DIR=${soft_out} -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_soft_forest.cmake)
add_test(NAME gpu.05_soft_shadows.point_light COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_05_soft_shadows>
         -DOUT_DIR=${soft_out} -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_soft_cube.cmake)
add_test(NAME gpu.05_soft_shadows.quad_search COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_05_soft_shadows>
         -DSOURCE_DIR=${CMAKE_SOURCE_DIR} -DOUT_DIR=${soft_out} -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_quad_search.cmake)
# The student's code drives the overlays: checked on the untouched stubs only (a student's own
# exercises give their own figures).
set(stub ${CMAKE_SOURCE_DIR}/lessons/05_soft_shadows/exercises.cpp)
file(SHA256 ${stub} stub_hash)
file(READ ${CMAKE_CURRENT_SOURCE_DIR}/grading/pristine.sha256 pristine)
string(FIND "${pristine}" "${stub_hash}  lessons/05_soft_shadows/exercises.cpp" found)
if(found GREATER -1)
  set(stubs_pristine ON)
else()
  set(stubs_pristine OFF)
endif()
add_test(NAME gpu.05_soft_shadows.theory COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_05_soft_shadows>
         -DOUT_DIR=${soft_out} -DSTUBS_PRISTINE=${stubs_pristine}
         -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_soft_theory.cmake)
set_tests_properties(gpu.05_soft_shadows.accuracy gpu.05_soft_shadows.forest gpu.05_soft_shadows.point_light
                     gpu.05_soft_shadows.quad_search
                     gpu.05_soft_shadows.theory PROPERTIES LABELS gpu TIMEOUT 600)
if(TARGET shadowlab_bench)
  add_test(NAME bench.05_soft_shadows COMMAND ${CMAKE_COMMAND} -DBENCH=$<TARGET_FILE:shadowlab_bench>
           -DLESSON=$<TARGET_FILE:lesson_05_soft_shadows> -DPATH_FILE=${CMAKE_SOURCE_DIR}/bench/paths/soft_showcase.path
           -DDIR=${CMAKE_BINARY_DIR}/test-bench-soft -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_soft_bench.cmake)
  set_tests_properties(bench.05_soft_shadows PROPERTIES LABELS gpu TIMEOUT 600)
endif()
