#include "Common/DistanceInsideMask.h"

#include <cmath>
#include <limits>
#include <queue>

namespace sgp
{

namespace
{

struct Candidate
{
  float distance;
  long voxel;
  bool operator>(const Candidate& other) const { return distance > other.distance; }
};

} // namespace

DistanceField DistanceInsideMask(const MaskGrid& mask,
                                 const std::array<double, 3>& spacingMm,
                                 bool outsideIsBackground,
                                 float maximumDistanceMm)
{
  const float infinity = std::numeric_limits<float>::max();
  DistanceField field;
  field.distanceMm.assign(mask.voxels.size(), 0.0f);
  field.nearestBackground.assign(mask.voxels.size(), { 0, 0, 0 });
  std::vector<float>& distance = field.distanceMm;
  std::vector<std::array<int, 3>>& site = field.nearestBackground;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> queue;
  const auto length = [&](const std::array<long, 3>& a, const std::array<int, 3>& b)
  {
    const double x = (a[0] - b[0]) * spacingMm[0], y = (a[1] - b[1]) * spacingMm[1], z = (a[2] - b[2]) * spacingMm[2];
    return static_cast<float>(std::sqrt(x * x + y * y + z * z));
  };
  const auto outside = [&](long i, long j, long k)
  { return i < 0 || j < 0 || k < 0 || i >= mask.size[0] || j >= mask.size[1] || k >= mask.size[2]; };
  const auto isBackground = [&](long i, long j, long k)
  { return outside(i, j, k) ? outsideIsBackground : !mask.voxels[mask.Flat(i, j, k)]; };

  // Seeds: each foreground voxel with a background 26-neighbour, at the distance to the nearest
  // one. Found from whichever side is smaller: the band outside a lumen is mostly foreground.
  const auto offer = [&](long flat, const std::array<long, 3>& p, const std::array<long, 3>& q)
  {
    const float d = length(p, { int(q[0]), int(q[1]), int(q[2]) });
    if (d < distance[flat])
    {
      distance[flat] = d;
      site[flat] = { int(q[0]), int(q[1]), int(q[2]) };
    }
  };
  long foreground = 0;
  for (long flat = 0; flat < mask.Count(); ++flat)
    if (mask.voxels[flat])
    {
      distance[flat] = infinity;
      ++foreground;
    }
  const bool fromBackground = mask.Count() - foreground < foreground;
  for (long flat = 0, k = 0; k < mask.size[2]; ++k)
    for (long j = 0; j < mask.size[1]; ++j)
      for (long i = 0; i < mask.size[0]; ++i, ++flat)
      {
        const bool fg = mask.voxels[flat] != 0;
        const std::array<long, 3> p{ i, j, k };
        const bool border = p[0] == 0 || p[1] == 0 || p[2] == 0 || p[0] == mask.size[0] - 1 ||
                            p[1] == mask.size[1] - 1 || p[2] == mask.size[2] - 1;
        // From the background side, a foreground voxel still has to look outside the box itself.
        if (fg && (fromBackground ? !(border && outsideIsBackground) : false))
          continue;
        if (!fg && !fromBackground)
          continue;
        for (int dk = -1; dk <= 1; ++dk)
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di)
            {
              const std::array<long, 3> q{ p[0] + di, p[1] + dj, p[2] + dk };
              if (fg)
              {
                if ((fromBackground ? outside(q[0], q[1], q[2]) && outsideIsBackground
                                    : isBackground(q[0], q[1], q[2])))
                  offer(flat, p, q);
              }
              else if (!outside(q[0], q[1], q[2]) && mask.voxels[mask.Flat(q[0], q[1], q[2])])
              {
                offer(mask.Flat(q[0], q[1], q[2]), q, p);
              }
            }
      }
  for (long flat = 0; flat < mask.Count(); ++flat)
    if (mask.voxels[flat] && distance[flat] < infinity)
      queue.push({ distance[flat], flat });

  std::array<std::array<int, 3>, 27> neighbour{};
  std::array<long, 27> offset{};
  for (int m = 0; m < 27; ++m)
  {
    neighbour[m] = { m % 3 - 1, (m / 3) % 3 - 1, m / 9 - 1 };
    offset[m] = neighbour[m][0] + mask.size[0] * (neighbour[m][1] + mask.size[1] * neighbour[m][2]);
  }
  while (!queue.empty())
  {
    const Candidate c = queue.top();
    queue.pop();
    if (c.distance > distance[c.voxel])
      continue;
    const auto p = mask.Ijk(c.voxel);
    const std::array<int, 3> from = site[c.voxel];
    // Away from the box's faces every neighbour is in the box: flat offsets, no bounds checks.
    const bool interior =
      p[0] > 0 && p[1] > 0 && p[2] > 0 && p[0] < mask.size[0] - 1 && p[1] < mask.size[1] - 1 && p[2] < mask.size[2] - 1;
    for (int m = 0; m < 27; ++m)
    {
      if (m == 13)
        continue; // the voxel itself
      const std::array<long, 3> q{ p[0] + neighbour[m][0], p[1] + neighbour[m][1], p[2] + neighbour[m][2] };
      long n = 0;
      if (interior)
      {
        n = c.voxel + offset[m];
        if (!mask.voxels[n])
          continue;
      }
      else
      {
        if (outside(q[0], q[1], q[2]) || isBackground(q[0], q[1], q[2]))
          continue;
        n = mask.Flat(q[0], q[1], q[2]);
      }
      const float d = length(q, from);
      if (d < distance[n] && d <= maximumDistanceMm)
      {
        distance[n] = d;
        site[n] = from;
        queue.push({ d, n });
      }
    }
  }
  for (float& d : distance)
    if (d == infinity)
      d = maximumDistanceMm; // beyond the band, or no background at all
  return field;
}

} // namespace sgp
