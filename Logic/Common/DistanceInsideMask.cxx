#include "Common/DistanceInsideMask.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "Common/TwoCores.h"

namespace sgp
{

namespace
{

const double Infinite = std::numeric_limits<double>::infinity();

/// Boxes of fewer voxels are transformed on the calling thread alone.
constexpr long minimumVoxelsForTwoCores = 65536;

/// Lines transformed together along j and k (see the passes).
constexpr long lineBlock = 16;

/// One line of the separable transform: the lower envelope of the parabolas
/// (p − q)²·s² + f(q) over the line's samples q with finite f (Felzenszwalb & Huttenlocher 2012,
/// section 3), plus — when the box's outside is background — a site at q = −1 and q = n with
/// f = 0. For every p of the line, `best[p]` is the minimum and `from[p]` the q that gives it
/// (−1 or n for the virtual sites; −2 when the line has no site at all). The line's n samples
/// are read as doubles from `f`; `best` (squared mm, rounded to float as stored) and `from` hold n.
class LineTransform
{
public:
  void Run(const float* f, long n, double spacing, bool outsideSites, float* best, long* from)
  {
    const double s2 = spacing * spacing;
    m_Q.clear();
    m_Boundary.clear();
    const auto add = [&](long q, double fq)
    {
      const double key = fq + s2 * double(q) * double(q);
      while (!m_Q.empty())
      {
        const long r = m_Q.back();
        const double fr = r < 0 || r >= n ? 0.0 : double(f[r]);
        // Where the new parabola crosses the last one kept: beyond the last one's start, or the
        // last one never lies lowest and goes.
        const double cross = (key - (fr + s2 * double(r) * double(r))) / (2.0 * s2 * double(q - r));
        if (cross > m_Boundary.back())
        {
          m_Q.push_back(q);
          m_Boundary.push_back(cross);
          return;
        }
        m_Q.pop_back();
        m_Boundary.pop_back();
      }
      m_Q.push_back(q);
      m_Boundary.push_back(-Infinite);
    };
    if (outsideSites)
      add(-1, 0.0);
    for (long q = 0; q < n; ++q)
      if (double(f[q]) < Infinite)
        add(q, double(f[q]));
    if (outsideSites)
      add(n, 0.0);
    if (m_Q.empty())
    {
      std::fill(best, best + n, float(Infinite));
      std::fill(from, from + n, -2L);
      return;
    }
    std::size_t piece = 0;
    for (long p = 0; p < n; ++p)
    {
      while (piece + 1 < m_Q.size() && m_Boundary[piece + 1] <= double(p))
        ++piece;
      const long q = m_Q[piece];
      const double fq = q < 0 || q >= n ? 0.0 : double(f[q]);
      best[p] = static_cast<float>(s2 * double(p - q) * double(p - q) + fq);
      from[p] = q;
    }
  }

private:
  std::vector<long> m_Q;          ///< the parabolas of the envelope, left to right
  std::vector<double> m_Boundary; ///< where each starts to be the lowest
};

} // namespace

DistanceField DistanceInsideMask(const MaskGrid& mask,
                                 const std::array<double, 3>& spacingMm,
                                 bool outsideIsBackground,
                                 float maximumDistanceMm)
{
  // The exact Euclidean distance transform by separable passes along i, j and k, each the lower
  // envelope of parabolas on a line (P. F. Felzenszwalb and D. P. Huttenlocher, "Distance
  // transforms of sampled functions", Theory of Computing 8, 2012), carrying along each voxel's
  // nearest site (the feature transform; C. R. Maurer, R. Qi, V. Raghavan, "A linear time
  // algorithm for computing exact Euclidean distance transforms of binary images in arbitrary
  // dimensions", IEEE PAMI 25, 2003). Sites are the background voxels and, when
  // outsideIsBackground, the one-voxel shell around the box. Linear in the box's voxels.
  const std::array<long, 3> n{ mask.size[0], mask.size[1], mask.size[2] };
  const long count = mask.Count();
  DistanceField field;
  field.nearestBackground.resize(std::size_t(count)); // unwritten until the first loop (DefaultInitAllocator)
  auto& site = field.nearestBackground;
  // Squared distances (mm²) until the last step; float is exact enough: at 100 mm, 0.001 mm.
  auto& squared = field.distanceMm;
  squared.resize(std::size_t(count));
  const long slice = n[0] * n[1];
  // Small boxes (the thinning's one-voxel layers, the tests') on the calling thread alone: starting
  // threads would cost more than the loops.
  const auto split = [&](long slices, auto body)
  {
    if (count >= minimumVoxelsForTwoCores)
      OnTwoCores(slices, body);
    else
      body(0L, slices);
  };
  // Every loop below on both cores: the first two over slices, each pass over its lines (a line
  // reads and writes its own voxels only), so the field is the same as one core's, bit for bit.
  split(n[2],
        [&](long firstSlice, long endSlice)
        {
          long flat = firstSlice * slice;
          for (int k = int(firstSlice); k < int(endSlice); ++k)
            for (int j = 0; j < int(n[1]); ++j)
              for (int i = 0; i < int(n[0]); ++i, ++flat)
                if (!mask.voxels[flat])
                {
                  squared[std::size_t(flat)] = 0.0f;
                  site[std::size_t(flat)] = { i, j, k };
                }
                else
                {
                  squared[std::size_t(flat)] = std::numeric_limits<float>::infinity();
                  site[std::size_t(flat)] = { 0, 0, 0 }; // stays so when the voxel has no site at all
                }
        });
  const std::array<long, 3> stride{ 1, n[0], n[0] * n[1] };
  for (int axis = 0; axis < 3; ++axis)
  {
    // The two axes that index the lines, u the faster. Along j and k (u = i) the lines of a block
    // of `lineBlock` neighbours are read and written together: each step along the line then
    // touches one run of neighbouring voxels instead of one voxel per page, which matters on big
    // boxes (lines of hundreds of pages; under AddressSanitizer's shadow memory, 100x). Along i the
    // lines are contiguous already. Each line is transformed as before, on its own voxels.
    const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
    const long length = n[axis];
    const long width = axis == 0 ? 1 : lineBlock;
    split(n[v],
          [&](long firstB, long endB)
          {
            LineTransform transform;
            const std::size_t blockVoxels = static_cast<std::size_t>(width * length);
            std::vector<float> lineSquared(blockVoxels), newSquared(blockVoxels);
            std::vector<std::array<int, 3>> lineSites(blockVoxels);
            std::vector<long> newFrom(blockVoxels);
            std::array<bool, lineBlock> foreground{};
            for (long b = firstB; b < endB; ++b)
              for (long a0 = 0; a0 < n[u]; a0 += width)
              {
                const long lines = std::min(width, n[u] - a0);
                const long start = a0 * stride[u] + b * stride[v];
                const auto at = [&](long t, long q) { return start + t * stride[u] + q * stride[axis]; };
                const auto in = [&](long t, long q) { return std::size_t(t * length + q); };
                // A line of background only (distance 0 throughout) stays as it is: most lines of a
                // lumen's bounding box.
                bool any = false;
                foreground.fill(false);
                for (long q = 0; q < length; ++q)
                  for (long t = 0; t < lines; ++t)
                    if (mask.voxels[at(t, q)] != 0)
                      foreground[std::size_t(t)] = any = true;
                if (!any)
                  continue;
                for (long q = 0; q < length; ++q)
                  for (long t = 0; t < lines; ++t)
                    if (foreground[std::size_t(t)])
                    {
                      lineSquared[in(t, q)] = squared[std::size_t(at(t, q))];
                      lineSites[in(t, q)] = site[std::size_t(at(t, q))];
                    }
                for (long t = 0; t < lines; ++t)
                  if (foreground[std::size_t(t)])
                    transform.Run(&lineSquared[in(t, 0)], length, spacingMm[axis], outsideIsBackground,
                                  &newSquared[in(t, 0)], &newFrom[in(t, 0)]);
                for (long p = 0; p < length; ++p)
                  for (long t = 0; t < lines; ++t)
                  {
                    if (!foreground[std::size_t(t)])
                      continue;
                    const long flat = at(t, p);
                    squared[std::size_t(flat)] = newSquared[in(t, p)];
                    const long q = newFrom[in(t, p)];
                    if (q == -2)
                      continue;
                    if (q < 0 || q >= length)
                    {
                      // The virtual site in the shell: straight across this axis from the voxel itself.
                      std::array<int, 3> s{};
                      s[std::size_t(axis)] = int(q);
                      s[std::size_t(u)] = int(a0 + t);
                      s[std::size_t(v)] = int(b);
                      site[std::size_t(flat)] = s;
                    }
                    else
                    {
                      site[std::size_t(flat)] = lineSites[in(t, q)];
                    }
                  }
              }
          });
  }
  split(n[2],
        [&](long firstSlice, long endSlice)
        {
          // No site at all: infinity, hence the maximum.
          for (long flat = firstSlice * slice; flat < endSlice * slice; ++flat)
            squared[std::size_t(flat)] = std::min(std::sqrt(squared[std::size_t(flat)]), maximumDistanceMm);
        });
  return field;
}

} // namespace sgp
