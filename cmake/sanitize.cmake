# TIDELINE_SANITIZE=ON builds everything (library, tools, tests) with
# AddressSanitizer and UndefinedBehaviorSanitizer, plus gcc's check of
# float-to-int conversions out of range (not in its `undefined` group; in
# clang's it is). Any report aborts (no recovery), so its test fails. scripts/test.sh builds
# this into build-asan/ and runs the suite there with the options and the
# LSan suppressions of tests/sanitizers/ (see tests/CMakeLists.txt).
option(TIDELINE_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
if(TIDELINE_SANITIZE)
  set(TL_SANITIZE_FLAGS -fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer
                        -fno-sanitize-recover=all)
  add_compile_options(${TL_SANITIZE_FLAGS})
  add_link_options(${TL_SANITIZE_FLAGS})
endif()
