#!/usr/bin/python3
"""A scan that ends just below the aortic bifurcation, through the CLI (issue 13, item 2).

Usage: test_partial_plan.py --phantom PHANTOM_EXE --cli SGS_EXE --workdir DIR

The default anatomy (1 x 1 x 1.5 mm) with the slices more than 20 mm below the truth's aortic
bifurcation taken away:
- the whole plan runs (exit 0): the aortic values are measured and within 1.5 mm of the truth (the
  lumen bar on slices over 1.25 mm), the values that need more of the iliacs are -1 in the return
  parameter file, stderr has the "WARNING: Partial plan" line naming the coverage, stdout says the
  plan is partial;
- the proximal part of the fit check is made with the whole scan's main body: the same
  mainBodyDiameter and covered ostia, proximalOversizing within 1 % and proximalSealLength within
  one ring spacing of the whole scan's; the limbs' sizes, seal lengths and oversizing are -1,
  fitCheckPassed and withinIfu are false, and a WARNING says so;
- asking for the simulated graft as well changes nothing (exit 0, the same main body) and writes
  the model (issue 33: a plan is a result, never an error for an output asked for).
Cut 5 mm below the bifurcation: one ERROR line naming the scan's extent, nothing written.
Prints one line per check and `N passed, M failed`; exits 1 on any failure.
"""

import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sem_rules  # noqa: E402
from test_bad_input import bad_case, check, crop_above, fresh_dir, results, run, run_cli  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "StentGraftPlanner"))
from StentGraftPlannerLib import Results  # noqa: E402

