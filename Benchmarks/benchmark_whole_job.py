#!/usr/bin/python3
"""The whole planning job, timed against the floor of merely reading its input (issue 5).

Usage: benchmark_whole_job.py BUILD_DIR [--workdir DIR] [--repeat N]

Generates a 512 x 512 x 400 phantom (0.7 x 0.7 x 1.0 mm, vertebra and kidneys, a wall in fat with sac
thrombus; gzip NRRD, as
Slicer and PACS exports write them), then, in the same run and N times each (best kept, so a
busy moment of the machine does not count):
  - the floor: sgpReadVolume, the CLI's own reader, reading and decompressing the file and
    nothing else (a separate process, like the CLI);
  - a plain zlib read (issue 34, item 5): Python's zlib inflating the file's gzip data into a
    numpy array, timed inside the process (interpreter start and imports left out), with glibc's
    malloc asked for huge pages as the job's own large buffers are;
  - the whole job: StentGraftSimulation as Slicer starts it, with every output requested
    (read -> segmentation -> centerlines -> ACM -> outer wall -> measurements -> device selection ->
    simulated graft -> label map, wall label map, outer wall model, centerlines, landmarks, stent
    model, simulated graft, measurements table, diameter profile, report, return file);
and prints a Markdown table: wall times, their ratio against the 3x target, the peak resident
memory of the job against 2 GiB, and the per-stage times from the job's <filter-time> tags.

Then the re-plan (issue 45): the same job from the lumen label map it wrote
(--inputLumenSegmentation), as the panel's Re-plan runs it: its time against the whole job's, and its
SegmentLumen stage (which takes the given lumen: not repeated) against the region growing's.

Then the memory row (issue 11): a 512 x 512 x 1000 phantom (0.7 x 0.7 x 0.5 mm slices, as
whole-aorta CTAs are taken), the whole job once, its peak resident memory against 2 x the
decompressed input (512 * 512 * 1000 * 2 bytes of HU).
And the same on real anatomy (issue 48 item 3): the AVT case D1's manual vessel-tree mask
(../shared/data/avt, or --shared), its 3 mm slices made four times thinner (1,004 slices of 0.75 mm,
the mask interpolated linearly and kept at >= 0.5) and painted as the AVT tests paint it.

With --check, exits 1 when any row misses its target (the CTest label `benchmark` runs it; not
part of scripts/test.sh's default run, since timings are noisy). Timings are asserted nowhere
else; tests check correctness.
"""
import argparse
import os
import platform
import re
import subprocess
import sys
import tempfile
import time

TARGET_RATIO = 3.0
TARGET_ZLIB_RATIO = 1.2  # issue 34 item 5: the whole job <= 1.2 x a plain zlib read of its input
ZLIB_READ = r"""
import sys, time, zlib
import numpy
start = time.monotonic()
raw = open(sys.argv[1], "rb").read()
body = raw.index(b"\n\n") + 2
voxels = numpy.frombuffer(zlib.decompress(raw[body:], 31), dtype="<i2")
print(time.monotonic() - start, voxels.size)
"""
ZLIB_VOXELS = 512 * 512 * 400  # what the zlib read must have inflated (one gzip member: the whole file)
TARGET_MIB = 2048.0
TARGET_INPUT_MULTIPLE = 2.0  # issue 11: peak resident memory <= 2 x the decompressed input


def cpu_name():
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def run_measured(argv, env=None):
    """Runs argv (with env, when given); returns (seconds, peak RSS in MiB, stdout, stderr, exit code)."""
    start = time.monotonic()
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        process = subprocess.Popen(argv, stdout=out, stderr=err, env=env)
        _, status, usage = os.wait4(process.pid, 0)
        seconds = time.monotonic() - start
        out.seek(0)
        err.seek(0)
        return (seconds, usage.ru_maxrss / 1024.0, out.read().decode(), err.read().decode(),
                os.waitstatus_to_exitcode(status))


def best_of(argv, repeat, label, env=None):
    best = None
    for _ in range(repeat):
        result = run_measured(argv, env)
        if result[4] != 0:
            sys.exit(f"{label} failed (exit {result[4]}): {result[3].strip()}")
        if best is None or result[0] < best[0]:
            best = result
    return best


