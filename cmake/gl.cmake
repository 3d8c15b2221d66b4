# The GL layers: common/gl (thin RAII over OpenGL 4.1 core, through libepoxy) and common/app (the
# lesson framework: GLFW window or headless EGL, the loop, the UI, the command line).
if(NOT SHADOWLAB_WEB)  # the browser build has its own (cmake/web.cmake)
  shadowlab_dependency(epoxy PKG_CONFIG epoxy HEADER epoxy/gl.h LIBRARY epoxy)
  shadowlab_dependency(imgui PACKAGE imgui TARGETS imgui::imgui PKG_CONFIG imgui HEADER imgui.h SUFFIXES imgui
                       LIBRARY imgui ALSO_LINK stb INCLUDE_EXTRA imgui_impl_glfw.h)
  find_package(glfw3 3.3 REQUIRED)

  # Headless runs (tests, graders, benchmarks, --headless) use EGL where the platform has it (Linux:
  # Mesa's surfaceless platform or a GPU's device platform), else a hidden GLFW window rendering into
  # the same offscreen framebuffer (macOS and Windows have no EGL; that path needs a display).
  # SHADOWLAB_EGL: AUTO (EGL when found), ON (required), OFF (the hidden window; tested here under
  # Xvfb by portability.no_egl).
  set(SHADOWLAB_EGL AUTO CACHE STRING "Headless contexts through EGL: AUTO, ON or OFF")
  set_property(CACHE SHADOWLAB_EGL PROPERTY STRINGS AUTO ON OFF)
  if(NOT SHADOWLAB_EGL STREQUAL "OFF")
    if(SHADOWLAB_EGL STREQUAL "ON")
      shadowlab_dependency(egl PKG_CONFIG egl HEADER EGL/egl.h LIBRARY EGL)
    else()
      shadowlab_dependency(egl PKG_CONFIG egl HEADER EGL/egl.h LIBRARY EGL OPTIONAL)
    endif()
  endif()
endif()

file(GLOB GL_SOURCES CONFIGURE_DEPENDS common/gl/*.cpp)
shadowlab_platform_sources(GL_SOURCES)
add_library(shadowlab_gl STATIC ${GL_SOURCES})
target_link_libraries(shadowlab_gl PUBLIC shadowlab_algorithms shadowlab::epoxy)

file(GLOB APP_SOURCES CONFIGURE_DEPENDS common/app/*.cpp)
shadowlab_platform_sources(APP_SOURCES)
if(SHADOWLAB_WEB)  # one context: the page's canvas (context_web.cpp)
  list(FILTER APP_SOURCES EXCLUDE REGEX "/context_(egl|glfw)\\.cpp$")
  set(headless "nothing: a page always draws into its canvas")
elseif(SHADOWLAB_HAVE_egl)
  set(headless "EGL")
else()
  list(FILTER APP_SOURCES EXCLUDE REGEX "/context_egl\\.cpp$")
  # Only this file's command line differs, so every other object is the EGL build's (compiler cache).
  set_property(SOURCE common/app/context_glfw.cpp APPEND PROPERTY COMPILE_DEFINITIONS SHADOWLAB_HEADLESS_GLFW)
  set(headless "a hidden GLFW window (no EGL: needs a display)")
endif()
message(STATUS "shadowlab: headless runs through ${headless}")
add_library(shadowlab_app STATIC ${APP_SOURCES})
target_compile_definitions(shadowlab_app PUBLIC GLFW_INCLUDE_NONE)  # GL comes from epoxy only
target_link_libraries(shadowlab_app PUBLIC shadowlab_gl shadowlab_measure shadowlab_grading shadowlab::imgui glfw
                                           ${CMAKE_DL_LIBS})
if(SHADOWLAB_HAVE_egl)
  target_link_libraries(shadowlab_app PUBLIC shadowlab::egl)
endif()

# The technique layer (common/technique): the contract every shadow technique keeps (technique.hpp)
# and the passes they share (scene cache, caster pass, lit pass, map settings). The techniques
# themselves live in the lesson that teaches them (cmake/lessons.cmake).
file(GLOB TECHNIQUE_SOURCES CONFIGURE_DEPENDS common/technique/*.cpp)
add_library(shadowlab_technique STATIC ${TECHNIQUE_SOURCES})
target_link_libraries(shadowlab_technique PUBLIC shadowlab_app)
