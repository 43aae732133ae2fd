#include "StentGraftSimulationParameters.h"

#include "Errors.h"

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

void ValidateParameters(const std::string& inputVolume,
                        const std::vector<float>& seed,
                        const RegionGrowingParams& params,
                        const SkeletonGraphParams& graphParams,
                        const CenterlineParams& centerlineParams)
{
  if (inputVolume.empty())
  {
    throw InputError("No input volume given; expected a CT volume file or DICOM folder as the first argument.");
  }
  if (seed.empty())
  {
    throw InputError("No seed given; expected --seed x,y,z (mm, RAS) inside the aortic lumen.");
  }
  RasToLps(seed);
  ValidateRegionGrowingParams(params);
  ValidateSkeletonGraphParams(graphParams);
  ValidateCenterlineParams(centerlineParams);
}

} // namespace sgp
