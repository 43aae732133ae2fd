#!/usr/bin/python3
"""The cohort workflow (workflows/cohort, issue 16) on six phantoms, on this machine.

Usage: test_cohort_workflow.py --phantom PHANTOM_EXE --cli SGS_EXE --workdir DIR [--chromium EXE]

Six phantoms (1 x 1 x 1.5 mm): a wall in fat with 14 mm iliacs (a device fits), a vertebra in a
scan that ends 20 mm below the aortic bifurcation (a partial plan: no limb can be sized), kidneys on a grid rotated 90 degrees about the body axis with a --device, the first anatomy with an
empty seed cell (the CLI finds the aorta itself), a smaller sac with a neck too wide for any device, and one without contrast (lumen
100 HU, under the CLI's 150 HU seedMinimumHu). The manifest has every optional column, images
given relative to its folder. `snakemake --cores 2` then must give:
- cohort.csv with the columns case,status,error + the XML's return values in order, five `ok` rows
  whose values equal each case's own ret.params exactly, the seedless one with seedSource
  automatic, at least one device recommended, and one failed row (the non-contrast case) whose
  error is the one ERROR line of its log, its value cells empty and no output written;
- each planned case with graft.vtp, written in one run; where no graft can be simulated (the wide
  neck fits no device) it is empty and status.json says why (the report's reason);
- cohort.html, self-contained (no script, every src/href a data: URI, no http/https/file
  reference), naming the failure, and opening in headless Chromium without a console message (a
  control page that logs one is caught, so the detector can fail);
- a second identical run that does nothing: "Nothing to be done", no file's mtime changes.
The aggregation functions are also checked directly on rows made here (-1 left out and counted,
an error's markup escaped, flagged outputs not taken for return values).
Prints one line per check and `N passed, M failed`; exits 1 on any failure.
"""

import argparse
import html.parser
import json
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cohort_harness import (DEVICE_FITS, FAST_GRID, SOURCE, check, check_cohort_csv, fresh_dir,  # noqa: E402
                            make_phantom, results, run_snakemake, snakemake_argv, write_manifest)

sys.path.insert(0, os.path.join(SOURCE, "Testing", "CLI"))
from test_bad_input import crop_above  # noqa: E402
from test_report_html import chromium, console_messages  # noqa: E402

sys.path.insert(0, os.path.join(SOURCE, "workflows", "cohort", "scripts"))
import aggregate  # noqa: E402

ROTATED_90_ABOUT_Z = "0,1,0,-1,0,0,0,0,1"  # i along LPS y, j along -x: the grid is not the patient's axes
COLUMNS = ["case", "image", "seedRas", "lowestRenalOstiumRas", "device"]


def phantoms(exe, folder):
    """(case, phantom options, seed given?, device, expected status) of the six cases."""
    cases = [("c1-fits", FAST_GRID + DEVICE_FITS, True, "", "ok"),
             ("c2-bone-cut", FAST_GRID + ["--includeBone"], True, "", "ok"),
             ("c3-kidneys-rotated", FAST_GRID + DEVICE_FITS + ["--includeKidneys", "--directionLps", ROTATED_90_ABOUT_Z],
              True, "Endurant II", "ok"),
             ("c4-no-seed", FAST_GRID + DEVICE_FITS, False, "", "ok"),
             # A 36 mm neck (outer), wider than every main body within 10-20 %: no device, no graft.
             ("c5-small-sac", FAST_GRID + ["--maxAneurysmDiameterMm", "42", "--neckLengthMm", "18",
                                           "--neckDiameterMm", "36"], True, "", "ok"),
             ("c6-non-contrast", FAST_GRID + ["--lumenHu", "100"], True, "", "failed")]
    rows, expected = [], []
    for name, options, seeded, device, status in cases:
        seed = make_phantom(exe, folder, name, options)
        if name == "c2-bone-cut" and seed:  # the phantom's aortic bifurcation lies at LPS z = 0
            volume = os.path.join(folder, name + ".nrrd")
            os.replace(crop_above(volume, volume + ".cut.nrrd", -20.0), volume)
        rows.append({"case": name, "image": os.path.join(folder, name + ".nrrd"), "seedRas": seed if seeded else "",
                     "device": device})
        expected.append((name, status))
    return rows, expected


