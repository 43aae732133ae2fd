#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (GoogleTest unit tests, the SEM/Slicer
# protocol tests of the CLIs). Usage: scripts/test.sh [ctest arguments…] (default: -LE benchmark)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

sgp_install
# Warnings are errors in CI (STYLE.md B9); locally they are shown.
werror=OFF
if [ "${CI:-}" = "true" ]; then werror=ON; fi
sgp_build -DSGP_WERROR=$werror -DBUILD_TESTING=ON

echo "== Running the tests"
cd "$SGP_BUILD"
# Benchmarks (CTest label `benchmark`) only when asked, e.g. scripts/test.sh -L benchmark:
# their timings depend on the machine's load.
if [ $# -eq 0 ]; then
  set -- -LE benchmark
fi
ctest --output-on-failure -j 2 "$@"
