# grading.tamper (cmake -P): a submission that forges its grade.
#   -DISOLATED=grade_isolated -DREPORT=grade_report -DREFERENCE=grade_ex01_reference
#   -DGRADER=grade_fixture_tamper_ex01 (lesson 01's stubs and grading/fixtures/tamper/tamper.cpp) -DOUT=DIR
# 1. The forgery is real: run as a plain grader (its own --results-json), the stubs score 40 / 40.
# 2. The trust boundary holds: graded by grade_isolated, they score 0 / 40, every exercise a stub,
#    also after the process the forger left behind had time to strike again.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT}/direct ${OUT}/isolated)

function(score dir out_var)
  execute_process(COMMAND ${REPORT} --out ${dir} ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE report ERROR_VARIABLE err)
  if(NOT code EQUAL 0 OR NOT EXISTS ${dir}/score.json)
    message(FATAL_ERROR "grade_report exited ${code}:\n${report}${err}")
  endif()
  file(READ ${dir}/score.json json)
  string(JSON points GET "${json}" score)
  set(${out_var} ${points} PARENT_SCOPE)
  set(last_report "${report}" PARENT_SCOPE)
  set(last_score "${json}" PARENT_SCOPE)
endfunction()

execute_process(COMMAND ${GRADER} --results-json=${OUT}/direct/ex01.json OUTPUT_QUIET ERROR_QUIET TIMEOUT 60)
execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1)
score(${OUT}/direct direct ${OUT}/direct/ex01.json)
if(NOT direct EQUAL 40)
  message(FATAL_ERROR "the fixture did not forge a plain grader's results (${direct} points, expected the forged 40): "
                      "it no longer attacks, so this test would prove nothing\n${last_report}")
endif()

execute_process(COMMAND ${ISOLATED} --reference=${REFERENCE} --results-json=${OUT}/isolated/ex01.json -- ${GRADER}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "grade_isolated exited ${code}:\n${out}${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 4)  # the forger's leftover process strikes for 3 s
score(${OUT}/isolated isolated ${OUT}/isolated/ex01.json)
set(failures "")
if(NOT isolated EQUAL 0)
  string(APPEND failures "\n  the stubs scored ${isolated} points through grade_isolated, expected 0")
endif()
foreach(id IN ITEMS 01.1 01.2 01.3 01.4)
  string(JSON stub GET "${last_score}" exercises ${id} stub)
  if(NOT stub)
    string(APPEND failures "\n  exercise ${id} is not reported as a stub")
  endif()
endforeach()
if(failures)
  message(FATAL_ERROR "a submission forged its grade through grade_isolated:${failures}\n${out}\n${last_report}")
endif()
message(STATUS "forged 40 / 40 as a plain grader; ${isolated} / 40 through grade_isolated:\n${last_report}")
