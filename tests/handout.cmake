# The student handout and the instructor's grader (label handout, part of make test; they build a
# second tree and the grader, so they take minutes):
#   handout.make                 make handout, into build/.../handout
#   handout.no_reference_bodies  no line of any reference implementation is in it (text files and
#                                the libraries' strings)
#   handout.leak_detected        ...and that check fails on a folder holding a reference file
#   handout.builds               unpacked outside this tree it builds with make build, refers
#                                nowhere into this tree, runs every lesson with impl=reference and
#                                passes its own unit and validity tests
#   handout.grade_untouched      the grader (public and hidden cases) on the untouched handout: 0
#   handout.grade_reference      the grader on the reference solutions: full marks, hidden included
#   handout.grade_one_week       the same with LESSONS=01,03: exactly those lessons graded, full marks
# The handout itself has no make_handout.sh, so it has none of these.
if(SHADOWLAB_UNIT_ONLY OR SHADOWLAB_SUBMISSION OR NOT EXISTS ${CMAKE_SOURCE_DIR}/tools/handout/make_handout.sh)
  return()
endif()
set(handout ${CMAKE_BINARY_DIR}/handout)
set(check bash ${CMAKE_SOURCE_DIR}/tools/handout/check_handout.sh)
add_test(NAME handout.make COMMAND ${CMAKE_COMMAND} -E env SHADOWLAB_BUILD=${CMAKE_BINARY_DIR}
                                   bash ${CMAKE_SOURCE_DIR}/tools/handout/make_handout.sh ${handout})
set_tests_properties(handout.make PROPERTIES FIXTURES_SETUP handout)
add_test(NAME handout.no_reference_bodies COMMAND ${check} bodies ${handout}/shadowlab)
add_test(NAME handout.leak_detected COMMAND ${check} leak ${CMAKE_BINARY_DIR}/handout-leak)
# Unpacked outside this tree (its build must not refer into it), in a folder of this build's own:
# two checkouts testing at once (worktrees, CI beside a developer) must not share it.
string(MD5 build_id ${CMAKE_BINARY_DIR})
string(SUBSTRING ${build_id} 0 12 build_id)
add_test(NAME handout.builds COMMAND ${check} build ${handout}/shadowlab-student.tar.gz /tmp/shadowlab_handout_check_${build_id})
add_test(NAME handout.grade_untouched COMMAND ${check} grade ${handout}/shadowlab ${handout}/grade_untouched zero)
add_test(NAME handout.grade_reference COMMAND ${check} grade reference ${handout}/grade_reference full)
# One week's assignment alone (LESSONS=01,03): only those lessons built and graded, full marks.
add_test(NAME handout.grade_one_week COMMAND ${CMAKE_COMMAND} -E env LESSONS=01,03 ${check} grade reference
                                             ${handout}/grade_one_week full)
set_tests_properties(handout.no_reference_bodies handout.builds handout.grade_untouched handout.grade_reference
                     handout.grade_one_week PROPERTIES FIXTURES_REQUIRED handout)
set_tests_properties(handout.grade_untouched handout.grade_reference handout.grade_one_week PROPERTIES
                     RESOURCE_LOCK grade_submission)
set_tests_properties(handout.make handout.no_reference_bodies handout.leak_detected handout.builds handout.grade_untouched
                     handout.grade_reference handout.grade_one_week PROPERTIES LABELS handout TIMEOUT 3600)
