/// \file ReportHtml.h
/// The visual planning report: one self-contained HTML page (inline CSS and SVG, the CT images as
/// PNG data URIs; no script, no external reference) with a print stylesheet for A4, as a surgeon
/// opens it from the case folder or prints it to PDF.
///
/// Order: header (input, its grid, run date, version, the proximal site and its source); the
/// summary box (recommendation or why none, hostile neck, fit check, partial plan, every
/// warning); the measurement table (each value as the return-parameter file has it, its unit,
/// wall and definition); the diameter profiles (mean, min–max band and outer wall per ring,
/// levels (a)–(f), the device's nominal diameters); the straightened views aorta → right and
/// aorta → left iliac (lumen and outer-wall edges, levels, landmarks, the graft's extent, 10 mm
/// scale bar); the cross-section at each level (the measured ring, its shortest and longest
/// diameter, the outer contour); where each component holds (with a deployment tolerance
/// assessed: per component its edge and the band over which it may land, ReportFigureSvg.h); the
/// device table (every family's sizes and IFU checks with
/// status and margin); the fit check (seal lengths, oversizing, covered ostia, apposition per
/// segment).
///
/// Machine-readable marks for tests and tools: every value cell has `data-name` (the return
/// parameter's name); each level line on a straightened view has `data-level` and `data-path-mm`.
/// CT window: −150 … 450 HU (W 600 / L 150, a CTA vessel window), stated on the page.
/// \throws InputError naming the path when it cannot be written; InputError from the figures.
#pragma once

#include <string>

#include "Pipeline/PlanRepair.h"
#include "Views/ReportFigures.h"

namespace sgp
{

/// What the header says of the run.
struct ReportRun
{
  std::string inputVolume;
  std::string deviceCatalog;
  std::string neckRules;
  std::string date;    ///< of the run, e.g. "2026-12-02 13:05 UTC"
  std::string version; ///< StentGraftPlanner's
};

/// The window the CT images are drawn with, HU.
constexpr double ReportWindowLowHu = -150.0;
constexpr double ReportWindowHighHu = 450.0;

/// The page; see the file comment.
std::string ReportHtml(const RepairPlan& plan, const ReportFigures& figures, const ReportRun& run);

/// The current time as ReportRun::date wants it (UTC).
std::string ReportDateNow();

} // namespace sgp
