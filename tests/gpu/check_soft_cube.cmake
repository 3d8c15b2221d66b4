# Lesson 05's point light inside the scene: no one frustum holds it, so the sample-map techniques
# draw a cube of six faces (lessons/05_soft_shadows/soft_maps), against the Embree sphere-light
# reference (--measure, 64 rays a pixel, 320x180, the default view):
#   at the spot's own position, the cube's figures are the spot's (many point lights and PCF within
#     1.25x of the spot's RMSE): six wide faces lose nothing the one cone had;
#   low among the casters (light0 at 0.5 2.2 -0.5: face seams cross the sphere, the box's shadow and
#     the floor), every sample-map technique keeps its order (16 point lights within 3x the noise
#     floor, below PCSS, below the fixed kernel, below the hard shadow; Parker's outer hull over-
#     and never under-estimates the umbra) and the header says "a cube";
#   control: VSM has no cube form: the header says so and its error is that of no shadow at all,
#     over 4x the point lights' (what every technique showed before the cube: RMSE 0.29).
# Run: cmake -DLESSON=... -DOUT_DIR=... -P this
include(${CMAKE_CURRENT_LIST_DIR}/soft_measure.cmake)
file(MAKE_DIRECTORY ${OUT_DIR})

function(expect_counter name pattern)
  string(JSON said ERROR_VARIABLE missing GET "${${name}_json}" counters light0)
  if(missing OR NOT said MATCHES "${pattern}")
    message(FATAL_ERROR "${name}: the header's light0 line should match '${pattern}': '${said}'")
  endif()
endfunction()

set(point --set light0.kind=point)
foreach(t many pcf)
  soft_run(spot_${t} --set technique=${t})
  soft_run(cube_${t} --set technique=${t} ${point})
  expect_counter(cube_${t} "^a cube: 6 faces")
  soft_get(spot_${t} rmse spot_${t}_rmse)
  soft_get(cube_${t} rmse cube_${t}_rmse)
  expect_scaled_less("${t}: the point light's cube within 1.25x of the spot's error" 100 ${cube_${t}_rmse} 125
                     ${spot_${t}_rmse})
endforeach()

set(low ${point} "--set" "light0.position=0.5 2.2 -0.5")
soft_run(noise ${low} --set technique=many --set many.samples=16 --set measure.noise_floor=true)
soft_get(noise reference_noise_rmse floor)
soft_get(noise rmse many16_rmse)
soft_run(many1 ${low} --set technique=many --set many.samples=1)
soft_get(many1 rmse many1_rmse)
foreach(t pcf pcss parker mesh)
  soft_run(${t} ${low} --set technique=${t})
  soft_get(${t} rmse ${t}_rmse)
endforeach()
foreach(t noise many1 pcf pcss parker)
  expect_counter(${t} "^a cube: 6 faces inside the scene")
endforeach()
expect_scaled_less("low: 16 point lights within 3x the noise floor" 1 ${many16_rmse} 3 ${floor})
expect_less("low: 16 point lights beat PCSS" ${many16_rmse} ${pcss_rmse})
expect_less("low: PCSS beats the fixed kernel" ${pcss_rmse} ${pcf_rmse})
expect_less("low: PCF softens the hard shadow" ${pcf_rmse} ${many1_rmse})
expect_less("low: the light mesh is a shadow" ${mesh_rmse} 0.2)
soft_get(parker umbra_over_pct parker_over)
soft_get(parker umbra_under_pct parker_under)
expect_less("low: Parker over-estimates the umbra" 1.0 ${parker_over})
expect_less("low: Parker never under-estimates it" ${parker_under} 0.05)

soft_run(vsm ${low} --set technique=vsm)
expect_counter(vsm "no soft shadow .*no cube form")
soft_get(vsm rmse vsm_rmse)
expect_scaled_less("control: VSM without a cube is over 4x the point lights' error" 4 ${many16_rmse} 1 ${vsm_rmse})
