# Exercise graders. For every lessons/NN_name/exercises.cpp with tests/grading/exNN_tests.cpp:
#   grade_exNN            the tests against the student's exercises.cpp; ctest label exNN
#                         (students: ctest --test-dir build/default -L exNN; `make grade LESSON=NN`
#                         also writes out/grades/exNN.json and exNN.xml)
#   grade_exNN_reference  the same tests against the reference in common/ (exNN_reference.cpp)
# The public cases are grading/exNN_tests.cpp; the hidden ones, grading/hidden/exNN_hidden.cpp
# (doctest suite "hidden"), exist only in the instructor's tree: the student handout (make
# handout) leaves them out, and `make grade-submission` runs them with a seed it chooses.
# With -DSHADOWLAB_SUBMISSION=DIR, grade_exNN is built from DIR/lessons/NN_name/exercises.cpp
# (a student's submission) instead of the tree's own file.
# And the proof that each grader is valid (label validity, part of `make test`):
#   validity.exNN.reference  every case (public and hidden) passes on the reference
#   validity.exNN.stubs      every case fails on the untouched stubs: a stub scores 0
#   validity.exNN.stubs_seeds the same with each of 40 seeds (grading runs draw theirs at random)
# The stub check needs the stubs untouched: their SHA-256 is recorded in grading/pristine.sha256.
# A student who edited exercises.cpp gets the check left out (with a message); CI configures with
# SHADOWLAB_REQUIRE_PRISTINE_STUBS=ON so a changed stub without an updated hash fails loudly.
file(GLOB EXERCISE_STUBS CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/lessons/*/exercises.cpp)
set(PRISTINE_FILE ${CMAKE_CURRENT_SOURCE_DIR}/grading/pristine.sha256)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PRISTINE_FILE})
set(PRISTINE_TEXT "")
if(EXISTS ${PRISTINE_FILE})
  file(READ ${PRISTINE_FILE} PRISTINE_TEXT)
endif()

foreach(stub IN LISTS EXERCISE_STUBS)
  get_filename_component(lesson_dir ${stub} DIRECTORY)
  get_filename_component(lesson ${lesson_dir} NAME)
  string(SUBSTRING ${lesson} 0 2 nn)
  set(tests ${CMAKE_CURRENT_SOURCE_DIR}/grading/ex${nn}_tests.cpp)
  set(reference ${CMAKE_CURRENT_SOURCE_DIR}/grading/ex${nn}_reference.cpp)
  if(NOT EXISTS ${tests})
    # CI (SHADOWLAB_REQUIRE_PRISTINE_STUBS) refuses exercises without a grader; a developer's build
    # in the middle of writing a lesson warns and goes on.
    if(SHADOWLAB_REQUIRE_PRISTINE_STUBS)
      message(FATAL_ERROR "lessons/${lesson}/exercises.cpp has no grader: write tests/grading/ex${nn}_tests.cpp and ex${nn}_reference.cpp")
    endif()
    message(WARNING "lessons/${lesson}/exercises.cpp has no grader yet (tests/grading/ex${nn}_tests.cpp, ex${nn}_reference.cpp)")
    continue()
  endif()
  set(cases ${tests})
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/grading/hidden/ex${nn}_hidden.cpp)
    list(APPEND cases ${CMAKE_CURRENT_SOURCE_DIR}/grading/hidden/ex${nn}_hidden.cpp)
  endif()
  set(student ${stub})
  if(SHADOWLAB_SUBMISSION AND EXISTS ${SHADOWLAB_SUBMISSION}/lessons/${lesson}/exercises.cpp)
    set(student ${SHADOWLAB_SUBMISSION}/lessons/${lesson}/exercises.cpp)
  endif()
  # The reference exercises of the lesson as a library: the forwarding file here, or (student
  # handout) prebuilt in lib/, so no reference source ships.
  set(prebuilt ${CMAKE_SOURCE_DIR}/lib/libshadowlab_ex${nn}_reference.a)
  if(EXISTS ${reference})
    add_library(shadowlab_ex${nn}_reference STATIC ${reference})
    target_include_directories(shadowlab_ex${nn}_reference PRIVATE ${lesson_dir})
    target_link_libraries(shadowlab_ex${nn}_reference PUBLIC shadowlab_algorithms shadowlab_grading)
  elseif(EXISTS ${prebuilt})
    add_library(shadowlab_ex${nn}_reference STATIC IMPORTED GLOBAL)
    set_target_properties(shadowlab_ex${nn}_reference PROPERTIES IMPORTED_LOCATION ${prebuilt})
    target_link_libraries(shadowlab_ex${nn}_reference INTERFACE shadowlab_algorithms shadowlab_grading)
  endif()
  set(graders grade_ex${nn})
  add_executable(grade_ex${nn} ${cases} ${student})
  if(TARGET shadowlab_ex${nn}_reference)
    add_executable(grade_ex${nn}_reference ${cases})
    target_link_libraries(grade_ex${nn}_reference PRIVATE shadowlab_ex${nn}_reference)
    list(APPEND graders grade_ex${nn}_reference)
  endif()
  # Graders link only the GL-free layers: the taught algorithms (the references) and core.
  foreach(target IN LISTS graders)
    target_include_directories(${target} PRIVATE ${lesson_dir})
    target_link_libraries(${target} PRIVATE shadowlab_test_main shadowlab_algorithms)
  endforeach()
  # The lesson's exercises panel runs these public cases in-process (app/exercises.hpp).
  if(TARGET lesson_${lesson})
    target_sources(lesson_${lesson} PRIVATE ${tests})
    target_include_directories(lesson_${lesson} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/support)
  endif()
  shadowlab_discover_tests(grade_ex${nn} LABELS ex${nn})
  if(SHADOWLAB_SUBMISSION)
    continue()  # grading a submission: its files are not the stubs, and validity is CI's business
  endif()

  if(TARGET grade_ex${nn}_reference)
    add_test(NAME validity.ex${nn}.reference COMMAND grade_ex${nn}_reference)
    set_tests_properties(validity.ex${nn}.reference PROPERTIES LABELS validity)
  endif()

  file(SHA256 ${stub} stub_hash)
  file(RELATIVE_PATH stub_rel ${CMAKE_SOURCE_DIR} ${stub})
  string(FIND "${PRISTINE_TEXT}" "${stub_hash}  ${stub_rel}" found)
  if(found GREATER -1)
    add_test(NAME validity.ex${nn}.stubs COMMAND grade_ex${nn} --expect-stub-scores-zero)
    set_tests_properties(validity.ex${nn}.stubs PROPERTIES LABELS validity)
    add_test(NAME validity.ex${nn}.stubs_seeds
             COMMAND ${CMAKE_COMMAND} -DGRADER=$<TARGET_FILE:grade_ex${nn}> -DFIRST=1 -DLAST=40
                     -P ${CMAKE_CURRENT_SOURCE_DIR}/grading/check_stub_seeds.cmake)
    set_tests_properties(validity.ex${nn}.stubs_seeds PROPERTIES LABELS validity)
  elseif(SHADOWLAB_REQUIRE_PRISTINE_STUBS)
    message(FATAL_ERROR "${stub_rel} differs from its recorded pristine hash; if the stubs changed on purpose, run `make stub-hashes`")
  else()
    message(STATUS "${stub_rel} was edited: validity.ex${nn}.stubs left out (it runs on a clean checkout in CI)")
  endif()
endforeach()

# `make grade` is the student's whole loop: under an exercise that fails (and is not a stub) the
# report prints its first failing public case, name and why, and never a hidden case's output.
if(TARGET grade_report)
  add_test(NAME grading.report_first_failure
           COMMAND grade_report --out ${CMAKE_CURRENT_BINARY_DIR}/report_first_failure
                   ${CMAKE_CURRENT_SOURCE_DIR}/grading/fixtures/one_failing.json)
  set_tests_properties(grading.report_first_failure PROPERTIES LABELS unit
    PASS_REGULAR_EXPRESSION "exercise 01\\.1: [0-9.]+ / 10 points, 1 of 3 cases \\(1 hidden\\)\n    first failing case: ex01\\.1: grazing light\n    \\| tests/grading/ex01_tests\\.cpp:20: CHECK\\( diffuse == 0\\.5 \\) is NOT correct!\n    \\|   values: CHECK\\( 0\\.25 == 0\\.5 \\)\n    \\|   logged: N = \\(0, 1, 0\\), L = \\(0\\.7, 0\\.7, 0\\)\nexercise 01\\.2: 0 / 10 points, 0 of 1 cases \\(0 hidden\\), still a stub\nscore"
    FAIL_REGULAR_EXPRESSION "SECRET")
endif()

# A class of a hundred brings crashes and endless loops: tests/grading/fixtures/faulty_ex01 has 01.1
# right, 01.2 an endless loop, 01.3 a crash and 01.4 the untouched stub. Graded by grade_isolated
# (one exercise per process, limits), 01.1 earns its points, 01.2 and 01.3 score 0 with their
# reasons, and the grade is written (grading/check_isolated.cmake).
if(TARGET grade_isolated AND TARGET grade_ex01_reference AND NOT SHADOWLAB_SUBMISSION
   AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/grading/fixtures/faulty_ex01/exercises.cpp)
  add_executable(grade_fixture_faulty_ex01 ${CMAKE_CURRENT_SOURCE_DIR}/grading/ex01_tests.cpp
                                           ${CMAKE_CURRENT_SOURCE_DIR}/grading/fixtures/faulty_ex01/exercises.cpp)
  target_include_directories(grade_fixture_faulty_ex01 PRIVATE ${CMAKE_SOURCE_DIR}/lessons/01_lighting)
  target_link_libraries(grade_fixture_faulty_ex01 PRIVATE shadowlab_test_main shadowlab_algorithms)
  add_test(NAME grading.isolated
           COMMAND ${CMAKE_COMMAND} -DISOLATED=$<TARGET_FILE:grade_isolated> -DREPORT=$<TARGET_FILE:grade_report>
                   -DREFERENCE=$<TARGET_FILE:grade_ex01_reference> -DGRADER=$<TARGET_FILE:grade_fixture_faulty_ex01>
                   -DOUT=${CMAKE_CURRENT_BINARY_DIR}/grading_isolated
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/grading/check_isolated.cmake)
  set_tests_properties(grading.isolated PROPERTIES LABELS validity)
endif()
