"""Colours and opacities of the planning outputs and of the diameter-profile plot.

Colours are RGB triples in [0, 1]. The lumen is drawn translucent so that the centerlines and the
stent surfaces inside it stay visible; the outer wall is a second, fainter segment around it (the
thrombus and the wall lie between the two), drawn as an outline only in the slice views so that the
CT and the lumen stay readable there. The fitted (measure-mode) surface is a pale, translucent
shell, the simulated graft an opaque, warmer one coloured by its apposition gap where the CLI
wrote that point data. The outer-wall surface model, coloured by thrombus thickness, is loaded
hidden: the segment already shows the outer wall, and two translucent shells in one place would
hide each other. Right and left are the patient's, as everywhere in the project.
"""

import collections

Look = collections.namedtuple("Look", "color opacity scalars scalarRangeMm lineWidth sliceFillOpacity visible",
                              defaults=(None, True))
Look.__doc__ = """How one output is shown.

color: RGB in [0, 1].
opacity: 0 (invisible) to 1 (opaque), in the 3D view.
scalars: point-data array to colour by, or None for the plain colour.
scalarRangeMm: (low, high) of the colour map when scalars is set, else None.
lineWidth: line width in pixels (centerlines), or None.
sliceFillOpacity: a segment's fill opacity in the slice views (0: outline only), or None for
    Slicer's default.
visible: shown once the run ends (False: loaded, and ready to be switched on in the Data module).
"""

#: The segments of the vessel segmentation, in name -> the label map output each is made from:
#: every voxel with a label of 1 or more (the outer wall's label map holds 1 lumen, 2 thrombus and
#: wall, 3 calcification, so the segment is everything inside the outer wall). Their looks are
#: LOOKS[role].
SEGMENTS = (("Lumen", "outputLabelMap"), ("Outer wall", "outputWallLabelMap"))

LOOKS = {
    "outputLabelMap": Look((0.85, 0.25, 0.2), 0.25, None, None, None),
    "outputWallLabelMap": Look((0.85, 0.8, 0.65), 0.3, None, None, None, sliceFillOpacity=0.0),
    # ThrombusThicknessMm: 0 (no thrombus) to 25 mm (a thick sac thrombus).
    "outputOuterWallModel": Look((0.85, 0.8, 0.65), 0.3, "ThrombusThicknessMm", (0.0, 25.0), None, visible=False),
    "outputCenterlines": Look((1.0, 0.85, 0.1), 1.0, None, None, 3),
    "outputLandmarks": Look((0.1, 0.9, 0.9), 1.0, None, None, None),
    "outputStentModel": Look((0.55, 0.75, 1.0), 0.35, None, None, None),
    # Apposition: the gap to the wall in mm; 0 (sealed) to 5 mm (clearly not apposed).
    "outputSimulatedStentModel": Look((0.95, 0.6, 0.15), 0.9, "Apposition", (0.0, 5.0), None),
}

#: Plot colour of each vessel's diameter series.
VESSEL_COLORS = {
    "aorta": (0.85, 0.15, 0.15),
    "rightIliac": (0.15, 0.45, 0.85),
    "leftIliac": (0.15, 0.65, 0.3),
}

VESSEL_TITLES = {"aorta": "Aorta", "rightIliac": "Right iliac", "leftIliac": "Left iliac"}

_OTHER_COLORS = ((0.5, 0.3, 0.7), (0.6, 0.45, 0.2), (0.4, 0.4, 0.4))


def vesselColor(vessel, index=0):
    """The plot colour of a vessel; other vessels cycle through spare colours by their index."""
    return VESSEL_COLORS.get(vessel, _OTHER_COLORS[index % len(_OTHER_COLORS)])


def vesselTitle(vessel):
    """Legend text for a vessel ("Right iliac"); unknown names are shown as they are."""
    return VESSEL_TITLES.get(vessel, vessel)
