# The warp inside each cascade (csm.warp, Lloyd et al. 2006) against the same four cascades without
# it, at the same total texels (lesson 10's default view: the city from 45 m, 2048^2 per light).
# Inside a cascade an orthographic map spends its texels evenly over the slice's depth; the LiSPSM
# warp spends more at the slice's near end, where a texel covers more screen pixels, so over the
# screen the warped cascades' mean aliasing m must be lower. A warp that did not reach the maps (the
# orthographic matrices drawn) gives the same m and fails; so does a warp that left a slice without
# its n. Run: cmake -DLESSON=... -DOUT_DIR=... -P this
foreach(warp 0 1)
  execute_process(COMMAND ${LESSON} --headless --frames 2 --size 480x270 --strict-gl --set technique=csm
                          --set csm.warp=${warp} --measure ${OUT_DIR}/warp_${warp}.json
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "csm.warp=${warp}: lesson exited ${rc}: ${err}")
  endif()
  file(READ ${OUT_DIR}/warp_${warp}.json json)
  string(JSON m${warp} GET "${json}" aliasing mean)
endforeach()
string(JSON ns GET "${json}" counters "light0 cascade warp n")
message(STATUS "mean m: orthographic cascades ${m0}, warped ${m1}; warp n per cascade ${ns}")
if(NOT ns MATCHES "^[0-9.e+]+ / [0-9.e+]+ / [0-9.e+]+ / [0-9.e+]+ m$" OR ns MATCHES "(^| )0 ")
  message(FATAL_ERROR "the four cascades do not each have a warp: '${ns}'")
endif()
if(NOT m1 LESS m0)
  message(FATAL_ERROR "the warped cascades alias no less than the orthographic ones: mean m ${m1} against ${m0}")
endif()
