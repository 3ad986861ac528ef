# Pure modules (no GL) and render tests (EGL; llvmpipe on CI).
tl_add_test(test_render SOURCES test_render.c LIBS tideline_gl)
tl_add_test(test_still_files SOURCES test_still_files.c LIBS tideline_gl)
tl_add_test(test_cli SOURCES test_cli.c LIBS tideline_core
  ARGS $<TARGET_FILE:tideline> ${PROJECT_SOURCE_DIR}/shaders)
tl_add_test(test_docs SOURCES test_docs.c LIBS tideline_core
  ARGS ${PROJECT_SOURCE_DIR}/docs/timeline.md)
