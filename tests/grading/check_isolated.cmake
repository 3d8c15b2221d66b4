# grading.isolated (cmake -P): the faulty submission graded one exercise per process.
#   -DISOLATED=grade_isolated -DREPORT=grade_report -DREFERENCE=grade_ex01_reference
#   -DGRADER=grade_fixture_faulty_ex01 -DOUT=DIR
# 01.1 (right) earns all its points; 01.2 (an endless loop) scores 0 as over the time limit; 01.3
# (a crash) scores 0 as crashed with SIGSEGV, naming the case; 01.4 is still a stub; the grade is
# written.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${ISOLATED} --reference=${REFERENCE} --timeout=3 --results-json=${OUT}/ex01.json -- ${GRADER}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "grade_isolated exited ${code}:\n${out}${err}")
endif()
execute_process(COMMAND ${REPORT} --out ${OUT} ${OUT}/ex01.json RESULT_VARIABLE code OUTPUT_VARIABLE report
                ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT EXISTS ${OUT}/score.json OR NOT EXISTS ${OUT}/results.json)
  message(FATAL_ERROR "grade_report exited ${code} or wrote no score.json/results.json:\n${report}${err}")
endif()
file(READ ${OUT}/score.json score)
set(failures "")
macro(expect_points id points stub)
  string(JSON got GET "${score}" exercises ${id} points)
  string(JSON got_stub GET "${score}" exercises ${id} stub)
  if(NOT got EQUAL ${points} OR NOT got_stub STREQUAL "${stub}")
    string(APPEND failures "\n  exercise ${id}: ${got} points (stub ${got_stub}), expected ${points} (stub ${stub})")
  endif()
endmacro()
expect_points(01.1 10 OFF)
expect_points(01.2 0 OFF)
expect_points(01.3 0 OFF)
expect_points(01.4 0 ON)
foreach(reason IN ITEMS "exercise 01.2 did not finish within 3 s (the time limit)"
                        "exercise 01.3 crashed with SIGSEGV (a bad pointer or a stack overflow) in case 'ex01.3: ")
  string(FIND "${report}" "${reason}" at)
  if(at EQUAL -1)
    string(APPEND failures "\n  the report does not say '${reason}'")
  endif()
endforeach()
if(failures)
  message(FATAL_ERROR "the faulty submission was not graded exercise by exercise:${failures}\n${out}\n${report}")
endif()
message(STATUS "graded exercise by exercise:\n${report}")
