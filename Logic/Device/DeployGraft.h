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
/// **Fabric does not shorten** (issue 46 item 5). The rings are laid at the centerline's path
/// positions, and the fitted rings stay in their planes but their centres move: through an
/// off-centre lumen in a sac or round an angled neck the fitted graft runs straighter than the
/// centerline, so its own axis (GraftAxis: the fitted rings' centres) is shorter than the path it
/// was laid on. The pipeline (PlanRepair) therefore lays the configuration out again with every
/// path position moved to where its fabric, measured along the last fit's axis, reaches
/// (PlacedAlongTheGraft), until each side's axis is within FabricLengthToleranceMm of the fabric
/// ordered: the layout's components then hold where the simulated graft put them, the
/// configuration where the centerline length would have.
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

#include <array>
#include <functional>
#include <limits>
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
  /// Each component's ends as ordered (its fabric, mm from the proximal edge along its side: the
  /// configuration's positions before PlacedAlongTheGraft) — `components` hold where the simulated
  /// graft put them on the centerline — and the gate's end so; what the overlaps are measured on.
  std::vector<std::array<double, 2>> fabricMm;
  double fabricGateEndMm = std::numeric_limits<double>::quiet_NaN();
  bool configured = false;
  /// The path position of a point `s` mm along the iliac of `side`, and back.
  double PathOfIliac(int side, double iliacAbscissaMm) const;
  double IliacOfPath(int side, double pathMm) const;
};

/// The configured graft's layout (see the file comment), at `configuration`'s path positions;
/// `ordered`, the configuration as ordered when `configuration` is it placed along a graft's axis
/// (PlacedAlongTheGraft; nullptr: `configuration` itself), gives the fabric positions.
/// \throws InputError from BuildStentMesh.
GraftLayout LayOutGraft(const CenterlineTree& tree,
                        const Measurements& measurements,
                        const DeviceConfiguration& configuration,
                        double targetAbscissaMm,
                        StentMeshParams meshParams,
                        const DeviceConfiguration* ordered = nullptr);

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

/// The simulated graft's own axis on one side (issue 46 item 5): the centres of its fitted rings
/// (RingCentroid) — the trunk's from its first, then that side's leg's — joined by straight
/// segments. Per ring: its length along that axis from the first ring, and its path position (the
/// layout's: mm from the deployment target along the side's centerline path), both mm.
struct GraftAxis
{
  std::vector<double> lengthMm;
  std::vector<double> pathMm;
  double LengthMm() const { return lengthMm.empty() ? 0.0 : lengthMm.back(); }
  /// The path position where the axis has run `fabricMm` from its first ring: linear between rings;
  /// beyond its ends mm for mm along the path (a leg in its iliac follows the centerline).
  double PathAt(double fabricMm) const;
};

/// How close each side's graft axis must come to its fabric's length, mm, and in how many layouts
/// at most (DeployTheFabric: the first at the centerline's lengths, then along the last fit's axes).
constexpr double FabricLengthToleranceMm = 0.5;
constexpr int FabricLengthPasses = 4;

/// The axis of `side` (0 right, 1 left) of the surface V (#V×3, LPS mm) on `layout`'s mesh.
GraftAxis GraftAxisOf(const GraftLayout& layout, const Points& V, int side);

/// `configuration` with its path positions — every component's ends, the flow divider, the gate's
/// end, each side's covered length — moved to where its fabric reaches along each side's graft
/// axis `axes` (GraftAxis::PathAt of the position, read as fabric from the proximal edge): fabric
/// does not shorten, so a graft that runs straighter than the centerline through a sac reaches
/// further down its iliacs than the centerline length says. Lengths and overlaps stay the
/// catalogue's. The main body and the flow divider follow the ipsilateral axis, the gate's end the
/// contralateral one (the trunk's rings are on both).
DeviceConfiguration PlacedAlongTheGraft(const DeviceConfiguration& configuration, const std::array<GraftAxis, 2>& axes);

/// `configuration` (deployed with its target `targetShiftMm` further down the aorta than the target
/// `axes` were fitted from) placed along those axes: its positions read from the old target
/// (+ shift), placed (PlacedAlongTheGraft), and read from its own target again (− shift); the main
/// body's proximal edge stays at its target. The path between the two targets is exact; the fabric
/// there is taken as long as the path (the neck runs nearly straight at the target). What the
/// deployment tolerance (DeploymentTolerance.h) uses to deploy a displaced configuration in one
/// fit: a component moved a few millimetres does not change the graft's course.
DeviceConfiguration PlacedAlongShiftedGraft(const DeviceConfiguration& configuration,
                                            double targetShiftMm,
                                            const std::array<GraftAxis, 2>& axes);

struct FabricDeployment
{
  DeployedGraft graft;
  std::array<GraftAxis, 2> axes; ///< its right and left axes
  /// False when the fabric would carry a distal edge past the iliac in view: the graft stays where
  /// the last layout put it, shorter than its fabric.
  bool carried = true;
};

/// The configuration deployed at `targetAbscissaMm` with fabric that does not shorten (the file
/// comment): laid out (LayOutGraft) and fitted by `fit` (DeployGraft with the caller's wall field)
/// at the centerline's positions, then at PlacedAlongTheGraft of the last fit's axes, until each
/// side's axis is within FabricLengthToleranceMm of its fabric (at most FabricLengthPasses
/// layouts). \throws InputError from LayOutGraft.
FabricDeployment DeployTheFabric(const CenterlineTree& tree,
                                 const Measurements& measurements,
                                 const DeviceConfiguration& configuration,
                                 double targetAbscissaMm,
                                 const StentMeshParams& meshParams,
                                 const std::function<DeployedGraft(GraftLayout)>& fit);

/// Expands `layout` in `wall` (a field over the layout's reach: StentReach) with `params` (weights,
/// pressure, step; the balloon radii are the layout's nominal radii, per vertex).
DeployedGraft DeployGraft(GraftLayout layout,
                          const WallDistanceField& wall,
                          ActiveContourParams params,
                          const ProgressCallback& progress = {});

} // namespace sgp
