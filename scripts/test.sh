#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (GoogleTest unit tests, the SEM/Slicer
# protocol tests of the CLIs), then the unit and CLI tests once more in a sanitizer build
# (AddressSanitizer, UndefinedBehaviorSanitizer; SGP_SANITIZERS=0 skips it).
# Usage: scripts/test.sh [ctest arguments…] (default: -LE benchmark)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# Each stage's wall time, printed at the end (also when a stage fails): .ci/run shows them.
stage_names=()
stage_seconds=()
stage_start=$SECONDS
stage_done() {
  stage_names+=("$1")
  stage_seconds+=($((SECONDS - stage_start)))
  stage_start=$SECONDS
}
print_stage_times() {
  local status=$?
  echo "== Stage times (scripts/test.sh$( [ $status -ne 0 ] && echo ", stopped with exit code $status"))"
  local i
  for i in "${!stage_names[@]}"; do
    printf '   %-34s %4d min %02d s\n' "${stage_names[$i]}" $((stage_seconds[$i] / 60)) $((stage_seconds[$i] % 60))
  done
  printf '   %-34s %4d min %02d s\n' "total" $((SECONDS / 60)) $((SECONDS % 60))
}
trap print_stage_times EXIT

sgp_install all
stage_done "install"
# Warnings are errors in CI (STYLE.md B9); locally they are shown.
werror=OFF
if [ "${CI:-}" = "true" ]; then werror=ON; fi
# (Both asked for: a build folder the demo configured has them off.)
sgp_build -DSGP_WERROR=$werror -DBUILD_TESTING=ON -DSGP_BUILD_BENCHMARKS=ON
stage_done "build"

echo "== Running the tests"
cd "$SGP_BUILD"
# Benchmarks (CTest label `benchmark`) only when asked, e.g. scripts/test.sh -L benchmark:
# their timings depend on the machine's load. Issue 32's 60-draw sweep runs in the default pass
# (labels `sweep` and `sweep32`; scripts/test.sh -L sweep32 runs it alone).
if [ $# -eq 0 ]; then
  set -- -LE benchmark
fi
ctest --output-on-failure -j 2 "$@"
stage_done "tests"

# The same unit and CLI tests built with AddressSanitizer and UndefinedBehaviorSanitizer, in a
# second folder (-O1 -g1: optimised as AddressSanitizer's documentation advises, with line tables
# for the reports' file:line — half the compile time of RelWithDebInfo's -O2 -g); any report fails
# the run. Only on the default run (no ctest arguments given), or with SGP_SANITIZERS=1.
if [ "$#" -eq 2 ] && [ "$1" = "-LE" ] && [ "$2" = "benchmark" ] || [ "${SGP_SANITIZERS:-}" = "1" ]; then
  if [ "${SGP_SANITIZERS:-}" != "0" ]; then
    echo "== Sanitizer build (address, undefined) in $SGP_ROOT/build-sanitize"
    SGP_BUILD="$SGP_ROOT/build-sanitize" sgp_build -DSGP_WERROR=$werror -DBUILD_TESTING=ON \
      -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
      -DSGP_SANITIZE=address,undefined -DSGP_BUILD_BENCHMARKS=OFF
    stage_done "sanitizer build"
    echo "== Running the unit and CLI tests under the sanitizers"
    cd "$SGP_ROOT/build-sanitize"
    # no_huge_pages_for_shadow=0: the shadow memory may use huge pages. With 4 KB pages a pass
    # along k over a big box misses the TLB at every voxel on this virtual machine (a distance
    # transform's passes ran 100x slower than without the sanitizer; 5-15 % of a plan's time here).
    export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:detect_stack_use_after_return=1:allocator_may_return_null=1:no_huge_pages_for_shadow=0"
    export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
    export LSAN_OPTIONS="suppressions=$SGP_ROOT/Testing/Sanitizers/lsan.supp:print_suppressions=0"
    # Under the sanitizers the code runs 7-12 times slower. Tests that repeat a path already run
    # here on more phantoms (more plans, more parameter values, the CLI scripts that plan many
    # volumes) run in the Release pass only: Testing/Sanitizers/release-only.txt lists them, one
    # CTest regular expression per line, with the reasons and the member of each family kept here.
    # (Lines hold no groups: CTest's regular expressions allow only 9 in the joined expression.)
    repeated=$(grep -v -e '^[[:space:]]*#' -e '^[[:space:]]*$' "$SGP_ROOT/Testing/Sanitizers/release-only.txt" | paste -sd '|')
    all=$(ctest -N -L 'unit|cli' | grep -c 'Test *#')
    kept=$(ctest -N -L 'unit|cli' -E "$repeated" | grep -c 'Test *#')
    echo "== $kept of the $all unit and CLI tests (the others: Testing/Sanitizers/release-only.txt)"
    if [ "$kept" -ge "$all" ]; then
      echo "ERROR: Testing/Sanitizers/release-only.txt excluded none of $all tests; expected its list to match some" >&2
      exit 1
    fi
    ctest --output-on-failure -j 2 -L 'unit|cli' -E "$repeated"
    stage_done "sanitizer tests"
  fi
fi
