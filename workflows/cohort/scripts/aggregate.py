#!/usr/bin/python3
"""The cohort's table and summary page, from each case's status and return-parameter file.

Usage: aggregate.py --cli EXE --manifest CSV [--cases-dir DIR] --csv OUT.csv --html OUT.html

- `cohort.csv`: one row per case in manifest order, columns `case,status,error` and then every
  return value of StentGraftSimulation in the order of its `--xml` (the `<parameters>` children
  with `<channel>output</channel>` and neither `<flag>` nor `<longflag>`). The values are copied
  as text from the case's `ret.params` (`name = value` lines, split at the first `=`), so the table
  says exactly what the CLI said; a failed case has empty value cells, and so has a value that
  its file lacks.
- `cohort.html`: one self-contained page (inline CSS and SVG, no script, no link to any file or
  address): the counts (cases, planned, failed), the distributions of Dmax, the proximal neck
  diameter and the neck length (-1 = not measured: left out and counted), the recommended device
  families (`none` = none within the IFU), and each failure with its ERROR line.

Raises RuntimeError when the CLI's XML cannot be read (no column order), ValueError for a bad
manifest; a missing or unreadable status file makes that case `failed` with the reason in `error`.
The functions are plain and importable, for Testing/Workflow.
"""

import argparse
import csv
import html
import json
import math
import os
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from manifest import read_manifest  # noqa: E402

FIXED_COLUMNS = ["case", "status", "error"]
RETURN_FILE = "ret.params"
MIN_BINS = 10  # bars on the narrowest histogram axis
NOT_MEASURED = -1.0  # the CLI's number for a value it could not measure
# (return parameter, title, unit) of the distributions on the page
DISTRIBUTIONS = (
    ("maxAneurysmDiameter", "Maximum aneurysm diameter (Dmax)", "mm"),
    ("proximalNeckDiameter", "Proximal neck diameter", "mm"),
    ("proximalNeckLength", "Proximal neck length", "mm"),
)


def return_parameter_names(xml_text):
    """The CLI's return values in XML order: outputs with no flag or longflag."""
    root = ElementTree.fromstring(xml_text)
    names = []
    for group in root.iter("parameters"):
        for parameter in group:
            if (parameter.findtext("channel", "").strip() == "output" and parameter.find("flag") is None
                    and parameter.find("longflag") is None and parameter.findtext("name")):
                names.append(parameter.findtext("name").strip())
    return names


def cli_return_parameter_names(cli):
    result = subprocess.run([cli, "--xml"], capture_output=True, text=True, timeout=120)
    if result.returncode != 0:
        raise RuntimeError(f"{cli} --xml exited with {result.returncode}: {result.stderr.strip()[:300]}")
    names = return_parameter_names(result.stdout)
    if not names:
        raise RuntimeError(f"{cli} --xml declares no return parameter")
    return names


def read_return_parameters(path):
    """name -> value (text) from a `name = value` file, split at the first '=' (as Slicer does)."""
    values = {}
    with open(path, encoding="utf-8") as handle:
        for line in handle:
            line = line.rstrip("\r\n")
            if "=" not in line:
                continue
            key, value = line.split("=", 1)
            if key.strip(" \t"):
                values[key.strip(" \t")] = value.strip(" \t")
    return values


def case_row(case, case_dir, names):
    """One row of cohort.csv for the case whose folder is case_dir."""
    row = dict.fromkeys(FIXED_COLUMNS + names, "")
    row["case"] = case
    try:
        with open(os.path.join(case_dir, "status.json"), encoding="utf-8") as handle:
            status = json.load(handle)
    except (OSError, ValueError) as error:
        row.update(status="failed", error=f"no readable status.json ({error})")
        return row
    row["status"] = "ok" if status.get("status") == "ok" else "failed"
    row["error"] = status.get("error", "") if row["status"] == "failed" else ""
    if row["status"] == "ok":
        try:
            values = read_return_parameters(os.path.join(case_dir, RETURN_FILE))
        except OSError as error:
            row.update(status="failed", error=f"planned, but {RETURN_FILE} cannot be read ({error})")
            return row
        for name in names:
            row[name] = values.get(name, "")
    return row


