# GLSL exercise graders (label exNN, like the C++ graders; see app/glsl_cases.hpp). For every
# tests/grading/glsl/exNN_glsl.cpp (public cases; hidden ones in grading/hidden/exNN_glsl_hidden.cpp):
#   grade_exNN_glsl        the GLSL cases on the GPU and the lesson's renders (grading/glsl_grader.cpp)
#   glsl_lesson_NN_name    the lesson built with the REFERENCE C++ exercises: its renders differ from
#                          the reference only in the student's GLSL
# ctest: "exNN.k GLSL" per GLSL exercise (label exNN, for students); and, proving the grader
# valid (label validity, in make test): validity.exNN_glsl.reference (the reference GLSL as the
# student's file passes every case), validity.exNN_glsl.stubs (the untouched stubs score 0; needs
# the pristine hash of exercises.glsl), validity.exNN_glsl.stubs_seeds (the same with each of 10
# seeds, renders left out), validity.exNN_glsl.stub_seed_S (renders included, at a seed that
# once let the stub pass a hidden render) and validity.exNN_glsl.compile_error (a file that does
# not compile scores 0, its compiler error in the report).
if(SHADOWLAB_UNIT_ONLY)
  return()
endif()
set(stub_seeds_09 322703142)  # validity.exNN_glsl.stub_seed_S below
file(GLOB GLSL_CASE_FILES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/grading/glsl/ex*_glsl.cpp)
foreach(cases IN LISTS GLSL_CASE_FILES)
  get_filename_component(case_name ${cases} NAME_WE)
  string(SUBSTRING ${case_name} 2 2 nn)
  file(GLOB lesson_dir LIST_DIRECTORIES true ${CMAKE_SOURCE_DIR}/lessons/${nn}_*)
  get_filename_component(lesson ${lesson_dir} NAME)
  if(NOT TARGET lesson_${lesson} OR NOT TARGET shadowlab_ex${nn}_reference)
    continue()
  endif()
  target_sources(lesson_${lesson} PRIVATE ${cases})  # the panel's public GLSL cases

  set(grading_lesson glsl_lesson_${lesson})
  add_executable(${grading_lesson} ${lesson_dir}/main.cpp ${CMAKE_CURRENT_SOURCE_DIR}/grading/ex${nn}_tests.cpp ${cases})
  target_include_directories(${grading_lesson} PRIVATE ${lesson_dir} ${CMAKE_CURRENT_SOURCE_DIR}/support)
  get_target_property(lesson_libraries lesson_${lesson} LINK_LIBRARIES)  # whatever the lesson links
  target_link_libraries(${grading_lesson} PRIVATE ${lesson_libraries} shadowlab_ex${nn}_reference)

  set(sources ${CMAKE_CURRENT_SOURCE_DIR}/grading/glsl_grader.cpp ${cases})
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/grading/hidden/ex${nn}_glsl_hidden.cpp)
    list(APPEND sources ${CMAKE_CURRENT_SOURCE_DIR}/grading/hidden/ex${nn}_glsl_hidden.cpp)
  endif()
  add_executable(grade_ex${nn}_glsl ${sources})
  target_compile_definitions(grade_ex${nn}_glsl PRIVATE SHADOWLAB_GLSL_LESSON="${lesson}")
  target_link_libraries(grade_ex${nn}_glsl PRIVATE shadowlab_app)
  add_dependencies(grade_ex${nn}_glsl ${grading_lesson})
  set(grade_glsl $<TARGET_FILE:grade_ex${nn}_glsl> --lesson-binary=$<TARGET_FILE:${grading_lesson}>)

  # One ctest entry per GLSL exercise the case file names ("ex02.4: ..." -> 02.4).
  file(STRINGS ${cases} case_lines REGEX "\"ex${nn}\\.[0-9]+:")
  set(ids "")
  foreach(line IN LISTS case_lines)
    string(REGEX MATCH "ex${nn}\\.[0-9]+" id "${line}")
    string(SUBSTRING ${id} 2 -1 id)
    list(APPEND ids ${id})
  endforeach()
  list(REMOVE_DUPLICATES ids)
  foreach(id IN LISTS ids)
    add_test(NAME "ex${id} GLSL" COMMAND ${grade_glsl} --exercise=${id})
    set_tests_properties("ex${id} GLSL" PROPERTIES LABELS ex${nn})
  endforeach()
  if(SHADOWLAB_SUBMISSION)
    continue()
  endif()

  if(EXISTS ${CMAKE_SOURCE_DIR}/shaders/${lesson}/exercises_reference.glsl)
    add_test(NAME validity.ex${nn}_glsl.reference COMMAND ${grade_glsl} --student=reference)
    set_tests_properties(validity.ex${nn}_glsl.reference PROPERTIES LABELS validity)
  endif()
  # The handout's path: against what --record-reference recorded, the reference passes, a tampered
  # recording fails (grading/check_glsl_precomputed.cmake).
  if(EXISTS ${CMAKE_SOURCE_DIR}/shaders/${lesson}/exercises_reference.glsl)
    add_test(NAME validity.ex${nn}_glsl.precomputed COMMAND ${CMAKE_COMMAND}
             "-DGRADER=$<TARGET_FILE:grade_ex${nn}_glsl>" "-DLESSON_BINARY=$<TARGET_FILE:${grading_lesson}>"
             -DLESSON=${lesson} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/glsl_precomputed_${nn}
             -P ${CMAKE_CURRENT_SOURCE_DIR}/grading/check_glsl_precomputed.cmake)
    set_tests_properties(validity.ex${nn}_glsl.precomputed PROPERTIES LABELS validity)
  endif()
  # Known slips each render must see (grading/check_glsl_mutant.cmake).
  if(nn STREQUAL "03" AND EXISTS ${CMAKE_SOURCE_DIR}/shaders/${lesson}/exercises_reference.glsl)
    add_test(NAME validity.ex03_glsl.mutant_no_receiver_plane COMMAND ${CMAKE_COMMAND}
             "-DGRADER=$<TARGET_FILE:grade_ex${nn}_glsl>" "-DLESSON_BINARY=$<TARGET_FILE:${grading_lesson}>"
             -DLESSON=${lesson} -DSOURCE=${CMAKE_SOURCE_DIR} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/glsl_mutant_03
             "-DFROM=depth + dot(dzduv, o)" -DTO=depth
             "-DEXPECT=ex03.6: the pcf_5x5 preset, the receiver plane in place of the slope bias"
             -P ${CMAKE_CURRENT_SOURCE_DIR}/grading/check_glsl_mutant.cmake)
    set_tests_properties(validity.ex03_glsl.mutant_no_receiver_plane PROPERTIES LABELS validity)
  endif()
  # A student file that does not compile: every case fails and the report carries the error.
  add_test(NAME validity.ex${nn}_glsl.compile_error COMMAND ${CMAKE_COMMAND}
           "-DGRADER=$<TARGET_FILE:grade_ex${nn}_glsl>" "-DLESSON_BINARY=$<TARGET_FILE:${grading_lesson}>"
           -DLESSON=${lesson} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/glsl_compile_error_${nn}
           -P ${CMAKE_CURRENT_SOURCE_DIR}/grading/check_glsl_compile_error.cmake)
  set_tests_properties(validity.ex${nn}_glsl.compile_error PROPERTIES LABELS validity)

  set(glsl_stub ${CMAKE_SOURCE_DIR}/shaders/${lesson}/exercises.glsl)
  file(SHA256 ${glsl_stub} glsl_hash)
  string(FIND "${PRISTINE_TEXT}" "${glsl_hash}  shaders/${lesson}/exercises.glsl" found)
  if(found GREATER -1)
    add_test(NAME validity.ex${nn}_glsl.stubs COMMAND ${grade_glsl} --expect-stub-scores-zero)
    set_tests_properties(validity.ex${nn}_glsl.stubs PROPERTIES LABELS validity)
    # Each of 10 seeds, the cases without the renders (those redraw placements that show too
    # little to grade, grading::renderInformative, unit-tested, or where the untouched stub's
    # render matches the reference's: no seed can give the stub a render it passes).
    # (The instructor's tree only: the handout's reference values are recorded at one seed.)
    if(NOT EXISTS ${CMAKE_SOURCE_DIR}/shaders/${lesson}/exercises_reference.glsl)
      continue()
    endif()
    add_test(NAME validity.ex${nn}_glsl.stubs_seeds COMMAND ${grade_glsl} --expect-stub-scores-zero --cases-only
                                                             --seeds=1-10)
    set_tests_properties(validity.ex${nn}_glsl.stubs_seeds PROPERTIES LABELS validity)
    # Seeds whose hidden renders once let the untouched stub pass, renders included, so the
    # redraw stays: 09 322703142 (a CI run's grade_untouched: lesson 09 fell back to its uniform
    # map in "hidden render 1: face maps", so the stub's cubeFaceLayer never ran).
    foreach(seed IN LISTS stub_seeds_${nn})
      add_test(NAME validity.ex${nn}_glsl.stub_seed_${seed} COMMAND ${grade_glsl} --expect-stub-scores-zero --seed=${seed})
      set_tests_properties(validity.ex${nn}_glsl.stub_seed_${seed} PROPERTIES LABELS validity)
    endforeach()
  elseif(SHADOWLAB_REQUIRE_PRISTINE_STUBS)
    message(FATAL_ERROR "shaders/${lesson}/exercises.glsl differs from its recorded pristine hash; if the stubs changed on purpose, run `make stub-hashes`")
  else()
    message(STATUS "shaders/${lesson}/exercises.glsl was edited: validity.ex${nn}_glsl.stubs left out")
  endif()
