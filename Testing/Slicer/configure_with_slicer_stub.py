#!/usr/bin/python3
"""Configure and build the extension's Slicer branch against the stub in SlicerStub/, and check it.

Usage: configure_with_slicer_stub.py --cmake CMAKE --source SOURCE_DIR --workdir SCRATCH_DIR
           [--generator GEN] [--jobs N] [--lock FILE] [--standalone-build BUILD_DIR]

Slicer cannot be installed here, so this is how the Slicer branch of the CMake code is tested:
1. `cmake -S SOURCE -B SCRATCH/build -DSlicer_DIR=SlicerStub` must succeed with what Slicer does
   not ship hidden: no nlohmann JSON, GoogleTest or Google Benchmark package may be looked for
   (CMAKE_DISABLE_FIND_PACKAGE_*), and nothing may be found in /usr/include (CMAKE_IGNORE_PATH:
   no system tclap/CmdLine.h). nlohmann JSON must come from the FetchContent declaration (URL and
   SHA-256 pinned); this machine cannot download, so the configure runs FETCHCONTENT_FULLY_DISCONNECTED
   with FETCHCONTENT_SOURCE_DIR_NLOHMANN_JSON pointing at a stand-in for the unpacked release
   archive (its include/nlohmann is a link to Debian's headers). TCLAP must be SEM's (the stub's
   TCLAP_DIR) and Python Slicer's (the stub's PythonSlicer).
2. The stub's record must show the whole branch ran: find_package(Slicer), the use file, both
   CLIs built as SEM builds them (SHARED <Name>Lib), the scripted module with its files, the
   generate-config include and then the CPack include.
3. Every file the generated install scripts would install from the source tree exists, and the
   device catalogue Resources/devices.json is installed into the CLI folder (beside the CLI).
4. The build a Slicer extension build makes (the default target) succeeds; both CLIs are built as SEM builds them, with the real compiler and linker: a SHARED
   <Name>Lib holding the module and the project's static libraries (which must be position
   independent) and a launcher that calls its ModuleEntryPoint. UseITK registers no ImageIO
   factory in this build (the stub's UseSlicer sets ITK_NO_IO_FACTORY_REGISTER_MANAGER, as Slicer
   does) and the stub's launcher registers none either (Slicer's does), so the runs below read and
   write only through the project's own registration. The stub's GenerateCLP parses points with
   atof, as SEM's does.
5. The built CLIs run: --xml; the phantom CLI writes a volume; StentGraftSimulation plans on it
   (exit 0, its outputs written, the catalogue found beside it); `--seed a,b,c` and `--seed 1,2` are
   rejected with one ERROR line by the CLI's own check; a seed outside the volume is reported
   after the volume was read.
   Issue 33: <Name>.xml is copied beside each launcher (equal to its --xml) and installed there;
   an unknown flag or enumeration value is TCLAP's `PARSE ERROR:` with the usage (SEM leaves
   TCLAP's exception handling on); the generated header includes ModuleProcessInformation.h and
   defines its symbols out of line, so two CLP headers in one binary do not link (planted: they
   do not), while each CLI's test binary, built with -DSGP_BUILD_GTESTS=ON, links and passes;
   the tests that need Chromium, Snakemake, Slurm or pyflakes are registered to report a missing
   tool as skipped (run_if_tools.py, SKIP_RETURN_CODE 77), and nothing else needs one.
   Issue 45 item 5, as SEM's GenerateCLP at the commit Slicer 5.8 pins: the generated header brings
   in nothing of the project (no CLPSupport.h, no sgp::clp; planted: a file that uses sgp::clp
   with only the CLP header does not compile); every vector, point and region parameter is
   declared empty and gets its values, the XML default included, only from PARSE_ARGS (a probe
   built from the XML's parameters, no name written here); the arguments are reordered before
   TCLAP (flags first, positionals last), so an unknown flag's error names ct.nrrd, and the Slicer
   build's registered cli.Help, cli.UnknownFlag and cli.UnknownFlagMessage pass.
6. With --standalone-build: that (standalone) build found Debian's nlohmann JSON, TCLAP,
   /usr/bin/python3, GoogleTest and Google Benchmark.
7. Planted defects make the checks fail: a missing script and missing metadata stop the stub; a
   static library without PIC in a CLI module fails to link ("recompile with -fPIC") while the
   same with PIC links; each hidden package cannot be found by a plain lookup.
Builds (not the configures) hold --lock, when given, so that they queue behind the other builds
of a shared machine.
"""
import argparse
import contextlib
import fcntl
import glob
import importlib.util
import json
import os
import re
import shutil
import subprocess
import sys
import time

