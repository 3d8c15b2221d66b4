# Slides (label: slides): every deck slides/NN_name.md is built with figures rendered by the lesson
# binaries of THIS build, then opened in headless Chromium (tools/web/check-page.mjs): no console or
# page error, every image loaded, every formula rendered (no .katex-error), and as many slides as
# the source has. Needs node, the npm packages (npm ci --prefix tools/web) and /usr/bin/chromium;
# `make test` installs them. Output goes to the build tree, never to out/.
#   slides.build            builds every deck (HTML + PDF) into <build>/slides (fixture)
#   slides.check.NN_name    checks one deck, slide count taken from the Markdown by this file
#   slides.selftest         proves the checks fail: broken formula, missing image, bad preset, ...

if(NOT TARGET lesson_01_lighting)
  message(STATUS "slides tests: no lesson_01_lighting target in this build (GL off?); slide tests not registered")
  return()
endif()
find_program(NODE node)
if(NOT NODE)
  message(WARNING "slides tests: node not found; slide tests not registered (tools/install-deps.sh --slides)")
  return()
endif()

set(SLIDES_SOURCE_DIR ${CMAKE_SOURCE_DIR}/slides)
set(SLIDES_OUT ${CMAKE_BINARY_DIR}/slides)
set(SLIDES_BIN $<TARGET_FILE_DIR:lesson_01_lighting>)

# Slide count from the Markdown, independently of the builder: lines that are exactly `---` outside
# fenced code, minus the two that delimit the front matter, plus one.
function(slides_count_in deck out_var)
  file(STRINGS ${deck} lines REGEX "^(---[ \t]*| ? ? ?(```|~~~).*)$")
  set(separators 0)
  set(fence "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^ ? ? ?(```|~~~)")
      string(SUBSTRING "${CMAKE_MATCH_1}" 0 1 mark)
      if(fence STREQUAL "")
        set(fence "${mark}")
      elseif(fence STREQUAL mark)
        set(fence "")
      endif()
    elseif(fence STREQUAL "" AND line MATCHES "^---[ \t]*$")
      math(EXPR separators "${separators} + 1")
    endif()
  endforeach()
  math(EXPR slides "${separators} - 2 + 1")
  set(${out_var} ${slides} PARENT_SCOPE)
endfunction()

file(GLOB SLIDE_DECKS CONFIGURE_DEPENDS ${SLIDES_SOURCE_DIR}/[0-9][0-9]_*.md)
if(NOT SLIDE_DECKS)
  message(STATUS "slides tests: no decks in ${SLIDES_SOURCE_DIR}")
  return()
endif()

add_test(NAME slides.build
  COMMAND ${NODE} ${CMAKE_SOURCE_DIR}/tools/slides/build.mjs --bin ${SLIDES_BIN} --out ${SLIDES_OUT}
          --decks ${SLIDES_SOURCE_DIR}
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(slides.build PROPERTIES LABELS slides FIXTURES_SETUP slides_built TIMEOUT 600)

foreach(deck IN LISTS SLIDE_DECKS)
  get_filename_component(name ${deck} NAME_WE)
  slides_count_in(${deck} expected)
  # The expected count is read at configure time: re-configure (on the next build) when a deck changes.
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${deck})
  add_test(NAME slides.check.${name}
    COMMAND ${NODE} ${CMAKE_SOURCE_DIR}/tools/web/check-page.mjs ${SLIDES_OUT}/${name}.html --expect-slides ${expected}
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(slides.check.${name} PROPERTIES LABELS slides FIXTURES_REQUIRED slides_built TIMEOUT 120)
endforeach()

add_test(NAME slides.check.index
  COMMAND ${NODE} ${CMAKE_SOURCE_DIR}/tools/web/check-page.mjs ${SLIDES_OUT}/index.html
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(slides.check.index PROPERTIES LABELS slides FIXTURES_REQUIRED slides_built TIMEOUT 120)

add_test(NAME slides.selftest
  COMMAND ${NODE} ${CMAKE_SOURCE_DIR}/tools/slides/selftest.mjs --bin ${SLIDES_BIN} --lesson 01_lighting
          --work ${CMAKE_CURRENT_BINARY_DIR}/slides_selftest
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(slides.selftest PROPERTIES LABELS slides TIMEOUT 300)

# Every deck shows its lesson's passes and exercises as generated blocks ({{passes}}, {{exercises}}:
# tools/slides/deck.mjs fills them from main.cpp and --info), so no deck lists them by hand and
# falls behind its lesson (seven decks had left exercises out).
foreach(deck IN LISTS SLIDE_DECKS)
  get_filename_component(name ${deck} NAME_WE)
  add_test(NAME slides.generated.${name}
           COMMAND ${CMAKE_COMMAND} -DDECK=${deck} -P ${CMAKE_CURRENT_SOURCE_DIR}/support/check_deck_generated.cmake)
  set_tests_properties(slides.generated.${name} PROPERTIES LABELS slides)
endforeach()
