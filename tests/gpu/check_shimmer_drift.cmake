# The shimmer figures under a moving camera are exact: when the camera moved, the lesson draws the
# frame's shadows once more from the previous camera (Lesson::redrawLit), so each pixel compares
# the very point it showed before ("redrawn" in the JSON). Lesson 03's `stable` (texel snapping on,
# the camera drifting 6 mm a frame) then flips not one pixel, and `shimmer` (the same without
# snapping) flips some every few frames; lesson 10's cascades the same along the city's drift
# (bench/paths/city_drift.path). Lesson 02's spot map, which never follows the camera, and lesson
# 04's stencil volumes, exact wherever the camera is, flip nothing. Lesson 01, which cannot draw
# again, falls back to following points by reprojection ("reprojected").
# Run: cmake -DLESSON01=... -DLESSON02=... -DLESSON03=... -DLESSON04=... -DLESSON10=... -DDRIFT=...
#            -DOUT_DIR=... -P this
function(measure lesson name frames)
  file(GLOB old ${OUT_DIR}/drift_${name}_*)
  if(old)
    file(REMOVE ${old})
  endif()
  execute_process(COMMAND ${lesson} --headless --frames ${frames} --size 320x180 --strict-gl ${ARGN}
                          --measure ${OUT_DIR}/drift_${name}_%d.json
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: lesson exited ${rc}: ${err}")
  endif()
endfunction()

# Sums the extra flips of frames 1..frames-1 into ${out}; each frame must carry temporal figures
# compared the way `how` says (redrawn or reprojected).
function(extra_flips name frames how out)
  set(total 0)
  math(EXPR last "${frames} - 1")
  foreach(frame RANGE 1 ${last})
    file(READ ${OUT_DIR}/drift_${name}_${frame}.json json)
    string(JSON pixels ERROR_VARIABLE missing GET "${json}" temporal pixels)
    if(missing)
      message(FATAL_ERROR "${name}, frame ${frame}: no temporal figures: ${missing}")
    endif()
    string(JSON compared GET "${json}" temporal ${how})
    if(NOT compared STREQUAL "ON" AND NOT compared STREQUAL "true")
      message(FATAL_ERROR "${name}, frame ${frame}: the camera moved but temporal.${how} is ${compared}")
    endif()
    string(JSON extra GET "${json}" temporal extra_flips)
    string(JSON reference GET "${json}" temporal reference_flips)
    if(how STREQUAL "redrawn" AND NOT reference EQUAL 0)
      message(FATAL_ERROR "${name}, frame ${frame}: the same points under a still light, yet the reference flips ${reference}")
    endif()
    if(NOT pixels GREATER 5000)
      message(FATAL_ERROR "${name}, frame ${frame}: only ${pixels} pixels compared")
    endif()
    math(EXPR total "${total} + ${extra}")
  endforeach()
  set(${out} ${total} PARENT_SCOPE)
endfunction()

measure(${LESSON03} l03_stable 6 --preset stable)
measure(${LESSON03} l03_shimmer 6 --preset shimmer)
extra_flips(l03_stable 6 redrawn stable)
extra_flips(l03_shimmer 6 redrawn shimmer)
if(NOT stable EQUAL 0 OR NOT shimmer GREATER 5)
  message(FATAL_ERROR "lesson 03: stable (snapped) flips ${stable} px beyond the reference over 5 frames, shimmer "
                      "(unsnapped) ${shimmer}: snapped edges must stand still and unsnapped ones crawl")
endif()
foreach(snap true false)
  measure(${LESSON10} l10_csm_${snap} 5 --replay ${DRIFT}@0..0.0667 --set technique=csm --set csm.snap=${snap}
          --set texels=1024)
  extra_flips(l10_csm_${snap} 5 redrawn csm_${snap})
endforeach()
if(NOT csm_true EQUAL 0 OR NOT csm_false GREATER 5)
  message(FATAL_ERROR "lesson 10: the snapped cascades flip ${csm_true} px beyond the reference over 4 frames of the "
                      "drift, the unsnapped ${csm_false}: snapped edges must stand still and unsnapped ones crawl")
endif()
foreach(lesson 02 04)
  measure(${LESSON${lesson}} l${lesson} 4 --replay ${DRIFT}@0..0.05)
  extra_flips(l${lesson} 4 redrawn l${lesson})
  if(NOT l${lesson} EQUAL 0)
    message(FATAL_ERROR "lesson ${lesson}: ${l${lesson}} px flip beyond the reference over 3 frames of the drift, "
                        "though its shadows do not depend on the camera")
  endif()
endforeach()
measure(${LESSON01} l01 3 --replay ${DRIFT}@0..0.0333)
extra_flips(l01 3 reprojected l01)
message(STATUS "extra flips over the frames: lesson 03 stable ${stable}, shimmer ${shimmer}; lesson 10 csm snapped "
               "${csm_true}, unsnapped ${csm_false}; lessons 02 and 04: ${l02}, ${l04}; lesson 01 (reprojected) ${l01}")
