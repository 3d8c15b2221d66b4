# shadowlab_discover_tests(TARGET LABELS label...): one ctest entry per doctest case of TARGET,
# found after each build by listing the binary's cases (as doctest_discover_tests does), but with
# names kept whole: doctest's own discovery splits names at ';' (CMake's list separator), so
# "a; b" became two entries that each ran zero cases and passed. Every entry runs the binary with
# --test-case=NAME (commas escaped, as doctest's filter syntax wants); test_main.cpp fails any run
# that executes no case, so a name that does not match can never pass silently again.
set(SHADOWLAB_DISCOVER_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/discover_add_tests.cmake)

function(shadowlab_discover_tests target)
  cmake_parse_arguments(arg "" "" "LABELS" ${ARGN})
  set(tests_file ${CMAKE_CURRENT_BINARY_DIR}/${target}_cases.cmake)
  set(include_file ${CMAKE_CURRENT_BINARY_DIR}/${target}_include.cmake)
  add_custom_command(TARGET ${target} POST_BUILD
    BYPRODUCTS ${tests_file}
    COMMAND ${CMAKE_COMMAND} -D "EXECUTABLE=$<TARGET_FILE:${target}>" -D "LABELS=${arg_LABELS}"
            -D "OUT=${tests_file}" -D "WORKING_DIR=${CMAKE_CURRENT_BINARY_DIR}" -P ${SHADOWLAB_DISCOVER_SCRIPT}
    VERBATIM)
  file(WRITE ${include_file}
    "if(EXISTS \"${tests_file}\")\n  include(\"${tests_file}\")\nelse()\n"
    "  add_test(${target}_NOT_BUILT ${target}_NOT_BUILT)\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${include_file})
endfunction()
