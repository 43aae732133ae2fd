#include "Common/MaskGrid.h"

#include <algorithm>
#include <cmath>

#include "Common/HugePages.h"
#include "Common/TwoCores.h"

namespace sgp
{

namespace
{

/// Flat offsets of the six face neighbours, with the axis and sign of each.
struct FaceStep
{
  int axis;
  int sign;
};
constexpr std::array<FaceStep, 6> faceSteps{ { { 0, -1 }, { 0, 1 }, { 1, -1 }, { 1, 1 }, { 2, -1 }, { 2, 1 } } };

/// Flat index of the face neighbour of (ijk) along `step`, or -1 outside the box.
long FaceNeighbour(const MaskGrid& grid, const std::array<long, 3>& ijk, const FaceStep& step)
{
  std::array<long, 3> n = ijk;
  n[step.axis] += step.sign;
  if (n[step.axis] < 0 || n[step.axis] >= grid.size[step.axis])
  {
    return -1;
  }
  return grid.Flat(n[0], n[1], n[2]);
}

/// Whether a face neighbour of the voxel is background or outside the box: the mask's boundary.
bool HasBackgroundFace(const MaskGrid& grid, const std::array<long, 3>& ijk)
{
  for (const FaceStep& step : faceSteps)
  {
    const long n = FaceNeighbour(grid, ijk, step);
    if (n < 0 || !grid.voxels[n])
      return true;
  }
  return false;
}

bool InBox(const MaskGrid& grid, long i, long j, long k)
{
  return i >= 0 && j >= 0 && k >= 0 && i < grid.size[0] && j < grid.size[1] && k < grid.size[2];
}

/// Breadth-first flood over voxels with value `value`, from `starts`, marking `visited`.
void Flood(const MaskGrid& grid, std::uint8_t value, std::vector<long>& queue, std::vector<std::uint8_t>& visited)
{
  for (std::size_t head = 0; head < queue.size(); ++head)
  {
    const std::array<long, 3> ijk = grid.Ijk(queue[head]);
    for (const FaceStep& step : faceSteps)
    {
      const long n = FaceNeighbour(grid, ijk, step);
      if (n >= 0 && !visited[n] && grid.voxels[n] == value)
      {
        visited[n] = 1;
        queue.push_back(n);
      }
    }
  }
}

} // namespace

MaskGrid::MaskGrid(const std::array<long, 3>& boxSize)
  : size(boxSize)
{
  AssignAdvised(voxels, static_cast<std::size_t>(boxSize[0] * boxSize[1] * boxSize[2]), std::uint8_t(0));
}

long MaskGrid::CountForeground() const
{
  return static_cast<long>(std::count(voxels.begin(), voxels.end(), std::uint8_t{ 1 }));
}

std::vector<std::array<int, 3>> BallOffsets(const std::array<int, 3>& radiusIjk)
{
  std::vector<std::array<int, 3>> offsets;
  const auto term = [](int d, int r) { return r == 0 ? 0.0 : (double(d) * d) / (double(r) * r); };
  for (int dk = -radiusIjk[2]; dk <= radiusIjk[2]; ++dk)
  {
    for (int dj = -radiusIjk[1]; dj <= radiusIjk[1]; ++dj)
    {
      for (int di = -radiusIjk[0]; di <= radiusIjk[0]; ++di)
      {
        if (term(di, radiusIjk[0]) + term(dj, radiusIjk[1]) + term(dk, radiusIjk[2]) <= 1.0 + 1e-9)
        {
          offsets.push_back({ di, dj, dk });
        }
      }
    }
  }
  return offsets;
}

std::vector<std::array<int, 3>> PhysicalBallOffsets(const std::array<double, 3>& spacingMm, double radiusMm)
{
  std::array<int, 3> reach{};
  for (unsigned a = 0; a < 3; ++a)
    reach[a] = static_cast<int>(std::floor(radiusMm / spacingMm[a] + 1e-9));
  std::vector<std::array<int, 3>> ball;
  for (int k = -reach[2]; k <= reach[2]; ++k)
    for (int j = -reach[1]; j <= reach[1]; ++j)
      for (int i = -reach[0]; i <= reach[0]; ++i)
      {
        const double x = i * spacingMm[0], y = j * spacingMm[1], z = k * spacingMm[2];
        if (x * x + y * y + z * z <= radiusMm * radiusMm + 1e-9)
          ball.push_back({ i, j, k });
      }
  return ball;
}

MaskGrid Erode(const MaskGrid& mask, const std::vector<std::array<int, 3>>& ball)
{
  MaskGrid out(mask.size);
  const long slice = mask.size[0] * mask.size[1];
  // Each output voxel reads the input only: both cores, by slices (TwoCores.h).
  OnTwoCores(mask.size[2],
             [&](long firstSlice, long endSlice)
             {
               for (long flat = firstSlice * slice; flat < endSlice * slice; ++flat)
               {
                 if (!mask.voxels[flat])
                 {
                   continue;
                 }
                 const std::array<long, 3> ijk = mask.Ijk(flat);
                 bool keep = true;
                 for (const auto& d : ball)
                 {
                   const long i = ijk[0] + d[0], j = ijk[1] + d[1], k = ijk[2] + d[2];
                   if (!InBox(mask, i, j, k) || !mask.voxels[mask.Flat(i, j, k)])
                   {
                     keep = false;
                     break;
                   }
                 }
                 out.voxels[flat] = keep ? 1 : 0;
               }
             });
  return out;
}

MaskGrid Dilate(const MaskGrid& mask, const std::vector<std::array<int, 3>>& ball)
{
  MaskGrid out = mask;
  for (long flat = 0; flat < mask.Count(); ++flat)
  {
    if (!mask.voxels[flat])
    {
      continue;
    }
    const std::array<long, 3> ijk = mask.Ijk(flat);
    // Interior voxels (all six faces foreground) add nothing that their neighbours do not.
    if (!HasBackgroundFace(mask, ijk))
    {
      continue;
    }
    for (const auto& d : ball)
    {
      const long i = ijk[0] + d[0], j = ijk[1] + d[1], k = ijk[2] + d[2];
      if (InBox(mask, i, j, k))
      {
        out.voxels[mask.Flat(i, j, k)] = 1;
      }
    }
  }
  return out;
}

MaskGrid ConnectedComponent(const MaskGrid& mask, long seedFlat)
{
  MaskGrid out(mask.size);
  if (seedFlat < 0 || seedFlat >= mask.Count() || !mask.voxels[seedFlat])
  {
    return out;
  }
  std::vector<long> queue{ seedFlat };
  out.voxels[seedFlat] = 1;
  Flood(mask, 1, queue, out.voxels);
  return out;
}

std::vector<int> LabelComponents(const MaskGrid& mask, std::vector<long>& sizes)
{
  std::vector<int> labels;
  AssignAdvised(labels, mask.voxels.size(), 0);
  sizes.clear();
  std::vector<long> queue;
  for (long flat = 0; flat < mask.Count(); ++flat)
  {
    if (!mask.voxels[flat] || labels[flat])
      continue;
    const int label = static_cast<int>(sizes.size()) + 1;
    queue.assign(1, flat);
    labels[flat] = label;
    for (std::size_t head = 0; head < queue.size(); ++head)
    {
      const std::array<long, 3> ijk = mask.Ijk(queue[head]);
      for (const FaceStep& step : faceSteps)
      {
        const long n = FaceNeighbour(mask, ijk, step);
        if (n >= 0 && mask.voxels[n] && !labels[n])
        {
          labels[n] = label;
          queue.push_back(n);
        }
      }
    }
    sizes.push_back(static_cast<long>(queue.size()));
  }
  return labels;
}

namespace
{

/// FillHoles on the whole box.
void FillHolesInBox(MaskGrid& mask)
{
  // Flood the outside from a one-voxel shell of background around the box (so the outside is one
  // connected region that touches every face of the box).
  const long px = mask.size[0] + 2, py = mask.size[1] + 2, pz = mask.size[2] + 2;
  const long count = px * py * pz;
  enum : std::uint8_t
  {
    Unreached = 0,
    Foreground = 1,
    Outside = 2
  };
  std::vector<std::uint8_t> state(static_cast<std::size_t>(count), Unreached);
  for (long k = 0; k < mask.size[2]; ++k)
    for (long j = 0; j < mask.size[1]; ++j)
    {
      const long row = mask.Flat(0, j, k), padded = 1 + px * ((j + 1) + py * (k + 1));
      for (long i = 0; i < mask.size[0]; ++i)
        state[padded + i] = mask.voxels[row + i] ? Foreground : Unreached;
    }
  // A scanline fill: each pop marks a whole run of a row, and pushes one voxel per unreached run
  // of the four rows beside it (a stack of runs, not of voxels).
  std::vector<long> stack{ 0 };
  while (!stack.empty())
  {
    const long v = stack.back();
    stack.pop_back();
    if (state[v] != Unreached)
      continue;
    const long rowStart = v - v % px, rowEnd = rowStart + px;
    long first = v, last = v + 1;
    while (first > rowStart && state[first - 1] == Unreached)
      --first;
    while (last < rowEnd && state[last] == Unreached)
      ++last;
    std::fill(state.begin() + first, state.begin() + last, std::uint8_t(Outside));
    const long row = rowStart / px, j = row % py, k = row / py;
    const long besideRows[4][2] = { { j - 1, k }, { j + 1, k }, { j, k - 1 }, { j, k + 1 } };
    for (const auto& beside : besideRows)
    {
      if (beside[0] < 0 || beside[0] >= py || beside[1] < 0 || beside[1] >= pz)
        continue;
      const long shift = px * (beside[0] + py * beside[1]) - rowStart;
      bool inRun = false;
      for (long n = first + shift; n < last + shift; ++n)
      {
        const bool open = state[n] == Unreached;
        if (open && !inRun)
          stack.push_back(n);
        inRun = open;
      }
    }
  }
  for (long k = 0; k < mask.size[2]; ++k)
    for (long j = 0; j < mask.size[1]; ++j)
    {
      const long row = mask.Flat(0, j, k), padded = 1 + px * ((j + 1) + py * (k + 1));
      for (long i = 0; i < mask.size[0]; ++i)
        if (state[padded + i] == Unreached)
          mask.voxels[row + i] = 1;
    }
}

} // namespace

void FillHoles(MaskGrid& mask)
{
  // Only the foreground's bounding box grown by a voxel needs the flood: a background voxel
  // outside the foreground's box reaches the border in a straight line away from it, and a path
  // from inside to the border crosses the grown box's surface, every background voxel of which
  // is such a voxel or on the border itself. Same result, on the lumen's crop a third fewer voxels.
  std::array<long, 3> low{ mask.size[0], mask.size[1], mask.size[2] }, high{ -1, -1, -1 };
  for (long k = 0; k < mask.size[2]; ++k)
    for (long j = 0; j < mask.size[1]; ++j)
    {
      const std::uint8_t* row = &mask.voxels[static_cast<std::size_t>(mask.Flat(0, j, k))];
      const std::uint8_t* end = row + mask.size[0];
      const std::uint8_t* first = std::find(row, end, std::uint8_t{ 1 });
      if (first == end)
        continue;
      const std::uint8_t* last = end - 1;
      while (!*last)
        --last;
      low = { std::min(low[0], long(first - row)), std::min(low[1], j), std::min(low[2], k) };
      high = { std::max(high[0], long(last - row)), std::max(high[1], j), std::max(high[2], k) };
    }
  if (high[0] < 0)
    return; // no foreground: no holes
  std::array<long, 3> first{}, size{};
  for (unsigned a = 0; a < 3; ++a)
  {
    first[a] = std::max(0L, low[a] - 1);
    size[a] = std::min(mask.size[a] - 1, high[a] + 1) - first[a] + 1;
  }
  if (size == mask.size)
  {
    FillHolesInBox(mask);
    return;
  }
  MaskGrid inner(size);
  for (long k = 0; k < size[2]; ++k)
    for (long j = 0; j < size[1]; ++j)
      std::copy_n(&mask.voxels[static_cast<std::size_t>(mask.Flat(first[0], first[1] + j, first[2] + k))], size[0],
                  &inner.voxels[static_cast<std::size_t>(inner.Flat(0, j, k))]);
  FillHolesInBox(inner);
  for (long k = 0; k < size[2]; ++k)
    for (long j = 0; j < size[1]; ++j)
      std::copy_n(&inner.voxels[static_cast<std::size_t>(inner.Flat(0, j, k))], size[0],
                  &mask.voxels[static_cast<std::size_t>(mask.Flat(first[0], first[1] + j, first[2] + k))]);
}

void FillSurfacePits(MaskGrid& mask, int minimumFaceNeighbours)
{
  // The pits of the mask as given (found on both cores, each half its own list), then filled.
  std::array<std::vector<long>, 2> pits;
  const long nx = mask.size[0], ny = mask.size[1], nz = mask.size[2], slice = nx * ny;
  const std::uint8_t* v = mask.voxels.data();
  OnTwoCores(nz,
             [&](long firstSlice, long endSlice)
             {
               std::vector<long>& found = pits[firstSlice == 0 ? 0 : 1];
               for (long k = firstSlice; k < endSlice; ++k)
                 for (long j = 0; j < ny; ++j)
                   for (long i = 0, flat = nx * (j + ny * k); i < nx; ++i, ++flat)
                   {
                     if (v[flat])
                       continue;
                     const int neighbours = (i > 0 && v[flat - 1]) + (i + 1 < nx && v[flat + 1]) +
                                            (j > 0 && v[flat - nx]) + (j + 1 < ny && v[flat + nx]) +
                                            (k > 0 && v[flat - slice]) + (k + 1 < nz && v[flat + slice]);
                     if (neighbours >= minimumFaceNeighbours)
                       found.push_back(flat);
                   }
             });
  for (const std::vector<long>& found : pits)
    for (const long flat : found)
      mask.voxels[flat] = 1;
}

void GrowConstrained(MaskGrid& mask, const std::vector<std::uint8_t>& accept, int steps)
{
  // The first front is the mask's boundary: an interior voxel has no background face to grow into.
  std::vector<long> front;
  for (long flat = 0; flat < mask.Count(); ++flat)
    if (mask.voxels[flat] && HasBackgroundFace(mask, mask.Ijk(flat)))
      front.push_back(flat);
  std::vector<long> next;
  for (int step = 0; step < steps && !front.empty(); ++step)
  {
    next.clear();
    for (const long flat : front)
    {
      const std::array<long, 3> ijk = mask.Ijk(flat);
      for (const FaceStep& faceStep : faceSteps)
      {
        const long n = FaceNeighbour(mask, ijk, faceStep);
        if (n >= 0 && !mask.voxels[n] && accept[n])
        {
          mask.voxels[n] = 1;
          next.push_back(n);
        }
      }
    }
    front.swap(next);
  }
}

} // namespace sgp
