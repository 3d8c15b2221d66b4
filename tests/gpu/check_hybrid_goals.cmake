# The issue's goals for lesson 07 on the city's default view against ground truth (480x270), with
# the hybrid map at eps0 = 0.01 (what meets them; lessons/07_hybrid_maps/README.md):
#   equal source resolution  misclassified within 10 % of the full 2048^2 map's
#   equal memory             near shadow edges (within 2 source texels), at most half the
#                            misclassified share of a standard map holding as many bytes, at 24 bits
#                            (4 bytes a texel, as the hybrid map's 32-bit words); at the paper's 16
#                            bits the standard map gets twice the texels for the bytes, and the
#                            hybrid map must still do better there, if not 2x (README: 1.9x)
#   memory                   at most 15 % of the full map's texels stored
# and the paper's own eps0 = 0.25, as measured: fewer texels still, but more than twice the full
# map's errors (it merges silhouettes). The standard maps' sizes come from the hybrid map's own
# byte count, read from its header. Integer arithmetic: shares in millionths.
# Run: cmake -DLESSON=... -DOUT_DIR=... -P this
include(${CMAKE_CURRENT_LIST_DIR}/hybrid_common.cmake)

# The side of a standard map of `bytes` bytes at `per` bytes a texel: floor(sqrt(bytes / per)).
function(equal_side out bytes per)
  math(EXPR target "${bytes} / ${per}")
  set(lo 1)
  set(hi 8192)
  while(hi GREATER lo)
    math(EXPR mid "(${lo} + ${hi} + 1) / 2")
    math(EXPR sq "${mid} * ${mid}")
    if(sq GREATER target)
      math(EXPR hi "${mid} - 1")
    else()
      set(lo ${mid})
    endif()
  endwhile()
  set(${out} ${lo} PARENT_SCOPE)
endfunction()

hybrid_run(full --set levels=0)
hybrid_run(tuned --set eps0=0.01)
hybrid_run(tuned24 --set eps0=0.01 --set format=24)
hybrid_run(paper)
hybrid_get(bytes "${tuned_json}" counters "light0 hybrid bytes")
hybrid_get(bytes24 "${tuned24_json}" counters "light0 hybrid bytes")
equal_side(side16 ${bytes} 2)
equal_side(side24 ${bytes24} 4)
hybrid_run(equal16 --set levels=0 --set map_size=${side16} --set edge_band.map_size=2048)
hybrid_run(equal24 --set levels=0 --set map_size=${side24} --set format=24 --set edge_band.map_size=2048)

hybrid_get(full_mis "${full_json}" hard misclassified)
hybrid_get(tuned_mis "${tuned_json}" hard misclassified)
math(EXPR limit "${full_mis} + ${full_mis} / 10")
if(tuned_mis GREATER limit)
  message(FATAL_ERROR "equal source resolution: ${tuned_mis} misclassified against the full map's ${full_mis} (over 10 %)")
endif()
hybrid_ppm(tuned_band "${tuned_json}" edge_band)
hybrid_ppm(tuned24_band "${tuned24_json}" edge_band)
hybrid_ppm(equal16_band "${equal16_json}" edge_band)
hybrid_ppm(equal24_band "${equal24_json}" edge_band)
math(EXPR twice "2 * ${tuned24_band}")
if(twice GREATER equal24_band)
  message(FATAL_ERROR "equal memory at 24 bits (${bytes24} bytes, a ${side24}^2 map): near edges ${tuned24_band} against ${equal24_band} ppm, not 2x lower")
endif()
if(NOT tuned_band LESS equal16_band)
  message(FATAL_ERROR "equal memory at 16 bits (${bytes} bytes, a ${side16}^2 map): near edges ${tuned_band} against ${equal16_band} ppm, no better")
endif()
hybrid_get(stored "${tuned_json}" counters "light0 stored texels")
math(EXPR share "${stored} * 1000 / 4194304")
if(share GREATER 150)
  message(FATAL_ERROR "the hybrid map stores ${stored} texels of 4194304 (${share} per mille): more than 15 %")
endif()
hybrid_get(paper_mis "${paper_json}" hard misclassified)
hybrid_get(paper_stored "${paper_json}" counters "light0 stored texels")
math(EXPR twice_full "2 * ${full_mis}")
if(NOT paper_mis GREATER twice_full OR NOT paper_stored LESS stored)
  message(FATAL_ERROR "the paper's eps0 = 0.25: ${paper_mis} misclassified (full map ${full_mis}), ${paper_stored} texels stored (eps0 0.01: ${stored})")
endif()
message(STATUS "equal source: ${tuned_mis} vs ${full_mis} misclassified; near edges at equal memory: ${tuned24_band} vs ${equal24_band} ppm (24 bits, ${side24}^2), ${tuned_band} vs ${equal16_band} ppm (16 bits, ${side16}^2); stored ${share} per mille; paper: ${paper_mis} misclassified, ${paper_stored} texels")
