# Lesson 04's shadow volumes against ground truth (Embree rays from the very pixels shaded).
# Stencil shadow volumes are pixel exact for hard shadows: away from shadow boundaries no pixel may
# be misclassified, whatever the path (CPU or geometry-shader silhouettes, one- or two-pass
# stencil, infinite far plane or depth clamp, the eye inside a volume with z-fail). Boundary
# pixels are excluded by the edge-tolerant figure (common/measure/metrics.hpp). As a control, z-pass
# with the eye inside a volume must be badly wrong: the check can tell a right answer from a wrong one.
# Run: cmake -DLESSON=... -DOUT_DIR=... -P this
include(${CMAKE_CURRENT_LIST_DIR}/volume_figures.cmake)
function(measure name expect)
  execute_process(COMMAND ${LESSON} --headless --frames 2 --size 480x270 --strict-gl ${ARGN}
                          --measure ${OUT_DIR}/04_volumes_${name}.json
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: lesson exited ${rc}: ${err}")
  endif()
  check_volume_figures(${name} ${expect} ${OUT_DIR}/04_volumes_${name}.json)
endfunction()

file(MAKE_DIRECTORY ${OUT_DIR})
measure(default exact)
measure(gpu_silhouettes exact --set silhouettes=gpu)
measure(two_pass_depth_clamp exact --set two_sided=false --set far=depth_clamp)
measure(point_light exact --set measure.light=1)
measure(camera_in_volume_zfail exact --preset camera_in_volume_zfail)
measure(camera_in_volume_auto exact --preset camera_in_volume --set method=auto)
measure(city exact --preset city)
measure(camera_in_volume_zpass wrong --preset camera_in_volume)
