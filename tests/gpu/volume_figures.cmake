# Stencil shadow volumes' figures against ground truth, shared by check_volumes.cmake (lesson 04's
# scenes) and check_model_volumes.cmake (a loaded open model). include() it, then
#   check_volume_figures(NAME exact|wrong MEASURE_JSON [MIN_SHADOWED_PERMILLE])
# exact: at most 0.2 % misclassified away from shadow boundaries and 0.5 % in all; wrong: over 20 %
# away from boundaries (the control: z-pass with the eye in a volume). MIN_SHADOWED_PERMILLE: the
# reference must shadow at least that share of the facing pixels (a caster that cast nothing would
# otherwise pass as exact).
function(check_volume_figures name expect file)
  file(READ ${file} json)
  string(JSON facing GET "${json}" hard facing_pixels)
  string(JSON shadowed GET "${json}" hard reference_shadowed)
  string(JSON edge_pct GET "${json}" hard edge_tolerant_pct)
  string(JSON all_pct GET "${json}" hard misclassified_pct)
  if(NOT facing GREATER 10000)
    message(FATAL_ERROR "${name}: only ${facing} pixels face the light: the read-back lost the surface")
  endif()
  math(EXPR shadowed_permille "1000 * ${shadowed} / ${facing}")
  if(ARGC GREATER 3)
    if(shadowed_permille LESS ${ARGV3})
      message(FATAL_ERROR "${name}: the reference shadows only ${shadowed_permille} per mille of the facing pixels "
                          "(at least ${ARGV3}): the caster's shadow is not in view")
    endif()
  endif()
  if(expect STREQUAL "exact")
    # 0.2 % of the ~90k facing pixels is ~180 pixels: specks along the smooth shapes' terminators
    # (shading normal toward the light, the facet itself away from it), never a wrong region. A
    # broken count (z-pass in a volume, a missing cap) is wrong by tens of percent.
    if(edge_pct GREATER 0.2)
      message(FATAL_ERROR "${name}: ${edge_pct} % misclassified away from shadow boundaries (limit 0.2 %)")
    endif()
    if(all_pct GREATER 0.5)
      message(FATAL_ERROR "${name}: ${all_pct} % misclassified in all (limit 0.5 %, boundaries included)")
    endif()
  elseif(NOT edge_pct GREATER 20)
    message(FATAL_ERROR "${name}: only ${edge_pct} % wrong, but z-pass with the eye in a volume must fail")
  endif()
  message(STATUS "${name}: ${all_pct} % misclassified, ${edge_pct} % away from boundaries, of ${facing} facing pixels"
                 " (${shadowed_permille} per mille shadowed in the reference)")
endfunction()
