#include "Pipeline/ValueText.h"

#include <cmath>
#include <map>

#include "Common/Format.h"
#include "Common/Text.h"

namespace sgp
{

std::string ValueLabel(const std::string& name)
{
  static const std::map<std::string, std::string> words = {
    { "proximalNeckDiameter", "(a) neck diameter at the proximal site, outer wall" },
    { "neckDiameter15mm", "(b) neck diameter 15 mm below the site, outer wall" },
    { "maxAneurysmDiameter", "(c) largest aneurysm diameter, outer wall" },
    { "distalNeckMinDiameter", "(d) smallest distal aortic diameter, outer wall" },
    { "rightIliacDiameter", "(e) right common iliac diameter, outer wall" },
    { "leftIliacDiameter", "(f) left common iliac diameter, outer wall" },
    { "proximalNeckLumenDiameter", "(a) neck diameter at the proximal site, lumen" },
    { "neckLumenDiameter15mm", "(b) neck diameter 15 mm below the site, lumen" },
    { "maxAneurysmLumenDiameter", "(c) largest aneurysm diameter, lumen" },
    { "distalNeckMinLumenDiameter", "(d) smallest distal aortic diameter, lumen" },
    { "rightIliacLumenDiameter", "(e) right common iliac diameter, lumen" },
    { "leftIliacLumenDiameter", "(f) left common iliac diameter, lumen" },
    { "proximalNeckLength", "neck length" },
    { "proximalSiteToBifurcationLength", "proximal site to the aortic bifurcation" },
    { "rightIliacLength", "aortic bifurcation to the right internal iliac origin" },
    { "leftIliacLength", "aortic bifurcation to the left internal iliac origin" },
    { "proximalSiteToFlowDividerLength", "proximal site to the flow divider" },
    { "rightIliacLengthFromFlowDivider", "flow divider to the right internal iliac origin" },
    { "leftIliacLengthFromFlowDivider", "flow divider to the left internal iliac origin" },
    { "neckAngleBeta", "neck angle β (neck to aneurysm)" },
    { "neckAngleAlpha", "neck angle α (suprarenal aorta to neck)" },
    { "neckConicity", "neck conicity (b against a)" },
    { "rightIliacTortuosity", "right iliac tortuosity" },
    { "leftIliacTortuosity", "left iliac tortuosity" },
    { "rightAccessMinDiameter", "narrowest right access vessel" },
    { "leftAccessMinDiameter", "narrowest left access vessel" },
    { "thrombusVolume", "thrombus volume" },
    { "sacVolume", "sac volume" },
    { "maxThrombusThickness", "thickest thrombus" },
    { "neckThrombusArc", "neck circumference with thrombus over 2 mm" },
    { "neckCalcificationArc", "calcified neck circumference" },
    { "mainBodyDiameter", "main body diameter" },
    { "rightLimbDiameter", "right limb diameter" },
    { "leftLimbDiameter", "left limb diameter" },
    { "mainBodyLength", "main body length" },
    { "rightLimbLength", "right limb length" },
    { "leftLimbLength", "left limb length" },
    { "proximalSealLength", "proximal seal on healthy wall" },
    { "rightIliacSealLength", "right iliac seal on healthy wall" },
    { "leftIliacSealLength", "left iliac seal on healthy wall" },
    { "proximalOversizing", "main body oversizing at the proximal edge" },
    { "rightLimbOversizing", "right limb oversizing in the landing zone" },
    { "leftLimbOversizing", "left limb oversizing in the landing zone" },
  };
  const auto found = words.find(name);
  if (found != words.end())
    return found->second;
  return IdentifierWords(name);
}

std::string ClinicalText(double value, const std::string& unit)
{
  if (!std::isfinite(value))
    return "not measured";
  if (unit == "mm")
    return FormatNumber(value, 1) + " mm";
  if (unit == "deg")
    return FormatNumber(value, 1) + "°";
  if (unit == "%")
    return FormatNumber(value, 0) + " %";
  if (unit == "ratio")
    return FormatNumber(value, 2);
  if (unit == "mL")
    return FormatNumber(value, 1) + " mL";
  return FormatNumber(value, 1) + (unit.empty() ? "" : " " + unit);
}

} // namespace sgp
