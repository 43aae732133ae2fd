#!/usr/bin/env bash
# Shared by scripts/demo.sh and scripts/test.sh (sourced, not run): installs the Debian packages
# the project needs when any is missing, configures and builds. Idempotent: a second run installs
# nothing and rebuilds only what changed.

SGP_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
SGP_BUILD=${SGP_BUILD:-$SGP_ROOT/build}
SGP_PYTHON=/usr/bin/python3 # Debian's, with numpy; `python3` on the PATH may be another one

# What the demo needs (scripts/demo.sh): compilers and CMake; ITK 5.2 (with its Eigen 3.3.9), VTK 9.1,
# TCLAP, nlohmann JSON; the GDCM tools ITK's CMake config refers to; Python for its summary.
SGP_DEMO_PACKAGES=(
  cmake g++ make
  libinsighttoolkit5-dev libvtk9-dev libtclap-dev nlohmann-json3-dev
  libdeflate-dev # the reader's fast path for gzip NRRD (Logic/IO/InflateGzipNrrd.h)
  libgdcm-tools
  python3 # the demo's summary
)
# What the tests add (scripts/test.sh): GoogleTest, Google Benchmark, Debian's Python modules for
# the test scripts, a real browser, the cohort workflow's tools.
SGP_TEST_PACKAGES=(
  libgtest-dev libbenchmark-dev
  python3-numpy python3-scipy python3-skimage python3-jsonschema python3-vtk9 python3-pyflakes
  chromium # the visual report is checked in a real browser (Testing/CLI/test_report_html.py)
  snakemake slurm-wlm munge # the cohort workflow (workflows/cohort) and its local and Slurm tests (Testing/Workflow)
  ccache # compiles once per source and flags on this machine, across clones and build folders (sgp_build)
)

# sgp_install demo|all: the demo's packages, or the demo's and the tests'.
sgp_install() {
  local wanted=("${SGP_DEMO_PACKAGES[@]}")
  if [ "${1:-all}" = "all" ]; then
    wanted+=("${SGP_TEST_PACKAGES[@]}")
  fi
  local missing=() package
  for package in "${wanted[@]}"; do
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
  # --force-unsafe-io: dpkg skips its fsync after every file it unpacks (the demo's 546 packages
  # hold 2.1 GB in small files), as the official Debian and Ubuntu Docker images have dpkg do; a
  # power cut during this install can leave the files just unpacked damaged (reinstall those
  # packages), nothing already installed.
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends \
    -o Dpkg::Options::=--force-unsafe-io "${missing[@]}"
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
  # SGP_CCACHE=0 compiles without it (the demo's first build: on an empty cache ccache only adds
  # its own preprocessing to every compile). The launcher is given on the command line as well as
  # in the environment, so that a build folder configured without it takes it later.
  local launcher=""
  if [ "${SGP_CCACHE:-1}" != "0" ] && command -v ccache >/dev/null; then
    launcher=ccache
    export CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache
    export CCACHE_BASEDIR="$SGP_ROOT" CCACHE_NOHASHDIR=true
  fi
  options=("-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher" "-DCMAKE_C_COMPILER_LAUNCHER=$launcher" "${options[@]}")
  echo "== Configuring in $SGP_BUILD"
  mkdir -p "$SGP_BUILD"
  cmake -S "$SGP_ROOT" -B "$SGP_BUILD" -DCMAKE_BUILD_TYPE=Release "${options[@]}" >"$SGP_BUILD/configure.log" 2>&1 ||
    { cat "$SGP_BUILD/configure.log"; return 1; }
  echo "== Building (2 jobs: ITK templates are heavy on this machine's 2 cores)"
  local target_args=()
  for t in "${targets[@]}"; do target_args+=(--target "$t"); done
  cmake --build "$SGP_BUILD" -j 2 "${target_args[@]}"
}
