#!/usr/bin/python3
"""The panel's Re-plan (issue 45 item 3) in its plain-Python layer, on real CLI runs.

Usage: check_panel_replan.py --phantom PHANTOM_EXE --cli SGS_EXE --workdir DIR

The phantom: 0.8 x 0.8 x 1.5 mm voxels on a grid turned 90 degrees about the body's axis (the grid's
axes are not the patient's: a frame mistake moves a landmark to the wrong place), a 1.5 mm wall in fat
(the outer wall is traced, so the outer diameters are values that could change), iliacs of 14 and
10 mm outer (a right/left swap cannot pass).

1. A plan, made as the panel makes it (check_panel_run.py): Settings.cliParametersCreatingOutputs
   with the default settings, argv by Slicer's rules (Testing/CLI/sem_rules.py).
2. Re-plan 1: the right internal iliac origin of the landmarks file is dragged 8 mm along the right
   iliac's centerline toward its distal end (the centerlines file's rightIliac polyline, LPS), and
   Replan.replanParameters makes the parameters from the plan's. Then:
   - the moved landmark is the CLI's --rightInternalIliacOrigin, in RAS (its LPS with L and P
     negated), and the landmarks nobody moved are not passed (the CLI finds them again);
   - the plan's lumen label map is --inputLumenSegmentation, and no --lumenLabels is sent;
   - the CLI exits 0; its return file says lumenSource given and rightInternalIliacOriginSource given,
     its report's rightInternalIliacOrigin "source" is "given" (the bifurcation's stays "found"), its
     landmarks file's description starts with "Given"; the lumen volume is the plan's (the round trip);
   - the right iliac length grows by the distance the origin moved along the centerline, and the
     change list (Replan.changeLines on the two runs' results, read by Outcome.planningResults as the
     panel reads them) names it, and does not name what does not hang from that origin: (a) outer and
     lumen, the proximal neck length, the site-to-bifurcation length, the left iliac length, (f).
3. Re-plan 2, from re-plan 1: the aortic bifurcation is dragged 5 mm up the aortic centerline. The
   right internal iliac origin given in re-plan 1 is given again; the bifurcation is given, in RAS;
   re-plan 1's lumen is passed. The report says both are "given"; the site-to-bifurcation length
   shrinks and both iliac lengths grow, by the 5 mm moved; the change list names those three and
   not (a) or the proximal neck length.
Prints one line per check and `N passed, M failed`; exits 1 on any failure.
"""

import argparse
import csv
import json
import math
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "Testing", "CLI"))
from StentGraftPlannerLib import Outcome, Replan, Settings  # noqa: E402
import sem_rules  # noqa: E402
from test_bad_input import check  # noqa: E402
from check_panel_run import EXTENSIONS, finish, run  # noqa: E402  (the panel run's harness)


#: How far the given point's effect may differ from the distance it was moved along the centerline, in
#: mm: the CLI takes a given point to the nearest point of its centerline, sampled every
#: centerlineStepMm (1 mm by default), so its abscissa is the moved one's within one step.
STEP_TOLERANCE_MM = 1.0

#: Return values that do not hang from an internal iliac origin (so re-plan 1 must not list them), and
#: from the bifurcation (re-plan 2): the labels the change list gives them.
UNRELATED_TO_ILIAC_ORIGIN = ("(a) proximal neck diameter, outer wall", "(a) proximal neck diameter, lumen",
                             "Proximal neck length", "Proximal site to bifurcation", "Left iliac length",
                             "(f) left iliac diameter, outer wall", "(f) left iliac diameter, lumen")
UNRELATED_TO_BIFURCATION = ("(a) proximal neck diameter, outer wall", "(a) proximal neck diameter, lumen",
                            "Proximal neck length")


def centerline(path, name):
    """The LPS points of the centerlines file's polyline named ``name`` (cell data Name), in order."""
    import vtk  # python3-vtk9 standalone; Slicer's Python has it too

    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    polyData = reader.GetOutput()
    space = polyData.GetFieldData().GetAbstractArray("SPACE")
    if space is None or space.GetValue(0) != "LPS":
        raise ValueError("%s does not say its points are LPS (field data SPACE)" % path)
    names = polyData.GetCellData().GetAbstractArray("Name")
    for cell in range(polyData.GetNumberOfCells()):
        if names.GetValue(cell) == name:
            ids = polyData.GetCell(cell).GetPointIds()
            return [tuple(polyData.GetPoint(ids.GetId(i))) for i in range(ids.GetNumberOfIds())]
    raise ValueError("%s has no polyline named %s" % (path, name))


