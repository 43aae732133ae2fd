#!/usr/bin/env bash
# Shared by scripts/demo.sh and scripts/test.sh (sourced, not run): installs the Debian packages
# the project needs when any is missing, configures and builds. Idempotent: a second run installs
# nothing and rebuilds only what changed.

SGP_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
SGP_BUILD=${SGP_BUILD:-$SGP_ROOT/build}
SGP_PYTHON=/usr/bin/python3 # Debian's, with numpy; `python3` on the PATH may be another one

# Compilers and CMake; ITK 5.2 (with its Eigen 3.3.9), VTK 9.1, TCLAP, GoogleTest, Google Benchmark,
# nlohmann JSON;
# Debian's Python modules for the test scripts; the GDCM tools ITK's CMake config refers to.
SGP_PACKAGES=(
  cmake g++ make
  libinsighttoolkit5-dev libvtk9-dev libtclap-dev libgtest-dev libbenchmark-dev nlohmann-json3-dev
  libdeflate-dev # the reader's fast path for gzip NRRD (Logic/IO/InflateGzipNrrd.h)
  python3 python3-numpy python3-scipy python3-skimage python3-jsonschema python3-vtk9 python3-pyflakes
  libgdcm-tools
  chromium # the visual report is checked in a real browser (Testing/CLI/test_report_html.py)
  snakemake slurm-wlm munge # the cohort workflow (workflows/cohort) and its local and Slurm tests (Testing/Workflow)
  ccache # compiles once per source and flags on this machine, across clones and build folders (sgp_build)
)

sgp_install() {
  local missing=() package
  for package in "${SGP_PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$package")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  echo "== Installing Debian packages: ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    sudo=sudo
  fi
  $sudo apt-get update
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends "${missing[@]}"
}

# sgp_build [cmake options…] [-- targets…]
sgp_build() {
  local options=() targets=()
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do options+=("$1"); shift; done
  if [ "${1:-}" = "--" ]; then shift; targets=("$@"); fi
  # Every compile goes through ccache when it is installed: a fresh clone (CI's) or a second build
  # folder (the sanitizer build, extension.SlicerConfigure's, which inherits these variables) then
  # recompiles only what changed since any earlier build on this machine. Paths are hashed relative
  # to the clone (CCACHE_BASEDIR, CCACHE_NOHASHDIR), so clones in other folders share the cache; an
  # object taken from the cache keeps the folder it was first compiled in in its debug information.
  # SGP_CCACHE=0 compiles without it.
  if [ "${SGP_CCACHE:-1}" != "0" ] && command -v ccache >/dev/null; then
    export CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache
    export CCACHE_BASEDIR="$SGP_ROOT" CCACHE_NOHASHDIR=true
  fi
  echo "== Configuring in $SGP_BUILD"
  mkdir -p "$SGP_BUILD"
  cmake -S "$SGP_ROOT" -B "$SGP_BUILD" -DCMAKE_BUILD_TYPE=Release "${options[@]}" >"$SGP_BUILD/configure.log" 2>&1 ||
    { cat "$SGP_BUILD/configure.log"; return 1; }
  echo "== Building (2 jobs: ITK templates are heavy on this machine's 2 cores)"
  local target_args=()
  for t in "${targets[@]}"; do target_args+=(--target "$t"); done
  cmake --build "$SGP_BUILD" -j 2 "${target_args[@]}"
}
