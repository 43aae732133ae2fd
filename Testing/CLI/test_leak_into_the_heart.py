#!/usr/bin/python3
"""A lumen that spreads into the heart and the great veins: no made-up Y (issue 13, item 1).

Usage: test_leak_into_the_heart.py --phantom PHANTOM_EXE --cli SGS_EXE --workdir DIR

A real thoraco-abdominal CTA ending at the coeliac level, seeded in the aorta there, gave a plan:
the lumen had spread into the heart and the chest vessels, and where the aorta met the heart the
aorta above, the inferior vena cava to the right and the aorta below to the left were named the
aorta and its two iliacs. The class, rebuilt from the project's own phantom: the default phantom
with its grid extended 90 mm up and 50 mm forward, the aorta carried on to the top border, and
painted at lumen contrast against it the heart (an ellipsoid 90 x 72 x 80 mm overlapping the
aorta's anterior wall by 5 mm: no fat plane, so the region grows into it), the pulmonary veins
to both sides, the superior vena cava to the top border and the inferior vena cava from the right
atrium down the abdomen (contrast refluxing into it), blurred 1 mm and with 20 HU noise like the
phantom.

- Scan ending at the coeliac level (the quoted case), seed in the aorta at the coeliac: one ERROR
  line with the scan's extent (and, on the noise draws whose skeleton has the shape of a Y, the
  junction refused), nothing written — for the whole plan and for --outputCenterlines alone.
- The whole abdomen in view, heart without the vena cava (an arterial phase), seed at the top of
  the abdominal aorta: the real Y is found and the neck and sac values equal those of the same
  phantom without the heart (the heart lies 70 mm above the renal arteries).
Prints one line per check and `N passed, M failed`; exits 1 on any failure.
"""

import argparse
import json
import os
import sys

import numpy as np
from scipy.ndimage import gaussian_filter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sem_rules  # noqa: E402
from test_bad_input import bad_case, check, crop_above, fresh_dir, results, run, run_cli  # noqa: E402


