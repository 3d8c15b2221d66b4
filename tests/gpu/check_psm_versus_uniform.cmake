# One direction of psm_bench's light sweep (bench/paths/psm_light_sweep.path@T: the city, 30,000
# triangles, 2048^2 texels, 320x180, as tools/psm_bench.sh runs it) through lesson 09: PSM with every
# fix against the uniform map at the same texels. Issue 12's goal is "at no direction worse than
# uniform by more than 10 %"; the check asks for mean aliasing m below the uniform map's. Before the
# fall back to the uniform map (fix.fallback) the warp aliased 1.55x (T = 12) and 1.11x (T = 17) the
# uniform map's; with EXPECT=fail (a control, e.g. --set fix.fallback=false) the bound must break.
# Run: cmake -DLESSON=... -DPATH_FILE=... -DT=... -DOUT_DIR=... -DNAME=... -DEXPECT=ok|fail -DARGS=a;b -P this
set(common --headless --frames 2 --size 320x180 --strict-gl --replay ${PATH_FILE}@${T} --set scene=city
           --set triangles=30000 --set map_size=2048)
include(${CMAKE_CURRENT_LIST_DIR}/psm_pair.cmake)
psm_pair("${common}" "${ARGS}")
string(JSON counters GET "${json_psm}" counters)
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
