// sgpThinMask MASK SKELETON: thins a label map with ThinLabelMap and writes the skeleton, for the
// comparison with scikit-image (Testing/compare_skeletons.py). Prints one line:
// "seconds=<thinning time> voxels=<skeleton voxels> maskVoxels=<mask voxels>".
#include <chrono>
#include <cstdio>
#include <exception>

#include "Centerlines/ThinLabelMap.h"
#include "IO/ReadCtImage.h"
#include "IO/WriteImage.h"

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::fprintf(stderr, "ERROR: usage: sgpThinMask MASK SKELETON\n");
    return 1;
  }
  try
  {
    const auto mask = sgp::ReadLabelMap(argv[1]);
    const auto start = std::chrono::steady_clock::now();
    const sgp::Skeleton skeleton = sgp::ThinLabelMap(*mask);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    sgp::WriteLabelMap(*sgp::SkeletonToImage(skeleton, *mask), argv[2]);
    long maskVoxels = 0;
    for (std::size_t i = 0; i < mask->GetLargestPossibleRegion().GetNumberOfPixels(); ++i)
      maskVoxels += mask->GetBufferPointer()[i] != 0;
    std::printf("seconds=%.4f voxels=%zu maskVoxels=%ld\n", seconds, skeleton.voxels.size(), maskVoxels);
    return 0;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "ERROR: %s\n", e.what());
    return 1;
  }
}
