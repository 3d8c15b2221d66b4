# Lesson 04 (stencil shadow volumes) against ground truth: tests/gpu/check_volumes.cmake runs the
# lesson with --measure on fixed presets and asserts the edge-tolerant misclassified share is near
# zero (and that z-pass with the eye inside a volume is caught failing). Label gpu.
if(SHADOWLAB_UNIT_ONLY OR NOT TARGET lesson_04_shadow_volumes)
  return()
endif()
add_test(NAME gpu.04_shadow_volumes.accuracy COMMAND ${CMAKE_COMMAND}
         -DLESSON=$<TARGET_FILE:lesson_04_shadow_volumes> -DOUT_DIR=${CMAKE_BINARY_DIR}/test-screenshots
         -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_volumes.cmake)
set_tests_properties(gpu.04_shadow_volumes.accuracy PROPERTIES LABELS gpu TIMEOUT 600)