STUB = os.path.join(os.path.dirname(os.path.abspath(__file__)), "SlicerStub")
CLI_DIR = "lib/Slicer-5.8/cli-modules"  # the stub's Slicer_CLIMODULES_BIN_DIR (and its install folder)
NLOHMANN_URL = "https://github.com/nlohmann/json/releases/download/v3.11.2/json.tar.xz"
NLOHMANN_SHA256 = "8c4b26bf4b422252e13f332bc5e388ec0ab5c3443d24399acb675e68278d341f"
DEBIAN_NLOHMANN = "/usr/include/nlohmann"
HIDE = ["-DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON", "-DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON",
        "-DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON", "-DCMAKE_IGNORE_PATH=/usr/include"]

results = []


def check(what, ok, detail=""):
    results.append(bool(ok))
    print("%s: %s%s" % ("PASS" if ok else "FAIL", what, (" - " + detail) if detail and not ok else ""))
    return ok


@contextlib.contextmanager
def build_lock(path):
    if not path:
        yield
        return
    with open(path, "a") as handle:
        started = time.time()
        fcntl.flock(handle, fcntl.LOCK_EX)
        waited = time.time() - started
        if waited > 1:
            print("NOTE: waited %.0f s for the build lock %s" % (waited, path))
        try:
            yield
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)


def run(argv, cwd=None, timeout=1800):
    print("RUN: " + " ".join(argv))
    return subprocess.run(argv, capture_output=True, text=True, cwd=cwd, timeout=timeout,
                          env=dict(os.environ, ITK_AUTOLOAD_PATH=""))


def cmake_build(args, build, targets):
    argv = [args.cmake, "--build", build, "-j", str(args.jobs)]
    for target in targets:
        argv += ["--target", target]
    with build_lock(args.lock):
        started = time.time()
        result = run(argv)
        return result, time.time() - started


def read_cache(build):
    cache = {}
    path = os.path.join(build, "CMakeCache.txt")
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                match = re.match(r"^([^#/][^:=]*)(?::[A-Z]+)?=(.*)$", line.rstrip("\n"))
                if match:
                    cache[match.group(1)] = match.group(2)
    return cache


def installedSourceFiles(buildDir, sourceDir):
    """(destination, path) of every file(INSTALL ... FILES ...) in the generated install scripts."""
    found = []
    for script in glob.glob(os.path.join(buildDir, "**", "cmake_install.cmake"), recursive=True):
        with open(script) as f:
            text = f.read()
        for destination, files in re.findall(r'file\(INSTALL DESTINATION "([^"]*)" TYPE \w+[^)]*?FILES ([^)]*)\)', text):
            for path in re.findall(r'"([^"]+)"', files):
                # (the build tree may lie inside the source tree; its files are built, not named)
                if path.startswith(sourceDir + os.sep) and not path.startswith(buildDir + os.sep):
                    found.append((destination, path))
    return found


def elf_type(path):
    """ELF e_type (2 executable, 3 shared object or PIE), or None."""
    try:
        with open(path, "rb") as f:
            header = f.read(18)
    except OSError:
        return None
    if header[:4] != b"\x7fELF":
        return None
    return int.from_bytes(header[16:18], "little" if header[5] == 1 else "big")


def stderr_lines(result):
    return [line for line in result.stderr.splitlines() if line.strip()]


def plantedDefect(cmake, scratch, name, body, extra=()):
    """Configure a small project that includes the stub and does one wrong thing; it must fail."""
    project = os.path.join(scratch, "planted-" + name)
    os.makedirs(project, exist_ok=True)
    with open(os.path.join(project, "CMakeLists.txt"), "w") as f:
        f.write("cmake_minimum_required(VERSION 3.16)\nproject(Planted LANGUAGES NONE)\n" + body)
    configure = subprocess.run([cmake, "-S", project, "-B", os.path.join(project, "build"),
                                "-DSlicer_DIR=" + STUB, *extra], capture_output=True, text=True)
    return configure.returncode != 0, configure.stderr


PLANTED_XML = """<?xml version="1.0" encoding="UTF-8"?>
<executable>
  <category>Testing</category>
  <title>Planted</title>
  <description>A planted CLI module.</description>
  <version>0.1</version>
  <parameters>
    <label>IO</label>
    <description>Parameters</description>
    <integer>
      <name>count</name>
      <longflag>count</longflag>
      <description>A number.</description>
      <label>Count</label>
      <default>1</default>
    </integer>
  </parameters>
</executable>
"""


