#!/usr/bin/python3
"""The surgeon's own lumen and landmarks at the command line (issue 45), run as Slicer runs it.

Usage: test_given_inputs.py --phantom PHANTOM_EXE --cli SGS_EXE --workdir DIR

On a small phantom (1.5 x 1.5 x 2 mm, as test_bad_input.py's):
- the round trip: plan -> --outputLabelMap -> plan with --inputLumenSegmentation: every returned
  number within 0.1 (mm, degrees, %, mL), the same order list, lumenSource = given;
- the segmentation alone (its path as the input volume too): the plan runs without a CT, says
  so, sizes on the lumen (outer-wall diameters -1) and reads the same lumen diameters;
- a given landmark is reported as given: the return file's ...Source, the report's "source",
  the landmarks file's description;
- a segmentation of several pieces plans with one WARNING naming the pieces left out;
- each bad input of the issue gives one ERROR line naming the value and leaves no output file: a
  segmentation that does not overlap the CT (both extents named), labels with no voxel (the
  labels present listed), several labels and no --lumenLabels, labels that form no aorto-iliac Y,
  a missing segmentation file, an internal iliac origin 15 mm from its centerline, a bifurcation
  25 mm from the aorta's lower end, a right internal iliac origin on the patient's left, a
  landmark that is not three numbers.
Prints one line per check and `N passed, M failed`; exits 1 on any failure.
"""

import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sem_rules  # noqa: E402
from test_bad_input import (bad_case, check, fresh_dir, make_small_phantom, results, run,  # noqa: E402
                            seed_text)

#: Returned numbers that are not plan values (what was used, run times), and texts compared apart.
NOT_PLAN_VALUES = {"seedUsed", "lowerHuUsed", "upperHuUsed", "edgeHuUsed", "notMeasured", "seedSource",
                   "lumenSource"}


def write_label_nrrd(path, labels, header):
    """`labels` ([k, j, i] array) as a raw unsigned-char NRRD on the grid of `header` (read_nrrd's)."""
    directions = header["directions"]
    lines = ["NRRD0004", "type: unsigned char", "dimension: 3", "space: left-posterior-superior",
             "sizes: %d %d %d" % tuple(header["sizes"]),
             "space directions: " + " ".join("(%r,%r,%r)" % tuple(float(v) for v in row) for row in directions),
             "kinds: domain domain domain", "encoding: raw",
             "space origin: (%r,%r,%r)" % tuple(float(v) for v in header["origin"])]
    with open(path, "wb") as handle:
        handle.write(("\n".join(lines) + "\n\n").encode() + np.ascontiguousarray(labels, dtype=np.uint8).tobytes())
    return path


def lps_z(header, k):
    return float(header["origin"][2]) + k * float(np.asarray(header["directions"], dtype=float)[2][2])


def plan(cli, outdir, volume, extra):
    paths = {name: os.path.join(outdir, name) for name in
             ("lumen.nrrd", "ret.params", "report.json", "landmarks.mrk.json")}
    argv = [cli, "--returnparameterfile", paths["ret.params"], *extra, "--outputLabelMap", paths["lumen.nrrd"],
            "--outputReport", paths["report.json"], "--outputLandmarks", paths["landmarks.mrk.json"], volume]
    print(f"RUN: {' '.join(argv)}")
    result = run(argv, outdir)
    values = sem_rules.read_return_parameters(paths["ret.params"]) if os.path.isfile(paths["ret.params"]) else {}
    return result, values, paths


