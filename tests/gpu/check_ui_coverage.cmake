# The picture first: with the UI shown as a lesson starts (the compact header, the parameter panel
# and the exercises as title bars, no stats), the UI covers at most 25 % of the window, so the 3D
# view keeps at least 75 %, at 1280x720 and 1920x1080, UI scales 1 and 2 (a projector's). The share
# is the sum of the UI's rectangles from --ui-layout (overlaps counted twice: an upper bound); the
# views the lesson draws into corners (insets) are picture, not UI. The control: with the panel and
# the stats open (F3, F2) the same sum must exceed the bound at UI scale 2 on 1280x720, so a sum
# that cannot grow would fail here.
# Run: cmake -DLESSON=<program> -DOUT_DIR=... -P this
include(${CMAKE_CURRENT_LIST_DIR}/ui_layout_lib.cmake)
file(MAKE_DIRECTORY ${OUT_DIR})
get_filename_component(name ${LESSON} NAME)

# ui_share(JSON OUT): the UI's share of the window, in per mille.
function(ui_share json out)
  string(JSON vw GET "${json}" viewport 0)
  string(JSON vh GET "${json}" viewport 1)
  string(JSON n LENGTH "${json}" windows)
  math(EXPR last "${n} - 1")
  set(area 0)
  set(parts "")
  foreach(i RANGE ${last})
    string(JSON w_name GET "${json}" windows ${i} name)
    # Insets are views of the scene; "Parameters content/widgets" are measures inside the panel.
    if(w_name MATCHES "inset$" OR w_name MATCHES "^Parameters (content|widgets)$")
      continue()
    endif()
    string(JSON w GET "${json}" windows ${i} w)
    string(JSON h GET "${json}" windows ${i} h)
    truncate("${w} * ${h}" a)
    math(EXPR area "${area} + ${a}")
    string(APPEND parts " ${w_name}=${w}x${h}")
  endforeach()
  math(EXPR share "1000 * ${area} / (${vw} * ${vh})")
  set(${out} ${share} PARENT_SCOPE)
  set(${out}_parts "${parts}" PARENT_SCOPE)
endfunction()

foreach(config "1280x720;1" "1280x720;2" "1920x1080;1" "1920x1080;2")
  list(GET config 0 size)
  list(GET config 1 scale)
  layout(cover_${name}_${size}_${scale} --size ${size} --ui-scale ${scale} --show-ui)
  ui_share("${json}" share)
  message(STATUS "${name} ${size} UI scale ${scale}: the UI covers ${share} per mille:${share_parts}")
  if(share GREATER 250)
    message(FATAL_ERROR "${name} at ${size}, UI scale ${scale}: the UI covers ${share} per mille of the window "
                        "(at most 250: the picture keeps 75 %):${share_parts}")
  endif()
endforeach()

layout(cover_${name}_open --size 1280x720 --ui-scale 2 --show-panel --show-stats)
ui_share("${json}" open)
if(NOT open GREATER 250)
  message(FATAL_ERROR "the control: with the panel and the stats open the UI should cover more than 250 per mille, "
                      "got ${open}:${open_parts}")
endif()
message(STATUS "control: panel and stats open, ${open} per mille")
