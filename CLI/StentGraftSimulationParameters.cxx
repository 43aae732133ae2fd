#include "StentGraftSimulationParameters.h"

#include "CLPSupport.h"
#include "Common/CheckRange.h"
#include "Common/Errors.h"
#include "Common/Format.h"
#include "IO/ConfigurationFile.h"

namespace sgp
{

Point3 RasToLps(const std::vector<float>& ras)
{
  if (ras.size() != 3)
  {
    throw InputError("A point needs three coordinates (x,y,z in mm, RAS); got " + std::to_string(ras.size()) + ".");
  }
  return { -double(ras[0]), -double(ras[1]), double(ras[2]) };
}

RegionGrowingParams MakeRegionGrowingParams(const std::string& thresholdMode,
                                            double lowerHu,
                                            double upperHu,
                                            double windowSigmas,
                                            double seedMinimumHu,
                                            double leakOpeningRadiusMm,
                                            double maximumLumenVolumeMl)
{
  RegionGrowingParams params;
  if (thresholdMode == "auto")
  {
    params.thresholdMode = ThresholdMode::Auto;
  }
  else if (thresholdMode == "manual")
  {
    params.thresholdMode = ThresholdMode::Manual;
  }
  else
  {
    throw InputError("thresholdMode is '" + thresholdMode + "'; expected auto or manual.");
  }
  params.lowerHu = lowerHu;
  params.upperHu = upperHu;
  params.windowSigmas = windowSigmas;
  params.seedMinimumHu = seedMinimumHu;
  params.leakOpeningRadiusMm = leakOpeningRadiusMm;
  params.maximumLumenVolumeMl = maximumLumenVolumeMl;
  return params;
}

SkeletonGraphParams MakeSkeletonGraphParams(double spurLengthRatio)
{
  SkeletonGraphParams params;
  params.spurLengthRatio = spurLengthRatio;
  return params;
}

CenterlineParams MakeCenterlineParams(double centerlineStepMm, double centerlineSmoothingMm)
{
  CenterlineParams params;
  params.stepMm = centerlineStepMm;
  params.smoothingMm = centerlineSmoothingMm;
  return params;
}

StentMeshParams MakeStentMeshParams(int verticesPerRing,
                                    double ringSpacingMm,
                                    double startRadiusMm,
                                    double proximalStartMm)
{
  StentMeshParams params;
  params.verticesPerRing = verticesPerRing;
  params.ringSpacingMm = ringSpacingMm;
  params.startRadiusMm = startRadiusMm;
  params.proximalAbscissaMm = proximalStartMm;
  return params;
}

namespace
{

StiffnessWeights WeightsFrom(const std::vector<double>& w, const char* name)
{
  if (w.size() != 5)
    throw InputError(std::string(name) + " has " + std::to_string(w.size()) + " values; expected five (w1 to w5).");
  return { w[0], w[1], w[2], w[3], w[4] };
}

} // namespace

ActiveContourParams MakeActiveContourParams(const std::string& acmMode,
                                            const std::vector<double>& measureStiffnessWeights,
                                            double measureBalloonRadiusMm,
                                            double measureBalloonPressure,
                                            const std::vector<double>& stentDiametersMm,
                                            const std::vector<double>& stentStiffnessWeights,
                                            double stentBalloonPressure,
                                            double acmTau,
                                            double wallWeight,
                                            double wallSofteningMm,
                                            int acmMaxIterations,
                                            double acmToleranceMm)
{
  ActiveContourParams params;
  if (acmMode == "measure")
  {
    params = ActiveContourParams::Measure();
    params.weights = WeightsFrom(measureStiffnessWeights, "measureStiffnessWeights");
    params.balloonRadiusMm = { measureBalloonRadiusMm, measureBalloonRadiusMm, measureBalloonRadiusMm };
    params.balloonPressure = measureBalloonPressure;
  }
  else if (acmMode == "simulate")
  {
    if (stentDiametersMm.size() != 3)
      throw InputError("stentDiametersMm has " + std::to_string(stentDiametersMm.size()) +
                       " values; expected three (trunk, right leg, left leg).");
    for (double d : stentDiametersMm)
      CheckRange("stentDiametersMm", d, 2.0, 400.0, "mm");
    params = ActiveContourParams::Simulate({ stentDiametersMm[0], stentDiametersMm[1], stentDiametersMm[2] });
    params.weights = WeightsFrom(stentStiffnessWeights, "stentStiffnessWeights");
    params.balloonPressure = stentBalloonPressure;
  }
  else
  {
    throw InputError("acmMode is '" + acmMode + "'; expected measure or simulate.");
  }
  params.tau = acmTau;
  params.wallWeight = wallWeight;
  params.wallSofteningMm = wallSofteningMm;
  params.maxIterations = acmMaxIterations;
  params.toleranceMm = acmToleranceMm;
  return params;
}

void ValidatePointArguments(int argc, const char* const argv[], const std::vector<std::string>& pointFlags)
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    for (const std::string& flag : pointFlags)
    {
      if (argv[i] != "--" + flag)
        continue;
      try
      {
        clp::SplitNumbers<float>(argv[i + 1], flag, 3);
      }
      catch (const clp::ParseError& e)
      {
        throw InputError(e.what());
      }
    }
  }
}