def plantedNonPicModule(args, scratch, source, pic):
    """A CLI module whose TARGET_LIBRARIES is a static library built with or without PIC: (configure ok, build)."""
    name = "pic" if pic else "no-pic"
    project = os.path.join(scratch, "planted-module-" + name)
    os.makedirs(project, exist_ok=True)
    files = {
        "CMakeLists.txt":
            "cmake_minimum_required(VERSION 3.16)\nproject(Planted LANGUAGES C CXX)\nset(CMAKE_CXX_STANDARD 17)\n"
            'foreach(n HOMEPAGE CONTRIBUTORS DESCRIPTION ICONURL SCREENSHOTURLS DEPENDS)\n'
            '  set(EXTENSION_${n} "https://x")\nendforeach()\n'
            "find_package(Slicer REQUIRED)\ninclude(${Slicer_USE_FILE})\n"
            "find_package(SlicerExecutionModel REQUIRED)\ninclude(${SlicerExecutionModel_USE_FILE})\n"
            "add_library(plantedStatic STATIC Planted.cpp)\n"
            "set_target_properties(plantedStatic PROPERTIES POSITION_INDEPENDENT_CODE %s)\n"
            "SEMMacroBuildCLI(NAME PlantedCli TARGET_LIBRARIES plantedStatic INCLUDE_DIRECTORIES %s)\n"
            % ("ON" if pic else "OFF", os.path.join(source, "CLI")),
        "Planted.cpp": "#include <iostream>\nvoid Planted(int count)\n{\n  std::cout << count << std::endl;\n}\n",
        "PlantedCli.cxx": '#include "PlantedCliCLP.h"\nvoid Planted(int count);\n'
                          "int main(int argc, char* argv[])\n{\n  PARSE_ARGS;\n  Planted(count);\n  return 0;\n}\n",
        "PlantedCli.xml": PLANTED_XML,
    }
    for filename, text in files.items():
        with open(os.path.join(project, filename), "w") as f:
            f.write(text)
    build = os.path.join(project, "build")
    configure = subprocess.run([args.cmake, "-S", project, "-B", build, "-G", args.generator,
                                "-DSlicer_DIR=" + STUB], capture_output=True, text=True)
    if configure.returncode != 0:
        return False, configure
    result, _ = cmake_build(args, build, ["PlantedCli"])
    return True, result


def check_compile_commands(build, source, standin):
    try:
        with open(os.path.join(build, "compile_commands.json")) as f:
            commands = json.load(f)
    except (OSError, ValueError) as error:
        check("compile_commands.json is written", False, str(error))
        return
    def output(command):
        if "output" in command:
            return command["output"]
        words = command["command"].split()
        return words[words.index("-o") + 1] if "-o" in words else ""

    # The objects of libraries (the launchers' own objects are executables' and need no PIC).
    launchers = re.compile(r"CMakeFiles/(StentGraftSimulation|SyntheticAorticPhantom)\.dir/")
    ours = [c for c in commands if (c["file"].startswith(os.path.join(source, "Logic")) or
                                    c["file"].startswith(os.path.join(source, "CLI"))) and not launchers.search(output(c))]
    not_pic = [os.path.relpath(c["file"], source) for c in ours if "-fPIC" not in c["command"].split()]
    check("every Logic and CLI object (%d) is compiled as position-independent code (-fPIC)" % len(ours),
          ours and not not_pic, "without -fPIC: " + ", ".join(not_pic[:10]))
    sem_tclap = os.path.join(build, "slicer-stub", "tclap", "include")
    module = [c for c in commands if c["file"] == os.path.join(source, "CLI", "StentGraftSimulation.cxx")]
    check("StentGraftSimulation.cxx is compiled with SEM's TCLAP and -Dmain=ModuleEntryPoint",
          module and sem_tclap in module[0]["command"] and "-Dmain=ModuleEntryPoint" in module[0]["command"],
          module[0]["command"] if module else "not compiled")
    json_user = [c for c in commands if c["file"].endswith(os.path.join("Logic", "IO", "ReadDeviceCatalog.cxx"))]
    check("ReadDeviceCatalog.cxx is compiled with the fetched nlohmann JSON headers",
          json_user and os.path.join(standin, "include") in json_user[0]["command"],
          json_user[0]["command"] if json_user else "not compiled")


