# Timeline tests.
tl_add_test(test_curve SOURCES test_curve.c LIBS tideline_core)
tl_add_test(test_path SOURCES test_path.c LIBS tideline_core)
