# The GL layers: common/gl (thin RAII over OpenGL 4.1 core, through libepoxy) and common/app (the
# lesson framework: GLFW window or headless EGL, the loop, the UI, the command line).
pkg_check_modules(EPOXY REQUIRED IMPORTED_TARGET epoxy)
pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
find_package(glfw3 3.3 REQUIRED)

file(GLOB GL_SOURCES CONFIGURE_DEPENDS common/gl/*.cpp)
add_library(shadowlab_gl STATIC ${GL_SOURCES})
target_link_libraries(shadowlab_gl PUBLIC shadowlab_algorithms PkgConfig::EPOXY)

file(GLOB APP_SOURCES CONFIGURE_DEPENDS common/app/*.cpp)
add_library(shadowlab_app STATIC ${APP_SOURCES})
target_compile_definitions(shadowlab_app PUBLIC GLFW_INCLUDE_NONE)  # GL comes from epoxy only
target_link_libraries(shadowlab_app PUBLIC shadowlab_gl shadowlab_measure shadowlab_grading PkgConfig::EGL PkgConfig::IMGUI glfw ${CMAKE_DL_LIBS})

# The technique layer (common/technique): the contract every shadow technique keeps (technique.hpp)
# and the passes they share (scene cache, caster pass, lit pass, map settings). The techniques
# themselves live in the lesson that teaches them (cmake/lessons.cmake).
file(GLOB TECHNIQUE_SOURCES CONFIGURE_DEPENDS common/technique/*.cpp)
add_library(shadowlab_technique STATIC ${TECHNIQUE_SOURCES})
target_link_libraries(shadowlab_technique PUBLIC shadowlab_app)
