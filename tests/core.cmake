# Pure modules (no GL) and render tests (EGL; llvmpipe on CI).
tl_add_test(test_render SOURCES test_render.c LIBS tideline_gl)
tl_add_test(test_still_files SOURCES test_still_files.c LIBS tideline_gl)
tl_add_test(test_render_progress SOURCES test_render_progress.c LIBS tideline_gl)
tl_add_test(test_cli SOURCES test_cli.c LIBS tideline_core
  ARGS $<TARGET_FILE:tideline> ${PROJECT_SOURCE_DIR}/shaders)
tl_add_test(test_docs SOURCES test_docs.c LIBS tideline_core
  ARGS ${PROJECT_SOURCE_DIR}/docs/timeline.md)
# The library example renders a frame of a bundled timeline.
add_test(NAME example_render_frame
  COMMAND sh -c "$<TARGET_FILE:render_frame> ${PROJECT_SOURCE_DIR}/timelines/calm.tl 12 example.png 64x36 && test -s example.png && rm example.png && echo EXAMPLE_OK"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(example_render_frame PROPERTIES PASS_REGULAR_EXPRESSION "frame 12 \\(t = 0.5000 s\\) -> example.png\nEXAMPLE_OK")
tl_add_test(test_writer SOURCES test_writer.c ${PROJECT_SOURCE_DIR}/src/cli/tl_cli_writer.c
  LIBS tideline_core)
tl_add_test(test_render_cmd SOURCES test_render_cmd.c LIBS tideline_gl
  ARGS $<TARGET_FILE:tideline>)
# Every bundled timeline is valid.
add_test(NAME check_bundled_timelines
  COMMAND sh -c "for f in ${PROJECT_SOURCE_DIR}/timelines/*.tl; do $<TARGET_FILE:tideline> check \"$f\" >/dev/null || exit 1; done")
# The farm example splits a shot over 3 processes; together they write every frame.
add_test(NAME example_farm_xargs
  COMMAND sh -c "rm -rf farm && TIDELINE=$<TARGET_FILE:tideline> ${PROJECT_SOURCE_DIR}/examples/farm/xargs.sh ${PROJECT_SOURCE_DIR}/timelines/calm.tl farm 3 --frames 0-239:24 --size 32x18 --quality draft && test $(ls farm | wc -l) -eq 10 && ls farm/calm_0216.exr && rm -rf farm"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
tl_add_test(test_giant SOURCES test_giant.c LIBS tideline_core)
tl_add_test(test_uniform_list SOURCES test_uniform_list.c LIBS tideline_core ARGS ${PROJECT_SOURCE_DIR}/shaders)
tl_add_test(test_giant_render SOURCES test_giant_render.c LIBS tideline_gl)
tl_add_test(test_giant_light SOURCES test_giant_light.c LIBS tideline_gl)
tl_add_test(test_mesh SOURCES test_mesh.c LIBS tideline_core ARGS ${PROJECT_SOURCE_DIR}/tests/meshes)
tl_add_test(test_boat_render SOURCES test_boat_render.c LIBS tideline_gl
  ARGS ${PROJECT_SOURCE_DIR}/tests/meshes ${PROJECT_SOURCE_DIR}/timelines)
tl_add_test(test_wake SOURCES test_wake.c LIBS tideline_gl)
tl_add_test(test_underwater SOURCES test_underwater.c LIBS tideline_gl)
tl_add_test(test_polish SOURCES test_polish.c LIBS tideline_gl)
tl_add_test(test_glare SOURCES test_glare.c LIBS tideline_gl)
tl_add_test(test_sky SOURCES test_sky.c LIBS tideline_gl ARGS ${PROJECT_SOURCE_DIR}/tests/references)
# The live preview under Xvfb (its own X server): same pixels as still, hot
# reload, keys, dynamic resolution, no display.
add_test(NAME test_preview
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_preview.sh $<TARGET_FILE:tideline>
          ${PROJECT_SOURCE_DIR}/timelines)
# The bench in miniature: its table, CSV and plot (timings are not checked).
add_test(NAME test_bench
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_bench.sh $<TARGET_FILE:tideline>
          ${PROJECT_SOURCE_DIR}/timelines)
set_tests_properties(test_bench PROPERTIES PASS_REGULAR_EXPRESSION "BENCH_OK")
# still's and bench's progress on a (pseudo-)terminal.
add_test(NAME test_progress
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_progress.sh $<TARGET_FILE:tideline>
          ${PROJECT_SOURCE_DIR}/timelines)
set_tests_properties(test_progress PROPERTIES PASS_REGULAR_EXPRESSION "PROGRESS_OK")
# Extremes (issue 15): every row of docs/precision.md's table; it prints the
# table. The timeout is the "no hang" bound.
tl_add_test(test_extremes SOURCES test_extremes.c LIBS tideline_gl)
set_tests_properties(test_extremes PROPERTIES TIMEOUT 300)
tl_add_test(test_extremes_params SOURCES test_extremes_params.c LIBS tideline_gl)
set_tests_properties(test_extremes_params PROPERTIES TIMEOUT 300)
# Soak: renders killed (SIGKILL, SIGTERM) at random moments and resumed with
# --skip-existing end as an uninterrupted run does, with no temporary left.
add_test(NAME test_soak
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test_soak.sh $<TARGET_FILE:tideline>)
set_tests_properties(test_soak PROPERTIES PASS_REGULAR_EXPRESSION "SOAK_OK" TIMEOUT 300)
# The bad-input catalogue of docs/errors.md through `render`, over a good frame.
tl_add_test(test_errors SOURCES test_errors.c LIBS tideline_core
  ARGS $<TARGET_FILE:tideline> ${PROJECT_SOURCE_DIR}/shaders)
