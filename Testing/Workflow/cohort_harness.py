"""What the cohort workflow tests share: phantoms, the manifest, the snakemake run, cohort.csv.

- `make_phantom` runs SyntheticAorticPhantom and returns its volume and seedRas;
- `write_manifest` writes a manifest with relative image paths (the workflow resolves them
  relative to the manifest's folder);
- `snakemake_argv` is the documented command line (README-section.md), with absolute paths;
- `check_cohort_csv` checks cohort.csv against each case's own files: the columns, one row per
  case in manifest order, the expected status of each, the ERROR line of a failed case, the
  values of a planned one.
`check`, `run` and `fresh_dir` come from Testing/CLI/test_bad_input.py, `read_return_parameters`
from Testing/CLI/sem_rules.py, so these tests report and run programs the way the CLI tests do.
"""

import csv
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
SNAKEFILE = os.path.join(SOURCE, "workflows", "cohort", "Snakefile")
PROFILES = os.path.join(SOURCE, "workflows", "cohort", "profiles")
sys.path.insert(0, os.path.join(SOURCE, "Testing", "CLI"))
import sem_rules  # noqa: E402
from test_bad_input import check, fresh_dir, results, run  # noqa: E402,F401

__all__ = ["DEVICE_FITS", "FAST_GRID", "PLANNED_FILES", "PROFILES", "SOURCE", "check", "check_cohort_csv",
           "fresh_dir", "make_phantom", "results", "run", "run_snakemake", "snakemake_argv", "write_manifest"]
SNAKEMAKE = "/usr/bin/snakemake"  # Debian's, which runs on /usr/bin/python3
SNAKEMAKE_TIMEOUT_S = 600  # six small phantoms, ~1-20 s of CLI each on 2 cores; under CTest's 900 s
# Every file a planned case writes into its folder (workflows/cohort/scripts/run_case.py).
PLANNED_FILES = ["status.json", "log.txt", "ret.params", "lumen.nrrd", "wall-labels.nrrd", "outer-wall.vtp",
                 "centerlines.vtp", "landmarks.mrk.json", "stent.vtp", "stent-initial.vtp", "measurements.csv",
                 "profile.csv", "report.json", "report.html", "straight-right.nrrd", "straight-left.nrrd"]
# A wall in fat and 14 mm iliacs (outer; 11 mm lumens take the catalogue's limbs): a device fits.
DEVICE_FITS = ["--wallThicknessMm", "1.5", "--tissueHu", "-100", "--rightIliacDiameterMm", "14",
               "--leftIliacDiameterMm", "14"]
FAST_GRID = ["--spacingMm", "1,1,1.5"]  # coarse enough to keep each case to seconds


def make_phantom(exe, folder, name, options):
    """Writes folder/name.nrrd; returns its seedRas text ("x,y,z") or None when it failed."""
    volume, params = os.path.join(folder, name + ".nrrd"), os.path.join(folder, name + ".params")
    result = run([exe, "--returnparameterfile", params, *options, volume], folder)
    ok = check(result.returncode == 0 and os.path.isfile(volume), f"phantom {name} is generated",
               f"exit {result.returncode}; {result.stderr.strip()[:400]}")
    return sem_rules.read_return_parameters(params).get("seedRas") if ok else None


def write_manifest(path, rows, columns):
    """rows: dicts over columns; the image column is written relative to the manifest's folder."""
    folder = os.path.dirname(path)
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.DictWriter(handle, fieldnames=columns, lineterminator="\n")
        writer.writeheader()
        for row in rows:
            row = dict(row, image=os.path.relpath(row["image"], folder))
            writer.writerow({c: row.get(c) or "" for c in columns})
    return path


def snakemake_argv(out, manifest, cli, extra=()):
    return [SNAKEMAKE, "--snakefile", SNAKEFILE, "--directory", out, "--config",
            f"manifest={manifest}", f"cli={os.path.abspath(cli)}", *extra]


