#!/usr/bin/python3
"""Configure the extension's Slicer branch against the stub in SlicerStub/ and check what it did.

Usage: configure_with_slicer_stub.py --cmake CMAKE --source SOURCE_DIR --workdir SCRATCH_DIR

Slicer cannot be installed here, so this is how the Slicer branch of the CMake code is tested:
1. `cmake -S SOURCE -B SCRATCH/build -DSlicer_DIR=SlicerStub` must succeed. The stub's
   SEMMacroBuildCLI, slicerMacroBuildScriptedModule, slicer_add_python_unittest and the
   generate-config and CPack includes stop the configure when a file they are given does not
   exist, a keyword is misspelt or the metadata is missing; any CMake syntax error stops it too.
2. The stub's record must show the whole branch ran: find_package(Slicer), the use file, both
   CLIs, the scripted module with StentGraftPlanner.py, its .ui and icon, the generate-config
   include and then the CPack include.
3. Every file the generated install scripts would install from the source tree exists, and the
   device catalogue Resources/devices.json is installed into the CLI folder (beside the CLI).
4. Planted defects (a missing script, missing metadata) make the stub fail, so the check can fail.
"""
import argparse
import glob
import os
import re
import shutil
import subprocess
import sys

STUB = os.path.join(os.path.dirname(os.path.abspath(__file__)), "SlicerStub")
CLI_DIR = "lib/Slicer-5.8/cli-modules"  # the stub's Slicer_INSTALL_CLIMODULES_BIN_DIR

results = []


def check(what, ok, detail=""):
    results.append(ok)
    print("%s: %s%s" % ("PASS" if ok else "FAIL", what, (" - " + detail) if detail and not ok else ""))


def installedSourceFiles(buildDir, sourceDir):
    """(destination, path) of every file(INSTALL ... FILES ...) in the generated install scripts."""
    found = []
    for script in glob.glob(os.path.join(buildDir, "**", "cmake_install.cmake"), recursive=True):
        with open(script) as f:
            text = f.read()
        for destination, files in re.findall(r'file\(INSTALL DESTINATION "([^"]*)" TYPE \w+[^)]*?FILES ([^)]*)\)', text):
            for path in re.findall(r'"([^"]+)"', files):
                if path.startswith(sourceDir):
                    found.append((destination, path))
    return found


def plantedDefect(cmake, scratch, name, body):
    """Run a small project that includes the stub and does one wrong thing; it must fail to configure."""
    project = os.path.join(scratch, "planted-" + name)
    os.makedirs(project, exist_ok=True)
    with open(os.path.join(project, "CMakeLists.txt"), "w") as f:
        f.write("cmake_minimum_required(VERSION 3.16)\nproject(Planted LANGUAGES NONE)\n" + body)
    run = subprocess.run([cmake, "-S", project, "-B", os.path.join(project, "build"), "-DSlicer_DIR=" + STUB],
                         capture_output=True, text=True)
    return run.returncode != 0 and "Slicer stub:" in run.stderr, run.stderr


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cmake", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    source = os.path.realpath(args.source)
    shutil.rmtree(args.workdir, ignore_errors=True)
    build = os.path.join(args.workdir, "build")
    os.makedirs(build)

    run = subprocess.run([args.cmake, "-S", source, "-B", build, "-DSlicer_DIR=" + STUB,
                          "-DSGP_BUILD_BENCHMARKS=OFF"], capture_output=True, text=True)
    check("the Slicer branch configures (cmake exit code %d)" % run.returncode, run.returncode == 0,
          "\n" + run.stdout[-3000:] + run.stderr[-6000:])
    if run.returncode != 0:
        return

    with open(os.path.join(build, "slicer-stub-record.txt")) as f:
        record = f.read().splitlines()
    print("stub record:\n    " + "\n    ".join(record))

    def index(pattern):
        return next((i for i, line in enumerate(record) if re.search(pattern, line)), -1)

    check("find_package(Slicer) and include(${Slicer_USE_FILE}) ran", index(r"^find_package\(Slicer\)") == 0 and index(r"^include\(Slicer_USE_FILE\) project=StentGraftPlanner$") > 0)
    for cli in ("StentGraftSimulation", "SyntheticAorticPhantom"):
        check("SEMMacroBuildCLI builds %s from its XML" % cli, index(r"^SEMMacroBuildCLI %s XML %s\.xml" % (cli, cli)) > 0)
    module = index(r"^slicerMacroBuildScriptedModule StentGraftPlanner ")
    check("slicerMacroBuildScriptedModule builds StentGraftPlanner", module > 0)
    if module > 0:
        line = record[module]
        for needed in ("StentGraftPlanner.py", "StentGraftPlannerLib/__init__.py", "Resources/UI/StentGraftPlanner.ui",
                       "Resources/Icons/StentGraftPlanner.png"):
            check("  ... with %s" % needed, " %s" % needed in line)
    check("slicer_add_python_unittest runs the module's self-test", index(r"^slicer_add_python_unittest StentGraftPlanner\.py$") > 0)
    generate, cpack = index(r"^include\(Slicer_EXTENSION_GENERATE_CONFIG\)"), index(r"^include\(Slicer_EXTENSION_CPACK\)")
    check("the generate-config include runs after every module", generate > max(module, index(r"^SEMMacroBuildCLI")))
    check("the CPack include runs last", cpack == len(record) - 1 and cpack > generate)

    installed = installedSourceFiles(build, source)
    missing = [path for _, path in installed if not os.path.exists(path)]
    check("the %d source files the install scripts name exist" % len(installed), not missing, ", ".join(missing))
    catalog = [destination for destination, path in installed if path == os.path.join(source, "Resources", "devices.json")]
    check("Resources/devices.json is installed beside the CLIs", any(d.endswith(CLI_DIR) for d in catalog),
          "installed to %s" % catalog)
    check("the devices.json copy for the build tree exists", os.path.exists(os.path.join(build, CLI_DIR, "devices.json")))

    metadata = "".join('set(EXTENSION_%s "https://x")\n' % n for n in ("HOMEPAGE", "CONTRIBUTORS", "DESCRIPTION", "ICONURL", "SCREENSHOTURLS", "DEPENDS"))
    plants = {
        "a missing script": metadata + "find_package(Slicer REQUIRED)\ninclude(${Slicer_USE_FILE})\n"
                            "slicerMacroBuildScriptedModule(NAME Planted SCRIPTS Planted.py)\n",
        "missing EXTENSION_ICONURL": metadata.replace('set(EXTENSION_ICONURL "https://x")\n', "") +
                                     "find_package(Slicer REQUIRED)\ninclude(${Slicer_USE_FILE})\n",
        "CPack without generate-config": metadata + "find_package(Slicer REQUIRED)\ninclude(${Slicer_USE_FILE})\n"
                                         "include(${Slicer_EXTENSION_CPACK})\n",
    }
    for name, body in plants.items():
        rejected, stderr = plantedDefect(args.cmake, args.workdir, re.sub(r"\W+", "-", name), body)
        check("planted defect, %s, stops the configure" % name, rejected, stderr[-1500:])


if __name__ == "__main__":
    main()
    print("%d passed, %d failed" % (results.count(True), results.count(False)))
    sys.exit(0 if results and all(results) else 1)