def cohort_rows(cases, cases_dir, names):
    return [case_row(case, os.path.join(cases_dir, case), names) for case in cases]


def write_csv(path, names, rows):
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.DictWriter(handle, fieldnames=FIXED_COLUMNS + names, lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)


def measured_values(rows, name):
    """(values, not measured count, unreadable count) of a numeric return value over planned cases."""
    values, not_measured, unreadable = [], 0, 0
    for row in rows:
        if row["status"] != "ok":
            continue
        try:
            value = float(row.get(name, ""))
        except ValueError:
            unreadable += 1
            continue
        if value == NOT_MEASURED or not math.isfinite(value):
            not_measured += 1
        else:
            values.append(value)
    return values, not_measured, unreadable


def bin_width(values, max_bins=20, min_width=1.0):
    """A round bin width (1, 2 or 5 times a power of ten) giving at most max_bins bins, and no
    narrower than min_width (1 mm: finer differences between patients do not change a plan)."""
    span = max(values) - min(values)
    if span <= max_bins * min_width:
        return min_width
    width = 10.0 ** math.floor(math.log10(span / max_bins))
    for factor in (1, 2, 5, 10):
        if span / (width * factor) <= max_bins:
            return width * factor
    return width * 10


def svg_histogram(values, unit, width_px=420, height_px=170):
    """An inline SVG histogram of values; each bar has a <title> with its range and count."""
    if not values:
        return '<p class="muted">No measured value.</p>'
    step = bin_width(values)
    low = math.floor(min(values) / step) * step
    count = max(1, int(math.floor((max(values) - low) / step)) + 1)
    if count < MIN_BINS:  # a narrow cohort: show it on an axis of MIN_BINS bins around it
        low -= (MIN_BINS - count) // 2 * step
        count = MIN_BINS
    bins = [0] * count
    for value in values:
        bins[min(count - 1, int((value - low) // step))] += 1
    left, right, bottom, top = 34, 20, 28, 8
    plot_w, plot_h = width_px - left - right, height_px - bottom - top
    tallest = max(bins)
    bar_w = plot_w / count
    parts = [f'<svg width="{width_px}" height="{height_px}" '
             f'viewBox="0 0 {width_px} {height_px}" role="img">',
             f'<line x1="{left}" y1="{top + plot_h}" x2="{left + plot_w}" y2="{top + plot_h}" class="axis"/>',
             f'<text x="{left - 4}" y="{top + 10}" class="tick" text-anchor="end">{tallest}</text>',
             f'<text x="{left - 4}" y="{top + plot_h}" class="tick" text-anchor="end">0</text>']
    for index, n in enumerate(bins):
        x = left + index * bar_w
        h = plot_h * n / tallest
        start = low + index * step
        parts.append(f'<rect x="{x + 1:.1f}" y="{top + plot_h - h:.1f}" width="{max(bar_w - 2, 1):.1f}" '
                     f'height="{h:.1f}" class="bar"><title>{start:g} to {start + step:g} {unit}: {n}</title></rect>')
    labels = sorted({0, count // 2, count})
    for index in labels:
        x = left + index * bar_w
        parts.append(f'<text x="{x:.1f}" y="{top + plot_h + 14}" class="tick" text-anchor="middle">'
                     f'{low + index * step:g}</text>')
    parts.append(f'<text x="{left + plot_w / 2:.1f}" y="{height_px - 2}" class="tick" '
                 f'text-anchor="middle">{html.escape(unit)} (bins of {step:g})</text></svg>')
    return "".join(parts)


def family_counts(rows):
    """recommendedDevice -> number of planned cases, most frequent first; 'none' last."""
    counts = {}
    for row in rows:
        if row["status"] == "ok":
            family = row.get("recommendedDevice", "") or "(not reported)"
            counts[family] = counts.get(family, 0) + 1
    return sorted(counts.items(), key=lambda item: (item[0] == "none", -item[1], item[0]))


STYLE = """
body { font: 14px/1.4 sans-serif; margin: 1.5em auto; max-width: 980px; color: #222; }
h1 { font-size: 1.5em; } h2 { font-size: 1.15em; margin-top: 1.6em; }
table { border-collapse: collapse; } td, th { border: 1px solid #ccc; padding: 3px 8px; text-align: left; }
.counts td { font-size: 1.3em; text-align: right; } .muted { color: #777; }
.grid { display: flex; flex-wrap: wrap; gap: 16px; } .panel { border: 1px solid #ddd; padding: 8px; }
.bar { fill: #3a6ea5; } .axis { stroke: #444; } .tick { font-size: 10px; fill: #444; }
.failed { color: #a00; } code { font-size: 0.92em; }
"""


def html_page(rows, title="Cohort summary"):
    """The summary page as text (see the module docstring)."""
    esc = html.escape
    planned = sum(row["status"] == "ok" for row in rows)
    failed = [row for row in rows if row["status"] != "ok"]
    out = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
           f"<title>{esc(title)}</title><style>{STYLE}</style></head><body>",
           f"<h1>{esc(title)}</h1>",
           '<table class="counts"><tr><th>cases</th><th>planned</th><th>failed</th></tr>',
           f"<tr><td>{len(rows)}</td><td>{planned}</td><td>{len(failed)}</td></tr></table>",
           "<h2>Distributions over the planned cases</h2>", '<div class="grid">']
    for name, label, unit in DISTRIBUTIONS:
        values, not_measured, unreadable = measured_values(rows, name)
        note = f"{len(values)} measured, {not_measured} not measured (-1)"
        if unreadable:
            note += f", {unreadable} not a number"
        if values:
            note += f"; median {sorted(values)[len(values) // 2]:.1f} {unit}, range {min(values):.1f} to {max(values):.1f}"
        out.append(f'<div class="panel"><b>{esc(label)}</b> <code>{esc(name)}</code><br>'
                   f"{svg_histogram(values, unit)}<br><span class=\"muted\">{esc(note)}</span></div>")
    out.append("</div><h2>Recommended device families</h2>")
    families = family_counts(rows)
    if families:
        out.append("<table><tr><th>family</th><th>cases</th></tr>")
        for family, n in families:
            shown = "none within the IFU" if family == "none" else family
            out.append(f"<tr><td>{esc(shown)}</td><td>{n}</td></tr>")
        out.append("</table>")
    else:
        out.append('<p class="muted">No planned case.</p>')
    out.append(f"<h2>Failures ({len(failed)})</h2>")
    if failed:
        out.append("<table><tr><th>case</th><th>error</th></tr>")
        for row in failed:
            out.append(f'<tr><td>{esc(row["case"])}</td><td class="failed">{esc(row["error"])}</td></tr>')
        out.append("</table>")
    else:
        out.append('<p class="muted">None.</p>')
    out.append("</body></html>")
    return "\n".join(out) + "\n"


def aggregate(cli, manifest_path, cases_dir, csv_path, html_path):
    names = cli_return_parameter_names(cli)
    cases = [case["case"] for case in read_manifest(manifest_path)]
    rows = cohort_rows(cases, cases_dir, names)
    write_csv(csv_path, names, rows)
    with open(html_path, "w", encoding="utf-8") as handle:
        handle.write(html_page(rows))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True, help="StentGraftSimulation executable (for --xml)")
    parser.add_argument("--manifest", required=True)
    parser.add_argument("--cases-dir", default="cases")
    parser.add_argument("--csv", required=True)
    parser.add_argument("--html", required=True)
    args = parser.parse_args()
    rows = aggregate(args.cli, args.manifest, args.cases_dir, args.csv, args.html)
    planned = sum(row["status"] == "ok" for row in rows)
    print(f"cohort: {len(rows)} cases, {planned} planned, {len(rows) - planned} failed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