class Links(html.parser.HTMLParser):
    """Every tag name and every src/href value of a page."""

    def __init__(self):
        super().__init__()
        self.tags, self.references, self.text = [], [], []

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        self.references += [value or "" for name, value in attrs if name in ("src", "href", "xlink:href")]

    def handle_data(self, data):
        self.text.append(data)


def check_html(path, failed_case, failed_error, device, workdir, chromium_exe):
    text = open(path, encoding="utf-8").read() if os.path.isfile(path) else ""
    check(text, "cohort.html is written")
    page = Links()
    page.feed(text)
    words = " ".join(" ".join(page.text).split())
    check("script" not in page.tags and "<script" not in text.lower(), "cohort.html has no script")
    bad = [r for r in page.references if not r.startswith("data:")]
    check(not bad, "cohort.html: every src/href is a data: URI", f"{bad[:3]}")
    lowered = text.lower()
    check(not any(s in lowered for s in ("http://", "https://", "file:")),
          "cohort.html names no http, https or file address")
    check("cases planned failed 6 5 1" in words, "cohort.html counts 6 cases, 5 planned, 1 failed", words[:200])
    check(failed_case in words and " ".join(failed_error.split()) in words,
          "cohort.html lists the failed case with its ERROR line")
    check(device and device in words, "cohort.html lists the recommended family", f"{device!r}")
    check(text.count("<svg") == 3, "cohort.html draws the three distributions (Dmax, neck diameter, neck length)")
    profile = tempfile.mkdtemp(prefix="sgp-chromium-")
    try:
        probe = os.path.join(workdir, "probe.html")
        open(probe, "w").write('<html><body><script>console.error("sgp-console-probe")</script></body></html>')
        logged = chromium(chromium_exe, ["--dump-dom", "file://" + probe], profile)
        check(any("sgp-console-probe" in m for m in console_messages(logged.stderr)),
              "control: Chromium's console detector catches a page that logs an error", logged.stderr[-400:])
        dom = chromium(chromium_exe, ["--dump-dom", "file://" + path], profile)
        check(dom.returncode == 0 and "</html>" in dom.stdout, "Chromium renders cohort.html", dom.stderr[-400:])
        check(not console_messages(dom.stderr), "cohort.html opens without a console message",
              "; ".join(console_messages(dom.stderr))[:400])
    finally:
        shutil.rmtree(profile, ignore_errors=True)


def check_graft_models(out, planned):
    """Every planned case has graft.vtp (the CLI writes it in one run, issue 33): with a graft where
    the report names the simulated family, else empty, with graftModel false and the report's reason
    in the note. The wide neck (c5) fits no device; the partial plan (c2) has its main body
    simulated; every other case has a whole graft (a phantom without a wall is sized on the lumen)."""
    with_graft, without = [], []
    for case in planned:
        folder = os.path.join(out, "cases", case)
        status = json.load(open(os.path.join(folder, "status.json")))
        device = json.load(open(os.path.join(folder, "report.json"))).get("device") or {}
        if not os.path.isfile(os.path.join(folder, "graft.vtp")):
            continue
        if status.get("graftModel") is True and device.get("simulated"):
            with_graft.append(case)
        elif (status.get("graftModel") is False and device.get("simulated") is None
              and status.get("note") == device.get("notSimulated")
              and "No catalogue device has a main body" in status.get("note", "")):
            without.append(case)
    check(without == ["c5-small-sac"] and len(with_graft) + len(without) == len(planned),
          "every planned case has its graft model; where no graft can be simulated it is empty and "
          "status.json gives the report's reason", f"with {with_graft}, without {without}, of {planned}")


def file_times(folder):
    times = {}
    for root, _, files in os.walk(folder):
        for name in files:
            times[os.path.join(root, name)] = os.stat(os.path.join(root, name)).st_mtime_ns
    return times