def numbers(values):
    out = {}
    for name, text in values.items():
        if name in NOT_PLAN_VALUES:
            continue
        try:
            out[name] = float(text)
        except ValueError:
            pass
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--phantom", required=True, help="SyntheticAorticPhantom executable")
    parser.add_argument("--cli", required=True, help="StentGraftSimulation executable")
    parser.add_argument("--workdir", required=True, help="scratch directory")
    args = parser.parse_args()
    workdir = os.path.abspath(args.workdir)
    os.makedirs(workdir, exist_ok=True)
    cli = os.path.abspath(args.cli)
    volume, seed, _ = make_small_phantom(os.path.abspath(args.phantom), workdir)
    truth = json.load(open(os.path.join(workdir, "small-truth.json")))
    seed_args = ["--seed", seed_text(seed)]

    # The plan from the CT (the reference) and its lumen label map.
    first = fresh_dir(os.path.join(workdir, "grown"))
    result, grown, grown_paths = plan(cli, first, volume, seed_args)
    check(result.returncode == 0, "the plan from the CT exits 0", result.stderr[-500:])
    check(grown.get("lumenSource") == "grown", "the plan from the CT says lumenSource = grown",
          str(grown.get("lumenSource")))
    lumen_path = grown_paths["lumen.nrrd"]

    # The round trip.
    second = fresh_dir(os.path.join(workdir, "round-trip"))
    result, given, given_paths = plan(cli, second, volume, ["--inputLumenSegmentation", lumen_path])
    check(result.returncode == 0, "the plan from its own label map exits 0", result.stderr[-500:])
    check(given.get("lumenSource") == "given", "round trip: lumenSource = given", str(given.get("lumenSource")))
    a, b = numbers(grown), numbers(given)
    differ = {n: (a[n], b.get(n)) for n in a if b.get(n) is None or abs(a[n] - b[n]) > 0.1}
    check(len(a) > 40 and not differ, "round trip: every returned number within 0.1 of the plan from the CT",
          str(differ))
    check(grown.get("orderList") and given.get("orderList") == grown.get("orderList"),
          "round trip: the same order list", f"{grown.get('orderList')!r} / {given.get('orderList')!r}")
    check(given.get("fitCheckPassed") == grown.get("fitCheckPassed"), "round trip: the same fit-check verdict")

    # The segmentation alone: no CT.
    third = fresh_dir(os.path.join(workdir, "segmentation-alone"))
    result, alone, _ = plan(cli, third, lumen_path, ["--inputLumenSegmentation", lumen_path])
    check(result.returncode == 0, "the segmentation alone plans (exit 0)", result.stderr[-500:])
    check("No CT was given" in result.stderr, "the segmentation alone: a warning says no CT was given",
          result.stderr[:800])
    check("no CT, so no outer wall" in result.stdout, "the segmentation alone: the summary says so")
    check(alone.get("proximalNeckDiameter") == "-1", "the segmentation alone: the outer (a) is not measured",
          str(alone.get("proximalNeckDiameter")))
    for name in ("proximalNeckLumenDiameter", "maxAneurysmLumenDiameter", "rightIliacLumenDiameter",
                 "leftIliacLumenDiameter"):
        check(abs(float(alone.get(name, "nan")) - float(grown[name])) <= 0.1,
              f"the segmentation alone: {name} as from the CT", f"{alone.get(name)} / {grown[name]}")

    # A landmark given is reported as given: the left internal iliac origin where the truth has it.
    origin_lps = truth["landmarks"]["leftIliacBifurcation"]
    origin_ras = [-origin_lps[0], -origin_lps[1], origin_lps[2]]
    fourth = fresh_dir(os.path.join(workdir, "landmark-given"))
    result, marked, marked_paths = plan(cli, fourth, volume,
                                        seed_args + ["--leftInternalIliacOrigin", seed_text(origin_ras)])
    check(result.returncode == 0, "a plan with the left internal iliac origin given exits 0", result.stderr[-500:])
    check(marked.get("leftInternalIliacOriginSource") == "given"
          and marked.get("rightInternalIliacOriginSource") == "found"
          and marked.get("aorticBifurcationSource") == "found",
          "the return file says which landmark was given and which found",
          f"{marked.get('leftInternalIliacOriginSource')} {marked.get('rightInternalIliacOriginSource')} "
          f"{marked.get('aorticBifurcationSource')}")
    report = json.load(open(marked_paths["report.json"])) if os.path.isfile(marked_paths["report.json"]) else {}
    check((report.get("leftInternalIliacOrigin") or {}).get("source") == "given"
          and (report.get("aorticBifurcation") or {}).get("source") == "found",
          "the report says which landmark was given")
    markups = json.load(open(marked_paths["landmarks.mrk.json"]))["markups"][0]["controlPoints"]
    described = {p["label"]: p["description"] for p in markups}
    check(described.get("leftInternalIliacOrigin", "").startswith("Given")
          and described.get("rightInternalIliacOrigin", "").startswith("Found")
          and described.get("lowestRenalOstium", "").startswith("Found"),
          "the landmarks file describes each landmark as given or found", str(described))
    check("left internal iliac origin given" in result.stdout, "the summary says the landmark was given")

    labels, header = sem_rules.read_nrrd(lumen_path)
    # Several pieces: a separate 5-voxel blob far from the lumen is left out with a warning.
    pieces = labels.copy()
    pieces[2:4, 2:4, 2:4] = 1
    pieces_path = write_label_nrrd(os.path.join(workdir, "pieces.nrrd"), pieces, header)
    fifth = fresh_dir(os.path.join(workdir, "pieces"))
    result, _, _ = plan(cli, fifth, volume, ["--inputLumenSegmentation", pieces_path])
    warned = [line for line in result.stderr.splitlines() if "separate pieces" in line]
    check(result.returncode == 0 and len(warned) == 1 and warned[0].startswith("WARNING: ") and "mL" in warned[0],
          "a segmentation of two pieces plans, with one WARNING naming the volume left out", result.stderr[:600])

    # Bad inputs.
    far_header = dict(header)
    far_header["origin"] = [float(header["origin"][0]) + 1000.0, *header["origin"][1:]]
    far = write_label_nrrd(os.path.join(workdir, "far.nrrd"), labels, far_header)
    bad_case(cli, workdir, "segmentation-elsewhere", volume, ["--inputLumenSegmentation", far],
             ["does not overlap", "mm LPS", "the CT spans"])
    bad_case(cli, workdir, "labels-without-voxels", volume,
             ["--inputLumenSegmentation", lumen_path, "--lumenLabels", "7"], ["No voxel", "(7)", "1 ("])
    two = np.where(labels > 0, 1, 0).astype(np.uint8)  # the lower half of the slices 2, the upper 1
    k_half = labels.shape[0] // 2
    two[:k_half][two[:k_half] > 0] = 2
    two_path = write_label_nrrd(os.path.join(workdir, "two-labels.nrrd"), two, header)
    bad_case(cli, workdir, "several-labels", volume, ["--inputLumenSegmentation", two_path],
             ["holds 2 labels", "lumenLabels"])
    # The aorta alone (nothing below 30 mm above the bifurcation, which the phantom puts at z = 0).
    top = labels.copy()
    for k in range(top.shape[0]):
        if lps_z(header, k) < 30.0:
            top[k] = 0
    top_path = write_label_nrrd(os.path.join(workdir, "aorta-only.nrrd"), top, header)
    bad_case(cli, workdir, "no-y", volume, ["--inputLumenSegmentation", top_path],
             ["forms no aorto-iliac Y", "lumenLabels"])
    missing = os.path.join(workdir, "no-such-segmentation.nii.gz")
    bad_case(cli, workdir, "missing-segmentation", volume, ["--inputLumenSegmentation", missing],
             [missing, "does not exist"])
    right_lps = truth["landmarks"]["rightIliacBifurcation"]
    far_origin = [-right_lps[0], -right_lps[1] + 15.0, right_lps[2]]  # 15 mm anterior (RAS y)
    bad_case(cli, workdir, "origin-far", volume, seed_args + ["--rightInternalIliacOrigin", seed_text(far_origin)],
             ["rightInternalIliacOrigin", "from the right iliac centerline", "within 10 mm"])
    b_lps = truth["landmarks"]["aorticBifurcation"]
    high_b = [-b_lps[0], -b_lps[1], b_lps[2] + 25.0]
    bad_case(cli, workdir, "bifurcation-far", volume, seed_args + ["--aorticBifurcation", seed_text(high_b)],
             ["aorticBifurcation", "from the aortic centerline's lower end", "within 15 mm"])
    bad_case(cli, workdir, "origin-wrong-side", volume,
             seed_args + ["--rightInternalIliacOrigin", seed_text(origin_ras)],
             ["rightInternalIliacOrigin", "on the patient's left"])
    bad_case(cli, workdir, "ct-outputs-without-a-ct", lumen_path,
             ["--inputLumenSegmentation", lumen_path, "--outputReportHtml", "{outdir}/report.html",
              "--outputWallLabelMap", "{outdir}/wall.nrrd"],
             ["there is no CT", "outputWallLabelMap, outputReportHtml"])
    bad_case(cli, workdir, "landmark-not-numbers", volume, seed_args + ["--aorticBifurcation", "a,b,c"],
             ["aorticBifurcation", "a,b,c"])

    passed = sum(results)
    print(f"{passed} passed, {len(results) - passed} failed")
    return 0 if passed == len(results) else 1


if __name__ == "__main__":
    sys.exit(main())
