#!/usr/bin/python3
"""A scan that ends just below the aortic bifurcation, through the CLI (issue 13, item 2).

Usage: test_partial_plan.py --phantom PHANTOM_EXE --cli SGS_EXE --workdir DIR

The default anatomy (1 x 1 x 1.5 mm) with the slices more than 20 mm below the truth's aortic
bifurcation taken away:
- the whole plan runs (exit 0): the aortic values are measured and within 1.5 mm of the truth (the
  lumen bar on slices over 1.25 mm), the values that need more of the iliacs are -1 in the return
  parameter file, stderr has the "WARNING: Partial plan" line naming the coverage and the one
  saying no graft is simulated, stdout says the plan is partial;
- asking for the simulated graft as well is one ERROR line and nothing written.
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
    result = run([args.phantom, "--returnparameterfile", params, "--spacingMm", "1,1,1.5",
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
                 "mainBodyDiameter"):
        check(values.get(name) == "-1", f"cut 20 mm below: {name} is -1 (not measured)", values.get(name))
    warnings = [line for line in result.stderr.splitlines() if line.startswith("WARNING: ")]
    check(any(w.startswith("WARNING: Partial plan: the scan ends ") and "below the aortic bifurcation along the right"
              in w for w in warnings), "cut 20 mm below: a WARNING names the right iliac's coverage",
          str(warnings)[:600])
    check(any("The plan is partial" in w and "no graft is simulated" in w for w in warnings),
          "cut 20 mm below: a WARNING says no graft is simulated", str(warnings)[:600])
    check("Partial plan: the scan ends below the bifurcation after" in result.stdout,
          "cut 20 mm below: the summary on stdout says the plan is partial", result.stdout[-600:])

    # Found after the measurements: the warnings of the stages before it stay on stderr, the
    # error is its one last line, and nothing is written.
    outdir = fresh_dir(os.path.join(workdir, "case-cut20-graft"))
    result = run_cli(args.cli, outdir, cut, ["--seed", seed, "--outputSimulatedStentModel",
                                             os.path.join(outdir, "graft.vtk")])
    lines = result.stderr.strip().splitlines()
    errors = [line for line in lines if line.startswith("ERROR: ")]
    check(result.returncode is not None and result.returncode > 0,
          "cut 20 mm below, simulated graft asked for: non-zero exit", f"exit {result.returncode}")
    check(len(errors) == 1 and lines[-1] == errors[0] and "The plan is partial" in errors[0]
          and "outputSimulatedStentModel" in errors[0] and all(
              line.startswith(("ERROR: ", "WARNING: ")) for line in lines),
          "cut 20 mm below, simulated graft asked for: one ERROR line, last, naming the partial plan",
          str(lines[-2:])[:600])
    check(not os.listdir(outdir), "cut 20 mm below, simulated graft asked for: nothing written",
          str(os.listdir(outdir)))
    cut5 = crop_above(volume, os.path.join(workdir, "cut5.nrrd"), bifurcation_z - 5.0)
    bad_case(args.cli, workdir, "cut 5 mm below", cut5, ["--seed", seed], ["the scan spans z "])

    passed = sum(results)
    print(f"{passed} passed, {len(results) - passed} failed")
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
