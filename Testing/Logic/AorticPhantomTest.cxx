// Tests of the synthetic phantom: its labels and intensities agree with its analytic geometry
// on any grid, and its truth is what the sizing definitions say.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>
#include <itkImageRegionIteratorWithIndex.h>

#include "Common/Errors.h"
#include "Common/ImageGeometry.h"
#include "Measurement/SectionTilt.h"
#include "Phantom/AorticPhantom.h"

namespace sgp
{
namespace
{

unsigned char LabelAt(const AorticPhantom& phantom, const Point3& lps)
{
  return phantom.labels->GetPixel(LpsToIndexInside(*phantom.labels, lps, "point"));
}

const PhantomVessel& Vessel(const AorticPhantom& phantom, const std::string& name)
{
  for (const PhantomVessel& v : phantom.truth.vessels)
    if (v.name == name)
      return v;
  throw std::runtime_error("no vessel " + name);
}

Point3 Landmark(const AorticPhantom& phantom, const std::string& name)
{
  for (const PhantomLandmark& l : phantom.truth.landmarks)
    if (l.name == name)
      return l.lps;
  throw std::runtime_error("no landmark " + name);
}

/// The voxel nearest a point can lie half a voxel diagonal away (0.64 mm on 0.8 × 0.8 × 1.0 mm),
/// so points are tested 1 mm inside and outside the analytic surface.
constexpr double probeMm = 1.0;

TEST(AorticPhantom, SacCrossSection_LabelsFollowAnalyticRadius)
{
  const AorticPhantom phantom = GenerateAorticPhantom(PhantomParams{});
  const PhantomVessel& aorta = Vessel(phantom, "aorta");
  for (Eigen::Index i = 0; i < aorta.axis.rows(); i += 7)
  {
    const Point3 c = aorta.axis.row(i).transpose();
    const double r = aorta.radiusMm[i];
    for (const Point3& dir : { Point3(1, 0, 0), Point3(0, -1, 0), Point3(0.6, 0.8, 0) })
    {
      if (c.z() < 2.0) // the bifurcation: the iliacs join here
        continue;
      EXPECT_EQ(LabelAt(phantom, c + (r - probeMm) * dir), LumenLabel) << "z " << c.z();
      const Point3 outside = c + (r + probeMm) * dir;
      if (c.z() < 115.0) // above, the renal (125–137 mm), mesenteric and coeliac ostia open the wall
      {
        EXPECT_EQ(LabelAt(phantom, outside), TissueLabel) << "z " << c.z();
      }
    }
  }
}

TEST(AorticPhantom, SizingTruth_FromTheRadiusProfile)
{
  PhantomParams p;
  p.neckLengthMm = 9.0; // (b) then lies 6 mm into the sac
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const PhantomSizing& s = phantom.truth.sizing;
  EXPECT_DOUBLE_EQ(s.proximalNeckDiameter, 22.0);
  EXPECT_GT(s.neckDiameter15mm, 22.0);
  // The sac's blend from 11 to 9 mm radius moves the maximum 0.9 mm off mid-sac: +0.023 mm.
  EXPECT_NEAR(s.maxAneurysmDiameter, 55.0, 0.03);
  EXPECT_DOUBLE_EQ(s.distalNeckMinDiameter, 18.0);
  // The neck ends where the diameter first exceeds (a) by 10 %: 11 mm radius → 12.1 mm, reached
  // at u = (sacTop − z) / 80 mm with 11 − 2u + 17.5 sin(πu) = 12.1 (the sac's blend and half-sine
  // bump) — solved here by bisection, independently of the generator's 1 µm stepping.
  double lo = 0.0, hi = 0.5;
  for (int i = 0; i < 60; ++i)
  {
    const double u = 0.5 * (lo + hi);
    (11.0 - 2.0 * u + 17.5 * std::sin(M_PI * u) < 12.1 ? lo : hi) = u;
  }
  EXPECT_NEAR(s.proximalNeckLength, 9.0 + 80.0 * lo, 0.002); // the generator steps 1 µm along the axis
  EXPECT_GT(s.proximalNeckLength, 10.0);                     // a 9 mm shoulder is a 10.6 mm neck by the 10 % rule
  EXPECT_DOUBLE_EQ(s.proximalSiteToBifurcationLength, 20.0 + 80.0 + 9.0);
  const PhantomVessel& aorta = Vessel(phantom, "aorta");
  EXPECT_NEAR(2 * aorta.radiusMm.maxCoeff(), s.maxAneurysmDiameter, 0.02); // 1 mm samples near the top
}

/// The flow divider where two straight iliac lumens of radius r part: in their frontal plane,
/// the point r from both axes between them — the meeting point of the axes' inner parallels,
/// solved here from the angles (x_side = s·sin θ_side outward, z = −s·cos θ_side).
Point3 ParallelsMeet(double rightDeg, double leftDeg, double r)
{
  const double a = rightDeg * M_PI / 180.0, b = leftDeg * M_PI / 180.0;
  // Inner normals (toward the midline) n_right = (cos a, −sin a), n_left = (−cos b, −sin b) in
  // (x, z); the point p with p·n_side = r for both.
  Eigen::Matrix2d n;
  n << std::cos(a), -std::sin(a), -std::cos(b), -std::sin(b);
  const Eigen::Vector2d xz = n.fullPivLu().solve(Eigen::Vector2d(r, r));
  return Point3(xz(0), 0.0, xz(1));
}

struct DividerCase
{
  const char* name;
  double rightDeg, leftDeg, distalNeckDiameterMm;
};

class FlowDividerTruth : public ::testing::TestWithParam<DividerCase>
{
};

TEST_P(FlowDividerTruth, WhereTheIliacLumensPart)
{
  const DividerCase c = GetParam();
  PhantomParams p;
  p.spacingMm = { 2.0, 2.0, 2.0 }; // the truth does not depend on the grid
  p.noiseSigmaHu = 0.0;
  p.rightCommonIliacAngleDeg = c.rightDeg;
  p.leftCommonIliacAngleDeg = c.leftDeg;
  p.distalNeckDiameterMm = c.distalNeckDiameterMm;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const PhantomSizing& s = phantom.truth.sizing;
  const Point3 divider = Landmark(phantom, "flowDivider");
  const double r = 6.0; // the 12 mm iliacs' lumen radius
  const Point3 expected = ParallelsMeet(c.rightDeg, c.leftDeg, r);
  const double capsule = c.distalNeckDiameterMm / 2; // the aorta's round end around B
  if (expected.norm() > capsule)
  {
    // The bisection stops within 1 nm in z; x is searched to 1e-7 mm (10 µm: about the flat
    // maximum's spread at the apex, where both tubes are equally far).
    EXPECT_NEAR(divider.z(), expected.z(), 1e-5);
    EXPECT_NEAR(divider.x(), expected.x(), 0.01);
  }
  else
  {
    // Below the aorta's round end: on the sphere of its radius around B, outside both iliacs.
    EXPECT_NEAR(divider.norm(), capsule, 1e-5);
    EXPECT_LT(divider.z(), expected.z());
  }
  EXPECT_DOUBLE_EQ(divider.y(), 0.0);
  EXPECT_NEAR(s.proximalSiteToFlowDividerLength - s.proximalSiteToBifurcationLength, -divider.z(), 1e-12);
  // From the divider to the internal iliac origin: the iliac's length less the divider's
  // projection on its (straight) axis.
  const double angles[2] = { c.rightDeg * M_PI / 180.0, c.leftDeg * M_PI / 180.0 };
  const double lengths[2] = { s.rightIliacLengthFromFlowDivider, s.leftIliacLengthFromFlowDivider };
  for (int side = 0; side < 2; ++side)
  {
    const Point3 axis((side == 0 ? -1.0 : 1.0) * std::sin(angles[side]), 0.0, -std::cos(angles[side]));
    EXPECT_NEAR(lengths[side], 55.0 - divider.dot(axis), 1e-9) << side;
  }
}

INSTANTIATE_TEST_SUITE_P(AorticPhantom,
                         FlowDividerTruth,
                         ::testing::Values(DividerCase{ "SymmetricY", 25.0, 25.0, 18.0 },
                                           DividerCase{ "UnequalAngles", 15.0, 40.0, 18.0 },
                                           DividerCase{ "WideDistalAorta", 25.0, 25.0, 30.0 }),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(AorticPhantom, NeckAngle_NeckAxisLeansAnteriorlyByBeta)
{
  PhantomParams p;
  p.neckAngleDeg = 40.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  EXPECT_DOUBLE_EQ(phantom.truth.sizing.neckAngleBetaDeg, 40.0);
  const PhantomVessel& aorta = Vessel(phantom, "aorta");
  // Above the sac's top (z = 100) the axis runs at 40° from the vertical, toward anterior (−y).
  const Point3 top = aorta.axis.row(0).transpose(), bend = Point3(0, 0, 100);
  const Eigen::Vector3d neck = (top - bend).normalized();
  EXPECT_NEAR(std::acos(neck.z()) * 180.0 / M_PI, 40.0, 1e-9);
  EXPECT_LT(neck.y(), 0.0);
  // Lengths along the aorta are kept: the site is 109 mm of axis above the bifurcation.
  const Point3 site = Landmark(phantom, "proximalImplantationSite");
  EXPECT_NEAR((site - bend).norm() + 100.0, phantom.truth.sizing.proximalSiteToBifurcationLength, 1e-9);
  // The labels follow the bent neck: on its axis is lumen, where the straight aorta would be is not.
  const Point3 onNeck = bend + 40.0 * neck, straight = bend + Point3(0, 0, 40.0);
  EXPECT_EQ(LabelAt(phantom, onNeck), LumenLabel);
  EXPECT_EQ(LabelAt(phantom, straight), TissueLabel); // 40·sin 40° = 26 mm from the neck's axis
}

/// (d)'s truth on a sac that narrows straight into B over iliacs wider than the distal aorta (issue
/// 46's sweep: 17.1 mm iliacs on a 15 mm distal aorta). Each iliac's tube starts at B with a round
/// end, so at a level h above B the lumen's section holds the aorta's disc of radius r(h) and the
/// cap's of √(ri² − h²), both centred on the axis: no section is narrower than the larger of the
/// two, whatever else the tubes add — a lower bound read off the radius profile alone, which the
/// profile's own minimum (15 mm at B) breaks by 2 mm. With iliacs narrower than the aorta at B the
/// caps lie inside its disc and the truth is the profile's minimum, exactly.
TEST(AorticPhantom, DistalNeckTruth_IliacCapsWiderThanTheAortaAtB)
{
  PhantomParams p;
  p.maxAneurysmDiameterMm = 58.0;
  p.aneurysmLengthMm = 77.0;
  p.distalNeckLengthMm = 0.0;
  p.distalNeckDiameterMm = 15.0;
  p.rightIliacDiameterMm = 17.0;
  p.leftIliacDiameterMm = 12.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const PhantomSizing& wide = phantom.truth.sizing;
  const PhantomVessel& aorta = phantom.truth.vessels.front();
  // r(h): the aorta's radius samples (every 1 mm of its axis, B its last point), interpolated.
  const auto radiusAt = [&](double h)
  {
    for (Eigen::Index k = aorta.axis.rows() - 1; k > 0; --k)
    {
      const double z0 = aorta.axis(k, 2), z1 = aorta.axis(k - 1, 2);
      if (h >= z0 && h <= z1)
        return aorta.radiusMm[k] + (h - z0) / (z1 - z0) * (aorta.radiusMm[k - 1] - aorta.radiusMm[k]);
    }
    return aorta.radiusMm[aorta.axis.rows() - 1];
  };
  const double cap = 8.5; // the right iliac's radius
  double bound = 1e9;
  for (double h = 0.0; h <= 30.0; h += 0.01)
    bound = std::min(bound, 2.0 * std::max(radiusAt(h), std::sqrt(std::max(0.0, cap * cap - h * h))));
  std::cout << "(d) truth " << wide.distalNeckMinDiameter << " mm, the discs' bound " << bound << " mm\n";
  // 0.05 mm: the radius samples' linear interpolation on the funnel's curve, and the truth's
  // bisection of each ray (0.1 µm) and its 0.1 mm levels.
  EXPECT_GE(wide.distalNeckMinDiameter, bound - 0.05);
  EXPECT_GT(wide.distalNeckMinDiameter, 15.0 + 1.0);
  p.rightIliacDiameterMm = 12.0;
  p.leftIliacDiameterMm = 11.0;
  EXPECT_DOUBLE_EQ(GenerateAorticPhantom(p).truth.sizing.distalNeckMinDiameter, 15.0);
}

TEST(AorticPhantom, NeckBend_BTruthIsTheNarrowestSectionNearTheKink)
{
  // A 15.5 mm neck: (b) lies on the neck 0.5 mm above the sac's top, where the neck bends. Straight
  // (β = 0) its truth is the neck's disc, 22 mm. At β = 55° the sac's tube reaches into that plane
  // (KinkSection.h: within about r·sin β of the kink), and the truth is the narrowest section of
  // the phantom's own lumen through the level. Cross-checked against the plan's own search
  // (FindNarrowestSection) on the phantom's sharp label map: two implementations, one analytic,
  // one on voxels, within 0.5 mm (0.8 mm pixels: up to half a pixel per edge, averaged over the
  // chords); the voxels' reading lies 0.9 mm from the disc's 22 mm, the analytic truth 0.7 mm.
  // On a 35 mm neck at β = 55° the level is 20 mm from the kink: the disc again.
  PhantomParams p;
  p.neckLengthMm = 15.5;
  EXPECT_NEAR(GenerateAorticPhantom(p).truth.sizing.neckDiameter15mm, 22.0, 1e-9);
  p.neckAngleDeg = 55.0;
  const AorticPhantom bent = GenerateAorticPhantom(p);
  const double b = bent.truth.sizing.neckDiameter15mm;
  auto lumen = LabelImage::New();
  lumen->CopyInformation(bent.labels);
  lumen->SetRegions(bent.labels->GetLargestPossibleRegion());
  lumen->Allocate(true);
  for (itk::ImageRegionIteratorWithIndex<LabelImage> it(lumen, lumen->GetLargestPossibleRegion()); !it.IsAtEnd(); ++it)
    it.Set(bent.labels->GetPixel(it.GetIndex()) == LumenLabel ? 1 : 0);
  const double beta = 55.0 * M_PI / 180.0;
  const Eigen::Vector3d neck(0.0, -std::sin(beta), std::cos(beta)); // upward along the neck
  const NarrowestSection s = FindNarrowestSection(*lumen, Point3(Point3(0.0, 0.0, 100.0) + 0.5 * neck), -neck, 30.0);
  EXPECT_NEAR(s.meanMm, b, 0.5);
  EXPECT_GT(std::abs(s.meanMm - 22.0), 0.5); // a truth left at the disc's value fails the cross-check
  EXPECT_GT(std::abs(b - 22.0), 0.3);        // and the truth itself moved off the disc's value
  p.neckLengthMm = 35.0;
  EXPECT_NEAR(GenerateAorticPhantom(p).truth.sizing.neckDiameter15mm, 22.0, 1e-9);
}

// The proximal site is the lower edge of the lowest renal's ostium on the lumen's wall (evar-sizing
// §2.4): found here by brute force — the lowest point, along the neck's axis, of the renal's lumen
// on the neck's wall, over a 0.05 mm grid — on a vertical neck (the renal perpendicular to it: its
// axis a renal radius above the site) and on leaning ones (the horizontal renal leaves the neck
// obliquely, so its lowest wall point lies lower: at 60° by 1.2 mm, which putting the renal's axis
// a radius above the site missed).
class RenalOstium : public ::testing::TestWithParam<double>
{
};

TEST_P(RenalOstium, LowerEdgeOnTheWallAtTheSite)
{
  PhantomParams p;
  p.neckAngleDeg = GetParam();
  p.sizeVoxels = { 40, 40, 40 }; // the truth is what is tested, not the volume
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const PhantomVessel& aorta = Vessel(phantom, "aorta");
  const PhantomVessel& renal = Vessel(phantom, "rightRenal");
  const Eigen::Vector3d up = (aorta.axis.row(0) - aorta.axis.row(1)).transpose().normalized();
  const Point3 origin = renal.axis.row(0).transpose();
  const Eigen::Vector3d along = (renal.axis.row(1) - renal.axis.row(0)).transpose().normalized();
  const double R = p.neckDiameterMm / 2, rho = renal.radiusMm[0];
  const Point3 site = Landmark(phantom, "proximalImplantationSite");
  // The grid spans the ostium: within 8 mm of where the renal's axis meets the wall.
  const Point3 centre = origin + along * R;
  const double step = 0.05;
  double lowest = 1e9;
  for (double i = -8; i <= 8; i += step)
    for (double j = -8; j <= 8; j += step)
      for (double k = -8; k <= 8; k += step)
      {
        const Point3 q = centre + Point3(i, j, k);
        const Eigen::Vector3d w = q - origin;
        const double radial = (w - w.dot(up) * up).norm();
        if (radial > R || radial < R - step) // on the neck's wall (a shell one grid step thick)
          continue;
        const double t = std::max(0.0, w.dot(along));
        if ((w - t * along).norm() > rho) // in the renal's lumen
          continue;
        lowest = std::min(lowest, w.dot(up));
      }
  const double siteHeight = (site - origin).dot(up);
  // Grid step plus shell thickness: the brute force finds the edge to 0.1 mm.
  EXPECT_NEAR(siteHeight, lowest, 0.1) << "beta " << GetParam();
  if (GetParam() == 0.0)
  {
    EXPECT_NEAR(siteHeight, -rho, 0.1); // perpendicular: a renal radius below its axis
  }
}

INSTANTIATE_TEST_SUITE_P(AorticPhantom, RenalOstium, ::testing::Values(0.0, 30.0, 60.0));

TEST(AorticPhantom, ObliqueFlippedGrid_RightIliacStaysOnPatientRight)
{
  PhantomParams p;
  p.spacingMm = { 0.9, 0.9, 1.5 };
  p.rightIliacDiameterMm = 16.0;
  p.leftIliacDiameterMm = 8.0;
  p.directionLps = (Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix() *
                    Eigen::Vector3d(-1, 1, -1).asDiagonal());
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const PhantomVessel& right = Vessel(phantom, "rightIliac");
  const PhantomVessel& left = Vessel(phantom, "leftIliac");
  const Point3 rightMid = right.axis.row(right.axis.rows() / 2).transpose();
  const Point3 leftMid = left.axis.row(left.axis.rows() / 2).transpose();
  EXPECT_LT(rightMid.x(), -10.0); // patient right is −x in LPS
  EXPECT_GT(leftMid.x(), 10.0);
  const Point3 forward(0, -1, 0); // perpendicular to both iliacs (they lie in the coronal plane)
  EXPECT_EQ(LabelAt(phantom, rightMid + (8.0 - probeMm) * forward), LumenLabel);
  EXPECT_EQ(LabelAt(phantom, leftMid + (8.0 - probeMm) * forward), TissueLabel);
  EXPECT_EQ(LabelAt(phantom, leftMid + (4.0 - probeMm) * forward), LumenLabel);
}

TEST(AorticPhantom, Intensities_LumenTissueBoneKidney)
{
  PhantomParams p;
  p.includeBone = true;
  p.includeKidneys = true;
  p.noiseSigmaHu = 0.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const auto hu = [&](const Point3& x) { return phantom.ct->GetPixel(LpsToIndexInside(*phantom.ct, x, "point")); };
  const double rMax = phantom.truth.sizing.maxAneurysmDiameter / 2;
  // Deep inside each structure the blur (σ 1 mm) leaves the nominal value to within 1 HU.
  EXPECT_NEAR(hu(phantom.truth.seedLps), 350, 1);
  EXPECT_NEAR(hu(Point3(0, -rMax - 15, 60)), 40, 1);
  const double columnCentre = rMax + 2.0 + 20.0;
  EXPECT_NEAR(hu(Point3(0, columnCentre, 60)), 250, 1);
  EXPECT_EQ(LabelAt(phantom, Point3(0, columnCentre, 60)), BoneLabel);
  EXPECT_EQ(LabelAt(phantom, Point3(0, rMax + 1.0, 60)), TissueLabel); // inside the 2 mm gap
  // The cortex (2 mm) against its analytic blur at the centre of the voxel nearest mid-cortex:
  // 40 + 1060·Φ(−d/σ) − 850·Φ(−(d + 2)/σ), d the signed distance to the column's surface.
  const auto index = LpsToIndexInside(*phantom.ct, Point3(0, rMax + 2.0 + 1.0, 60), "cortex");
  const Point3 centre = IndexToLps(*phantom.ct, index);
  const double d = std::hypot(centre.x(), centre.y() - columnCentre) - 20.0;
  const auto phi = [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
  EXPECT_NEAR(phantom.ct->GetPixel(index), 40 + 1060 * phi(-d) - 850 * phi(-(d + 2.0)), 0.5 + 1e-9); // rounding
  EXPECT_GT(phantom.ct->GetPixel(index), 700); // cortical bone as CT shows it
  EXPECT_EQ(LabelAt(phantom, Point3(-80, 15, 120)), KidneyLabel);
  EXPECT_NEAR(hu(Point3(-80, 15, 120)), 180, 1);
}

TEST(AorticPhantom, NoiseSeed_DeterminesTheVolume)
{
  PhantomParams p;
  p.spacingMm = { 2.0, 2.0, 2.0 };
  const AorticPhantom a = GenerateAorticPhantom(p), b = GenerateAorticPhantom(p);
  p.noiseSeed = 1;
  const AorticPhantom c = GenerateAorticPhantom(p);
  const long n = static_cast<long>(a.ct->GetLargestPossibleRegion().GetNumberOfPixels());
  long sameAB = 0, sameAC = 0;
  for (long i = 0; i < n; ++i)
  {
    sameAB += a.ct->GetBufferPointer()[i] == b.ct->GetBufferPointer()[i];
    sameAC += a.ct->GetBufferPointer()[i] == c.ct->GetBufferPointer()[i];
  }
  EXPECT_EQ(sameAB, n);
  EXPECT_LT(sameAC, n / 10); // σ 20 HU: two draws round to the same HU about 1.4 % of the time
}

TEST(AorticPhantom, SizeGiven_GridCentredOnAnatomy)
{
  PhantomParams p;
  p.sizeVoxels = { 300, 200, 250 };
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const auto size = phantom.ct->GetLargestPossibleRegion().GetSize();
  EXPECT_EQ(size[0], 300u);
  EXPECT_EQ(size[2], 250u);
  EXPECT_EQ(LabelAt(phantom, phantom.truth.seedLps), LumenLabel);
}

TEST(AorticPhantom, ParameterOutOfRange_InputErrorNamesIt)
{
  const std::vector<std::pair<std::string, std::function<void(PhantomParams&)>>> cases{
    { "spacingMm (k) is 0.10 mm", [](auto& p) { p.spacingMm[2] = 0.1; } },
    { "sizeVoxels (j) is 8.00 voxels",
      [](auto& p) {
        p.sizeVoxels = { 100, 8, 100 };
      } },
    { "sizeVoxels must be 0,0,0",
      [](auto& p) {
        p.sizeVoxels = { 100, 0, 0 };
      } },
    { "directionLps is not orthonormal", [](auto& p) { p.directionLps(0, 1) = 0.5; } },
    { "neckDiameterMm is 5.00 mm", [](auto& p) { p.neckDiameterMm = 5; } },
    { "neckLengthMm is 1.00 mm", [](auto& p) { p.neckLengthMm = 1; } },
    { "maxAneurysmDiameterMm is 20.00 mm; expected 22.0", [](auto& p) { p.maxAneurysmDiameterMm = 20; } },
    { "aneurysmLengthMm is 300.00 mm", [](auto& p) { p.aneurysmLengthMm = 300; } },
    { "distalNeckDiameterMm is 50.00 mm", [](auto& p) { p.distalNeckDiameterMm = 50; } },
    { "rightIliacDiameterMm is 2.00 mm", [](auto& p) { p.rightIliacDiameterMm = 2; } },
    { "leftIliacDiameterMm is 40.00 mm", [](auto& p) { p.leftIliacDiameterMm = 40; } },
    { "lumenHu is 50.00 HU", [](auto& p) { p.lumenHu = 50; } },
    { "tissueHu is 300.00 HU", [](auto& p) { p.tissueHu = 300; } },
    { "blurSigmaMm is 4.00 mm", [](auto& p) { p.blurSigmaMm = 4; } },
    { "noiseSigmaHu is -1.00 HU", [](auto& p) { p.noiseSigmaHu = -1; } },
    { "noiseSeed is -3.00", [](auto& p) { p.noiseSeed = -3; } },
    { "boneGapMm is 0.00 mm", [](auto& p) { p.boneGapMm = 0; } },
    { "kidneyHu is 500.00 HU", [](auto& p) { p.kidneyHu = 500; } },
    { "neckAngleDeg is 80.00 degrees", [](auto& p) { p.neckAngleDeg = 80; } },
  };
  for (const auto& [expected, plant] : cases)
  {
    PhantomParams p;
    plant(p);
    try
    {
      GenerateAorticPhantom(p);
      ADD_FAILURE() << "no error for " << expected;
    }
    catch (const InputError& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind(expected, 0), 0u) << e.what();
    }
  }
}

TEST(ImageGeometry, FlippedDirection_PointMapsToItsVoxel)
{
  auto image = LabelImage::New();
  LabelImage::RegionType region;
  region.SetSize({ { 10, 20, 30 } });
  image->SetRegions(region);
  LabelImage::DirectionType d;
  d.Fill(0);
  d(0, 0) = -1; // i grows toward patient right
  d(1, 1) = -1;
  d(2, 2) = 1;
  image->SetDirection(d);
  const double spacing[3] = { 1.0, 2.0, 3.0 };
  image->SetSpacing(spacing);
  const double origin[3] = { 5.0, 10.0, -20.0 };
  image->SetOrigin(origin);
  const auto index = LpsToIndexInside(*image, Point3(5.0 - 3.0, 10.0 - 4.0, -20.0 + 9.0), "P");
  EXPECT_EQ(index[0], 3);
  EXPECT_EQ(index[1], 2);
  EXPECT_EQ(index[2], 3);
  EXPECT_TRUE(IndexToLps(*image, index).isApprox(Point3(2.0, 6.0, -11.0)));
  const auto b = ImageBoundsLps(*image);
  EXPECT_DOUBLE_EQ(b[0], 5.0 - 9.5);
  EXPECT_DOUBLE_EQ(b[1], 5.5);
  try
  {
    LpsToIndexInside(*image, Point3(6.0, 0.0, 0.0), "Seed");
    ADD_FAILURE();
  }
  catch (const InputError& e)
  {
    EXPECT_STREQ(e.what(), "Seed (6.0, 0.0, 0.0) mm LPS lies outside the image (x -4.5 to 5.5, y -29.0 to 11.0, "
                           "z -21.5 to 68.5 mm LPS); place it inside this volume.");
  }
}

} // namespace
} // namespace sgp
