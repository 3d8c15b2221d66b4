# Lesson 10's four-up view, as a room sees it: each quarter's label (its technique, ms, texels,
# triangles, memory) clear of the other labels, the header, the panel and the exercises, and inside
# the frame, at 640x360 and at 1280x720 UI scales 1 and 2. One ground truth cannot judge four
# techniques: with the error overlay on, the header says so (no figures, no overlay, no legend) and
# --measure refuses with the same reason instead of measuring a frame the quarters never wrote
# (it reported 100 % misclassified).
# Run: cmake -DLESSON=<lesson 10> -DOUT_DIR=... -P this
include(${CMAKE_CURRENT_LIST_DIR}/ui_layout_lib.cmake)
file(MAKE_DIRECTORY ${OUT_DIR})
foreach(config "640x360;1" "1280x720;1" "1280x720;2")
  list(GET config 0 size)
  list(GET config 1 scale)
  string(REPLACE "x" ";" wh ${size})
  list(GET wh 0 w)
  list(GET wh 1 h)
  layout(four_up_${size}_${scale} --size ${size} --ui-scale ${scale} --show-ui --preset four_up --set measure.overlay=error)
  foreach(q 0 1 2 3)
    check_inside("${json}" "quarter ${q} label" ${w} ${h})
    foreach(other shadowlab Parameters Exercises)
      check_apart("${json}" "quarter ${q} label" ${other})
    endforeach()
    foreach(r 0 1 2 3)
      if(r GREATER q)
        check_apart("${json}" "quarter ${q} label" "quarter ${r} label")
      endif()
    endforeach()
  endforeach()
  has("${json}" Legend legend)
  if(legend)
    message(FATAL_ERROR "four-up at ${size}: a legend for an overlay that is not drawn")
  endif()
endforeach()
execute_process(COMMAND ${LESSON} --headless --size 320x180 --frames 2 --preset four_up --measure ${OUT_DIR}/four_up_m.json
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "--measure: not in the four-up view \\(four techniques in one frame\\): measure one at a time")
  message(FATAL_ERROR "--measure in the four-up view: want exit 1 with the reason, got ${rc}: ${err}")
endif()
message(STATUS "four-up: labels clear at 640x360 and 1280x720 (UI 1, 2); --measure refused: ${err}")
