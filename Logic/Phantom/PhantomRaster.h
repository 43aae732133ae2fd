/// \file PhantomRaster.h
/// Drawing the synthetic phantom's anatomy (PhantomAnatomy.h) on its voxel grid: the grid, the
/// blurred edge profile, the visit of the voxels near a box, the signed distances to a tube and to
/// an ellipsoid, and the aorta's wall. Internal to Logic/Phantom. Frame: LPS mm; HU relative to
/// the tissue level.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "Common/Types.h"
#include "Phantom/AorticPhantom.h"
#include "Phantom/AorticWall.h"
#include "Phantom/PhantomAnatomy.h"

namespace sgp::phantom
{

/// The voxel grid: LPS of voxel (i,j,k) is origin + direction · diag(spacing) · (i,j,k).
struct Grid
{
  Point3 origin;
  Eigen::Matrix3d direction;
  Eigen::Vector3d spacing;
  std::array<long, 3> size;
  Eigen::Matrix3d IndexToLps() const { return direction * spacing.asDiagonal(); }
  long Flat(long i, long j, long k) const { return i + size[0] * (j + size[1] * k); }
};

/// Standard normal CDF, with the hard step for an unblurred edge.
double EdgeProfile(double signedDistance, double sigma);

/// EdgeProfile, exactly 1 and 0 beyond 8.5 σ inside and outside (the same HU after rounding,
/// without the erfc). Only for values added to the HU: where tails are compared — which layer is
/// the brightest at a voxel (DrawAorticWall) — the exact EdgeProfile decides, as it always has.
double SaturatedEdgeProfile(double signedDistance, double sigma);

/// See PhantomRaster.cxx.
Grid MakeGrid(const PhantomParams& p, const std::array<Point3, 2>& bounds);

/// See PhantomRaster.cxx.
double EllipsoidSignedDistance(const Ellipsoid& e, const Point3& x);

/// What lies under a lumen drawn over the wall (`layer`): nothing (tissue), the wall, or thrombus.
enum class UnderLumen : unsigned char
{
  Tissue = 0,
  Wall = 1,
  Thrombus = 2,
  /// A calcification or a neighbour pad brighter than the layers here: the lumen's blur meets it by
  /// the brightest value, as before (a linear sum would bloom a plaque into the lumen, a CT effect
  /// the lumen's window is not built for, and lift an enhancing vein past the lumen's edge level).
  Brighter = 3
};

/// The aorta's wall and thrombus as nested solids blurred linearly, as a scanner's point-spread
/// function blurs attenuation: (wall − tissue)·P(outer) + (thrombus − wall)·P(inner wall), P the
/// edge profile — so the lumen drawn over them later (AorticPhantom.cxx) meets the wall or the
/// thrombus, not the tissue beyond the wall, at its edge (issue 32: the lumen's half-maximum edge
/// is half-way between the lumen and what borders it). Calcification and neighbour pads are
/// blurred likewise and the brightest taken where they meet the wall. `layer[flat]` is set to the
/// sharp class under a lumen (UnderLumen) inside the outer wall, or Brighter where a
/// calcification or a neighbour pad is the brightest. Labels by priority: calcium,
/// wall, thrombus, neighbours (the lumens, drawn after, override them all).
void DrawAorticWall(const AorticWall& wall,
                    const PhantomParams& p,
                    const Grid& grid,
                    double reach,
                    std::vector<float>& contrast,
                    std::vector<unsigned char>& labels,
                    std::vector<unsigned char>& layer);

/// Calls f(flat, lps) for every voxel of the grid whose centre may lie within the LPS box: those
/// whose centre lies within the box widened on each LPS axis by one voxel's extent along it (on an
/// axis-aligned grid, the index box's floor and ceiling; on an oblique grid, each row of voxels is
/// clipped to the widened box, so a tall box on a tilted grid visits its slab, not the grid).
template<typename Function>
void ForEachVoxelNear(const Grid& grid, const Point3& lo, const Point3& hi, Function f)
{
  const Eigen::Matrix3d m = grid.IndexToLps();
  const Eigen::Matrix3d toIndex = m.inverse();
  Eigen::Vector3d iMin = Eigen::Vector3d::Constant(1e18), iMax = -iMin;
  for (int corner = 0; corner < 8; ++corner)
  {
    const Point3 c((corner & 1 ? hi : lo).x(), (corner & 2 ? hi : lo).y(), (corner & 4 ? hi : lo).z());
    const Eigen::Vector3d index = toIndex * (c - grid.origin);
    iMin = iMin.cwiseMin(index);
    iMax = iMax.cwiseMax(index);
  }
  std::array<long, 3> first{}, last{};
  for (int a = 0; a < 3; ++a)
  {
    first[a] = std::max(0L, static_cast<long>(std::floor(iMin[a])));
    last[a] = std::min(grid.size[a] - 1, static_cast<long>(std::ceil(iMax[a])));
  }
  // The box widened by a voxel's LPS extent, and the i range of a row inside it (the row's centres
  // are rowStart + i · m.col(0)).
  const Eigen::Vector3d pad = m.cwiseAbs().rowwise().sum();
  const Eigen::Vector3d wideLo = lo - pad, wideHi = hi + pad;
  for (long k = first[2]; k <= last[2]; ++k)
  {
    for (long j = first[1]; j <= last[1]; ++j)
    {
      const Point3 rowStart = grid.origin + m * Eigen::Vector3d(0.0, double(j), double(k));
      double from = double(first[0]), to = double(last[0]);
      for (int c = 0; c < 3 && from <= to; ++c)
      {
        const double step = m(c, 0);
        if (std::abs(step) < 1e-12)
        {
          if (rowStart[c] < wideLo[c] || rowStart[c] > wideHi[c])
            to = from - 1.0; // the row misses the box on this axis
          continue;
        }
        const double a = (wideLo[c] - rowStart[c]) / step, b = (wideHi[c] - rowStart[c]) / step;
        from = std::max(from, std::ceil(std::min(a, b)));
        to = std::min(to, std::floor(std::max(a, b)));
      }
      for (long i = static_cast<long>(from); i <= static_cast<long>(to); ++i)
      {
        f(grid.Flat(i, j, k), Point3(grid.origin + m * Eigen::Vector3d(double(i), double(j), double(k))));
      }
    }
  }
}

/// Signed distance to a tube's surface by the closest-axis-point rule (see the header), for the
/// voxels of a grid visited in order. The closest point is the first axis segment (in axis order)
/// at the least distance, as a plain scan of every segment finds it, and every value is computed
/// by the same arithmetic, so the phantom is the same voxel for voxel; what changes is the cost:
/// segments are grouped in runs of `RunLength` inside bounding spheres, the run that held the
/// previous voxel's closest point is scanned first, and a run whose sphere lies farther than the
/// best distance so far is skipped.
class TubeDistance
{
public:
  explicit TubeDistance(const Tube& tube)
    : m_Tube(tube)
  {
    double start = 0.0;
    for (std::size_t k = 0; k + 1 < tube.axis.size(); ++k)
    {
      Segment segment;
      segment.a = tube.axis[k];
      segment.ab = tube.axis[k + 1] - segment.a;
      segment.length = segment.ab.norm();
      segment.start = start;
      m_Segments.push_back(segment);
      start += segment.length;
    }
    for (std::size_t first = 0; first < m_Segments.size(); first += RunLength)
    {
      const std::size_t end = std::min(m_Segments.size(), first + RunLength);
      Point3 lo = m_Segments[first].a, hi = lo;
      for (std::size_t k = first; k < end; ++k)
        for (const Point3& v : { m_Segments[k].a, Point3(m_Segments[k].a + m_Segments[k].ab) })
        {
          lo = lo.cwiseMin(v);
          hi = hi.cwiseMax(v);
        }
      Run run{ first, end, 0.5 * (lo + hi), 0.0 };
      for (std::size_t k = first; k < end; ++k)
        run.radius = std::max({ run.radius, (m_Segments[k].a - run.centre).norm(),
                                (m_Segments[k].a + m_Segments[k].ab - run.centre).norm() });
      m_Runs.push_back(run);
    }
  }