void RequireNoCtOutputs(const PlanOutputPaths& paths)
{
  std::string asked;
  for (const auto& [name, path] :
       { std::pair<const char*, const std::string*>{ "outputWallLabelMap", &paths.wallLabelMap },
         { "outputOuterWallModel", &paths.outerWallModel },
         { "outputReportHtml", &paths.reportHtml },
         { "outputStraightenedVolume", &paths.straightenedVolume },
         { "outputStraightenedLeftVolume", &paths.straightenedLeftVolume } })
    if (!path->empty())
      asked += (asked.empty() ? "" : ", ") + std::string(name);
  if (!asked.empty())
    throw InputError("The input volume is the lumen segmentation itself, so there is no CT, and " + asked +
                     " show or trace the CT; give the CT as the input volume, or leave them out.");
}

void ValidateParameters(const std::string& inputVolume,
                        const std::vector<float>& seed,
                        const RegionGrowingParams& params,
                        const SkeletonGraphParams& graphParams,
                        const CenterlineParams& centerlineParams,
                        const StentMeshParams& meshParams,
                        const ActiveContourParams& acmParams)
{
  if (inputVolume.empty())
  {
    throw InputError("No input volume given; expected a CT volume file or DICOM folder as the first argument.");
  }
  if (!seed.empty()) // without one the aorta is found automatically (PlanRepair)
    RasToLps(seed);
  ValidateRegionGrowingParams(params);
  ValidateSkeletonGraphParams(graphParams);
  ValidateCenterlineParams(centerlineParams);
  ValidateStentMeshParams(meshParams);
  ValidateActiveContourParams(acmParams);
  for (double w :
       { acmParams.weights.w1, acmParams.weights.w2, acmParams.weights.w3, acmParams.weights.w4, acmParams.weights.w5 })
    CheckRange("a stiffness weight", w, 0.0, 1e6, "");
}

DeviceSelectionParams MakeDeviceSelectionParams(const std::string& device,
                                                const std::vector<double>& proximalOversizingRange,
                                                const std::vector<double>& limbOversizingRange,
                                                const std::string& ipsilateralSide)
{
  for (const auto& [name, range] : { std::pair{ "proximalOversizingRange", &proximalOversizingRange },
                                     std::pair{ "limbOversizingRange", &limbOversizingRange } })
  {
    if (range->size() != 2)
      throw InputError(std::string(name) + " has " + std::to_string(range->size()) +
                       " values; expected two, min,max in % (e.g. 10,20).");
    if ((*range)[0] > (*range)[1])
      throw InputError(std::string(name) + " is " + FormatNumber((*range)[0]) + "," + FormatNumber((*range)[1]) +
                       " %; expected min,max with min <= max (e.g. 10,20).");
  }
  DeviceSelectionParams params;
  params.proximalOversizingMinPercent = proximalOversizingRange[0];
  params.proximalOversizingMaxPercent = proximalOversizingRange[1];
  params.limbOversizingMinPercent = limbOversizingRange[0];
  params.limbOversizingMaxPercent = limbOversizingRange[1];
  params.forcedDevice = device == "auto" ? std::string() : device;
  params.ipsilateralSide = ParseIpsilateralSide(ipsilateralSide, "ipsilateralSide");
  ValidateDeviceSelectionParams(params);
  return params;
}

GivenConfiguration ReadGivenConfiguration(const std::string& path,
                                          const DeviceSelectionParams& selection,
                                          const DeviceCatalog& catalog)
{
  if (!selection.forcedDevice.empty())
    throw InputError("configuration (" + path + ") and device (" + selection.forcedDevice +
                     ") are both given; expected one: the configuration names its family and sizes.");
  GivenConfiguration given = ReadConfiguration(path);
  const ResolvedConfiguration resolved = ResolveGivenConfiguration(given, catalog);
  if (resolved.mainBodySide >= 0 && selection.ipsilateralSide != IpsilateralSide::Auto &&
      (selection.ipsilateralSide == IpsilateralSide::Right) != (resolved.mainBodySide == 0))
    throw InputError(
      std::string("ipsilateralSide is ") + (selection.ipsilateralSide == IpsilateralSide::Right ? "right" : "left") +
      " but the configuration (" + path + ") gives mainBodySide " + (resolved.mainBodySide == 0 ? "right" : "left") +
      "; expected one side (leave ipsilateralSide auto).");
  return given;
}

double CheckDeploymentOffset(double deploymentOffsetMm)
{
  CheckRange("deploymentOffsetMm", deploymentOffsetMm, -30.0, 60.0, "mm");
  return deploymentOffsetMm;
}

double CheckDeploymentTolerance(double deploymentToleranceMm)
{
  CheckRange("deploymentToleranceMm", deploymentToleranceMm, 0.0, 20.0, "mm");
  return deploymentToleranceMm;
}

} // namespace sgp
