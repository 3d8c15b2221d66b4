# Dropping a model file on the window, headless through --drop (app/input's dropFiles, what the GLFW
# drop callback calls; the frame loop then loads it as for a window). Lesson 02:
#   the showcase, then tetrahedron.glb dropped before frame 1: the scene switches to the model, and
#     the last frame is the very picture --model tetrahedron.glb draws (and not the showcase's)
#   cube.obj loaded, then empty.obj dropped: the one-line error naming the file, and the cube stays
#     (the picture --model cube.obj draws)
# Run: cmake -DLESSON=... -DMODELS=... -DOUT_DIR=... -P this
file(MAKE_DIRECTORY ${OUT_DIR})
function(shot name)
  execute_process(COMMAND ${LESSON} --headless --frames 3 --size 320x180 --strict-gl ${ARGN}
                          --screenshot ${OUT_DIR}/drop_${name}.png RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: exited ${rc}: ${err}")
  endif()
  set(err_${name} "${err}" PARENT_SCOPE)
endfunction()
function(same a b expect)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT_DIR}/drop_${a}.png ${OUT_DIR}/drop_${b}.png
                  RESULT_VARIABLE differ)
  if(expect AND differ)
    message(FATAL_ERROR "drop_${a}.png and drop_${b}.png differ: ${ARGN}")
  elseif(NOT expect AND NOT differ)
    message(FATAL_ERROR "drop_${a}.png and drop_${b}.png are the same picture: ${ARGN}")
  endif()
endfunction()

shot(showcase)
shot(dropped --drop ${MODELS}/tetrahedron.glb)
shot(loaded --model ${MODELS}/tetrahedron.glb)
if(NOT err_dropped MATCHES "02_shadow_maps: model tetrahedron.glb: 4 triangles")
  message(FATAL_ERROR "the drop did not report the model: ${err_dropped}")
endif()
same(dropped loaded TRUE "the dropped model is not drawn as --model draws it")
same(dropped showcase FALSE "the scene did not switch from the showcase")

shot(cube --model ${MODELS}/cube.obj)
shot(bad_drop --model ${MODELS}/cube.obj --drop ${MODELS}/empty.obj@1)
if(NOT err_bad_drop MATCHES "02_shadow_maps: model '[^']*empty.obj': the file is empty")
  message(FATAL_ERROR "the bad drop gave no clear error: ${err_bad_drop}")
endif()
same(bad_drop cube TRUE "a bad drop changed the scene")
same(cube showcase FALSE "the cube run drew the showcase")
message(STATUS "--drop: the scene switched to tetrahedron.glb; empty.obj refused in one line, the cube kept")