  double SignedDistance(const Point3& x)
  {
    Closest closest;
    if (m_Runs.empty())
    {
      return closest.distance - m_Tube.radiusAt(0.0); // no segment: farther than any voxel
    }
    Scan(m_Runs[m_HintRun], x, closest);
    for (std::size_t r = 0; r < m_Runs.size(); ++r)
    {
      // A margin far above the rounding of these few operations: a run is skipped only when each
      // of its points lies strictly farther than the best so far.
      if (r != m_HintRun && (x - m_Runs[r].centre).norm() - m_Runs[r].radius <= closest.distance + 1e-6)
      {
        Scan(m_Runs[r], x, closest);
      }
    }
    m_HintRun = closest.segment / RunLength;
    return closest.distance - m_Tube.radiusAt(closest.s);
  }

private:
  static constexpr std::size_t RunLength = 16;
  struct Segment
  {
    Point3 a, ab;
    double length = 0.0, start = 0.0;
  };
  struct Run
  {
    std::size_t first = 0, end = 0;
    Point3 centre;
    double radius = 0.0;
  };
  struct Closest
  {
    double distance = 1e18, s = 0.0;
    std::size_t segment = std::numeric_limits<std::size_t>::max();
  };

  void Scan(const Run& run, const Point3& x, Closest& closest) const
  {
    for (std::size_t k = run.first; k < run.end; ++k)
    {
      const Segment& g = m_Segments[k];
      const double t = std::clamp((x - g.a).dot(g.ab) / (g.length * g.length), 0.0, 1.0);
      const double d = (x - (g.a + t * g.ab)).norm();
      // The first segment in axis order among those at the least distance.
      if (d < closest.distance || (d == closest.distance && k < closest.segment))
      {
        closest.distance = d;
        closest.s = g.start + t * g.length;
        closest.segment = k;
      }
    }
  }

  const Tube& m_Tube;
  std::vector<Segment> m_Segments;
  std::vector<Run> m_Runs;
  std::size_t m_HintRun = 0;
};

} // namespace sgp::phantom
