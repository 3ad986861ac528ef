#!/usr/bin/env bash
# Set up, build, and run the whole test suite through ctest; then the same
# suite built with the sanitizers (scripts/sanitize.sh), the fuzzers for a
# bounded time (scripts/fuzz.sh, TIDELINE_FUZZ_SECONDS each, side by side)
# and memcheck over a still and a short render (scripts/valgrind.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
# Every warning is an error here (and so in CI); scripts/setup.sh alone
# leaves the build folder's setting as it was.
export TIDELINE_WERROR=ON
scripts/setup.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
echo "test: the suite again under AddressSanitizer + UBSan (build-asan/)"
scripts/sanitize.sh
scripts/fuzz.sh
scripts/valgrind.sh
