# Shared set-up for the README's two commands (.ci/start and .ci/test): Debian packages,
# configure, build. Sourced, not run. Prints how long each phase took.
set -euo pipefail

KINEMA_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
KINEMA_BUILD=${KINEMA_BUILD:-$KINEMA_ROOT/build}

# Everything Kinema builds and tests with, from Debian 12 packages.
KINEMA_PACKAGES=(build-essential cmake ninja-build pkg-config
  libglfw3-dev libglm-dev libimgui-dev libstb-dev python3-glad libtinygltf-dev nlohmann-json3-dev
  libcli11-dev libeigen3-dev libbullet-dev libegl-dev libosmesa6-dev libgtest-dev libbenchmark-dev
  xvfb xauth xdotool imagemagick clang libclang-rt-14-dev
  libegl-mesa0 libgl1-mesa-dri libglx-mesa0 ffmpeg fonts-dejavu-core)
# libbullet-dev: rigid bodies and constraints for ragdolls (library kinema_ragdoll only).
# The last three are Mesa's EGL, llvmpipe and GLX drivers: they come in today through
# libegl1 and libgl1, but rendering needs them, so they are named rather than assumed.
# fonts-dejavu-core: the editor's text font (DejaVu Sans; ImGui's built-in font without it).
# ffmpeg is optional for users (`kinema demo` says so when it is absent and writes no GIF or
# MP4); the suite installs it so the GIF and MP4 path is tested for real.
# The Khronos glTF validator (npm package, tests/tools/gltf_validator) runs on node. Only
# when npm is missing: NodeSource's nodejs bundles npm and conflicts with Debian's package.
if ! command -v npm >/dev/null 2>&1; then KINEMA_PACKAGES+=(nodejs npm); fi

kinema_phase_start() { KINEMA_PHASE=$1; KINEMA_PHASE_T0=$(date +%s); echo "== $1"; }
kinema_phase_end() {
  local dt=$(( $(date +%s) - KINEMA_PHASE_T0 ))
  echo "== $KINEMA_PHASE took ${dt} s"
  KINEMA_TIMES+=("$KINEMA_PHASE: ${dt} s")
}
KINEMA_TIMES=()
kinema_print_times() { printf '%s\n' "Phase times:" "${KINEMA_TIMES[@]/#/  }"; }

kinema_install_packages() {
  kinema_phase_start "packages"
  local missing=()
  for p in "${KINEMA_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    local line="apt-get install -y --no-install-recommends ${missing[*]}"
    if [ "$(id -u)" -ne 0 ]; then
      echo "Kinema needs Debian packages that are not installed. Run as root:" >&2
      echo "  apt-get update && $line" >&2
      exit 1
    fi
    echo "installing: ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  else
    echo "all ${#KINEMA_PACKAGES[@]} packages present"
  fi
  kinema_phase_end
}

# kinema_build [extra cmake args...]; KINEMA_BUILD_TARGETS (space-separated) builds only those.
kinema_build() {
  kinema_phase_start "configure + build ($(basename "$KINEMA_BUILD"))"
  cmake -S "$KINEMA_ROOT" -B "$KINEMA_BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release -DKINEMA_WERROR=ON "$@" >/dev/null
  local targets=()
  for t in ${KINEMA_BUILD_TARGETS:-}; do targets+=(--target "$t"); done
  cmake --build "$KINEMA_BUILD" -j2 "${targets[@]}"
  kinema_phase_end
}
