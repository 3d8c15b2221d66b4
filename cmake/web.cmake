# The browser build (make web): the same lesson sources compiled by Debian's emscripten to
# WebAssembly + WebGL2, configured with emscripten's CMake toolchain (tools/wasm/build.sh).
#
# Where each dependency comes from:
#   GLM, stb, nlohmann-json, doctest  Debian's header-only packages, through a folder of links
#                                     (-I/usr/include would pull glibc's headers into the build)
#   Dear ImGui, libspng, zlib         Debian's source packages, compiled here (tools/wasm/debian-sources.sh
#                                     fetched them into SHADOWLAB_WEB_SOURCES)
#   GLFW, OpenGL ES 3.0               emscripten's own (-sUSE_GLFW=3, WebGL2)
#   Embree, Assimp, EGL               none: the ground truth, --model and headless runs say on the page
#                                     that they need the native lesson (`make run`)
set(SHADOWLAB_WEB TRUE)
set(SHADOWLAB_SOURCE_ROOT /shadowlab)  # where the page's data puts the tree's files (shadowlab_web_page)
set(SHADOWLAB_WEB_SOURCES "" CACHE PATH "Debian's unpacked source packages (tools/wasm/debian-sources.sh)")
if(NOT EXISTS "${SHADOWLAB_WEB_SOURCES}/imgui/imgui.h")
  message(FATAL_ERROR "shadowlab web: SHADOWLAB_WEB_SOURCES='${SHADOWLAB_WEB_SOURCES}' holds no imgui/imgui.h; "
                      "`make web` fetches Debian's source packages there (tools/wasm/debian-sources.sh DIR)")
endif()
# Every object of the browser build: C++ exceptions are how the course reports bad input (a bad
# preset, a missing file), so they are compiled in (WebAssembly's own exception handling).
add_compile_options(-fwasm-exceptions)
add_link_options(-fwasm-exceptions)

set(headers ${CMAKE_BINARY_DIR}/system-headers)
file(MAKE_DIRECTORY ${headers})
foreach(dir IN ITEMS glm stb nlohmann doctest)
  if(NOT EXISTS /usr/include/${dir})
    message(FATAL_ERROR "shadowlab web: /usr/include/${dir} missing; `make deps` installs Debian's package")
  endif()
  file(CREATE_LINK /usr/include/${dir} ${headers}/${dir} SYMBOLIC)
endforeach()
add_library(shadowlab_web_headers INTERFACE)
target_include_directories(shadowlab_web_headers SYSTEM INTERFACE ${headers} ${headers}/stb)
foreach(alias IN ITEMS glm::glm shadowlab::stb nlohmann_json::nlohmann_json doctest::doctest)
  add_library(${alias} ALIAS shadowlab_web_headers)
endforeach()

set(src ${SHADOWLAB_WEB_SOURCES})
file(GLOB zlib_sources ${src}/zlib/*.c)
list(FILTER zlib_sources EXCLUDE REGEX "/(example|minigzip)\\.c$")
add_library(shadowlab_web_zlib STATIC ${zlib_sources})
target_include_directories(shadowlab_web_zlib SYSTEM PUBLIC ${src}/zlib)
target_compile_options(shadowlab_web_zlib PRIVATE -w)
add_library(shadowlab_web_spng STATIC ${src}/spng/spng/spng.c)
target_include_directories(shadowlab_web_spng SYSTEM PUBLIC ${src}/spng/spng)
target_compile_definitions(shadowlab_web_spng PUBLIC SPNG_STATIC)
target_compile_options(shadowlab_web_spng PRIVATE -w)
target_link_libraries(shadowlab_web_spng PUBLIC shadowlab_web_zlib)
add_library(shadowlab::spng ALIAS shadowlab_web_spng)

set(imgui ${src}/imgui)
add_library(shadowlab_web_imgui STATIC ${imgui}/imgui.cpp ${imgui}/imgui_draw.cpp ${imgui}/imgui_tables.cpp
                                       ${imgui}/imgui_widgets.cpp ${imgui}/imgui_demo.cpp
                                       ${imgui}/backends/imgui_impl_glfw.cpp ${imgui}/backends/imgui_impl_opengl3.cpp)
target_include_directories(shadowlab_web_imgui SYSTEM PUBLIC ${imgui} ${imgui}/backends)
target_compile_options(shadowlab_web_imgui PRIVATE -w -sUSE_GLFW=3)
add_library(shadowlab::imgui ALIAS shadowlab_web_imgui)

# emscripten's GLFW 3 and WebGL 2 (OpenGL ES 3.0): link options of every lesson page.
add_library(glfw INTERFACE)
target_compile_options(glfw INTERFACE -sUSE_GLFW=3)
target_link_options(glfw INTERFACE -sUSE_GLFW=3 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2 -sFULL_ES3=1)
add_library(shadowlab_web_none INTERFACE)
add_library(shadowlab::epoxy ALIAS shadowlab_web_none)  # GL comes from <GLES3/gl3.h> (gl/gl.hpp)
add_library(assimp::assimp ALIAS shadowlab_web_none)

# The lessons the browser build makes pages of: every one.
set(SHADOWLAB_WEB_LESSONS 01 02 03 04 05 06 07 08 09 10)

# shadowlab_web_page(TARGET LESSON): the lesson's program as a page in ${CMAKE_BINARY_DIR}/site:
# TARGET.html (tools/wasm/shell.html around the canvas), .js, .wasm and .data (the files the
# program reads, at the paths it reads them natively, under /shadowlab). The sealed and withheld
# shader files stay out of the data, as they stay out of the student handout (the sealed ones are
# compiled in, obscured).
function(shadowlab_web_page target lesson)
  set(root ${CMAKE_SOURCE_DIR})
  set(excludes "")
  foreach(file IN LISTS sealed_files)  # cmake/sealed.cmake's list, sealed and withheld alike
    list(APPEND excludes "SHELL:--exclude-file ${file}")
  endforeach()
  set_target_properties(${target} PROPERTIES SUFFIX ".html" RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/site)
  target_link_options(${target} PRIVATE
    --shell-file ${root}/tools/wasm/shell.html -sMINIFY_HTML=0
    -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=64MB -sEXIT_RUNTIME=0
    "SHELL:-sEXPORTED_RUNTIME_METHODS=['callMain','FS','ccall']"
    ${excludes}
    "SHELL:--preload-file ${root}/shaders@/shadowlab/shaders"
    "SHELL:--preload-file ${root}/textures@/shadowlab/textures"
    "SHELL:--preload-file ${root}/lessons/${lesson}/presets.txt@/shadowlab/lessons/${lesson}/presets.txt")
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${root}/tools/wasm/shell.html)
endfunction()
