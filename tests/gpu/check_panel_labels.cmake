# The parameter panel cuts off none of its labels or buttons (the widgets' right edge within the
# panel's visible content, from --ui-layout): every lesson at 640x360 (the narrowest panel) and at
# a projector's UI scale of 2 on 1280x720. ImGui's default widths cut lesson 09's
# "plane_normal_offset" and pushed the presets' "defaults" button off the panel in every lesson.
# At the scale of 2 the F1 help is drawn too and stays inside the frame (its lines ran off it).
# Lesson 05's A_frac plot keeps clear of the header, the panel and the exercises panel (it covered
# the exercises panel at every scale, and the header at 2 on 1280x720).
# Run: cmake "-DLESSONS=<program>;..." -DOUT_DIR=... -P this
include(${CMAKE_CURRENT_LIST_DIR}/ui_layout_lib.cmake)
file(MAKE_DIRECTORY ${OUT_DIR})
foreach(LESSON IN LISTS LESSONS)
  get_filename_component(name ${LESSON} NAME)
  # The panel open (F3: as a title bar it has no widgets to cut); lesson 05's plot on (P: it starts off).
  set(extra --show-panel)
  if(name MATCHES "05_soft_shadows")
    list(APPEND extra --set theory.plot=true)
  endif()
  foreach(config "640x360;1;--show-ui" "1280x720;2;--show-help")
    list(GET config 0 size)
    list(GET config 1 scale)
    list(GET config 2 show)
    layout(panel_${name}_${scale} --size ${size} --ui-scale ${scale} ${show} ${extra})
    check_within("${json}" "Parameters widgets" "Parameters content")
    if(show STREQUAL "--show-help")
      check_inside("${json}" "Help (F1)" 1280 720)
    endif()
    # A lesson's own window (lesson 05's A_frac plot) clear of the framework's.
    has("${json}" "A_frac, the visible fraction" plot)
    if(name MATCHES "05_soft_shadows" AND NOT plot)
      message(FATAL_ERROR "lesson 05 with theory.plot=true draws no A_frac plot")
    endif()
    if(plot)
      foreach(other shadowlab Parameters Exercises)
        check_apart("${json}" "A_frac, the visible fraction" ${other})
      endforeach()
    endif()
  endforeach()
endforeach()
message(STATUS "panel labels fit in ${LESSONS}")
