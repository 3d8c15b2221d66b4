# shadowlab_sealed: the shader files tools/handout/sealed_shaders.txt lists, compiled in (obscured)
# by tools/seal_files, and the names of the withheld ones (their text is not compiled in). The
# #include preprocessor falls back on them when a file is absent on disk (core/shader_files.hpp).
# In this tree every file is on disk as well, so they change nothing; the student handout ships
# the library prebuilt (lib/) and leaves the files out.
set(SEALED_MANIFEST ${CMAKE_SOURCE_DIR}/tools/handout/sealed_shaders.txt)
if(EXISTS ${CMAKE_SOURCE_DIR}/lib/libshadowlab_sealed.a)
  add_library(shadowlab_sealed STATIC IMPORTED GLOBAL)
  set_target_properties(shadowlab_sealed PROPERTIES IMPORTED_LOCATION ${CMAKE_SOURCE_DIR}/lib/libshadowlab_sealed.a)
  return()
endif()
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${SEALED_MANIFEST})
file(STRINGS ${SEALED_MANIFEST} sealed_lines)
set(sealed_files "")
foreach(line IN LISTS sealed_lines)
  string(REGEX REPLACE "#.*" "" line "${line}")
  string(STRIP "${line}" line)
  string(REGEX REPLACE "^withheld[ \t]+" "" line "${line}")
  if(line)
    list(APPEND sealed_files ${CMAKE_SOURCE_DIR}/shaders/${line})
  endif()
endforeach()
if(SHADOWLAB_WEB)  # the tool runs on this machine, not in a browser: the host's compiler builds it
  set(seal_tool ${CMAKE_BINARY_DIR}/host/seal_files)
  add_custom_command(OUTPUT ${seal_tool}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/host
    COMMAND c++ -std=c++20 -O1 -I${CMAKE_SOURCE_DIR}/common ${CMAKE_SOURCE_DIR}/tools/seal_files.cpp -o ${seal_tool}
    DEPENDS ${CMAKE_SOURCE_DIR}/tools/seal_files.cpp ${CMAKE_SOURCE_DIR}/common/core/sealed_files.hpp
    COMMENT "Building the host tool seal_files")
else()
  add_executable(seal_files ${CMAKE_SOURCE_DIR}/tools/seal_files.cpp)
  target_include_directories(seal_files PRIVATE ${CMAKE_SOURCE_DIR}/common)
  set(seal_tool seal_files)
endif()
# The browser's pages show every technique, so by default they seal the withheld GLSL references
# in as well (obscured like the sealed files, which a browser's shader debugger still shows: see
# docs/teaching.md). -DSHADOWLAB_WEB_WITHHOLD=ON builds pages that withhold them as the handout does.
option(SHADOWLAB_WEB_WITHHOLD "browser build: withhold the GLSL exercises' references, as the handout does" OFF)
set(seal_manifest ${SEALED_MANIFEST})
if(SHADOWLAB_WEB AND NOT SHADOWLAB_WEB_WITHHOLD)
  set(seal_manifest ${CMAKE_BINARY_DIR}/generated/sealed_shaders_web.txt)
  file(READ ${SEALED_MANIFEST} manifest_text)
  string(REGEX REPLACE "(^|\n)withheld[ \t]+" "\\1" manifest_text "${manifest_text}")
  file(WRITE ${seal_manifest}.new "${manifest_text}")
  file(COPY_FILE ${seal_manifest}.new ${seal_manifest} ONLY_IF_DIFFERENT)
endif()
set(sealed_cpp ${CMAKE_BINARY_DIR}/generated/sealed_files.cpp)
add_custom_command(OUTPUT ${sealed_cpp}
  COMMAND ${seal_tool} ${seal_manifest} ${CMAKE_SOURCE_DIR}/shaders ${sealed_cpp}
  DEPENDS ${seal_tool} ${seal_manifest} ${sealed_files}
  COMMENT "Sealing the shader files of tools/handout/sealed_shaders.txt")
add_library(shadowlab_sealed STATIC ${sealed_cpp})
target_include_directories(shadowlab_sealed PRIVATE ${CMAKE_SOURCE_DIR}/common)
