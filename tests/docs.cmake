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

# Every lesson README in one order, true to its lesson (label docs; needs the lesson binaries and
# node): tools/docs/lesson_docs.mjs --check. The sections, 3-5 outcomes, the time and prerequisites
# the lesson states (--info), one item per main.cpp banner, the generated hotkeys and presets
# blocks and the top README's lessons table as `make docs` writes them, "What to try" items each
# from a preset that exists, every exercise and `make grade LESSON=NN`, no ctest grading command
# and no dated diary; and every lesson's F1 help names a key only with the parameter it drives.
find_program(DOCS_NODE node)
if(TARGET lesson_10_showdown AND DOCS_NODE)
  add_test(NAME docs.lesson_readmes
           COMMAND ${DOCS_NODE} ${CMAKE_SOURCE_DIR}/tools/docs/lesson_docs.mjs --bin $<TARGET_FILE_DIR:lesson_01_lighting>
                   --root ${CMAKE_SOURCE_DIR} --check)
  set_tests_properties(docs.lesson_readmes PROPERTIES LABELS docs)
  # ...and the check can fail: a fixture that breaks each rule, each reported on its line.
  add_test(NAME docs.lesson_readmes_detects
           COMMAND ${DOCS_NODE} ${CMAKE_SOURCE_DIR}/tools/docs/lesson_docs.mjs --bin $<TARGET_FILE_DIR:lesson_01_lighting>
                   --root ${CMAKE_SOURCE_DIR} --check --lesson 03_shadow_quality
                   --readme ${CMAKE_CURRENT_SOURCE_DIR}/support/readme_bad.md)
  set_tests_properties(docs.lesson_readmes_detects PROPERTIES LABELS docs
    PASS_REGULAR_EXPRESSION "readme_bad.md:3: the ## sections are \\[What you will learn, Time and prerequisites, Theory, The passes, What to try, Exercises, Measured\\].*readme_bad.md:3: \"What you will learn\" has 2 outcomes.*readme_bad.md:7: time in class says 45 minutes; the lesson \\(--info\\) says 120.*readme_bad.md:7: prerequisites name lessons \\[05\\]; the lesson \\(--info\\) says \\[02\\].*readme_bad.md:14: the passes are numbered \\[1, 3\\]; main.cpp's banners are \\[1, 2, 3, 4\\].*no generated hotkeys block.*no generated presets block.*readme_bad.md:19: a \"What to try\" item starts with `--preset NAME`.*readme_bad.md:12: \"3 December 2026\": a dated figure.*readme_bad.md:20: --preset no_such_preset_xyz: no such preset.*readme_bad.md:24: grade with \"make grade LESSON=03\".*readme_bad.md:23: exercise 03.6 \\(pcfKernel\\) is not in \"Exercises\".*readme_bad.md:23: \"Exercises\" does not give the command that grades them: make grade LESSON=03")
endif()
if(TARGET lesson_05_soft_shadows AND DOCS_NODE)
  # ...and the F1 help's key check can fail: lesson 05's old help (keys A and E, taken by the fly
  # camera; letters whose parameter the line does not name) and framework keys, each reported.
  add_test(NAME docs.help_keys_detects
           COMMAND ${DOCS_NODE} ${CMAKE_SOURCE_DIR}/tools/docs/lesson_docs.mjs --bin $<TARGET_FILE_DIR:lesson_05_soft_shadows>
                   --root ${CMAKE_SOURCE_DIR} --check --lesson 05_soft_shadows
                   --help-text ${CMAKE_CURRENT_SOURCE_DIR}/support/help_bad.txt)
  set_tests_properties(docs.help_keys_detects PROPERTIES LABELS docs
    PASS_REGULAR_EXPRESSION "help_bad.txt:1: the help names key T, which drives technique; the line does not name technique.*help_bad.txt:4: the help names key A, which drives nothing in this lesson \\(A is the framework's\\).*help_bad.txt:6: the help names key R, which drives nothing.*help_bad.txt:6: the help names key Q")
endif()
