# frame_bench on lesson 01's default view at a small size: exit 0, frames.csv with one row whose
# frame time and floor are positive, and frames.html (the times themselves are not asserted: noisy).
# Then bad input: a lesson --bin does not hold (exit 2, naming the valid ones), and a lesson whose
# runs fail (a stand-in that exits 3: frame_bench exits 1 and names the run, not a 0 ms row).
cmake_policy(VERSION 3.20)
execute_process(COMMAND ${TOOL} --bin ${BIN} --out ${OUT} --lessons 01_lighting --default-only --quick --size 320x180
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "frame_bench exited ${rc}: ${out}${err}")
endif()
file(STRINGS ${OUT}/frames.csv rows)
list(LENGTH rows n)
if(NOT n EQUAL 2)
  message(FATAL_ERROR "expected a header and one row in frames.csv, got:\n${rows}")
endif()
list(GET rows 1 row)
string(REPLACE "," ";" f "${row}")
list(GET f 3 ms)
list(GET f 4 floor)
if(NOT ms GREATER 0 OR NOT floor GREATER 0)
  message(FATAL_ERROR "frame and floor must be positive: ${row}")
endif()
if(NOT EXISTS ${OUT}/frames.html)
  message(FATAL_ERROR "no frames.html")
endif()
message(STATUS "frames.csv: ${row}")

execute_process(COMMAND ${TOOL} --bin ${BIN} --out ${OUT} --lessons 05 --default-only --quick
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "no lesson '05'" OR NOT err MATCHES "valid: .*01_lighting")
  message(FATAL_ERROR "an unknown lesson: expected exit 2 naming the valid ones, got ${rc}: ${out}${err}")
endif()
set(fake ${OUT}/fake_bin)
file(REMOVE_RECURSE ${fake})
file(MAKE_DIRECTORY ${fake})
file(WRITE ${fake}/lesson_00_broken "#!/bin/sh\n[ \"$1\" = --list-presets ] && exit 0\necho broken >&2\nexit 3\n")
file(CHMOD ${fake}/lesson_00_broken PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
execute_process(COMMAND ${TOOL} --bin ${fake} --out ${OUT}/fake --default-only --quick
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "a run failed: .*lesson_00_broken.*exit 3")
  message(FATAL_ERROR "a failing lesson: expected exit 1 naming the run, got ${rc}: ${out}${err}")
endif()
message(STATUS "bad input: an unknown lesson and a failing one are reported")
