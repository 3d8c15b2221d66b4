# Lesson 05's live theory, through the figures the header shows (--measure writes the counters):
#   the predicted half-width of the test edge (box edge 11, light0 at (0.96, 7, -1.62), R = 0.5):
#     its middle (-4.680, 2, -3.599) is 2 m over the ground, the light 5 m above it, so the ray from
#     the light's centre drops 5 over D = |(-5.640, -5, -1.979)| = 7.793 and reaches the ground after
#     d = 2/5 D = 3.117, with n.L = 5 / D = 0.6416: r = d / (n.L) R / D = 0.08 D R = 0.3117 m; twice
#     that for R = 1 (linear in R);
#   A_frac against (1 + a/R) / 2: 5.77 % at a/R = +-0.618 (sqrt(1 - pi^2 / 16));
#   with impl=student on the untouched stubs (half-width 0, both fractions 1/2): 0 m and 0 %, so the
#     student's code is what draws (only while exercises.cpp is pristine: STUBS_PRISTINE);
#   the predicted edges are drawn: the picture changes with theory.edges, and only with it (two
#     runs without are byte-identical);
#   the light mesh is baked once for a still light (1 build, maps reused), every frame for a moving one.
# Run: cmake -DLESSON=... -DOUT_DIR=... -DSTUBS_PRISTINE=ON|OFF -P this
include(${CMAKE_CURRENT_LIST_DIR}/soft_measure.cmake)
file(MAKE_DIRECTORY ${OUT_DIR})

function(expect_counter name counter pattern)
  string(JSON value ERROR_VARIABLE missing GET "${${name}_json}" counters "${counter}")
  if(missing)
    message(FATAL_ERROR "${name}: no counter '${counter}' in the header")
  endif()
  if(NOT value MATCHES "${pattern}")
    message(FATAL_ERROR "${name}: '${counter}' is '${value}', expected to match '${pattern}'")
  endif()
  message(STATUS "${name}: ${counter} = ${value}")
endfunction()

lesson_measure(r05 --frames 1)
expect_counter(r05 "penumbra r predicted" "^0\\.3117 m at the middle \\(edge 11\\)")
expect_counter(r05 "A_frac linear error" "^5\\.77 % at a/R = [-+]0\\.61[89]$")
lesson_measure(r10 --frames 1 --set light0.radius=1)
expect_counter(r10 "penumbra r predicted" "^0\\.623[34] m")
if(STUBS_PRISTINE)
  lesson_measure(student --frames 1 --set impl=student)
  expect_counter(student "penumbra r predicted" "^0\\.0000 m")
  expect_counter(student "A_frac linear error" "^0\\.00 %")
endif()

# The overlay: drawn with theory.edges, nothing else changes the picture.
foreach(run plain plain_again edges)
  set(extra "")
  if(run STREQUAL "edges")
    set(extra --set theory.edges=true)
  endif()
  execute_process(COMMAND ${LESSON} --headless --frames 1 --size 320x180 --strict-gl --preset penumbra_edges
                          --set theory.edges=false ${extra} --screenshot ${OUT_DIR}/theory_${run}.png
                  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${run}: lesson exited ${rc}: ${err}")
  endif()
  file(SHA256 ${OUT_DIR}/theory_${run}.png ${run}_hash)
endforeach()
if(NOT plain_hash STREQUAL plain_again_hash)
  message(FATAL_ERROR "two identical runs gave different pictures: the overlay check would mean nothing")
endif()
if(plain_hash STREQUAL edges_hash)
  message(FATAL_ERROR "theory.edges=true left the picture unchanged: the predicted edges are not drawn")
endif()
message(STATUS "the predicted edges change the picture; identical runs do not")

# The light mesh: baked once while nothing moves, every frame while the light does.
lesson_measure(still --frames 3 --set technique=mesh)
expect_counter(still "light mesh build" ", 1 build\\(s\\)$")
expect_counter(still "maps reused" "^1$")
file(WRITE ${OUT_DIR}/moving_light.path "shadowlab-path 1\n"
     "key 0  -5 12 12  -3.5 0 -0.5  0.96 7 -1.62  -0.33 -0.94 0.08\n"
     "key 1  -5 12 12  -3.5 0 -0.5  0.5 7 -1.0  -0.33 -0.94 0.08\n"
     "key 2  -5 12 12  -3.5 0 -0.5  0.0 7 -0.5  -0.33 -0.94 0.08\n")
lesson_measure(moving --frames 3 --set technique=mesh --replay ${OUT_DIR}/moving_light.path)
expect_counter(moving "light mesh build" ", 3 build\\(s\\)$")
