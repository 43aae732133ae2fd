/// \file StentGraftSimulationParameters.h
/// The CLI edge of StentGraftSimulation: the single RAS → LPS conversion, the copy of the parsed
/// XML parameters into the Logic's parameter structs, and ValidateParameters, which checks every
/// range and cross-parameter rule once at entry (STYLE.md B4), before any file is read.
#pragma once

#include <string>
#include <vector>

#include "Centerlines/LabelAortoIliacTree.h"
#include "Centerlines/SkeletonGraph.h"
#include "Common/Types.h"
#include "Device/SelectDevice.h"
#include "IO/WritePlanOutputs.h"
#include "Segmentation/GrowLumenRegion.h"
#include "Stent/ActiveContour.h"

namespace sgp
{

/// RAS (as Slicer sends points declared `coordinateSystem="ras"`) to LPS: (x, y, z) → (−x, −y, z).
/// \throws InputError unless `ras` has three components.
Point3 RasToLps(const std::vector<float>& ras);

/// Copies the segmentation parameters; `thresholdMode` is "auto" or "manual" (TCLAP already
/// restricts it to these). \throws InputError for any other mode.
RegionGrowingParams MakeRegionGrowingParams(const std::string& thresholdMode,
                                            double lowerHu,
                                            double upperHu,
                                            double windowSigmas,
                                            double seedMinimumHu,
                                            double leakOpeningRadiusMm,
                                            double maximumLumenVolumeMl);

/// Copies the centerline parameters.
SkeletonGraphParams MakeSkeletonGraphParams(double spurLengthRatio);
CenterlineParams MakeCenterlineParams(double centerlineStepMm, double centerlineSmoothingMm);

/// Copies the stent-mesh parameters.
StentMeshParams MakeStentMeshParams(int verticesPerRing,
                                    double ringSpacingMm,
                                    double startRadiusMm,
                                    double proximalStartMm);

/// The active contour's parameters for `acmMode` ("measure" or "simulate"): the mode's weights,
/// balloon radius and pressure, and the shared step, wall and stopping parameters.
/// \throws InputError for a weight vector that is not five values, diameters not three values,
///         or another mode.
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
                                            double acmToleranceMm);

/// The device-selection parameters: `device` "auto" (every family) or "Family[:diameter]"; each
/// range two values min,max in %; `ipsilateralSide` auto, right or left. \throws InputError for a
/// range that is not two values, or min > max, or out of [0, 100] (ValidateDeviceSelectionParams),
/// or another side.
DeviceSelectionParams MakeDeviceSelectionParams(const std::string& device,
                                                const std::vector<double>& proximalOversizingRange,
                                                const std::vector<double>& limbOversizingRange,
                                                const std::string& ipsilateralSide = "auto");

/// The surgeon's configuration file (--configuration), read and resolved against `catalog` at once so
/// that a bad code fails before any heavy work. \throws InputError with --device also given, when the
/// configuration's mainBodySide contradicts a non-auto ipsilateralSide, or as ReadConfiguration and
/// ResolveGivenConfiguration.
GivenConfiguration ReadGivenConfiguration(const std::string& path,
                                          const DeviceSelectionParams& selection,
                                          const DeviceCatalog& catalog);

/// The deployment offset, mm. \throws InputError "deploymentOffsetMm is … mm; expected -30.0 to
/// 60.0 mm." outside that range.
double CheckDeploymentOffset(double deploymentOffsetMm);

/// The deployment tolerance, mm. \throws InputError "deploymentToleranceMm is … mm; expected 0.0 to
/// 20.0 mm." outside that range.
double CheckDeploymentTolerance(double deploymentToleranceMm);

/// Checks the text of each point argument on the command line (`--<flag> x,y,z` for every flag
/// in `pointFlags`): three comma-separated numbers, each complete. Inside Slicer the CLI is built
/// with SEM's GenerateCLP, which converts each component with `atof` and checks no count, so
/// `--seed a,b,c` would reach the CLI as the origin; the standalone build's generator already
/// rejects it, and this check, run on argv after PARSE_ARGS, makes both builds reject it alike.
/// \throws InputError naming the flag and the text.
void ValidatePointArguments(int argc, const char* const argv[], const std::vector<std::string>& pointFlags);

/// Planning on a lumen segmentation without a CT (the input volume is the segmentation itself):
/// the outputs that show or trace the CT — the wall label map, the outer wall model, the visual
/// report and the straightened volumes — cannot be made. \throws InputError naming those asked for.
void RequireNoCtOutputs(const PlanOutputPaths& paths);

/// Checks the inputs a run needs: an input volume, a seed of three numbers, and parameters in
/// range. \throws InputError naming the value and what was expected.
void ValidateParameters(const std::string& inputVolume,
                        const std::vector<float>& seed,
                        const RegionGrowingParams& params,
                        const SkeletonGraphParams& graphParams = {},
                        const CenterlineParams& centerlineParams = {},
                        const StentMeshParams& meshParams = {},
                        const ActiveContourParams& acmParams = ActiveContourParams::Measure());

} // namespace sgp
