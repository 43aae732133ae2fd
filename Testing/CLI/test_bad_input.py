#!/usr/bin/python3
"""StentGraftSimulation rejects bad input cleanly: one ERROR line, no output left.

Usage: test_bad_input.py --phantom PHANTOM_EXE --cli SGS_EXE --workdir DIR

Slicer reads nothing but the exit code and shows stderr to the user
(slicer-conventions.md 2.2; STYLE.md B5). So for each bad input this proves
that the CLI
- exits with a non-zero code (and does not crash),
- prints exactly one stderr line, starting with "ERROR: ",
- names the offending value in it,
- leaves its output folder empty: no partial label map, no temporary file,
  no return-parameter file.
The cases: missing input file, unreadable file, a 2-D image, a seed outside
the image, a seed in soft tissue, an inverted manual HU window, no seed, a
non-numeric seed and one of two numbers, a stent mesh whose rings are not a multiple of 4, two
stent diameters where three are needed, a scan that stops above the
aortic bifurcation with centerlines requested (no Y may be made up), a post-EVAR scan (an
endograft's struts in the aorta, with and without a seed), a device
catalogue with a missing field and with a wrongly typed one, an unknown
--device, an inverted oversizing range, and a lowest-renal point far from the
aorta. A positive control through the same harness (valid input
exits 0 and leaves lumen.nrrd and ret.params) shows the harness can tell
success from failure. Prints one line per check and `N passed, M failed`;
exits 1 on any failure.
"""

import argparse
import json
import os
import random
import shutil
import struct
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sem_rules  # noqa: E402

TIMEOUT_S = 600  # small phantom; generous for the 2-core test machine
results = []


def check(ok, what, detail=""):
    results.append(bool(ok))
    print(f"{'PASS' if ok else 'FAIL'}: {what}" + (f" -- {detail}" if detail and not ok else ""))
    return ok


def run(argv, cwd):
    try:
        result = subprocess.run(argv, capture_output=True, timeout=TIMEOUT_S, cwd=cwd,
                                env=dict(os.environ, ITK_AUTOLOAD_PATH=""))
    except subprocess.TimeoutExpired as expired:
        result = subprocess.CompletedProcess(argv, None, expired.stdout or b"", expired.stderr or b"")
    result.stdout = result.stdout.decode("utf-8", errors="replace")
    result.stderr = result.stderr.decode("utf-8", errors="replace")
    return result


def make_small_phantom(exe, workdir):
    """A small valid phantom; returns (volume path, seed RAS, truth label path)."""
    paths = {name: os.path.join(workdir, name)
             for name in ("small.nrrd", "small-truth.json", "small-label.nrrd", "small.params")}
    argv = [exe, "--returnparameterfile", paths["small.params"], "--spacingMm", "1.5,1.5,2",
            "--outputTruth", paths["small-truth.json"],
            "--outputTruthLabelMap", paths["small-label.nrrd"], paths["small.nrrd"]]
    print(f"RUN: {' '.join(argv)}")
    result = run(argv, workdir)
    check(result.returncode == 0, "small phantom is generated (exit 0)",
          f"exit code {result.returncode}; stderr: {result.stderr.strip()[:500]}")
    seed = None
    if os.path.isfile(paths["small.params"]):
        try:
            seed = [float(v) for v in
                    sem_rules.read_return_parameters(paths["small.params"])["seedRas"].split(",")]
        except (KeyError, ValueError):
            seed = None
    check(seed is not None and len(seed) == 3, "small phantom returns seedRas as x,y,z")
    return paths["small.nrrd"], seed, paths["small-label.nrrd"]


