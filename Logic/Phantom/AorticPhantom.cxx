#include "Phantom/AorticPhantom.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <random>
#include <unordered_map>

#include <Eigen/Dense>

#include "Common/CheckRange.h"
#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/HugePages.h"
#include "Phantom/AorticWall.h"
#include "Phantom/PhantomAnatomy.h"
#include "Phantom/PhantomRaster.h"

namespace sgp
{

using namespace phantom;

void ValidatePhantomParams(const PhantomParams& p)
{
  const auto check = CheckRange;
  const char* axes[3] = { "i", "j", "k" };
  int sized = 0;
  for (int a = 0; a < 3; ++a)
  {
    check(std::string("spacingMm (") + axes[a] + ")", p.spacingMm[a], 0.2, 5.0, "mm");
    if (p.sizeVoxels[a] != 0)
    {
      check(std::string("sizeVoxels (") + axes[a] + ")", p.sizeVoxels[a], 16, 2048, "voxels");
      ++sized;
    }
  }
  if (sized != 0 && sized != 3)
  {
    throw InputError("sizeVoxels must be 0,0,0 (fit the anatomy) or three sizes; got " +
                     std::to_string(p.sizeVoxels[0]) + "," + std::to_string(p.sizeVoxels[1]) + "," +
                     std::to_string(p.sizeVoxels[2]) + ".");
  }
  const double orthonormalError = (p.directionLps.transpose() * p.directionLps - Eigen::Matrix3d::Identity()).norm();
  if (!(orthonormalError < 1e-4))
  {
    throw InputError("directionLps is not orthonormal (|DᵀD − I| = " + FormatNumber(orthonormalError, 4) +
                     "); give three unit, mutually perpendicular axis directions.");
  }
  check("neckDiameterMm", p.neckDiameterMm, 12, 40, "mm");
  check("neckLengthMm", p.neckLengthMm, 2, 60, "mm");
  check("maxAneurysmDiameterMm", p.maxAneurysmDiameterMm, std::max(p.neckDiameterMm, p.distalNeckDiameterMm), 100,
        "mm");
  check("aneurysmLengthMm", p.aneurysmLengthMm, 20, 200, "mm");
  check("distalNeckDiameterMm", p.distalNeckDiameterMm, 10, 40, "mm");
  check("rightIliacDiameterMm", p.rightIliacDiameterMm, 5, 30, "mm");
  check("leftIliacDiameterMm", p.leftIliacDiameterMm, 5, 30, "mm");
  check("rightCommonIliacLengthMm", p.rightCommonIliacLengthMm, 10, 80, "mm");
  check("leftCommonIliacLengthMm", p.leftCommonIliacLengthMm, 10, 80, "mm");
  check("lumenHu", p.lumenHu, 100, 1000, "HU");
  check("tissueHu", p.tissueHu, -200, 100, "HU");
  check("blurSigmaMm", p.blurSigmaMm, 0, 3, "mm");
  check("noiseSigmaHu", p.noiseSigmaHu, 0, 200, "HU");
  check("noiseSeed", p.noiseSeed, 0, 2147483647.0, "");
  check("boneGapMm", p.boneGapMm, 0.5, 50, "mm");
  check("kidneyHu", p.kidneyHu, 50, 400, "HU");
  check("neckAngleDeg", p.neckAngleDeg, 0, 75, "degrees");
  check("wallThicknessMm", p.wallThicknessMm, 0, 4, "mm");
  check("wallHu", p.wallHu, -200, 400, "HU");
  check("thrombusMaxThicknessMm", p.thrombusMaxThicknessMm, 0, 40, "mm");
  check("thrombusHu", p.thrombusHu, -200, 400, "HU");
  check("neckThrombusThicknessMm", p.neckThrombusThicknessMm, 0, 15, "mm");
  check("neckThrombusLengthMm", p.neckThrombusLengthMm, 3, 60, "mm");
  check("calcificationHu", p.calcificationHu, 200, 3000, "HU");
  check("sacCalcificationArcDeg", p.sacCalcificationArcDeg, 0, 360, "degrees");
  check("neckCalcificationArcDeg", p.neckCalcificationArcDeg, 0, 360, "degrees");
  check("psoasHu", p.psoasHu, -200, 400, "HU");
  check("ivcHu", p.ivcHu, -200, 400, "HU");
  check("duodenumHu", p.duodenumHu, -200, 400, "HU");
  check("leftRenalVeinHu", p.leftRenalVeinHu, -200, 400, "HU");
  check("ivcArcDeg", p.ivcArcDeg, 72, 180, "degrees");
  check("sacAxisRatio", p.sacAxisRatio, 1, 1.5, "");
  check("bolusGradientHuPerCm", p.bolusGradientHuPerCm, -10, 10, "HU/cm");
  check("aortaAboveSiteMm", p.aortaAboveSiteMm, 20, 400, "mm");
  check("renalRadiusMm", p.renalRadiusMm, 2, 5, "mm");
  check("renalDescentDeg", p.renalDescentDeg, 0, 65, "degrees");
  check("renalTakeoffDeg", p.renalTakeoffDeg, -60, 60, "degrees");
  check("renalStubMm", p.renalStubMm, 0, 60, "mm");
  check("renalDivisionMm", p.renalDivisionMm, 0, 40, "mm");
  check("accessoryRenalOffsetMm", p.accessoryRenalOffsetMm, -40, 40, "mm");
  check("commonIliacKinkDeg", p.commonIliacKinkDeg, 0, 60, "degrees");
  check("rightCommonIliacAngleDeg", p.rightCommonIliacAngleDeg, 10, 60, "degrees");
  check("leftCommonIliacAngleDeg", p.leftCommonIliacAngleDeg, 10, 60, "degrees");
  check("distalNeckLengthMm", p.distalNeckLengthMm, 0, 40, "mm");
  check("rightIliacDecoyBranchMm", p.rightIliacDecoyBranchMm, 0, std::max(0.0, p.rightCommonIliacLengthMm - 15.0),
        "mm");
  if (p.accessoryRenalOffsetMm != 0.0 && std::abs(p.accessoryRenalOffsetMm) < 8.0)
    throw InputError("accessoryRenalOffsetMm is " + FormatNumber(p.accessoryRenalOffsetMm) +
                     " mm; expected 0 (none) or at least 8 mm above or below the right renal.");
  const bool needsWall = p.thrombusMaxThicknessMm > 0 || p.neckThrombusThicknessMm > 0 ||
                         p.sacCalcificationArcDeg > 0 || p.neckCalcificationArcDeg > 0 || p.includePsoas ||
                         p.includeIvc || p.includeDuodenum || p.includeLeftRenalVein;
  if (needsWall && !(p.wallThicknessMm > 0))
    throw InputError("Thrombus, calcification and the neighbours lie in or against the vessel wall; wallThicknessMm is "
                     "0 — give a wall (e.g. 1.5 mm).");
  if (p.sacAxisRatio > 1.0 && !(p.thrombusMaxThicknessMm > 0))
    throw InputError("sacAxisRatio is " + FormatNumber(p.sacAxisRatio) +
                     "; an elliptical sac is filled by thrombus around its round lumen — give "
                     "thrombusMaxThicknessMm > 0 (or sacAxisRatio 1).");
  // The lumen must keep at least a quarter of the inner wall's radius where the thrombus is thickest.
  const double innerSac = p.maxAneurysmDiameterMm / 2 - p.wallThicknessMm;
  const double sacThrombus = (p.thrombusConcentric ? 1.0 : 0.5) * p.thrombusMaxThicknessMm;
  if (p.thrombusMaxThicknessMm > 0 && innerSac - sacThrombus < 0.25 * innerSac)
    throw InputError("thrombusMaxThicknessMm (" + FormatNumber(p.thrombusMaxThicknessMm) +
                     " mm) leaves less than a quarter of the sac's inner radius (" + FormatNumber(innerSac) +
                     " mm) as lumen; give a thinner thrombus or a wider sac.");
  const double innerNeck = p.neckDiameterMm / 2 - p.wallThicknessMm;
  if (p.neckThrombusThicknessMm > 0.75 * innerNeck ||
      p.wallThicknessMm > 0.25 * std::min(p.rightIliacDiameterMm, p.leftIliacDiameterMm))
    throw InputError("The wall and neck thrombus leave too little lumen (neck inner radius " + FormatNumber(innerNeck) +
                     " mm, neckThrombusThicknessMm " + FormatNumber(p.neckThrombusThicknessMm) +
                     " mm, wallThicknessMm " + FormatNumber(p.wallThicknessMm) + " mm); make them thinner.");
}

double SideDegrees(PhantomSide side)
{
  switch (side)
  {
    case PhantomSide::Anterior:
      return 0.0;
    case PhantomSide::Left:
      return 90.0;
    case PhantomSide::Posterior:
      return 180.0;
    case PhantomSide::Right:
      return 270.0;
  }
  return 0.0;
}

PhantomSide ParsePhantomSide(const std::string& text, const std::string& parameter)
{
  if (text == "anterior")
    return PhantomSide::Anterior;
  if (text == "left")
    return PhantomSide::Left;
  if (text == "posterior")
    return PhantomSide::Posterior;
  if (text == "right")
    return PhantomSide::Right;
  throw InputError(parameter + " is '" + text + "'; expected anterior, left, posterior or right.");
}

AorticPhantom GenerateAorticPhantom(const PhantomParams& p, const ProgressCallback& progress)
{
  ValidatePhantomParams(p);
  Anatomy anatomy = BuildAnatomy(p);
  SampleVessels(anatomy, anatomy.truth);
  const Grid grid = MakeGrid(p, AnatomyBounds(anatomy));
  const long count = grid.size[0] * grid.size[1] * grid.size[2];
  std::vector<float> contrast;
  std::vector<unsigned char> labels;
  AssignAdvised(contrast, static_cast<std::size_t>(count), 0.0f);
  AssignAdvised(labels, static_cast<std::size_t>(count), static_cast<unsigned char>(TissueLabel));
  const double reach = 4.0 * p.blurSigmaMm + grid.spacing.norm();

  // With a wall the lumens are drawn over it linearly (PhantomRaster.h): `layer` holds the sharp
  // class under a lumen, and each voxel near a lumen its largest edge profile over the tubes.
  std::vector<unsigned char> layer;
  std::unordered_map<long, std::pair<float, float>> nearLumen; // flat → {profile, lumen contrast}
  if (anatomy.wall)
  {
    ReportProgress(progress, 0.0, "Vessel wall");
    AssignAdvised(layer, static_cast<std::size_t>(count), static_cast<unsigned char>(UnderLumen::Tissue));
    DrawAorticWall(*anatomy.wall, p, grid, reach, contrast, labels, layer);
    for (const Tube& tube : anatomy.wallTubes)
    {
      const auto [lo, hi] = TubeBox(tube, reach);
      TubeDistance distance(tube);
      ForEachVoxelNear(grid, lo, hi,
                       [&](long flat, const Point3& x)
                       {
                         const double sd = distance.SignedDistance(x);
                         contrast[flat] = std::max(
                           contrast[flat], float((p.wallHu - p.tissueHu) * SaturatedEdgeProfile(sd, p.blurSigmaMm)));
                         if (sd < 0.0 && labels[flat] == TissueLabel)
                           labels[flat] = WallLabel;
                         if (sd < 0.0 && layer[flat] == static_cast<unsigned char>(UnderLumen::Tissue))
                           layer[flat] = static_cast<unsigned char>(UnderLumen::Wall);
                       });
    }
  }

  for (std::size_t t = 0; t < anatomy.tubes.size(); ++t)
  {
    ReportProgress(progress, 0.7 * double(t) / anatomy.tubes.size(), "Vessels");
    const Tube& tube = anatomy.tubes[t];
    const auto [lo, hi] = TubeBox(tube, reach);
    TubeDistance distance(tube);
    ForEachVoxelNear(grid, lo, hi,
                     [&](long flat, const Point3& x)
                     {
                       const double sd = LumenSignedDistance(anatomy, t, distance, x);
                       // The bolus's cranio-caudal gradient, from the site's level (0 by default).
                       const double lumenContrast =
                         p.lumenHu + p.bolusGradientHuPerCm * (x.z() - anatomy.siteZ) / 10.0 - p.tissueHu;
                       const double profile = SaturatedEdgeProfile(sd, p.blurSigmaMm);
                       if (layer.empty())
                         contrast[flat] = std::max(contrast[flat], float(lumenContrast * profile));
                       else if (profile > 0.0)
                       {
                         auto& entry = nearLumen[flat];
                         if (float(profile) > entry.first)
                           entry = { float(profile), float(lumenContrast) };
                       }
                       if (sd < 0.0)
                       {
                         labels[flat] = LumenLabel;
                       }
                     });
  }
  // Over a wall: what lies under the lumen plus the step from it to the lumen, blurred. The
  // neighbour pads (psoas, IVC, duodenum, left renal vein) and calcification are drawn over the
  // vessel by the brightest value, not nested in its layers; the lumen's blur meets them so too.
  for (const auto& [flat, entry] : nearLumen)
  {
    const unsigned char label = labels[static_cast<std::size_t>(flat)];
    if (label == PsoasLabel || label == IvcLabel || label == DuodenumLabel || label == RenalVeinLabel ||
        layer[static_cast<std::size_t>(flat)] == static_cast<unsigned char>(UnderLumen::Brighter))
    {
      contrast[flat] = std::max(contrast[flat], entry.second * entry.first);
      continue;
    }
    const auto under = static_cast<UnderLumen>(layer[static_cast<std::size_t>(flat)]);
    const double sharp = under == UnderLumen::Thrombus ? p.thrombusHu - p.tissueHu
                         : under == UnderLumen::Wall   ? p.wallHu - p.tissueHu
                                                       : 0.0;
    contrast[flat] = std::max(contrast[flat], float(contrast[flat] + (entry.second - sharp) * entry.first));
  }
  std::unordered_map<long, std::pair<float, float>>().swap(nearLumen);
  std::vector<unsigned char>().swap(layer);
  for (const Ellipsoid& kidney : anatomy.kidneys)
  {
    ForEachVoxelNear(grid, kidney.centre - kidney.semiAxes - Point3::Constant(reach),
                     kidney.centre + kidney.semiAxes + Point3::Constant(reach),
                     [&](long flat, const Point3& x)
                     {
                       const double sd = EllipsoidSignedDistance(kidney, x);
                       contrast[flat] = std::max(
                         contrast[flat], float((p.kidneyHu - p.tissueHu) * SaturatedEdgeProfile(sd, p.blurSigmaMm)));
                       if (sd < 0.0 && labels[flat] == TissueLabel)
                       {
                         labels[flat] = KidneyLabel;
                       }
                     });
  }
  if (anatomy.column)
  {
    ReportProgress(progress, 0.75, "Vertebral column");
    const double r = vertebraRadiusMm + reach;
    ForEachVoxelNear(grid, Point3(-r, anatomy.columnY - r, -1e6), Point3(r, anatomy.columnY + r, 1e6),
                     [&](long flat, const Point3& x)
                     {
                       const double rho = std::hypot(x.x(), x.y() - anatomy.columnY);
                       const double outer = rho - vertebraRadiusMm, inner = outer + corticalThicknessMm;
                       const double bone = (corticalHu - p.tissueHu) * SaturatedEdgeProfile(outer, p.blurSigmaMm) -
                                           (corticalHu - cancellousHu) * SaturatedEdgeProfile(inner, p.blurSigmaMm);
                       contrast[flat] = std::max(contrast[flat], float(bone));
                       if (outer < 0.0 && labels[flat] == TissueLabel)
                       {
                         labels[flat] = BoneLabel;
                       }
                     });
  }

  ReportProgress(progress, 0.8, "Noise");
  AorticPhantom phantom;
  const auto makeImage = [&](auto image)
  {
    typename decltype(image)::ObjectType::RegionType region;
    region.SetSize(
      { { itk::SizeValueType(grid.size[0]), itk::SizeValueType(grid.size[1]), itk::SizeValueType(grid.size[2]) } });
    image->SetRegions(region);
    image->SetSpacing(grid.spacing.data());
    image->SetOrigin(grid.origin.data());
    typename decltype(image)::ObjectType::DirectionType direction;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        direction(r, c) = grid.direction(r, c);
    image->SetDirection(direction);
    AllocateAdvised(*image);
    return image;
  };
  phantom.ct = makeImage(CtImage::New());
  phantom.labels = makeImage(LabelImage::New());
  std::mt19937 generator(static_cast<std::mt19937::result_type>(p.noiseSeed));
  std::normal_distribution<double> noise(0.0, p.noiseSigmaHu > 0 ? p.noiseSigmaHu : 1.0);
  short* ct = phantom.ct->GetBufferPointer();
  long lumenVoxels = 0;
  for (long flat = 0; flat < count; ++flat)
  {
    const double value = p.tissueHu + contrast[flat] + (p.noiseSigmaHu > 0 ? noise(generator) : 0.0);
    ct[flat] = static_cast<short>(std::lround(std::clamp(value, -1024.0, 3071.0)));
    phantom.labels->GetBufferPointer()[flat] = labels[flat];
    lumenVoxels += labels[flat] == LumenLabel ? 1 : 0;
  }
  phantom.truth = anatomy.truth;
  phantom.truth.lumenVolumeMl = lumenVoxels * grid.spacing.prod() / 1000.0;
  ReportProgress(progress, 1.0, "Done");
  return phantom;
}

} // namespace sgp
