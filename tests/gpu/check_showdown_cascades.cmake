# Cascaded shadow maps against their own one-cascade case at the same total texels (lesson 10's
# default view: the city from 45 m, 2048^2 per light): four 1024^2 cascades put fine texels near the
# eye and coarse ones far away, one 2048^2 map spreads them evenly, so over the screen the cascades'
# mean aliasing m (screen pixels per texel, measured from the texel Jacobian) must be lower, and
# their near cascade's texels finer than the single map's. A cascade set that never left cascade 0,
# or drew every cascade with one matrix, fails. The maximum of m must come from the maps, not from
# the seams: m is measured through each pixel's own cascade (SHADOW_TEXEL_JACOBIAN), so the
# largest m is at most 4x the 95th percentile (rounded up) (differencing two cascades' texel coordinates across a
# seam gave a maximum of 393 against a p95 of 2.2 here). Run: cmake -DLESSON=... -DOUT_DIR=... -P this
foreach(n 1 4)
  execute_process(COMMAND ${LESSON} --headless --frames 2 --size 480x270 --strict-gl --set technique=csm
                          --set csm.cascades=${n} --measure ${OUT_DIR}/cascades_${n}.json
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "csm.cascades=${n}: lesson exited ${rc}: ${err}")
  endif()
  file(READ ${OUT_DIR}/cascades_${n}.json json)
  string(JSON m${n} GET "${json}" aliasing mean)
  string(JSON p95_${n} GET "${json}" aliasing p95)
  string(JSON max${n} GET "${json}" aliasing max)
  string(JSON texels${n} GET "${json}" counters "light0 cascade texels")
endforeach()
# "1.23 / 4.56 cm": the near cascade's texel is the first figure.
string(REGEX MATCH "^[0-9.]+" near1 "${texels1}")
string(REGEX MATCH "^[0-9.]+" near4 "${texels4}")
message(STATUS "mean m: 1 cascade ${m1}, 4 cascades ${m4}; near texel ${near1} cm against ${near4} cm")
# (CMake's LESS compares the two as real numbers.)
if(NOT m4 LESS m1)
  message(FATAL_ERROR "4 cascades alias no less than one at the same texels: mean m ${m4} against ${m1}")
endif()
if(NOT near4 LESS near1)
  message(FATAL_ERROR "the near cascade's texel (${near4} cm) is not finer than one map's (${near1} cm)")
endif()
# (CMake's math is integer: the bound is 4x the p95 rounded up to a whole number.)
string(REGEX MATCH "^[0-9]+" max4_int "${max4}")
string(REGEX MATCH "^[0-9]+" p95_4_int "${p95_4}")
math(EXPR bound "4 * (${p95_4_int} + 1)")
message(STATUS "4 cascades: max m ${max4}, p95 ${p95_4} (at most ${bound})")
if(max4_int GREATER bound)
  message(FATAL_ERROR "4 cascades: max m ${max4} against p95 ${p95_4}: a seam spike (m measured across two cascades)")
endif()
