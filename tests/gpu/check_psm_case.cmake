# One robustness case of the perspective shadow maps through lesson 09's own --set interface
# (tests/psm_lessons.cmake lists them): the run must end with no GL error (--strict-gl), no
# non-finite visibility or texel Jacobian, and, against ground truth, at most MAX_BP / 100 %
# misclassified and at most MAX_LEAK_BP / 100 % of the truly shadowed pixels leaked (a vanished shadow). With
# EXPECT=fail (a control) the same bounds must be broken: the check can tell a wrong answer.
# With -DCOUNTER=NAME the header's counter NAME must be there (what the lesson says about the
# case), with -DNO_COUNTER=NAME it must not.
# Run: cmake -DLESSON=... -DOUT=...json -DNAME=... -DEXPECT=ok|fail -DMAX_BP=... -DMAX_LEAK_BP=... [-DSIZE=WxH (480x270)]
#   [-DCOUNTER=... | -DNO_COUNTER=...] -DARGS=a;b;c -P this
if(NOT DEFINED SIZE)
  set(SIZE 480x270)
endif()
execute_process(COMMAND ${LESSON} --headless --frames 2 --size ${SIZE} --strict-gl ${ARGS} --measure ${OUT}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NAME}: lesson exited ${rc}: ${err}")
endif()
file(READ ${OUT} json)
string(JSON facing GET "${json}" hard facing_pixels)
string(JSON shadowed GET "${json}" hard reference_shadowed)
string(JSON leaks GET "${json}" hard leaks)
string(JSON wrong GET "${json}" hard misclassified)
string(JSON pct GET "${json}" hard misclassified_pct)
string(JSON bad_v GET "${json}" nonfinite visibility)
string(JSON bad_j GET "${json}" nonfinite texel_jacobian)
string(JSON counters GET "${json}" counters)
if(DEFINED COUNTER OR DEFINED NO_COUNTER)
  string(JSON said ERROR_VARIABLE missing GET "${json}" counters "${COUNTER}${NO_COUNTER}")
  if(DEFINED COUNTER AND missing)
    message(FATAL_ERROR "${NAME}: the lesson does not say '${COUNTER}':\n${counters}")
  elseif(DEFINED NO_COUNTER AND NOT missing)
    message(FATAL_ERROR "${NAME}: the lesson says '${NO_COUNTER}: ${said}' where it should not")
  endif()
endif()
if(NOT bad_v EQUAL 0 OR NOT bad_j EQUAL 0)
  message(FATAL_ERROR "${NAME}: ${bad_v} non-finite visibilities, ${bad_j} non-finite texel Jacobians")
endif()
if(NOT DEFINED MIN_FACING)
  set(MIN_FACING 5000)
endif()
if(NOT facing GREATER MIN_FACING)
  message(FATAL_ERROR "${NAME}: only ${facing} facing pixels (fewer than ${MIN_FACING}): the case shows nothing to judge")
endif()
# Shares in millionths (CMake has no floating-point arithmetic).
math(EXPR wrong_ppm "${wrong} * 1000000 / ${facing}")
set(leak_ppm 0)
if(shadowed GREATER 1000)  # a handful of shadowed pixels (the light at the eye) has no share to judge
  math(EXPR leak_ppm "${leaks} * 1000000 / ${shadowed}")
endif()
math(EXPR max_ppm "${MAX_BP} * 100")  # bounds in hundredths of a percent
math(EXPR max_leak_ppm "${MAX_LEAK_BP} * 100")
set(within TRUE)
if(wrong_ppm GREATER max_ppm OR leak_ppm GREATER max_leak_ppm)
  set(within FALSE)
endif()
set(figures "${pct} % misclassified (${wrong} of ${facing} facing), ${leaks} of ${shadowed} truly shadowed pixels leaked")
if(EXPECT STREQUAL "fail")
  if(within)
    message(FATAL_ERROR "${NAME} (a control that must fail): ${figures}, within ${MAX_BP} / ${MAX_LEAK_BP} hundredths of a percent")
  endif()
  message(STATUS "${NAME} (control): ${figures}: outside the bounds, as it must be")
elseif(NOT within)
  message(FATAL_ERROR "${NAME}: ${figures}; bounds ${MAX_BP} / 100 % misclassified, ${MAX_LEAK_BP} / 100 % of the shadow leaked\n${counters}")
else()
  message(STATUS "${NAME}: ${figures} (bounds ${MAX_BP} / 100 %, ${MAX_LEAK_BP} / 100 %)")
endif()
