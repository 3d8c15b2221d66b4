# validity.exNN_glsl.mutant_*: a submission that is the reference GLSL with one known slip (FROM
# replaced by TO, e.g. the receiver-plane term left out of the PCF kernel) must fail the case named
# EXPECT: the proof that that case sees the slip. -DGRADER -DLESSON_BINARY -DLESSON -DSOURCE -DOUT
# -DFROM -DTO -DEXPECT.
set(sub ${OUT}/submission/shaders/${LESSON})
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${sub})
file(READ ${SOURCE}/shaders/${LESSON}/exercises_reference.glsl text)
string(FIND "${text}" "${FROM}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "'${FROM}' is not in the reference GLSL of ${LESSON}: the mutant would be the reference")
endif()
string(REPLACE "${FROM}" "${TO}" text "${text}")
file(WRITE ${sub}/exercises.glsl "${text}")
execute_process(COMMAND ${GRADER} --lesson-binary=${LESSON_BINARY} --student=${OUT}/submission
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(FIND "${out}" "FAILED: ${EXPECT}" failed)
if(NOT rc EQUAL 1 OR failed EQUAL -1)
  message(FATAL_ERROR "the reference with '${FROM}' -> '${TO}' did not fail '${EXPECT}' (exit ${rc}):\n${out}${err}")
endif()
message(STATUS "the reference with '${FROM}' -> '${TO}' fails '${EXPECT}'")
