# Stress suite: seeded random PSM configurations with invariants (GL-free, label `stress`).
# SHADOWLAB_STRESS_CONFIGS sets the count (default 100000); `stress_soak` runs 10,000,000.
file(GLOB STRESS_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/stress/*.cpp)
if(STRESS_SOURCES)
  add_executable(stress_tests ${STRESS_SOURCES})
  target_link_libraries(stress_tests PRIVATE shadowlab_test_main shadowlab_algorithms)
  shadowlab_discover_tests(stress_tests LABELS stress)
  add_custom_target(stress_soak
    COMMAND ${CMAKE_COMMAND} -E env SHADOWLAB_STRESS_CONFIGS=10000000 $<TARGET_FILE:stress_tests>
    DEPENDS stress_tests USES_TERMINAL
    COMMENT "PSM stress soak: 10,000,000 configurations")
endif()
