# TIDELINE_FUZZ=ON (clang only) instruments everything for libFuzzer's
# coverage, with AddressSanitizer and UBSan, and adds the fuzz targets of
# fuzz/ (fuzz_timeline, fuzz_mesh). scripts/fuzz.sh builds them into
# build-fuzz/ and runs each for a bounded time.
option(TIDELINE_FUZZ "Build the libFuzzer targets (needs clang)" OFF)
if(TIDELINE_FUZZ)
  if(NOT CMAKE_C_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "TIDELINE_FUZZ needs clang (CC=clang-14; Debian packages "
                        "'clang-14' and 'libclang-rt-14-dev')")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
                      -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
