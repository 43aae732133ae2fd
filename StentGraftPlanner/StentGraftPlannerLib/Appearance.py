"""Colours and opacities of the planning outputs and of the diameter-profile plot.

Colours are RGB triples in [0, 1]. The lumen is drawn translucent so that the centerlines and the
stent surfaces inside it stay visible; the outer wall is a second, fainter segment around it (the
thrombus and the wall lie between the two), drawn as an outline only in the slice views so that the
CT and the lumen stay readable there. The fitted (measure-mode) surface is a pale, translucent
shell, the simulated graft an opaque one coloured by component (ComponentRole: main body, limbs,
iliac extensions, aortic cuffs in the visual report's colours, COMPONENT_ROLES), so each ordered
component can be told apart in the 3D view. The outer-wall surface model, coloured by thrombus thickness, is loaded
hidden: the segment already shows the outer wall, and two translucent shells in one place would
hide each other. Right and left are the patient's, as everywhere in the project.
"""

import collections

Look = collections.namedtuple("Look", "color opacity scalars scalarRange lineWidth sliceFillOpacity visible colorTable",
                              defaults=(None, True, None))
Look.__doc__ = """How one output is shown.

color: RGB in [0, 1].
opacity: 0 (invisible) to 1 (opaque), in the 3D view.
scalars: point-data array to colour by, or None for the plain colour.
scalarRange: (low, high) of the colour map when scalars is set (in the array's unit: mm, or role
    codes), else None.
lineWidth: line width in pixels (centerlines), or None.
sliceFillOpacity: a segment's fill opacity in the slice views (0: outline only), or None for
    Slicer's default.
visible: shown once the run ends (False: loaded, and ready to be switched on in the Data module).
colorTable: None for Slicer's rainbow colour map, or COMPONENT_COLOR_TABLE for the discrete table of
    COMPONENT_ROLES (one colour per role code).
"""

ComponentRole = collections.namedtuple("ComponentRole", "code name color")
ComponentRole.__doc__ = """One kind of ordered component, as the simulated graft's ComponentRole point data codes it.

code: the JSON report's deployment.components[].role ("mainBody", ...).
name: in words, as a person reads it (the colour table's entry name).
color: RGB in [0, 1], the visual report's colour of that component.
"""

#: The simulated graft's ComponentRole codes in order: entry i is the role with code i (the XML's
#: outputSimulatedStentModel: 0 main body, 1 ipsilateral limb, 2 contralateral limb, 3 iliac
#: extension, 4 aortic cuff), coloured as the visual report colours the components.
COMPONENT_ROLES = (
    ComponentRole("mainBody", "main body", (0.15, 0.35, 0.85)),
    ComponentRole("ipsilateralLimb", "ipsilateral limb", (0.1, 0.65, 0.25)),
    ComponentRole("contralateralLimb", "contralateral limb", (0.95, 0.55, 0.05)),
    ComponentRole("iliacExtension", "iliac extension", (0.55, 0.25, 0.75)),
    ComponentRole("aorticCuff", "aortic cuff", (0.0, 0.6, 0.6)),
)

#: Name of the discrete colour table node made from COMPONENT_ROLES (Look.colorTable).
COMPONENT_COLOR_TABLE = "Stent graft components"

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
    # One colour per component role (codes 0-4, COMPONENT_ROLES); Apposition, Sealing, HealthyWall
    # and the other point data stay available to colour by in the Models module.
    "outputSimulatedStentModel": Look((0.95, 0.6, 0.15), 0.9, "ComponentRole", (0.0, len(COMPONENT_ROLES) - 1.0), None,
                                      colorTable=COMPONENT_COLOR_TABLE),
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


def componentColorTable():
    """The discrete colour table of the simulated graft's components: (index, name, (r, g, b, a)) per
    entry, index = the ComponentRole code. With the Look's scalar range 0 to n - 1 over n entries,
    Slicer's lookup maps each integer code to its own entry."""
    return [(index, role.name, role.color + (1.0,)) for index, role in enumerate(COMPONENT_ROLES)]
