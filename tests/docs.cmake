# Citations a student can follow (label unit): no README, deck, document, exercise statement or
# header of the taught algorithms (the handout ships those without their sources)
# cites the internal "seeds NNN" names or points outside the repository (../shared), and every
# key cited as [Key] is an entry of docs/references.md.
add_test(NAME docs.citations COMMAND ${CMAKE_COMMAND} -DROOT=${CMAKE_SOURCE_DIR}
         -P ${CMAKE_CURRENT_SOURCE_DIR}/support/check_citations.cmake)
set_tests_properties(docs.citations PROPERTIES LABELS unit)
