#!/usr/bin/env bash
# Builds the whole project with AddressSanitizer and UndefinedBehaviorSanitizer
# into build-asan/ and runs the test suite there (every test: leak checks,
# and a failure on any report; see tests/CMakeLists.txt and
# tests/sanitizers/). Needs what scripts/setup.sh installs.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/build.sh
tl_build build-asan -DTIDELINE_SANITIZE=ON
ctest --test-dir build-asan --output-on-failure -j"$(nproc)"