LUMEN_BAR_MM = 1.5  # issue 13's lumen tolerance on slices thicker than 1.25 mm


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--phantom", required=True, help="SyntheticAorticPhantom executable")
    parser.add_argument("--cli", required=True, help="StentGraftSimulation executable")
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    workdir = fresh_dir(os.path.abspath(args.workdir))

    volume = os.path.join(workdir, "phantom.nrrd")
    truth_path = os.path.join(workdir, "truth.json")
    params = os.path.join(workdir, "phantom.params")
    # A wall in fat (the devices are sized on the outer wall, which needs fat around it to be seen)
    # and 14 mm iliacs (outer; their 11 mm lumens take the catalogue's limbs), so that the whole
    # scan's plan simulates a graft to compare the partial plan's proximal fit check with.
    result = run([args.phantom, "--returnparameterfile", params, "--spacingMm", "1,1,1.5", "--wallThicknessMm", "1.5",
                  "--tissueHu", "-100", "--rightIliacDiameterMm", "14", "--leftIliacDiameterMm", "14",
                  "--outputTruth", truth_path, volume], workdir)
    if not check(result.returncode == 0, "the phantom is generated", result.stderr[:400]):
        return 1
    truth = json.load(open(truth_path))
    bifurcation_z = truth["landmarks"]["aorticBifurcation"][2]
    seed = sem_rules.read_return_parameters(params)["seedRas"]

    cut = crop_above(volume, os.path.join(workdir, "cut20.nrrd"), bifurcation_z - 20.0)
    outdir = fresh_dir(os.path.join(workdir, "case-cut20"))
    result = run_cli(args.cli, outdir, cut, ["--seed", seed])
    check(result.returncode == 0, "cut 20 mm below: the whole plan runs (exit 0)",
          f"exit {result.returncode}; stderr {result.stderr.strip()[:600]}")
    values = {}
    if os.path.isfile(os.path.join(outdir, "ret.params")):
        values = sem_rules.read_return_parameters(os.path.join(outdir, "ret.params"))
    sizing = truth["sizing"]
    for name, truth_name in (("proximalNeckLumenDiameter", "proximalNeckDiameter"),
                             ("neckLumenDiameter15mm", "neckDiameter15mm"),
                             ("maxAneurysmLumenDiameter", "maxAneurysmDiameter")):
        measured = float(values.get(name, "nan"))
        check(abs(measured - sizing[truth_name]) <= LUMEN_BAR_MM,
              f"cut 20 mm below: {name} {measured} within {LUMEN_BAR_MM} mm of the truth's "
              f"{sizing[truth_name]}")
    for name in ("rightIliacLumenDiameter", "leftIliacLumenDiameter", "rightIliacLength", "leftIliacLength",
                 "rightAccessMinDiameter", "leftAccessMinDiameter", "proximalSiteToBifurcationLength",
                 "rightLimbDiameter", "leftLimbDiameter", "rightIliacSealLength", "leftIliacSealLength",
                 "rightLimbOversizing", "leftLimbOversizing"):
        check(values.get(name) == "-1", f"cut 20 mm below: {name} is -1 (not measured)", values.get(name))
    warnings = [line for line in result.stderr.splitlines() if line.startswith("WARNING: ")]
    check(any(w.startswith("WARNING: Partial plan: the scan ends ") and "below the aortic bifurcation along the right"
              in w for w in warnings), "cut 20 mm below: a WARNING names the right iliac's coverage",
          str(warnings)[:600])

    # The proximal part of the fit check against the whole scan's.
    wholedir = fresh_dir(os.path.join(workdir, "case-whole"))
    whole_run = run_cli(args.cli, wholedir, volume, ["--seed", seed])
    whole = {}
    if check(whole_run.returncode == 0, "the whole scan's plan runs", whole_run.stderr.strip()[-400:]):
        whole = sem_rules.read_return_parameters(os.path.join(wholedir, "ret.params"))
    for name in ("mainBodyDiameter", "coveredOstia"):
        check(values.get(name) == whole.get(name) and values.get(name) not in (None, "-1"),
              f"cut 20 mm below: {name} {values.get(name)} is the whole scan's", whole.get(name))
    # (a) of the two plans within 0.1 mm of each other: 0.5 % of the oversizing; 1 % with margin.
    check(abs(float(values.get("proximalOversizing", "nan")) - float(whole.get("proximalOversizing", "nan"))) <= 1.0,
          f"cut 20 mm below: proximalOversizing {values.get('proximalOversizing')} within 1 % of the whole "
          f"scan's {whole.get('proximalOversizing')}")
    # The seal zone is quantized by the rings (4 mm apart by default).
    check(abs(float(values.get("proximalSealLength", "nan")) - float(whole.get("proximalSealLength", "nan"))) <= 4.0,
          f"cut 20 mm below: proximalSealLength {values.get('proximalSealLength')} within a ring spacing of the "
          f"whole scan's {whole.get('proximalSealLength')}")
    # The not-measured contract (issue 32): the limbs' oversizings are signed (a real -1 % exists), so
    # only the notMeasured list tells their -1 from a value. It names them and every other -1 above,
    # not the measured proximal oversizing; the whole scan's list is "none"; and the panel reads
    # through the return file: the listed values not measured, a signed value that is not listed a
    # number — the whole scan's conicity, whatever its sign.
    listed = set(values.get("notMeasured", "").split(","))
    unlisted = ("proximalOversizing", "proximalNeckLumenDiameter", "mainBodyDiameter", "neckConicity")
    check({"rightLimbOversizing", "leftLimbOversizing", "rightIliacLength", "proximalSiteToBifurcationLength"}
          <= listed and not listed & set(unlisted),
          "cut 20 mm below: notMeasured names the limbs' oversizings and the other -1s, not the measured values",
          values.get("notMeasured"))
    check(whole.get("notMeasured") == "none", "the whole scan's notMeasured is none", whole.get("notMeasured"))
    panel = Results.readReturnValues(lambda name: values.get(name, ""))
    panelWhole = Results.readReturnValues(lambda name: whole.get(name, ""))
    check(panel["rightIliacLength"] is None and panel["rightLimbLength"] is None
          and panel["proximalNeckLumenDiameter"] == float(values.get("proximalNeckLumenDiameter", "nan")),
          "cut 20 mm below: the panel reads the listed values as not measured and the others as numbers",
          f"{panel['rightIliacLength']} {panel['rightLimbLength']} {panel['proximalNeckLumenDiameter']}")
    check(panelWhole["neckConicity"] is not None
          and panelWhole["neckConicity"] == float(whole.get("neckConicity", "nan")),
          "the whole scan: the panel reads the signed neck conicity as the number written",
          f"{panelWhole['neckConicity']} vs {whole.get('neckConicity')}")
    check(values.get("fitCheckPassed") == "false" and values.get("withinIfu") == "false",
          "cut 20 mm below: fitCheckPassed and withinIfu false (the limbs are not known)",
          f"{values.get('fitCheckPassed')} / {values.get('withinIfu')}")
    check(any(w.startswith("WARNING: Partial plan: the proximal part of the fit check is made with the ")
              and "not checked" in w for w in warnings),
          "cut 20 mm below: a WARNING gives the proximal fit check and says what is not checked",
          str(warnings)[:900])
    check("Partial plan: the scan ends below the bifurcation after" in result.stdout,
          "cut 20 mm below: the summary on stdout says the plan is partial", result.stdout[-600:])

    # Asking for the simulated graft as well (issue 33 item 1: a plan is a result): the same run,
    # exit 0, the main body alone in the model (the proximal fit check is made with it).
    outdir = fresh_dir(os.path.join(workdir, "case-cut20-graft"))
    graft_path = os.path.join(outdir, "graft.vtk")
    result = run_cli(args.cli, outdir, cut, ["--seed", seed, "--outputSimulatedStentModel", graft_path])
    check(result.returncode == 0 and not any(line.startswith("ERROR: ") for line in result.stderr.splitlines()),
          "cut 20 mm below, simulated graft asked for: exit 0, no ERROR line",
          f"exit {result.returncode}; {result.stderr.strip()[-400:]}")
    check(os.path.isfile(graft_path) and os.path.getsize(graft_path) > 0,
          "cut 20 mm below, simulated graft asked for: the model is written", str(os.listdir(outdir)))
    graft_values = {}
    if os.path.isfile(os.path.join(outdir, "ret.params")):
        graft_values = sem_rules.read_return_parameters(os.path.join(outdir, "ret.params"))
    check(graft_values.get("mainBodyDiameter") == values.get("mainBodyDiameter"),
          "cut 20 mm below, simulated graft asked for: the same main body as without it",
          f"{graft_values.get('mainBodyDiameter')} vs {values.get('mainBodyDiameter')}")
    cut5 = crop_above(volume, os.path.join(workdir, "cut5.nrrd"), bifurcation_z - 5.0)
    bad_case(args.cli, workdir, "cut 5 mm below", cut5, ["--seed", seed], ["the scan spans z "])

    passed = sum(results)
    print(f"{passed} passed, {len(results) - passed} failed")
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