def make_phantom(build, work, name, spacing, size):
    """Writes a gzip-NRRD phantom with bone and kidneys, a 1.5 mm wall in fat, a 12 mm crescent of sac
    thrombus and 14 mm common iliacs (the plan sizes on the outer wall, which needs fat to be seen;
    the iliacs admit a sheath); returns (path, seed RAS text)."""
    phantom = os.path.join(build, "CLI", "SyntheticAorticPhantom")
    volume = os.path.join(work, name + ".nrrd")
    params = os.path.join(work, name + ".params")
    subprocess.run([phantom, "--returnparameterfile", params, "--spacingMm", spacing, "--sizeVoxels", size,
                    "--includeBone", "--includeKidneys", "--wallThicknessMm", "1.5", "--tissueHu", "-100",
                    "--thrombusMaxThicknessMm", "12", "--rightIliacDiameterMm", "14", "--leftIliacDiameterMm", "14",
                    volume], check=True, capture_output=True)
    seed = dict(line.split(" = ", 1) for line in open(params).read().splitlines())["seedRas"]
    return volume, seed


def whole_job_argv(build, work, volume, seed):
    """StentGraftSimulation with every output requested, as Slicer starts it."""
    cli = os.path.join(build, "CLI", "StentGraftSimulation")
    out = lambda name: os.path.join(work, name)  # noqa: E731
    return [cli, "--returnparameterfile", out("run.params"), "--seed", seed,
            "--outputLabelMap", out("lumen.nrrd"), "--outputCenterlines", out("centerlines.vtp"),
            "--outputLandmarks", out("landmarks.mrk.json"), "--outputStentModel", out("stent.vtp"),
            "--outputMeasurements", out("measurements.csv"), "--outputDiameterProfile", out("profile.csv"),
            "--outputReport", out("report.json"), "--outputSimulatedStentModel", out("graft.vtp"),
            "--outputWallLabelMap", out("wall.nrrd"), "--outputOuterWallModel", out("outer-wall.vtp"), volume]


def memory_rows(build, work):
    """The peak-memory row on a 512 x 512 x 1000 phantom against 2 x its decompressed size."""
    os.makedirs(work, exist_ok=True)
    volume, seed = make_phantom(build, work, "phantom-512x1000", "0.7,0.7,0.5", "512,512,1000")
    input_mib = 512 * 512 * 1000 * 2 / 1048576.0
    _, job_mib, _, _, _ = best_of(whole_job_argv(build, work, volume, seed), 1, "StentGraftSimulation")
    os.remove(volume)
    multiple = job_mib / input_mib
    return [("Peak memory of the whole job on 512 x 512 x 1000 (0.7 x 0.7 x 0.5 mm), input %.0f MiB decompressed"
             % input_mib, "%.0f MiB = %.2f x the input" % (job_mib, multiple), "<= %g x" % TARGET_INPUT_MULTIPLE,
             multiple <= TARGET_INPUT_MULTIPLE)]


PAINT_AVT = r"""
import gzip, json, re, sys, zlib
import numpy
mask_path, seeds_path, case, out_path = sys.argv[1:5]
raw = open(mask_path, "rb").read()
head, body = raw.split(b"\n\n", 1)
header = head.decode()
size = [int(v) for v in re.search(r"^sizes: (.*)$", header, re.M).group(1).split()]
directions = [[float(c) for c in v.split(",")] for v in re.findall(r"\(([^)]*)\)", re.search(
    r"^space directions: (.*)$", header, re.M).group(1))]
origin = [float(c) for c in re.search(r"^space origin: \((.*)\)$", header, re.M).group(1).split(",")]
mask = numpy.frombuffer(zlib.decompress(body, 31), dtype=numpy.uint8).reshape(size[2], size[1], size[0]) > 0
# Slices four times thinner: the mask interpolated linearly between its slices, kept where >= 0.5.
factor = 4
k = (numpy.arange(size[2] * factor) + 0.5) / factor - 0.5
k0 = numpy.clip(numpy.floor(k).astype(int), 0, size[2] - 1)
k1 = numpy.clip(k0 + 1, 0, size[2] - 1)
t = numpy.clip(k - k0, 0.0, 1.0).astype(numpy.float32)
fine = numpy.empty((len(k), size[1], size[0]), dtype=bool)
for n in range(len(k)):
    fine[n] = (1.0 - t[n]) * mask[k0[n]] + t[n] * mask[k1[n]] >= 0.5
del mask
slices = fine.shape[0]
# Painted as the AVT tests paint (Testing/Anatomy/AvtSupport.h): lumen 400 HU at the top of the
# scan falling to 300 HU at its bottom, tissue 40 HU, noise sigma 15 HU.
zs = origin[2] + directions[2][2] / factor * (numpy.arange(slices) - (factor - 1) / 2.0)
lumen = 300.0 + 100.0 * (zs - zs.min()) / (zs.max() - zs.min())
rng = numpy.random.default_rng(5)
ct = numpy.empty(fine.shape, dtype="<i2")
for n in range(slices):
    ct[n] = numpy.rint(numpy.where(fine[n], lumen[n], 40.0) +
                       rng.standard_normal(fine[n].shape, dtype=numpy.float32) * 15.0)
del fine
step = [directions[0], directions[1], [c / factor for c in directions[2]]]
first = [origin[a] - (factor - 1) / 2.0 * step[2][a] for a in range(3)]
out = ("NRRD0004\ntype: short\ndimension: 3\nspace: left-posterior-superior\nsizes: %d %d %d\n"
       "space directions: %s\nkinds: domain domain domain\nendian: little\nencoding: gzip\n"
       "space origin: (%r,%r,%r)\n\n" % (size[0], size[1], slices,
       " ".join("(%r,%r,%r)" % tuple(v) for v in step), *first))
with open(out_path, "wb") as f:
    f.write(out.encode())
    f.write(gzip.compress(ct.tobytes(), compresslevel=1))
seed = json.load(open(seeds_path))[case]["seed_ijk"]
ijk = [seed[0], seed[1], seed[2] * factor + (factor - 1) / 2.0]
lps = [first[a] + sum(step[b][a] * ijk[b] for b in range(3)) for a in range(3)]
print("%d %r,%r,%r" % (slices, -lps[0], -lps[1], lps[2]))
"""
REAL_CASE = "D1"  # the AVT case painted at 0.75 mm: 512 x 666 x 1004


