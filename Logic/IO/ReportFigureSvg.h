/// \file ReportFigureSvg.h
/// The visual report's figures (ReportHtml.h), each written to `out` as one `<div class="figure">`
/// holding an inline SVG: the diameter profile of a vessel, the straightened view along one
/// aorta-to-iliac path, the cross-section at one sizing level. Lengths in the SVGs are mm in the
/// viewBox; the CT images are PNG data URIs in the report's window (ReportHtml.h).
///
/// Machine-readable marks: `data-profile` (vessel name), `data-straightened` ("right"/"left"),
/// each level line's `data-level` and `data-path-mm`, each landmark's `data-landmark`, each
/// simulated component's `data-component`, `data-from-mm`, `data-to-mm`; `data-section` and the
/// value spans' `data-name`/`data-value` on a cross-section.
/// \throws InputError from the PNG encoding (EncodePng.h).
#pragma once

#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "Pipeline/PlanRepair.h"
#include "Pipeline/PlanValues.h"
#include "Views/ReportFigures.h"

namespace sgp
{

/// Vessel `v`'s (0 aorta, 1 right, 2 left iliac) diameter profile: mean ring diameter with its
/// min–max band, the outer wall, the device's nominal diameter, the sizing `levels` on it.
void WriteProfilePlot(const RepairPlan& plan, int v, const std::vector<SizingLevel>& levels, std::ostream& out);

/// The straightened CT along one path, `side` "right" or "left": lumen and outer-wall edges,
/// levels, landmarks (in words), the simulated components' extents, a 10 mm scale bar.
void WriteStraightenedView(const StraightenedFigure& f, const char* side, std::ostream& out);

/// Where each component holds (issue 47): per component the deployment tolerance assessed, a small
/// crop of the straightened view around its edge as simulated (the main body's proximal edge on
/// the ipsilateral view, a limb's or extension's distal edge on its side's), the edge in red, the
/// band over which it may land and the plan still hold in green (over the CT, and as a solid bar
/// right of it), the tolerance ± dashed; the range in words below. 4 display px per mm. Marks:
/// `data-hold` (the component's index in the order list), `data-edge-mm` (path abscissa),
/// `data-band-from-mm`, `data-band-to-mm` (edge − above, edge + below) on the bar, `data-view-top-mm`
/// and `data-view-height-mm` on the SVG (its viewBox's vertical extent). Nothing when the tolerance
/// was not assessed.
void WriteHoldFigures(const RepairPlan& plan, const ReportFigures& figures, std::ostream& out);

/// The cross-section at one level: the measured ring, its shortest and longest diameter, the
/// outer contour, the level's outer and lumen values as the return file has them (`values`).
void WriteCrossSectionView(const CrossSectionFigure& f,
                           const std::map<std::string, PlanValue>& values,
                           std::ostream& out);

} // namespace sgp
