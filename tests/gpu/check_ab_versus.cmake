# The technique layer's promise, through the lessons: lesson 03 holds the uniform shadow map and
# lesson 04's stencil volumes, switches between them at run time (technique=...), and its A/B split
# shows one on each side with their own ground-truth figures. Each half must measure what its own
# lesson measures on the same view (within 0.5 % misclassified): A against lesson 03 alone, B
# against lesson 04 alone. The halves must also differ from each other's lesson figure, or the
# split could be showing one technique twice.
# Run: cmake -DLESSON03=... -DLESSON04=... -DOUT_DIR=... -P this
function(run lesson name)
  execute_process(COMMAND ${lesson} --headless --frames 2 --size 480x270 --strict-gl ${ARGN}
                          --measure ${OUT_DIR}/ab_versus_${name}.json
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: lesson exited ${rc}: ${err}")
  endif()
  file(READ ${OUT_DIR}/ab_versus_${name}.json json)
  set(${name}_json "${json}" PARENT_SCOPE)
endfunction()

# Misclassified share in millionths (integer arithmetic: CMake has no float subtraction).
function(share_ppm json out)
  string(JSON facing GET "${json}" ${ARGN} facing_pixels)
  string(JSON wrong GET "${json}" ${ARGN} misclassified)
  if(NOT facing GREATER 10000)
    message(FATAL_ERROR "only ${facing} facing pixels under '${ARGN}': the read-back lost the surface")
  endif()
  math(EXPR ppm "${wrong} * 1000000 / ${facing}")
  set(${out} ${ppm} PARENT_SCOPE)
endfunction()

function(expect_close what a b)
  math(EXPR diff "${a} - ${b}")
  if(diff LESS 0)
    math(EXPR diff "-${diff}")
  endif()
  if(diff GREATER 5000)  # 0.5 % in millionths
    message(FATAL_ERROR "${what}: ${a} against ${b} millionths misclassified (more than 0.5 % apart)")
  endif()
  message(STATUS "${what}: ${a} against ${b} millionths misclassified")
endfunction()

file(MAKE_DIRECTORY ${OUT_DIR})
run(${LESSON03} split --preset versus_volumes)
run(${LESSON03} uniform_alone --preset versus_volumes --set ab.enabled=false)
run(${LESSON04} volumes_alone --preset sun_only)
string(JSON b_preset GET "${split_json}" b preset)
if(NOT b_preset STREQUAL "versus_volumes_b")
  message(FATAL_ERROR "B shows preset '${b_preset}', not versus_volumes_b")
endif()
share_ppm("${split_json}" a hard)
share_ppm("${split_json}" b b hard)
share_ppm("${uniform_alone_json}" uniform hard)
share_ppm("${volumes_alone_json}" volumes hard)
expect_close("A (uniform map) against lesson 03 alone" ${a} ${uniform})
expect_close("B (stencil volumes) against lesson 04 alone" ${b} ${volumes})
# A control: the two techniques do not measure alike at this size, so a split that showed the same
# technique on both sides would be caught (their figures differ by more than a tenth of the error).
math(EXPR gap "${a} - ${b}")
if(gap LESS 0)
  math(EXPR gap "-${gap}")
endif()
math(EXPR tenth "(${a} + ${b}) / 20")
if(NOT gap GREATER tenth)
  message(FATAL_ERROR "A and B measure alike (${a} and ${b} millionths): is the split showing one technique twice?")
endif()