endforeach()

# The exercises panel and the stub banner, through the lessons (label gpu): --exercises reports
# each exercise's state from the public cases (stubs here; the reference C++ in the grading build),
# the file and line to write it at, and the one command that grades the lesson;
# and impl=student on the stubs prints the banner headless (lesson 04's stubbed projection leaves
# the frame black: the banner says so). Lesson 07 has no banner run: on the stubs its sweep stops
# the lesson with a clear error instead (gpu.hybrid.student).
foreach(lesson IN ITEMS 01_lighting 02_shadow_maps 03_shadow_quality 04_shadow_volumes 05_soft_shadows
                        06_texture_filtering 07_hybrid_maps 08_psm 09_psm_fixes 10_showdown)
  if(TARGET lesson_${lesson})
    string(SUBSTRING ${lesson} 0 2 nn)
    add_test(NAME gpu.${lesson}.exercises_panel COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_${lesson}>
             "-DEXPECT=${nn}\\.1 +stub [^\n]*\\(0 of [1-9][0-9]* public cases pass\\)\n      write [A-Za-z0-9_]+ in (lessons|shaders)/${lesson}/exercises\\.(cpp|glsl):[1-9][0-9]*\n.*\nGrade them \\(this builds what changed first\\): make grade LESSON=${nn}\nSee yours live: --set [a-z_.]+=student\n"
             -P ${CMAKE_CURRENT_SOURCE_DIR}/grading/check_exercises.cmake)
    set_tests_properties(gpu.${lesson}.exercises_panel PROPERTIES LABELS gpu)
    if(lesson STREQUAL 07_hybrid_maps)
      continue()
    endif()
    add_test(NAME gpu.${lesson}.stub_banner COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_${lesson}>
             "-DARGS=--headless;--frames;1;--size;320x180;--set;impl=student"
             "-DEXPECT=impl=student: your code is still a stub\n  ${nn}\\.[0-9]+ " -P ${CMAKE_CURRENT_SOURCE_DIR}/grading/check_exercises.cmake)
    set_tests_properties(gpu.${lesson}.stub_banner PROPERTIES LABELS gpu)
  endif()
