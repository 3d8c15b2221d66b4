# Runs LESSON with ARGS (a ;-list; default --headless --exercises); it must exit 0 and print a
# line matching EXPECT (a regex) on stdout.
if(NOT ARGS)
  set(ARGS --headless --exercises)
endif()
execute_process(COMMAND ${LESSON} ${ARGS} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${ARGS} exited ${rc}:\n${out}${err}")
endif()
if(NOT out MATCHES "${EXPECT}")
  message(FATAL_ERROR "${ARGS} printed nothing matching '${EXPECT}':\n${out}")
endif()
message(STATUS "${out}")
