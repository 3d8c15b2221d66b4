# The lecturer's own models (core/model_file through Assimp; --model FILE, scene=model): every scene
# lesson draws a committed model (the screenshot must be a picture, not one colour); broken files end
# the run with one line naming the file and the reason (exit 1), a model where a lesson has no
# scene=model is bad input (exit 2); lesson 04 on an open model draws it z-pass only and its shadows
# match the ground truth (tests/gpu/check_model_volumes.cmake). Labels gpu (they run lessons).
if(SHADOWLAB_UNIT_ONLY)
  return()
endif()
set(models ${CMAKE_CURRENT_SOURCE_DIR}/data/models)
set(shots ${CMAKE_BINARY_DIR}/test-screenshots)
# One family per technique the lessons teach: lighting (01), maps (02, 03), volumes (04), soft (05),
# hybrid (07), PSM (08, 09); a textured OBJ + MTL for most, glTF (.gltf, .glb) for some.
set(model_runs
    01_lighting cube.obj 02_shadow_maps tetrahedron.glb 03_shadow_quality cube.obj 04_shadow_volumes chimney.obj
    05_soft_shadows tetrahedron.gltf 07_hybrid_maps cube.obj 08_psm quads.obj 09_psm_fixes cube.obj)
while(model_runs)
  list(POP_FRONT model_runs name file)
  if(TARGET lesson_${name})
    add_test(NAME gpu.${name}.model COMMAND lesson_check $<TARGET_FILE:lesson_${name}> --png ${shots}/${name}_model.png
             -- --headless --frames 2 --size 640x360 --strict-gl --model ${models}/${file}
             --screenshot ${shots}/${name}_model.png)
    set_tests_properties(gpu.${name}.model PROPERTIES LABELS gpu)
    # The picture itself, guarded: tests/data/golden/models/NN_name/default.png (recorded as the
    # lesson's preset goldens are: SHADOWLAB_RECORD_GOLDEN=missing ctest -R model_golden).
    add_test(NAME gpu.${name}.model_golden COMMAND lesson_check $<TARGET_FILE:lesson_${name}>
             --png ${shots}/${name}_model_golden.png --golden ${CMAKE_CURRENT_SOURCE_DIR}/data/golden/models/${name}
             -- --headless --frames 2 --size 320x180 --strict-gl --model ${models}/${file}
             --screenshot ${shots}/${name}_model_golden.png)
    set_tests_properties(gpu.${name}.model_golden PROPERTIES LABELS gpu)
  endif()
endwhile()

if(TARGET lesson_02_shadow_maps)
  set(bin $<TARGET_FILE:lesson_02_shadow_maps>)
  set(errors
      missing "no_such_model.obj" "model '${models}/no_such_model.obj': no such file"
      empty "empty.obj" "model '${models}/empty.obj': the file is empty"
      truncated "truncated.glb" "model '${models}/truncated.glb': not a readable model file"
      corrupt "corrupt.gltf" "model '${models}/corrupt.gltf': not a readable model file"
      lines_only "lines_only.obj" "model '${models}/lines_only.obj': no triangles to draw (2 points and 3 lines skipped)"
      # A broken OBJ file: the line, the reason and the valid choices (core/obj_locate, after Assimp refuses it).
      bad_number "bad_number.obj"
      "model '${models}/bad_number.obj': line 4: 'abc' is not a number (valid: numbers such as 2, -0.5 or 1.5e-3, a digit first)"
      bad_index "bad_index.obj"
      "model '${models}/bad_index.obj': line 6: vertex index 7 is past the file's 3 vertices (valid: 1 to 3, or -1 to -3 counting back from the last vertex so far)"
      self_crossing "self_crossing.obj"
      "model '${models}/self_crossing.obj': line 7: a face with 5 corners crosses itself")  # the rest: see the unit case
  while(errors)
    list(POP_FRONT errors what file message)
    add_test(NAME cli.model.${what} COMMAND lesson_check ${bin} --expect-exit 1 --expect-stderr "${message}"
             -- --headless --frames 1 --model ${models}/${file})
    set_tests_properties(cli.model.${what} PROPERTIES LABELS gpu)
  endwhile()
  # A stated fallback, not an error: the run goes on (exit 0) and says what it used instead.
  add_test(NAME cli.model.missing_texture COMMAND lesson_check ${bin} --expect-exit 0
           --expect-stderr "missing_texture.obj': texture '${models}/no_such_texture.png' not found; material 'painted' uses its diffuse colour (0.20, 0.70, 0.30)"
           -- --headless --frames 1 --size 320x180 --model ${models}/missing_texture.obj)
  add_test(NAME cli.model.no_normals COMMAND lesson_check ${bin} --expect-exit 0
           --expect-stderr "no_normals.obj': 1 meshes had no normals: generated smooth ones from the faces"
           -- --headless --frames 1 --size 320x180 --model ${models}/no_normals.obj)
  add_test(NAME cli.model.skipped_lines COMMAND lesson_check ${bin} --expect-exit 0
           --expect-stderr "mixed_primitives.obj': skipped 2 points and 1 lines"
           -- --headless --frames 1 --size 320x180 --model ${models}/mixed_primitives.obj)
  # Assimp loads it without the garbled vertex: the run goes on, and the note names the line.
  add_test(NAME cli.model.skipped_statement COMMAND lesson_check ${bin} --expect-exit 0
           --expect-stderr "skipped_vertex.obj': line 5: 'x' is not a number (valid: numbers such as 2, -0.5 or 1.5e-3, a digit first). Assimp 5.2.5 loaded the file, skipping or misreading this statement: check the model"
           -- --headless --frames 1 --size 320x180 --model ${models}/skipped_vertex.obj)
  add_test(NAME cli.model.scene_without_file COMMAND lesson_check ${bin} --expect-exit 2
           --expect-stderr "scene=model draws the file given with --model FILE" -- --headless --set scene=model)
  set_tests_properties(cli.model.missing_texture cli.model.no_normals cli.model.skipped_lines cli.model.skipped_statement
                       cli.model.scene_without_file PROPERTIES LABELS gpu)
