/// \file AorticPhantom.h
/// A synthetic CT angiography volume of an aorto-iliac tree with an infrarenal aneurysm, with its
/// analytic ground truth — the oracle of the project's tests (STYLE.md B6).
///
/// Anatomy, in LPS mm with the aortic bifurcation at the origin and z pointing superior:
///  - **aorta** along the z axis from z = top down to the bifurcation at z = 0 — above the sac the
///    neck leans anteriorly by `neckAngleDeg` (β; the renal, mesenteric and coeliac arteries go
///    with it; lengths along the aorta are kept). Radius r(z), z the height along the aorta:
///    the neck radius above the sac; in the sac (length L, top at `sacTopZ`) a linear blend from
///    the neck radius to the distal-neck radius plus a half-sine bump that reaches
///    `maxAneurysmDiameterMm` near mid-sac — so the sac starts at a shoulder and the neck has a
///    definite end, as the neck-length rule needs; the distal-neck radius from the sac to the
///    bifurcation.
///  - **renal arteries** (radius `renalRadiusMm`, 3 mm): the right one at the lower level (it is the lowest renal;
///    the lower edge of its ostium is the proximal implantation site), the left 6 mm higher;
///    they run horizontally (laterally and slightly posteriorly) to the kidneys' hila. The patient's right is −x in
///    LPS. The right renal leaves the aortic axis where its ostium's lowest point on the lumen's
///    wall lies exactly at the site: 3 mm above it on a vertical neck, more on a leaning one
///    (β > 0), where the horizontal renal leaves the neck's axis obliquely (+1.2 mm at β = 60°).
///  - **superior mesenteric** and **coeliac** arteries leave anteriorly (−y) above the renals.
///  - **common iliacs** leave the bifurcation 25° from the midline (`rightCommonIliacAngleDeg`,
///    `leftCommonIliacAngleDeg`), `rightCommonIliacLengthMm` /
///    `leftCommonIliacLengthMm` long (55 mm by default), then split into **external** (continuing
///    caudally) and **internal** iliacs (posterior and lateral).
///  - optional **vertebral column** behind the aorta (cortical shell 2 mm at 1100 HU around
///    cancellous bone at 250 HU), placed `boneGapMm` from the sac at its widest.
///  - optional **kidneys**, ellipsoids of `kidneyHu` at the ends of the renal arteries.
///
/// A vessel is the set of points whose distance d to its axis polyline is below r(s) at the
/// closest axis point s, so every cross-section perpendicular to a straight piece of axis is a
/// disc of exactly r(s). The image is tissueHu plus, per structure, its contrast times
/// Φ(−sd/blurSigmaMm) (sd: signed distance to its surface; Φ: normal CDF), i.e. the analytic
/// blur of a locally flat edge by a Gaussian point-spread function, taking the brightest structure
/// where they meet — except that with a wall the vessel's own layers compose linearly, as a
/// scanner blurs attenuation: wall, thrombus and lumen are nested solids, each adding its step
/// over the layer around it times Φ (PhantomRaster.h), so the lumen's blurred edge meets the wall
/// or thrombus that borders it and its tail reaches through a thin wall into the fat (issue 32);
/// the neighbour pads, kidneys and bone are still the brightest where they meet. Then white
/// Gaussian noise from std::mt19937(noiseSeed). The truth labels are the signs of sd at the voxel
/// centres.
///
/// Grid: any spacing and orthonormal direction (flips allowed); the extent holds the anatomy with
/// a 10 mm margin unless `sizeVoxels` is given (then centred on the anatomy).
///
/// Errors: InputError for a parameter out of range or a non-orthonormal direction, naming it.
/// Complexity: linear in the voxels of each structure's bounding box, plus the whole grid for
/// noise.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "Common/Types.h"

namespace sgp
{

/// A side of a vessel's cross-section (the patient's), as an angle from anterior toward the left.
enum class PhantomSide
{
  Anterior,  ///< 0°
  Left,      ///< 90°
  Posterior, ///< 180°
  Right      ///< 270°
};

double SideDegrees(PhantomSide side);
/// "anterior", "left", "posterior", "right"; \throws InputError for any other text.
PhantomSide ParsePhantomSide(const std::string& text, const std::string& parameter);

/// Parameters; defaults equal the XML defaults of SyntheticAorticPhantom (a test compares them).
struct PhantomParams
{
  std::array<double, 3> spacingMm{ 0.8, 0.8, 1.0 };
  /// Columns are the unit directions of the i, j, k axes in LPS.
  Eigen::Matrix3d directionLps = Eigen::Matrix3d::Identity();
  std::array<int, 3> sizeVoxels{ 0, 0, 0 }; ///< 0,0,0 = fit the anatomy

