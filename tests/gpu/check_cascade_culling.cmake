# Caster culling per cascade: each cascade draws only the casters whose box, swept along the light,
# reaches its own light volume. Lesson 10's cascades with the culling on and off
# (csm.cull_per_cascade) on the same frame: the picture must be byte for byte the same (a caster
# left out of a cascade writes no texel of it), the culled casters more and the shadow triangles
# fewer with it on, and some caster culled at all (the city from lesson 10's default view: the near
# cascade covers a few metres, most blocks cannot reach it). The maps are redrawn in every frame
# (csm.reuse_maps=false): the figures are the measured frame's, and a kept map draws no triangle.
# Run: cmake -DLESSON=... -DOUT_DIR=... [-DARGS=a;b] -DNAME=... -P this
function(run name)
  execute_process(COMMAND ${LESSON} --headless --frames 2 --size 320x180 --strict-gl --set technique=csm --set csm.reuse_maps=false ${ARGS}
                          ${ARGN} --measure ${OUT_DIR}/${NAME}_${name}.json --screenshot ${OUT_DIR}/${NAME}_${name}.png
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NAME} (${name}): lesson exited ${rc}: ${err}")
  endif()
  file(READ ${OUT_DIR}/${NAME}_${name}.json json)
  string(JSON culled GET "${json}" counters "culled casters")
  string(JSON triangles GET "${json}" counters "shadow triangles")
  set(${name}_culled ${culled} PARENT_SCOPE)
  set(${name}_triangles ${triangles} PARENT_SCOPE)
endfunction()

file(MAKE_DIRECTORY ${OUT_DIR})
run(on --set csm.cull_per_cascade=true)
run(off --set csm.cull_per_cascade=false)
file(SHA256 ${OUT_DIR}/${NAME}_on.png a)
file(SHA256 ${OUT_DIR}/${NAME}_off.png b)
if(NOT a STREQUAL b)
  message(FATAL_ERROR "${NAME}: the picture with casters culled per cascade differs from the one drawing them all "
                      "(${OUT_DIR}/${NAME}_on.png, ${NAME}_off.png): a culled caster wrote texels")
endif()
if(NOT on_culled GREATER 0 OR NOT on_culled GREATER off_culled)
  message(FATAL_ERROR "${NAME}: ${on_culled} casters culled per cascade against ${off_culled} without: expected more, and some")
endif()
if(NOT on_triangles LESS off_triangles)
  message(FATAL_ERROR "${NAME}: ${on_triangles} shadow triangles culled per cascade against ${off_triangles} without: expected fewer")
endif()
math(EXPR share "100 * ${on_triangles} / ${off_triangles}")
message(STATUS "${NAME}: the same picture; culled casters ${on_culled} against ${off_culled}, shadow triangles "
               "${on_triangles} against ${off_triangles} (${share} %)")
