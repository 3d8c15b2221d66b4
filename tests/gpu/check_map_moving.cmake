# The other half of map reuse (check_map_reuse.cmake): under a light that moves on every frame of a
# replayed path, a lesson draws its maps in every frame with reuse on, and its last picture is byte
# for byte the one with reuse off. LESSON, PATH, REUSE (the switch), ROWS (timed shadow passes per
# frame), NAME, OUT_DIR, and optionally PRESET and SET (one more parameter, "name=value").
# Run: cmake -DLESSON=... -DPATH=... -DREUSE=... -DROWS=... -DNAME=... -DOUT_DIR=... [-DPRESET=...]
#      [-DSET=...] -P this
cmake_policy(VERSION 3.20)
if(NOT DEFINED PRESET)
  set(PRESET default)
endif()
set(frames 6)
set(extra)
if(DEFINED SET)
  set(extra --set ${SET})
endif()
file(MAKE_DIRECTORY ${OUT_DIR})
foreach(reuse true false)
  execute_process(COMMAND ${LESSON} --headless --frames ${frames} --size 320x180 --strict-gl --preset ${PRESET}
                          --replay ${PATH} ${extra} --set ${REUSE}=${reuse} --bench ${OUT_DIR}/${NAME}_${reuse}.csv
                          --screenshot ${OUT_DIR}/${NAME}_${reuse}.png
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${REUSE}=${reuse}: lesson exited ${rc}: ${err}")
  endif()
  file(STRINGS ${OUT_DIR}/${NAME}_${reuse}.csv rows REGEX ",shadow light[0-9]+,")
  list(LENGTH rows n)
  math(EXPR every "${frames} * ${ROWS}")
  if(NOT n EQUAL every)
    message(FATAL_ERROR "${REUSE}=${reuse}: ${n} shadow passes over ${frames} frames of a moving light, expected ${every}")
  endif()
endforeach()
file(SHA256 ${OUT_DIR}/${NAME}_true.png a)
file(SHA256 ${OUT_DIR}/${NAME}_false.png b)
if(NOT a STREQUAL b)
  message(FATAL_ERROR "under a moving light the picture with ${REUSE}=true differs from the one with false")
endif()
message(STATUS "a moving light: maps drawn in all ${frames} frames either way, the same last picture")
