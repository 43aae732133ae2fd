#!/usr/bin/python3
"""The dependency rule of Logic/ (docs/development.md "Layout"; Logic/CMakeLists.txt): a stage folder includes
only the shared vocabulary and the stages before it in DESIGN.md's data flow; Phantom only the
shared vocabulary; IO anything in Logic; nothing in Logic includes the CLI, tclap or a *CLP.h, and
only IO includes ITK/VTK readers or writers; and no file in Logic is longer than MAX_LINES (issue 34:
files a newcomer can hold in mind; STYLE.md aims at 300-400).

Usage: test_logic_layering.py LOGIC_DIR

Prints one line per violation and `N passed, M failed` (one check per source file); exits 1 on any.
"""
import os
import re
import sys

ORDER = ["Common", "Segmentation", "Centerlines", "Wall", "Stent", "Measurement", "Device", "Pipeline", "Views"]
ALLOWED = {stage: set(ORDER[:i + 1]) for i, stage in enumerate(ORDER)}
ALLOWED["Phantom"] = {"Common", "Phantom"}
ALLOWED["IO"] = set(ORDER) | {"Phantom", "IO"}
OURS = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
SYSTEM = re.compile(r'^\s*#\s*include\s+<([^>]+)>', re.M)
# What only the I/O room may use (STYLE.md B1): readers, writers, file streams, printing.
MAX_LINES = 700
IO_ONLY = re.compile(r"^(itkImageFileReader|itkImageFileWriter|itkImageSeriesReader|itkGDCM|vtkXML|vtk.*Writer|"
                     r"vtk.*Reader|fstream|iostream|tclap/)")


def main():
    logic = os.path.abspath(sys.argv[1])
    passed = failed = 0
    for folder in sorted(os.listdir(logic)):
        path = os.path.join(logic, folder)
        if not os.path.isdir(path):
            continue
        if folder not in ALLOWED:
            print(f"FAIL: Logic/{folder} is not a known stage folder; add it to the rule (docs/development.md, CMake, this test)")
            failed += 1
            continue
        for name in sorted(os.listdir(path)):
            if not name.endswith((".h", ".cxx")):
                continue
            text = open(os.path.join(path, name), encoding="utf-8").read()
            problems = []
            for include in OURS.findall(text):
                top = include.split("/")[0] if "/" in include else None
                if top is None:
                    problems.append(f'"{include}" is not written from Logic/ (Folder/File.h)')
                elif top not in ALLOWED[folder]:
                    problems.append(f'"{include}": {folder} may use only {", ".join(sorted(ALLOWED[folder]))}')
                if include.endswith("CLP.h"):
                    problems.append(f'"{include}": no command-line code in Logic')
            lines = text.count("\n")
            if lines > MAX_LINES:
                problems.append(f"{lines} lines, more than {MAX_LINES}: split it by step into files named after what they hold")
            if folder != "IO":
                problems += [f"<{inc}> is for the I/O room only" for inc in SYSTEM.findall(text) if IO_ONLY.match(inc)]
            if problems:
                failed += 1
                for problem in problems:
                    print(f"FAIL: Logic/{folder}/{name}: {problem}")
            else:
                passed += 1
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
