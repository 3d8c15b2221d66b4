# The benchmark runner on lesson 05 (a small real run: two techniques along the committed showcase
# path, the reference's noise floor on): report.csv carries the soft figures (RMSE, the umbra over-
# and under-estimate, the reference's noise), and at every path pose PCSS is closer to the
# reference than the hard shadow of one point light.
# Run: cmake -DBENCH=... -DLESSON=... -DPATH_FILE=... -DDIR=... -P this
cmake_policy(SET CMP0007 NEW)  # keep the empty cells: columns stay where the header says
file(REMOVE_RECURSE ${DIR})
execute_process(COMMAND ${BENCH} ${LESSON} --out ${DIR}
                        --config "hard: technique=many many.samples=1 measure.samples=32 measure.noise_floor=true"
                        --config "pcss: technique=pcss measure.samples=32 measure.noise_floor=true"
                        --path ${PATH_FILE} --path-samples 2 --repeat 1 --frames 2 --size 160x90
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "shadowlab_bench exited ${rc}: ${out}${err}")
endif()
file(STRINGS ${DIR}/report.csv lines)
list(GET lines 0 header)
string(REPLACE "," ";" columns "${header}")
foreach(name technique frame soft_rmse umbra_over_pct umbra_under_pct reference_noise_rmse)
  list(FIND columns ${name} col_${name})
  if(col_${name} LESS 0)
    message(FATAL_ERROR "report.csv lacks ${name}: ${header}")
  endif()
endforeach()
list(LENGTH lines n)
if(NOT n EQUAL 5)
  message(FATAL_ERROR "report.csv has ${n} lines; 2 techniques x 2 poses should give 4 rows")
endif()
foreach(i RANGE 1 4)
  list(GET lines ${i} line)
  string(REPLACE "," ";" cells "${line}")
  list(GET cells ${col_technique} technique)
  list(GET cells ${col_frame} frame)
  list(GET cells ${col_soft_rmse} rmse)
  list(GET cells ${col_reference_noise_rmse} noise)
  if(rmse STREQUAL "" OR noise STREQUAL "")
    message(FATAL_ERROR "row ${i} (${technique}, pose ${frame}) has no soft RMSE or noise floor: ${line}")
  endif()
  if(NOT noise GREATER 0)
    message(FATAL_ERROR "row ${i}: the reference's noise floor is ${noise}")
  endif()
  set(${technique}_${frame} ${rmse})
endforeach()
foreach(frame 0 1)
  if(NOT pcss_${frame} LESS hard_${frame})
    message(FATAL_ERROR "pose ${frame}: PCSS ${pcss_${frame}} is not closer to the reference than the hard shadow ${hard_${frame}}")
  endif()
  message(STATUS "pose ${frame}: PCSS ${pcss_${frame}} < hard ${hard_${frame}}")
endforeach()
