#!/usr/bin/env bash
# Builds the libFuzzer targets with clang into build-fuzz/ and runs each for
# TIDELINE_FUZZ_SECONDS (default 60), side by side, from the committed
# corpus in fuzz/corpus/. New inputs go to build-fuzz/corpus/ (the
# committed corpus is only read); a crash, hang or leak stops a fuzzer with
# its input saved in build-fuzz/artifacts/ and the script fails. Without
# clang it says so and skips (exit 0). Usage: scripts/fuzz.sh [timeline|mesh]...
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${TIDELINE_FUZZ_SECONDS:-60}
targets=("$@")
((${#targets[@]})) || targets=(timeline mesh)

cc=$(command -v clang-14 || command -v clang || true)
if [ -z "$cc" ]; then
  echo "fuzz: clang not found, fuzzers skipped (scripts/setup.sh installs clang-14 and libclang-rt-14-dev)"
  exit 0
fi
source scripts/lib/build.sh
CC=$cc tl_build build-fuzz -DTIDELINE_FUZZ=ON -- "${targets[@]/#/fuzz_}"

export LSAN_OPTIONS=suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
mkdir -p build-fuzz/artifacts

# One fuzzer; libFuzzer's chatter goes to build-fuzz/NAME.log.
fuzz_one() {
  local t=$1 dict=() unwind=1
  mkdir -p "build-fuzz/corpus/$t"
  [ ! -f "fuzz/$t.dict" ] || dict=(-dict="fuzz/$t.dict")
  # Slow unwinding at malloc for the mesh fuzzer: assimp's frames then show,
  # so its own leaks can be suppressed (tests/sanitizers/lsan.supp).
  [ "$t" != mesh ] || unwind=0
  # -timeout: an input slower than 10 s is a hang; -max_len: well above the
  # largest seed.
  ASAN_OPTIONS=fast_unwind_on_malloc=$unwind "build-fuzz/fuzz/fuzz_$t" \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
    -print_final_stats=1 "${dict[@]}" -artifact_prefix="build-fuzz/artifacts/$t-" \
    "build-fuzz/corpus/$t" "fuzz/corpus/$t" >"build-fuzz/$t.log" 2>&1
}

# True when the fuzzer stopped on an allocation assimp itself made (the
# first frame past malloc and operator new is in libassimp): a malformed
# glTF can make assimp ask for gigabytes, which tideline cannot bound.
# Either one allocation over the limit, or the process over its memory
# limit with assimp's allocation the largest live one (the first stack of
# libFuzzer's heap report). Reported, with its input kept, but not a
# failure of tideline.
assimp_allocation() {
  grep -Eq 'libFuzzer: out-of-memory \((malloc\(|used: )' "$1" &&
    awk '/ in (malloc|calloc|realloc) / { seen = 1; next }
         seen && /^ *#[0-9]+ / && !/libstdc\+\+|operator new/ { exit !/libassimp/ }
         END { if (!seen) exit 1 }' "$1"
}

echo "fuzz: ${targets[*]} for ${seconds} s (TIDELINE_FUZZ_SECONDS)"
pids=()
for t in "${targets[@]}"; do
  fuzz_one "$t" &
  pids+=($!)
done
status=0
for i in "${!targets[@]}"; do
  t=${targets[$i]}
  if wait "${pids[$i]}"; then
    grep -E '^stat::(number_of_executed_units|new_units_added)' "build-fuzz/$t.log" |
      sed "s/^/fuzz: $t: /"
  elif [ "$t" = mesh ] && assimp_allocation "build-fuzz/$t.log"; then
    echo "fuzz: mesh: stopped where assimp itself asked for $(sed -nE 's/^ *([0-9]+) byte\(s\).*in 1 allocation.*/\1/p; s/.*out-of-memory \(malloc\(([0-9]+)\)\).*/\1/p' \
      "build-fuzz/$t.log" | head -1) bytes for a malformed model: assimp's own allocation, not tideline's" \
      "(a known limit, docs/errors.md); the input is in build-fuzz/artifacts/"
  else
    tail -n 60 "build-fuzz/$t.log"
    echo "fuzz: $t failed; its input is in build-fuzz/artifacts/ (once fixed, add it to fuzz/corpus/$t/)"
    status=1
  fi
done
exit $status
