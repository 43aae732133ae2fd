#!/usr/bin/env bash
# Installs what is missing, builds, generates a synthetic aneurysm phantom (with a vertebra and
# enhancing kidneys), runs the whole planning job on it the way Slicer would (lumen, centerlines,
# stent fit, measurements, device selection, simulated graft), and prints the results next to
# the phantom's known truth, the recommendation and the fit check; it ends with the paths of the
# visual report (HTML) and the straightened views it wrote. Each stage's time is its own (the wall
# stage's is its work on the second core).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# Only what the demo uses: the tests' packages (GoogleTest, Chromium, Snakemake, Slurm, …) and the
# test and benchmark programs come with scripts/test.sh.
sgp_install demo
SGP_CCACHE=${SGP_CCACHE:-0} sgp_build -DBUILD_TESTING=OFF -DSGP_BUILD_BENCHMARKS=OFF -- StentGraftSimulation SyntheticAorticPhantom

demo="$SGP_BUILD/demo"
mkdir -p "$demo"
cli="$SGP_BUILD/CLI"

echo "== Generating the phantom (0.8 x 0.8 x 1.0 mm, noise 20 HU, vertebra 2 mm from the sac, kidneys;"
echo "   a 1.5 mm wall in fat, a 12 mm crescent of sac thrombus, 14 mm common iliacs)"
"$cli/SyntheticAorticPhantom" "$demo/phantom.nrrd" --outputTruth "$demo/truth.json" \
  --outputTruthLabelMap "$demo/truth-labels.nrrd" --includeBone --includeKidneys \
  --wallThicknessMm 1.5 --thrombusMaxThicknessMm 12 --tissueHu -100 \
  --rightIliacDiameterMm 14 --leftIliacDiameterMm 14 \
  --returnparameterfile "$demo/phantom.params" >/dev/null
seed=$(sed -n 's/^seedRas = //p' "$demo/phantom.params")

echo "== Running StentGraftSimulation (seed $seed, RAS)"
"$cli/StentGraftSimulation" "$demo/phantom.nrrd" --seed "$seed" \
  --outputLabelMap "$demo/lumen.nrrd" --outputCenterlines "$demo/centerlines.vtp" \
  --outputLandmarks "$demo/landmarks.mrk.json" --outputStentModel "$demo/stent.vtp" \
  --outputSimulatedStentModel "$demo/graft.vtp" --outputMeasurements "$demo/measurements.csv" \
  --outputDiameterProfile "$demo/profile.csv" --outputReport "$demo/report.json" \
  --outputWallLabelMap "$demo/wall.nrrd" --outputOuterWallModel "$demo/outer-wall.vtp" \
  --outputReportHtml "$demo/report.html" --outputStraightenedVolume "$demo/straight-right.nrrd" \
  --outputStraightenedLeftVolume "$demo/straight-left.nrrd" \
  --returnparameterfile "$demo/results.params" >"$demo/run.log"

"$SGP_PYTHON" - "$demo" <<'PY'
import csv, json, os, re, sys
demo = sys.argv[1]
truth = json.load(open(os.path.join(demo, "truth.json")))
returns = dict(line.split(" = ", 1) for line in open(os.path.join(demo, "results.params")).read().splitlines())
report = json.load(open(os.path.join(demo, "report.json")))
log = open(os.path.join(demo, "run.log")).read()
stages = re.findall(r"<filter-end>\s*<filter-name>([^<]*)</filter-name>\s*<filter-time>([^<]*)</filter-time>", log)
measured = float(returns["lumenVolumeMl"])
expected = truth["lumenVolumeMl"]
print()
print("StentGraftPlanner demo: planning EVAR on a synthetic abdominal aortic aneurysm")
print("  stage times:    " + ", ".join("%s %.2f s" % (n, float(t)) for n, t in stages))
print("  lumen volume:   %.1f mL (phantom truth %.1f mL, error %+.1f %%); HU window %.0f to %.0f"
      % (measured, expected, 100.0 * (measured - expected) / expected, float(returns["lowerHuUsed"]),
         float(returns["upperHuUsed"])))
summary = [l for l in log.splitlines() if l.startswith("Centerlines:")]
print("  " + (summary[0] if summary else "Centerlines: (none)"))
site = report["proximalSite"]
print("  proximal implantation site: from the %s (%s), %.1f mm down the aorta"
      % (site["source"], site.get("renal") or "-", site["abscissaMm"]))
print()
print("  %-52s %10s %8s %7s" % ("measurement", "measured", "truth", "error"))
sizing = truth["sizing"]
# (a)-(f) are outer-wall values (the truth's outer* keys); the lumen values are the truth's plain keys.
truth_of = dict(neckAngleBeta=sizing["neckAngleBetaDeg"], thrombusVolume=sizing.get("thrombusVolumeMl"),
                maxThrombusThickness=sizing.get("maxThrombusThicknessMm"),
                neckThrombusArc=sizing.get("neckThrombusArcPercent"),
                neckCalcificationArc=sizing.get("neckCalcificationArcPercent"))
