# Every dependency is a Debian 12 package. A missing one stops configure with
# the package to install (scripts/setup.sh installs them all).
find_package(PkgConfig)
if(NOT PKG_CONFIG_FOUND)
  message(FATAL_ERROR "pkg-config not found: install the Debian package 'pkg-config'")
endif()

function(tl_require_pkg var module debian_pkg)
  pkg_check_modules(${var} QUIET IMPORTED_TARGET ${module})
  if(NOT ${var}_FOUND)
    message(FATAL_ERROR
      "Missing dependency '${module}': install the Debian package '${debian_pkg}' "
      "(or run scripts/setup.sh)")
  endif()
  message(STATUS "Found ${module} ${${var}_VERSION}")
endfunction()

tl_require_pkg(EGL egl libegl-dev)
tl_require_pkg(EPOXY epoxy libepoxy-dev)
tl_require_pkg(CGLM cglm libcglm-dev)
tl_require_pkg(OPENEXR OpenEXR libopenexr-dev)
tl_require_pkg(PNG libpng libpng-dev)
tl_require_pkg(GLFW glfw3 libglfw3-dev)
tl_require_pkg(ASSIMP assimp libassimp-dev)
tl_require_pkg(STB stb libstb-dev)
tl_require_pkg(OCIO OpenColorIO libopencolorio-dev)
tl_require_pkg(SNDFILE sndfile libsndfile1-dev)
tl_require_pkg(SDL2 sdl2 libsdl2-dev)

# OpenEXR's pkg-config file names the C++ libraries too; tideline uses only
# the C API, so link OpenEXRCore alone.
find_library(OPENEXR_CORE_LIB OpenEXRCore-3_1 OpenEXRCore HINTS ${OPENEXR_LIBRARY_DIRS})
find_path(OPENEXR_CORE_INCLUDE OpenEXR/openexr.h HINTS ${OPENEXR_INCLUDEDIR}/..)
if(NOT OPENEXR_CORE_LIB OR NOT OPENEXR_CORE_INCLUDE)
  message(FATAL_ERROR "OpenEXRCore (C API) not found: install the Debian package 'libopenexr-dev'")
endif()
add_library(tl_openexr_core INTERFACE)
target_link_libraries(tl_openexr_core INTERFACE ${OPENEXR_CORE_LIB})
target_include_directories(tl_openexr_core INTERFACE ${OPENEXR_CORE_INCLUDE})

# tinygltf writes the camera's glTF (tideline export-camera). Debian's
# package ships the library and its header, whose declarations need no
# JSON library.
find_package(TinyGLTF CONFIG QUIET)
if(NOT TinyGLTF_FOUND)
  message(FATAL_ERROR "Missing dependency 'TinyGLTF': install the Debian package 'libtinygltf-dev' "
                      "(or run scripts/setup.sh)")
endif()

find_library(MATH_LIB m)

# POSIX threads: render writes frame n-1 while frame n renders.
set(THREADS_PREFER_PTHREAD_FLAG ON)
find_package(Threads REQUIRED)