  double neckDiameterMm = 22.0;
  double neckLengthMm = 25.0; ///< lowest renal lower edge to the sac's top (the shoulder)
  double maxAneurysmDiameterMm = 55.0;
  double aneurysmLengthMm = 80.0;
  double distalNeckDiameterMm = 18.0;
  double rightIliacDiameterMm = 12.0;
  double leftIliacDiameterMm = 12.0;
  /// Aortic bifurcation to the internal iliac origin, mm, in [10, 80].
  double rightCommonIliacLengthMm = 55.0;
  double leftCommonIliacLengthMm = 55.0;
  double neckAngleDeg = 0.0; ///< β: the neck leans anteriorly by this from the sac's vertical axis

  double lumenHu = 350.0;
  double tissueHu = 40.0;
  double blurSigmaMm = 1.0;
  double noiseSigmaHu = 20.0;
  int noiseSeed = 0;
  bool includeBone = false;
  double boneGapMm = 2.0;
  bool includeKidneys = false;
  double kidneyHu = 180.0;

  // The vessel wall (AorticWall.h). With wallThicknessMm > 0 the diameters above are outer-wall
  // diameters and the lumen lies inside the wall and the thrombus; with every option at its
  // default the phantom is the lumen-only phantom. HU defaults from vessel-wall.md §2.
  double wallThicknessMm = 0.0;                     ///< aorta and iliacs; 0 = no wall; [0, 4]
  double wallHu = 70.0;                             ///< slightly enhancing wall, 60–90 HU
  double thrombusMaxThicknessMm = 0.0;              ///< sac ILT at its thickest (mid-sac); 0 = none; [0, 40]
  bool thrombusConcentric = false;                  ///< false: eccentric crescent, the lumen off-centre
  PhantomSide thrombusSide = PhantomSide::Anterior; ///< the ILT's thick side (anterior in ≈ 50 %)
  double thrombusHu = 45.0;                         ///< ILT, 30–60 HU
  double neckThrombusThicknessMm = 0.0;             ///< crescent in the lower neck; 0 = none; [0, 15]
  double neckThrombusLengthMm = 10.0;               ///< from the sac's top upward; [3, 60]
  PhantomSide neckThrombusSide = PhantomSide::Anterior;
  /// Draw the neck's lumen level by level as the truth's discs (AorticWall::NeckLumenSignedDistance)
  /// rather than as the tube round its centre curve, which puts the neck thrombus's onset about
  /// 2.6 mm lower than the truth says (issue 46 item 2). Off by default: on, the thrombus phantom's
  /// outer (b) — its plane on a 120° neck plaque's blurred end — moves over its bar (+1.1 mm on
  /// 1 mm slices; VesselWallPlanTest), a real-scan class not yet fixed (docs/limitations.md).
  bool neckLumenPerLevel = false;
  double calcificationHu = 800.0;      ///< plaque after blurring, 600–1200 HU
  double sacCalcificationArcDeg = 0.0; ///< an arc over the sac's middle third; 0 = none; [0, 360]
  PhantomSide sacCalcificationSide = PhantomSide::Posterior;
  double neckCalcificationArcDeg = 0.0; ///< an arc from the site down 15 mm; 0 = none; [0, 360]
  PhantomSide neckCalcificationSide = PhantomSide::Left;
  bool includePsoas = false; ///< both psoas muscles against the sac, posterolateral
  double psoasHu = 45.0;
  bool includeIvc = false; ///< unenhanced IVC pressed against the sac's right side
  double ivcHu = 50.0;
  double ivcArcDeg = 80.0; ///< the IVC's contact arc on the aorta's right side; [72, 180]
  /// The sac's outer cross-section as an ellipse: its major semi-axis the profile's radius ×
  /// (1 + (sacAxisRatio − 1)·sin(π u)) (u from the sac's top to its bottom, 0…1), its minor the
  /// profile's radius; the lumen stays the round one and thrombus fills the rest. Needs sac
  /// thrombus; [1, 1.5] (1: round).
  double sacAxisRatio = 1.0;
  PhantomSide sacMajorAxis = PhantomSide::Left; ///< left or right: transverse; anterior or posterior: AP
  bool includeDuodenum = false;                 ///< duodenum crossing in front of the neck
  double duodenumHu = 120.0;                    ///< bowel wall in the arterial phase
  bool includeLeftRenalVein = false;            ///< enhancing LRV crossing in front of the aorta below the SMA
  double leftRenalVeinHu = 200.0;
  double bolusGradientHuPerCm = 0.0; ///< lumen HU change per cm upward from the site; [−10, 10]

