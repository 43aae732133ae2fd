#!/usr/bin/python3
"""The visual planning report and the straightened volumes through the CLI, checked in a real
browser (issue 15, "What must show").

Usage: test_report_html.py --phantom PHANTOM_EXE --cli SGS_EXE --workdir DIR [--chromium PATH]
                           [--screenshot-out PNG]

On the default phantom, the CLI with --outputReportHtml, --outputStraightenedVolume and
--outputStraightenedLeftVolume:
- the report is under 3 MB, has no script and no external reference (every src/href is a data URI);
- headless Chromium (Debian's) renders it without console messages (the detector is shown to catch
  a page that logs an error), its screenshot has the window's size and is not blank (the blankness
  check is shown to catch a blank page), and the DOM text holds the recommendation and (a)-(f)
  exactly as the return-parameter file has them;
- the straightened volume has the documented geometry, and at level (b)'s mark (the DOM's
  data-path-mm) the lumen's width across its middle coronal line is the truth's (b) within 1 mm.
printing it to PDF gives A4 pages. --screenshot-out writes the README's picture (the page at its
straightened views, halved).
Prints one line per check and `N passed, M failed`; exits 1 on any failure.
"""

import argparse
import html.parser
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sem_rules  # noqa: E402
from test_bad_input import check, fresh_dir, results, run  # noqa: E402

CHROMIUM_TIMEOUT_S = 180
WINDOW = (1000, 1400)  # width, height of the screenshot, px
MAX_BYTES = 3 * 1024 * 1024  # the bound
LEVELS = ["proximalNeckDiameter", "neckDiameter15mm", "maxAneurysmDiameter", "distalNeckMinDiameter",
          "rightIliacDiameter", "leftIliacDiameter", "proximalNeckLumenDiameter", "neckLumenDiameter15mm",
          "maxAneurysmLumenDiameter", "distalNeckMinLumenDiameter", "rightIliacLumenDiameter",
          "leftIliacLumenDiameter"]


def chromium(exe, args, profile):
    argv = [exe, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--no-first-run",
            f"--user-data-dir={profile}", "--enable-logging=stderr", "--v=0", *args]
    try:
        return subprocess.run(argv, capture_output=True, text=True, timeout=CHROMIUM_TIMEOUT_S)
    except subprocess.TimeoutExpired as expired:
        return subprocess.CompletedProcess(argv, None, expired.stdout or "", expired.stderr or "")


def console_messages(stderr):
    """Chromium logs each console message (and each uncaught error) as `…:CONSOLE(line)] "…"`."""
    return [line for line in stderr.splitlines() if ":CONSOLE" in line]


def screenshot(exe, url, out, profile):
    result = chromium(exe, [f"--window-size={WINDOW[0]},{WINDOW[1]}", f"--screenshot={out}", url], profile)
    if not os.path.exists(out):
        return None, result
    return read_png(out), result


