# The test registration itself (label unit). Names holding ';' or ',' become one ctest entry each
# (registration_fixture's three cases, listed whole by `ctest -N`), and a run whose filter matches
# no case fails with the reason instead of passing with zero cases.
add_executable(registration_fixture ${CMAKE_CURRENT_SOURCE_DIR}/support/registration_fixture.cpp)
target_link_libraries(registration_fixture PRIVATE shadowlab_test_main)
shadowlab_discover_tests(registration_fixture LABELS unit)

add_test(NAME registration.zero_cases_fail COMMAND ${CMAKE_COMMAND} -DBIN=$<TARGET_FILE:registration_fixture>
         -P ${CMAKE_CURRENT_SOURCE_DIR}/support/check_zero_cases.cmake)
add_test(NAME registration.names_whole COMMAND ${CMAKE_COMMAND} -DCTEST=${CMAKE_CTEST_COMMAND}
         -DBUILD=${CMAKE_BINARY_DIR} -P ${CMAKE_CURRENT_SOURCE_DIR}/support/check_names_whole.cmake)
set_tests_properties(registration.zero_cases_fail registration.names_whole PROPERTIES LABELS unit)
