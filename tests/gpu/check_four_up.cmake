# Lesson 10's four-up view, each quarter against ground truth: the four-up frame (PRESET, 480x270)
# is cut into its quarters, and each must be the picture of its technique drawn alone on the same
# camera at the quarter's size (quarter_compare: the golden images' tolerance). The technique
# alone is then measured against Embree's ground truth, so its figures are the quarter's: at most
# BOUNDS[q] / 100 % of the facing pixels misclassified and 5 % of the truly shadowed pixels leaked.
# A control: quarter 0 against quarter 1's technique alone must differ (the comparison can fail).
# Run: cmake -DLESSON=... -DCOMPARE=quarter_compare -DOUT_DIR=... -DNAME=... -DPRESET=...
#            -DQUARTERS=t0;t1;t2;t3 -DBOUNDS=b0;b1;b2;b3 -P this
set(four ${OUT_DIR}/${NAME}_four_up.png)
execute_process(COMMAND ${LESSON} --headless --frames 2 --size 480x270 --strict-gl --preset ${PRESET}
                        --screenshot ${four} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NAME}: the four-up run exited ${rc}: ${err}")
endif()
foreach(q RANGE 3)
  list(GET QUARTERS ${q} technique)
  list(GET BOUNDS ${q} max_bp)
  set(alone ${OUT_DIR}/${NAME}_${q}_${technique}.png)
  execute_process(COMMAND ${LESSON} --headless --frames 2 --size 240x135 --strict-gl --preset ${PRESET}
                          --set view=lit --set technique=${technique} --screenshot ${alone}
                          --measure ${OUT_DIR}/${NAME}_${q}.json RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NAME}: ${technique} alone exited ${rc}: ${err}")
  endif()
  execute_process(COMMAND ${COMPARE} ${four} ${q} ${alone} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NAME}: quarter ${q} is not ${technique}'s picture: ${out}${err}")
  endif()
  file(READ ${OUT_DIR}/${NAME}_${q}.json json)
  foreach(k facing_pixels reference_shadowed misclassified leaks misclassified_pct)
    string(JSON ${k} GET "${json}" hard ${k})
  endforeach()
  if(NOT facing_pixels GREATER 3000)
    message(FATAL_ERROR "${NAME}: quarter ${q} (${technique}) has only ${facing_pixels} facing pixels: nothing to judge")
  endif()
  math(EXPR wrong_ppm "${misclassified} * 1000000 / ${facing_pixels}")
  set(leak_ppm 0)
  if(reference_shadowed GREATER 300)
    math(EXPR leak_ppm "${leaks} * 1000000 / ${reference_shadowed}")
  endif()
  math(EXPR max_ppm "${max_bp} * 100")
  if(wrong_ppm GREATER max_ppm OR leak_ppm GREATER 50000)
    message(FATAL_ERROR "${NAME}: quarter ${q} (${technique}): ${misclassified_pct} % misclassified (at most "
                        "${max_bp} / 100 %), ${leaks} of ${reference_shadowed} shadowed pixels leaked (at most 5 %)")
  endif()
  string(APPEND figures " ${q} ${technique}: ${misclassified_pct} % misclassified, ${leaks} leaks;")
endforeach()
# The control: quarter 0 is not quarter 1's technique.
list(GET QUARTERS 1 other)
execute_process(COMMAND ${COMPARE} ${four} 0 ${OUT_DIR}/${NAME}_1_${other}.png RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(rc EQUAL 0)
  message(FATAL_ERROR "${NAME}: control: quarter 0 matched ${other} alone too, the comparison cannot tell them apart: ${out}")
endif()
message(STATUS "${NAME}: every quarter is its technique's picture;${figures}")
