# The teaching moments (issue 36): each before/after pair of tests/data/moments.txt rendered by its
# lesson in the lit picture must differ where the moment is (tests/gpu/moment_check.cpp says how).
# One test per lesson with moments, label gpu; the controls prove the check can fail.
if(SHADOWLAB_UNIT_ONLY)
  return()
endif()
add_executable(moment_check ${CMAKE_CURRENT_SOURCE_DIR}/gpu/moment_check.cpp)
target_link_libraries(moment_check PRIVATE shadowlab_core)

set(moments_file ${CMAKE_CURRENT_SOURCE_DIR}/data/moments.txt)
set(moments_out ${CMAKE_BINARY_DIR}/test-screenshots/moments)
file(STRINGS ${moments_file} moment_lines REGEX "^[0-9][0-9]_[a-z_]+ *\\|")
set(moment_lessons "")
foreach(line IN LISTS moment_lines)
  string(REGEX MATCH "^[0-9][0-9]_[a-z_]+" lesson "${line}")
  list(APPEND moment_lessons ${lesson})
endforeach()
list(REMOVE_DUPLICATES moment_lessons)
foreach(lesson IN LISTS moment_lessons)
  if(NOT TARGET lesson_${lesson})
    message(FATAL_ERROR "${moments_file}: no lesson '${lesson}' (lessons: ${SHADOWLAB_LESSONS})")
  endif()
  add_test(NAME gpu.${lesson}.moments
           COMMAND moment_check ${moments_file} $<TARGET_FILE_DIR:lesson_${lesson}> ${moments_out} --lesson ${lesson})
  set_tests_properties(gpu.${lesson}.moments PROPERTIES LABELS gpu TIMEOUT 600)
endforeach()

# Controls: a pair whose switch changes nothing on screen (lesson 03 keeping or redrawing its maps)
# fails with the share it measured; a malformed line is named by file and line.
if(TARGET lesson_03_shadow_quality)
  add_test(NAME gpu.moments.control
           COMMAND moment_check ${CMAKE_CURRENT_SOURCE_DIR}/support/moments_control.txt
                   $<TARGET_FILE_DIR:lesson_03_shadow_quality> ${moments_out}/control)
  set_tests_properties(gpu.moments.control PROPERTIES LABELS gpu TIMEOUT 300
    PASS_REGULAR_EXPRESSION "FAIL: .*moments_control.txt:2 \\(nothing changes\\): 0.0 % of the region changes \\(at least 1.0 % expected\\)")
  add_test(NAME gpu.moments.malformed
           COMMAND moment_check ${CMAKE_CURRENT_SOURCE_DIR}/support/moments_bad.txt
                   $<TARGET_FILE_DIR:lesson_03_shadow_quality> ${moments_out}/bad)
  set_tests_properties(gpu.moments.malformed PROPERTIES LABELS gpu
    PASS_REGULAR_EXPRESSION "FAIL: .*moments_bad.txt:2: the region must be 0 <= x0 < x1 <= 1")
endif()