def tissue_seed(seed_ras, label_path):
    """A RAS point in soft tissue (truth label 0) near the lumen seed.

    Tries 80 mm anterior of the seed first, then other offsets, and uses the
    first one inside the image whose truth label is 0.
    """
    offsets = [(0, 80, 0), (0, 60, 0), (0, 40, 0), (60, 0, 0), (-60, 0, 0)]
    try:
        labels, header = sem_rules.read_nrrd(label_path)
        axes = np.array(header["directions"], dtype=float).T  # columns: i, j, k steps in LPS mm
        origin = np.array(header["origin"], dtype=float)
    except (OSError, ValueError, KeyError, TypeError) as error:
        print(f"NOTE: cannot read the truth label map ({error}); using 80 mm anterior unchecked")
        return [seed_ras[0], seed_ras[1] + 80, seed_ras[2]]
    for offset in offsets:
        ras = np.add(seed_ras, offset)
        lps = np.array([-ras[0], -ras[1], ras[2]])
        ijk = np.rint(np.linalg.solve(axes, lps - origin)).astype(int)
        inside = all(0 <= ijk[a] < header["sizes"][a] for a in range(3))
        if inside and labels[ijk[2], ijk[1], ijk[0]] == 0:
            print(f"NOTE: soft-tissue seed RAS {ras.tolist()} (seed + {offset} mm), truth label 0")
            return ras.tolist()
    print("NOTE: no candidate soft-tissue point had truth label 0; using 80 mm anterior")
    return [seed_ras[0], seed_ras[1] + 80, seed_ras[2]]


def fresh_dir(path):
    if os.path.exists(path):
        shutil.rmtree(path)
    os.makedirs(path)
    return path


def non_contrast(volume_path, out_path):
    """The volume with every voxel above 100 HU (the contrast-filled lumen and its blurred edge)
    set to 45 HU, unenhanced blood, written as raw NRRD on the same grid."""
    data, header = sem_rules.read_nrrd(volume_path)
    data = np.where(data > 100, 45, data).astype("<i2")
    lines = ["NRRD0004", "type: short", "dimension: 3", "space: left-posterior-superior",
             "sizes: %d %d %d" % (data.shape[2], data.shape[1], data.shape[0]),
             "space directions: " + " ".join("(%r,%r,%r)" % tuple(d) for d in np.array(header["directions"], float)),
             "kinds: domain domain domain", "endian: little", "encoding: raw",
             "space origin: (%r,%r,%r)" % tuple(np.array(header["origin"], float))]
    with open(out_path, "wb") as handle:
        handle.write(("\n".join(lines) + "\n\n").encode())
        handle.write(np.ascontiguousarray(data).tobytes())


def with_endograft(volume_path, truth_path, out_path, strut_hu=2500):
    """The volume with a stent graft's Z-stent rings in the aorta (a post-EVAR scan): rings 10 mm
    high, 4 mm apart, 8 apices, on a cylinder 0.5 mm inside the neck's lumen around the truth's
    aortic axis, from 2 mm above the lowest renal ostium down to the bifurcation; each wire sample
    sets its nearest voxel to at least strut_hu. Written as raw NRRD on the same grid."""
    data, header = sem_rules.read_nrrd(volume_path)
    data = data.astype("<i2")
    truth = json.load(open(truth_path))
    origin, directions = np.array(header["origin"], float), np.array(header["directions"], float)
    inverse = np.linalg.inv(directions.T)  # LPS offset -> (i, j, k)
    axis = np.array(next(v for v in truth["vessels"] if v["name"] == "aorta")["points"], float)
    radius = truth["sizing"]["proximalNeckDiameter"] / 2.0 - 0.5
    top = truth["landmarks"]["rightRenalOstium"][2] + 2.0
    bottom = truth["landmarks"]["aorticBifurcation"][2]
    t = np.arange(0.0, 1.0, 0.0002)
    phase = np.mod(8.0 * t, 1.0)
    ring_top = top
    while ring_top - 10.0 >= bottom:
        z = ring_top - 10.0 * np.where(phase < 0.5, 2.0 * phase, 2.0 - 2.0 * phase)
        centre = axis[np.abs(axis[:, 2][None, :] - z[:, None]).argmin(axis=1)]
        points = np.stack([centre[:, 0] + radius * np.cos(2 * np.pi * t),
                           centre[:, 1] + radius * np.sin(2 * np.pi * t), z], axis=1)
        ijk = np.rint((points - origin) @ inverse.T).astype(int)
        ok = np.all((ijk >= 0) & (ijk < np.array(data.shape[::-1])), axis=1)
        i, j, k = ijk[ok].T
        data[k, j, i] = np.maximum(data[k, j, i], strut_hu)
        ring_top -= 14.0
    lines = ["NRRD0004", "type: short", "dimension: 3", "space: left-posterior-superior",
             "sizes: %d %d %d" % (data.shape[2], data.shape[1], data.shape[0]),
             "space directions: " + " ".join("(%r,%r,%r)" % tuple(d) for d in directions),
             "kinds: domain domain domain", "endian: little", "encoding: raw",
             "space origin: (%r,%r,%r)" % tuple(origin)]
    with open(out_path, "wb") as handle:
        handle.write(("\n".join(lines) + "\n\n").encode())
        handle.write(np.ascontiguousarray(data).tobytes())
    return out_path


