#!/usr/bin/python3
"""Each CLI describes itself to Slicer correctly, and our XML checker can fail.

Usage: test_xml_conformance.py EXE [EXE ...]
       test_xml_conformance.py --xml-file FILE [FILE ...]   (checker only, no executable)

For each executable this proves what Slicer's module discovery needs
(slicer-conventions.md 2.1):
- `EXE --xml` exits 0 within Slicer's 5 s timeout, writes nothing to stderr,
  and its stdout passes check_module_xml (SEM ModuleDescriptionParser rules plus
  the project's) with zero problems;
- `<exe>.xml` beside the executable (which Slicer reads instead of running it)
  equals that output;
- `EXE --help` exits 0; `EXE --version` exits 0 and prints the XML <version>.

Then it plants known defects in the real XML one at a time and proves that
the checker reports each one, naming the broken rule, so a clean result above
means something. Prints one line per check and `N passed, M failed`; exits 1 on
any failure.
"""

import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sem_rules  # noqa: E402

PARAMETER_TAG = "|".join(sorted(sem_rules.PARAMETER_ATTRIBUTES, key=len, reverse=True))
PARAMETER_BLOCK = re.compile(rf"<({PARAMETER_TAG})(\s[^>]*)?>.*?</\1>", re.S)

results = []


def check(ok, what, detail=""):
    results.append(bool(ok))
    print(f"{'PASS' if ok else 'FAIL'}: {what}" + (f" -- {detail}" if detail and not ok else ""))
    return ok


def _blocks(raw, tag=None, containing=None):
    """(start, end) of parameter elements, optionally of one tag / containing text."""
    found = []
    for match in PARAMETER_BLOCK.finditer(raw):
        if tag and match.group(1) != tag:
            continue
        if containing and not re.search(containing, match.group(0)):
            continue
        found.append((match.start(), match.end()))
    return found


def _edit_first_block(raw, edit, tag=None, containing=None):
    blocks = _blocks(raw, tag, containing)
    if not blocks:
        return None
    start, end = blocks[0]
    return raw[:start] + edit(raw[start:end]) + raw[end:]


def plant_missing_coordinate_system(raw):
    return _edit_first_block(
        raw, lambda b: re.sub(r'\s+coordinateSystem="[^"]*"', "", b, count=1), tag="point")


def plant_unknown_element(raw):
    return _edit_first_block(
        raw, lambda b: re.sub(r"(</name>)", r"\1<foo/>", b, count=1))


def plant_longflag_on_index(raw):
    return _edit_first_block(
        raw, lambda b: re.sub(r"(</name>)", r"\1<longflag>plantedLongflag</longflag>", b, count=1),
        containing=r"<index>")


def plant_duplicate_longflag(raw):
    longflags = re.findall(r"<longflag>\s*([^<]*?)\s*</longflag>", raw)
    if len(longflags) < 2:
        return None
    first, second = longflags[0], longflags[1]
    return raw.replace(f"<longflag>{second}</longflag>", f"<longflag>{first}</longflag>", 1)


def plant_leading_space(raw):
    return " " + raw


def plant_bad_enumeration_default(raw):
    tags = "|".join(sem_rules.ENUMERATION_TAGS)
    match = re.search(rf"<({tags})[\s>].*?</\1>", raw, re.S)
    if not match or "<default>" not in match.group(0):
        return None
    block = re.sub(r"<default>[^<]*</default>", "<default>notAnElement</default>",
                   match.group(0), count=1)
    return raw[:match.start()] + block + raw[match.end():]


def plant_hidden_point(raw):
    return _edit_first_block(raw, lambda b: b.replace("<point", '<point hidden="true"', 1),
                             tag="point")


# (description, planting function, text the problem must contain: the rule fired)
DEFECTS = [
    ("point without coordinateSystem", plant_missing_coordinate_system, "coordinateSystem"),
    ("unknown element <foo/> in a parameter", plant_unknown_element, "<foo>"),
    ("longflag on an index parameter", plant_longflag_on_index, "mutually exclusive"),
    ("duplicated longflag", plant_duplicate_longflag, "duplicate longflag"),
    ("space before <?xml", plant_leading_space, "byte 0"),
    ("enumeration default not among its elements", plant_bad_enumeration_default,
     "is not one of the <element>s"),
    ('<point hidden="true">', plant_hidden_point, "'hidden' is not accepted"),
]


