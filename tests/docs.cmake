# Citations a student can follow (label unit): no README, deck, document, lesson or shader source,
# framework source or header of the taught algorithms (the handout ships those without their sources)
# cites the internal "seeds NNN" names or points outside the repository (../shared), and every
# key cited as [Key] is an entry of docs/references.md.
add_test(NAME docs.citations COMMAND ${CMAKE_COMMAND} -DROOT=${CMAKE_SOURCE_DIR}
         -P ${CMAKE_CURRENT_SOURCE_DIR}/support/check_citations.cmake)
set_tests_properties(docs.citations PROPERTIES LABELS unit)
# ...and the check can fail: a fixture with a "Seeds NNN", a ../shared and an unknown key must be
# reported, each on its line.
add_test(NAME docs.citations_detects COMMAND ${CMAKE_COMMAND} -DROOT=${CMAKE_SOURCE_DIR}
         -DROOT_EXTRA=${CMAKE_CURRENT_SOURCE_DIR}/support/citations_bad.txt
         -P ${CMAKE_CURRENT_SOURCE_DIR}/support/check_citations.cmake)
set_tests_properties(docs.citations_detects PROPERTIES LABELS unit
  PASS_REGULAR_EXPRESSION "citations_bad.txt:2: cites an internal name.*citations_bad.txt:3: cites an internal name.*citations_bad.txt:4: \\[Nobody1999\\] is not an entry")