def check_runs(build, workdir):
    cli_dir = os.path.join(build, CLI_DIR)
    phantom, simulation = (os.path.join(cli_dir, n) for n in ("SyntheticAorticPhantom", "StentGraftSimulation"))
    runs = os.path.join(workdir, "runs")
    os.makedirs(runs, exist_ok=True)

    xml = run([simulation, "--xml"], cwd=cli_dir, timeout=60)
    check("the launcher prints the module's XML (--xml: exit 0, <?xml at byte 0, no stderr)",
          xml.returncode == 0 and xml.stdout.startswith("<?xml ") and not xml.stderr,
          "exit %s, stderr %r" % (xml.returncode, xml.stderr[:300]))

    volume = os.path.join(runs, "small.nrrd")
    made = run([phantom, "--returnparameterfile", os.path.join(runs, "small.params"), "--spacingMm", "1.5,1.5,2",
                volume], cwd=runs, timeout=600)
    check("the phantom CLI writes its volume (ImageIO factories registered by the project)",
          made.returncode == 0 and os.path.isfile(volume),
          "exit %s; stderr %s" % (made.returncode, made.stderr[-500:]))
    seed = "0,0,60"
    try:
        with open(os.path.join(runs, "small.params")) as f:
            seed = re.search(r"^seedRas\s*=\s*(\S+)", f.read(), re.M).group(1)
    except (OSError, AttributeError):
        pass

    planned = os.path.join(runs, "plan")
    shutil.rmtree(planned, ignore_errors=True)
    os.makedirs(planned)
    plan = run([simulation, "--returnparameterfile", os.path.join(planned, "ret.params"), "--seed", seed,
                "--outputLabelMap", os.path.join(planned, "lumen.nrrd"),
                "--outputReport", os.path.join(planned, "report.json"), volume], cwd=planned, timeout=900)
    written = [n for n in ("ret.params", "lumen.nrrd", "report.json") if os.path.isfile(os.path.join(planned, n))]
    check("StentGraftSimulation plans on it (exit 0; return values, label map and report written)",
          plan.returncode == 0 and len(written) == 3,
          "exit %s, written %s; stderr %s" % (plan.returncode, written, plan.stderr[-800:]))

    for label, text in (("a,b,c", "a,b,c"), ("two numbers", "1,2")):
        outdir = os.path.join(runs, "seed-" + re.sub(r"\W+", "-", label))
        shutil.rmtree(outdir, ignore_errors=True)
        os.makedirs(outdir)
        bad = run([simulation, "--returnparameterfile", os.path.join(outdir, "ret.params"), "--seed", text,
                   "--outputLabelMap", os.path.join(outdir, "lumen.nrrd"), volume], cwd=outdir, timeout=300)
        lines = stderr_lines(bad)
        check("--seed %s (atof under SEM's GenerateCLP) is rejected by the CLI: one ERROR line naming it, nothing written"
              % text,
              bad.returncode not in (0, None) and len(lines) == 1 and lines[0].startswith("ERROR: ") and text in lines[0]
              and not os.listdir(outdir),
              "exit %s, stderr %r, left %s" % (bad.returncode, bad.stderr[-500:], os.listdir(outdir)))

    outside = run([simulation, "--seed", "5000,5000,5000", volume], cwd=runs, timeout=300)
    lines = stderr_lines(outside)
    check("a seed outside the volume is reported after reading it (not 'Cannot read')",
          outside.returncode not in (0, None) and len(lines) == 1 and "5000" in lines[0] and "outside" in lines[0]
          and "Cannot read" not in lines[0], "exit %s, stderr %r" % (outside.returncode, outside.stderr[-500:]))


def compile_with_clp_header(build, source, unit, output):
    """Compile a unit against the stub build's generated CLP headers: link it to output, or only check it."""
    includes = ["-I" + os.path.join(build, "CLI"), "-I" + os.path.join(source, "CLI"),
                "-I" + os.path.join(build, "slicer-stub", "tclap", "include"),
                "-I" + os.path.join(STUB, "SlicerExecutionModel", "ModuleDescriptionParser")]
    return run(["c++", "-std=c++17", *includes, unit, *(["-o", output] if output else ["-fsyntax-only"])], timeout=600)


def check_nothing_of_the_project(args, build, source, header, text):
    """SEM's header includes TCLAP and ModuleProcessInformation.h only: sgp::clp must be included."""
    check("the generated header brings in nothing of the project (no CLPSupport.h, no sgp::clp)",
          "CLPSupport" not in text and "sgp::" not in text)
    planted = os.path.join(args.workdir, "planted-implicit-clp-support")
    os.makedirs(planted, exist_ok=True)
    use = "int main()\n{\n  return static_cast<int>(sgp::clp::SplitStrings(\"1,2\").size()) - 2;\n}\n"
    for name, includes in (("without", '#include "%s"\n' % header),
                           ("with", '#include "%s"\n#include "CLPSupport.h"\n' % header)):
        unit = os.path.join(planted, "%s.cxx" % name)
        with open(unit, "w") as f:
            f.write(includes + use)
        result = compile_with_clp_header(build, source, unit, None)
        if name == "without":
            check("planted defect, a file using sgp::clp with only the CLP header, does not compile (as under SEM)",
                  result.returncode != 0 and "clp" in result.stderr, result.stderr[-800:])
        else:
            check("  ... and the same file including CLPSupport.h itself compiles", result.returncode == 0,
                  result.stderr[-800:])


