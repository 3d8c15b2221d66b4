# Helpers of lesson 05's GPU checks (check_soft_*.cmake): run the lesson with --measure, read its
# soft figures, compare them. CMake's if() compares decimal numbers; math() has only integers, so a
# scaled comparison goes through millionths (to_micro).

# Runs the lesson headless at 320x180 with ARGN and --measure, and sets <name>_json in the caller.
function(lesson_measure name)
  set(out ${OUT_DIR}/soft_${name}.json)
  execute_process(COMMAND ${LESSON} --headless --size 320x180 --strict-gl ${ARGN} --measure ${out}
                  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: lesson exited ${rc}: ${err}")
  endif()
  file(READ ${out} json)
  set(${name}_json "${json}" PARENT_SCOPE)
endfunction()

# The same, measured against the soft reference with 64 rays a pixel (seconds at full size).
function(soft_run name)
  lesson_measure(${name} --frames 2 --set measure.samples=64 ${ARGN})
  set(${name}_json "${${name}_json}" PARENT_SCOPE)
endfunction()

# soft.<field> of a run (soft_get(run field out)); fails unless the run was measured as soft.
function(soft_get name field out)
  string(JSON type ERROR_VARIABLE missing TYPE "${${name}_json}" soft)
  if(missing)
    message(FATAL_ERROR "${name}: no soft figures in --measure's JSON (is light0.area a sphere?)")
  endif()
  string(JSON value GET "${${name}_json}" soft ${field})
  set(${out} ${value} PARENT_SCOPE)
endfunction()

# A decimal (1.5, 0.0123, 1.2e-05) in whole millionths, truncated.
function(to_micro value out)
  if(NOT value MATCHES "^(-?)([0-9]+)(\\.([0-9]+))?([eE]([-+]?[0-9]+))?$")
    message(FATAL_ERROR "'${value}' is not a number")
  endif()
  set(sign "${CMAKE_MATCH_1}")
  set(digits "${CMAKE_MATCH_2}${CMAKE_MATCH_4}")
  string(LENGTH "${CMAKE_MATCH_2}" whole)
  set(exponent "${CMAKE_MATCH_6}")
  if(exponent STREQUAL "")
    set(exponent 0)
  endif()
  math(EXPR point "${whole} + ${exponent} + 6")
  string(LENGTH "${digits}" length)
  if(point LESS_EQUAL 0)
    set(${out} 0 PARENT_SCOPE)
    return()
  endif()
  while(length LESS point)
    string(APPEND digits "0")
    math(EXPR length "${length} + 1")
  endwhile()
  string(SUBSTRING "${digits}" 0 ${point} digits)
  string(REGEX REPLACE "^0+" "" digits "${digits}")
  if(digits STREQUAL "")
    set(digits 0)
  endif()
  set(${out} "${sign}${digits}" PARENT_SCOPE)
endfunction()

# what: a < b (decimals).
function(expect_less what a b)
  if(NOT a LESS b)
    message(FATAL_ERROR "${what}: ${a} is not below ${b}")
  endif()
  message(STATUS "${what}: ${a} < ${b}")
endfunction()

# what: fa * a < fb * b, fa and fb whole numbers (a scaled comparison: "within 3x the floor").
function(expect_scaled_less what fa a fb b)
  to_micro(${a} ma)
  to_micro(${b} mb)
  math(EXPR left "${fa} * ${ma}")
  math(EXPR right "${fb} * ${mb}")
  if(NOT left LESS right)
    message(FATAL_ERROR "${what}: ${fa} x ${a} is not below ${fb} x ${b}")
  endif()
  message(STATUS "${what}: ${fa} x ${a} < ${fb} x ${b}")
endfunction()
