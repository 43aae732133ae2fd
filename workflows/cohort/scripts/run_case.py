#!/usr/bin/python3
"""Plans one case of a cohort: runs StentGraftSimulation with every output into the case's folder.

Usage: run_case.py --cli EXE --image PATH --outdir DIR [--seed x,y,z] [--lowestRenalOstium x,y,z]
                   [--device NAME] [--threads N]

Writes into DIR:
- the CLI's outputs (OUTPUTS below) and its return-parameter file `ret.params`;
- `log.txt`: the command line and the CLI's stdout and stderr, interleaved as they came;
- `status.json`, last: {"case", "status": "ok" | "failed", "error", "exitCode", "graftModel",
  "note"}. `error` is the CLI's one `ERROR: ...` line for a failed case, "" for a planned one.

The simulated graft (`graft.vtp`) is asked for, because it is what a planner wants to look at. When
no graft can be simulated (no device within the catalogue's ranges, the proximal site not known)
the CLI still plans and writes it as an empty model: the case is `ok` with `graftModel: false` and
the reason (the report's device.notSimulated) in `note`. A failed case is not repeated.

Exit code: 0 whenever the case was run, planned or not (its result is in status.json), so that one
bad case does not stop the cohort; 1 only when the CLI itself cannot be started (a broken
installation, not a property of the case), with status.json left unwritten so that the case runs
again once that is fixed.
"""

import argparse
import json
import os
import subprocess
import sys

RETURN_FILE = "ret.params"
REPORT_FILE = "report.json"
# flag -> file name in the case folder; every output of StentGraftSimulation.
OUTPUTS = (
    ("--outputSimulatedStentModel", "graft.vtp"),
    ("--outputLabelMap", "lumen.nrrd"),
    ("--outputWallLabelMap", "wall-labels.nrrd"),
    ("--outputOuterWallModel", "outer-wall.vtp"),
    ("--outputCenterlines", "centerlines.vtp"),
    ("--outputLandmarks", "landmarks.mrk.json"),
    ("--outputStentModel", "stent.vtp"),
    ("--outputInitialStentModel", "stent-initial.vtp"),
    ("--outputMeasurements", "measurements.csv"),
    ("--outputDiameterProfile", "profile.csv"),
    ("--outputReport", REPORT_FILE),
    ("--outputReportHtml", "report.html"),
    ("--outputStraightenedVolume", "straight-right.nrrd"),
    ("--outputStraightenedLeftVolume", "straight-left.nrrd"),
)


def cli_argv(cli, image, outdir, seed=None, lowest_renal=None, device=None):
    """The argument vector: return file, optional flags, outputs, then the positional input."""
    argv = [cli, "--returnparameterfile", os.path.join(outdir, RETURN_FILE)]
    if seed:
        argv += ["--seed", seed]
    if lowest_renal:
        argv += ["--lowestRenalOstium", lowest_renal]
    if device:
        argv += ["--device", device]
    for flag, name in OUTPUTS:
        argv += [flag, os.path.join(outdir, name)]
    return argv + [image]


def error_lines(text):
    return [line.strip() for line in text.splitlines() if line.startswith("ERROR:")]


def run_once(argv, log, env):
    """Runs the CLI with stdout and stderr into the open log; returns (exit code, ERROR line)."""
    log.write("$ " + " ".join(argv) + "\n")
    log.flush()
    start = log.tell()
    code = subprocess.run(argv, stdout=log, stderr=subprocess.STDOUT, env=env).returncode
    log.flush()
    with open(log.name, encoding="utf-8", errors="replace") as handle:
        handle.seek(start)
        errors = error_lines(handle.read())
    log.write(f"== exit code {code}\n")
    if code == 0:
        return 0, ""
    if errors:
        return code, errors[-1]
    if code < 0:
        return code, f"ERROR: StentGraftSimulation was killed by signal {-code} (see log.txt)"
    return code, f"ERROR: StentGraftSimulation exited with code {code} without an ERROR line (see log.txt)"


def run_case(cli, image, outdir, seed=None, lowest_renal=None, device=None, threads=None):
    """Runs one case; writes log.txt and then status.json; returns the status dict."""
    os.makedirs(outdir, exist_ok=True)
    for name in [RETURN_FILE] + [name for _, name in OUTPUTS]:
        if os.path.exists(os.path.join(outdir, name)):
            os.remove(os.path.join(outdir, name))  # a previous run's, which this run may not replace
    env = dict(os.environ)
    if threads:
        env["ITK_GLOBAL_DEFAULT_NUMBER_OF_THREADS"] = str(threads)  # stay within the job's cores
    status = {"case": os.path.basename(os.path.normpath(outdir)), "status": "ok", "error": "",
              "exitCode": 0, "graftModel": True, "note": ""}
    with open(os.path.join(outdir, "log.txt"), "w", encoding="utf-8") as log:
        code, error = run_once(cli_argv(cli, image, outdir, seed, lowest_renal, device), log, env)
    if code != 0:
        status.update(status="failed", error=error, exitCode=code, graftModel=False)
    else:
        reason = not_simulated_reason(os.path.join(outdir, REPORT_FILE))
        if reason:
            status.update(graftModel=False, note=reason)
    write_json(os.path.join(outdir, "status.json"), status)
    return status


def not_simulated_reason(report_path):
    """Why the plan simulated no graft (the report's device.notSimulated), or "" when it did."""
    with open(report_path, encoding="utf-8") as handle:
        reason = (json.load(handle).get("device") or {}).get("notSimulated")
    return reason if isinstance(reason, str) else ""


def write_json(path, value):
    """Writes through a temporary file, so a reader (or a killed job) never sees half a file."""
    with open(path + ".part", "w", encoding="utf-8") as handle:
        json.dump(value, handle, indent=1)
        handle.write("\n")
    os.replace(path + ".part", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True, help="StentGraftSimulation executable")
    parser.add_argument("--image", required=True, help="the case's CT volume")
    parser.add_argument("--outdir", required=True, help="the case's folder")
    parser.add_argument("--seed", default="", help="x,y,z in mm (RAS); empty: automatic")
    parser.add_argument("--lowestRenalOstium", default="", help="x,y,z in mm (RAS); empty: found")
    parser.add_argument("--device", default="", help="device family; empty: the best one")
    parser.add_argument("--threads", type=int, default=0, help="ITK threads; 0: ITK's default")
    args = parser.parse_args()
    if not (os.path.isfile(args.cli) and os.access(args.cli, os.X_OK)):
        print(f"ERROR: the CLI {args.cli} is not an executable file", file=sys.stderr)
        return 1
    status = run_case(args.cli, args.image, args.outdir, args.seed, args.lowestRenalOstium,
                      args.device, args.threads)
    print(f"{status['case']}: {status['status']}" + (f" -- {status['error']}" if status["error"] else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