def check_vectors_filled_by_parsing(args, build, source):
    """Each vector, point and region parameter with an XML default: empty after GENERATE_DECLARE, its
    default's items after PARSE_ARGS (SEM declares a <name>Temp string, split when parsing)."""
    spec = importlib.util.spec_from_file_location("sgp_generate_clp", os.path.join(source, "CMake", "GenerateCLP.py"))
    generator = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(generator)
    for cli in ("StentGraftSimulation", "SyntheticAorticPhantom"):
        _, _, params = generator.parse_xml(os.path.join(source, "CLI", cli + ".xml"))
        vectors = [p for p in params if not p.is_return and p.default and not p.multiple and
                   (p.tag.endswith("-vector") or p.tag in ("point", "region"))]
        positionals = [p for p in params if p.index is not None]
        declared = "".join('  if (!%s.empty()) { std::cout << "declared %s: " << %s.size() << " items\\n"; ++wrong; }\n'
                           % (p.name, p.name, p.name) for p in vectors)
        parsed = "".join('  if (%s.size() != %d) { std::cout << "parsed %s: " << %s.size() << " items\\n"; ++wrong; }\n'
                         % (p.name, len([v for v in p.default.split(",") if v.strip()]), p.name, p.name)
                         for p in vectors)
        probe = os.path.join(args.workdir, "probe-vectors-" + cli)
        os.makedirs(probe, exist_ok=True)
        unit = os.path.join(probe, "probe.cxx")
        with open(unit, "w") as f:
            f.write('#include "%sCLP.h"\n' % cli +
                    "int Declared()\n{\n  int wrong = 0;\n  GENERATE_DECLARE;\n" + declared + "  return wrong;\n}\n"
                    "int Parsed(int argc, char* argv[])\n{\n  int wrong = 0;\n  PARSE_ARGS;\n" + parsed +
                    "  return wrong;\n}\n"
                    "int main(int argc, char* argv[])\n{\n  return Declared() + Parsed(argc, argv) ? 1 : 0;\n}\n")
        built = compile_with_clp_header(build, source, unit, os.path.join(probe, "probe"))
        ran = built
        if built.returncode == 0:
            placeholders = ["positional%d" % i for i in range(len(positionals))]
            ran = run([os.path.join(probe, "probe")] + placeholders, timeout=60)
        check("%s: its %d vector parameters with a default are declared empty and filled by PARSE_ARGS (as SEM's)"
              % (cli, len(vectors)), vectors and ran.returncode == 0,
              built.stderr[-800:] if built.returncode else ran.stdout[-800:] + ran.stderr[-800:])


def check_registered_flag_tests(args, build):
    """The Slicer build's own cli.Help, cli.UnknownFlag and cli.UnknownFlagMessage, run by CTest there."""
    ctest = os.path.join(os.path.dirname(args.cmake), "ctest")
    ran = run([ctest if os.path.isfile(ctest) else "ctest", "-R", r"^cli\.(Help|UnknownFlag|UnknownFlagMessage)$",
               "--output-on-failure"], cwd=build, timeout=300)
    check("the Slicer build's cli.Help, cli.UnknownFlag and cli.UnknownFlagMessage pass (CTest in the stub build)",
          ran.returncode == 0 and "100% tests passed, 0 tests failed out of 3" in ran.stdout,
          (ran.stdout + ran.stderr)[-2500:])