  // Branch variants (issue 31). The SyntheticAorticPhantom CLI sets renalRadiusMm (as a diameter),
  // the common iliacs' angles, distalNeckLengthMm and which internal iliacs are drawn (issue 46's
  // sweep); the rest are library-only. With every one at its default the phantom is the one above,
  // voxel for voxel.
  double aortaAboveSiteMm = 80.0; ///< the aorta's top above the site, mm; [20, 400] (250+: into the chest)
  bool includeRenals = true;      ///< false: no renal artery (the truth's site stays where it was)
  double renalRadiusMm = 3.0;     ///< both renals' lumen radius (ostia of 4–10 mm across), mm; [2, 5]
  double renalDescentDeg = 0.0;   ///< both renals run down by this from horizontal; [0, 65]
  /// Both renals turned about the vertical from their lateral course: positive anterior (−y),
  /// negative posterior; [−60, 60].
  double renalTakeoffDeg = 0.0;
  double renalStubMm = 0.0; ///< 0: renals to the hila; else each ends this far outside the aortic lumen; [0, 60]
  /// 0: none; else each renal divides this far outside the aortic lumen into an upper and a lower
  /// branch (radius 2.2 mm, ±25° from its course in the vertical plane); [0, 40].
  double renalDivisionMm = 0.0;
  /// 0: none; else a right accessory renal (radius 2 mm, horizontal, lateral) this far above (+) or
  /// below (−) the right renal's origin, mm; |value| in [8, 40].
  double accessoryRenalOffsetMm = 0.0;
  bool includeInferiorMesenteric = false;  ///< IMA (radius 1.75 mm) from the sac's front, running down and left
  bool parallelSuperiorMesenteric = false; ///< the SMA turns down at once and runs parallel to the aorta, in front
  /// Each common iliac bends outward (laterally, in its frontal plane) by this 10 mm below the
  /// aortic bifurcation — a kinked start; its length along the axis is kept; [0, 60].
  double commonIliacKinkDeg = 0.0;
  /// Each common iliac's angle from the midline (in the frontal plane), degrees; [10, 60]. Unequal
  /// angles make a bifurcation that is not a symmetric Y (issue 46 item 7).
  double rightCommonIliacAngleDeg = 25.0;
  double leftCommonIliacAngleDeg = 25.0;
  /// The sac's bottom above the aortic bifurcation, mm; [0, 40]. 0: the sac narrows straight into
  /// the bifurcation, and with a wide distalNeckDiameterMm the iliacs leave from the sac's floor.
  double distalNeckLengthMm = 20.0;
  bool posteriorInternalIliac = false; ///< the internal iliacs leave from the back (mostly posterior, down)
  /// A branch as wide as the internal iliac leaving the right common iliac this far below the
  /// aortic bifurcation, running out, back and a little down for 35 mm (a large iliolumbar or an
  /// early posterior trunk): a labelling that takes the first wide branch for the internal iliac
  /// takes it. Not in the truth's landmarks (the internal iliac stays where it was); 0 = none;
  /// [0, the right common iliac's length − 15].
  double rightIliacDecoyBranchMm = 0.0;
  /// false: that side's internal iliac is not drawn — cut off, as on a vessel surface that ends at
  /// the common iliac's division; the common iliac runs on into the external iliac alone. The
  /// truth's internal iliac values stay those of the division.
  bool rightInternalIliac = true;
  bool leftInternalIliac = true;
};

/// Labels of the truth image.
enum PhantomLabel : unsigned char
{
  TissueLabel = 0,
  LumenLabel = 1,
  BoneLabel = 2,
  KidneyLabel = 3,
  WallLabel = 4,
  ThrombusLabel = 5,
  CalciumLabel = 6,
  PsoasLabel = 7,
  IvcLabel = 8,
  DuodenumLabel = 9,
  RenalVeinLabel = 10,
  PhantomLabelCount = 11
};

/// One vessel's analytic centerline, sampled every 1 mm from its start (points LPS mm, n×3) with
/// the lumen radius of the cross-section there (mm) and the radius of the largest sphere centred
/// there that fits in the vessel alone (mm; smaller than the cross-section's on the flanks of the
/// sac, where the wall slopes toward the centre).
struct PhantomVessel
{
  std::string name;
  Points axis;
  Eigen::VectorXd radiusMm;
  Eigen::VectorXd inscribedRadiusMm;
  Eigen::VectorXd outerRadiusMm; ///< the aorta with a wall: the outer wall's round profile there; else empty
};

struct PhantomLandmark
{
  std::string name;
  Point3 lps;
};

/// The sizing truth, after Egger et al. (2007) section 2.2 and the lengths the IFUs check (mm).
struct PhantomSizing
{
  double proximalNeckDiameter = 0.0;  ///< (a) at the lower edge of the lowest renal ostium
  double neckDiameter15mm = 0.0;      ///< (b) 15 mm inferior to (a) along the aorta
  double maxAneurysmDiameter = 0.0;   ///< (c)
  double distalNeckMinDiameter = 0.0; ///< (d) between the sac and the bifurcation
  double rightIliacDiameter = 0.0;    ///< (e) common iliac
  double leftIliacDiameter = 0.0;     ///< (f)
  /// Lowest renal lower edge to the first level where the diameter exceeds (a) by 10 % (the
  /// clinical rule; neckLengthMm plus the shoulder's rise to 110 % of the neck)
  double proximalNeckLength = 0.0;
  double proximalSiteToBifurcationLength = 0.0;
  double rightIliacLength = 0.0; ///< aortic bifurcation to the right internal iliac origin
  double leftIliacLength = 0.0;
  /// The flow divider (the "flowDivider" landmark): the highest point, in the common iliacs'
  /// frontal plane between their axes, outside every lumen as drawn — where the lumen divides
  /// (found by bisection to 1 µm on the tubes' own signed distances). Site to it along the aorta
  /// (the aorta is vertical below the sac: the site-to-bifurcation length plus its depth below B),
  /// and from it to each internal iliac origin along the common iliac's axis (the origin's
  /// arc length less that of the flow divider's nearest axis point), mm.
  double proximalSiteToFlowDividerLength = 0.0;
  double rightIliacLengthFromFlowDivider = 0.0;
  double leftIliacLengthFromFlowDivider = 0.0;
  double rightInternalIliacRadius = 0.0; ///< the internal iliac's lumen radius (its ostium's half width)
  double leftInternalIliacRadius = 0.0;
  /// Aortic bifurcation to the internal iliac ostium's upstream edge, along the common iliac's
  /// (last) axis piece, mm: where the internal iliac's lumen first shows beside the common and
  /// external iliacs' (its mouth as drawn). The branch leaves from the common iliac's end, whose
  /// round end and the external iliac hide its first millimetres: 2.6 mm past the division on the
  /// default anatomy, 0.3 mm with posteriorInternalIliac, up to 0.3 mm before it on a kinked one.
  double rightInternalIliacOstium = 0.0;
  double leftInternalIliacOstium = 0.0;
  double neckAngleBetaDeg = 0.0; ///< β, angle between the neck's axis and the sac's

