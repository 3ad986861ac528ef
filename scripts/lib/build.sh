# Sourced by the scripts: configure and build one build folder.
#
#   tl_build DIR [CMAKE_CONFIGURE_ARGS...] [-- TARGETS...]
#
# Configures DIR from the source tree and builds it, hiding make's progress
# lines but not the compiler's messages. The build's exit status is the
# function's: a compile error fails the calling script (which runs under
# `set -euo pipefail`). TIDELINE_WERROR=ON (scripts/test.sh, and so CI)
# makes every warning an error; unset, the folder keeps what it had.
tl_build() {
  local dir=$1
  shift
  local configure=() targets=()
  while (($#)); do
    if [ "$1" = -- ]; then
      shift
      targets=("$@")
      break
    fi
    configure+=("$1")
    shift
  done
  [ -z "${TIDELINE_WERROR:-}" ] || configure+=("-DTIDELINE_WERROR=$TIDELINE_WERROR")
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${configure[@]}" >/dev/null
  local target_args=()
  ((${#targets[@]} == 0)) || target_args=(--target "${targets[@]}")
  local status=0
  cmake --build "$dir" -j"$(nproc)" "${target_args[@]}" -- --no-print-directory >"$dir/build.log" 2>&1 ||
    status=$?
  grep -v '^\[' "$dir/build.log" || true
  if ((status != 0)); then
    echo "build: $dir failed (exit $status); the whole log is $dir/build.log" >&2
    return "$status"
  fi
}