def check_semantics_of_real_sem(args, build, source):
    """Issue 33 items 2-4 and 6: what SEM's GenerateCLP and SEMMacroBuildCLI do beyond the build."""
    cli_dir = os.path.join(build, CLI_DIR)
    simulation = os.path.join(cli_dir, "StentGraftSimulation")
    for cli in ("StentGraftSimulation", "SyntheticAorticPhantom"):
        beside = os.path.join(cli_dir, cli + ".xml")
        printed = run([os.path.join(cli_dir, cli), "--xml"], cwd=cli_dir, timeout=60).stdout
        same = os.path.isfile(beside) and open(beside).read().rstrip("\n") == printed.rstrip("\n")
        check("%s.xml is copied beside the launcher and equals its --xml" % cli, same,
              "exists %s" % os.path.isfile(beside))
    installed = installedSourceFiles(os.path.realpath(build), source)
    for cli in ("StentGraftSimulation", "SyntheticAorticPhantom"):
        xml = os.path.join(source, "CLI", cli + ".xml")
        check("%s.xml is installed beside the launcher" % cli,
              any(path == xml and destination.endswith(CLI_DIR) for destination, path in installed))

    # SEM hands TCLAP the flags first: the unknown switch is taken for the input volume, and the
    # error names ct.nrrd; the enumeration's error names its flag.
    for label, extra, first in (("an unknown flag", ["--noSuchFlag", "3"], "PARSE ERROR: Argument: ct.nrrd"),
                                ("a bad enumeration", ["--acmMode", "bogus"], "PARSE ERROR: Argument: (--acmMode)")):
        bad = run([simulation, "ct.nrrd", "--seed", "0,0,0"] + extra, cwd=cli_dir, timeout=60)
        lines = stderr_lines(bad)
        check("%s: TCLAP's PARSE ERROR (%s) and the usage, exit 1, as under SEM's GenerateCLP" % (label, first),
              bad.returncode == 1 and lines and lines[0] == first and len(lines) > 3,
              "exit %s, stderr %r" % (bad.returncode, bad.stderr[:300]))

    headers = [os.path.join(build, "CLI", n + "CLP.h") for n in ("StentGraftSimulation", "SyntheticAorticPhantom")]
    text = open(headers[0]).read()
    check("the generated header includes ModuleProcessInformation.h and defines its symbols out of line",
          '#include "ModuleProcessInformation.h"' in text and
          'extern "C" {\nModule_EXPORT char XMLModuleDescription[] = ' in text and "void splitString(" in text)
    check_nothing_of_the_project(args, build, source, headers[0], text)
    check_vectors_filled_by_parsing(args, build, source)
    # Two CLP headers in one binary: "multiple definition", as with SEM's; one alone links.
    planted = os.path.join(args.workdir, "planted-two-clp-headers")
    os.makedirs(planted, exist_ok=True)
    units = []
    for i, header in enumerate(headers):
        unit = os.path.join(planted, "unit%d.cxx" % i)
        with open(unit, "w") as f:
            f.write('#include "%s"\n' % header + ("int main() { return 0; }\n" if i == 0 else ""))
        units.append(unit)
    includes = ["-I" + os.path.join(source, "CLI"), "-I" + os.path.join(build, "slicer-stub", "tclap", "include"),
                "-I" + os.path.join(STUB, "SlicerExecutionModel", "ModuleDescriptionParser")]
    both = run(["c++", "-std=c++17", *includes, *units, "-o", os.path.join(planted, "both")], timeout=600)
    check("planted defect, two CLP headers in one binary, fails to link (multiple definition)",
          both.returncode != 0 and "multiple definition" in both.stderr, both.stderr[-800:])
    one = run(["c++", "-std=c++17", *includes, units[0], "-o", os.path.join(planted, "one")], timeout=600)
    check("  ... and one CLP header alone links", one.returncode == 0, one.stderr[-800:])

    # The tests a Slicer build registers: those that need a tool beyond Slicer report it skipped.
    registered = {}
    for testfile in glob.glob(os.path.join(build, "**", "CTestTestfile.cmake"), recursive=True):
        for line in open(testfile).read().splitlines():
            match = re.match(r"(?:add_test|set_tests_properties)\((?:\[=\[)?([\w.]+)", line)
            if match:
                registered[match.group(1)] = registered.get(match.group(1), "") + " " + line
    for name in ("StentGraftPlanner.SlicerCodeCompiles", "cli.ReportHtml", "workflow.Cohort", "workflow.CohortSlurm"):
        entry = registered.get(name, "")
        check("%s is registered to report a missing tool as skipped" % name,
              "run_if_tools.py" in entry and re.search(r'SKIP_RETURN_CODE "77"', entry), entry[:300])
    tools = ("chromium", "snakemake", "sbatch", "slurmctld", "pyflakes", "jsonschema", "skimage")
    unguarded = [n for n, entry in registered.items()
                 if "run_if_tools.py" not in entry and any(t in entry for t in tools)]
    check("no other registered test names a tool beyond Slicer", not unguarded, ", ".join(unguarded))
    missing = run([args.cmake, "-E", "env", "PATH=/nonexistent", os.path.realpath(os.path.join(
        build, "slicer-stub", "python-install", "bin", "PythonSlicer")), os.path.join(source, "Testing", "Tools",
        "run_if_tools.py"), "--program", "snakemake", "--", "false"], timeout=60)
    check("run_if_tools.py without the tool: one SKIPPED line naming it, exit 77",
          missing.returncode == 77 and missing.stdout.startswith("SKIPPED:") and "snakemake" in missing.stdout,
          "exit %s, %r" % (missing.returncode, missing.stdout + missing.stderr))

    # -DSGP_BUILD_GTESTS=ON (GoogleTest installed): each CLI's test binary links and passes.
    again = run([args.cmake, "-S", source, "-B", build, "-DSGP_BUILD_GTESTS=ON",
                 "-DCMAKE_DISABLE_FIND_PACKAGE_GTest=OFF", "-DCMAKE_IGNORE_PATH="])
    check("the Slicer build configures with -DSGP_BUILD_GTESTS=ON", again.returncode == 0,
          (again.stdout + again.stderr)[-2000:])
    if again.returncode == 0:
        built, seconds = cmake_build(args, build, ["sgpCliTests", "sgpPhantomCliTests"])
        print("build of the CLI test binaries: %.0f s" % seconds)
        check("sgpCliTests and sgpPhantomCliTests link in the Slicer build (one CLP header each)",
              built.returncode == 0, (built.stdout + built.stderr)[-3000:])
        if built.returncode == 0:
            for binary in ("sgpCliTests", "sgpPhantomCliTests"):
                ran = run([os.path.join(build, "Testing", binary)], timeout=300)
                check("  ... %s passes" % binary, ran.returncode == 0, ran.stdout[-1500:])


