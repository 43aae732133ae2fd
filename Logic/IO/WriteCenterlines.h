/// \file WriteCenterlines.h
/// Writes the centerline tree for 3D Slicer: a model of polylines and a markups file of landmarks.
///
/// WriteCenterlines: one polyline cell per vessel (aorta, rightIliac, leftIliac, then the side
/// branches), cell data string array `Name`, point data `Radius` (mm, inscribed sphere) and
/// `Abscissa` (mm from the vessel's start), points in LPS mm, written by WriteModelLps (so the
/// file carries `SPACE` = `LPS`). Format from the extension: .vtp or .vtk.
///
/// WriteLandmarks: a Slicer markups JSON file (`.mrk.json`, schema v1.0.3), one Fiducial node
/// whose control points are the landmarks, labelled by name — an aortic branch's ostium described
/// by the evidence for its name (Centerline::evidence) — `coordinateSystem` LPS. Slicer loads
/// it as a point list with named points; a pointfile parameter declares it
/// `coordinateSystem="lps"`. With the plan's measurements, the landmarks the plan measures from —
/// and that a person may give instead (GivenLandmarks.h) — stand where the plan used them, under
/// the names of the CLI's inputs: `lowestRenalOstium` (the proximal site on the aortic centerline,
/// when known), `aorticBifurcation` (B), `rightInternalIliacOrigin`, `leftInternalIliacOrigin` (in
/// place of the skeleton's junctions `…IliacBifurcation`); each described "Given by the user." or
/// "Found: …" (how), so a panel can tell which to pass back when one is moved.
///
/// \throws InputError naming the path when it cannot be written.
#pragma once

#include <string>

#include "Centerlines/Centerlines.h"
#include "Measurement/MeasureAnatomy.h"

namespace sgp
{

void WriteCenterlines(const CenterlineTree& tree, const std::string& path);
void WriteLandmarks(const CenterlineTree& tree, const std::string& path, const Measurements* measurements = nullptr);

} // namespace sgp
