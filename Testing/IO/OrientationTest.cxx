// Right and left are the patient's, whatever the file's axes or storage space (DESIGN.md,
// Coordinates): the whole chain from the file to the labelled Y.
#include <gtest/gtest.h>

#include "IO/ReadCtImage.h"
#include "NrrdTestSupport.h"
#include "Phantom/AorticPhantom.h"
#include "PipelineSupport.h"
#include "TemporaryFolder.h"

namespace sgp
{
namespace
{

class Orientation : public testing::TemporaryFolderTest
{
};

void ExpectRightIliacOnPatientRight(const CenterlineTree& tree)
{
  // Patient right is −x in LPS; the phantom's right iliac ends 35 mm right of the midline.
  EXPECT_LT(tree.rightIliac.points(tree.rightIliac.Size() - 1, 0), -25.0);
  EXPECT_GT(tree.leftIliac.points(tree.leftIliac.Size() - 1, 0), 25.0);
  EXPECT_LT(tree.FindLandmark("rightRenalOstium")->lps.x(), 5.0);
  const Centerline* rightRenal = tree.FindVessel("rightRenal");
  ASSERT_NE(rightRenal, nullptr);
  EXPECT_LT(rightRenal->points(rightRenal->Size() - 1, 0), -50.0);
}

TEST_F(Orientation, FlippedAxesStoredInRasSpace_RightIliacOnPatientRight)
{
  PhantomParams p;
  p.spacingMm = { 0.9, 0.9, 1.5 };
  // i grows toward the patient's right, j toward anterior, as in a volume stored in RAS order.
  p.directionLps = Eigen::Vector3d(-1, -1, 1).asDiagonal();
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  ExpectRightIliacOnPatientRight(testing::CenterlinesFromCt(*phantom.ct, phantom.truth.seedLps));

  const std::string path = (folder / "phantom-ras.nrrd").string();
  testing::WriteNrrdInRasSpace(*phantom.ct, path);
  const CtVolume read = ReadCtImage(path);
  EXPECT_NEAR(read.image->GetDirection()(0, 0), -1.0, 1e-12);
  EXPECT_NEAR(read.image->GetOrigin()[0], phantom.ct->GetOrigin()[0], 1e-9);
  ExpectRightIliacOnPatientRight(testing::CenterlinesFromCt(*read.image, phantom.truth.seedLps));
}

} // namespace
} // namespace sgp
