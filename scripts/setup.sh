#!/usr/bin/env bash
# Sets tideline up on Debian 12: installs the Debian packages that are
# missing (saying which; apt's own output hidden), then configures and
# builds into build/, saying what it does at each step (a first build
# takes minutes on two cores: silent, it looked hung). Safe to run any
# number of times.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake pkg-config # toolchain
  libegl-dev libegl-mesa0          # EGL (headless GL) and Mesa's EGL driver
  libgl1-mesa-dri                  # llvmpipe, the software GL used without a GPU
  libepoxy-dev                     # GL/EGL function dispatch
  libcglm-dev                      # vector math
  libopenexr-dev                   # OpenEXR 3 C API (OpenEXRCore)
  libpng-dev                       # PNG output
  libglfw3-dev                     # windows (the live preview)
  libassimp-dev                    # boat meshes: glTF and OBJ (assimp's C API)
  libstb-dev                       # boat textures: PNG and JPEG decoding (stb_image)
  libsndfile1-dev                  # the soundtrack: WAV, FLAC and Ogg decoding
  libsdl2-dev                      # the preview plays the soundtrack (SDL2 audio)
  ffmpeg                           # movies (tideline render --movie); ffprobe for tests
  xvfb xauth                       # a virtual display for the preview's tests
  gnuplot-nox                      # tideline bench --plot
  clang-14 libclang-rt-14-dev      # libFuzzer and the sanitizers' runtimes (scripts/fuzz.sh)
  valgrind                         # memcheck over a still and a render (scripts/valgrind.sh)
  libtinygltf-dev                  # glTF writing (tideline export-camera)
  libopencolorio-dev               # colour management: working spaces, studio display transforms
  blender python3-numpy            # a real client in the tests: Blender 3.4 reads the EXR passes
  openimageio-tools                # (Cryptomatte, Vector Blur) and the glTF; oiiotool lists the
                                   # layers (tests/test_blender.sh); numpy: its glTF importer
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  echo "setup: installing ${missing[*]}"
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y -qq -o DPkg::Lock::Timeout=300 --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "setup: the ${#packages[@]} Debian packages tideline uses are installed"
fi

source scripts/lib/build.sh
echo "setup: building tideline in build/ (minutes the first time on two cores; the log: build/build.log)"
tl_build build
test -x build/tideline
echo "setup: built build/tideline"