def readme_picture(exe, report, workdir, profile, out):
    """The README's picture: the page at its straightened views (a helper page shows the report in a
    frame at #straightened: headless Chromium's screenshot ignores a fragment of the page itself),
    halved (2 x 2 pixel means: the CT's noise is what makes a PNG large) to 500 x 700."""
    frame = os.path.join(workdir, "frame.html")
    with open(frame, "w") as handle:
        handle.write('<html><body style="margin:0"><iframe src="%s#straightened" style="border:0;width:%dpx;'
                     'height:%dpx"></iframe></body></html>' % (os.path.basename(report), WINDOW[0], WINDOW[1]))
    pixels, _ = screenshot(exe, "file://" + frame, os.path.join(workdir, "views.png"), profile)
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.util.numpy_support import numpy_to_vtk
    rgb = pixels[..., :3].astype(float)
    half = rgb.reshape(rgb.shape[0] // 2, 2, rgb.shape[1] // 2, 2, 3).mean(axis=(1, 3)).round().astype(np.uint8)
    image = vtkImageData()
    image.SetDimensions(half.shape[1], half.shape[0], 1)
    image.GetPointData().SetScalars(numpy_to_vtk(half[::-1].reshape(-1, 3).copy(), deep=1))  # VTK: bottom row first
    writer = vtkPNGWriter()
    writer.SetFileName(out)
    writer.SetInputData(image)
    writer.Write()


def blank(pixels):
    """Blank: (nearly) one colour; a page with text, plots and CT images has many grey levels."""
    grey = pixels[..., :3].mean(axis=2)
    return grey.std() < 5.0 or len(np.unique(grey.round())) < 32


class DataNames(html.parser.HTMLParser):
    """The text of every element with a data-name attribute (and its data-value, the return file's
    text), the level marks' data-path-mm, and the simulated components' extents per view."""

    def __init__(self):
        super().__init__()
        self.values, self.full, self.levels, self.components, self._open = {}, {}, {}, [], []
        self._view = None

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if "data-straightened" in attrs:
            self._view = attrs["data-straightened"]
        if "data-level" in attrs and "data-path-mm" in attrs:
            self.levels.setdefault(attrs["data-level"], []).append(float(attrs["data-path-mm"]))
        if "data-component" in attrs:
            self.components.append((self._view, attrs["data-component"], float(attrs["data-from-mm"]),
                                    float(attrs["data-to-mm"])))
        if "data-name" in attrs and "data-value" in attrs:
            self.full.setdefault(attrs["data-name"], []).append(attrs["data-value"])
        self._open.append(attrs.get("data-name"))

    def handle_endtag(self, tag):
        if self._open:
            self._open.pop()

    def handle_data(self, data):
        if self._open and self._open[-1]:
            self.values.setdefault(self._open[-1], []).append(data.strip())


def decode_png(data_uri, path):
    """The RGB pixels (rows from the top) of a PNG data URI, through VTK's reader."""
    import base64
    with open(path, "wb") as handle:
        handle.write(base64.b64decode(data_uri.split(",", 1)[1]))
    return read_png(path)


def check_order_and_graft(ok, dom, names, returned, deployment, workdir):
    """Issues 29 and 30 in the page: the order list first, the simulated graft drawn."""
    order, devices = dom.find('id="order"'), dom.find("<h2>Devices</h2>")
    ok(0 < order < devices, "the order list comes before the IFU tables", f"at {order}, devices at {devices}")
    shown = names.values.get("orderList", [])
    ok(shown and shown[0] == returned["orderList"] and " × " in shown[0],
       "the page's order list is the returned orderList (each component as diameter × length)", f"{shown}")
    full, texts = names.full.get("mainBodyLength", []), names.values.get("mainBodyLength", [])
    ok(full and full[0] == returned["mainBodyLength"] and texts and texts[0] == f"{float(full[0]):.1f} mm",
       "the main body's length is shown at 0.1 mm beside its return value", f"{texts} {full}")
    for name in ("proximalSealLength", "proximalOversizing"):
        texts, full = names.values.get(name, []), names.full.get(name, [])
        unit, decimals = (" mm", 1) if name.endswith("Length") else (" %", 0)
        ok(texts and full and texts[0] == f"{float(full[0]):.{decimals}f}{unit}",
           f"the fit check shows {name} at clinical precision, not its variable name", f"{texts} {full}")
    ok("proximalSealLength 3" not in dom and "proximalSealLength</td>" not in dom,
       "the fit check's rows are words, not variable names")
    # The 3-D views: two, not blank, showing the graft's colours (main body blue, limbs green and
    # orange; shaded, so compared by hue).
    uris = re.findall(r'class="graft-view"[^>]*src="(data:image/png;base64,[^"]*)"', dom)
    ok(len(uris) == 2, f"the page has the graft's two 3-D views ({len(uris)})")
    for k, uri in enumerate(uris):
        rgb = decode_png(uri, os.path.join(workdir, f"graft-view-{k}.png"))[..., :3].astype(int)
        r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
        blue = np.count_nonzero((b > 1.6 * r) & (b > 1.3 * g) & (b > 80))
        orange = np.count_nonzero((r > 1.3 * g) & (g > 1.5 * b) & (r > 120))
        ok(not blank(rgb) and blue > 500 and orange > 200,
           f"3-D view {k}: not blank, the main body's blue ({blue} px) and the contralateral limb's orange "
           f"({orange} px) show", f"{rgb.shape}")
    # The straightened views draw the simulated components: the main body from the deployment
    # target, and every component as long as the catalogue says (the graft neither slides nor
    # shortens), within 1 mm — the bar.
    target = deployment["anatomy"]["deploymentTargetAbscissaMm"] if deployment else None
    for view in ("right", "left"):
        drawn = [c for c in names.components if c[0] == view]
        body = [c for c in drawn if c[1] == "main body"]
        ok(body and target is not None and abs(body[0][2] - target) <= 1.0,
           f"{view} view: the main body is drawn from the deployment target ({target})", f"{body}")
        ok(len(drawn) >= 2, f"{view} view: the main body and the limb(s) on this side are drawn", f"{drawn}")
    lengths = {}
    for component in deployment["components"] if deployment else []:
        side = "right" if component["vessel"] in ("rightIliac",) else "left" if component["vessel"] == "leftIliac" else None
        if component["role"] in ("ipsilateralLimb", "contralateralLimb"):
            lengths[(side, component["role"].replace("Limb", " limb"))] = component["lengthMm"]
    for (side, role), length in lengths.items():
        drawn = [c for c in names.components if c[0] == side and c[1] == role]
        ok(drawn and abs((drawn[0][3] - drawn[0][2]) - length) <= 1.0,
           f"{side} view: the {role} is drawn {length} mm long as simulated", f"{drawn}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--phantom", required=True)
    parser.add_argument("--cli", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--chromium", default="/usr/bin/chromium")
    parser.add_argument("--screenshot-out")
    args = parser.parse_args()
    workdir = fresh_dir(os.path.abspath(args.workdir))
    profile = tempfile.mkdtemp(prefix="sgp-chromium-")
    try:
        return run_checks(args, workdir, profile)
    finally:
        shutil.rmtree(profile, ignore_errors=True)


HOLD_SCALE = 4.0  # display px per mm of a hold figure (ReportFigureSvg.h)


def check_hold_figures(ok, dom, deployment, workdir, exe, profile):
    """Issue 47 item 3: per component, its hold band on the straightened view, where the numbers say.

    The DOM: one figure per component the tolerance assessed, its band from the edge less the range
    above to the edge plus the range below (the report JSON's), to 0.001 mm. Chromium: each figure
    alone on a page, screenshot; the solid bar's green rows span the band to 2 px (0.5 mm at 4 px per
    mm: a pixel's rounding at each end), none where the band is empty; the figure is not blank."""
    holds = (deployment or {}).get("tolerance") or {}
    components = holds.get("components") or []
    ok(holds.get("assessed") and components, f"wall in fat: the deployment tolerance was assessed "
       f"({len(components)} components)", str(holds.get("notAssessedReason")))
    for hold in components:
        k = hold["component"]
        svg = re.search(r'(<svg[^>]*data-hold="%d"[^>]*>.*?</svg>)' % k, dom, re.S)
        bar = re.search(r'class="hold-band" data-hold="%d" data-edge-mm="([^"]*)" data-band-from-mm="([^"]*)" '
                        r'data-band-to-mm="([^"]*)"' % k, dom)
        if not ok(svg and bar, f"{hold['name']}: a hold figure with its band"):
            continue
        edge, start, end = (float(v) for v in bar.groups())
        ok(abs(start - (edge - hold["aboveMm"])) <= 1e-3 and abs(end - (edge + hold["belowMm"])) <= 1e-3,
           f"{hold['name']}: the band runs {hold['aboveMm']:.1f} mm above to {hold['belowMm']:.1f} mm below its edge",
           f"{start} {edge} {end}")
        tag = svg.group(1)[:svg.group(1).index(">")]
        top = float(re.search(r'data-view-top-mm="([^"]*)"', tag).group(1))
        width = int(re.search(r' width="(\d+)"', tag).group(1))
        height = int(re.search(r' height="(\d+)"', tag).group(1))
        view_left = float(re.search(r'viewBox="([^ ]*) ', tag).group(1))
        bar_x = float(re.search(r'class="hold-band"[^>]* x="([^"]*)"', svg.group(1)).group(1))
        page = os.path.join(workdir, f"hold-{k}.html")
        with open(page, "w") as handle:
            handle.write('<html><body style="margin:0;background:#fff">%s</body></html>' % svg.group(1))
        out = os.path.join(workdir, f"hold-{k}.png")
        result = chromium(exe, [f"--window-size={width},{height}", f"--screenshot={out}", "file://" + page], profile)
        if not ok(os.path.exists(out), f"{hold['name']}: Chromium draws the hold figure", result.stderr[-300:]):
            continue
        pixels = read_png(out)
        ok(not blank(pixels), f"{hold['name']}: the hold figure is not blank")
        column = int(round((bar_x + 2.0 - view_left) * HOLD_SCALE))  # the bar's middle (4 mm wide)
        rgb = pixels[:, column, :3].astype(int)
        green = np.flatnonzero((rgb[:, 1] > 140) & (rgb[:, 0] < 60) & (rgb[:, 2] < 60))
        expected = ((start - top) * HOLD_SCALE, (end - top) * HOLD_SCALE)
        if end - start < 0.25:
            ok(green.size == 0, f"{hold['name']}: no band drawn for a range of {end - start:.2f} mm", str(green[:5]))
        else:
            ok(green.size and abs(green[0] - expected[0]) <= 2 and abs(green[-1] + 1 - expected[1]) <= 2,
               f"{hold['name']}: in Chromium the band spans rows {expected[0]:.0f}-{expected[1]:.0f} as its numbers say",
               f"green rows {green[:1]}..{green[-1:]}")


def read_png(path):
    """The PNG at path as rows x columns x channels, row 0 the top."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[::-1]  # VTK's rows run upward


def run_checks(args, workdir, profile):
    # The default phantom (no wall to be seen: the outer values are -1 and nothing is recommended),
    # then the same anatomy with a 1.5 mm wall in fat and 14 mm iliacs, where every (a)-(f) is
    # measured and a device recommended, so that the DOM comparison compares numbers.
    cases = [("default", []), ("wall-in-fat", ["--wallThicknessMm", "1.5", "--tissueHu", "-100",
                                                "--rightIliacDiameterMm", "14", "--leftIliacDiameterMm", "14"])]
    for name, phantom_args in cases:
        check_case(args, fresh_dir(os.path.join(workdir, name)), profile, name, phantom_args,
                   args.screenshot_out if name == "wall-in-fat" else None)
    print(f"{sum(results)} passed, {len(results) - sum(results)} failed")
    return 0 if all(results) else 1


def check_case(args, workdir, profile, case, phantom_args, screenshot_out):
    def ok(condition, what, detail=""):
        return check(condition, f"{case}: {what}", detail)

    volume, truth_path = os.path.join(workdir, "phantom.nrrd"), os.path.join(workdir, "truth.json")
    params = os.path.join(workdir, "phantom.params")
    result = run([args.phantom, "--returnparameterfile", params, *phantom_args, "--outputTruth", truth_path, volume],
                 workdir)
    if not ok(result.returncode == 0, "the phantom is generated", result.stderr[:400]):
        return
    truth = json.load(open(truth_path))
    seed = sem_rules.read_return_parameters(params)["seedRas"]
    report, ret = os.path.join(workdir, "report.html"), os.path.join(workdir, "ret.params")
    right, left = os.path.join(workdir, "straight-right.nrrd"), os.path.join(workdir, "straight-left.nrrd")
    plan_json = os.path.join(workdir, "report.json")
    result = run([args.cli, "--returnparameterfile", ret, "--seed", seed, "--outputReportHtml", report,
                  "--outputReport", plan_json, "--outputStraightenedVolume", right,
                  "--outputStraightenedLeftVolume", left, volume], workdir)
    if not ok(result.returncode == 0 and os.path.exists(report), "the CLI writes the report (exit 0)",
                 f"exit {result.returncode}; {result.stderr.strip()[:600]}"):
        return
    returned = sem_rules.read_return_parameters(ret)
    deployment = json.load(open(plan_json)).get("deployment")
    text = open(report, encoding="utf-8").read()

    size = os.path.getsize(report)
    ok(size < MAX_BYTES, f"the report is under 3 MB ({size / 1e6:.2f} MB)")
    references = re.findall(r"""\b(?:src|href)\s*=\s*["']([^"']*)["']""", text, flags=re.I)
    external = [r[:60] for r in references if not r.startswith("data:")]
    ok(references and not external, f"every src/href of the report is a data URI ({len(references)} of them)",
          f"external: {external[:5]}")
    ok(not re.search(r"\b(?:https?|file):", re.sub(r"xmlns=\"[^\"]*\"", "", text)),
          "no http:, https: or file: anywhere in the page (the SVG namespace aside)")
    ok("<script" not in text.lower(), "the report has no script")

    # The console detector and the blankness check can fail: a page that logs, a blank page.
    probe = os.path.join(workdir, "probe.html")
    open(probe, "w").write('<html><body><script>console.error("sgp-console-probe")</script></body></html>')
    logged = chromium(args.chromium, ["--dump-dom", "file://" + probe], profile)
    ok(any("sgp-console-probe" in m for m in console_messages(logged.stderr)),
          "control: a page that logs an error is caught", logged.stderr[-600:])
    empty = os.path.join(workdir, "blank.html")
    open(empty, "w").write("<html><body></body></html>")
    pixels, _ = screenshot(args.chromium, "file://" + empty, os.path.join(workdir, "blank.png"), profile)
    ok(pixels is not None and blank(pixels), "control: a blank page's screenshot is found blank")

    dom = chromium(args.chromium, ["--dump-dom", "file://" + report], profile)
    ok(dom.returncode == 0 and "</html>" in dom.stdout, "Chromium renders the report (--dump-dom)",
          f"exit {dom.returncode}; {dom.stderr[-400:]}")
    messages = console_messages(dom.stderr)
    ok(not messages, "no console message while rendering", "; ".join(messages[:3]))
    shot = os.path.join(workdir, "report.png")
    pixels, taken = screenshot(args.chromium, "file://" + report, shot, profile)
    ok(pixels is not None and pixels.shape[1] == WINDOW[0] and pixels.shape[0] == WINDOW[1],
          f"the screenshot is {WINDOW[0]} x {WINDOW[1]}", f"{None if pixels is None else pixels.shape}; "
          f"{taken.stderr[-300:]}")
    ok(pixels is not None and not blank(pixels), "the screenshot is not blank")
    if screenshot_out:
        readme_picture(args.chromium, report, workdir, profile, screenshot_out)

    # The print stylesheet: "print to PDF" gives A4 pages (595 x 842 pt, 210 x 297 mm).
    pdf = os.path.join(workdir, "report.pdf")
    chromium(args.chromium, [f"--print-to-pdf={pdf}", "file://" + report], profile)
    boxes = re.findall(rb"/MediaBox\s*\[([^\]]*)\]", open(pdf, "rb").read()) if os.path.exists(pdf) else []
    sizes = {tuple(round(float(v)) for v in box.split()) for box in boxes}
    ok(boxes and sizes == {(0, 0, 595, 842)}, f"printed to PDF: {len(boxes)} pages, all A4", f"{sizes}")

    names = DataNames()
    names.feed(dom.stdout)
    shown = names.values.get("recommendedDevice", [])
    ok(shown and all(v == returned["recommendedDevice"] for v in shown),
       f"the DOM shows recommendedDevice = {returned['recommendedDevice']} as the return file has it", f"{shown}")
    # What a person reads (issue 30): at clinical precision, 0.1 mm, "not measured" for -1; the
    # return file's full-precision text rides along in data-value.
    for name in LEVELS:
        full, texts = names.full.get(name, []), names.values.get(name, [])
        expected = "not measured" if returned[name] == "-1" else f"{float(returned[name]):.1f} mm"
        ok(full and all(v == returned[name] for v in full) and texts and all(t == expected for t in texts),
           f"the DOM shows {name} as {expected!r}, with {returned[name]} as the return file has it",
           f"shown {texts}, data-value {full}")
    ok(returned["recommendedDevice"] in dom.stdout, "the recommendation is in the DOM text")
    # Issue 47: the recommendation line names the device once and says "within IFU" once, in words.
    line = re.search(r"<li><b>Recommendation:</b>(.*?)(<ul>|</li>)", dom.stdout, re.S)
    text = re.sub(r"<[^>]*>", "", line.group(1)) if line else ""
    device = returned["recommendedDevice"]
    ok(line and text.count(device) == 1 and text.count("within IFU") <= 1 and "true" not in text
       and names.full.get("withinIfu") == [returned["withinIfu"]],
       "the recommendation line names the device once, its IFU verdict once, no 'true'", text)
    # The straightened views' landmarks in words ("right renal ostium"), their names in data-landmark.
    marks = re.findall(r'data-landmark="([^"]*)">([^<]*)<', dom.stdout)
    ok(marks and all(not re.search(r"[a-z][A-Z]", shown) for _, shown in marks),
       f"the straightened views label {len(marks)} landmarks in words", f"{marks[:4]}")
    if case == "wall-in-fat":
        ok(returned["recommendedDevice"] != "none" and all(float(returned[n]) > 0 for n in LEVELS),
              "wall in fat: a device is recommended and every (a)-(f) is measured (the comparison compares numbers)")
        check_order_and_graft(ok, dom.stdout, names, returned, deployment, workdir)
        check_hold_figures(ok, dom.stdout, deployment, workdir, args.chromium, profile)

    # The straightened volume: geometry, and the lumen's width at (b)'s mark against the truth.
    data, header = sem_rules.read_nrrd(right)
    directions = np.array(header["directions"], float)
    step = float(np.linalg.norm(directions[2]))
    ok(np.allclose(directions / step, np.diag([1.0, 1.0, -1.0])) and data.shape[1] == data.shape[2],
          f"the straightened volume: square cross-sections, direction diag(1, 1, -1) ({data.shape}, {step} mm)")
    marks = names.levels.get("(b)", [])
    ok(len(marks) == 2 and abs(marks[0] - marks[1]) < 1e-6, "(b) is marked on both straightened views",
          f"{marks}")
    if marks:
        row = int(round(marks[0] / step))
        line = data[row, data.shape[1] // 2, :].astype(float)
        centre = line.size // 2
        lumen = np.median(line[centre - 3:centre + 4])
        # What borders the lumen: its wall or soft tissue, at least 40 HU (issue 32: half-way to the
        # fat beyond a thin wall the edge lies 0.5 mm out on each side; GrowLumenRegion's floor).
        outside = max(np.median(np.concatenate([line[:10], line[-10:]])), 40.0)
        half = 0.5 * (lumen + outside)
        inside = np.nonzero(line >= half)[0]
        # The run of pixels around the centre above half-maximum, edges interpolated linearly.
        lo, hi = centre, centre
        while lo > 0 and line[lo - 1] >= half:
            lo -= 1
        while hi < line.size - 1 and line[hi + 1] >= half:
            hi += 1
        left_edge = lo - (line[lo] - half) / (line[lo] - line[lo - 1])
        right_edge = hi + (line[hi] - half) / (line[hi] - line[hi + 1])
        width = (right_edge - left_edge) * step
        expected = truth["sizing"]["neckDiameter15mm"]
        # 1 mm: the diameter bar on these 1 mm slices (the blur and noise of the phantom).
        ok(abs(width - expected) <= 1.0 and inside.size > 0,
              f"at (b)'s mark the straightened lumen is {width:.2f} mm wide across (truth {expected:.2f} mm)")


if __name__ == "__main__":
    sys.exit(main())
