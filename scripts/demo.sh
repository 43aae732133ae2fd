#!/usr/bin/env bash
# Installs what is missing, builds, generates a synthetic aneurysm phantom (with a vertebra and
# enhancing kidneys), runs the planning CLI on it the way Slicer would (lumen, centerlines,
# landmarks), and prints the results next to the phantom's known truth.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

sgp_install
sgp_build -- StentGraftSimulation SyntheticAorticPhantom

demo="$SGP_BUILD/demo"
mkdir -p "$demo"
cli="$SGP_BUILD/CLI"

echo "== Generating the phantom (0.8 x 0.8 x 1.0 mm, noise 20 HU, vertebra 2 mm from the sac, kidneys)"
"$cli/SyntheticAorticPhantom" "$demo/phantom.nrrd" --outputTruth "$demo/truth.json" \
  --outputTruthLabelMap "$demo/truth-labels.nrrd" --includeBone --includeKidneys \
  --returnparameterfile "$demo/phantom.params" >/dev/null
seed=$(sed -n 's/^seedRas = //p' "$demo/phantom.params")

echo "== Running StentGraftSimulation (seed $seed, RAS)"
"$cli/StentGraftSimulation" "$demo/phantom.nrrd" --seed "$seed" \
  --outputLabelMap "$demo/lumen.nrrd" --outputCenterlines "$demo/centerlines.vtp" \
  --outputLandmarks "$demo/landmarks.mrk.json" --returnparameterfile "$demo/results.params" >"$demo/run.log"

"$SGP_PYTHON" - "$demo" <<'PY'
import json, os, re, sys
demo = sys.argv[1]
truth = json.load(open(os.path.join(demo, "truth.json")))
returns = dict(line.split(" = ", 1) for line in open(os.path.join(demo, "results.params")).read().splitlines())
log = open(os.path.join(demo, "run.log")).read()
stages = re.findall(r"<filter-end>\s*<filter-name>([^<]*)</filter-name>\s*<filter-time>([^<]*)</filter-time>", log)
measured = float(returns["lumenVolumeMl"])
expected = truth["lumenVolumeMl"]
print()
print("StentGraftPlanner demo: lumen and centerlines of a synthetic abdominal aortic aneurysm")
print("  stage times:        " + ", ".join("%s %.2f s" % (n, float(t)) for n, t in stages))
print("  HU window used:     %.0f to %.0f HU (estimated at the seed); boundary at %.0f HU"
      % (float(returns["lowerHuUsed"]), float(returns["upperHuUsed"]), float(returns["edgeHuUsed"])))
print("  lumen volume:       %.1f mL   (phantom truth %.1f mL, error %+.1f %%)"
      % (measured, expected, 100.0 * (measured - expected) / expected))
summary = [l for l in log.splitlines() if l.startswith("Centerlines:")]
print("  " + (summary[0] if summary else "Centerlines: (none)"))
markups = json.load(open(os.path.join(demo, "landmarks.mrk.json")))["markups"][0]["controlPoints"]
print("  landmarks (LPS mm)   found                     phantom truth")
for point in markups:
    name = point["label"]
    true = truth["landmarks"].get(name)
    print("    %-24s (%6.1f, %6.1f, %6.1f)   %s" % ((name,) + tuple(point["position"]) + (
        "(%6.1f, %6.1f, %6.1f)" % tuple(true) if true else "",)))
print("  phantom sizing truth (mm): " + ", ".join("%s %.1f" % (k, v) for k, v in truth["sizing"].items()
                                                    if k.endswith("Diameter") or k.endswith("15mm")))
print()
print("Outputs in %s:" % demo)
for name, what in (("phantom.nrrd", "CT volume (HU)"), ("truth.json", "analytic ground truth"),
                   ("truth-labels.nrrd", "truth labels: 1 lumen, 2 bone, 3 kidney"),
                   ("lumen.nrrd", "segmented lumen label map"),
                   ("centerlines.vtp", "centerlines (LPS; Name, Radius, Abscissa)"),
                   ("landmarks.mrk.json", "landmarks (Slicer markups, LPS)"),
                   ("results.params", "SEM return parameters")):
    print("  %-18s %s" % (name, what))
PY