def real_anatomy_memory_row(build, work, shared=None):
    """The peak-memory row on a real vessel tree (AVT D1's mask, its 3 mm slices made four times
    thinner, painted as the AVT tests paint) against 2 x its decompressed size. `shared`: the
    folder holding data/avt (default: ../shared beside the clone)."""
    os.makedirs(work, exist_ok=True)
    shared = shared or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared")
    avt = os.path.join(shared, "data", "avt")
    volume = os.path.join(work, "avt-%s-fine.nrrd" % REAL_CASE)
    painted = subprocess.run([sys.executable, "-c", PAINT_AVT, os.path.join(avt, "avt_dongyang_%s.seg.nrrd" % REAL_CASE),
                              os.path.join(avt, "seeds.json"), REAL_CASE, volume],
                             check=True, capture_output=True, text=True).stdout.split()
    slices, seed = int(painted[0]), painted[1]
    input_mib = 512 * 666 * slices * 2 / 1048576.0
    job_mib = best_of(whole_job_argv(build, work, volume, seed), 1, "StentGraftSimulation")[1]
    os.remove(volume)
    multiple = job_mib / input_mib
    return [("Peak memory of the whole job on AVT %s's real vessel tree painted at 512 x 666 x %d (0.71 x 0.71 x "
             "0.75 mm), input %.0f MiB decompressed" % (REAL_CASE, slices, input_mib),
             "%.0f MiB = %.2f x the input" % (job_mib, multiple), "<= %g x" % TARGET_INPUT_MULTIPLE,
             multiple <= TARGET_INPUT_MULTIPLE)]


def whole_job_rows(build, work, repeat=3):
    """[(measurement, result, target, met)] for the table in docs/development.md."""
    os.makedirs(work, exist_ok=True)
    reader = os.path.join(build, "Benchmarks", "sgpReadVolume")
    volume, seed = make_phantom(build, work, "phantom-512", "0.7,0.7,1.0", "512,512,400")
    job = whole_job_argv(build, work, volume, seed)
    floor_s = best_of([reader, volume], repeat, "sgpReadVolume")[0]
    # The reference gets huge pages as the job's buffers do (Common/HugePages.h): glibc's malloc
    # advises its large blocks with this tunable. Without it, on a virtual machine whose 4 KiB page
    # faults are dear, numpy's 200 MiB array costs the reference more than the inflation itself
    # (2.35 s against 0.67 s here, 2026-12-06) and the ratio would flatter the job.
    huge = dict(os.environ, GLIBC_TUNABLES="glibc.malloc.hugetlb=1")
    zlib_runs = [best_of([sys.executable, "-c", ZLIB_READ, volume], 1, "zlib read", huge)[2].split()
                 for _ in range(repeat)]
    if any(int(run[1]) != ZLIB_VOXELS for run in zlib_runs):
        sys.exit("the zlib read inflated %s voxels, not %d" % (zlib_runs[0][1], ZLIB_VOXELS))
    zlib_s = min(float(run[0]) for run in zlib_runs)
    job_s, job_mib, stdout, _, _ = best_of(job, repeat, "StentGraftSimulation")
    ratio = job_s / floor_s
    rows = [("Reading floor: sgpReadVolume, gzip NRRD 512 x 512 x 400 (best of %d)" % repeat, "%.2f s" % floor_s, "",
             None),
            ("Plain zlib read: Python's zlib inflating the same file into numpy, in-process, huge pages (best of %d)"
             % repeat,
             "%.2f s" % zlib_s, "", None),
            ("Whole job against the plain zlib read (issue 34)", "%.2f x" % (job_s / zlib_s),
             "<= %g x" % TARGET_ZLIB_RATIO, job_s / zlib_s <= TARGET_ZLIB_RATIO),
            ("Whole job: StentGraftSimulation, read -> segment -> centerlines -> ACM -> outer wall -> measurements -> "
             "device -> "
             "simulated graft -> all outputs "
             "(best of %d)" % repeat, "%.2f s = %.2f x the floor" % (job_s, ratio), "<= %g x" % TARGET_RATIO,
             ratio <= TARGET_RATIO),
            ("Peak memory of the whole job", "%.0f MiB" % job_mib, "< %.0f MiB" % TARGET_MIB, job_mib < TARGET_MIB)]
    stages = stage_times(stdout)
    for name, seconds in stages.items():
        rows.append(("  stage %s" % name, "%.2f s" % seconds, "", None))
    return rows + replan_rows(job, work, repeat, job_s, stages)


