# cmake --install: the headless library as static libraries, its headers
# under include/tideline/ and a pkg-config file, so that a C program can
# link tideline without add_subdirectory:
#   cc app.c $(pkg-config --cflags --libs tideline)          # headless
#   cc app.c $(pkg-config --cflags --libs tideline-window)   # with the window
# Plain lib/ and include/ under the prefix: the .pc files find them
# relative to themselves.
set(CMAKE_INSTALL_LIBDIR lib)
set(CMAKE_INSTALL_INCLUDEDIR include)
set(tl_installed core scene metrics waves mesh optics sky prepare shader color audio image passes timeline cutscene
    job movie gl render)
set(tl_libs "")
foreach(m IN LISTS tl_installed)
  install(TARGETS tl_${m} ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  # Static libraries: each before the ones it uses.
  string(PREPEND tl_libs "-ltl_${m} ")
endforeach()
install(TARGETS tl_gl_window tl_render_window ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tideline
  FILES_MATCHING PATTERN "*.h"
  PATTERN "cli" EXCLUDE PATTERN "*_internal.h" EXCLUDE)
get_filename_component(tl_exr_libdir "${OPENEXR_CORE_LIB}" DIRECTORY)
get_filename_component(tl_exr_lib "${OPENEXR_CORE_LIB}" NAME_WE)
string(REGEX REPLACE "^lib" "" tl_exr_lib "${tl_exr_lib}")
set(TL_PC_LIBS "${tl_libs}-l${tl_exr_lib} -lpthread -lm")
set(TL_PC_CFLAGS "")
if(NOT OPENEXR_CORE_INCLUDE STREQUAL "/usr/include")
  set(TL_PC_CFLAGS "-I${OPENEXR_CORE_INCLUDE}")
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/tideline.pc.in ${PROJECT_BINARY_DIR}/tideline.pc @ONLY)
configure_file(${PROJECT_SOURCE_DIR}/cmake/tideline-window.pc.in
  ${PROJECT_BINARY_DIR}/tideline-window.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/tideline.pc ${PROJECT_BINARY_DIR}/tideline-window.pc
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
