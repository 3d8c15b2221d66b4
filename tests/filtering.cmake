# Lesson 06's benchmark sweep (tools/filter_sweep.cpp): filter modes, GPU ms against the RMSE and
# flicker of each mode next to a supersampled reference. Kept here, beside the lesson's tests, so
# the shared CMake files stay untouched. `filter_sweep.smoke` runs two modes for a few frames and
# proves the CSV and HTML come out (label gpu); the full sweep is run by hand:
#   build/default/bin/filter_sweep --lesson build/default/bin/lesson_06_texture_filtering --out out/filter_sweep
if(SHADOWLAB_UNIT_ONLY OR NOT TARGET lesson_06_texture_filtering)
  return()
endif()
add_executable(filter_sweep ${PROJECT_SOURCE_DIR}/tools/filter_sweep.cpp)
set(sweep_out ${CMAKE_BINARY_DIR}/test-screenshots/filter_sweep)
add_test(NAME gpu.06_texture_filtering.sweep
         COMMAND ${CMAKE_COMMAND} -DSWEEP=$<TARGET_FILE:filter_sweep> -DLESSON=$<TARGET_FILE:lesson_06_texture_filtering>
                 -DOUT=${sweep_out} -P ${PROJECT_SOURCE_DIR}/tools/filter_sweep_check.cmake)
add_test(NAME cli.06_texture_filtering.sweep_bad_mode
         COMMAND filter_sweep --lesson $<TARGET_FILE:lesson_06_texture_filtering> --out ${sweep_out} --modes bogus)
set_tests_properties(cli.06_texture_filtering.sweep_bad_mode PROPERTIES WILL_FAIL TRUE)
set_tests_properties(gpu.06_texture_filtering.sweep cli.06_texture_filtering.sweep_bad_mode PROPERTIES LABELS gpu)
