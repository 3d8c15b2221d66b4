# Run by shadowlab_discover_tests after a build: lists EXECUTABLE's doctest cases and writes OUT,
# the ctest file with one add_test per case. A name is never passed through a CMake list (which
# would split it at ';'): the listing's ';' are swapped for a placeholder before the lines are
# split, and the names go into the file as bracket arguments, where ';' is an ordinary character.
execute_process(COMMAND "${EXECUTABLE}" --list-test-cases --no-intro
  OUTPUT_VARIABLE listing RESULT_VARIABLE result WORKING_DIRECTORY "${WORKING_DIR}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "listing the cases of ${EXECUTABLE} failed (${result}):\n${listing}")
endif()
set(semicolon "@SHADOWLAB_SEMICOLON@")
string(REPLACE ";" "${semicolon}" listing "${listing}")
string(REPLACE "\n" ";" lines "${listing}")
set(script "")
set(count 0)
foreach(line IN LISTS lines)
  if(line STREQUAL "" OR line MATCHES "^===+$" OR line MATCHES "^\\[doctest\\] ")
    continue()
  endif()
  string(REPLACE "${semicolon}" ";" name "${line}")
  string(REPLACE "," "\\," filter "${name}")
  string(APPEND script "add_test([==[${name}]==] \"${EXECUTABLE}\" [==[--test-case=${filter}]==])\n")
  string(APPEND script "set_tests_properties([==[${name}]==] PROPERTIES WORKING_DIRECTORY \"${WORKING_DIR}\" LABELS \"${LABELS}\")\n")
  math(EXPR count "${count} + 1")
endforeach()
if(count EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} lists no test cases")
endif()
file(WRITE "${OUT}" "${script}")
