# PCSS's quad search (pcss.quad_search, shaders/05_soft_shadows/shadow_pcss.frag): the four pixels of a 2x2
# quad share one blocker search, each reading a quarter of the taps, the sums passed round the quad
# by fine derivatives (GL_ARB_derivative_control). Against the Embree sphere-light reference
# (--measure, 64 rays a pixel, 320x180), in the box's contact view, the default view and the forest:
#   the quad search is what runs (the header's taps line says so);
#   its error is within 10 % of every pixel searching alone with all the taps (measured 2026-12-06:
#     1.4 to 4.5 % above it);
#   without the extension (Mesa's MESA_EXTENSION_OVERRIDE takes it away) the lesson falls back to
#     the per-pixel search, says so, and draws its figures;
#   control: a quad that does not share (a copy of shaders/ whose quadSum returns 4 v: each pixel
#     keeps its own quarter of the taps) is beyond the bound (measured 1.45 to 2.4 times the error).
# Run: cmake -DLESSON=... -DSOURCE_DIR=... -DOUT_DIR=... -P this
include(${CMAKE_CURRENT_LIST_DIR}/soft_measure.cmake)
file(MAKE_DIRECTORY ${OUT_DIR})

# A copy of the shaders whose quad keeps no neighbour's taps; textures and presets as the tree's.
set(mutant ${OUT_DIR}/quad_search_mutant)
file(REMOVE_RECURSE ${mutant})
file(COPY ${SOURCE_DIR}/shaders DESTINATION ${mutant})
file(MAKE_DIRECTORY ${mutant}/lessons)
file(CREATE_LINK ${SOURCE_DIR}/textures ${mutant}/textures SYMBOLIC)
file(CREATE_LINK ${SOURCE_DIR}/lessons/05_soft_shadows ${mutant}/lessons/05_soft_shadows SYMBOLIC)
set(pcss ${mutant}/shaders/05_soft_shadows/shadow_pcss.frag)
file(READ ${pcss} text)
string(REGEX REPLACE "(vec2 quadSum\\(vec2 v, vec2 corner\\) {)[^}]*}" "\\1 return 4.0 * v; }" mutated "${text}")
if(mutated STREQUAL text)
  message(FATAL_ERROR "the control's mutation found no quadSum in ${pcss}")
endif()
file(WRITE ${pcss} "${mutated}")

function(taps_line name out)
  string(JSON taps GET "${${name}_json}" counters taps)
  set(${out} "${taps}" PARENT_SCOPE)
endfunction()

set(contact_args --preset contact_hardening --set theory.edges=false)
set(default_args)
set(forest_args --preset forest)
foreach(view contact default forest)
  set(args ${${view}_args})
  soft_run(${view}_quad ${args})
  soft_run(${view}_pixel ${args} --set pcss.quad_search=false)
  soft_get(${view}_quad rmse quad)
  soft_get(${view}_pixel rmse pixel)
  taps_line(${view}_quad taps)
  if(NOT taps MATCHES "shared by its quad")
    message(FATAL_ERROR "${view}: the quad search is not what ran: taps '${taps}'")
  endif()
  expect_scaled_less("${view}: the quad's search within 10 % of every pixel's own" 100 ${quad} 110 ${pixel})

  set(ENV{SHADOWLAB_ROOT} ${mutant})
  soft_run(${view}_mutant ${args})
  unset(ENV{SHADOWLAB_ROOT})
  soft_get(${view}_mutant rmse unshared)
  expect_scaled_less("control, ${view}: a quad that does not share is beyond the bound" 110 ${pixel} 100 ${unshared})
endforeach()

# The fallback: no fine derivatives, every pixel searches alone.
set(ENV{MESA_EXTENSION_OVERRIDE} "-GL_ARB_derivative_control")
soft_run(fallback --preset contact_hardening --set theory.edges=false)
unset(ENV{MESA_EXTENSION_OVERRIDE})
taps_line(fallback taps)
if(NOT taps MATCHES "quad search off: no GL_ARB_derivative_control")
  message(FATAL_ERROR "without GL_ARB_derivative_control the header should say the quad search is off: '${taps}'")
endif()
soft_get(fallback rmse fallback)
soft_get(contact_pixel rmse pixel)
if(NOT fallback STREQUAL pixel)
  message(FATAL_ERROR "the fallback should draw the per-pixel search: RMSE ${fallback} against ${pixel}")
endif()
message(STATUS "fallback: '${taps}', RMSE ${fallback} as the per-pixel search's")
