# Every inset a lesson reports (Lesson::insets: its map views, the post-projective view, the god
# view) stays clear of the header, the parameter panel and the exercises panel, at --ui-scale 1
# and 2 on 1280x720; and at least EXPECT insets are reported (a lesson that stops reporting them
# fails here).
# Run: cmake -DLESSON=... -DNAME=... "-DARGS=--set;view=maps;..." -DEXPECT=N -DOUT_DIR=... -P this
include(${CMAKE_CURRENT_LIST_DIR}/ui_layout_lib.cmake)
file(MAKE_DIRECTORY ${OUT_DIR})
foreach(scale 1 2)
  layout(${NAME}_insets_${scale} --size 1280x720 --show-ui --ui-scale ${scale} ${ARGS})
  string(JSON n LENGTH "${json}" windows)
  math(EXPR last "${n} - 1")
  set(insets 0)
  foreach(i RANGE ${last})
    string(JSON name GET "${json}" windows ${i} name)
    if(name MATCHES "inset$|view$")
      check_apart("${json}" "${name}" shadowlab)
      check_apart("${json}" "${name}" Parameters)
      has("${json}" Exercises exercises)  # the exercises panel (bottom left) stops above them too
      if(exercises)
        check_apart("${json}" "${name}" Exercises)
      endif()
      check_inside("${json}" "${name}" 1280 720)
      math(EXPR insets "${insets} + 1")
    endif()
  endforeach()
  if(insets LESS EXPECT)
    message(FATAL_ERROR "${NAME} at --ui-scale ${scale}: ${insets} insets reported, ${EXPECT} expected: ${json}")
  endif()
  message(STATUS "${NAME} at --ui-scale ${scale}: ${insets} insets clear of the header and the panel")
endforeach()
