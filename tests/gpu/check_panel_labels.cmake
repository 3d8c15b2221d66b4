# The parameter panel cuts off none of its labels or buttons (the widgets' right edge within the
# panel's visible content, from --ui-layout): every lesson at 640x360 (the narrowest panel) and at
# a projector's UI scale of 2 on 1280x720. ImGui's default widths cut lesson 09's
# "plane_normal_offset" and pushed the presets' "defaults" button off the panel in every lesson.
# Run: cmake "-DLESSONS=<program>;..." -DOUT_DIR=... -P this
include(${CMAKE_CURRENT_LIST_DIR}/ui_layout_lib.cmake)
file(MAKE_DIRECTORY ${OUT_DIR})
foreach(LESSON IN LISTS LESSONS)
  get_filename_component(name ${LESSON} NAME)
  foreach(config "640x360;1" "1280x720;2")
    list(GET config 0 size)
    list(GET config 1 scale)
    layout(panel_${name}_${scale} --size ${size} --ui-scale ${scale} --show-ui)
    check_within("${json}" "Parameters widgets" "Parameters content")
  endforeach()
endforeach()
message(STATUS "panel labels fit in ${LESSONS}")
