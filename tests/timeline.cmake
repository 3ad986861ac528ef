# Timeline tests.
# The expected values tests/blender_curve_ref.py wrote (the file says how).
tl_add_test(test_curve SOURCES test_curve.c LIBS tideline_core
  ARGS ${CMAKE_CURRENT_SOURCE_DIR}/fixtures/curve_reference.txt LABELS unit)
tl_add_test(test_curve_ends SOURCES test_curve_ends.c LIBS tideline_core
  ARGS ${CMAKE_CURRENT_SOURCE_DIR}/fixtures/curve_reference.txt LABELS unit)
tl_add_test(test_path SOURCES test_path.c LIBS tideline_core LABELS unit)
tl_add_test(test_timeline SOURCES test_timeline.c LIBS tideline_core
  ARGS ${CMAKE_CURRENT_SOURCE_DIR}/fixtures/curve_reference.txt LABELS unit)
tl_add_test(test_shutter SOURCES test_shutter.c LIBS tideline_core LABELS unit)
# Golden `tideline check` messages for broken timelines (one per mistake).
tl_add_test(test_timeline_errors SOURCES test_timeline_errors.c LIBS tideline_core
  ARGS $<TARGET_FILE:tideline> ${PROJECT_SOURCE_DIR}/tests/timelines_bad LABELS unit)
tl_add_test(test_timeline_fuzz SOURCES test_timeline_fuzz.c LIBS tideline_core LABELS unit)
# The hero cutscene: floating, frames rendered alone, broken boat models.
tl_add_test(test_cutscene SOURCES test_cutscene.c LIBS tideline_core
  ARGS $<TARGET_FILE:tideline> ${PROJECT_SOURCE_DIR}/timelines ${PROJECT_SOURCE_DIR}/tests/meshes LABELS gl)