def crop_above(volume_path, out_path, z_min_lps):
    """Writes the slices of an axis-aligned volume whose LPS z is at least z_min_lps."""
    data, header = sem_rules.read_nrrd(volume_path)
    origin, directions = np.array(header["origin"], float), np.array(header["directions"], float)
    z = origin[2] + np.arange(data.shape[0]) * directions[2][2]
    keep = np.nonzero(z >= z_min_lps)[0]
    first = int(keep[0])
    new_origin = origin + first * directions[2]
    lines = ["NRRD0004", "type: short", "dimension: 3", "space: left-posterior-superior",
             "sizes: %d %d %d" % (data.shape[2], data.shape[1], len(keep)),
             "space directions: " + " ".join("(%r,%r,%r)" % tuple(d) for d in directions),
             "kinds: domain domain domain", "endian: little", "encoding: raw",
             "space origin: (%r,%r,%r)" % tuple(new_origin)]
    with open(out_path, "wb") as handle:
        handle.write(("\n".join(lines) + "\n\n").encode())
        handle.write(np.ascontiguousarray(data[first:first + len(keep)], dtype="<i2").tobytes())
    return out_path


def seed_text(ras):
    return ",".join("%g" % v for v in ras)


def run_cli(cli, outdir, input_path, extra):
    """The CLI with Slicer's argument order: return file, flags, outputs, positional input."""
    extra = [a.replace("{outdir}", outdir) for a in extra]  # outputs requested inside the case folder
    argv = [cli, "--returnparameterfile", os.path.join(outdir, "ret.params"), *extra,
            "--outputLabelMap", os.path.join(outdir, "lumen.nrrd"), input_path]
    print(f"RUN: {' '.join(argv)}")
    return run(argv, outdir)


