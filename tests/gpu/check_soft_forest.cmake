# Lesson 05's many point lights on the forest (the forest preset's view: leaf cards over the
# ground, a sphere of 1 m 22 m up), against the Embree sphere-light reference at 64 rays a pixel,
# 320x180. What lesson 05's README measured as the causes of the forest's plateau, each asserted:
#   the soft maps' depth pass tests the leaves' level-0 alpha (the reference's) and draws without a
#   slope-scaled polygon offset: 16 point lights are at least 10 % closer to the reference than the
#   same with the old offset (factor 1), which pushes nearly edge-on cards behind the cards they
#   touch (control: it must lose); on the leaf cards as receivers no slope bias and 0.7 texels
#   along the normal: 16 lights at least 20 % closer to the reference than with the solid
#   receivers' biases there (slope 0.5, 0.25 texels: 0.0515 against 0.0358 measured, 3.3x and 2.3x
#   the floor), and within 2.6x the floor, which only the card biases reach; the hard shadow of one
#   point light stays beyond 4x the noise floor (control). The lesson's goal, 16 lights within 2x
#   the floor, is met along the forest's benchmark path (1.99x at R 0.6 m, only just; 1.79x at
#   1.2 m; README "Measured"), not on this closer view (2.3x): no bound here pretends it is.
# Run: cmake -DLESSON=... -DOUT_DIR=... -P this
include(${CMAKE_CURRENT_LIST_DIR}/soft_measure.cmake)
file(MAKE_DIRECTORY ${OUT_DIR})
set(view --preset forest --set technique=many)

soft_run(forest16 ${view} --set many.samples=16 --set measure.noise_floor=true)
soft_get(forest16 rmse many16)
soft_get(forest16 reference_noise_rmse floor)
soft_run(forest16_slope ${view} --set many.samples=16 --set many.bias.offset_factor=1)
soft_get(forest16_slope rmse many16_slope)
soft_run(forest16_cards ${view} --set many.samples=16 --set many.bias.card_slope=0.5
         --set many.bias.card_normal_offset=0.25)
soft_get(forest16_cards rmse many16_cards)
soft_run(forest1 ${view} --set many.samples=1)
soft_get(forest1 rmse many1)

expect_less("the reference's noise floor is above zero (the seeds differ)" 0.0005 ${floor})
expect_scaled_less("without the caster's slope offset, 16 point lights are 10 % closer to the reference" 10 ${many16} 9
                   ${many16_slope})
expect_scaled_less("on the cards a normal offset instead of the slope bias: 16 point lights are 20 % closer" 5
                   ${many16} 4 ${many16_cards})
expect_scaled_less("16 point lights are within 2.6x the noise floor on this view" 5 ${many16} 13 ${floor})
expect_scaled_less("control: the hard shadow is beyond 4x the noise floor" 4 ${floor} 1 ${many1})
