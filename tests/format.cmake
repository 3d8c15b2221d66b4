# Every C++ file of the tree conforms to .clang-format (label unit). `make format` applies it.
# The file list is taken when the test runs (not at configure time), so a new file cannot slip by.
find_program(CLANG_FORMAT NAMES clang-format-14 clang-format)
if(NOT CLANG_FORMAT)
  message(WARNING "clang-format not found: format.check not registered (tools/install-deps.sh installs it)")
  return()
endif()
add_test(NAME format.check COMMAND ${CMAKE_COMMAND} -DCLANG_FORMAT=${CLANG_FORMAT} -DROOT=${CMAKE_SOURCE_DIR}
         -P ${CMAKE_CURRENT_SOURCE_DIR}/support/check_format.cmake)
set_tests_properties(format.check PROPERTIES LABELS unit)
