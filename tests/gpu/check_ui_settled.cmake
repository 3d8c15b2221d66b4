# A headless screenshot's UI is laid out for that frame's own content: ImGui sizes an auto-fit
# window (the header) from the frame before, and the header of lesson 07's default view gains its
# technique's lines after the first frame, so at --frames 2 it came out a line short (392 against
# 409 px). The header's rectangle at --frames 2 must equal the one at --frames 4 (the same lines).
# Run: cmake -DLESSON=... -DOUT_DIR=... -P this
cmake_policy(VERSION 3.20)
include(${CMAKE_CURRENT_LIST_DIR}/ui_layout_lib.cmake)
foreach(frames 2 4)
  execute_process(COMMAND ${LESSON} --headless --frames ${frames} --strict-gl --show-ui
                          --ui-layout ${OUT_DIR}/layout_settled_${frames}.json RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "--frames ${frames}: lesson exited ${rc}: ${err}")
  endif()
  file(READ ${OUT_DIR}/layout_settled_${frames}.json json)
  rect("${json}" shadowlab h)  # fails the test when the header is missing
  string(JSON n LENGTH "${json}" windows)
  math(EXPR last "${n} - 1")
  foreach(i RANGE ${last})
    string(JSON name GET "${json}" windows ${i} name)
    if(name STREQUAL "shadowlab")
      string(JSON height${frames} GET "${json}" windows ${i} h)
    endif()
  endforeach()
endforeach()
if(NOT height2 STREQUAL height4)
  message(FATAL_ERROR "the header is ${height2} px tall at --frames 2 and ${height4} px at --frames 4: "
                      "the screenshot frame's UI was laid out for the frame before")
endif()
message(STATUS "header ${height2} px at --frames 2 and 4")
