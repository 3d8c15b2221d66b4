# A doctest binary run with a filter that matches none of its cases must exit non-zero and say
# so; and the same binary run on a name holding ';' must run exactly that one case.
execute_process(COMMAND ${BIN} "--test-case=registration fixture: a name with a semicolon"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "a filter matching no case passed (exit 0):\n${out}${err}")
endif()
if(NOT "${err}" MATCHES "no test case ran")
  message(FATAL_ERROR "the zero-case failure does not say why:\n${out}${err}")
endif()
execute_process(COMMAND ${BIN} "--test-case=registration fixture: a name with a semicolon; kept whole"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT "${out}" MATCHES "test cases: +1 \\| +1 passed")
  message(FATAL_ERROR "the ';' name did not run exactly one passing case (exit ${rc}):\n${out}${err}")
endif()
message(STATUS "zero-case runs fail; the ';' name runs one case")
