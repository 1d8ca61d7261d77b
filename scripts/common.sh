# Shared helpers for the project's scripts (sourced, not run).
# shellcheck shell=bash

ICEDEM_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ICEDEM_BUILD="${ICEDEM_BUILD:-$ICEDEM_ROOT/build}"

log() { printf '[%s] %s\n' "$(date -u +%H:%M:%S)" "$*" >&2; }

# Debian packages the build, the tests and the scripts need
ICEDEM_PACKAGES=(
  build-essential cmake pkg-config
  libbullet-dev libeigen3-dev libhdf5-dev libtomlplusplus-dev libcli11-dev
  nlohmann-json3-dev libfmt-dev googletest libgtest-dev libbenchmark-dev
  libfclib-dev libsiconos-numerics-dev libsuitesparse-dev libssl-dev libboost-dev libcgal-dev
  python3-numpy python3-h5py python3-matplotlib
  python3-scipy python3-statsmodels python3-skimage python3-pil parallel slurm-wlm munge procps
  openfoam python3-paraview
)

# install missing packages (as root, or through sudo), once
ensure_packages() {
  local missing=()
  for p in "${ICEDEM_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  log "installing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# configure (once) and build
build_project() {
  if [ ! -f "$ICEDEM_BUILD/CMakeCache.txt" ]; then
    log "configuring in $ICEDEM_BUILD"
    cmake -S "$ICEDEM_ROOT" -B "$ICEDEM_BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
  fi
  log "building"
  cmake --build "$ICEDEM_BUILD" -j "$(nproc)" -- --no-print-directory >/dev/null
}
