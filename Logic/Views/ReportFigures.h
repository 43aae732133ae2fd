/// \file ReportFigures.h
/// What the visual planning report draws, computed from a RepairPlan and the CT: the straightened
/// views aorta → right iliac and aorta → left iliac with the edges, levels, landmarks and graft
/// marked, and the cross-section at each of the sizing levels (a)–(f) with the measured ring and
/// the outer contour. The HTML writer (IO/ReportHtml.h) only formats these.
///
/// Coordinates: a straightened view's marks are path abscissae (mm from the aorta's top in the
/// scan, VesselPath.h) and signed offsets along the row's u (mm, + to the patient's left, the
/// image's right); a cross-section's points are (u, v) offsets from its centre in mm (u the
/// patient's left, v posterior: ResliceCt.h). Levels sit at the Measurement's own abscissa (the
/// ring the value was read on: (a)–(d); the middle of the landing zone: (e), (f)).
///
/// With a simulated graft, each component's simulated extent on the straightened views and the
/// graft's 3-D views (SceneMeshes.h).
///
/// Needs a plan that reached the measurements (RepairPlan::Reached(Measurements)) and the CT the
/// plan was made from (or a crop of it that holds ±halfWidthMm around every centerline; samples
/// outside it read −1024 HU). A level that was not measured (NaN) has no cross-section and no mark.
/// Errors: InputError from SampleVesselPath / ResliceCt on degenerate centerlines.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "Pipeline/PlanRepair.h"
#include "Views/RenderScene.h"
#include "Views/ResliceCt.h"
#include "Views/VesselPath.h"

namespace sgp
{

struct ReportFigureParams
{
  double pixelMm = 0.5;       ///< straightened views and cross-sections
  double halfWidthMm = 40.0;  ///< of a straightened view, across the path
  double sectionHalfMm = 0.0; ///< of a cross-section; 0: 1.4 × the level's outer (else lumen) radius + 10 mm
};

/// A point on a straightened view: its path abscissa and, for edges, the offset along u.
struct PathMark
{
  std::string label; ///< "(a)", "rightRenalOstium", …
  double pathMm = 0.0;
  double offsetMm = 0.0;
};

/// One sizing level: which values it carries and where.
struct SizingLevel
{
  std::string label;     ///< "(a)" … "(f)"
  std::string outerName; ///< the outer-wall return value, e.g. proximalNeckDiameter
  std::string lumenName; ///< the lumen one, e.g. proximalNeckLumenDiameter
  std::string vessel;    ///< aorta, rightIliac, leftIliac
  double abscissaMm = std::numeric_limits<double>::quiet_NaN(); ///< along `vessel`
};

/// A component's simulated extent along a straightened view's path.
struct ComponentExtent
{
  std::string label; ///< "main body", "left contralateral limb", …
  Eigen::Vector3d rgb = Eigen::Vector3d::Zero();
  double fromMm = 0.0; ///< path abscissae
  double toMm = 0.0;
  std::size_t component = 0; ///< index into the simulated graft's components (the order list's, when configured)
};

struct StraightenedFigure
{
  VesselPath path;
  PlaneImage image;
  /// The edges at the image's left (−u) and right (+u) side per traced plane: lumen and outer wall.
  std::vector<PathMark> lumenLeft, lumenRight, outerLeft, outerRight;
  std::vector<PathMark> levels;    ///< (a)–(f) on this path
  std::vector<PathMark> landmarks; ///< ostia, the aortic bifurcation, this side's internal iliac origin
  /// The simulated graft's extent (its first trunk ring to this leg's last ring); NaN: none simulated.
  double graftStartMm = std::numeric_limits<double>::quiet_NaN();
  double graftEndMm = std::numeric_limits<double>::quiet_NaN();
  /// Each component on this side's path as simulated: from the first to the last ring of the fitted
  /// surface that carries it (as the outer component or the one inserted), the rings' centroids
  /// projected onto the path — not the planned extent.
  std::vector<ComponentExtent> components;
};

struct CrossSectionFigure
{
  SizingLevel level;
  PlaneImage image;
  std::vector<Eigen::Vector2d> ring;  ///< the measured ring (measure-mode fit), (u, v) mm; empty: none
  std::vector<Eigen::Vector2d> outer; ///< the outer-wall contour there, (u, v) mm; empty: none traced
  std::array<Eigen::Vector2d, 2> minCaliper{}, maxCaliper{}; ///< the ring's shortest and longest diameter
  bool hasCalipers = false;
};

struct ReportFigures
{
  std::array<StraightenedFigure, 2> straightened; ///< right, left
  std::vector<CrossSectionFigure> sections;       ///< (a)–(f) that were measured, in order
  /// The simulated graft in the vessel from the front and from the left (RenderScene.h: the lumen
  /// and outer wall translucent, the components in their colours), within 25 mm of the graft;
  /// empty when no graft was simulated.
  std::vector<RenderedImage> graftViews;
  std::vector<std::string> graftViewNames;
};

/// The six sizing levels of `measurements` (NaN abscissa where not measured).
std::vector<SizingLevel> SizingLevels(const Measurements& measurements);

/// See the file comment.
ReportFigures BuildReportFigures(const RepairPlan& plan, const CtImage& ct, const ReportFigureParams& params = {});

} // namespace sgp
