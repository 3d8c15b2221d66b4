# A shadow map nothing invalidated is not drawn again (issue: skip what a frame does not need):
# lesson 03 with three static lights over a static scene and an unmoving camera renders each map in
# the first frame only (the --bench CSV has no shadow pass after frame 0, "maps reused" is 3), and
# its picture is byte for byte the one drawn with every map rendered every frame (reuse_maps=false,
# whose CSV must show the passes in every frame: the control).
# The same for another lesson: NAME (file names), PRESET, MAPS (maps drawn in frame 0) and PASSES
# (timed passes per map: lesson 07's hybrid map has its depth pass, index, merge and records) and
# REUSE (the switch's name: csm.reuse_maps in lesson 10), and ROWS where the timed passes are not
# one per map (lesson 05's soft maps: one timed pass per light for all its sample maps).
# The other half with REPLAY (a replayed path whose light moves on every frame): with reuse on, the
# maps are drawn in every frame too, and the last picture is again the one with reuse off. SET adds
# one parameter ("name=value") to both runs.
# Run: cmake -DLESSON=... -DOUT_DIR=... [-DNAME=... -DPRESET=... -DMAPS=... -DPASSES=... -DREUSE=...
#      -DROWS=... -DREPLAY=... -DSET=...] -P this
if(NOT DEFINED NAME)
  set(NAME reuse)
endif()
if(NOT DEFINED PRESET)
  set(PRESET several_lights)
endif()
if(NOT DEFINED MAPS)
  set(MAPS 3)
endif()
if(NOT DEFINED PASSES)
  set(PASSES 1)
endif()
if(NOT DEFINED REUSE)
  set(REUSE reuse_maps)
endif()
set(extra)
if(DEFINED REPLAY)
  list(APPEND extra --replay ${REPLAY})
endif()
if(DEFINED SET)
  list(APPEND extra --set ${SET})
endif()
function(run name)
  execute_process(COMMAND ${LESSON} --headless --frames 6 --size 320x180 --strict-gl --preset ${PRESET} ${extra} ${ARGN}
                          --bench ${OUT_DIR}/${NAME}_${name}.csv --measure ${OUT_DIR}/${NAME}_${name}.json
                          --screenshot ${OUT_DIR}/${NAME}_${name}.png
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: lesson exited ${rc}: ${err}")
  endif()
endfunction()

# How many shadow passes the CSV holds, and how many after the first frame.
function(count_passes name total_var late_var)
  file(STRINGS ${OUT_DIR}/${NAME}_${name}.csv rows REGEX ",(shadow|hybrid [a-z]+) light[0-9]+,")
  list(LENGTH rows total)
  set(late 0)
  foreach(row IN LISTS rows)
    if(NOT row MATCHES "^0,")
      math(EXPR late "${late} + 1")
    endif()
  endforeach()
  set(${total_var} ${total} PARENT_SCOPE)
  set(${late_var} ${late} PARENT_SCOPE)
endfunction()

file(MAKE_DIRECTORY ${OUT_DIR})
run(kept)
run(redrawn --set ${REUSE}=false)
count_passes(kept kept_total kept_late)
count_passes(redrawn redrawn_total redrawn_late)
if(DEFINED ROWS)
  set(once ${ROWS})
else()
  math(EXPR once "${MAPS} * ${PASSES}")
endif()
math(EXPR every "6 * ${once}")
if(DEFINED REPLAY)  # a moving light: drawn in every frame either way
  if(NOT kept_total EQUAL every)
    message(FATAL_ERROR "a moving light: ${kept_total} shadow passes in 6 frames with reuse on (expected ${every})")
  endif()
elseif(NOT kept_total EQUAL once OR NOT kept_late EQUAL 0)
  message(FATAL_ERROR "reused maps: ${kept_total} shadow passes, ${kept_late} after frame 0 (expected ${once} and 0)")
endif()
if(NOT redrawn_total EQUAL every)
  message(FATAL_ERROR "${REUSE}=false: ${redrawn_total} shadow passes in 6 frames (expected ${every}): the control failed")
endif()
if(NOT DEFINED REPLAY)
  file(READ ${OUT_DIR}/${NAME}_kept.json json)
  string(JSON reused GET "${json}" counters "maps reused")
  if(NOT reused EQUAL MAPS)
    message(FATAL_ERROR "the header says ${reused} maps reused, expected ${MAPS}")
  endif()
endif()
file(SHA256 ${OUT_DIR}/${NAME}_kept.png a)
file(SHA256 ${OUT_DIR}/${NAME}_redrawn.png b)
if(NOT a STREQUAL b)
  message(FATAL_ERROR "the picture with reused maps differs from the one redrawn every frame")
endif()
if(DEFINED REPLAY)
  message(STATUS "a moving light: the maps drawn in all 6 frames either way, the same last picture")
else()
  message(STATUS "${MAPS} map(s) drawn once (${PASSES} pass(es) each) and reused for 5 frames; the picture equals the redrawn one")
endif()
