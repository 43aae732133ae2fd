#!/usr/bin/python3
"""The cohort workflow submitted to Slurm (`--profile workflows/cohort/profiles/slurm`, issue 16).

Usage: test_cohort_slurm.py --phantom PHANTOM_EXE --cli SGS_EXE --workdir DIR

Starts a one-node Slurm cluster of its own in DIR/cluster (slurm_cluster.py: munged, slurmctld,
slurmd on their own socket, ports and files; no accounting), plans three phantoms through the
Slurm profile (a device-fitting anatomy with a seed, a vertebra without one, a non-contrast scan
that must fail) and checks
- snakemake exits 0, and cohort.csv is right (cohort_harness.check_cohort_csv: columns, statuses,
  the failure's ERROR line, each planned case's values equal to its ret.params);
- the job completion log (jobcomp/filetxt: sacct needs slurmdbd) has exactly one job per case,
  named after it, COMPLETED, with the profile's 2 CPUs and the rule's memory (2000 MB: the floor
  of mem_mb for these ~4 MB volumes), and no other job (the aggregate is a localrule);
- a second identical run submits nothing ("Nothing to be done", no new job in the log);
- afterwards no daemon it started is left running.
The cluster is always stopped (try/finally), also on a failed check, an exception, SIGTERM or the
overall time bound. When the daemons cannot start, that is a FAIL with their logs, never a skip.
Prints one line per check and `N passed, M failed`; exits 1 on any failure.
"""

import argparse
import collections
import os
import re
import signal
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cohort_harness import (DEVICE_FITS, FAST_GRID, PROFILES, SOURCE, check, check_cohort_csv, fresh_dir,  # noqa: E402
                            make_phantom, results, run_snakemake, snakemake_argv, write_manifest)
from slurm_cluster import SlurmCluster  # noqa: E402

TOTAL_TIMEOUT_S = 780  # under CTest's TIMEOUT 900, so that the finally block still stops the daemons
SNAKEMAKE_TIMEOUT_S = 300  # three small cases, each a ~10 s Slurm job; two runs fit in TOTAL_TIMEOUT_S
EXPECTED_MEM = "mem=2000M"  # case_mem_mb's floor: these volumes are ~4 MB, 8 x 4 + 1000 < 2000
EXPECTED_CPUS = "cpu=2"  # threads of plan_case, which the profile passes as --cpus-per-task


class OutOfTime(Exception):
    pass


def on_signal(number, _frame):
    raise OutOfTime(f"signal {number}")


def completed_jobs(path):
    """name -> list of (state, tres) from jobcomp/filetxt lines (`Key=Value ...`)."""
    jobs = collections.defaultdict(list)
    if os.path.isfile(path):
        for line in open(path):
            fields = dict(re.findall(r"(\w+)=(\S*)", line))
            jobs[fields.get("Name", "?")].append((fields.get("JobState"), fields.get("Tres", "")))
    return jobs


def run_workflow(args, workdir, cluster):
    images = fresh_dir(os.path.join(workdir, "images"))
    cases = [("s1-fits", FAST_GRID + DEVICE_FITS, True, "ok"),
             ("s2-bone-no-seed", FAST_GRID + ["--includeBone"], False, "ok"),
             ("s3-non-contrast", FAST_GRID + ["--lumenHu", "100"], True, "failed")]
    rows = []
    for name, options, seeded, _ in cases:
        seed = make_phantom(args.phantom, images, name, options)
        rows.append({"case": name, "image": os.path.join(images, name + ".nrrd"), "seedRas": seed if seeded else ""})
    manifest = write_manifest(os.path.join(workdir, "cases.csv"), rows, ["case", "image", "seedRas"])
    out = os.path.join(workdir, "out")
    # From the source folder with the profile's relative path, as README-section.md shows it.
    profile = os.path.relpath(os.path.join(PROFILES, "slurm"), SOURCE)
    argv = snakemake_argv(out, manifest, args.cli, ["--cores", "2", "--profile", profile])
    result = run_snakemake(argv, SOURCE, env=cluster.env(), timeout=SNAKEMAKE_TIMEOUT_S)
    if not check(result.returncode == 0, "snakemake --profile .../slurm finishes (exit 0)",
                 f"exit {result.returncode}; {result.stderr[-2500:]}\n{cluster.logs(1500)}"):
        return
    submitted = re.findall(r"Submitted job \d+ with external jobid '(\d+)'", result.stdout + result.stderr)
    check(len(submitted) == len(cases), "snakemake submitted one Slurm job per case", f"{submitted}")
    check_cohort_csv(out, args.cli, [(name, status) for name, _, _, status in cases])

    jobs = completed_jobs(cluster.jobcomp)
    expected = {f"sgp-plan_case-{name}" for name, _, _, _ in cases}
    check(set(jobs) == expected and all(len(jobs[name]) == 1 for name in expected),
          "the job completion log has exactly one job per case and no other",
          f"{ {name: len(entries) for name, entries in jobs.items()} }")
    check(all(state == "COMPLETED" for entries in jobs.values() for state, _ in entries),
          "every case's job COMPLETED (a failed case is a recorded result, not a failed job)", f"{dict(jobs)}")
    check(all(EXPECTED_CPUS in tres.split(",") and EXPECTED_MEM in tres.split(",")
              for entries in jobs.values() for _, tres in entries),
          f"each job had the rule's resources ({EXPECTED_CPUS}, {EXPECTED_MEM})", f"{dict(jobs)}")

    again = run_snakemake(argv, SOURCE, env=cluster.env(), timeout=SNAKEMAKE_TIMEOUT_S)
    check(again.returncode == 0 and "Nothing to be done" in again.stdout + again.stderr,
          "a second run submits nothing (\"Nothing to be done\")", (again.stdout + again.stderr)[-800:])
    check(sum(len(entries) for entries in completed_jobs(cluster.jobcomp).values()) == len(cases),
          "no new job in the completion log after the second run")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--phantom", required=True, help="SyntheticAorticPhantom executable")
    parser.add_argument("--cli", required=True, help="StentGraftSimulation executable")
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    args.phantom, args.cli = os.path.abspath(args.phantom), os.path.abspath(args.cli)
    workdir = fresh_dir(os.path.abspath(args.workdir))
    cluster = SlurmCluster(os.path.join(workdir, "cluster"))
    signal.signal(signal.SIGTERM, on_signal)
    signal.signal(signal.SIGALRM, on_signal)
    signal.alarm(TOTAL_TIMEOUT_S)
    try:
        try:
            cluster.start()
            started, why = True, ""
        except (RuntimeError, OSError) as error:  # OSError: a daemon's executable is missing
            started, why = False, f"{error}\n{cluster.logs()}"
        if check(started, "a one-node Slurm cluster starts (munged, slurmctld, slurmd; the node idle)", why):
            run_workflow(args, workdir, cluster)
    except OutOfTime as why:
        check(False, f"the test finishes within {TOTAL_TIMEOUT_S} s", f"stopped by {why}\n{cluster.logs(1500)}")
    finally:
        signal.alarm(0)
        left = cluster.stop()
        check(not left, "every daemon the test started has stopped", f"still alive: {left}")
    return summary()


def summary():
    passed = sum(results)
    print(f"{passed} passed, {len(results) - passed} failed")
    return 0 if results and all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