for key in ("proximalNeckLength", "proximalSiteToBifurcationLength", "rightIliacLength", "leftIliacLength"):
    truth_of[key] = sizing[key]
for outer in ("proximalNeckDiameter", "neckDiameter15mm", "maxAneurysmDiameter", "distalNeckMinDiameter",
              "rightIliacDiameter", "leftIliacDiameter"):
    truth_of[outer] = sizing["outer" + outer[0].upper() + outer[1:]]
    truth_of[outer.replace("Diameter", "LumenDiameter")] = sizing[outer]
# The table's label and shown columns are the words and the clinical precision a person reads.
with open(os.path.join(demo, "measurements.csv"), newline="") as table:
    rows = list(csv.DictReader(table))
for row in rows:
    value = float(row["value"]) if row["value"] not in ("", "nan") else None
    t = truth_of.get(row["name"])
    compared = "%8.1f %+7.1f" % (t, value - t) if t is not None and value is not None else ""
    print("  %-52s %10s %s" % (row["label"], row["shown"], compared))
device = report.get("device") or {}
recommendation = device.get("recommendation") or {}
print()
print("Recommendation: " + (recommendation.get("summary") or "none"))
for reason in recommendation.get("reasons") or []:
    print("  - " + reason)
for family in device.get("families") or []:
    failing = [c["text"] for c in family["checks"] if c["status"] != "pass"]
    status = {"pass": "within IFU", "fail": "outside IFU", "indeterminate": "IFU not decided"}[family["ifuStatus"]]
    print("  %-22s %s" % (family["name"], status + (": " + "; ".join(failing) if failing else "")))
# The order list: the components a surgeon orders, where each lands, and why (the CLI's summary).
lines = log.splitlines()
start = next((i for i, line in enumerate(lines) if line.startswith("Order list:")), None)
print()
if start is not None:
    end = start + 1
    while end < len(lines) and lines[end].startswith("  "):
        end += 1
    print("\n".join(lines[start:end]))
else:
    print("Order list: none (%s)" % ((report.get("deployment") or {}).get("unknownReason") or "no device configured"))
fit = report.get("fitCheck")
if fit:
    print("Fit check of the simulated %s graft: %s" % (device.get("simulated"), "passed" if fit["passed"] else "FAILED"))
    shown = lambda value, unit: "not known" if value is None else "%.1f %s" % (value, unit)
    print("  seal on healthy wall: proximal %s, right iliac %s, left iliac %s"
          % tuple(shown(fit[k], "mm") for k in ("proximalSealLengthMm", "rightIliacSealLengthMm", "leftIliacSealLengthMm")))
    print("  oversizing: proximal %s, right limb %s, left limb %s"
          % tuple(shown(fit[k], "%") for k in ("proximalOversizingPercent", "rightLimbOversizingPercent",
                                               "leftLimbOversizingPercent")))
    print("  ostia covered: " + (", ".join(fit["coveredOstia"]) or "none")
          + "; migration risk: " + ("yes" if fit["migrationRisk"] else "no"))
    for finding in fit["findings"]:
        print("  - " + finding)
print()
print("Outputs in %s (open them in 3D Slicer; models are LPS):" % demo)
for name, what in (("phantom.nrrd", "CT volume (HU)"), ("truth.json", "analytic ground truth"),
                   ("lumen.nrrd", "segmented lumen label map"),
                   ("centerlines.vtp", "centerlines (Name, Radius, Abscissa)"),
                   ("landmarks.mrk.json", "landmarks (Slicer markups)"),
                   ("stent.vtp", "stent surface fitted in measure mode"),
                   ("graft.vtp", "simulated graft: every ordered component (ComponentRole, HealthyWall, Sealing)"),
                   ("wall.nrrd", "vessel wall label map (1 lumen, 2 thrombus and wall, 3 calcium)"),
                   ("outer-wall.vtp", "outer wall surface (ThrombusThicknessMm, Supported)"),
                   ("measurements.csv", "measurements table"), ("profile.csv", "diameter profiles"),
                   ("report.json", "the whole plan"), ("results.params", "SEM return parameters")):
    print("  %-18s %s" % (name, what))
print()
print("Device figures are public defaults (Resources/devices.json): verify them against the current IFU.")
print()
print("The visual report and the straightened views (CT resampled along the centerline; open the .nrrd in 3D Slicer):")
for name in ("report.html", "straight-right.nrrd", "straight-left.nrrd"):
    path = os.path.join(demo, name)
    print("  " + (path if os.path.isfile(path) and os.path.getsize(path) > 0 else path + " (missing!)"))
PY