def abscissae(points):
    total, result = 0.0, [0.0]
    for a, b in zip(points, points[1:]):
        total += math.dist(a, b)
        result.append(total)
    return result


def nearestAbscissa(points, point):
    """The abscissa along ``points`` of the point of the polyline nearest ``point`` (on its segments)."""
    best, bestAbscissa = math.inf, 0.0
    along = abscissae(points)
    for index, (a, b) in enumerate(zip(points, points[1:])):
        ab = [q - p for p, q in zip(a, b)]
        length2 = sum(c * c for c in ab) or 1e-12
        t = max(0.0, min(1.0, sum((x - p) * c for x, p, c in zip(point, a, ab)) / length2))
        foot = [p + t * c for p, c in zip(a, ab)]
        if math.dist(foot, point) < best:
            best, bestAbscissa = math.dist(foot, point), along[index] + t * math.sqrt(length2)
    return bestAbscissa


def pointAt(points, abscissa):
    along = abscissae(points)
    for index in range(len(points) - 1):
        if along[index + 1] >= abscissa:
            t = (abscissa - along[index]) / ((along[index + 1] - along[index]) or 1e-12)
            return tuple(p + t * (q - p) for p, q in zip(points[index], points[index + 1]))
    return points[-1]


def moveAlong(points, point, distanceMm, awayFrom):
    """``point`` moved ``distanceMm`` along the polyline from its nearest point, away from the end nearer
    ``awayFrom``; returns (the new point, its abscissa minus the old one's, measured from that end)."""
    if math.dist(points[-1], awayFrom) < math.dist(points[0], awayFrom):
        points = points[::-1]
    start = nearestAbscissa(points, point)
    return pointAt(points, start + distanceMm), distanceMm


def edit(markupsText, label, lps):
    """The landmarks file with one control point dragged to ``lps`` (what the panel's node then holds)."""
    data = json.loads(markupsText)
    for point in data["markups"][0]["controlPoints"]:
        if point["label"] == label:
            point["position"] = list(lps)
    return data


class Planner:
    """Runs the CLI the way the panel does, one folder per run, and reads what the panel reads."""

    def __init__(self, cli, workdir):
        self.cli, self.workdir = cli, workdir
        xml = run([cli, "--xml"], workdir)
        self.declared, _ = sem_rules.check_module_xml(xml.stdout)

    def outputs(self, name):
        folder = os.path.join(self.workdir, name)
        os.makedirs(folder, exist_ok=True)
        paths = {role.name: os.path.join(folder, role.name + EXTENSIONS[role.nodeClass]) for role in Settings.OUTPUT_ROLES}
        paths[Settings.REPORT_PARAMETER] = os.path.join(folder, "report.json")
        return folder, paths

    def run(self, name, parameters):
        """(parameters with this run's output paths, argv, outputs, return values, PlanningResults or None)
        of one run."""
        folder, paths = self.outputs(name)
        parameters = dict(parameters, **paths)
        retfile = sem_rules.slicer_return_parameter_file(folder)
        argv = sem_rules.slicer_argv(self.cli, self.declared, parameters, retfile)
        result = run(argv, folder)
        ok = result.returncode == 0 and not any(line.startswith("ERROR: ") for line in result.stderr.splitlines())
        check(ok, f"{name}: the CLI exits 0 without an ERROR line", f"exit {result.returncode}; {result.stderr[-600:]}")
        if not ok:
            return parameters, argv, paths, {}, None
        values = sem_rules.read_return_parameters(retfile)
        with open(paths["outputMeasurements"], newline="", encoding="utf-8") as table:
            rows = list(csv.DictReader(table))
        with open(paths[Settings.REPORT_PARAMETER], encoding="utf-8") as report:
            planned = Outcome.planningResults(report.read(), lambda n: values.get(n, ""), rows)
        return parameters, argv, paths, values, planned


def flagValue(argv, flag):
    """The value after ``flag`` in argv, or None when the flag is not there."""
    return argv[argv.index(flag) + 1] if flag in argv else None


def checkPoint(argv, flag, lps, what):
    """The argv passes ``flag`` as the RAS of ``lps`` (Slicer's six significant digits: within 0.001 mm)."""
    text = flagValue(argv, flag)
    ras = (-lps[0], -lps[1], lps[2])  # written out here: Replan.lpsToRas is what is being checked
    sent = [float(v) for v in text.split(",")] if text else []
    check(len(sent) == 3 and all(abs(s - r) < 1e-3 for s, r in zip(sent, ras)),
          f"{what}: {flag} is the landmark in RAS {tuple(round(c, 2) for c in ras)}", f"sent {text!r}")