endforeach()
if(TARGET lesson_04_shadow_volumes)
  add_test(NAME gpu.04_shadow_volumes.stub_banner_black COMMAND ${CMAKE_COMMAND}
           -DLESSON=$<TARGET_FILE:lesson_04_shadow_volumes> "-DARGS=--headless;--frames;1;--size;320x180;--set;impl=student"
           "-DEXPECT=\n  04\\.2 infinitePerspective: [^\n]*(\n  [^\n]*)*\nThe frame is [0-9]+% black or empty: that is the stub"
           -P ${CMAKE_CURRENT_SOURCE_DIR}/grading/check_exercises.cmake)
  set_tests_properties(gpu.04_shadow_volumes.stub_banner_black PROPERTIES LABELS gpu)
endif()
foreach(lesson IN ITEMS 02_shadow_maps 03_shadow_quality 04_shadow_volumes 05_soft_shadows 06_texture_filtering
                        07_hybrid_maps 08_psm 09_psm_fixes 10_showdown)
  if(TARGET glsl_lesson_${lesson})
    string(SUBSTRING ${lesson} 0 2 nn)
    add_test(NAME gpu.${lesson}.exercises_panel_reference COMMAND ${CMAKE_COMMAND}
             -DLESSON=$<TARGET_FILE:glsl_lesson_${lesson}> "-DEXPECT=${nn}\\.1 +passing "
             -P ${CMAKE_CURRENT_SOURCE_DIR}/grading/check_exercises.cmake)
    set_tests_properties(gpu.${lesson}.exercises_panel_reference PROPERTIES LABELS gpu)
  endif()
endforeach()

