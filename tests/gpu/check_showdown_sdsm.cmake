# Sample distribution shadow maps (technique=sdsm, Lauritzen et al. 2011) against the practical
# cascades they start from, at the same total texels (lesson 10's default view: the city from 45 m,
# 2048^2 per light, 480x270). The camera's depth buffer, reduced on the GPU to tiles, must give a
# depth range that starts where the nearest roof is (not at the near plane, 1 m) from every tile;
# split over that range and fitted to the tiles, the cascades must alias less (mean m) and misclassify
# fewer pixels than the practical ones, and the tight fit less than the same splits fitted to whole
# slices (sdsm.tight_fit=false). A reduction that read nothing back ("nothing on screen") or tiles
# the fit ignored fail. The tiles are kept with the maps while the camera is still. Run: cmake
# -DLESSON=... -DOUT_DIR=... -P this
foreach(run "csm|--set;technique=csm" "sdsm|--set;technique=sdsm" "loose|--set;technique=sdsm;--set;sdsm.tight_fit=false")
  string(REPLACE "|" ";" parts "${run}")
  list(GET parts 0 name)
  list(SUBLIST parts 1 -1 args)
  execute_process(COMMAND ${LESSON} --headless --frames 2 --size 480x270 --strict-gl ${args}
                          --measure ${OUT_DIR}/sdsm_${name}.json RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: lesson exited ${rc}: ${err}")
  endif()
  file(READ ${OUT_DIR}/sdsm_${name}.json json)
  string(JSON m_${name} GET "${json}" aliasing mean)
  string(JSON bad_${name} GET "${json}" hard misclassified)
  string(JSON splits_${name} GET "${json}" counters "light0 splits")
endforeach()
file(READ ${OUT_DIR}/sdsm_sdsm.json json)
string(JSON range GET "${json}" counters "light0 depth range")
message(STATUS "csm: mean m ${m_csm}, ${bad_csm} misclassified, splits ${splits_csm}")
message(STATUS "sdsm: mean m ${m_sdsm}, ${bad_sdsm} misclassified, splits ${splits_sdsm}, depth range ${range}")
message(STATUS "sdsm, slices fitted whole: mean m ${m_loose}, ${bad_loose} misclassified")
# "11.1 - 200 m, 2040 of 2040 tiles" (no latency: no age): 480x270 in tiles of 8 pixels is 60 x 34.
if(NOT range MATCHES "^([0-9.]+) - ([0-9.]+) m, 2040 of 2040 tiles$")
  message(FATAL_ERROR "the depth range is not read from all 2040 tiles of the frame: '${range}'")
endif()
set(nearest ${CMAKE_MATCH_1})
if(nearest LESS 2 OR nearest GREATER 40)
  message(FATAL_ERROR "the nearest depth on screen, ${nearest} m, is not the nearest roof's (the view is 45 m out)")
endif()
string(REGEX MATCH "^[0-9.]+" first "${splits_sdsm}")
if(NOT first LESS_EQUAL nearest OR first LESS 1.5)
  message(FATAL_ERROR "the splits (${splits_sdsm}) do not start just before the nearest depth ${nearest} m")
endif()
if(NOT m_sdsm LESS m_csm OR NOT bad_sdsm LESS bad_csm)
  message(FATAL_ERROR "sdsm (mean m ${m_sdsm}, ${bad_sdsm} misclassified) is no better than csm (${m_csm}, ${bad_csm})")
endif()
if(NOT m_sdsm LESS m_loose OR NOT bad_sdsm LESS bad_loose)
  message(FATAL_ERROR "the tight fit (mean m ${m_sdsm}, ${bad_sdsm}) is no better than whole slices (${m_loose}, ${bad_loose})")
endif()
# A still camera keeps the maps, and with them the tiles: the camera's depth is drawn and reduced
# once in three frames (the bench CSV's passes), every frame when the maps are redrawn every frame.
foreach(reuse true false)
  execute_process(COMMAND ${LESSON} --headless --frames 3 --size 480x270 --strict-gl --set technique=sdsm
                          --set sdsm.reuse_maps=${reuse} --bench ${OUT_DIR}/sdsm_passes_${reuse}.csv
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "sdsm.reuse_maps=${reuse}: lesson exited ${rc}: ${err}")
  endif()
  file(STRINGS ${OUT_DIR}/sdsm_passes_${reuse}.csv depth_rows REGEX ",sdsm depth,")
  file(STRINGS ${OUT_DIR}/sdsm_passes_${reuse}.csv reduction_rows REGEX ",sdsm reduction,")
  list(LENGTH depth_rows depth_${reuse})
  list(LENGTH reduction_rows reduction_${reuse})
endforeach()
if(NOT depth_true EQUAL 1 OR NOT reduction_true EQUAL 1 OR NOT depth_false EQUAL 3 OR NOT reduction_false EQUAL 3)
  message(FATAL_ERROR "the camera's depth was drawn ${depth_true} and reduced ${reduction_true} times in 3 still "
                      "frames with the maps kept (expected once), ${depth_false} and ${reduction_false} times with "
                      "them redrawn (expected 3)")
endif()
