# Shared by the check_hybrid_*.cmake scripts: run lesson 07 headless with --measure and read figures.
# hybrid_run(NAME args...) writes ${OUT_DIR}/NAME.json and sets NAME_json in the caller's scope.
function(hybrid_run name)
  file(MAKE_DIRECTORY ${OUT_DIR})
  execute_process(COMMAND ${LESSON} --headless --frames 2 --size 480x270 --strict-gl ${ARGN}
                          --measure ${OUT_DIR}/${name}.json
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: lesson 07 exited ${rc}: ${err}")
  endif()
  file(READ ${OUT_DIR}/${name}.json json)
  set(${name}_json "${json}" PARENT_SCOPE)
endfunction()

# hybrid_get(OUT json key...): a JSON value; a counter such as "476005 of 4194304 (11.3 %)" gives
# its first whole number.
function(hybrid_get out json)
  string(JSON value GET "${json}" ${ARGN})
  string(REGEX MATCH "^[0-9]+" number "${value}")
  if(number STREQUAL "")
    set(number "${value}")
  endif()
  set(${out} "${number}" PARENT_SCOPE)
endfunction()

# Misclassified share in millionths of the facing pixels (CMake has integers only).
function(hybrid_ppm out json section)
  string(JSON facing GET "${json}" ${section} ${ARGN} pixels)
  string(JSON wrong GET "${json}" ${section} ${ARGN} misclassified)
  math(EXPR ppm "${wrong} * 1000000 / ${facing}")
  set(${out} ${ppm} PARENT_SCOPE)
endfunction()
