# TIDELINE_SANITIZE=ON builds everything (library, tools, tests) with
# AddressSanitizer and UndefinedBehaviorSanitizer. Any UB report aborts
# (no recovery), so a test that triggers one fails. scripts/test.sh builds
# this into build-asan/ and runs the suite there with the options and the
# LSan suppressions of tests/sanitizers/ (see tests/CMakeLists.txt).
option(TIDELINE_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
if(TIDELINE_SANITIZE)
  set(TL_SANITIZE_FLAGS -fsanitize=address,undefined -fno-omit-frame-pointer
                        -fno-sanitize-recover=undefined)
  add_compile_options(${TL_SANITIZE_FLAGS})
  add_link_options(${TL_SANITIZE_FLAGS})
endif()
