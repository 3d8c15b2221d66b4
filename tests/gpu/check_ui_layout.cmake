# The UI leaves the picture and itself visible (issue 19), checked on the rectangles the lesson
# reports with --ui-layout:
# - --show-help draws the F1 help (headless screenshots for slides and docs); --show-ui alone does not
#   (the control);
# - at --ui-scale 2 on 1280x720 the header and the parameter panel do not overlap and stay inside
#   the frame; with the A/B split on, neither covers the split's labels; neither covers the god view
#   or lesson 02's map inset; a heatmap's legend appears with it, clear of both (and of the
#   exercises panel, issue 17).
# Run: cmake -DLESSON=<lesson 03> -DLESSON02=<lesson 02> -DOUT_DIR=... -P this
include(${CMAKE_CURRENT_LIST_DIR}/ui_layout_lib.cmake)

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
  # ...with its colour key (the viewer's frustum, the lights' maps), clear of the inset and the panels.
  check_apart("${json}" Legend "god view inset")
  check_apart("${json}" Legend shadowlab)
  check_apart("${json}" Legend Parameters)
  check_inside("${json}" Legend 1280 720)
endforeach()
# Heatmaps carry a colour key (the aliasing overlay: m's scale), clear of the header and the panel.
foreach(scale 1 2)
  layout(legend_${scale} --size 1280x720 --show-ui --ui-scale ${scale} --set measure.overlay=aliasing)
  check_apart("${json}" Legend shadowlab)
  check_apart("${json}" Legend Parameters)
  check_inside("${json}" Legend 1280 720)
  # Lesson 03's exercises panel (bottom left, collapsed) stays above the legend, clear of the rest.
  check_apart("${json}" Exercises Legend)
  check_apart("${json}" Exercises Parameters)
  check_apart("${json}" Exercises shadowlab)
  check_inside("${json}" Exercises 1280 720)
endforeach()
has("${json}" Legend legend_with)
layout(no_legend --size 640x360 --show-ui)
has("${json}" Legend legend_without)
if(legend_without OR NOT legend_with)
  message(FATAL_ERROR "legend with an overlay ${legend_with}, without one ${legend_without} (want TRUE, FALSE)")
endif()

# The A/B split with the error overlay at a projector's scale: the labels (three lines: what the
# half is, a key figure, its error) clear of the legend, the exercises, the header and the panel.
layout(split_legend --size 1280x720 --show-ui --ui-scale 2 --preset versus_volumes --set measure.overlay=error)
foreach(label "A label" "B label")
  foreach(other Legend Exercises shadowlab Parameters)
    check_apart("${json}" "${label}" ${other})
  endforeach()
  check_inside("${json}" "${label}" 1280 720)
endforeach()
# H hides the panels, not what explains the picture: once, the A/B labels and the legend stay and
# the header, panel and exercises go; twice, everything; a third time brings it all back.
layout(hide_1 --size 640x360 --show-ui --preset versus_volumes --set measure.overlay=error --frames 4 --keys H)
has("${json}" "A label" h1_a)
has("${json}" "B label" h1_b)
foreach(name Legend shadowlab Parameters Exercises)
  has("${json}" ${name} h1_${name})
endforeach()
layout(hide_2 --size 640x360 --show-ui --preset versus_volumes --frames 4 --keys H,H)
has("${json}" "A label" h2_label)
layout(hide_3 --size 640x360 --show-ui --preset versus_volumes --frames 5 --keys H,H,H)
has("${json}" shadowlab h3_header)
if(NOT h1_a OR NOT h1_b OR NOT h1_Legend OR h1_shadowlab OR h1_Parameters OR h1_Exercises OR h2_label OR NOT h3_header)
  message(FATAL_ERROR "H: once, labels ${h1_a}/${h1_b} legend ${h1_Legend} (want TRUE), header ${h1_shadowlab} panel "
                      "${h1_Parameters} exercises ${h1_Exercises} (want FALSE); twice, a label ${h2_label} (want "
                      "FALSE); three times, the header ${h3_header} (want TRUE)")
endif()

set(LESSON ${LESSON02})
layout(map_inset --size 1280x720 --show-ui)
check_apart("${json}" Parameters "shadow-map inset")
check_apart("${json}" shadowlab "shadow-map inset")
