# Helper of check_psm_versus_uniform.cmake and check_psm_fallback.cmake: lesson 09 run as PSM (with
# ARGS) and as the uniform map, each with COMMON, measured. Sets in the caller, for t in psm and
# uniform: m_<t> (mean aliasing m), mis_<t> (misclassified %), json_<t> (the whole --measure JSON).
function(psm_pair common args)
  foreach(t psm uniform)
    set(extra)
    if(t STREQUAL "psm")
      set(extra ${args})
    endif()
    execute_process(COMMAND ${LESSON} ${common} --set technique=${t} ${extra} --measure ${OUT_DIR}/${NAME}_${t}.json
                    RESULT_VARIABLE rc ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${NAME}: technique=${t}: lesson exited ${rc}: ${err}")
    endif()
    file(READ ${OUT_DIR}/${NAME}_${t}.json json)
    string(JSON m GET "${json}" aliasing mean)
    string(JSON mis GET "${json}" hard misclassified_pct)
    set(m_${t} ${m} PARENT_SCOPE)
    set(mis_${t} ${mis} PARENT_SCOPE)
    set(json_${t} "${json}" PARENT_SCOPE)
  endforeach()
endfunction()