def stage_times(stdout):
    """{stage: seconds} from the job's <filter-time> tags, in their order."""
    found = re.findall(r"<filter-end>\s*<filter-name>([^<]*)</filter-name>\s*<filter-time>([^<]*)</filter-time>",
                       stdout)
    return {name: float(seconds) for name, seconds in found}


def replan_rows(job, work, repeat, job_s, job_stages):
    """Issue 45: the re-plan the panel runs after the surgeon moves a landmark — the same job from the
    lumen label map the first run wrote (--inputLumenSegmentation; the CT still read for the outer
    wall) — against the whole job: what the region growing costs, that the re-plan does not repeat
    it (its SegmentLumen stage takes the given lumen: the stage's own text says so), and that the
    re-plan is the faster."""
    given = os.path.join(work, "given-lumen.nrrd")
    os.replace(os.path.join(work, "lumen.nrrd"), given)
    replan_s, replan_mib, stdout, _, _ = best_of(job[:-1] + ["--inputLumenSegmentation", given, job[-1]], repeat,
                                                 "StentGraftSimulation re-plan")
    stages = stage_times(stdout)
    grow, take = job_stages.get("SegmentLumen", float("nan")), stages.get("SegmentLumen", float("nan"))
    taken = ("Taking the lumen from the segmentation given" in stdout
             and "Segmenting the aortic lumen by region growing" not in stdout)
    return [("Re-plan from the first run's lumen label map (issue 45; best of %d)" % repeat,
             "%.2f s (whole job %.2f s: %.2f s saved)" % (replan_s, job_s, job_s - replan_s), "< the whole job",
             replan_s < job_s),
            ("  the region growing (the whole job's SegmentLumen) against the re-plan's SegmentLumen (the given "
             "lumen's checks, pieces and window; no growing)",
             "%.2f s against %.2f s%s" % (grow, take, "" if taken else "; the re-plan grew the lumen"),
             "not repeated", taken),
            ("  the re-plan's ReadVolume (the CT and the lumen label map) against the whole job's",
             "%.2f s against %.2f s" % (stages.get("ReadVolume", float("nan")), job_stages.get("ReadVolume", float("nan"))),
             "", None),
            ("  its peak memory", "%.0f MiB" % replan_mib, "< %.0f MiB" % TARGET_MIB, replan_mib < TARGET_MIB)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build")
    parser.add_argument("--workdir", default=None)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--shared", default=None, help="the shared folder with data/avt (default: ../shared)")
    parser.add_argument("--check", action="store_true", help="exit 1 when a row misses its target")
    args = parser.parse_args()
    work = args.workdir or tempfile.mkdtemp(prefix="sgp-whole-job-")
    os.makedirs(work, exist_ok=True)
    build = os.path.abspath(args.build)
    rows = (whole_job_rows(build, work, args.repeat) + memory_rows(build, os.path.join(work, "memory")) +
            real_anatomy_memory_row(build, os.path.join(work, "memory-avt"), args.shared))
    print("Machine: %s, %d cores, %s" % (cpu_name(), os.cpu_count(), platform.platform()))
    print()
    print("| measurement | result | target | met |")
    print("| --- | --- | --- | --- |")
    for what, value, target, met in rows:
        print("| %s | %s | %s | %s |" % (what, value, target, "" if met is None else ("yes" if met else "NO")))
    missed = [what for what, _, _, met in rows if met is False]
    if args.check:
        print("%d passed, %d failed" % (sum(1 for row in rows if row[3] is True), len(missed)))
        if missed:
            sys.exit(1)


if __name__ == "__main__":
    main()