def bad_case(cli, workdir, label, input_path, extra, needles, ignore_case=False):
    outdir = fresh_dir(os.path.join(workdir, "case-" + label))
    result = run_cli(cli, outdir, input_path, extra)
    stderr = result.stderr.strip()
    check(result.returncode is not None and result.returncode > 0,
          f"{label}: exits with a non-zero code (not a crash or a hang)",
          f"exit code {result.returncode}")
    lines = stderr.splitlines()
    check(len(lines) == 1 and lines[0].startswith("ERROR: "),
          f"{label}: stderr is exactly one line starting with 'ERROR: '", repr(stderr[:600]))
    print(f"NOTE: {label}: stderr: {stderr[:300]}")
    haystack = stderr.lower() if ignore_case else stderr
    for needle in needles:
        wanted = needle.lower() if ignore_case else needle
        check(wanted in haystack, f"{label}: the message names {needle!r}")
    left = sorted(os.listdir(outdir))
    check(not left, f"{label}: leaves the output folder empty", str(left))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--phantom", required=True, help="SyntheticAorticPhantom executable")
    parser.add_argument("--cli", required=True, help="StentGraftSimulation executable")
    parser.add_argument("--workdir", required=True, help="scratch directory")
    args = parser.parse_args()
    workdir = os.path.abspath(args.workdir)
    os.makedirs(workdir, exist_ok=True)
    cli = os.path.abspath(args.cli)

    volume, seed, label_path = make_small_phantom(os.path.abspath(args.phantom), workdir)
    if seed is None:
        seed = [0.0, 0.0, 0.0]
        print("NOTE: no phantom seed; cases needing a valid seed use 0,0,0")
    valid_seed = ["--seed", seed_text(seed)]

    # Positive control: the same harness must see success as success.
    outdir = fresh_dir(os.path.join(workdir, "case-positive-control"))
    result = run_cli(cli, outdir, volume, valid_seed)
    check(result.returncode == 0, "positive control: valid input exits 0",
          f"exit code {result.returncode}; stderr: {result.stderr.strip()[:500]}")
    left = sorted(os.listdir(outdir))
    check("lumen.nrrd" in left and "ret.params" in left,
          "positive control: leaves lumen.nrrd and ret.params", str(left))
    check(set(left) <= {"lumen.nrrd", "ret.params"},
          "positive control: leaves no other (temporary) file", str(left))

    missing = os.path.join(workdir, "does-not-exist.nrrd")
    if os.path.exists(missing):
        os.remove(missing)
    bad_case(cli, workdir, "missing-file", missing, valid_seed, [missing])

    garbage = os.path.join(workdir, "garbage.nrrd")
    with open(garbage, "wb") as handle:
        handle.write(bytes(random.Random(0).getrandbits(8) for _ in range(4096)))
    bad_case(cli, workdir, "unreadable-file", garbage, valid_seed, [garbage])

    # Headers that ITK's bundled readers complain about on stderr themselves (NIfTI: "** ERROR:
    # nifti_convert_nhdr2nim: bad datatype"; MetaIO: "MetaImage: Read: Cannot parse file"): still
    # exactly one line, ours (the reader fuzz test found the extra lines).
    nifti = os.path.join(workdir, "bad-datatype.nii")
    header = bytearray(352)
    struct.pack_into("<i", header, 0, 348)                              # sizeof_hdr
    struct.pack_into("<8h", header, 40, 3, 8, 8, 8, 1, 1, 1, 1)          # dim
    struct.pack_into("<hh", header, 70, 9999, 16)                       # datatype (none such), bitpix
    struct.pack_into("<8f", header, 76, 1, 1, 1, 1, 1, 1, 1, 1)          # pixdim
    struct.pack_into("<f", header, 108, 352.0)                          # vox_offset
    header[344:348] = b"n+1\0"
    with open(nifti, "wb") as handle:
        handle.write(bytes(header) + bytes(8 * 8 * 8 * 2))
    bad_case(cli, workdir, "nifti-bad-datatype", nifti, valid_seed, [nifti])
    meta = os.path.join(workdir, "no-dimsize.mha")
    with open(meta, "wb") as handle:
        handle.write(b"ObjectType = Image\nNDims = 3\nElementType = MET_SHORT\nElementDataFile = LOCAL\n")
        handle.write(bytes(64))
    bad_case(cli, workdir, "metaimage-without-dimsize", meta, valid_seed, [meta])

    flat = os.path.join(workdir, "flat-2d.nrrd")
    with open(flat, "wb") as handle:
        handle.write(b"NRRD0004\ntype: short\ndimension: 2\nsizes: 32 32\nspacings: 1 1\n"
                     b"encoding: raw\nendian: little\n\n")
        handle.write(np.full((32, 32), 300, dtype="<i2").tobytes())  # lumen-like HU
    bad_case(cli, workdir, "2d-image", flat, ["--seed", "16,16,0"], ["2-D"])

    bad_case(cli, workdir, "seed-outside", volume, ["--seed", "5000,5000,5000"], ["5000"])

    soft = tissue_seed(seed, label_path)
    bad_case(cli, workdir, "seed-in-tissue", volume, ["--seed", seed_text(soft)], ["HU"])

    bad_case(cli, workdir, "inverted-window", volume,
             valid_seed + ["--thresholdMode", "manual", "--lowerHu", "600", "--upperHu", "200"],
             ["600", "200"])

    # No seed: the CLI looks for the aorta itself (issue 16); on a scan without contrast (the lumen
    # at 45 HU, unenhanced blood) that is one ERROR saying what was looked for.
    plain = os.path.join(workdir, "non-contrast.nrrd")
    non_contrast(volume, plain)
    bad_case(cli, workdir, "no-seed-no-contrast", plain, [], ["No aorta found", "150 HU", "--seed"])

    # A post-EVAR scan (issue 33 item 8): an endograft's struts in the aorta's lumen. One ERROR
    # that says what it is, with or without a seed, instead of "No aortic bifurcation found".
    stented = with_endograft(volume, os.path.join(workdir, "small-truth.json"),
                             os.path.join(workdir, "post-evar.nrrd"))
    for label, extra in (("post-evar", valid_seed), ("post-evar-no-seed", [])):
        bad_case(cli, workdir, label, stented, extra + ["--outputCenterlines", "{outdir}/centerlines.vtp"],
                 ["endograft or another metal device is already in place", "pre-operative"])

    # Holds in both builds: inside Slicer SEM's GenerateCLP reads the components with atof (a,b,c
    # would be the origin), so the CLI checks the text of its points itself (ValidatePointArguments;
    # tested against SEM's parsing by extension.SlicerConfigure).
    bad_case(cli, workdir, "seed-not-numeric", volume, ["--seed", "a,b,c"], ["a,b,c"])
    bad_case(cli, workdir, "seed-two-numbers", volume, ["--seed", "1,2"], ["1,2"])

    # Stent-surface parameters are checked before anything is read.
    bad_case(cli, workdir, "vertices-per-ring", volume, valid_seed + ["--verticesPerRing", "18"],
             ["verticesPerRing", "18"])
    bad_case(cli, workdir, "stent-diameters", volume,
             valid_seed + ["--acmMode", "simulate", "--stentDiametersMm", "24,12"], ["stentDiametersMm", "three"])

    # A scan that stops above the aortic bifurcation: the lumen is fine, but there is no Y to
    # label, and the run must say so rather than make one up, and leave no output at all.
    cropped = crop_above(volume, os.path.join(workdir, "above-bifurcation.nrrd"), z_min_lps=15.0)
    bad_case(cli, workdir, "no-bifurcation", cropped,
             valid_seed + ["--outputCenterlines", "{outdir}/centerlines.vtp",
                           "--outputLandmarks", "{outdir}/landmarks.mrk.json"],
             ["No aortic bifurcation", "end points"])

    # The device catalogue and selection (issue 6): checked before the image is processed, each
    # error naming the file, the entry and the field, or the flag and its value.
    catalogue = os.path.join(os.path.dirname(cli), "devices.json")  # installed beside the CLI
    if check(os.path.isfile(catalogue), "the default device catalogue sits beside the CLI", catalogue):
        with open(catalogue, encoding="utf-8") as handle:
            entries = json.load(handle)
        del entries["families"][1]["ifu"]["neckDiameterMm"]["max"]
        broken = os.path.join(workdir, "broken-devices.json")
        with open(broken, "w", encoding="utf-8") as handle:
            json.dump(entries, handle)
        measure = ["--outputMeasurements", "{outdir}/measurements.csv"]
        family = entries["families"][1]["name"]
        bad_case(cli, workdir, "catalogue-missing-field", volume, valid_seed + measure + ["--deviceCatalog", broken],
                 [broken, family, "ifu.neckDiameterMm.max", "missing"])
        entries["families"][1]["ifu"]["neckDiameterMm"]["max"] = "thirty-two"
        with open(broken, "w", encoding="utf-8") as handle:
            json.dump(entries, handle)
        bad_case(cli, workdir, "catalogue-wrong-type", volume, valid_seed + measure + ["--deviceCatalog", broken],
                 [broken, family, "ifu.neckDiameterMm.max", "thirty-two"])
        # The component defects issue 29 names: each one ERROR: line naming file, family,
        # component and field, and no output left behind.
        planted = [
            ("catalogue-negative-length", lambda e: e["families"][0]["limbs"]["items"][2].update(lengthMm=-124),
             ["limbs.items[2]", "lengthMm", "-124 mm"]),
            ("catalogue-gate-beyond-body", lambda e: e["families"][0]["mainBodies"]["items"][0].update(gateEndMm=130),
             ["mainBodies.items[0]", "gateEndMm", "beyond the body's covered length"]),
            ("catalogue-overlap-above-gate", lambda e: e["families"][0]["junctions"]["overlapMm"].update(min=40),
             ["junctions.overlapMm.min", "40 mm, longer than the 34 mm contralateral gate", "mainBodies.items[0]"]),
            ("catalogue-missing-code", lambda e: e["families"][2]["limbs"]["items"][4].pop("code"),
             ["limbs.items[4]", "'code'", "is missing"]),
        ]
        for name, plant, parts in planted:
            with open(catalogue, encoding="utf-8") as handle:
                entries = json.load(handle)
            plant(entries)
            with open(broken, "w", encoding="utf-8") as handle:
                json.dump(entries, handle)
            family = entries["families"][2 if "missing-code" in name else 0]["name"]
            bad_case(cli, workdir, name, volume, valid_seed + measure + ["--deviceCatalog", broken],
                     [broken, family, "component"] + parts)
        bad_case(cli, workdir, "unknown-device", volume, valid_seed + measure + ["--device", "NoSuchGraft"],
                 ["NoSuchGraft", catalogue])
        bad_case(cli, workdir, "inverted-oversizing", volume,
                 valid_seed + measure + ["--proximalOversizingRange", "20,10"], ["proximalOversizingRange", "20.0,10.0"])
    # The hostile-neck rules (issue 12): read before the image is processed; a planted defect
    # names the file, the rule and the field, and no output is left behind.
    rules_path = os.path.join(os.path.dirname(cli), "hostile-neck-rules.json")  # installed beside the CLI
    if check(os.path.isfile(rules_path), "the default hostile-neck rules sit beside the CLI", rules_path):
        with open(rules_path, encoding="utf-8") as handle:
            rules = json.load(handle)
        rule_id = rules["rules"][2]["id"]
        rules["rules"][2]["threshold"] = "sixty"
        broken_rules = os.path.join(workdir, "broken-neck-rules.json")
        with open(broken_rules, "w", encoding="utf-8") as handle:
            json.dump(rules, handle)
        bad_case(cli, workdir, "neck-rules-wrong-type", volume,
                 valid_seed + ["--outputMeasurements", "{outdir}/measurements.csv", "--neckRules", broken_rules],
                 [broken_rules, rule_id, "threshold"])
    # A lowest-renal point far from the aorta cannot be on its wall.
    bad_case(cli, workdir, "renal-point-off-the-aorta", volume,
             valid_seed + ["--outputMeasurements", "{outdir}/measurements.csv", "--lowestRenalOstium", "90,0,60"],
             ["lowestRenalOstium", "(90.0, 0.0, 60.0) mm RAS", "from the aortic centerline"])

    passed = sum(results)
    failed = len(results) - passed
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
