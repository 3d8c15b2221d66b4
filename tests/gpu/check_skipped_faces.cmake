# Lesson 03's point_light preset shows what it promises: faces of the cube map that cannot shade a
# visible pixel are skipped, and how many depends on where the camera looks (its README: "orbit, and
# the header's skipped cube faces change"); the old preset put the light inside the view and the
# count stayed 0 at every angle.
# Run: cmake -DLESSON=<lesson 03> -DOUT_DIR=... -P this
file(MAKE_DIRECTORY ${OUT_DIR})
function(skipped yaw out)
  execute_process(COMMAND ${LESSON} --headless --strict-gl --size 160x90 --frames 2 --preset point_light
                          --set camera.yaw=${yaw} --measure ${OUT_DIR}/faces_${yaw}.json
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "point_light at yaw ${yaw}: exit ${rc}: ${err}")
  endif()
  file(READ ${OUT_DIR}/faces_${yaw}.json json)
  string(JSON n GET "${json}" counters "cube faces skipped")
  set(${out} ${n} PARENT_SCOPE)
endfunction()
skipped(0.6 preset)
skipped(1.6 toward)
if(preset LESS 2 OR NOT toward LESS preset)
  message(FATAL_ERROR "cube faces skipped: ${preset} at the preset's yaw (want 2 or more), ${toward} turned toward "
                      "the light (want fewer)")
endif()
message(STATUS "cube faces skipped: ${preset} at the preset's camera, ${toward} turned toward the light")
