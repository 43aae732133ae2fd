// sgpReadVolume: reads (and decompresses) a CT volume with the CLI's reader, and nothing else —
// the floor that no run of the whole planning job on that file can beat
// (Benchmarks/benchmark_whole_job.py times it beside StentGraftSimulation).
// Usage: sgpReadVolume VOLUME
#include <cstdlib>
#include <iostream>

#include "IO/ReadCtImage.h"

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "ERROR: expected one argument, the volume to read; got " << argc - 1 << "." << std::endl;
    return EXIT_FAILURE;
  }
  try
  {
    const sgp::CtVolume volume = sgp::ReadCtImage(argv[1]);
    const auto size = volume.image->GetLargestPossibleRegion().GetSize();
    std::cout << size[0] << " x " << size[1] << " x " << size[2] << " voxels" << std::endl;
    return EXIT_SUCCESS;
  }
  catch (const std::exception& e)
  {
    std::cerr << "ERROR: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
}
