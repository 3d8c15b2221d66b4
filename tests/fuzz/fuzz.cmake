# libFuzzer targets, one per GL-free parser (included by tests/CMakeLists.txt in the fuzz build
# only: CMake preset fuzz, clang, -fsanitize=fuzzer,address,undefined). Each has a seed corpus of
# valid files (tests/fuzz/NAME/seeds) and the inputs that crashed or were misread before
# (tests/fuzz/NAME/regressions). Label fuzz: a short bounded run of each (make test); make fuzz
# runs each for FUZZ_RUNS executions through tools/fuzz.sh.
set(FUZZ_DIR ${CMAKE_CURRENT_SOURCE_DIR}/fuzz)
set(SHADOWLAB_FUZZ_TARGETS obj presets params cli shader_source compile_log paths image answers)
# A bounded run in make test: every corpus file, then this many executions or these seconds,
# whichever comes first (the slowest targets, on files, do about 1,000 a second under ASan).
set(SHADOWLAB_FUZZ_TEST_RUNS 20000 CACHE STRING "executions of each fuzz target in its ctest entry")
set(SHADOWLAB_FUZZ_TEST_SECONDS 5 CACHE STRING "at most this long per fuzz target in its ctest entry")

add_custom_target(fuzz_targets)
foreach(name IN LISTS SHADOWLAB_FUZZ_TARGETS)
  set(sources ${FUZZ_DIR}/fuzz_${name}.cpp)
  if(name STREQUAL "paths")  # measure/paths alone: the rest of measure (Embree) is not a parser
    list(APPEND sources ${CMAKE_SOURCE_DIR}/common/measure/paths.cpp)
  elseif(name STREQUAL "answers")  # grading/answers alone (and the stub markers it replays)
    list(APPEND sources ${CMAKE_SOURCE_DIR}/common/grading/answers.cpp ${CMAKE_SOURCE_DIR}/common/grading/stub.cpp)
  endif()
  add_executable(fuzz_${name} ${sources})
  target_link_libraries(fuzz_${name} PRIVATE shadowlab_core)
  target_include_directories(fuzz_${name} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/support)
  target_link_options(fuzz_${name} PRIVATE -fsanitize=fuzzer)
  add_dependencies(fuzz_targets fuzz_${name})

  # New inputs of the bounded run land in a folder emptied first (each run replays the same files);
  # make fuzz keeps its growing corpus in fuzz-corpus/NAME instead. Never in the source tree.
  set(work ${CMAKE_BINARY_DIR}/test-corpus/${name})
  set(findings ${CMAKE_BINARY_DIR}/findings/${name})
  file(MAKE_DIRECTORY ${findings})
  set(corpus ${FUZZ_DIR}/${name}/seeds)
  if(EXISTS ${FUZZ_DIR}/${name}/regressions)
    list(APPEND corpus ${FUZZ_DIR}/${name}/regressions)
  endif()
  list(JOIN corpus " " corpus)
  add_test(NAME fuzz.${name} COMMAND sh -c "rm -rf ${work} && mkdir -p ${work} && exec $<TARGET_FILE:fuzz_${name}> \
-runs=${SHADOWLAB_FUZZ_TEST_RUNS} -max_total_time=${SHADOWLAB_FUZZ_TEST_SECONDS} -seed=1 -timeout=10 -rss_limit_mb=2048 \
-print_final_stats=1 -artifact_prefix=${findings}/ ${work} ${corpus}")
  set_tests_properties(fuzz.${name} PROPERTIES LABELS fuzz ENVIRONMENT "ASAN_OPTIONS=detect_leaks=1;LSAN_OPTIONS=suppressions=${CMAKE_SOURCE_DIR}/tests/lsan.supp"
                       FAIL_REGULAR_EXPRESSION "ERROR: libFuzzer|SUMMARY: .*Sanitizer|FUZZ_CHECK failed")
endforeach()
