# The fuzz corpora replayed through the fuzz entry points with this build's
# compiler (no libFuzzer needed): every input a fuzzer once broke on stays
# a regression test, under the sanitizers too in build-asan/.
tl_add_test(fuzz_replay_timeline
  SOURCES ${PROJECT_SOURCE_DIR}/fuzz/fuzz_replay.c ${PROJECT_SOURCE_DIR}/fuzz/fuzz_timeline.c
  LIBS tideline_core ARGS ${PROJECT_SOURCE_DIR}/fuzz/corpus/timeline LABELS unit)
tl_add_test(fuzz_replay_mesh
  SOURCES ${PROJECT_SOURCE_DIR}/fuzz/fuzz_replay.c ${PROJECT_SOURCE_DIR}/fuzz/fuzz_mesh.c
  LIBS tideline_core ARGS ${PROJECT_SOURCE_DIR}/fuzz/corpus/mesh LABELS unit)
