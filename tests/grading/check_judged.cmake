# validity.exNN.judged (cmake -P): the trust boundary grades like the graders themselves.
#   -DISOLATED=grade_isolated -DREPORT=grade_report -DREFERENCE=grade_exNN_reference
#   [-DSTUBS=grade_exNN (untouched stubs)] -DSEED=N -DOUT=DIR
# Through grade_isolated (each exercise answered in its own process, judged by the reference
# grader from the recorded answers), the reference answering earns every point, and the untouched
# stubs earn none, each exercise reported as a stub.
file(REMOVE_RECURSE ${OUT})
set(failures "")
function(judge name student)
  execute_process(COMMAND ${ISOLATED} --reference=${REFERENCE} --results-json=${OUT}/${name}/cpp.json -- ${student}
                          --seed=${SEED}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
  execute_process(COMMAND ${REPORT} --out ${OUT}/${name} ${OUT}/${name}/cpp.json RESULT_VARIABLE report_code
                  OUTPUT_VARIABLE report ERROR_VARIABLE report_err)
  if(NOT code EQUAL 0 OR NOT report_code EQUAL 0)
    message(FATAL_ERROR "${name}: grade_isolated exited ${code}, grade_report ${report_code}:\n${out}${err}${report}${report_err}")
  endif()
  file(READ ${OUT}/${name}/score.json json)
  set(score_json "${json}" PARENT_SCOPE)
  set(report "${report}" PARENT_SCOPE)
endfunction()

judge(reference ${REFERENCE})
string(JSON score GET "${score_json}" score)
string(JSON max GET "${score_json}" max_score)
if(NOT score EQUAL max OR max EQUAL 0)
  string(APPEND failures "\n  the reference answering scored ${score} of ${max}:\n${report}")
endif()

if(STUBS)
  judge(stubs ${STUBS})
  string(JSON score GET "${score_json}" score)
  string(JSON count LENGTH "${score_json}" exercises)
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    string(JSON id MEMBER "${score_json}" exercises ${i})
    string(JSON stub GET "${score_json}" exercises ${id} stub)
    if(NOT stub)
      string(APPEND failures "\n  exercise ${id} of the untouched stubs is not reported as a stub")
    endif()
  endforeach()
  if(NOT score EQUAL 0)
    string(APPEND failures "\n  the untouched stubs scored ${score}:\n${report}")
  endif()
endif()
if(failures)
  message(FATAL_ERROR "judged through the trust boundary, the grade differs from the grader's own:${failures}")
endif()
message(STATUS "reference: every point; stubs: 0 (seed ${SEED})")