def self_test_checker(label, raw, planted):
    """Plant each applicable defect in raw; the checker must report it."""
    _, original_problems = sem_rules.check_module_xml(raw)
    for description, plant, expected in DEFECTS:
        mutated = plant(raw)
        if mutated is None or mutated == raw:
            print(f"SKIP: {label}: cannot plant '{description}' (no suitable element)")
            continue
        planted.add(description)
        _, problems = sem_rules.check_module_xml(mutated)
        # Only a problem the unmodified XML does not already have counts.
        hit = [p for p in problems if expected in p and p not in original_problems]
        check(hit, f"{label}: checker reports planted defect: {description}",
              f"expected a problem containing {expected!r}, got {problems}")


def run(argv, cwd):
    env = dict(os.environ, ITK_AUTOLOAD_PATH="")  # as Slicer runs CLIs
    return subprocess.run(argv, cwd=cwd, env=env, capture_output=True, timeout=5)


def test_executable(exe, planted):
    exe = os.path.abspath(exe)
    label = os.path.basename(exe)
    cwd = os.path.dirname(exe)  # Slicer probes with the executable's folder as cwd
    try:
        result = run([exe, "--xml"], cwd)
    except subprocess.TimeoutExpired:
        check(False, f"{label} --xml finishes within Slicer's 5 s timeout")
        return
    except OSError as error:
        check(False, f"{label} --xml can be started", str(error))
        return
    check(True, f"{label} --xml finishes within Slicer's 5 s timeout")
    check(result.returncode == 0, f"{label} --xml exits 0", f"exit code {result.returncode}")
    check(result.stderr == b"", f"{label} --xml writes nothing to stderr",
          result.stderr.decode(errors="replace")[:500])
    raw = result.stdout.decode("utf-8", errors="replace")
    params, problems = sem_rules.check_module_xml(raw)
    check(not problems, f"{label} --xml passes the module-description rules",
          "; ".join(problems))
    check(params, f"{label} --xml declares parameters")

    beside = exe + ".xml"
    if check(os.path.isfile(beside), f"{label}.xml exists beside the executable", beside):
        with open(beside, encoding="utf-8", errors="replace") as handle:
            text = handle.read()
        check(text.rstrip("\n") == raw.rstrip("\n"),
              f"{label}.xml equals the --xml output (modulo a trailing newline)")

    for flag in ("--help", "--version"):
        try:
            result_flag = run([exe, flag], cwd)
        except subprocess.TimeoutExpired:
            check(False, f"{label} {flag} exits 0", "timed out after 5 s")
            continue
        check(result_flag.returncode == 0, f"{label} {flag} exits 0",
              f"exit code {result_flag.returncode}")
        if flag == "--version":
            try:
                version = sem_rules.module_info(raw).get("version", "")
            except Exception as error:  # not well-formed: already reported above
                check(False, f"{label} --version can be compared with the XML <version>", str(error))
                continue
            printed = result_flag.stdout.decode(errors="replace")
            check(version and version in printed,
                  f"{label} --version prints the XML version '{version}'", printed.strip()[:200])
    if raw.startswith("<?xml "):
        self_test_checker(label, raw, planted)


def main(argv):
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 2
    planted = set()
    if argv[0] == "--xml-file":
        for path in argv[1:]:
            with open(path, encoding="utf-8") as handle:
                raw = handle.read()
            label = os.path.basename(path)
            params, problems = sem_rules.check_module_xml(raw)
            check(not problems, f"{label} passes the module-description rules",
                  "; ".join(problems))
            check(params, f"{label} declares parameters")
            self_test_checker(label, raw, planted)
    else:
        for exe in argv:
            test_executable(exe, planted)
    # Every defect must have been planted somewhere, or the self-test proved nothing.
    for description, _, _ in DEFECTS:
        check(description in planted, f"defect '{description}' was planted in at least one XML")
    passed = sum(results)
    failed = len(results) - passed
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