endif()
if(TARGET lesson_06_texture_filtering)
  add_test(NAME cli.model.lesson_without_scenes COMMAND lesson_check $<TARGET_FILE:lesson_06_texture_filtering>
           --expect-exit 2 --expect-stderr "--model: lesson 06_texture_filtering has no scene choice 'model'"
           -- --headless --model ${models}/cube.obj)
  set_tests_properties(cli.model.lesson_without_scenes PROPERTIES LABELS gpu)
endif()
if(TARGET lesson_04_shadow_volumes)
  add_test(NAME gpu.04_shadow_volumes.model_open_mesh COMMAND ${CMAKE_COMMAND}
           -DLESSON=$<TARGET_FILE:lesson_04_shadow_volumes> -DMODEL=${models}/chimney.obj -DOUT_DIR=${shots}
           -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_model_volumes.cmake)
  set_tests_properties(gpu.04_shadow_volumes.model_open_mesh PROPERTIES LABELS gpu TIMEOUT 600)
endif()
# Open models are drawn two-sided: looking into the open chimney, the measured error of four lessons'
# lit passes stays at the edge residue (tests/gpu/check_model_two_sided.cmake gives the figures).
if(TARGET lesson_02_shadow_maps AND TARGET lesson_03_shadow_quality AND TARGET lesson_04_shadow_volumes
   AND TARGET lesson_07_hybrid_maps)
  add_test(NAME gpu.model.open_two_sided COMMAND ${CMAKE_COMMAND} -DBIN_DIR=$<TARGET_FILE_DIR:lesson_03_shadow_quality>
           -DMODEL=${models}/chimney.obj -DOUT_DIR=${shots} -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_model_two_sided.cmake)
  set_tests_properties(gpu.model.open_two_sided PROPERTIES LABELS gpu TIMEOUT 600)
endif()
# The benchmark runner on a model: two configurations of lesson 03, the model against the showcase;
# the report's files and numbers as for the procedural scenes (check_bench_report.cmake).
if(TARGET lesson_03_shadow_quality AND TARGET shadowlab_bench)
  set(bench_dir ${CMAKE_BINARY_DIR}/test-bench-model)
  add_test(NAME bench.model.run COMMAND shadowlab_bench $<TARGET_FILE:lesson_03_shadow_quality> --out ${bench_dir}
           --model ${models}/cube.obj --scenes model,showcase --config "pcf: filter=pcf_nxn" --config "nearest: filter=nearest"
           --repeat 1 --frames 2 --size 320x180)
  add_test(NAME bench.model.report COMMAND ${CMAKE_COMMAND} -DDIR=${bench_dir} -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_bench_report.cmake)
  set_tests_properties(bench.model.run PROPERTIES FIXTURES_SETUP bench_model LABELS gpu)
  set_tests_properties(bench.model.report PROPERTIES FIXTURES_REQUIRED bench_model LABELS gpu)
endif()
