# What a window's keyboard and mouse drop do, driven headless through the same handlers (app/input's
# pressKey and dropFiles): --keys scripts the fly camera and hotkeys, --drop drops a model file on
# the window. Labels gpu (they run lessons).
if(SHADOWLAB_UNIT_ONLY)
  return()
endif()
set(shots ${CMAKE_BINARY_DIR}/test-screenshots)
if(TARGET lesson_03_shadow_quality)
  add_test(NAME gpu.input.scripted_keys COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_03_shadow_quality>
           -DOUT_DIR=${shots} -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_scripted_keys.cmake)
  set_tests_properties(gpu.input.scripted_keys PROPERTIES LABELS gpu)
endif()
if(TARGET lesson_02_shadow_maps)
  add_test(NAME gpu.input.drop_model COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_02_shadow_maps>
           -DMODELS=${CMAKE_CURRENT_SOURCE_DIR}/data/models -DOUT_DIR=${shots}
           -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_drop_model.cmake)
  set_tests_properties(gpu.input.drop_model PROPERTIES LABELS gpu)
  set(bin $<TARGET_FILE:lesson_02_shadow_maps>)
  add_test(NAME cli.keys.bad_key COMMAND lesson_check ${bin} --expect-exit 2
           --expect-stderr "--keys: 'w' is not a key (valid: A-Z, 0-9, Tab, Home, F1" -- --headless --keys Tab,w)
  add_test(NAME cli.keys.past_last_frame COMMAND lesson_check ${bin} --expect-exit 2
           --expect-stderr "--keys: the steps take 11 frames, the run has 3 (--frames N)" -- --headless --keys Tab,W*10)
  add_test(NAME cli.drop.past_last_frame COMMAND lesson_check ${bin} --expect-exit 2
           --expect-stderr "--drop m.obj@5: the run has frames 0 to 2 (--frames N)" -- --headless --drop m.obj@5)
  set_tests_properties(cli.keys.bad_key cli.keys.past_last_frame cli.drop.past_last_frame PROPERTIES LABELS gpu)
endif()
