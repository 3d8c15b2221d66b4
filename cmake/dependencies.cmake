# Finding the libraries the way each platform provides them, in this order:
#   1. a CMake package (vcpkg on Windows and macOS, Homebrew, Debian where it ships one),
#   2. pkg-config (Debian's only form for epoxy, imgui, spng, stb and EGL),
#   3. a header and a library wherever CMake looks (CMAKE_PREFIX_PATH; a plain install).
# Each dependency becomes one target, shadowlab::NAME, and configure prints one line saying where
# it came from. -DSHADOWLAB_PKG_CONFIG=OFF skips step 2 (the portability test builds that way, so
# step 3 is exercised on every `make test`).
option(SHADOWLAB_PKG_CONFIG "Look for dependencies through pkg-config after CMake packages" ON)
if(SHADOWLAB_PKG_CONFIG)
  find_package(PkgConfig QUIET)
endif()

# shadowlab_dependency(NAME [PACKAGE pkg TARGETS t1 t2...] [PKG_CONFIG module]
#                      [HEADER file [SUFFIXES dir...]] [LIBRARY names...] [ALSO_LINK names...]
#                      [INCLUDE_EXTRA header...] [OPTIONAL])
# ALSO_LINK: libraries the found library needs where they exist (Debian's libimgui.a wants libstb,
# which its pkg-config file says and a bare library cannot). INCLUDE_EXTRA: headers in a folder
# of their own (imgui's backends) whose folder is added too.
# HEADER without LIBRARY: a header-only library. The found include directory is the one that holds
# HEADER, so sources include <HEADER> whatever the platform's folder layout.
function(shadowlab_dependency name)
  cmake_parse_arguments(arg "OPTIONAL" "PACKAGE;PKG_CONFIG;HEADER" "TARGETS;SUFFIXES;LIBRARY;INCLUDE_EXTRA;ALSO_LINK" ${ARGN})
  set(target shadowlab_dep_${name})
  add_library(${target} INTERFACE IMPORTED GLOBAL)
  add_library(shadowlab::${name} ALIAS ${target})
  set(how "")
  if(arg_PACKAGE)
    find_package(${arg_PACKAGE} CONFIG QUIET)
    foreach(t IN LISTS arg_TARGETS)
      if(NOT how AND TARGET ${t})
        target_link_libraries(${target} INTERFACE ${t})
        set(how "CMake package ${arg_PACKAGE} (${t})")
      endif()
    endforeach()
  endif()
  if(NOT how AND arg_PKG_CONFIG AND PKG_CONFIG_FOUND)
    pkg_check_modules(SHADOWLAB_PC_${name} QUIET IMPORTED_TARGET ${arg_PKG_CONFIG})
    if(SHADOWLAB_PC_${name}_FOUND)
      target_link_libraries(${target} INTERFACE PkgConfig::SHADOWLAB_PC_${name})
      set(how "pkg-config ${arg_PKG_CONFIG}")
    endif()
  endif()
  if(NOT how AND arg_HEADER)
    find_path(SHADOWLAB_${name}_INCLUDE ${arg_HEADER} PATH_SUFFIXES ${arg_SUFFIXES})
    set(library_ok TRUE)
    if(arg_LIBRARY)
      find_library(SHADOWLAB_${name}_LIBRARY NAMES ${arg_LIBRARY})
      if(NOT SHADOWLAB_${name}_LIBRARY)
        set(library_ok FALSE)
      endif()
    endif()
    if(SHADOWLAB_${name}_INCLUDE AND library_ok)
      target_include_directories(${target} INTERFACE ${SHADOWLAB_${name}_INCLUDE})
      if(arg_LIBRARY)
        target_link_libraries(${target} INTERFACE ${SHADOWLAB_${name}_LIBRARY})
      endif()
      foreach(also IN LISTS arg_ALSO_LINK)
        find_library(SHADOWLAB_${name}_${also}_LIBRARY NAMES ${also})
        if(SHADOWLAB_${name}_${also}_LIBRARY)
          target_link_libraries(${target} INTERFACE ${SHADOWLAB_${name}_${also}_LIBRARY})
        endif()
      endforeach()
      set(how "header ${SHADOWLAB_${name}_INCLUDE}/${arg_HEADER}")
      if(arg_LIBRARY)
        string(APPEND how ", library ${SHADOWLAB_${name}_LIBRARY}")
      endif()
    endif()
  endif()
  if(how)
    # The folder that holds HEADER, whichever way the package came: Debian's imgui.pc names
    # /usr/include/imgui, its backends sit one folder deeper; vcpkg puts them beside imgui.h.
    foreach(extra IN LISTS arg_INCLUDE_EXTRA)
      find_path(SHADOWLAB_${name}_${extra}_DIR ${extra} HINTS ${SHADOWLAB_PC_${name}_INCLUDE_DIRS} ${SHADOWLAB_${name}_INCLUDE}
                PATH_SUFFIXES backends imgui imgui/backends)
      if(SHADOWLAB_${name}_${extra}_DIR)
        target_include_directories(${target} INTERFACE ${SHADOWLAB_${name}_${extra}_DIR})
      endif()
    endforeach()
    message(STATUS "shadowlab: ${name} from ${how}")
    set(SHADOWLAB_HAVE_${name} TRUE PARENT_SCOPE)
  elseif(arg_OPTIONAL)
    message(STATUS "shadowlab: ${name} not found (optional)")
    set(SHADOWLAB_HAVE_${name} FALSE PARENT_SCOPE)
  else()
    message(FATAL_ERROR "shadowlab: ${name} not found: tried the CMake package '${arg_PACKAGE}', pkg-config "
                        "'${arg_PKG_CONFIG}' and the header '${arg_HEADER}'. On Debian/Ubuntu `make deps` "
                        "installs it; on Windows and macOS use the vcpkg manifest (vcpkg.json, see README.md).")
  endif()
endfunction()
