# Lesson 07, hybrid-resolution shadow maps, beyond what gpu.cmake gives every lesson (label gpu):
#   hybrid_gpu_tests        the GPU passes word for word against the CPU reference, and the GLSL
#                           descent against hybrid::descend, for every texel (tests/gpu/hybrid_gl.cpp)
#   gpu.hybrid.paths        lesson 07 on the city with build=gpu and build=cpu: the same figures and
#                           counters (the reference drawn live), per criterion and level count
#   gpu.hybrid.standard     levels 0 is a standard map: lesson 03's uniform map (nearest) measures the
#                           same errors; a hybrid map that merged does not
#   gpu.hybrid.goals        the issue's goals on the city against ground truth, at equal source
#                           resolution and at equal memory, and the paper's eps0 = 0.25 as measured
#   gpu.hybrid.student      impl=student on the untouched stubs: a clear error naming exercise 07.2
# The unit tests of the GL-free half (tests/unit/test_hybrid_map.cpp, test_measure_band.cpp) are
# in unit_tests.
if(SHADOWLAB_UNIT_ONLY OR NOT TARGET lesson_07_hybrid_maps)
  return()
endif()

add_executable(hybrid_gpu_tests ${CMAKE_CURRENT_SOURCE_DIR}/gpu/hybrid_gl.cpp)
target_link_libraries(hybrid_gpu_tests PRIVATE shadowlab_test_main shadowlab_07_hybrid_maps)
doctest_discover_tests(hybrid_gpu_tests PROPERTIES LABELS gpu)

set(hybrid_out ${CMAKE_BINARY_DIR}/test-screenshots/hybrid)
foreach(check IN ITEMS paths standard goals)
  add_test(NAME gpu.hybrid.${check} COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_07_hybrid_maps>
           -DOUT_DIR=${hybrid_out}
           -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_hybrid_${check}.cmake)
  set_tests_properties(gpu.hybrid.${check} PROPERTIES LABELS gpu TIMEOUT 900)
endforeach()
add_test(NAME gpu.hybrid.student COMMAND lesson_check $<TARGET_FILE:lesson_07_hybrid_maps> --expect-exit 1
         --expect-stderr "impl=student: sweepLevel returned a 0x0 grid" -- --headless --frames 1 --size 160x90
         --set impl=student)
set_tests_properties(gpu.hybrid.student PROPERTIES LABELS gpu)