# The sealed shader files (cmake/sealed.cmake) stand in for the files themselves: with every one
# of them gone from a copy of the tree, as in the student handout, every preset of each lesson that
# uses one renders its golden image. (The handout has no files to remove: its own tests run
# without them anyway.)
file(STRINGS ${CMAKE_SOURCE_DIR}/tools/handout/sealed_shaders.txt sealed_lines)
set(without_sealed "")
foreach(line IN LISTS sealed_lines)
  string(REGEX REPLACE "#.*" "" line "${line}")
  string(STRIP "${line}" line)
  if(line AND EXISTS ${CMAKE_SOURCE_DIR}/shaders/${line})
    list(APPEND without_sealed --without shaders/${line})
  endif()
endforeach()
foreach(lesson IN ITEMS 01_lighting 02_shadow_maps 03_shadow_quality 04_shadow_volumes 05_soft_shadows
                        06_texture_filtering 07_hybrid_maps 08_psm 09_psm_fixes 10_showdown)
  if(TARGET lesson_${lesson} AND without_sealed AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/data/golden/${lesson})
    add_test(NAME gpu.${lesson}.sealed_shaders COMMAND lesson_check $<TARGET_FILE:lesson_${lesson}> ${without_sealed}
             --all-presets --png ${shots}/${lesson}_sealed.png --golden ${CMAKE_CURRENT_SOURCE_DIR}/data/golden/${lesson}
             -- --headless --frames 2 --size 320x180 --screenshot ${shots}/${lesson}_sealed.png)
    set_tests_properties(gpu.${lesson}.sealed_shaders PROPERTIES LABELS gpu)
  endif()
endforeach()

# The student handout withholds the reference GLSL of the exercises (`withheld` in the manifest):
# without those files each lesson still runs, says whose GLSL draws, and gives the driver no line of
# them (grading/check_withheld.cmake, with a run in this tree proving the check can fail).
# The view that calls each lesson's withheld functions where the default view does not (the
# exercise's usedWhen in the lesson's declare()).
set(withheld_view_02_shadow_maps compare=manual)
set(withheld_view_03_shadow_quality filter=pcf_nxn)
set(withheld_view_04_shadow_volumes silhouettes=gpu)
set(withheld_view_06_texture_filtering sampling=rip_map)
foreach(lesson IN ITEMS 02_shadow_maps 03_shadow_quality 04_shadow_volumes 05_soft_shadows 06_texture_filtering
                        07_hybrid_maps 08_psm 09_psm_fixes 10_showdown)
  if(TARGET lesson_${lesson} AND EXISTS ${CMAKE_SOURCE_DIR}/shaders/${lesson}/exercises_reference.glsl)
    add_test(NAME gpu.${lesson}.withheld COMMAND ${CMAKE_COMMAND} -DLESSON_BINARY=$<TARGET_FILE:lesson_${lesson}>
             -DLESSON=${lesson} -DSOURCE=${CMAKE_SOURCE_DIR} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/withheld_${lesson}
             "-DVIEW=${withheld_view_${lesson}}"
             -P ${CMAKE_CURRENT_SOURCE_DIR}/grading/check_withheld.cmake)
    set_tests_properties(gpu.${lesson}.withheld PROPERTIES LABELS gpu)
  endif()
endforeach()
# ... and there F4 shows the reference's picture of the preset in view (app/reference_picture.hpp):
# the golden image itself, whatever the student's stubs draw live (in manual_compare and pcf_5x5
# the stubs draw no shadow: without F4 those differ from the golden).
set(without_answers "")
foreach(line IN LISTS sealed_lines)
  if(line MATCHES "^withheld[ \t]+([^ \t#]+)" AND EXISTS ${CMAKE_SOURCE_DIR}/shaders/${CMAKE_MATCH_1})
    list(APPEND without_answers --without shaders/${CMAKE_MATCH_1})
  endif()
endforeach()
set(reference_picture_presets_02_shadow_maps default,manual_compare)
set(reference_picture_presets_03_shadow_quality default,pcf_5x5)
foreach(lesson IN ITEMS 02_shadow_maps 03_shadow_quality)
  if(TARGET lesson_${lesson} AND without_answers)
    set(png ${shots}/${lesson}_reference_picture.png)
    add_test(NAME gpu.${lesson}.reference_picture COMMAND lesson_check $<TARGET_FILE:lesson_${lesson}> ${without_answers}
             --presets ${reference_picture_presets_${lesson}} --png ${png} --golden ${CMAKE_CURRENT_SOURCE_DIR}/data/golden/${lesson}
             -- --headless --frames 2 --size 320x180 --keys F4 --screenshot ${png})
    set_tests_properties(gpu.${lesson}.reference_picture PROPERTIES LABELS gpu)
  endif()
endforeach()