  // With a wall (PhantomParams::wallThicknessMm > 0) the diameters above are of the lumen, these
  // of the outer wall, perpendicular to the vessel axis; without one both are the same vessel.
  double outerProximalNeckDiameter = 0.0;  ///< (a)
  double outerNeckDiameter15mm = 0.0;      ///< (b)
  double outerMaxAneurysmDiameter = 0.0;   ///< (c), Dmax outer to outer
  double outerDistalNeckMinDiameter = 0.0; ///< (d)
  double outerRightIliacDiameter = 0.0;    ///< (e)
  double outerLeftIliacDiameter = 0.0;     ///< (f)
  double thrombusVolumeMl = 0.0;           ///< site to bifurcation
  double maxThrombusThicknessMm = 0.0;     ///< over the same stretch
  double neckThrombusArcPercent = 0.0;     ///< largest share, site to 15 mm below, thicker than 2 mm
  /// The seal a graft can get on healthy wall, mm: from the site down to the first level where
  /// thrombus thicker than 2 mm lies under more than 10 % of the circumference (a ring seals when 90 %
  /// of it does: FitCheck.h) or the outer diameter exceeds (a) by 10 % (the neck length).
  double healthyNeckLength = 0.0;
  /// From the site down to the first level where thrombus thicker than 2 mm lies under at least a
  /// quarter of the circumference, mm; infinity when it never does above the sac.
  double neckThrombusBelowSite = 0.0;
  double neckCalcificationArcPercent = 0.0; ///< largest share, site to 15 mm below
};

struct PhantomTruth
{
  std::vector<PhantomVessel> vessels; ///< aorta first, then iliacs and side branches
  std::vector<PhantomLandmark> landmarks;
  PhantomSizing sizing;
  Point3 seedLps = Point3::Zero(); ///< in the aneurysm lumen, 0.5 mm off the axis
  double lumenVolumeMl = 0.0;      ///< lumen voxels × voxel volume
};

struct AorticPhantom
{
  CtImage::Pointer ct;        ///< HU
  LabelImage::Pointer labels; ///< PhantomLabel per voxel, same grid
  PhantomTruth truth;
};

/// Checks every range of `params`; \throws InputError naming the parameter and its value.
void ValidatePhantomParams(const PhantomParams& params);

/// Builds the phantom; see the file comment.
AorticPhantom GenerateAorticPhantom(const PhantomParams& params, const ProgressCallback& progress = {});

} // namespace sgp
