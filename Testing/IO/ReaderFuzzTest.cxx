// A seeded mutation test of every reader of the CLI's inputs: the CT volume's file formats (NRRD
// raw and gzip, NIfTI, MetaImage), the device catalogue, the hostile-neck rules and the point
// arguments (the markups Slicer hands over as "x,y,z"). Each valid input is mutated (bit flips,
// byte replacements with the characters a parser cares about, deletions, duplications,
// truncations, inserted numbers such as 1e308, nan or -1) and read back: the reader either
// succeeds or throws InputError with a one-line message — what the CLI prints as its one
// `ERROR:` line with exit code 1. Any other exception, or a crash, fails (and in the sanitizer
// build, any memory or undefined-behaviour report). The count of mutated inputs is printed.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>

#include <gtest/gtest.h>
#include <itkImageFileWriter.h>

#include "Common/Errors.h"
#include "IO/ReadCtImage.h"
#include "IO/ReadDeviceCatalog.h"
#include "IO/ReadNeckRules.h"
#include "CLPSupport.h"
#include "StentGraftSimulationParameters.h"
#include "TemporaryFolder.h"

namespace sgp
{
namespace
{

namespace fs = std::filesystem;

std::string ReadBytes(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void WriteBytes(const fs::path& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
}

/// One to four seeded mutations of `input`.
std::string Mutate(std::string input, std::mt19937& random)
{
  static const std::string interesting = "0123456789-+.,eE\"{}[]: \n\t\\";
  static const char* const numbers[] = {
    "-1", "0", "1e308", "-1e308", "nan", "inf", "99999999999", "1e-320", "2147483648", "-0", "18446744073709551616", ""
  };
  std::uniform_int_distribution<int> count(1, 4), kind(0, 6);
  for (int m = count(random); m > 0 && !input.empty(); --m)
  {
    std::uniform_int_distribution<std::size_t> at(0, input.size() - 1);
    const std::size_t p = at(random);
    const std::size_t length = std::min<std::size_t>(1 + random() % 16, input.size() - p);
    switch (kind(random))
    {
      case 0:
        input[p] = static_cast<char>(input[p] ^ (1 << (random() % 8)));
        break;
      case 1:
        input[p] = interesting[random() % interesting.size()];
        break;
      case 2:
        input[p] = static_cast<char>(random() % 256);
        break;
      case 3:
        input.erase(p, length);
        break;
      case 4:
        input.insert(p, input.substr(p, length));
        break;
      case 5:
        input.resize(p);
        break;
      default:
        input.insert(p, numbers[random() % (sizeof numbers / sizeof numbers[0])]);
        break;
    }
  }
  return input;
}

/// Reads every mutation of `valid` with `read`: success or InputError on one line, nothing else.
template<typename Read>
int FuzzReader(const std::string& what,
               const std::string& valid,
               const fs::path& path,
               int mutations,
               unsigned seed,
               Read read)
{
  std::mt19937 random(seed);
  int errors = 0;
  for (int i = 0; i < mutations; ++i)
  {
    const std::string mutated = Mutate(valid, random);
    WriteBytes(path, mutated);
    try
    {
      read(path.string());
    }
    catch (const InputError& e)
    {
      const std::string message = e.what();
      EXPECT_FALSE(message.empty()) << what << " mutation " << i;
      ++errors;
    }
    catch (const std::exception& e)
    {
      ADD_FAILURE() << what << " mutation " << i << " (seed " << seed << "): not an InputError: " << e.what();
      fs::copy_file(path, path.string() + ".failed-" + std::to_string(i), fs::copy_options::overwrite_existing);
    }
  }
  std::printf("%s: %d mutated inputs read, %d rejected with an InputError\n", what.c_str(), mutations, errors);
  return errors;
}

class ReaderFuzz : public testing::TemporaryFolderTest
{
protected:
  static CtImage::Pointer SmallVolume()
  {
    auto image = CtImage::New();
    image->SetRegions(CtImage::SizeType{ { 6, 5, 4 } });
    image->Allocate();
    const double spacing[3] = { 0.7, 0.8, 2.5 };
    image->SetSpacing(spacing);
    for (long v = 0; v < 120; ++v)
      image->GetBufferPointer()[v] = static_cast<short>(v * 13 - 500);
    return image;
  }
  std::string WriteValid(const std::string& name, bool compress)
  {
    auto writer = itk::ImageFileWriter<CtImage>::New();
    writer->SetInput(SmallVolume());
    writer->SetFileName((folder / name).string());
    writer->SetUseCompression(compress);
    writer->Update();
    return ReadBytes(folder / name);
  }
};

TEST_F(ReaderFuzz, CtVolumeHeaders_InputErrorOrAVolume)
{
  struct Format
  {
    const char* name;
    bool compress;
  };
  itk::Object::GlobalWarningDisplayOff(); // as the CLI runs (ITK's own warnings are not its output)
  int total = 0;
  for (const Format& f : { Format{ "raw.nrrd", false }, Format{ "gzip.nrrd", true }, Format{ "volume.nii", false },
                           Format{ "volume.mha", false } })
  {
    const std::string valid = WriteValid(std::string("valid-") + f.name, f.compress);
    ASSERT_NO_THROW(ReadCtImage((folder / (std::string("valid-") + f.name)).string()));
    const int mutations = 300;
    FuzzReader(f.name, valid, folder / (std::string("mutated-") + f.name), mutations, 7 + unsigned(total),
               [](const std::string& path)
               {
                 const CtVolume volume = ReadCtImage(path);
                 ASSERT_TRUE(volume.image);
               });
    total += mutations;
  }
  std::printf("CT volumes: %d mutated inputs in all\n", total);
}

// A header that declares more voxels than any CT (here 4096³, 137 GB of HU behind a 120-voxel
// file) is refused before anything is allocated for it, naming the sizes.
TEST_F(ReaderFuzz, HeaderDeclaringBillionsOfVoxels_InputErrorBeforeAllocating)
{
  std::string header = "NRRD0004\ntype: short\ndimension: 3\nsizes: 4096 4096 4096\nencoding: raw\n"
                       "endian: little\nspace: left-posterior-superior\n\n";
  WriteBytes(folder / "huge.nrrd", header + std::string(240, '\0'));
  try
  {
    ReadCtImage((folder / "huge.nrrd").string());
    ADD_FAILURE() << "no error";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("declares 4096 × 4096 × 4096 voxels (68.7 billion)"), std::string::npos)
      << e.what();
  }
}

TEST_F(ReaderFuzz, DeviceCatalogue_InputErrorOrACatalogue)
{
  const std::string valid = ReadBytes(SGP_DEVICES_JSON);
  ASSERT_FALSE(valid.empty());
  const int rejected = FuzzReader("devices.json", valid, folder / "devices.json", 2000, 11,
                                  [](const std::string& path) { ReadDeviceCatalog(path); });
  EXPECT_GT(rejected, 1000); // most mutations of a strict schema are errors: the mutations reach the checks
}

TEST_F(ReaderFuzz, HostileNeckRules_InputErrorOrARuleSet)
{
  const std::string valid = ReadBytes(SGP_NECK_RULES_JSON);
  ASSERT_FALSE(valid.empty());
  const int rejected = FuzzReader("hostile-neck-rules.json", valid, folder / "rules.json", 2000, 13,
                                  [](const std::string& path) { ReadNeckRules(path); });
  EXPECT_GT(rejected, 1000);
}

TEST_F(ReaderFuzz, PointArguments_InputErrorOrThreeNumbers)
{
  std::mt19937 random(17);
  int rejected = 0;
  const int mutations = 3000;
  for (int i = 0; i < mutations; ++i)
  {
    std::string text = Mutate("12.5,-30.25,118", random);
    text = text.substr(0, text.find('\0')); // an argument cannot hold a NUL: argv ends it there
    const char* argv[] = { "StentGraftSimulation", "--seed", text.c_str(), "volume.nrrd" };
    try
    {
      ValidatePointArguments(4, argv, { "seed" }); // flag names without the dashes
      // Accepted: three finite numbers, as the CLI then reads them.
      const std::vector<float> seed = clp::SplitNumbers<float>(text, "seed", 3);
      for (const float v : seed)
        EXPECT_TRUE(std::isfinite(v)) << "'" << text << "' accepted with a non-finite component";
    }
    catch (const InputError& e)
    {
      // What the CLI prints: one line, naming the flag.
      const std::string printed = "ERROR: " + clp::OneLine(e.what());
      EXPECT_EQ(printed.find('\n'), std::string::npos) << text;
      EXPECT_NE(printed.find("--seed got '"), std::string::npos) << printed;
      ++rejected;
    }
    catch (const std::exception& e)
    {
      ADD_FAILURE() << "'" << text << "': not an InputError: " << e.what();
    }
  }
  std::printf("point arguments: %d mutated inputs read, %d rejected with an InputError\n", mutations, rejected);
  EXPECT_GT(rejected, mutations / 3);
}

} // namespace
} // namespace sgp
