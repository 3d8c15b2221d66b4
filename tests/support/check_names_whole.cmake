# `ctest -N` must list registration_fixture's three cases as three whole entries (no fragment
# of a name split at ';' or ',').
execute_process(COMMAND ${CTEST} -N -R "registration fixture" WORKING_DIRECTORY ${BUILD}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX MATCHALL "Test +#[0-9]+:" entries "${out}")
list(LENGTH entries n)
set(want "registration fixture: a name with a semicolon@SEMI@ kept whole"
         "registration fixture: a name with a comma, kept whole" "registration fixture: a plain name")
foreach(name IN LISTS want)
  string(REPLACE "@SEMI@" ";" name "${name}")
  string(FIND "${out}" ": ${name}\n" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "ctest -N does not list '${name}' whole:\n${out}")
  endif()
endforeach()
if(NOT n EQUAL 3)
  message(FATAL_ERROR "expected 3 entries for registration_fixture, found ${n}:\n${out}")
endif()
message(STATUS "3 whole entries")
