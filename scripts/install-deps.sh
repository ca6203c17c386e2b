#!/usr/bin/env bash
# Installs the Debian 12 packages parksim needs, only those missing. Run as root.
set -euo pipefail

packages=(
  build-essential cmake pkg-config ninja-build
  libbullet-dev libeigen3-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libnanoflann-dev libstb-dev zlib1g-dev
  libegl-dev libgl1-mesa-dri libosmesa6-dev libfontconfig-dev fonts-dejavu-core
  libgtest-dev libgmock-dev libbenchmark-dev libompl-dev ffmpeg locales
  slurm-wlm munge python3
  pybind11-dev python3-dev python3-numpy python3-pytest python3-yaml python3-pandas
  jupyter-nbconvert python3-nbformat python3-ipykernel
)

# Only the benchmarks need these; bench/ builds without them (bench/mujoco.cmake).
bench_packages=(
  libmujoco-dev
)
packages+=("${bench_packages[@]}")

# The locale tests run parksim inside a decimal-comma locale (tests/app/LocaleRoundTripTest.cpp).
ensure_test_locale() {
  if locale -a 2>/dev/null | grep -qix 'de_DE.utf8'; then return 0; fi
  if [ "$(id -u)" -ne 0 ]; then
    echo "install-deps: locale de_DE.UTF-8 missing (its tests will be skipped); as root: localedef -i de_DE -f UTF-8 de_DE.UTF-8" >&2
    return 0
  fi
  echo "install-deps: generating locale de_DE.UTF-8"
  localedef -i de_DE -f UTF-8 de_DE.UTF-8
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  ensure_test_locale
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages (${missing[*]}); run as root or install them with apt-get" >&2
  exit 1
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
ensure_test_locale
