#!/usr/bin/python3
"""Lumen, outer wall and thrombus volume on wall phantoms the project's generator did not make (issue 32).

Usage: test_independent_wall_phantom.py --cli SGS_EXE --workdir DIR [--keep]

Issue 32 found, on AAA phantoms built independently of SyntheticAorticPhantom, every lumen
diameter 0.55-0.95 mm large and the thrombus volume 20-21 % high, with the outer wall right. A
phantom drawn by the same code that the pipeline was tuned on shares its conventions (how the
blur, the wall and the neighbours are drawn), so this test draws its own, here in numpy, from a
different model, and counts its truth voxel by voxel from its own masks:

- an abdominal aorta on the z axis: a 22 mm neck (lumen) with a 1.5 mm wall, a fusiform sac of
  60 mm outer diameter (a bulge on the neck-to-distal taper) whose lumen lies off-centre in an **eccentric** crescent of thrombus (or a
  **concentric** ring of it), an 18 mm distal aorta; renal arteries (the left one the lowest: its
  lower lumen edge is the proximal site), a superior mesenteric artery, common iliacs of unequal
  size (14 and 10 mm) with internal and external iliacs;
- the wall in **periaortic fat** (-100 HU) inside soft tissue (40 HU); a 3 mm crescent of neck
  thrombus 4-11 mm below the site; a 70 deg arc of calcium in the sac's wall; the **psoas**
  muscles (50 HU), the **inferior vena cava** (enhancing, 120 HU) and the **duodenum** (30 HU)
  touching the sac; a vertebra 3 mm behind it;
- every class drawn as a sharp mask on the voxel centres of a grid 4 x finer in each in-plane
  axis and 2 x finer along z than the scan, averaged down (partial volume), blurred with a
  Gaussian point-spread function (sigma 0.9 mm) and given 15 HU of Gaussian noise (seeded).

Truth: the lumen and outer diameters of the drawn circles ((a) and (b) in the straight neck, (c)
the sac's widest lumen circle, (d) the distal aorta, (e) and (f) the common iliacs); the thrombus
volume counted on the fine grid, thrombus voxels between the site and the bifurcation (z = 0).
Checks, on 1 mm and on 2.5 mm slices: the plan runs; lumen (a)-(f) within 1.0 mm (1.5 mm on
2.5 mm slices), outer within 1.5 mm (2.0 mm), issue 32's bars, and the six lumen errors without a
common offset (their mean within 0.5 mm: the class the issue found was an offset of every edge);
the thrombus volume within 10 % of the voxel count. Prints one line per check and `N passed, M failed`; exits 1 on any failure.
"""

import argparse
import csv
import json
import math
import os
import sys

import numpy as np
from scipy.ndimage import gaussian_filter  # Debian's python3-scipy, a dependency of python3-skimage

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_bad_input import check, fresh_dir, results, run  # noqa: E402

# Tissue classes of the drawn masks, later ones painted over earlier ones.
HU = {"tissue": 40.0, "fat": -100.0, "psoas": 50.0, "ivc": 120.0, "duodenum": 30.0, "bone": 250.0,
      "cortex": 650.0, "wall": 60.0, "thrombus": 40.0, "calcium": 900.0, "lumen": 330.0}
WALL_MM = 1.5
NECK_LUMEN_R = 11.0  # (a), (b): 22 mm
DISTAL_LUMEN_R = 9.0  # (d): 18 mm
SAC_OUTER_R = 31.0  # the bulge's peak over the neck's outer radius (Dmax as drawn: 60.0 mm)
SITE_Z = 150.0  # the left renal's lower lumen edge
SAC_TOP, SAC_BOTTOM = 122.0, 25.0  # the neck is 28 mm long
ILIAC_R = {"right": 7.0, "left": 5.0}  # 14 and 10 mm lumen (ratio 1.4)
ILIAC_END = {"right": (-35.0, 5.0, -60.0), "left": (35.0, 5.0, -60.0)}
RENAL_R = 3.0
BLUR_MM = 0.9
NOISE_HU = 15.0


def outer_radius(z):
    """The aorta's outer radius at height z (mm): neck, sac (sin^2 bulge on a taper), distal aorta."""
    z = np.asarray(z, float)
    t = np.clip((SAC_TOP - z) / (SAC_TOP - SAC_BOTTOM), 0.0, 1.0)
    base = (NECK_LUMEN_R + WALL_MM) * (1 - t) + (DISTAL_LUMEN_R + WALL_MM) * t
    return base + (SAC_OUTER_R - (NECK_LUMEN_R + WALL_MM)) * np.sin(math.pi * t) ** 2


