#!/usr/bin/env bash
# Builds the whole project with AddressSanitizer and UndefinedBehaviorSanitizer
# into build-asan/ and runs the test suite there (every test: leak checks,
# and a failure on any report; see tests/CMakeLists.txt and
# tests/sanitizers/). Needs what scripts/setup.sh installs.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTIDELINE_SANITIZE=ON >/dev/null
# Progress lines hidden; a failed build still fails the script (pipefail).
cmake --build build-asan -j"$(nproc)" -- --no-print-directory | { grep -v '^\[' || true; }
ctest --test-dir build-asan --output-on-failure -j"$(nproc)"
