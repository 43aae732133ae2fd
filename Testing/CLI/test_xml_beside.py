#!/usr/bin/python3
"""<Name>.xml beside a CLI executable is exactly what the executable prints for --xml.

Usage: test_xml_beside.py EXECUTABLE

Slicer reads a module's description from <Name>.xml next to the executable when it finds one,
instead of running it with --xml (issue 33 item 4): the copy the build puts there must not drift
from the description compiled into the module. Exits 1 when the file is missing or differs.
"""
import os
import subprocess
import sys


def main():
    exe = os.path.abspath(sys.argv[1])
    beside = os.path.splitext(exe)[0] + ".xml"
    printed = subprocess.run([exe, "--xml"], capture_output=True, timeout=30).stdout
    if not os.path.isfile(beside):
        print("FAIL: no %s beside the executable" % beside)
        return 1
    with open(beside, "rb") as handle:
        copied = handle.read()
    # --xml prints the description and a line break after it.
    same = copied.rstrip(b"\n") == printed.rstrip(b"\n") and copied
    print("%s: %s equals the executable's --xml (%d bytes)" % ("PASS" if same else "FAIL", beside, len(copied)))
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
