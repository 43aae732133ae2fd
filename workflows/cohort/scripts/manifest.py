"""The cohort manifest: which cases to plan, and with which optional points and device.

A manifest is a CSV file (UTF-8, comma-separated, a header row) with the columns
- `case`: the case's name; it names the folder `cases/<case>/`, so it may hold only letters,
  digits, `.`, `_` and `-`, must not start with `.`, and must be unique;
- `image`: the CT volume (any format StentGraftSimulation reads: NRRD, NIfTI, MetaImage, a DICOM
  folder); a relative path is relative to the folder that holds the manifest;
and optionally
- `seedRas`, `lowestRenalOstiumRas`: points as `x,y,z` in mm (RAS), quoted because of the commas;
- `device`: a device family name from the catalogue.
An empty cell or a missing optional column means "not given" (the CLI then uses its own default:
the automatic seed, the renal arteries it finds, the best family). Other columns are ignored, so a
manifest can carry the site's own notes.

`read_manifest` raises ValueError naming the line and the value for a malformed manifest; the
workflow then stops before any case runs, because a bad manifest is the user's input error, not a
case's.
"""

import csv
import os
import re

OPTIONAL_COLUMNS = ("seedRas", "lowestRenalOstiumRas", "device")
POINT_COLUMNS = ("seedRas", "lowestRenalOstiumRas")
CASE_NAME = re.compile(r"^[A-Za-z0-9_-][A-Za-z0-9._-]*$")
NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


def read_manifest(path):
    """Returns the cases in manifest order: a list of dicts with keys case, image (absolute) and
    the optional columns (None when not given)."""
    path = os.path.abspath(path)
    folder = os.path.dirname(path)
    with open(path, newline="", encoding="utf-8-sig") as handle:
        reader = csv.DictReader(handle)
        columns = [c.strip() for c in (reader.fieldnames or [])]
        for required in ("case", "image"):
            if required not in columns:
                raise ValueError(f"{path}: the manifest has no '{required}' column (columns: {', '.join(columns)})")
        reader.fieldnames = columns
        cases, seen = [], set()
        for row in reader:
            line = reader.line_num
            name = (row.get("case") or "").strip()
            image = (row.get("image") or "").strip()
            if not name and not image:
                continue  # a blank line
            if not CASE_NAME.match(name):
                raise ValueError(f"{path}, line {line}: case name '{name}' must be letters, digits, '.', '_' or '-'")
            if name in seen:
                raise ValueError(f"{path}, line {line}: case '{name}' appears twice")
            if not image:
                raise ValueError(f"{path}, line {line}: case '{name}' has no image")
            seen.add(name)
            case = {"case": name, "image": os.path.normpath(os.path.join(folder, image))}
            for column in OPTIONAL_COLUMNS:
                value = (row.get(column) or "").strip()
                case[column] = value or None
            for column in POINT_COLUMNS:
                if case[column] is not None:
                    case[column] = point_text(case[column], f"{path}, line {line}, {column}")
            cases.append(case)
    if not cases:
        raise ValueError(f"{path}: the manifest lists no case")
    return cases


def point_text(text, where):
    """'x, y, z' -> 'x,y,z' (the CLI's form); ValueError unless it is three numbers."""
    parts = [p.strip() for p in text.split(",")]
    if len(parts) != 3 or not all(NUMBER.match(p) for p in parts):
        raise ValueError(f"{where}: '{text}' is not a point x,y,z")
    return ",".join(parts)


def input_size_mb(path):
    """Size of an image file, or the sum over a DICOM folder's files, in MB; 0 when missing."""
    if os.path.isdir(path):
        total = 0
        for root, _, files in os.walk(path):
            total += sum(os.path.getsize(os.path.join(root, f)) for f in files)
        return total / 1024 / 1024
    return os.path.getsize(path) / 1024 / 1024 if os.path.isfile(path) else 0.0


def case_mem_mb(path):
    """Memory to ask the scheduler for one case, in MB.

    The CLI peaks at about 1.8 times the decompressed HU volume, and a gzip NRRD or .nii.gz
    compresses CT about 3 to 4 times, so 8 times the file size covers a compressed input with a
    margin (a raw file is over-asked by about 4 times, which is safe); the 1000 MB constant is the
    executable, ITK and VTK themselves, and 2000 MB is the floor for small scans.
    """
    return int(max(2000, 8 * input_size_mb(path) + 1000))
