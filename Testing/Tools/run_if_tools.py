#!/usr/bin/python3
"""Runs a test command when the tools it needs are there; otherwise reports it skipped.

Usage: run_if_tools.py [--program NAME]... [--module NAME]... -- COMMAND [ARG]...

Inside a Slicer build (issue 33 item 6) the extension factory runs the tests with Slicer's Python
on a machine that may lack Chromium, Snakemake, Slurm or pyflakes. A test that needs one is
registered through this script there, with CTest's SKIP_RETURN_CODE 77: a missing tool makes it
print one `SKIPPED: ...` line naming the tool and exit 77 (CTest reports the test skipped, not
passed); with every tool present the command runs and its exit code is the test's. The standalone
build registers the same tests without it, so there a missing tool fails them.

--program NAME: an executable found on the PATH (or NAME itself, when it is a path to one).
--module NAME: a module the running Python imports (the build's Python runs this script).
"""
import importlib.util
import os
import shutil
import subprocess
import sys

SKIPPED = 77


def main(argv):
    if "--" not in argv:
        print("usage: run_if_tools.py [--program NAME]... [--module NAME]... -- COMMAND [ARG]...", file=sys.stderr)
        return 2
    split = argv.index("--")
    options, command = argv[:split], argv[split + 1:]
    missing = []
    for kind, name in zip(options[::2], options[1::2]):
        if kind == "--program":
            found = shutil.which(name) or (os.path.isfile(name) and os.access(name, os.X_OK))
            if not found:
                missing.append("the program %s (not on the PATH)" % name)
        elif kind == "--module":
            if importlib.util.find_spec(name) is None:
                missing.append("the Python module %s (not importable by %s)" % (name, sys.executable))
        else:
            print("run_if_tools.py: unknown option %s" % kind, file=sys.stderr)
            return 2
    if len(options) % 2 or not command:
        print("run_if_tools.py: options come in pairs and a command follows --", file=sys.stderr)
        return 2
    if missing:
        print("SKIPPED: this test needs %s, which this machine does not have." % "; ".join(missing))
        return SKIPPED
    return subprocess.call(command)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
