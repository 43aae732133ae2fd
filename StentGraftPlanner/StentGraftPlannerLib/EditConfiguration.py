"""The panel's editable order list and *Simulate this configuration* (issue 47 item 3), without Slicer.

Every run asks the CLI for the configuration it simulated (``--outputConfiguration``, the format
``--configuration`` reads: Resources/configuration.schema.json). The panel shows it as an editable
table — one row per component, a catalogue entry of that component's role to choose, and the side
the main body goes up — and *Simulate this configuration* runs the CLI with the edited file.

- ``rows``: the table's rows of a configuration document: (label in words, role, current entry).
- ``catalogueEntries``: the entries of a role a family makes (devices.json), each with its text.
- ``entryText``: "16–16 × 124 mm (ETLW1616C124E)", as the order list writes a component.
- ``editedConfiguration``: the document with the chosen entries and side. A component whose entry
  changed keeps its position (its overlap: the plan then simulates exactly what was changed); a
  different main-body side drops every limb's and extension's position (they belonged to the other
  side's gate and leg: the plan places them again).
- ``simulationParameters``: the run's CLI parameters with the edited file (and --device auto: the
  configuration names its family).

Units mm; sides are the patient's.
"""

import copy

#: The configuration file's role names in words.
ROLE_WORDS = {"mainBody": "main body", "limb": "limb", "iliacExtension": "iliac extension"}

#: The catalogue's group of each role (devices.json).
_GROUPS = {"mainBody": "mainBodies", "limb": "limbs", "iliacExtension": "iliacExtensions"}

#: The fields that name a component (the rest are its position).
IDENTITY_FIELDS = ("code", "diameterMm", "distalDiameterMm", "lengthMm")

#: Its positions (GivenConfiguration.h).
POSITION_FIELDS = ("proximalEdgeBelowLowestRenalMm", "overlapMm", "distalEdgeAboveInternalIliacMm")

#: The CLI parameter that takes the edited file.
CONFIGURATION_PARAMETER = "configuration"


def _size(value):
    """A catalogue size as the catalogue writes it: 25, 14.5."""
    return "%g" % float(value)


def entryText(entry):
    """"16–16 × 124 mm (ETLW1616C124E)": proximal–distal × length, the code where it is public."""
    proximal, distal = entry.get("diameterMm"), entry.get("distalDiameterMm")
    diameters = "–".join(_size(d) for d in (proximal, distal) if d is not None) or "?"
    length = entry.get("lengthMm")
    text = "%s × %s mm" % (diameters, _size(length) if length is not None else "?")
    return text + (" (%s)" % entry["code"] if entry.get("code") else "")


def identity(component):
    """The fields that name a component: its code, or its sizes where the code is not public."""
    if component.get("code"):
        return {"code": component["code"]}
    return {k: component[k] for k in ("diameterMm", "distalDiameterMm", "lengthMm") if component.get(k) is not None}


def catalogueEntries(catalog, family, role):
    """The entries of ``role`` ("mainBody", "limb", "iliacExtension") that ``family`` makes in the parsed
    catalogue ``catalog`` (devices.json), in its order: (identity, text) pairs. [] for a family or role the
    catalogue does not list."""
    for entry in catalog.get("families", []):
        if entry.get("name", "").strip().lower() == str(family).strip().lower():
            items = (entry.get(_GROUPS[role]) or {}).get("items", [])
            return [(identity(item), entryText(item)) for item in items]
    return []


def rows(document):
    """The table's rows: (label, role, identity) per component, in the document's order; labels in words
    ("main body", "right limb", "left iliac extension")."""
    result = []
    for component in document.get("components", []):
        role = component.get("role", "")
        words = ROLE_WORDS.get(role, role)
        label = words if role == "mainBody" else "%s %s" % (component.get("side", ""), words)
        result.append((label, role, identity(component)))
    return result


def editedConfiguration(document, chosen, mainBodySide):
    """``document`` with each component's entry replaced by ``chosen[i]`` (an identity from
    ``catalogueEntries``; None keeps it) and the main body going up ``mainBodySide`` ("right" or "left").
    Returns (the new document, the edits in words). Raises ValueError for a list of choices whose length
    is not the number of components, or a side that is neither."""
    components = document.get("components", [])
    if len(chosen) != len(components):
        raise ValueError("%d choices for %d components" % (len(chosen), len(components)))
    if mainBodySide not in ("right", "left"):
        raise ValueError("main body side %r; expected right or left" % (mainBodySide,))
    edited = copy.deepcopy(document)
    edited["description"] = "Edited in the StentGraftPlanner panel"
    edits = []
    for (label, _, before), component, after in zip(rows(document), edited["components"], chosen):
        if after is None or after == before:
            continue
        for field in IDENTITY_FIELDS:
            component.pop(field, None)
        component.update(after)
        edits.append("%s: %s" % (label, entryText(after) if "code" not in after or len(after) > 1 else after["code"]))
    if document.get("mainBodySide") != mainBodySide:
        edited["mainBodySide"] = mainBodySide
        edited.pop("bodyLegLandsAlone", None)
        for component in edited["components"]:
            if component.get("role") != "mainBody":
                for field in ("overlapMm", "distalEdgeAboveInternalIliacMm"):
                    component.pop(field, None)
        edits.append("main body from the %s (the limbs placed again)" % mainBodySide)
    return edited, edits


def simulationParameters(parameters, configurationPath):
    """The run's CLI parameters (``Settings.buildCliParameters``) with the edited configuration file: the
    same inputs and settings, ``configuration`` the file and ``device`` auto (the file names its family;
    the CLI refuses both)."""
    result = dict(parameters)
    result[CONFIGURATION_PARAMETER] = str(configurationPath)
    result["device"] = "auto"
    return result
