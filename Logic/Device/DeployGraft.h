/// \file DeployGraft.h
/// The simulated graft (issue 30): the configuration the plan orders (ConfigureDevice.h) built as
/// one bifurcated surface — the paper's trunk, legs and connection element (StentMesh.h,
/// Egger et al. 2007 figure 2) — from its deployment target down each side to that side's planned
/// distal edge, each vertex tagged with the component it belongs to, then expanded by the active
/// contour toward each component's nominal diameter and held where it was deployed (its rings stay
/// in their planes: ActiveContour.h), so it neither slides nor shortens.
///
/// **Layout.** The trunk's first ring lies exactly at the deployment target (along the aorta,
/// mm from its top), its last 3 × startRadiusMm above the aortic centerline's end; each leg runs
/// from 3 × startRadiusMm down its iliac to exactly the iliac abscissa of that side's distal edge
/// (ConfigureDevice's path position less L_AB and the iliac's start beyond B). Every vertex has:
///  - `side`, the path it lies on: a leg's own; on the trunk the right half of each ring (columns
///    n/4 … 3n/4, StentMesh.h) is the right path, the rest the left;
///  - `pathMm`, its ring's distance from the target along that path;
///  - `component`, the outermost component covering that position on that path (an inserted limb
///    lies inside the gate or leg it overlaps), and `innerComponent`, the one inserted into it there
///    (−1 outside overlaps) — indices into the component list;
///  - `nominalRadiusMm`, R for the balloon: half the outermost component's diameter there (a main
///    body's proximal diameter above its flow divider; below it its ipsilateral leg's, or on the
///    contralateral path its gate's — the contralateral limb's top where the catalogue gives no
///    gate diameter; a limb's or extension's distal diameter). Below the flow divider the real
///    device runs as two legs side by side in the aorta, which the single trunk tube stands for:
///    there R is the envelope of the two legs, ½ d_side (1 + |cos θ|) at angle θ from the ring's
///    left axis — d_side across (both legs side by side span d_right + d_left) and about half that
///    front to back.
///
/// **Not configured** (the catalogue lacks a length, a landmark is missing, a partial plan): the
/// graft is laid on the measure-mode mesh's own extents (StentMesh.h: trunk from the proximal site,
/// legs to 5 mm above the internal iliac origins) with the chosen diameters — main body on the
/// trunk, each limb on its leg — and `configured` false: it shows how the diameters fit, not the
/// device a surgeon orders (LayOutOnMeasureMesh).
///
/// Input: the labelled CenterlineTree and Measurements (B, the iliac offsets), the configuration
/// (its components' path extents), the deployment target's abscissa, the mesh parameters (ring
/// spacing, vertices per ring, start radius), all LPS mm. Errors: InputError (StentMesh) when a
/// distal edge lies beyond the iliac in view or a vessel is too short for two rings.
#pragma once

#include <string>
#include <vector>

#include "Device/ConfigureDevice.h"
#include "Measurement/MeasureAnatomy.h"
#include "Stent/ActiveContour.h"
#include "Stent/StentMesh.h"

namespace sgp
{

struct GraftLayout
{
  StentMesh mesh;
  /// The components the vertices refer to (the configuration's, or the stand-ins of an
  /// unconfigured graft), in chain order on each side: main body, then per side inward to outward.
  std::vector<ConfiguredComponent> components;
  Eigen::VectorXi side;            ///< #V, 0 right, 1 left
  Eigen::VectorXd pathMm;          ///< #V, mm from the deployment target along `side`'s path
  Eigen::VectorXi component;       ///< #V, index into `components`
  Eigen::VectorXi innerComponent;  ///< #V, the component inserted into it there, or −1
  Eigen::VectorXd nominalRadiusMm; ///< #V, R (mm)
  double targetAbscissaMm = 0.0;   ///< the trunk's first ring, along the aorta from its top
  double toBifurcationMm = 0.0;    ///< L_AB, along the aorta from the target
  std::array<double, 2> iliacStartBeyondBifurcationMm{ 0.0, 0.0 };
  double flowDividerMm = std::numeric_limits<double>::quiet_NaN(); ///< f on the path (NaN: not known)
  double gateEndMm = std::numeric_limits<double>::quiet_NaN();     ///< g on the contralateral path (NaN: not known)
  int ipsilateralSide = 0;                                         ///< the main body's side
  bool configured = false;
  /// The path position of a point `s` mm along the iliac of `side`, and back.
  double PathOfIliac(int side, double iliacAbscissaMm) const;
  double IliacOfPath(int side, double pathMm) const;
};

/// The configured graft's layout (see the file comment). \throws InputError from BuildStentMesh.
GraftLayout LayOutGraft(const CenterlineTree& tree,
                        const Measurements& measurements,
                        const DeviceConfiguration& configuration,
                        double targetAbscissaMm,
                        StentMeshParams meshParams);

/// An unconfigured graft on the measure-mode mesh: the main body (`diametersMm[0]`) on the trunk
/// and each limb (`diametersMm[1 + side]`; NaN: not sized, R the lumen's median ring diameter
/// `fallbackLegDiameterMm` so that the leg carries the connection element) on its leg, named after
/// `family`.
GraftLayout LayOutOnMeasureMesh(const StentMesh& mesh,
                                const Measurements& measurements,
                                const std::string& family,
                                const std::array<double, 3>& diametersMm,
                                const std::array<double, 2>& fallbackLegDiameterMm);

struct DeployedGraft
{
  GraftLayout layout;
  ActiveContourResult fit;
};

/// Expands `layout` in `wall` (a field over the layout's reach: StentReach) with `params` (weights,
/// pressure, step; the balloon radii are the layout's nominal radii, per vertex).
DeployedGraft DeployGraft(GraftLayout layout,
                          const WallDistanceField& wall,
                          ActiveContourParams params,
                          const ProgressCallback& progress = {});

} // namespace sgp