def check_aggregate_functions():
    xml = ("<executable><parameters><double><name>a</name><channel>output</channel></double>"
           "<file><name>f</name><longflag>f</longflag><channel>output</channel></file>"
           "<string><name>b</name><channel>output</channel></string>"
           "<double><name>in</name><longflag>in</longflag><channel>input</channel></double></parameters></executable>")
    check(aggregate.return_parameter_names(xml) == ["a", "b"],
          "aggregate: return values are the flagless outputs in order (a file output with a longflag is not)")
    rows = [{"status": "ok", "d": "50"}, {"status": "ok", "d": "-1"}, {"status": "failed", "d": ""},
            {"status": "ok", "d": "60.5"}]
    check(aggregate.measured_values(rows, "d") == ([50.0, 60.5], 1, 0),
          "aggregate: -1 is left out of a distribution and counted as not measured; failed rows are skipped")
    page = aggregate.html_page([{"case": "x", "status": "failed", "error": "ERROR: <b>&"}])
    check("ERROR: &lt;b&gt;&amp;" in page and "<b>&" not in page, "aggregate: an error's markup is escaped")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--phantom", required=True, help="SyntheticAorticPhantom executable")
    parser.add_argument("--cli", required=True, help="StentGraftSimulation executable")
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--chromium", default="/usr/bin/chromium")
    args = parser.parse_args()
    args.phantom, args.cli = os.path.abspath(args.phantom), os.path.abspath(args.cli)
    workdir = fresh_dir(os.path.abspath(args.workdir))
    check_aggregate_functions()

    images = fresh_dir(os.path.join(workdir, "images"))
    rows, expected = phantoms(args.phantom, images)
    manifest = write_manifest(os.path.join(workdir, "cases.csv"), rows, COLUMNS)
    out = os.path.join(workdir, "out")
    argv = snakemake_argv(out, manifest, args.cli, ["--cores", "2"])
    result = run_snakemake(argv, workdir)
    if not check(result.returncode == 0, "snakemake --cores 2 finishes (exit 0) with one bad case",
                 f"exit {result.returncode}; {result.stderr[-1500:]}"):
        return summary()

    by_case = check_cohort_csv(out, args.cli, expected)
    check(by_case.get("c4-no-seed", {}).get("seedSource") == "automatic"
          and by_case.get("c1-fits", {}).get("seedSource") == "user",
          "the seedless case's seed was found automatically (seedSource), the others' were given",
          f"c4 {by_case.get('c4-no-seed', {}).get('seedSource')!r}, c1 {by_case.get('c1-fits', {}).get('seedSource')!r}")
    devices = sorted({row.get("recommendedDevice") for row in by_case.values()
                      if row.get("status") == "ok" and row.get("recommendedDevice") not in ("", "none")})
    check(devices, "at least one planned case has a recommended device", f"{[r.get('recommendedDevice') for r in by_case.values()]}")
    check_graft_models(out, [case for case, status in expected if status == "ok"])
    failed = by_case.get("c6-non-contrast", {})
    check_html(os.path.join(out, "cohort.html"), "c6-non-contrast", failed.get("error", "?"),
               devices[0] if devices else "", workdir, args.chromium)

    before = file_times(out)
    again = run_snakemake(argv, workdir)
    check(again.returncode == 0 and "Nothing to be done" in again.stdout + again.stderr,
          "a second run of the same command does nothing (\"Nothing to be done\")",
          f"exit {again.returncode}; {(again.stdout + again.stderr)[-800:]}")
    after = file_times(out)
    changed = sorted(p for p in before if after.get(p) != before[p] and "/.snakemake/" not in p)
    check(len(before) > 6 * 2 and not changed, "the second run changes no file of cases/ or the cohort",
          f"changed: {[os.path.relpath(p, out) for p in changed[:6]]}")
    return summary()


def summary():
    passed = sum(results)
    print(f"{passed} passed, {len(results) - passed} failed")
    return 0 if results and all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