def lumen_circle(z, concentric):
    """The aortic lumen at height z: radius and the centre's y (LPS mm; anterior is -y)."""
    z = np.asarray(z, float)
    t = np.clip((SAC_TOP - z) / (SAC_TOP - SAC_BOTTOM), 0.0, 1.0)
    inner = outer_radius(z) - WALL_MM
    base = NECK_LUMEN_R * (1 - t) + DISTAL_LUMEN_R * t
    radius = base + 0.45 * (inner - base)
    centre_y = np.zeros_like(z) if concentric else -0.8 * (inner - radius)
    return radius, centre_y


def segment_distance(x, y, z, a, b):
    """Distance of each point to the segment a-b, and the position along it (0..1)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    d = b - a
    length2 = float(d @ d)
    t = np.clip(((x - a[0]) * d[0] + (y - a[1]) * d[1] + (z - a[2]) * d[2]) / length2, 0.0, 1.0)
    return np.sqrt((x - a[0] - t * d[0]) ** 2 + (y - a[1] - t * d[1]) ** 2 + (z - a[2] - t * d[2]) ** 2), t


def draw(x, y, z, concentric):
    """Class masks on the points of a grid, LPS mm: a dict of boolean arrays of its shape, painted in HU order.

    x, y and z are the grid's coordinates as arrays that broadcast against each other (x along the
    last axis, y the middle one, z the first): every value is computed on the points it depends on,
    and each branch only within its own reach, which gives the same masks as full grids, faster.
    """
    shape = np.broadcast_shapes(x.shape, y.shape, z.shape)
    r_out = outer_radius(z)
    r_lumen, cy = lumen_circle(z, concentric)
    rho = np.hypot(x, y)
    above_fork = z >= 0.0
    aorta_outer = (rho <= r_out) & above_fork
    aorta_lumen = (np.hypot(x, y - cy) <= r_lumen) & above_fork
    lumen = np.broadcast_to(aorta_lumen, shape).copy()
    outer = np.broadcast_to(aorta_outer, shape).copy()
    fat_reach = np.broadcast_to(rho <= r_out + 12.0, shape).copy()
    # Side branches and iliacs: lumen tubes with a wall; blind ends in fat.
    branches = [((0, 0, SITE_Z + RENAL_R), (70, 8, SITE_Z + RENAL_R), RENAL_R, 1.0),  # left renal, the lowest
                ((0, 0, SITE_Z + 11.0), (-70, 8, SITE_Z + 13.0), RENAL_R, 1.0),  # right renal
                ((0, 0, SITE_Z + 24.0), (0, -32, SITE_Z + 20.0), 3.5, 1.0),  # SMA, forward
                ((0, -32, SITE_Z + 20.0), (0, -38, SITE_Z - 35.0), 3.0, 1.0)]  # and down
    for side in ("right", "left"):
        end = ILIAC_END[side]
        sx = 1.0 if side == "left" else -1.0
        branches += [((0, 0, 2.0), end, ILIAC_R[side], WALL_MM),  # common iliac
                     (end, (sx * 45.0, -5.0, -135.0), ILIAC_R[side] - 1.5, 1.2),  # external
                     (end, (sx * 28.0, 38.0, -100.0), 3.0, 1.0)]  # internal
    z_lo, z_hi = float(z.min()), float(z.max())
    for a, b, radius, wall in branches:
        reach = radius + wall + 8.0
        if min(a[2], b[2]) - reach > z_hi or max(a[2], b[2]) + reach < z_lo:
            continue  # the segment is nowhere near these slices
        # Only the points within the segment's box widened by its reach can lie in these masks.
        near_x = np.flatnonzero((x.ravel() >= min(a[0], b[0]) - reach) & (x.ravel() <= max(a[0], b[0]) + reach))
        near_y = np.flatnonzero((y.ravel() >= min(a[1], b[1]) - reach) & (y.ravel() <= max(a[1], b[1]) + reach))
        if near_x.size == 0 or near_y.size == 0:
            continue
        cols, rows = slice(near_x[0], near_x[-1] + 1), slice(near_y[0], near_y[-1] + 1)
        dist, _ = segment_distance(x[..., cols], y[:, rows, :], z, a, b)
        lumen[:, rows, cols] |= dist <= radius
        outer[:, rows, cols] |= dist <= radius + wall
        fat_reach[:, rows, cols] |= dist <= radius + wall + 8.0
    aorta_inner = aorta_outer & (rho <= r_out - WALL_MM)
    wall = outer & ~lumen & ~aorta_inner
    thrombus = aorta_inner & ~lumen
    # Neck thrombus: a crescent on the left, 3 mm thick at most, 4-11 mm below the site.
    neck = (z <= SITE_Z - 4.0) & (z >= SITE_Z - 11.0)
    crescent = neck & (np.hypot(x + 3.0, y) > NECK_LUMEN_R) & (rho <= NECK_LUMEN_R)
    thrombus |= crescent
    lumen &= ~crescent
    # Calcium: a 70 deg arc of the sac's wall, posterior-left, 60-95 mm up.
    angle = np.degrees(np.arctan2(y, x))  # 90 deg: posterior
    calcium = wall & aorta_outer & (z >= 60.0) & (z <= 95.0) & (np.abs(angle - 55.0) <= 35.0)
    wall &= ~calcium
    # Neighbours.
    r_sac = SAC_OUTER_R
    psoas = (np.hypot(np.abs(x) - 38.0, y - 22.0) <= 14.0) & (z <= 120.0)  # 1.1 mm into the widest sac
    ivc = (np.hypot(x + 40.0, y - 5.0) <= 11.0) & (z >= -20.0)  # pressed 1.7 mm into the widest sac
    z_duo = 95.0
    duo_y = -(float(outer_radius(z_duo)) + 12.0)
    duodenum = (np.hypot(y - duo_y, z - z_duo) <= 12.0) & (np.abs(x) <= 70.0)
    vy = r_sac + 3.0 + 18.0
    bone_r = np.hypot(x, y - vy)
    bone = bone_r <= 18.0
    cortex = bone & (bone_r >= 16.0)
    masks = {"fat": fat_reach, "psoas": psoas, "ivc": ivc, "duodenum": duodenum, "bone": bone, "cortex": cortex,
             "wall": wall, "thrombus": thrombus, "calcium": calcium, "lumen": lumen}
    return {name: np.broadcast_to(mask, shape) for name, mask in masks.items()}


def make_scan(path, spacing, concentric, noise_seed):
    """Draws the phantom on `spacing` (x, y, z mm) and writes it as NRRD; returns the truth."""
    lo = np.array([-80.0, -72.0, -140.0])
    hi = np.array([80.0, 80.0, 240.0])
    size = np.floor((hi - lo) / spacing).astype(int)
    sub = (4, 4, 2)  # fine points per voxel along x, y, z
    hu = np.zeros(size[::-1], np.float32)  # [k, j, i]
    thrombus_mm3 = 0.0
    fine_cell = spacing[0] * spacing[1] * spacing[2] / (sub[0] * sub[1] * sub[2])
    xi = lo[0] + (np.arange(size[0] * sub[0]) + 0.5) * spacing[0] / sub[0]
    yi = lo[1] + (np.arange(size[1] * sub[1]) + 0.5) * spacing[1] / sub[1]
    for k in range(size[2]):
        zk = lo[2] + (k * sub[2] + np.arange(sub[2]) + 0.5) * spacing[2] / sub[2]
        z, y, x = zk[:, None, None], yi[None, :, None], xi[None, None, :]
        masks = draw(x, y, z, concentric)
        value = np.full(masks["lumen"].shape, HU["tissue"], np.float32)
        for name in ("fat", "psoas", "ivc", "duodenum", "bone", "cortex", "wall", "thrombus", "calcium", "lumen"):
            value[masks[name]] = HU[name]
        within = (z >= 0.0) & (z <= SITE_Z)
        thrombus_mm3 += float((masks["thrombus"] & within).sum()) * fine_cell
        hu[k] = value.reshape(sub[2], size[1], sub[1], size[0], sub[0]).mean(axis=(0, 2, 4))
    hu = gaussian_filter(hu, BLUR_MM / np.asarray(spacing)[::-1])
    hu += np.random.default_rng(noise_seed).normal(0.0, NOISE_HU, hu.shape).astype(np.float32)
    data = np.clip(np.round(hu), -1024, 3071).astype("<i2")
    origin = lo + 0.5 * np.asarray(spacing)
    lines = ["NRRD0004", "type: short", "dimension: 3", "space: left-posterior-superior",
             "sizes: %d %d %d" % tuple(size), "space directions: (%r,0,0) (0,%r,0) (0,0,%r)" % tuple(spacing),
             "kinds: domain domain domain", "endian: little", "encoding: raw",
             "space origin: (%r,%r,%r)" % tuple(origin)]
    with open(path, "wb") as handle:
        handle.write(("\n".join(lines) + "\n\n").encode() + data.tobytes())
    zs = np.linspace(SAC_BOTTOM, SAC_TOP, 2001)
    r_lumen, _ = lumen_circle(zs, concentric)
    neck_outer = NECK_LUMEN_R + WALL_MM
    truth = {"proximalNeckLumenDiameter": 2 * NECK_LUMEN_R, "neckLumenDiameter15mm": 2 * NECK_LUMEN_R,
             "maxAneurysmLumenDiameter": 2 * float(r_lumen.max()), "distalNeckMinLumenDiameter": 2 * DISTAL_LUMEN_R,
             "rightIliacLumenDiameter": 2 * ILIAC_R["right"], "leftIliacLumenDiameter": 2 * ILIAC_R["left"],
             "proximalNeckDiameter": 2 * neck_outer, "neckDiameter15mm": 2 * neck_outer,
             # Dmax as drawn: the bulge rides on the neck-to-distal taper, which lies 1 mm under the
             # neck's outer radius at mid-sac, so the widest outer radius is 30.0 mm, not SAC_OUTER_R
             # (the truth said 62 mm until issue 46: planes tilted by the lumen's lean read the
             # sections 0.6-0.9 mm long and hid it).
             "maxAneurysmDiameter": 2 * float(outer_radius(zs).max()),
             "distalNeckMinDiameter": 2 * (DISTAL_LUMEN_R + WALL_MM),
             "rightIliacDiameter": 2 * (ILIAC_R["right"] + WALL_MM), "leftIliacDiameter": 2 * (ILIAC_R["left"] + WALL_MM),
             "thrombusVolume": thrombus_mm3 / 1000.0}
    return truth


def read_values(path):
    values = {}
    with open(path, newline="") as handle:
        for row in csv.DictReader(handle):
            values[row["name"]] = float(row["value"]) if row["value"] not in ("", "nan") else float("nan")
    return values


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True, help="StentGraftSimulation executable")
    parser.add_argument("--workdir", required=True, help="scratch directory")
    parser.add_argument("--cases", default="eccentric-1mm,concentric-1mm,eccentric-2.5mm",
                        help="comma-separated <eccentric|concentric>-<1mm|2.5mm>")
    args = parser.parse_args()
    workdir = os.path.abspath(args.workdir)
    os.makedirs(workdir, exist_ok=True)
    for case in args.cases.split(","):
        shape, slices = case.split("-")
        thick = slices == "2.5mm"
        spacing = (0.8, 0.8, 2.5) if thick else (0.8, 0.8, 1.0)
        folder = fresh_dir(os.path.join(workdir, case))
        volume = os.path.join(folder, "ct.nrrd")
        truth = make_scan(volume, spacing, shape == "concentric", noise_seed=32)
        with open(os.path.join(folder, "truth.json"), "w") as handle:
            json.dump(truth, handle, indent=1)
        seed_ras = "0,0,%g" % (SITE_Z + 40.0)  # LPS (0, 0, z): RAS flips x and y
        measurements = os.path.join(folder, "measurements.csv")
        result = run([os.path.abspath(args.cli), "--seed", seed_ras, "--outputMeasurements", measurements, volume], folder)
        if not check(result.returncode == 0 and os.path.exists(measurements), f"{case}: the plan runs",
                     f"exit {result.returncode}: {result.stderr[-600:]}"):
            continue
        values = read_values(measurements)
        lumen_bar, outer_bar = (1.5, 2.0) if thick else (1.0, 1.5)  # issue 32's tolerances by slice
        lumen_errors = [values.get(n, float("nan")) - v for n, v in truth.items() if "Lumen" in n]
        mean_error = sum(lumen_errors) / len(lumen_errors)
        # A boundary level off sits every lumen edge off the same way (issue 32: +0.55 to +0.95 mm at
        # all six levels); a level's own errors (a ring at a renal mouth, noise) do not share a sign.
        check(abs(mean_error) <= 0.5, f"{case}: the lumen (a)-(f) have no common offset (mean within 0.5 mm)",
              f"mean {mean_error:+.2f} mm")
        print(f"NOTE: {case}: mean lumen error {mean_error:+.2f} mm")
        for name, expected in truth.items():
            if name == "thrombusVolume":
                continue
            bar = lumen_bar if "Lumen" in name else outer_bar
            got = values.get(name, float("nan"))
            check(abs(got - expected) <= bar, f"{case}: {name} within {bar} mm",
                  f"{got:.2f} for {expected:.2f} mm ({got - expected:+.2f})")
            print(f"NOTE: {case}: {name} {got:.2f} for {expected:.2f} mm ({got - expected:+.2f})")
        got, expected = values.get("thrombusVolume", float("nan")), truth["thrombusVolume"]
        # Issue 32's bar: 10 % of a voxel-counted truth.
        check(abs(got - expected) <= 0.10 * expected, f"{case}: thrombus volume within 10 % of the voxel count",
              f"{got:.1f} for {expected:.1f} mL ({100 * (got / expected - 1):+.1f} %)")
        print(f"NOTE: {case}: thrombusVolume {got:.1f} for {expected:.1f} mL ({100 * (got / expected - 1):+.1f} %)")
    failed = results.count(False)
    print(f"{len(results) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
