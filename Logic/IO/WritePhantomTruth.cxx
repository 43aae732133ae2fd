#include "IO/WritePhantomTruth.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "IO/WriteTextFile.h"

namespace sgp
{

namespace
{

std::string Number(double value)
{
  if (!std::isfinite(value))
    return "null"; // a truth the phantom does not have (no flow divider within reach)
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.6g", value);
  return buffer;
}

std::string Triple(double x, double y, double z)
{
  return "[" + Number(x) + ", " + Number(y) + ", " + Number(z) + "]";
}

std::string Triple(const Point3& p)
{
  return Triple(p.x(), p.y(), p.z());
}

} // namespace

void WritePhantomTruth(const AorticPhantom& phantom, const std::string& path)
{
  const PhantomTruth& truth = phantom.truth;
  const CtImage& ct = *phantom.ct;
  std::ostringstream json;
  const auto size = ct.GetLargestPossibleRegion().GetSize();
  const auto& d = ct.GetDirection();
  json << "{\n  \"frame\": \"LPS\",\n  \"units\": \"mm\",\n";
  json << "  \"grid\": {\"size\": [" << size[0] << ", " << size[1] << ", " << size[2]
       << "], \"spacing\": " << Triple(ct.GetSpacing()[0], ct.GetSpacing()[1], ct.GetSpacing()[2])
       << ", \"origin\": " << Triple(ct.GetOrigin()[0], ct.GetOrigin()[1], ct.GetOrigin()[2]) << ", \"direction\": ["
       << Number(d(0, 0)) << ", " << Number(d(1, 0)) << ", " << Number(d(2, 0)) << ", " << Number(d(0, 1)) << ", "
       << Number(d(1, 1)) << ", " << Number(d(2, 1)) << ", " << Number(d(0, 2)) << ", " << Number(d(1, 2)) << ", "
       << Number(d(2, 2)) << "]},\n";
  json << "  \"seedLps\": " << Triple(truth.seedLps) << ",\n";
  json << "  \"seedRas\": " << Triple(-truth.seedLps.x(), -truth.seedLps.y(), truth.seedLps.z()) << ",\n";
  json << "  \"lumenVolumeMl\": " << Number(truth.lumenVolumeMl) << ",\n";
  const PhantomSizing& s = truth.sizing;
  json << "  \"sizing\": {\"proximalNeckDiameter\": " << Number(s.proximalNeckDiameter)
       << ", \"neckDiameter15mm\": " << Number(s.neckDiameter15mm)
       << ", \"maxAneurysmDiameter\": " << Number(s.maxAneurysmDiameter)
       << ", \"distalNeckMinDiameter\": " << Number(s.distalNeckMinDiameter)
       << ", \"rightIliacDiameter\": " << Number(s.rightIliacDiameter)
       << ", \"leftIliacDiameter\": " << Number(s.leftIliacDiameter)
       << ", \"proximalNeckLength\": " << Number(s.proximalNeckLength)
       << ", \"healthyNeckLength\": " << Number(s.healthyNeckLength)
       << ", \"proximalSiteToBifurcationLength\": " << Number(s.proximalSiteToBifurcationLength)
       << ", \"rightIliacLength\": " << Number(s.rightIliacLength)
       << ", \"leftIliacLength\": " << Number(s.leftIliacLength)
       << ", \"proximalSiteToFlowDividerLength\": " << Number(s.proximalSiteToFlowDividerLength)
       << ", \"rightIliacLengthFromFlowDivider\": " << Number(s.rightIliacLengthFromFlowDivider)
       << ", \"leftIliacLengthFromFlowDivider\": " << Number(s.leftIliacLengthFromFlowDivider)
       << ", \"rightInternalIliacRadius\": " << Number(s.rightInternalIliacRadius)
       << ", \"leftInternalIliacRadius\": " << Number(s.leftInternalIliacRadius)
       << ", \"rightInternalIliacOstium\": " << Number(s.rightInternalIliacOstium)
       << ", \"leftInternalIliacOstium\": " << Number(s.leftInternalIliacOstium)
       << ", \"neckAngleBetaDeg\": " << Number(s.neckAngleBetaDeg)
       << ", \"outerProximalNeckDiameter\": " << Number(s.outerProximalNeckDiameter)
       << ", \"outerNeckDiameter15mm\": " << Number(s.outerNeckDiameter15mm)
       << ", \"outerMaxAneurysmDiameter\": " << Number(s.outerMaxAneurysmDiameter)
       << ", \"outerDistalNeckMinDiameter\": " << Number(s.outerDistalNeckMinDiameter)
       << ", \"outerRightIliacDiameter\": " << Number(s.outerRightIliacDiameter)
       << ", \"outerLeftIliacDiameter\": " << Number(s.outerLeftIliacDiameter)
       << ", \"thrombusVolumeMl\": " << Number(s.thrombusVolumeMl)
       << ", \"maxThrombusThicknessMm\": " << Number(s.maxThrombusThicknessMm)
       << ", \"neckThrombusArcPercent\": " << Number(s.neckThrombusArcPercent)
       << ", \"neckCalcificationArcPercent\": " << Number(s.neckCalcificationArcPercent) << "},\n";
  json << "  \"landmarks\": {";
  for (std::size_t i = 0; i < truth.landmarks.size(); ++i)
  {
    json << (i ? ", " : "") << "\"" << truth.landmarks[i].name << "\": " << Triple(truth.landmarks[i].lps);
  }
  json << "},\n  \"vessels\": [\n";
  for (std::size_t v = 0; v < truth.vessels.size(); ++v)
  {
    const PhantomVessel& vessel = truth.vessels[v];
    json << "    {\"name\": \"" << vessel.name << "\", \"points\": [";
    for (Eigen::Index i = 0; i < vessel.axis.rows(); ++i)
    {
      json << (i ? ", " : "") << Triple(vessel.axis(i, 0), vessel.axis(i, 1), vessel.axis(i, 2));
    }
    json << "], \"radiusMm\": [";
    for (Eigen::Index i = 0; i < vessel.radiusMm.size(); ++i)
    {
      json << (i ? ", " : "") << Number(vessel.radiusMm[i]);
    }
    if (vessel.outerRadiusMm.size() > 0)
    {
      json << "], \"outerRadiusMm\": [";
      for (Eigen::Index i = 0; i < vessel.outerRadiusMm.size(); ++i)
        json << (i ? ", " : "") << Number(vessel.outerRadiusMm[i]);
    }
    json << "]}" << (v + 1 < truth.vessels.size() ? "," : "") << "\n";
  }
  json << "  ],\n  \"labels\": {\"0\": \"tissue\", \"1\": \"lumen\", \"2\": \"bone\", \"3\": \"kidney\", \"4\": "
          "\"wall\", \"5\": \"thrombus\", \"6\": \"calcium\", \"7\": \"psoas\", \"8\": \"ivc\", \"9\": \"duodenum\", "
          "\"10\": \"leftRenalVein\"}\n}\n";
  WriteTextFile(json.str(), path, "the ground truth");
}

} // namespace sgp
