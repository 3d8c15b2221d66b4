# validity.exNN_glsl.compile_error: a submission whose exercises.glsl does not compile must score
# 0 on every GLSL case (exit 1), and the report must carry the compiler's error naming the file.
set(sub ${OUT}/submission/shaders/${LESSON})
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${sub})
file(WRITE ${sub}/exercises.glsl "// a student's file with a typo\nfloat broken( { return 1.0 }\n")
execute_process(COMMAND ${GRADER} --lesson-binary=${LESSON_BINARY} --student=${OUT}/submission
                --score-json=${OUT}/score.json --results-json=${OUT}/results.json
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "expected exit 1 for a file that does not compile, got '${rc}':\n${out}${err}")
endif()
file(READ ${OUT}/score.json score)
string(JSON points GET "${score}" score)
string(JSON cases GET "${score}" cases)
string(JSON failed GET "${score}" cases_failed)
if(NOT points EQUAL 0 OR NOT cases EQUAL failed)
  message(FATAL_ERROR "a file that does not compile scored ${points} (${failed} of ${cases} cases failed)")
endif()
file(READ ${OUT}/results.json results)
if(NOT results MATCHES "does not compile" OR NOT results MATCHES "exercises.glsl:2: error")
  message(FATAL_ERROR "the report does not carry the compile error with file:line:\n${results}")
endif()
# ... and the file it names is the student's, which exists, not the grader's staged copy (deleted).
string(FIND "${results}" "${sub}/exercises.glsl:2: error" at)
if(at EQUAL -1 OR results MATCHES "shadowlab_glsl_")
  message(FATAL_ERROR "the compile error does not name the student's file ${sub}/exercises.glsl:\n${results}")
endif()
message(STATUS "a file that does not compile scores 0 of ${cases} cases, with its error in the report")
