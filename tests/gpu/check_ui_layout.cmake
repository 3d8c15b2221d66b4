# The UI leaves the picture and itself visible (issue 19), checked on the rectangles the lesson
# reports with --ui-layout:
# - --show-help draws the F1 help (headless screenshots for slides and docs); --show-ui alone does not
#   (the control);
# - at --ui-scale 2 on 1280x720 the header and the parameter panel do not overlap and stay inside
#   the frame; with the A/B split on, neither covers the split's labels; neither covers the god view
#   or lesson 02's map inset; a heatmap's legend appears with it, clear of both.
# Run: cmake -DLESSON=<lesson 03> -DLESSON02=<lesson 02> -DOUT_DIR=... -P this
function(layout name)
  execute_process(COMMAND ${LESSON} --headless --frames 2 --strict-gl ${ARGN} --ui-layout ${OUT_DIR}/layout_${name}.json
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: lesson exited ${rc}: ${err}")
  endif()
  file(READ ${OUT_DIR}/layout_${name}.json json)
  set(json "${json}" PARENT_SCOPE)
endfunction()

# rect(JSON NAME PREFIX): PREFIX_x0 _y0 _x1 _y1 of the window NAME, or FATAL_ERROR if absent.
function(rect json name prefix)
  string(JSON n LENGTH "${json}" windows)
  math(EXPR last "${n} - 1")
  foreach(i RANGE ${last})
    string(JSON w_name GET "${json}" windows ${i} name)
    if(w_name STREQUAL name)
      foreach(k x y w h)
        string(JSON ${k} GET "${json}" windows ${i} ${k})
      endforeach()
      set(${prefix}_x0 ${x} PARENT_SCOPE)
      set(${prefix}_y0 ${y} PARENT_SCOPE)
      set(${prefix}_x1 "${x} + ${w}" PARENT_SCOPE)
      set(${prefix}_y1 "${y} + ${h}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  message(FATAL_ERROR "no window '${name}' in the layout: ${json}")
endfunction()

function(has json name out)
  string(FIND "${json}" "\"name\": \"${name}\"" at)
  if(at EQUAL -1)
    set(${out} FALSE PARENT_SCOPE)
  else()
    set(${out} TRUE PARENT_SCOPE)
  endif()
endfunction()

# Rectangles as floats: compare through math(EXPR) on integers (truncated; a pixel does not matter).
function(truncate expr out)
  string(REGEX REPLACE "\\.[0-9]+" "" expr "${expr}")
  math(EXPR v "${expr}")
  set(${out} ${v} PARENT_SCOPE)
endfunction()

function(check_apart json a b)
  rect("${json}" "${a}" A)
  rect("${json}" "${b}" B)
  foreach(v A_x0 A_y0 A_x1 A_y1 B_x0 B_y0 B_x1 B_y1)
    truncate("${${v}}" ${v})
  endforeach()
  if(A_x0 LESS B_x1 AND B_x0 LESS A_x1 AND A_y0 LESS B_y1 AND B_y0 LESS A_y1)
    message(FATAL_ERROR "'${a}' (${A_x0},${A_y0})-(${A_x1},${A_y1}) overlaps '${b}' (${B_x0},${B_y0})-(${B_x1},${B_y1})")
  endif()
endfunction()

function(check_inside json name width height)
  rect("${json}" "${name}" R)
  foreach(v R_x0 R_y0 R_x1 R_y1)
    truncate("${${v}}" ${v})
  endforeach()
  if(R_x0 LESS 0 OR R_y0 LESS 0 OR R_x1 GREATER width OR R_y1 GREATER height)
    message(FATAL_ERROR "'${name}' (${R_x0},${R_y0})-(${R_x1},${R_y1}) leaves the ${width}x${height} frame")
  endif()
endfunction()

file(MAKE_DIRECTORY ${OUT_DIR})
layout(ui --size 640x360 --show-ui)
has("${json}" "Help (F1)" help_without)
layout(help --size 640x360 --show-help)
has("${json}" "Help (F1)" help_with)
if(help_without OR NOT help_with)
  message(FATAL_ERROR "--show-help: help window with the flag ${help_with}, without it ${help_without} (want TRUE, FALSE)")
endif()

layout(scale2 --size 1280x720 --show-ui --ui-scale 2)
check_apart("${json}" shadowlab Parameters)
check_inside("${json}" shadowlab 1280 720)
check_inside("${json}" Parameters 1280 720)

layout(split --size 1280x720 --show-ui --preset versus_volumes)
check_apart("${json}" Parameters "A label")
check_apart("${json}" Parameters "B label")
check_apart("${json}" shadowlab "A label")
check_apart("${json}" shadowlab "B label")

# The insets: lesson 03's god view and lesson 02's shadow map stay clear of the header and panel,
# at the default UI scale and at 2.
foreach(scale 1 2)
  layout(god_${scale} --size 1280x720 --show-ui --ui-scale ${scale} --set view.god=true)
  check_apart("${json}" Parameters "god view inset")
  check_apart("${json}" shadowlab "god view inset")
endforeach()
# Heatmaps carry a colour key (the aliasing overlay: m's scale), clear of the header and the panel.
foreach(scale 1 2)
  layout(legend_${scale} --size 1280x720 --show-ui --ui-scale ${scale} --set measure.overlay=aliasing)
  check_apart("${json}" Legend shadowlab)
  check_apart("${json}" Legend Parameters)
  check_inside("${json}" Legend 1280 720)
endforeach()
has("${json}" Legend legend_with)
layout(no_legend --size 640x360 --show-ui)
has("${json}" Legend legend_without)
if(legend_without OR NOT legend_with)
  message(FATAL_ERROR "legend with an overlay ${legend_with}, without one ${legend_without} (want TRUE, FALSE)")
endif()

set(LESSON ${LESSON02})
layout(map_inset --size 1280x720 --show-ui)
check_apart("${json}" Parameters "shadow-map inset")
check_apart("${json}" shadowlab "shadow-map inset")
