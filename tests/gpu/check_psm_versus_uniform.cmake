# One direction of psm_bench's light sweep (bench/paths/psm_light_sweep.path@T: the city, 30,000
# triangles, 2048^2 texels, 320x180, as tools/psm_bench.sh runs it) through lesson 09: PSM with every
# fix against the uniform map at the same texels. Issue 12's goal is "at no direction worse than
# uniform by more than 10 %"; the check asks for mean aliasing m below the uniform map's. Before the
# fall back to the uniform map (fix.fallback) the warp aliased 1.55x (T = 12) and 1.11x (T = 17) the
# uniform map's; with EXPECT=fail (a control, e.g. --set fix.fallback=false) the bound must break.
# Run: cmake -DLESSON=... -DPATH_FILE=... -DT=... -DOUT_DIR=... -DNAME=... -DEXPECT=ok|fail -DARGS=a;b -P this
set(common --headless --frames 2 --size 320x180 --strict-gl --replay ${PATH_FILE}@${T} --set scene=city
           --set triangles=30000 --set map_size=2048)
foreach(t psm uniform)
  set(extra)
  if(t STREQUAL "psm")
    set(extra ${ARGS})
  endif()
  execute_process(COMMAND ${LESSON} ${common} --set technique=${t} ${extra} --measure ${OUT_DIR}/${NAME}_${t}.json
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NAME}: technique=${t}: lesson exited ${rc}: ${err}")
  endif()
  file(READ ${OUT_DIR}/${NAME}_${t}.json json)
  string(JSON m_${t} GET "${json}" aliasing mean)
  if(t STREQUAL "psm")
    string(JSON counters GET "${json}" counters)
  endif()
endforeach()
set(figures "mean m: PSM ${m_psm}, uniform ${m_uniform}")
if(EXPECT STREQUAL "fail")
  if(m_psm LESS m_uniform)
    message(FATAL_ERROR "${NAME} (a control that must fail): ${figures}: the PSM aliases less\n${counters}")
  endif()
  message(STATUS "${NAME} (control): ${figures}: the PSM aliases more, as it must")
elseif(NOT m_psm LESS m_uniform)
  message(FATAL_ERROR "${NAME}: ${figures}: the PSM aliases no less than the uniform map\n${counters}")
else()
  message(STATUS "${NAME}: ${figures}")
endif()
