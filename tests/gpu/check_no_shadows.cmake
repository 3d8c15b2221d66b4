# The smallest technique, NoShadows (V = 1), through lesson 03: against ground truth every error
# must be a light leak (no false shadow can come from a technique that shadows nothing), and there
# must be leaks, since the city's towers do shadow the streets.
# Run: cmake -DLESSON=... -DOUT=...json -P this
execute_process(COMMAND ${LESSON} --headless --frames 2 --size 480x270 --strict-gl --set technique=none --measure ${OUT}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "lesson exited ${rc}: ${err}")
endif()
file(READ ${OUT} json)
string(JSON facing GET "${json}" hard facing_pixels)
string(JSON leaks GET "${json}" hard leaks)
string(JSON false_shadows GET "${json}" hard false_shadows)
if(NOT facing GREATER 10000)
  message(FATAL_ERROR "only ${facing} facing pixels: the lit pass left the measurement without depth")
endif()
if(NOT false_shadows EQUAL 0)
  message(FATAL_ERROR "${false_shadows} false shadows from a technique that shadows nothing")
endif()
math(EXPR tenth "${facing} / 20")
if(NOT leaks GREATER tenth)
  message(FATAL_ERROR "only ${leaks} leaks of ${facing} facing pixels: the city's shadows should be 5 % or more")
endif()
message(STATUS "technique=none: ${leaks} leaks, 0 false shadows, of ${facing} facing pixels")