def check_standalone(build):
    cache = read_cache(build)
    if not cache:
        check("the standalone build's CMakeCache.txt is readable", False, build)
        return
    found = lambda key: cache.get(key, "") and not cache[key].endswith("NOTFOUND")  # noqa: E731
    check("the standalone build found Debian's nlohmann JSON package",
          found("nlohmann_json_DIR"), "nlohmann_json_DIR=%r" % cache.get("nlohmann_json_DIR"))
    check("the standalone build found a system TCLAP (find_path)", found("TCLAP_INCLUDE_DIR"),
          "TCLAP_INCLUDE_DIR=%r" % cache.get("TCLAP_INCLUDE_DIR"))
    check("the standalone build uses /usr/bin/python3", cache.get("SGP_PYTHON") == "/usr/bin/python3",
          "SGP_PYTHON=%r" % cache.get("SGP_PYTHON"))
    if cache.get("SGP_BUILD_GTESTS", "ON") == "ON" and cache.get("BUILD_TESTING", "ON") == "ON":
        check("the standalone build found GoogleTest", found("GTest_DIR") or found("GTEST_INCLUDE_DIR"),
              "GTest_DIR=%r" % cache.get("GTest_DIR"))
    if cache.get("SGP_BUILD_BENCHMARKS") == "ON":
        check("the standalone build found Google Benchmark", found("benchmark_DIR"),
              "benchmark_DIR=%r" % cache.get("benchmark_DIR"))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cmake", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--generator", default="Unix Makefiles")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--lock", default="")
    parser.add_argument("--standalone-build", default="")
    args = parser.parse_args()
    source = os.path.realpath(args.source)
    shutil.rmtree(args.workdir, ignore_errors=True)
    build = os.path.join(args.workdir, "build")
    os.makedirs(build)

    # Stands in for the unpacked json.tar.xz (FetchContent's source folder): include/nlohmann.
    standin = os.path.join(args.workdir, "nlohmann-json-3.11.2")
    os.makedirs(os.path.join(standin, "include"))
    os.symlink(DEBIAN_NLOHMANN, os.path.join(standin, "include", "nlohmann"))

    started = time.time()
    configure = run([args.cmake, "-S", source, "-B", build, "-G", args.generator, "-DSlicer_DIR=" + STUB,
                     "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON", *HIDE,
                     "-DFETCHCONTENT_FULLY_DISCONNECTED=ON", "-DFETCHCONTENT_SOURCE_DIR_NLOHMANN_JSON=" + standin])
    print("configure: %.0f s" % (time.time() - started))
    check("the Slicer branch configures with nlohmann JSON, GoogleTest, Google Benchmark and /usr/include hidden "
          "(cmake exit code %d)" % configure.returncode, configure.returncode == 0,
          "\n" + configure.stdout[-3000:] + configure.stderr[-6000:])
    if configure.returncode != 0:
        return

    with open(os.path.join(build, "slicer-stub-record.txt")) as f:
        record = f.read().splitlines()
    print("stub record:\n    " + "\n    ".join(record))

    def index(pattern):
        return next((i for i, line in enumerate(record) if re.search(pattern, line)), -1)

    check("find_package(Slicer) and include(${Slicer_USE_FILE}) ran", index(r"^find_package\(Slicer\)") == 0 and index(r"^include\(Slicer_USE_FILE\) project=StentGraftPlanner$") > 0)
    for cli in ("StentGraftSimulation", "SyntheticAorticPhantom"):
        check("SEMMacroBuildCLI builds %s from its XML as a SHARED library and a launcher" % cli,
              index(r"^SEMMacroBuildCLI %s XML %s\.xml LIB SHARED " % (cli, cli)) > 0)
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

    # What Slicer does not ship: fetched, SEM's or Slicer's, or not built.
    output = configure.stdout + configure.stderr
    fetched = "nlohmann JSON: FetchContent %s (SHA256 %s), headers from %s/include" % (NLOHMANN_URL, NLOHMANN_SHA256, standin)
    check("nlohmann JSON is declared for FetchContent (pinned URL and SHA-256) and taken from its source folder",
          fetched in output, "expected the line: " + fetched)
    cache = read_cache(build)
    found = [k for k in ("nlohmann_json_DIR", "GTest_DIR", "GTEST_INCLUDE_DIR", "benchmark_DIR", "TCLAP_INCLUDE_DIR")
             if cache.get(k, "") and not cache[k].endswith("NOTFOUND")]
    check("no system nlohmann JSON, GoogleTest, Google Benchmark or TCLAP was looked up", not found,
          ", ".join("%s=%s" % (k, cache[k]) for k in found))
    check("GoogleTest suites and benchmarks are off by default inside Slicer",
          cache.get("SGP_BUILD_GTESTS") == "OFF" and cache.get("SGP_BUILD_BENCHMARKS") == "OFF",
          "SGP_BUILD_GTESTS=%r SGP_BUILD_BENCHMARKS=%r" % (cache.get("SGP_BUILD_GTESTS"), cache.get("SGP_BUILD_BENCHMARKS")))
    python = os.path.join(build, "slicer-stub", "python-install", "bin", "PythonSlicer")
    tests = os.path.join(build, "StentGraftPlanner", "CTestTestfile.cmake")
    check("Slicer's Python runs the scripts (configure message and the module's tests)",
          "Python: %s (Slicer's)" % python in output and os.path.exists(tests) and python in open(tests).read())

    installed = installedSourceFiles(os.path.realpath(build), source)
    missing = [path for _, path in installed if not os.path.exists(path)]
    check("the %d source files the install scripts name exist" % len(installed), not missing, ", ".join(missing))
    catalog = [destination for destination, path in installed if path == os.path.join(source, "Resources", "devices.json")]
    check("Resources/devices.json is installed beside the CLIs", any(d.endswith(CLI_DIR) for d in catalog),
          "installed to %s" % catalog)
    check("the devices.json copy for the build tree exists", os.path.exists(os.path.join(build, CLI_DIR, "devices.json")))
    check_compile_commands(build, source, standin)

    # The build SEM's macro makes, with the real compiler and linker.
    built, seconds = cmake_build(args, build, [])  # the default target: what a Slicer build builds
    print("build of the default target (both CLI modules and the libraries): %.0f s" % seconds)
    log = built.stdout + built.stderr
    relocation = [line for line in log.splitlines() if "relocation" in line or "recompile with" in line]
    check("both CLI modules build and link (SHARED <Name>Lib + launcher)", built.returncode == 0,
          "\n".join(relocation[:5]) + "\n" + log[-4000:])
    if built.returncode == 0:
        cli_dir = os.path.join(build, CLI_DIR)
        for cli in ("StentGraftSimulation", "SyntheticAorticPhantom"):
            library = os.path.join(cli_dir, "lib%sLib.so" % cli)
            launcher = os.path.join(cli_dir, cli)
            symbols = subprocess.run(["nm", "-D", "--defined-only", library], capture_output=True, text=True).stdout
            needed = subprocess.run(["readelf", "-d", launcher], capture_output=True, text=True).stdout
            check("%s: lib%sLib.so is a shared object exporting ModuleEntryPoint, and the launcher needs it" % (cli, cli),
                  elf_type(library) == 3 and re.search(r"\bT ModuleEntryPoint$", symbols, re.M)
                  and "[lib%sLib.so]" % cli in needed,
                  "ELF type %s; ModuleEntryPoint exported: %s; NEEDED: %s" % (
                      elf_type(library), bool(re.search(r"\bT ModuleEntryPoint$", symbols, re.M)),
                      re.findall(r"\[(.*?)\]", needed)))
        header = os.path.join(build, "CLI", "StentGraftSimulationCLP.h")
        text = open(header).read() if os.path.exists(header) else ""
        check("the stub's GenerateCLP parses points with atof, as SEM's does",
              "seedTemp = seedArg.getValue();" in text and "seed.emplace_back(atof(word.c_str()));" in text)
        check_runs(build, args.workdir)
        check_semantics_of_real_sem(args, build, source)
        check_registered_flag_tests(args, build)

    if args.standalone_build:
        check_standalone(args.standalone_build)

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
        check("planted defect, %s, stops the configure" % name, rejected and "Slicer stub:" in stderr, stderr[-1500:])
    lookups = {
        "find_package(nlohmann_json REQUIRED)": "find_package(nlohmann_json REQUIRED)",
        "find_package(GTest REQUIRED)": "find_package(GTest REQUIRED)",
        "find_package(benchmark REQUIRED)": "find_package(benchmark REQUIRED)",
        "find_path(... tclap/CmdLine.h REQUIRED)": "find_path(TCLAP_INCLUDE_DIR tclap/CmdLine.h REQUIRED)",
    }
    for name, body in lookups.items():
        rejected, stderr = plantedDefect(args.cmake, args.workdir, "lookup-" + re.sub(r"\W+", "-", name), body + "\n",
                                         HIDE)
        check("planted lookup, %s, fails with the packages hidden" % name, rejected, stderr[-1500:])

    configured, built = plantedNonPicModule(args, args.workdir, source, pic=False)
    check("planted defect, a static library without PIC in a CLI module, fails to link for that reason",
          configured and built.returncode != 0 and "recompile with -fPIC" in built.stdout + built.stderr,
          (built.stdout + built.stderr)[-2000:])
    configured, built = plantedNonPicModule(args, args.workdir, source, pic=True)
    check("  ... and the same module with a PIC static library links", configured and built.returncode == 0,
          (built.stdout + built.stderr)[-2000:])


if __name__ == "__main__":
    started = time.time()
    main()
    print("%d passed, %d failed (%.0f s)" % (results.count(True), results.count(False), time.time() - started))
    sys.exit(0 if results and all(results) else 1)