def tube(grid, a, b, radius):
    """Voxels within `radius` mm of the segment a-b (LPS mm)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    axis = b - a
    length = np.linalg.norm(axis)
    axis /= length
    rel = np.stack([grid[0] - a[0], grid[1] - a[1], grid[2] - a[2]], -1)
    t = np.clip(rel @ axis, 0.0, length)
    return np.linalg.norm(rel - t[..., None] * axis, axis=-1) <= radius


def paint_heart(volume_path, out_path, with_vena_cava, noise_seed=5):
    """The phantom with the heart and great veins painted against its aorta (module docstring)."""
    data, header = sem_rules.read_nrrd(volume_path)
    origin = np.array(header["origin"], float)
    spacing = np.array([header["directions"][a][a] for a in range(3)], float)
    pad_top, pad_anterior = int(round(90 / spacing[2])), int(round(50 / spacing[1]))
    nz, ny, nx = data.shape
    tissue = float(np.median(data[-1]))  # the top slice is tissue only
    big = np.full((nz + pad_top, ny + pad_anterior, nx), tissue, np.float32)
    big[:nz, pad_anterior:, :] = data
    origin[1] -= pad_anterior * spacing[1]
    axes = [origin[a] + np.arange(big.shape[2 - a]) * spacing[a] for a in range(3)]
    z, y, x = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    grid = (x, y, z)
    top = axes[2][-1]
    lumen = (x ** 2 + y ** 2 <= 11 ** 2) & (z >= 200)  # the aorta on to the top border
    lumen |= ((x - 25) / 45) ** 2 + ((y + 42) / 36) ** 2 + ((z - 275) / 40) ** 2 <= 1  # the heart
    lumen |= tube(grid, (25, -48, 275), (-75, -40, 255), 6)  # right pulmonary veins
    lumen |= tube(grid, (25, -48, 275), (77, -40, 255), 6)  # left pulmonary veins
    lumen |= tube(grid, (0, -48, 290), (-20, -45, top + 5), 9)  # superior vena cava
    if with_vena_cava:
        lumen |= tube(grid, (-10, -45, 262), (-28, -8, 200), 11) | tube(grid, (-28, -8, 200), (-28, -8, -140), 11)
    contrast = gaussian_filter(np.where(lumen, 310.0, 0.0), 1.0 / spacing[::-1])  # lumen 350 HU on 40 HU
    noise = np.random.default_rng(noise_seed).normal(0.0, 20.0, big.shape)
    painted = np.where(contrast > 1.0, np.maximum(big, tissue + contrast + noise), big)
    painted = np.clip(np.round(painted), -1024, 3071).astype("<i2")
    lines = ["NRRD0004", "type: short", "dimension: 3", "space: left-posterior-superior",
             "sizes: %d %d %d" % (painted.shape[2], painted.shape[1], painted.shape[0]),
             "space directions: (%r,0,0) (0,%r,0) (0,0,%r)" % tuple(spacing),
             "kinds: domain domain domain", "endian: little", "encoding: raw",
             "space origin: (%r,%r,%r)" % tuple(origin)]
    with open(out_path, "wb") as handle:
        handle.write(("\n".join(lines) + "\n\n").encode() + painted.tobytes())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--phantom", required=True, help="SyntheticAorticPhantom executable")
    parser.add_argument("--cli", required=True, help="StentGraftSimulation executable")
    parser.add_argument("--workdir", required=True, help="scratch directory")
    args = parser.parse_args()
    workdir = os.path.abspath(args.workdir)
    os.makedirs(workdir, exist_ok=True)
    cli = os.path.abspath(args.cli)

    phantom = os.path.join(workdir, "phantom.nrrd")
    truth_path = os.path.join(workdir, "truth.json")
    result = run([os.path.abspath(args.phantom), "--outputTruth", truth_path, phantom], workdir)
    if not check(result.returncode == 0, "the default phantom is generated", result.stderr[:300]):
        return 1
    truth = json.load(open(truth_path))
    coeliac_z = truth["landmarks"]["coeliacOstium"][2]
    seed_at_coeliac = "0,0,%g" % (coeliac_z + 5)  # in the aorta (on its axis, x = y = 0)

    # Whether the skeleton meets in one junction with the shape of a Y depends on the noise: of noise
    # draws 0-7, draws 0, 1, 2, 4 and 6 gave it (named a Y before the plausibility rules; with the
    # seed's window alone, before the window came from the lumen's core, draws 3 and 4), the others
    # a skeleton without one. Since a limb's radius is read past the junction's inscribed sphere
    # (BranchRadius, issue 46 item 9), only draw 2's junction keeps the shape of a Y (draws 0-7 run
    # with that change); on draw 4 the error names the scan's extent and the vessels its border cuts
    # instead. Both kinds are run; each must be one clean error, and draw 2's must name the junction
    # refused.
    for noise_seed, refused in ((2, True), (4, False), (5, False)):
        chest = os.path.join(workdir, "heart-and-venae-cavae.nrrd")
        paint_heart(phantom, chest, with_vena_cava=True, noise_seed=noise_seed)
        ending_at_coeliac = os.path.join(workdir, "ending-at-the-coeliac-%d.nrrd" % noise_seed)
        crop_above(chest, ending_at_coeliac, coeliac_z - 10)
        needles = ["No aortic bifurcation found", "the scan spans z "]
        if refused:
            needles.append("has the shape of a Y, but")
        bad_case(cli, workdir, "ends-at-coeliac-noise-%d-whole-plan" % noise_seed, ending_at_coeliac,
                 ["--seed", seed_at_coeliac, "--outputStentModel", "{outdir}/stent.vtp"], needles)
        if noise_seed == 2:
            bad_case(cli, workdir, "ends-at-coeliac-noise-2-centerlines-only", ending_at_coeliac,
                     ["--seed", seed_at_coeliac, "--outputCenterlines", "{outdir}/centerlines.vtp"], needles)

    # The whole abdomen in view, an arterial phase (no contrast in the vena cava): the real Y.
    heart = os.path.join(workdir, "heart.nrrd")
    paint_heart(phantom, heart, with_vena_cava=False)
    values = {}
    for label, volume in (("plain", phantom), ("heart", heart)):
        outdir = fresh_dir(os.path.join(workdir, "case-" + label))
        result = run_cli(cli, outdir, volume, ["--seed", "0,0,%g" % (coeliac_z + 30)])
        check(result.returncode == 0, f"{label}: a plan (exit 0)", result.stderr.strip()[:400])
        if result.returncode == 0:
            values[label] = sem_rules.read_return_parameters(os.path.join(outdir, "ret.params"))
    if len(values) == 2:
        for name in ("proximalNeckLumenDiameter", "neckLumenDiameter15mm", "maxAneurysmLumenDiameter",
                     "distalNeckMinLumenDiameter", "proximalNeckLength", "proximalSiteToBifurcationLength",
                     "rightIliacLength", "leftIliacLength"):
            plain, with_heart = float(values["plain"][name]), float(values["heart"][name])
            # The same lumen below the renal arteries: each slice's boundary level lies half-way
            # between its own slab's lumen and the tissue around the lumen in that slab (20 mm
            # slabs), so the heart 70 mm above the renals moves nothing below them (measured: at
            # most 0.006 mm, on the site-to-bifurcation length; with one tissue level for the whole
            # lumen it moved the boundary level by 3 HU, the site-to-bifurcation length by 0.53-0.69
            # mm and the iliac lengths by up to 0.6 mm). 0.1 mm: a tenth of the centerline's step.
            tolerance = 0.1
            check(plain > 0 and abs(with_heart - plain) <= tolerance,
                  f"heart in view: {name} as without it (within {tolerance} mm)", f"{with_heart} vs {plain}")

    failed = results.count(False)
    print(f"{len(results) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
