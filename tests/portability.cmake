# Beyond Debian (label portability): what can be checked on this machine of the macOS and Windows
# builds. The OpenGL 4.1 context itself is tests/gl41.cmake.
#   portability.mingw          core, algorithms, grading and measure cross-compiled for Windows
#                              (MinGW-w64, warnings as errors), no unguarded POSIX-only header
#   portability.mingw_detects  ...and that check fails on a file with a POSIX habit
#   portability.no_egl         the tree configured without EGL and without pkg-config, as macOS and
#                              Windows build it: lessons 01 and 03 and gpu_tests on a hidden GLFW
#                              window under Xvfb, images as the EGL build's
#   portability.clang          the whole tree compiled by clang with warnings as errors
if(SHADOWLAB_UNIT_ONLY)
  return()
endif()
set(portability ${CMAKE_BINARY_DIR}/portability)
file(MAKE_DIRECTORY ${portability})

add_test(NAME portability.mingw COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/portability/mingw.sh ${CMAKE_SOURCE_DIR}
         ${portability}/mingw)
add_test(NAME portability.mingw_detects COMMAND ${CMAKE_COMMAND} -DPROGRAM=bash
         "-DARGS=${CMAKE_CURRENT_SOURCE_DIR}/portability/mingw.sh;${CMAKE_CURRENT_SOURCE_DIR}/data/portability/posix_habit;${portability}/mingw_detects"
         -DEXIT=1 "-DSTDERR=common/core/wait_status.cpp includes a POSIX-only header without a Windows branch"
         -DWORKDIR=${portability}/mingw_detects_cwd -P ${CMAKE_CURRENT_SOURCE_DIR}/support/check_cli.cmake)
add_test(NAME portability.no_egl COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/portability/no_egl.sh ${CMAKE_SOURCE_DIR}
         ${portability}/no_egl)
set_tests_properties(portability.mingw portability.mingw_detects portability.no_egl PROPERTIES LABELS portability
                     TIMEOUT 1800)
add_test(NAME portability.clang COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/portability/clang.sh ${CMAKE_SOURCE_DIR}
         ${portability}/clang)
set_tests_properties(portability.clang PROPERTIES LABELS portability TIMEOUT 3600)
