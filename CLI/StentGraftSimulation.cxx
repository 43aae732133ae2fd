// StentGraftSimulation: the SEM command-line module of StentGraftPlanner.
// Sequence (STYLE.md B7): PARSE_ARGS, ValidateParameters, read, convert the seed once, run the
// stages in DESIGN.md's order with progress, write every output at once, return.
#include <cstdlib>
#include <iostream>

#include <itkObject.h>
#include <vtkObject.h>

#include "AssignInscribedRadii.h"
#include "GrowLumenRegion.h"
#include "IO/WriteCenterlines.h"
#include "CLPSupport.h"
#include "IO/OutputTransaction.h"
#include "IO/ReadCtImage.h"
#include "IO/WriteImage.h"
#include "IO/WriteReturnParameters.h"
#include "IO/WriteStentModel.h"
#include "SlicerProgress.h"
#include "StentGraftSimulationCLP.h"
#include "StentGraftSimulationParameters.h"

namespace
{

void PrintWarnings(const std::vector<std::string>& warnings)
{
  for (const std::string& warning : warnings)
  {
    std::cerr << "WARNING: " << warning << std::endl;
  }
}

} // namespace

int main(int argc, char* argv[])
{
  PARSE_ARGS;
  // ITK and VTK would print multi-line diagnostics to stderr; every failure reaches the user
  // instead as the one ERROR line below.
  itk::Object::GlobalWarningDisplayOff();
  vtkObject::GlobalWarningDisplayOff();
  try
  {
    using namespace sgp;
    const RegionGrowingParams growParams = MakeRegionGrowingParams(
      thresholdMode, lowerHu, upperHu, windowSigmas, seedMinimumHu, leakOpeningRadiusMm, maximumLumenVolumeMl);
    const SkeletonGraphParams graphParams = MakeSkeletonGraphParams(spurLengthRatio);
    const CenterlineParams centerlineParams = MakeCenterlineParams(centerlineStepMm, centerlineSmoothingMm);
    const StentMeshParams meshParams =
      MakeStentMeshParams(verticesPerRing, ringSpacingMm, startRadiusMm, proximalStartMm);
    const ActiveContourParams acmParams =
      MakeActiveContourParams(acmMode, measureStiffnessWeights, measureBalloonRadiusMm, measureBalloonPressure,
                              stentDiametersMm, stentStiffnessWeights, stentBalloonPressure, acmTau, wallWeight,
                              wallSofteningMm, acmMaxIterations, acmToleranceMm);
    ValidateParameters(inputVolume, seed, growParams, graphParams, centerlineParams, meshParams, acmParams);
    const bool wantStent = !outputStentModel.empty() || !outputInitialStentModel.empty();
    const bool wantCenterlines = wantStent || !outputCenterlines.empty() || !outputLandmarks.empty();
    SlicerProgress progress(std::cout, { { "ReadVolume", 2.0 },
                                         { "SegmentLumen", 4.0 },
                                         { "ThinLumen", 2.0 },
                                         { "ExtractCenterlines", 1.0 },
                                         { "FitStent", 2.0 },
                                         { "WriteOutputs", 1.0 } });

    progress.Begin("ReadVolume", "Reading the CT volume");
    const CtVolume volume = ReadCtImage(inputVolume);
    PrintWarnings(volume.warnings);
    const Point3 seedLps = RasToLps(seed);

    progress.Begin("SegmentLumen", "Segmenting the aortic lumen by region growing");
    const LumenSegmentation lumen = GrowLumenRegion(*volume.image, seedLps, growParams, progress.Callback());
    PrintWarnings(lumen.warnings);
    lumenVolumeMl = lumen.volumeMl;
    lowerHuUsed = lumen.lowerHu;
    upperHuUsed = lumen.upperHu;
    edgeHuUsed = lumen.edgeHu;

    CenterlineTree centerlines;
    if (wantCenterlines)
    {
      progress.Begin("ThinLumen", "Thinning the lumen into its skeleton");
      const Skeleton skeleton = ThinLabelMap(*lumen.mask, progress.Callback());
      progress.Begin("ExtractCenterlines", "Labelling the aorta, the iliac arteries and their branches");
      const SkeletonGraph graph = BuildSkeletonGraph(skeleton, *lumen.mask, graphParams);
      progress.Report(0.3);
      centerlines = LabelAortoIliacTree(graph, centerlineParams);
      AssignInscribedRadii(centerlines, skeleton);
    }
    StentMesh mesh;
    ActiveContourResult fit;
    Eigen::VectorXd initialRadius, initialWallDistance;
    if (wantStent)
    {
      progress.Begin("FitStent", "Fitting the bifurcated stent surface (active contour)");
      mesh = BuildStentMesh(centerlines, meshParams);
      const WallDistanceField wall = WallDistanceField::FromLumen(*lumen.mask);
      if (!outputInitialStentModel.empty()) // only that output needs the initial surface's values
      {
        initialRadius = Eigen::VectorXd::Constant(mesh.V.rows(), meshParams.startRadiusMm);
        initialWallDistance.resize(mesh.V.rows());
        for (Eigen::Index i = 0; i < mesh.V.rows(); ++i)
          initialWallDistance[i] = wall.Sample(mesh.V.row(i).transpose());
      }
      fit = FitActiveContour(mesh, wall, acmParams, progress.Callback());
      acmIterations = fit.iterations;
      acmConverged = fit.converged;
      if (!fit.converged)
        std::cerr << "WARNING: The active contour did not converge within " << fit.iterations
                  << " iterations (acmMaxIterations); the surface written is the last one." << std::endl;
    }

    progress.Begin("WriteOutputs", "Writing the outputs");
    OutputTransaction outputs;
    if (!outputLabelMap.empty())
    {
      WriteLabelMap(*lumen.mask, outputs.Stage(outputLabelMap));
    }
    if (!outputCenterlines.empty())
    {
      WriteCenterlines(centerlines, outputs.Stage(outputCenterlines));
    }
    if (!outputLandmarks.empty())
    {
      WriteLandmarks(centerlines, outputs.Stage(outputLandmarks));
    }
    if (!outputInitialStentModel.empty())
    {
      WriteStentModel(mesh, mesh.V, initialRadius, initialWallDistance, outputs.Stage(outputInitialStentModel));
    }
    if (!outputStentModel.empty())
    {
      WriteStentModel(mesh, fit.V, fit.radiusMm, fit.wallDistanceMm, outputs.Stage(outputStentModel));
    }
    if (!returnParameterFile.empty())
    {
      WriteReturnParameters({ { "lumenVolumeMl", FormatReturnValue(lumenVolumeMl) },
                              { "lowerHuUsed", FormatReturnValue(lowerHuUsed) },
                              { "upperHuUsed", FormatReturnValue(upperHuUsed) },
                              { "edgeHuUsed", FormatReturnValue(edgeHuUsed) },
                              { "acmIterations", std::to_string(acmIterations) },
                              { "acmConverged", acmConverged ? "true" : "false" } },
                            outputs.Stage(returnParameterFile));
    }
    outputs.Commit();
    progress.End();

    std::cout << "Lumen: " << FormatReturnValue(lumenVolumeMl) << " mL; window " << FormatReturnValue(lowerHuUsed)
              << " to " << FormatReturnValue(upperHuUsed) << " HU (seed median " << lumen.seedMedianHu << " HU, sigma "
              << lumen.seedSigmaHu << " HU); boundary at " << FormatReturnValue(edgeHuUsed) << " HU" << std::endl;
    if (wantCenterlines)
    {
      std::cout << "Centerlines: aorta " << FormatReturnValue(centerlines.aorta.LengthMm()) << " mm, right iliac "
                << FormatReturnValue(centerlines.rightIliac.LengthMm()) << " mm, left iliac "
                << FormatReturnValue(centerlines.leftIliac.LengthMm()) << " mm; side branches:";
      for (const Centerline& c : centerlines.sideBranches)
        std::cout << " " << c.name;
      std::cout << std::endl;
    }
    if (wantStent)
    {
      std::cout << "Stent surface: " << mesh.V.rows() << " vertices, " << acmMode << " mode, "
                << (fit.converged ? "converged" : "not converged") << " after " << fit.iterations << " iterations"
                << std::endl;
    }
    return EXIT_SUCCESS;
  }
  catch (const std::exception& e)
  {
    std::cerr << "ERROR: " << sgp::clp::OneLine(e.what()) << std::endl;
    return EXIT_FAILURE;
  }
}
