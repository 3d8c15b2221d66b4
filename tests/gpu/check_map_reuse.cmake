# A shadow map nothing invalidated is not drawn again (issue: skip what a frame does not need):
# lesson 03 with three static lights over a static scene and an unmoving camera renders each map in
# the first frame only (the --bench CSV has no shadow pass after frame 0, "maps reused" is 3), and
# its picture is byte for byte the one drawn with every map rendered every frame (reuse_maps=false,
# whose CSV must show the passes in every frame: the control).
# Run: cmake -DLESSON=... -DOUT_DIR=... -P this
function(run name)
  execute_process(COMMAND ${LESSON} --headless --frames 6 --size 320x180 --strict-gl --preset several_lights ${ARGN}
                          --bench ${OUT_DIR}/reuse_${name}.csv --measure ${OUT_DIR}/reuse_${name}.json
                          --screenshot ${OUT_DIR}/reuse_${name}.png
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: lesson exited ${rc}: ${err}")
  endif()
endfunction()

# How many shadow passes the CSV holds, and how many after the first frame.
function(count_passes name total_var late_var)
  file(STRINGS ${OUT_DIR}/reuse_${name}.csv rows REGEX ",shadow light[0-9]+,")
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
run(redrawn --set reuse_maps=false)
count_passes(kept kept_total kept_late)
count_passes(redrawn redrawn_total redrawn_late)
if(NOT kept_total EQUAL 3 OR NOT kept_late EQUAL 0)
  message(FATAL_ERROR "reused maps: ${kept_total} shadow passes, ${kept_late} after frame 0 (expected 3 and 0)")
endif()
if(NOT redrawn_total EQUAL 18)
  message(FATAL_ERROR "reuse_maps=false: ${redrawn_total} shadow passes in 6 frames (expected 18): the control failed")
endif()
file(READ ${OUT_DIR}/reuse_kept.json json)
string(JSON reused GET "${json}" counters "maps reused")
if(NOT reused EQUAL 3)
  message(FATAL_ERROR "the header says ${reused} maps reused, expected 3")
endif()
file(SHA256 ${OUT_DIR}/reuse_kept.png a)
file(SHA256 ${OUT_DIR}/reuse_redrawn.png b)
if(NOT a STREQUAL b)
  message(FATAL_ERROR "the picture with reused maps differs from the one redrawn every frame")
endif()
message(STATUS "3 maps drawn once and reused for 5 frames; the picture equals the redrawn one")
