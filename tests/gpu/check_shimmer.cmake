# The temporal (shimmer) figures of --measure, through lesson 09's uniform map: the sun turning
# 0.1 degree a frame over a still camera (bench/paths/sun_turn.path) moves shadows, so from the
# second measured frame on the JSON has a "temporal" block in which the reference flips pixels
# (the shadows truly moved) and the map flips some beyond them (its texels turn with the light);
# the same frames with the sun still flip nothing at all.
# Run: cmake -DLESSON=... -DPATH_FILE=... -DOUT_DIR=... -P this
function(measure name)
  file(GLOB old ${OUT_DIR}/shimmer_${name}_*)
  if(old)
    file(REMOVE ${old})
  endif()
  execute_process(COMMAND ${LESSON} --headless --frames 4 --size 320x180 --strict-gl --set technique=uniform ${ARGN}
                          --measure ${OUT_DIR}/shimmer_${name}_%d.json
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: lesson exited ${rc}: ${err}")
  endif()
endfunction()

measure(turning --replay ${PATH_FILE})
measure(still)
foreach(frame 2 3)
  file(READ ${OUT_DIR}/shimmer_turning_${frame}.json turning)
  string(JSON pixels ERROR_VARIABLE missing GET "${turning}" temporal pixels)
  if(missing)
    message(FATAL_ERROR "frame ${frame} under the turning sun has no temporal figures: ${missing}")
  endif()
  string(JSON reference GET "${turning}" temporal reference_flips)
  string(JSON extra GET "${turning}" temporal extra_flips)
  if(NOT pixels GREATER 10000 OR NOT reference GREATER 50 OR NOT extra GREATER 0)
    message(FATAL_ERROR "frame ${frame} under the turning sun: ${pixels} pixels, the reference flips ${reference}, "
                        "the map ${extra} more: a moving shadow should flip both")
  endif()
  file(READ ${OUT_DIR}/shimmer_still_${frame}.json still)
  string(JSON flips GET "${still}" temporal flips)
  string(JSON reference_still GET "${still}" temporal reference_flips)
  if(NOT flips EQUAL 0 OR NOT reference_still EQUAL 0)
    message(FATAL_ERROR "frame ${frame} with the sun still: ${flips} map flips, ${reference_still} reference flips")
  endif()
  message(STATUS "frame ${frame}: the reference flips ${reference} of ${pixels} px, the map ${extra} more; still: 0")
endforeach()
