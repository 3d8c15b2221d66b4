# Lesson 05's techniques against the Embree sphere-light reference (--measure, 64 rays a pixel,
# 320x180, the contact_hardening view: the box's shadow fills the frame). What a correct
# implementation must reach, each next to a control a broken one would fail:
#   the reference's own noise (two seeds) is small but not zero;
#   many point lights converge: N = 1 (a hard shadow) > 4 > 16 > 64, and N = 16 is within 2x the
#     noise floor (the goal of lesson 05), while the hard shadow is beyond 4x;
#   PCF and PCSS soften: both below the hard shadow; PCSS below the fixed kernel;
#   Parker and Haines keep the hard shadow as the umbra: they over-estimate it (> 1 % of the
#     pixels) and never under-estimate it (< 0.05 %), where many point lights over-estimate it by
#     less than 0.2 %;
#   VSM bleeds in vsm_bleeding (its umbra under-estimated three times as much as by 16 point
#     lights), and its bleeding reduction lowers the error.
# Run: cmake -DLESSON=... -DOUT_DIR=... -P this
include(${CMAKE_CURRENT_LIST_DIR}/soft_measure.cmake)
file(MAKE_DIRECTORY ${OUT_DIR})
set(view --preset contact_hardening --set theory.edges=false)

soft_run(noise ${view} --set technique=many --set many.samples=16 --set measure.noise_floor=true)
soft_get(noise reference_noise_rmse floor)
expect_less("the reference's noise floor is above zero (the seeds differ)" 0.0005 ${floor})
expect_less("the reference's noise floor at 64 rays" ${floor} 0.015)

foreach(n 1 4 16 64)
  soft_run(many${n} ${view} --set technique=many --set many.samples=${n})
  soft_get(many${n} rmse many${n}_rmse)
endforeach()
expect_less("many lights: 4 samples beat 1" ${many4_rmse} ${many1_rmse})
expect_less("many lights: 16 beat 4" ${many16_rmse} ${many4_rmse})
expect_less("many lights: 64 beat 16" ${many64_rmse} ${many16_rmse})
soft_get(noise rmse noise_many16)
if(NOT noise_many16 STREQUAL many16_rmse)
  message(FATAL_ERROR "measure.noise_floor changed the figure it sits beside: ${noise_many16} against ${many16_rmse}")
endif()
expect_scaled_less("many lights at 16 samples within 2x the noise floor" 1 ${many16_rmse} 2 ${floor})
expect_scaled_less("control: the hard shadow is beyond 4x the noise floor" 4 ${floor} 1 ${many1_rmse})

foreach(t pcf pcss parker haines)
  soft_run(${t} ${view} --set technique=${t})
  soft_get(${t} rmse ${t}_rmse)
  soft_get(${t} umbra_over_pct ${t}_over)
  soft_get(${t} umbra_under_pct ${t}_under)
endforeach()
expect_less("PCF softens the hard shadow" ${pcf_rmse} ${many1_rmse})
expect_less("PCSS softens the hard shadow" ${pcss_rmse} ${many1_rmse})
expect_less("PCSS (16 + 16 taps) beats a fixed kernel of 16 taps" ${pcss_rmse} ${pcf_rmse})
foreach(t parker haines)
  expect_less("${t} over-estimates the umbra" 1.0 ${${t}_over})
  expect_less("${t} never under-estimates it" ${${t}_under} 0.05)
endforeach()
soft_get(many64 umbra_over_pct many64_over)
expect_less("control: 64 point lights barely over-estimate the umbra" ${many64_over} 0.2)

soft_run(bleeding --preset vsm_bleeding)
soft_run(reduced --preset vsm_bleeding --set vsm.bleed=0.5)
soft_run(bleeding_many --preset vsm_bleeding --set technique=many)
soft_get(bleeding rmse bleeding_rmse)
soft_get(bleeding umbra_under_pct bleeding_under)
soft_get(reduced rmse reduced_rmse)
soft_get(bleeding_many rmse bleeding_many_rmse)
soft_get(bleeding_many umbra_under_pct bleeding_many_under)
expect_less("VSM bleeds where casters overlap: far above many lights" ${bleeding_many_rmse} ${bleeding_rmse})
expect_scaled_less("VSM's bleeding lights the umbra: over 3 times what many lights under-estimate" 3
                   ${bleeding_many_under} 1 ${bleeding_under})
expect_less("the bleeding reduction lowers VSM's error" ${reduced_rmse} ${bleeding_rmse})
