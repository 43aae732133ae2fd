/// \file WriteMeasurements.h
/// The measurements as files Slicer and a spreadsheet read: two CSV tables (Slicer loads a `.csv`
/// `<table>` output as a vtkMRMLTableNode) and the measurement part of the JSON report.
///
/// Measurements table, one row per value (MeasureAnatomy.h), header
///   `name,value,unit,definition,vessel,abscissaMm,minDiameterMm,maxDiameterMm,areaDiameterMm,wall,estimated,label,shown`
/// — value empty when not measured (full precision, for machines), the diameter columns empty for
/// non-diameters; `wall` outer, lumen or empty (neither applies); `estimated` true for an outer
/// diameter at a level less than 60 % supported (MeasureOuterWall.h) or a value sized on the lumen;
/// `label` the value in words and `shown` the value as a person reads it, at clinical precision
/// with its unit (ValueText.h). Text fields are
/// double-quoted (definitions contain commas). Numbers with up to 10 significant digits.
/// Diameter profile table, one row per ring of the fitted surface, header
///   `vessel,abscissaMm,meanDiameterMm,minDiameterMm,maxDiameterMm,areaDiameterMm`
/// — vessel aorta (abscissa from the aorta's top), rightIliac, leftIliac (from the bifurcation).
/// All lengths mm, LPS where a point is given.
/// \throws InputError naming the path when a file cannot be written.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "Device/FitCheck.h"
#include "Measurement/MeasureAnatomy.h"

namespace sgp
{

std::string FormatMeasurementsTable(const std::vector<Measurement>& rows);
std::string FormatMeasurementsTable(const Measurements& measurements);
std::string FormatDiameterProfiles(const Measurements& measurements);
void WriteMeasurementsTable(const std::vector<Measurement>& rows, const std::string& path);
void WriteDiameterProfiles(const Measurements& measurements, const std::string& path);

/// {"proximalSite": {"source", "abscissaMm", "lps", "renal"} (source "notFound": abscissaMm and lps
/// null, and "surfaceStartAbscissaMm" where the measure-mode surface began), "aorticBifurcation": {"lps",
/// "abscissaMm"}, "measurements": [{"name", "value" (null when not measured), "unit",
/// "definition", "vessel", "abscissaMm", and for diameters "minDiameterMm", "maxDiameterMm",
/// "areaDiameterMm"}], "diameterProfiles": {vessel: [[abscissaMm, mean, min, max, area], …]},
/// "warnings": […]}.
nlohmann::json MeasurementsToJson(const Measurements& measurements);

/// {"passed", "migrationRisk", "proximalSealLengthMm", "minimumProximalSealMm", "minimumIliacSealMm"
/// (the minimums the seals were judged against), "proximalSealEnd" (why it ends, words),
/// "proximalSealUncertaintyMm" and "proximalSealUncertainty" (its reason, words),
/// "shortestAppositionLengthMm", "minimumAppositionLengthMm", "shortestAppositionSide" (the patient's side
/// of its column, words), "shortestAppositionEnd" (why it ends, words), "proximalCalcifiedPercent",
/// "sealEstimatedOnLumen": {"proximal", "right", "left"}, "sealDefinition", "rightIliacSealLengthMm",
/// "leftIliacSealLengthMm", "proximalOversizingPercent", "rightLimbOversizingPercent",
/// "leftLimbOversizingPercent", "coveredOstia": [names], "ostia": [{"branch", "parent",
/// "upperAbscissaMm", "lowerAbscissaMm", "overlapMm", "covered"}], "findings": [lines]}.
nlohmann::json FitCheckToJson(const FitCheck& check);

} // namespace sgp