def run_snakemake(argv, cwd, env=None, timeout=SNAKEMAKE_TIMEOUT_S):
    print("RUN: " + " ".join(argv))
    try:
        result = subprocess.run(argv, capture_output=True, text=True, cwd=cwd, timeout=timeout,
                                env=env or dict(os.environ))
    except subprocess.TimeoutExpired as expired:
        out = expired.stdout.decode() if isinstance(expired.stdout, bytes) else (expired.stdout or "")
        err = expired.stderr.decode() if isinstance(expired.stderr, bytes) else (expired.stderr or "")
        result = subprocess.CompletedProcess(argv, None, out, err + f"\n(timed out after {timeout} s)")
    return result


def xml_return_names(cli):
    """The CLI's return values in XML order, read here independently of aggregate.py."""
    xml = subprocess.run([cli, "--xml"], capture_output=True, text=True, timeout=120).stdout
    names = []
    for group in ElementTree.fromstring(xml).iter("parameters"):
        for parameter in group:
            if (parameter.findtext("channel") == "output" and parameter.find("flag") is None
                    and parameter.find("longflag") is None):
                names.append(parameter.findtext("name"))
    return names


def read_csv(path):
    with open(path, newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    return (rows[0], [dict(zip(rows[0], row)) for row in rows[1:]]) if rows else ([], [])


def last_error_line(path):
    lines = [line.strip() for line in open(path, encoding="utf-8", errors="replace") if line.startswith("ERROR:")]
    return lines, (lines[-1] if lines else None)


def check_cohort_csv(out, cli, expected):
    """expected: [(case, "ok" | "failed")] in manifest order. Returns the rows by case."""
    names = xml_return_names(cli)
    check(len(names) >= 50, "the CLI's XML declares its return values (at least the 50 of issue 16)", f"{len(names)}")
    header, rows = read_csv(os.path.join(out, "cohort.csv"))
    check(header == ["case", "status", "error"] + names,
          "cohort.csv columns: case,status,error, then every return value in the XML's order",
          f"header {header[:6]}... ({len(header)} columns, expected {len(names) + 3})")
    check([row["case"] for row in rows] == [case for case, _ in expected],
          "cohort.csv: one row per case, in manifest order", f"{[row['case'] for row in rows]}")
    by_case = {row["case"]: row for row in rows}
    for case, status in expected:
        row, folder = by_case.get(case, {}), os.path.join(out, "cases", case)
        check(row.get("status") == status, f"{case}: status {status}",
              f"status {row.get('status')!r}, error {row.get('error', '')!r}")
        if status == "failed":
            check_failed_case(case, row, folder, names)
        elif row.get("status") == "ok":
            check_planned_case(case, row, folder, names)
    return by_case


def check_failed_case(case, row, folder, names):
    lines, error = last_error_line(os.path.join(folder, "log.txt"))
    check(len(lines) == 1 and row.get("error") == error and error.startswith("ERROR: "),
          f"{case}: the row's error is the one ERROR line of the case's log.txt",
          f"row {row.get('error')!r}; log ERROR lines {lines}")
    status = json.load(open(os.path.join(folder, "status.json")))
    check(status.get("status") == "failed" and status.get("error") == error,
          f"{case}: status.json says failed with the same ERROR line", f"{status}")
    check(all(row.get(name) == "" for name in names), f"{case}: every value cell of the failed row is empty")
    written = sorted(set(os.listdir(folder)) - {"log.txt", "status.json"})
    check(not written, f"{case}: a failed case leaves only log.txt and status.json", f"also {written}")


def check_planned_case(case, row, folder, names):
    missing = [name for name in PLANNED_FILES if not os.path.isfile(os.path.join(folder, name))]
    check(not missing, f"{case}: every output of the CLI is in cases/{case}/", f"missing {missing}")
    try:
        own = sem_rules.read_return_parameters(os.path.join(folder, "ret.params"))
    except OSError as error:
        check(False, f"{case}: its return-parameter file is readable", str(error))
        return
    absent = [name for name in names if name not in own]
    check(not absent, f"{case}: its return-parameter file has every XML return value", f"absent {absent}")
    differ = [(name, row.get(name), own.get(name)) for name in names if row.get(name) != own.get(name, "")]
    check(not differ and row.get("error") == "", f"{case}: every value equals its own ret.params exactly",
          f"differ (name, csv, file): {differ[:5]}")
