# Measurement (common/measure): the report page check (label: web). The unit tests of the module
# live in tests/unit/test_measure_*.cpp (label: unit).
#   measure.report_demo   writes a small report with tools/measure_report_demo.cpp (fixture)
#   measure.report_page   opens it in headless Chromium (tools/web/check-page.mjs): no console
#                         error, no request off the page, every thumbnail loaded
# Needs node, the npm packages (npm ci --prefix tools/web) and /usr/bin/chromium.

add_executable(measure_report_demo ${CMAKE_SOURCE_DIR}/tools/measure_report_demo.cpp)
target_link_libraries(measure_report_demo PRIVATE shadowlab_measure)

find_program(NODE node)
if(NOT NODE OR NOT EXISTS ${CMAKE_SOURCE_DIR}/tools/web/check-page.mjs)
  message(STATUS "measure tests: node or tools/web/check-page.mjs missing; report page check not registered")
  return()
endif()

set(MEASURE_REPORT_OUT ${CMAKE_BINARY_DIR}/measure_report_demo)
add_test(NAME measure.report_demo
  COMMAND measure_report_demo ${MEASURE_REPORT_OUT})
set_tests_properties(measure.report_demo PROPERTIES LABELS web FIXTURES_SETUP measure_report TIMEOUT 120)
add_test(NAME measure.report_page
  COMMAND ${NODE} ${CMAKE_SOURCE_DIR}/tools/web/check-page.mjs ${MEASURE_REPORT_OUT}/report.html
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(measure.report_page PROPERTIES LABELS web FIXTURES_REQUIRED measure_report TIMEOUT 120)

# The reference overlay shows the visibility it measured: lesson 05's penumbrae (mid-grey values)
# drawn by measure.overlay=reference match, pixel for pixel, the visibility image --measure writes
# (FILE_reference.png); an overlay uploaded as sRGB was decoded once more and drawn darker.
if(TARGET lesson_05_soft_shadows)
  add_executable(overlay_compare ${CMAKE_CURRENT_SOURCE_DIR}/gpu/overlay_compare.cpp)
  target_link_libraries(overlay_compare PRIVATE shadowlab_core)
  set(overlay_out ${CMAKE_BINARY_DIR}/test-measure/overlay)
  add_test(NAME gpu.measure.reference_overlay_values
           COMMAND ${CMAKE_COMMAND} -E chdir ${CMAKE_BINARY_DIR}
                   sh -c "mkdir -p '${overlay_out}' && '$<TARGET_FILE:lesson_05_soft_shadows>' --headless --strict-gl --size 320x180 --frames 3 --set measure.overlay=reference --measure '${overlay_out}/m.json' --screenshot '${overlay_out}/shot.png' && '$<TARGET_FILE:overlay_compare>' '${overlay_out}/shot.png' '${overlay_out}/m_reference.png'")
  set_tests_properties(gpu.measure.reference_overlay_values PROPERTIES LABELS gpu)
endif()
