# validity.exNN.stubs_seeds: GRADER --expect-stub-scores-zero --seed=S for every S in FIRST..LAST.
# A grading run draws its seed at random (tools/grading/grade_submission.sh), so no seed may let
# the untouched stub pass a random hidden case; validity.exNN.stubs checks one seed only.
#   cmake -DGRADER=grade_exNN -DFIRST=1 -DLAST=40 -P check_stub_seeds.cmake
if(NOT GRADER OR NOT DEFINED FIRST OR NOT DEFINED LAST)
  message(FATAL_ERROR "usage: cmake -DGRADER=PATH -DFIRST=N -DLAST=M -P check_stub_seeds.cmake")
endif()
set(ran 0)
foreach(seed RANGE ${FIRST} ${LAST})
  execute_process(COMMAND ${GRADER} --expect-stub-scores-zero --seed=${seed} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "seed ${seed}: the untouched stub passes a case (replay: ${GRADER} --seed=${seed})\n${err}${out}")
  endif()
  math(EXPR ran "${ran} + 1")
endforeach()
if(ran EQUAL 0)
  message(FATAL_ERROR "no seed ran")
endif()
message(STATUS "${ran} seeds (${FIRST}-${LAST}): the untouched stub scores 0 with each")
