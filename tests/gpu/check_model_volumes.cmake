# Lesson 04 on a loaded open model (tests/data/models/chimney.obj: four walls, no top, no bottom, 8
# open edges) against ground truth (Embree rays from the very pixels shaded). Real models are rarely
# closed; the lesson reports the open edges and draws the model z-pass only (open_meshes=z_pass_only),
# which is exact while the eye is outside every volume: away from shadow boundaries no pixel may be
# misclassified, and the chimney's shadow must be there (a model that cast nothing would be "exact"
# only where nothing is shadowed, so the reference's shadowed share is asserted too). The open
# surface casts from both sides (findSilhouette's twoSided): before, the far walls, which show the
# sun their inner side through the open top, cast nothing and 0.65 % of these views leaked.
# Control: the eye inside the chimney's shadow volume, where z-pass without caps must be badly wrong.
# Run: cmake -DLESSON=... -DMODEL=... -DOUT_DIR=... -P this
function(measure name expect)
  execute_process(COMMAND ${LESSON} --headless --frames 2 --size 480x270 --strict-gl --model ${MODEL}
                          --set light1.enabled=false ${ARGN} --measure ${OUT_DIR}/04_model_${name}.json
                          --screenshot ${OUT_DIR}/04_model_${name}.png
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: lesson exited ${rc}: ${err}")
  endif()
  if(NOT err MATCHES "model chimney.obj: 8 open edges in 1 of 1 meshes: open_meshes=z_pass_only")
    message(FATAL_ERROR "${name}: the lesson did not report the model's 8 open edges and the z-pass path: ${err}")
  endif()
  file(READ ${OUT_DIR}/04_model_${name}.json json)
  string(JSON facing GET "${json}" hard facing_pixels)
  string(JSON shadowed GET "${json}" hard reference_shadowed)
  string(JSON edge_pct GET "${json}" hard edge_tolerant_pct)
  string(JSON all_pct GET "${json}" hard misclassified_pct)
  if(NOT facing GREATER 10000)
    message(FATAL_ERROR "${name}: only ${facing} pixels face the light: the read-back lost the surface")
  endif()
  math(EXPR shadowed_permille "1000 * ${shadowed} / ${facing}")
  if(expect STREQUAL "exact")
    # The chimney's shadow is about 1.3 % of the facing pixels in these views; the far walls' part
    # that the one-sided open-mesh volume left out was about half of it (0.65 % misclassified).
    if(shadowed_permille LESS 8)
      message(FATAL_ERROR "${name}: the reference shadows only ${shadowed_permille} per mille of the facing pixels: no chimney shadow in view")
    endif()
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

file(MAKE_DIRECTORY ${OUT_DIR})
# Views from the side the shadow falls on (the sun travels -0.4 -1 -0.3; the default camera sees the
# chimney hide its own shadow). Not from above: through the open top the camera sees the walls' back
# faces, which the lit pass culls and the rays hit, a visibility difference and no shadow's.
measure(behind exact --set camera.yaw=3.14)
measure(beside exact --set camera.yaw=4.71)
measure(beside_gpu_silhouettes exact --set camera.yaw=4.71 --set silhouettes=gpu)
measure(behind_two_pass exact --set camera.yaw=3.14 --set two_sided=false)
# The chimney stands 4 m tall on x, z in [-0.67, 0.67]: from (-1.2, 0.3, -0.8) the sun is behind its -x wall.
measure(eye_in_volume wrong --set "camera.target=-1.2 0.3 -0.8" --set camera.distance=0.2 --set camera.pitch=0.3)
