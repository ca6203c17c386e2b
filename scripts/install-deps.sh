#!/usr/bin/env bash
# Installs the Debian 12 packages parksim needs, only those missing (apt-get update first when
# something is missing). Run as root.
#
#   scripts/install-deps.sh demo   what `scripts/demo.sh` builds and runs: the compiler, the
#                                  libraries the parksim program links, ffmpeg for the video
#   scripts/install-deps.sh build  what everything is compiled against: the demo's libraries
#                                  (not what only runs it: Mesa's drivers, ffmpeg, the font),
#                                  and the tests', benchmarks', Python module's and fuzzers'
#   scripts/install-deps.sh test   (the default) the above, and what only running the tests
#                                  needs (a browser, Slurm, pytest, pandas, Jupyter, a locale):
#                                  scripts/test.sh installs these behind its first build
# Each then fetches the pinned npm libraries the HTML reports draw with (parksim/pages/web:
# package.json and package-lock.json) with `npm ci` into parksim/pages/web/node_modules/ (not
# in the repository); the build embeds their files (docs/pages.md).
set -euo pipefail
cd "$(dirname "$0")/.."

set_name=${1:-test}

# The parksim program and the libraries it links (scripts/demo.sh): what it is compiled against,
demo_packages=(
  build-essential cmake pkg-config ninja-build
  # The build records the commit it was built from (cmake/GitCommit.cmake; `parksim --version`,
  # plan.json); without git it records "unknown", and Cli.EveryCommandPrintsTheVersionAndBuild
  # fails (seen in a fresh Debian 12 with the source copied in).
  git
  libbullet-dev libeigen3-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libnanoflann-dev libstb-dev zlib1g-dev libompl-dev
  # The PNG frames' Adler-32 (libdeflate's, 4x parksim's former SSE2 loop: docs/rendering.md).
  libdeflate-dev
  # SVG maps in world files (`map:`) are parsed by libxml2.
  libxml2-dev
  libegl-dev libfontconfig-dev
  # scripts/build.sh compiles with clang unless CXX names a compiler (half of GCC's time).
  clang
  # Links with lld where it is installed (cmake/TargetDefaults.cmake): about 2.5x faster.
  lld
)
# and what it needs to run: Mesa's drivers behind EGL (llvmpipe), a font, ffmpeg for the video.
demo_run_packages=(libgl1-mesa-dri fonts-dejavu-core ffmpeg)

# What the tests, the benchmarks, the Python module and the fuzzers compile against
# (scripts/test.sh).
build_packages=(
  # OSMesa: the tests compare its images with EGL's, byte for byte.
  libosmesa6-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  # bench/bench_render's BM_PngLibrary: the PNG libraries measured beside parksim's encoder.
  libspng-dev
  pybind11-dev python3 python3-dev
  # The sanitizers' runtimes, and clang's libFuzzer runtime (scripts/fuzz.sh), come with
  # libclang-rt-14-dev (Debian 12's clang).
  libclang-rt-14-dev
  # bench/bench_mujoco: MuJoCo side by side with parksim (optional at configure time).
  libmujoco-dev
  # scripts/build.sh compiles through it where it is installed: a second build of the same
  # sources on one machine (a test.sh run again, another clone) costs seconds (CI does without).
  ccache
)

# What only running the tests needs (scripts/test.sh installs these, with demo_run_packages,
# while its first build compiles: nothing is compiled against them, and configuring looks for
# none of them).
test_packages=(
  locales
  # The sweep's Slurm path, tested on a one-node cluster (scripts/slurm-local.sh); procps:
  # pkill, which stops a task mid-shard in tests/sweep/slurm_missing_test.sh.
  slurm-wlm munge procps
  python3-numpy python3-pytest python3-yaml python3-pandas
  # Gymnasium's dependencies: the Python tests run against Gymnasium 1.3.0's source in
  # ../shared/third_party (PARKSIM_THIRD_PARTY; tests/python/conftest.py), not packaged here.
  python3-cloudpickle python3-typing-extensions
  jupyter-nbconvert python3-nbformat python3-ipykernel
  # JUnit reports (`--junit`) read by a real consumer and checked with xmllint.
  python3-junitparser libxml2-utils
  # The HTML reports opened from file:// in a real browser (tests/pages/test_pages.py and
  # test_hostile_names.py, which also reads world files with python3-yaml).
  chromium chromium-driver python3-selenium
)

case "$set_name" in
  demo) packages=("${demo_packages[@]}" "${demo_run_packages[@]}") ;;
  build) packages=("${demo_packages[@]}" "${build_packages[@]}") ;;
  test) packages=("${demo_packages[@]}" "${demo_run_packages[@]}" "${build_packages[@]}"
                  "${test_packages[@]}") ;;
  *) echo "usage: scripts/install-deps.sh [demo|build|test]" >&2; exit 2 ;;
esac

# The locale tests run parksim inside a decimal-comma locale (tests/app/LocaleRoundTripTest.cpp).
ensure_test_locale() {
  [ "$set_name" = test ] || return 0
  if locale -a 2>/dev/null | grep -qix 'de_DE.utf8'; then return 0; fi
  if [ "$(id -u)" -ne 0 ]; then
    echo "install-deps: locale de_DE.UTF-8 missing (its tests will be skipped); as root: localedef -i de_DE -f UTF-8 de_DE.UTF-8" >&2
    return 0
  fi
  echo "install-deps: generating locale de_DE.UTF-8"
  localedef -i de_DE -f UTF-8 de_DE.UTF-8
}

# npm for the reports' libraries, from Debian where no Node.js with its own npm is installed.
command -v npm >/dev/null || packages+=(npm)

# The pinned npm libraries, fetched again only when package-lock.json changed since the last
# `npm ci` (its copy in node_modules/ is the stamp).
fetch_page_libraries() {
  local web=parksim/pages/web
  if cmp -s "$web/package-lock.json" "$web/node_modules/.parksim-lock.json" 2>/dev/null; then
    return 0
  fi
  echo "install-deps: npm ci in $web"
  (cd "$web" && npm ci --ignore-scripts --no-audit --no-fund --loglevel=error)
  cp "$web/package-lock.json" "$web/node_modules/.parksim-lock.json"
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages for '$set_name' present"
  ensure_test_locale
  fetch_page_libraries
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
fetch_page_libraries
