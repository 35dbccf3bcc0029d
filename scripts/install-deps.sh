#!/usr/bin/env bash
# Installs the Debian packages AMP builds with, only those not yet installed.
# --test adds the packages only the test suite needs (OMPL, the oracle of tests/oracle; pytest;
# Chromium, which opens the 3-D viewer's pages headless);
# --sanitize those of the sanitizer and fuzzing build (clang 14 and its libFuzzer runtime).
set -euo pipefail
with_test=0
with_sanitize=0
for arg in "$@"; do
  case "$arg" in
    --test) with_test=1 ;;
    --sanitize) with_sanitize=1 ;;
    *) echo "usage: $0 [--test] [--sanitize]" >&2; exit 2 ;;
  esac
done
packages=(
  build-essential cmake pkg-config lld ninja-build ccache
  libeigen3-dev libfcl-dev libccd-dev libassimp-dev libcgal-dev libgmp-dev libmpfr-dev
  libboost-dev libboost-math-dev libyaml-cpp-dev nlohmann-json3-dev libcli11-dev libsqlite3-dev libpng-dev
  pybind11-dev python3-dev python3-numpy
  libgtest-dev libgmock-dev libbenchmark-dev
  libopenmpi-dev openmpi-bin
  liburdfdom-dev liborocos-kdl-dev libtinyxml2-dev
  libjs-three
)
if [ "$with_test" -eq 1 ]; then
  packages+=(libompl-dev python3-pytest chromium)
fi
if [ "$with_sanitize" -eq 1 ]; then
  packages+=(clang-14 libclang-rt-14-dev llvm-14)
fi
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "Installing: ${missing[*]}"
sudo_cmd=""
if [ "$(id -u)" -ne 0 ]; then sudo_cmd="sudo"; fi
$sudo_cmd apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
