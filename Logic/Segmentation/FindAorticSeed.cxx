#include "Segmentation/FindAorticSeed.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/ImageGeometry.h"
#include "Common/SampleCt.h"

namespace sgp
{
namespace
{

constexpr double pi = 3.14159265358979323846;
constexpr float outsideHu = -2000.0f; // below every tissue: outside the image is not body

/// An axial level resampled: pixel (i, j) lies at (x0 + i·px, y0 + j·px, z), LPS mm.
struct Level
{
  double z = 0.0, x0 = 0.0, y0 = 0.0, px = 1.0;
  int w = 0, h = 0;
  std::vector<float> hu;
};

Level Resample(const CtSampler& sample, double x0, double x1, double y0, double y1, double z, double px)
{
  Level level;
  level.z = z;
  level.x0 = x0;
  level.y0 = y0;
  level.px = px;
  level.w = std::max(1, static_cast<int>(std::floor((x1 - x0) / px)) + 1);
  level.h = std::max(1, static_cast<int>(std::floor((y1 - y0) / px)) + 1);
  level.hu.resize(static_cast<size_t>(level.w) * level.h);
  for (int j = 0; j < level.h; ++j)
    for (int i = 0; i < level.w; ++i)
      level.hu[static_cast<size_t>(j) * level.w + i] = sample(Eigen::Vector3d(x0 + i * px, y0 + j * px, z));
  return level;
}

/// One connected piece of the pixels at or above the threshold (4-connected).
struct Piece
{
  std::vector<int> pixels;
  double cx = 0.0, cy = 0.0; ///< centre, LPS mm
  double diameterMm = 0.0;   ///< area-equivalent
  double roundness = 0.0;
  double medianHu = 0.0;
  double brightFraction = 0.0;
  double rimMinusMedianHu = 0.0; ///< the edge pixels' median less the piece's: > 0 for bone
  double shellMinusCoreHu = 0.0; ///< ShellMinusCoreHu, when it was measured
  double midlineOffsetMm = 0.0;
  Point3 seed = Point3::Zero(); ///< the piece's deepest pixel
};

std::vector<Piece> Pieces(const Level& level, double minimumHu, double minimumDiameterMm)
{
  std::vector<Piece> pieces;
  std::vector<char> seen(level.hu.size(), 0);
  std::vector<int> stack;
  const double minimumArea = pi * 0.25 * minimumDiameterMm * minimumDiameterMm;
  for (int start = 0; start < static_cast<int>(level.hu.size()); ++start)
  {
    if (seen[start] || level.hu[start] < minimumHu)
      continue;
    Piece piece;
    stack.assign(1, start);
    seen[start] = 1;
    while (!stack.empty())
    {
      const int p = stack.back();
      stack.pop_back();
      piece.pixels.push_back(p);
      const int i = p % level.w, j = p / level.w;
      const int next[4][2] = { { i - 1, j }, { i + 1, j }, { i, j - 1 }, { i, j + 1 } };
      for (const auto& n : next)
      {
        if (n[0] < 0 || n[1] < 0 || n[0] >= level.w || n[1] >= level.h)
          continue;
        const int q = n[1] * level.w + n[0];
        if (!seen[q] && level.hu[q] >= minimumHu)
        {
          seen[q] = 1;
          stack.push_back(q);
        }
      }
    }
    const double area = static_cast<double>(piece.pixels.size()) * level.px * level.px;
    if (area < minimumArea)
      continue;
    for (const int p : piece.pixels)
    {
      piece.cx += level.x0 + (p % level.w) * level.px;
      piece.cy += level.y0 + (p / level.w) * level.px;
    }
    piece.cx /= static_cast<double>(piece.pixels.size());
    piece.cy /= static_cast<double>(piece.pixels.size());
    piece.diameterMm = 2.0 * std::sqrt(area / pi);
    double reach = 0.0;
    std::vector<float> values;
    for (const int p : piece.pixels)
    {
      reach = std::max(reach, std::hypot(level.x0 + (p % level.w) * level.px - piece.cx,
                                         level.y0 + (p / level.w) * level.px - piece.cy));
      values.push_back(level.hu[p]);
    }
    reach += 0.5 * level.px; // the pixel's own half width
    piece.roundness = area / (pi * reach * reach);
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    piece.medianHu = values[values.size() / 2];
    // The rim: a vessel's edge is darker than its middle (partial volume with the tissue around
    // it), a bone's brighter (the cortex around the cancellous core).
    std::vector<float> rim;
    for (const int q : piece.pixels)
    {
      const int i = q % level.w, j = q / level.w;
      const bool edge = i == 0 || j == 0 || i == level.w - 1 || j == level.h - 1 || level.hu[q - 1] < minimumHu ||
                        level.hu[q + 1] < minimumHu || level.hu[q - level.w] < minimumHu ||
                        level.hu[q + level.w] < minimumHu;
      if (edge)
        rim.push_back(level.hu[q]);
    }
    std::nth_element(rim.begin(), rim.begin() + rim.size() / 2, rim.end());
    piece.rimMinusMedianHu = rim[rim.size() / 2] - piece.medianHu;
    const double bright = std::max(700.0, piece.medianHu + 300.0);
    piece.brightFraction =
      static_cast<double>(std::count_if(values.begin(), values.end(), [&](float v) { return v >= bright; })) /
      static_cast<double>(values.size());
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

/// Roundness × min(width, 25 mm) / 25 mm: a round vessel of aortic width (HU plays no part past
/// the threshold: the bolus makes the chest's aorta brighter than the abdomen's).
double Score(const Piece& piece)
{
  return piece.roundness * std::min(piece.diameterMm, 25.0) / 25.0;
}

/// Each pixel's distance to the piece's border (its pixels with a 4-neighbour outside it), mm, in
/// the order of piece.pixels.
std::vector<double> PixelDepths(const Level& level, const Piece& piece)
{
  std::vector<char> in(level.hu.size(), 0);
  for (const int p : piece.pixels)
    in[p] = 1;
  std::vector<int> border;
  for (const int p : piece.pixels)
  {
    const int i = p % level.w, j = p / level.w;
    if (i == 0 || j == 0 || i == level.w - 1 || j == level.h - 1 || !in[p - 1] || !in[p + 1] || !in[p - level.w] ||
        !in[p + level.w])
      border.push_back(p);
  }
  std::vector<double> depth(piece.pixels.size(), std::numeric_limits<double>::infinity());
  for (size_t n = 0; n < piece.pixels.size(); ++n)
  {
    const int p = piece.pixels[n];
    for (const int b : border)
      depth[n] =
        std::min(depth[n], level.px * std::hypot(double(p % level.w - b % level.w), double(p / level.w - b / level.w)));
  }
  return depth;
}

/// The piece's pixel farthest from its border (the most homogeneous place to grow from).
Point3 DeepestPixel(const Level& level, const Piece& piece, const std::vector<double>& depth)
{
  const size_t n = static_cast<size_t>(std::max_element(depth.begin(), depth.end()) - depth.begin());
  const int best = piece.pixels[n];
  return Point3(level.x0 + (best % level.w) * level.px, level.y0 + (best / level.w) * level.px, level.z);
}

/// The median HU of the piece's shell (pixels 1–4 mm inside its border, where a bone's cortex
/// lies) less the median of its core (at least half the deepest pixel's depth): > 0 for a bone,
/// whose cortex is brighter than its cancellous middle; ≤ 0 for a vessel, whose edge takes partial
/// volume from the tissue around it.
double ShellMinusCoreHu(const Level& level, const Piece& piece, const std::vector<double>& depth)
{
  const double deepest = *std::max_element(depth.begin(), depth.end());
  std::vector<double> shell, core;
  for (size_t n = 0; n < piece.pixels.size(); ++n)
  {
    if (depth[n] >= 1.0 && depth[n] <= 4.0)
      shell.push_back(level.hu[piece.pixels[n]]);
    if (depth[n] >= 0.5 * deepest)
      core.push_back(level.hu[piece.pixels[n]]);
  }
  if (shell.empty() || core.empty())
    return 0.0;
  const auto median = [](std::vector<double>& v)
  {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  return median(shell) - median(core);
}

/// The shell may be this much brighter than the core in a vessel (the medians of hundreds of
/// pixels: noise moves them by a few HU; a calcified arc covers a minority of the shell).
constexpr double maximumShellOverCoreHu = 30.0;

/// The left–right centre of the body (pixels above −500 HU) on the level; NaN without any.
double BodyCentreX(const Level& level)
{
  double sum = 0.0;
  long count = 0;
  for (int p = 0; p < static_cast<int>(level.hu.size()); ++p)
    if (level.hu[p] > -500.0f)
    {
      sum += level.x0 + (p % level.w) * level.px;
      ++count;
    }
  return count ? sum / static_cast<double>(count) : std::numeric_limits<double>::quiet_NaN();
}

/// How far (mm) the piece continues from its level in direction `dir` (±1 along z), up to `limit`.
double Follow(const CtSampler& sample,
              const Piece& start,
              double z0,
              int dir,
              double zLow,
              double zHigh,
              double limit,
              const AorticSeedParams& p)
{
  double cx = start.cx, cy = start.cy, r = 0.5 * start.diameterMm, run = 0.0;
  for (int k = 1;; ++k)
  {
    const double z = z0 + dir * k * p.trackStepMm;
    if (z < zLow || z > zHigh || run >= limit)
      break;
    const double margin = r + 15.0;
    const Level local = Resample(sample, cx - margin, cx + margin, cy - margin, cy + margin, z, p.pixelMm);
    const std::vector<Piece> pieces = Pieces(local, p.minimumHu, 0.5 * p.minimumDiameterMm);
    const Piece* next = nullptr;
    double nextDistance = std::max(3.0, 0.5 * r);
    for (const Piece& q : pieces)
      for (const int px : q.pixels)
      {
        const double d =
          std::hypot(local.x0 + (px % local.w) * local.px - cx, local.y0 + (px / local.w) * local.px - cy);
        if (d < nextDistance || (d == nextDistance && next && q.pixels.size() > next->pixels.size()))
        {
          nextDistance = d;
          next = &q;
        }
      }
    if (!next)
      break;
    cx = next->cx;
    cy = next->cy;
    r = 0.5 * next->diameterMm;
    run += p.trackStepMm;
  }
  return run;
}

} // namespace

AorticSeed FindAorticSeed(const CtImage& ct, const AorticSeedParams& p)
{
  const std::array<double, 6> b = ImageBoundsLps(ct);
  const CtSampler sample(ct, outsideHu);
  const double zLow = b[4] + 5.0, zHigh = b[5] - 5.0;
  const double neededRun = std::min(p.minimumRunMm, 0.8 * (b[5] - b[4]));
  struct Candidate
  {
    Piece piece;
    double z = 0.0, run = 0.0, score = 0.0;
  };
  std::vector<Candidate> accepted;
  std::string nearestMiss;
  double nearestMissScore = -1.0;
  int levels = 0;
  bool anyContrast = false;
  for (double z = zLow; z <= zHigh + 1e-9; z += p.levelStepMm)
  {
    ++levels;
    const Level level = Resample(sample, b[0], b[1], b[2], b[3], z, p.pixelMm);
    const double midline = BodyCentreX(level);
    anyContrast =
      anyContrast || std::any_of(level.hu.begin(), level.hu.end(), [&](float v) { return v >= p.minimumHu; });
    for (Piece& piece : Pieces(level, p.minimumHu, p.minimumDiameterMm))
    {
      piece.midlineOffsetMm = std::isfinite(midline) ? std::abs(piece.cx - midline) : 0.0;
      const double score = Score(piece);
      std::string miss;
      std::vector<double> depth; // measured for the shell test, and kept for the seed
      const auto shellOverCore = [&]
      {
        depth = PixelDepths(level, piece);
        piece.shellMinusCoreHu = ShellMinusCoreHu(level, piece, depth);
        return piece.shellMinusCoreHu;
      };
      if (piece.diameterMm > p.maximumDiameterMm)
        miss = FormatNumber(piece.diameterMm) + " mm wide (at most " + FormatNumber(p.maximumDiameterMm) + ")";
      else if (piece.roundness < p.minimumRoundness)
        miss =
          "roundness " + FormatNumber(piece.roundness, 2) + " (at least " + FormatNumber(p.minimumRoundness, 2) + ")";
      else if (piece.brightFraction > p.maximumBrightFraction || piece.rimMinusMedianHu > 0.0 ||
               shellOverCore() > maximumShellOverCoreHu)
        miss = "bone: its rim " + FormatNumber(std::max(piece.rimMinusMedianHu, piece.shellMinusCoreHu), 0) +
               " HU brighter than its middle, " + FormatNumber(100.0 * piece.brightFraction, 0) +
               " % of it bone-bright (at most " + FormatNumber(100.0 * p.maximumBrightFraction, 0) + " %)";
      else if (piece.midlineOffsetMm > p.maximumMidlineOffsetMm)
        miss = FormatNumber(piece.midlineOffsetMm) + " mm from the body's midline (at most " +
               FormatNumber(p.maximumMidlineOffsetMm) + ")";
      double run = 0.0;
      if (miss.empty())
      {
        // Each way up to the run needed: enough to tell a vessel from a vertebral body or a kidney.
        run = Follow(sample, piece, z, +1, zLow - 5.0, zHigh + 5.0, neededRun, p) +
              Follow(sample, piece, z, -1, zLow - 5.0, zHigh + 5.0, neededRun, p);
        if (run < neededRun)
          miss = "followed over only " + FormatNumber(run, 0) + " mm (at least " + FormatNumber(neededRun, 0) + ")";
      }
      if (!miss.empty())
      {
        if (score > nearestMissScore)
        {
          nearestMissScore = score;
          nearestMiss = "a piece of median " + FormatNumber(piece.medianHu, 0) + " HU, " +
                        FormatNumber(piece.diameterMm) + " mm wide at LPS z " + FormatNumber(z) + " mm: " + miss;
        }
        continue;
      }
      piece.seed = DeepestPixel(level, piece, depth); // an accepted piece passed the shell test
      accepted.push_back({ std::move(piece), z, run, score });
    }
  }
  if (accepted.empty())
  {
    const std::string looked =
      "looked on " + std::to_string(levels) + " axial levels (LPS z " + FormatNumber(zLow) + " … " +
      FormatNumber(zHigh) + " mm, every " + FormatNumber(p.levelStepMm, 0) + " mm) for a round (roundness ≥ " +
      FormatNumber(p.minimumRoundness, 2) + ") contrast-filled (≥ " + FormatNumber(p.minimumHu, 0) +
      " HU) cross-section " + FormatNumber(p.minimumDiameterMm, 0) + "–" + FormatNumber(p.maximumDiameterMm, 0) +
      " mm wide within " + FormatNumber(p.maximumMidlineOffsetMm, 0) +
      " mm of the body's midline, followed over at least " + FormatNumber(neededRun, 0) + " mm";
    throw AlgorithmError(
      "No aorta found for an automatic seed: " + looked + "; " +
      (!nearestMiss.empty() ? "the nearest was " + nearestMiss
       : anyContrast        ? "no piece at or above " + FormatNumber(p.minimumHu, 0) + " HU was " +
                         FormatNumber(p.minimumDiameterMm, 0) + " mm wide on any level (a scan without contrast?)"
                     : "no voxel reached " + FormatNumber(p.minimumHu, 0) + " HU (a scan without contrast?)") +
      ". Place --seed in the aortic lumen.");
  }
  // The abdominal aorta: the most inferior candidate scoring within 75 % of the best, on a level
  // where it is the one such vessel (below the bifurcation the two common iliacs come in pairs; in
  // the chest the ascending aorta lies beside the descending one).
  const double top = std::max_element(accepted.begin(), accepted.end(),
                                      [](const Candidate& a, const Candidate& c) { return a.score < c.score; })
                       ->score;
  const auto pairedOnItsLevel = [&](const Candidate& c)
  {
    return std::any_of(accepted.begin(), accepted.end(),
                       [&](const Candidate& o) {
                         return &o != &c && std::abs(o.z - c.z) < 1e-6 &&
                                o.piece.diameterMm >= 0.7 * c.piece.diameterMm;
                       });
  };
  auto best = accepted.end();
  for (auto c = accepted.begin(); c != accepted.end(); ++c)
    if (c->score >= 0.75 * top && !pairedOnItsLevel(*c) && (best == accepted.end() || c->z < best->z))
      best = c;
  if (best == accepted.end()) // every good one is paired: the best of all
    best = std::max_element(accepted.begin(), accepted.end(),
                            [](const Candidate& a, const Candidate& c) { return a.score < c.score; });
  AorticSeed seed;
  seed.lps = best->piece.seed;
  seed.description = "the lowest round contrast-filled cross-section of aortic width near the midline (median " +
                     FormatNumber(best->piece.medianHu, 0) + " HU, " + FormatNumber(best->piece.diameterMm) +
                     " mm wide, roundness " + FormatNumber(best->piece.roundness, 2) + ") at LPS z " +
                     FormatNumber(best->z) + " mm, followed over at least " + FormatNumber(best->run, 0) +
                     " mm along the body; " + std::to_string(accepted.size()) + " candidates on " +
                     std::to_string(levels) + " levels";
  return seed;
}

} // namespace sgp