def changes(before, after):
    lines = Replan.changeLines(Replan.resultsSnapshot(before.values, before.report),
                               Replan.resultsSnapshot(after.values, after.report))
    print("CHANGES:\n  " + "\n  ".join(lines or ["(none)"]))
    return lines


def named(lines, label):
    return [line for line in lines if line.startswith(label + ": ")]


def checkReplan(what, argv, paths, values, previousPaths, given, found):
    """What every re-plan must show: the previous lumen passed without labels, the given landmarks given."""
    check(flagValue(argv, "--inputLumenSegmentation") == previousPaths["outputLabelMap"],
          f"{what}: the previous run's lumen label map is --inputLumenSegmentation",
          str(flagValue(argv, "--inputLumenSegmentation")))
    check("--lumenLabels" not in argv, f"{what}: no --lumenLabels (every non-zero voxel of the CLI's own map)",
          str(flagValue(argv, "--lumenLabels")))
    for label in found:
        check("--" + label not in argv, f"{what}: the unmoved, found {label} is not passed (found again)",
              str(flagValue(argv, "--" + label)))
    check(values.get("lumenSource") == "given", f"{what}: the return file says lumenSource given",
          str(values.get("lumenSource")))
    with open(paths[Settings.REPORT_PARAMETER], encoding="utf-8") as report:
        data = json.load(report)
    with open(paths["outputLandmarks"], encoding="utf-8") as landmarks:
        read = Replan.landmarksFromMarkups(landmarks.read())
    for label in given:
        check((data.get(label) or {}).get("source") == "given" and values.get(label + "Source") == "given",
              f"{what}: the report and the return file say {label} is given",
              f"report {data.get(label)}, return {values.get(label + 'Source')}")
        check(label in read and read[label].given, f"{what}: the landmarks file marks {label} Given", str(read.get(label)))
    for label in found:
        if label in ("aorticBifurcation", "rightInternalIliacOrigin", "leftInternalIliacOrigin"):
            check((data.get(label) or {}).get("source") == "found", f"{what}: the report says {label} is found",
                  str(data.get(label)))
    return read


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--phantom", required=True, help="SyntheticAorticPhantom executable")
    parser.add_argument("--cli", required=True, help="StentGraftSimulation executable")
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    workdir = os.path.abspath(args.workdir)
    args.phantom, args.cli = os.path.abspath(args.phantom), os.path.abspath(args.cli)  # the runs change folder
    if os.path.exists(workdir):
        shutil.rmtree(workdir)
    os.makedirs(workdir)

    volume = os.path.join(workdir, "phantom.nrrd")
    phantomParams = os.path.join(workdir, "phantom.params")
    result = run([args.phantom, "--returnparameterfile", phantomParams, "--spacingMm", "0.8,0.8,1.5",
                  "--directionLps", "0,1,0,-1,0,0,0,0,1", "--wallThicknessMm", "1.5", "--tissueHu", "-100",
                  "--rightIliacDiameterMm", "14", "--leftIliacDiameterMm", "10", volume], workdir)
    if not check(result.returncode == 0, "the phantom is generated", result.stderr[:400]):
        return finish()
    seed = [float(v) for v in sem_rules.read_return_parameters(phantomParams)["seedRas"].split(",")]
    planner = Planner(args.cli, workdir)

    # 1. The plan, as Apply makes it.
    _, paths = planner.outputs("plan")
    plan = Settings.cliParametersCreatingOutputs(Settings.defaultSettings(), {"inputVolume": volume, "seed": seed},
                                                 {"seed": 1}, lambda role: paths[role.name], paths["outputReport"])
    plan, _, planPaths, planValues, planned = planner.run("plan", plan)
    if planned is None:
        return finish()
    with open(planPaths["outputLandmarks"], encoding="utf-8") as landmarks:
        planLandmarksText = landmarks.read()
    planLandmarks = Replan.landmarksFromMarkups(planLandmarksText)
    check(set(planLandmarks) == set(Replan.EDITABLE_LANDMARKS) and not any(m.given for m in planLandmarks.values()),
          "plan: the landmarks file holds the four editable landmarks, each found", str(planLandmarks))
    if set(planLandmarks) != set(Replan.EDITABLE_LANDMARKS):
        return finish()

    # 2. Re-plan 1: the right internal iliac origin dragged 8 mm distally along the right iliac.
    label = "rightInternalIliacOrigin"
    rightIliac = centerline(planPaths["outputCenterlines"], "rightIliac")
    movedLps, movedMm = moveAlong(rightIliac, planLandmarks[label].lps, 8.0, planLandmarks["aorticBifurcation"].lps)
    edited = Replan.landmarksFromMarkups(edit(planLandmarksText, label, movedLps))
    inputs = Replan.replanParameters(plan, planLandmarks, edited)
    check(inputs.moved == [label] and not inputs.givenAgain and not inputs.lumenEdited,
          "re-plan 1: only the right internal iliac origin counts as moved", str(inputs[1:]))
    replan1, argv, paths1, values1, replanned1 = planner.run("replan1", inputs.parameters)
    checkPoint(argv, "--" + label, movedLps, "re-plan 1")
    if replanned1 is None:
        return finish()
    landmarks1 = checkReplan("re-plan 1", argv, paths1, values1, planPaths, given=(label,),
                             found=("lowestRenalOstium", "aorticBifurcation", "leftInternalIliacOrigin"))
    check(abs(float(values1["lumenVolumeMl"]) - float(planValues["lumenVolumeMl"])) <= 0.001 * float(planValues["lumenVolumeMl"]),
          "re-plan 1: the lumen is the plan's (volume within 0.1 %: the same voxels)",
          f"{values1['lumenVolumeMl']} mL against {planValues['lumenVolumeMl']} mL")
    grown = replanned1.values["rightIliacLength"] - planned.values["rightIliacLength"]
    check(abs(grown - movedMm) <= STEP_TOLERANCE_MM,
          f"re-plan 1: the right iliac length grows by the {movedMm} mm moved (within {STEP_TOLERANCE_MM} mm)",
          f"grew {grown:.2f} mm")
    lines = changes(planned, replanned1)
    check(len(named(lines, "Right iliac length")) == 1, "re-plan 1: the change list names the right iliac length",
          str(lines))
    wrong = [line for name in UNRELATED_TO_ILIAC_ORIGIN for line in named(lines, name)]
    check(not wrong, "re-plan 1: the change list names nothing that does not hang from the origin "
                     "((a), neck length, site to bifurcation, the left iliac)", str(wrong))

    # 3. Re-plan 2, from re-plan 1: the aortic bifurcation dragged 5 mm up the aorta.
    with open(paths1["outputLandmarks"], encoding="utf-8") as landmarks:
        landmarks1Text = landmarks.read()
    aorta = centerline(paths1["outputCenterlines"], "aorta")
    bifurcation = landmarks1["aorticBifurcation"].lps
    movedLps2, movedMm2 = moveAlong(aorta, bifurcation, 5.0, bifurcation)
    edited2 = Replan.landmarksFromMarkups(edit(landmarks1Text, "aorticBifurcation", movedLps2))
    inputs2 = Replan.replanParameters(replan1, landmarks1, edited2)  # what re-plan 1 ran with, its outputs too
    check(inputs2.moved == ["aorticBifurcation"] and inputs2.givenAgain == [label],
          "re-plan 2: the bifurcation counts as moved, the origin given in re-plan 1 as given again", str(inputs2[1:]))
    _, argv2, paths2, values2, replanned2 = planner.run("replan2", inputs2.parameters)
    checkPoint(argv2, "--aorticBifurcation", movedLps2, "re-plan 2")
    checkPoint(argv2, "--" + label, movedLps, "re-plan 2 (given again)")
    if replanned2 is None:
        return finish()
    checkReplan("re-plan 2", argv2, paths2, values2, paths1, given=("aorticBifurcation", label),
                found=("lowestRenalOstium", "leftInternalIliacOrigin"))
    lines = changes(replanned1, replanned2)
    shift = {name: replanned2.values[name] - replanned1.values[name]
             for name in ("proximalSiteToBifurcationLength", "rightIliacLength", "leftIliacLength")}
    expected = {"proximalSiteToBifurcationLength": -movedMm2, "rightIliacLength": movedMm2, "leftIliacLength": movedMm2}
    check(all(abs(shift[name] - expected[name]) <= STEP_TOLERANCE_MM for name in shift),
          f"re-plan 2: site to bifurcation shrinks and both iliac lengths grow by the {movedMm2} mm moved "
          f"(within {STEP_TOLERANCE_MM} mm)", str({k: round(v, 2) for k, v in shift.items()}))
    for name in ("Proximal site to bifurcation", "Right iliac length", "Left iliac length"):
        check(len(named(lines, name)) == 1, f"re-plan 2: the change list names the {name.lower()}", str(lines))
    wrong = [line for name in UNRELATED_TO_BIFURCATION for line in named(lines, name)]
    check(not wrong, "re-plan 2: the change list does not name (a) or the proximal neck length", str(wrong))
    return finish()


if __name__ == "__main__":
    sys.exit(main())
