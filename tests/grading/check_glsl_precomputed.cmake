# validity.exNN_glsl.precomputed: the student handout grades GLSL against what the instructor's
# tree recorded (grade_exNN_glsl --record-reference, which make handout runs), since it withholds
# the reference GLSL. Here: record, then the reference file as the student's against the recording
# passes every public case and render; with one recorded value or image changed it fails that case:
# the recording is what decides. -DGRADER -DLESSON_BINARY -DLESSON -DOUT.
file(REMOVE_RECURSE ${OUT})
# grade(WANT_EXIT WHAT args...): the grader at the default seed, its exit checked; its stdout in `out`.
function(grade want what)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=SHADOWLAB_SEED ${GRADER} --lesson-binary=${LESSON_BINARY}
                          ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL want)
    message(FATAL_ERROR "${what}: exit ${rc}, expected ${want}:\n${out}${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()
grade(0 "--record-reference" --record-reference=${OUT}/recorded)
file(READ ${OUT}/recorded/${LESSON}.json recording)
string(JSON values LENGTH "${recording}" cases)
string(JSON renders LENGTH "${recording}" renders)
if(values EQUAL 0 AND renders EQUAL 0)
  message(FATAL_ERROR "the recording holds no value and no render:\n${recording}")
endif()

grade(0 "the reference GLSL against its own recording" --student=reference --precomputed=${OUT}/recorded
      --score-json=${OUT}/score.json)
file(READ ${OUT}/score.json score)
string(JSON cases GET "${score}" cases)
string(JSON failed GET "${score}" cases_failed)
if(cases EQUAL 0 OR NOT failed EQUAL 0 OR score MATCHES "\"hidden_(passed|failed)\": [1-9]")
  message(FATAL_ERROR "against the recording: ${failed} of ${cases} cases failed, or hidden cases ran:\n${score}")
endif()

# One recorded value changed (or, with none, the first render's image swapped for another's).
file(COPY ${OUT}/recorded/ DESTINATION ${OUT}/tampered)
if(values GREATER 0)
  string(JSON victim GET "${recording}" cases 0 name)
  string(JSON tampered SET "${recording}" cases 0 value "[9, 9, 9, 9]")
  file(WRITE ${OUT}/tampered/${LESSON}.json "${tampered}")
elseif(renders GREATER 1)
  string(JSON victim GET "${recording}" renders 0 name)
  string(JSON other GET "${recording}" renders 1 image)
  string(JSON tampered SET "${recording}" renders 0 image "\"${other}\"")
  file(WRITE ${OUT}/tampered/${LESSON}.json "${tampered}")
else()
  message(FATAL_ERROR "nothing to tamper with in the recording of ${LESSON}")
endif()
grade(1 "the reference against a recording with '${victim}' tampered" --student=reference
      --precomputed=${OUT}/tampered)
string(FIND "${out}" "FAILED: ${victim}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "with '${victim}' tampered in the recording the grade did not fail that case:\n${out}")
endif()
message(STATUS "${LESSON}: ${values} recorded values and ${renders} recorded renders grade the reference "
               "${cases} of ${cases} public cases; a tampered recording fails '${victim}'")
