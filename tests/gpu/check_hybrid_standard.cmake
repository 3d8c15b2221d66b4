# levels = 0 is a standard shadow map: lesson 07's hybrid technique without a sweep must measure,
# pixel for pixel, what lesson 03's uniform map (the same technique lesson 03 draws, held here as
# technique=standard) measures at the same size, format, filter and bias. A control: the paper's
# two sweeps (eps0 = 0.25) must not, or this test could be comparing a technique with itself.
# Run: cmake -DLESSON=... -DOUT_DIR=... -P this
include(${CMAKE_CURRENT_LIST_DIR}/hybrid_common.cmake)
hybrid_run(levels0 --set levels=0)
hybrid_run(uniform --set technique=standard --set uniform.filter=nearest --set uniform.format=16)
hybrid_run(paper)
foreach(key leaks false_shadows misclassified)
  hybrid_get(a "${levels0_json}" hard ${key})
  hybrid_get(b "${uniform_json}" hard ${key})
  if(NOT a EQUAL b)
    message(FATAL_ERROR "${key}: ${a} with levels = 0 but ${b} with the uniform map")
  endif()
endforeach()
hybrid_get(full "${levels0_json}" hard misclassified)
hybrid_get(merged "${paper_json}" hard misclassified)
math(EXPR margin "${full} + ${full} / 10")
if(NOT merged GREATER margin)
  message(FATAL_ERROR "the paper's sweeps misclassify ${merged} pixels, the standard map ${full}: no difference")
endif()
message(STATUS "levels 0 = uniform map: ${full} misclassified; the paper's sweeps: ${merged}")
