#include "Segmentation/ContinueThinBranches.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <unordered_map>
#include <vector>

#include "Common/MaskGrid.h"

namespace sgp
{
namespace
{

/// The image's grid: sizes, and the flat indices of a voxel's face neighbours inside it.
struct Grid
{
  long nx = 0, ny = 0, nz = 0;
  std::array<long, 3> Ijk(long flat) const { return { flat % nx, (flat / nx) % ny, flat / (nx * ny) }; }
  long Flat(long i, long j, long k) const { return i + nx * (j + ny * k); }
  bool Inside(long i, long j, long k) const { return i >= 0 && j >= 0 && k >= 0 && i < nx && j < ny && k < nz; }
  template<typename F>
  void ForFaceNeighbours(long flat, F f) const
  {
    const auto [i, j, k] = Ijk(flat);
    static constexpr int d[6][3] = { { -1, 0, 0 }, { 1, 0, 0 }, { 0, -1, 0 }, { 0, 1, 0 }, { 0, 0, -1 }, { 0, 0, 1 } };
    for (const auto& o : d)
      if (Inside(i + o[0], j + o[1], k + o[2]))
        f(Flat(i + o[0], j + o[1], k + o[2]));
  }
};

/// One piece copied into its bounding box (padded by one voxel), for the shape tests.
struct PieceBox
{
  std::array<long, 3> first{};
  MaskGrid mask;
  long Local(const Grid& g, long flat) const
  {
    const auto ijk = g.Ijk(flat);
    return mask.Flat(ijk[0] - first[0], ijk[1] - first[1], ijk[2] - first[2]);
  }
};

PieceBox BoxOf(const Grid& g, const std::vector<long>& piece)
{
  std::array<long, 3> lo{ g.nx, g.ny, g.nz }, hi{ -1, -1, -1 };
  for (long flat : piece)
  {
    const auto ijk = g.Ijk(flat);
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], ijk[a]);
      hi[a] = std::max(hi[a], ijk[a]);
    }
  }
  PieceBox box;
  std::array<long, 3> size{};
  for (int a = 0; a < 3; ++a)
  {
    box.first[a] = lo[a] - 1;
    size[a] = hi[a] - lo[a] + 3;
  }
  box.mask = MaskGrid(size);
  for (long flat : piece)
    box.mask.voxels[box.Local(g, flat)] = 1;
  return box;
}

/// Whether a ball (offsets `ball`) lies inside the piece somewhere, but for `holeShare` of its
/// voxels: noise leaves voxels of a thick tissue below the edge level, which a whole ball would
/// have to avoid.
bool HoldsBall(const PieceBox& box, const std::vector<std::array<int, 3>>& ball, double holeShare)
{
  const MaskGrid& m = box.mask;
  const auto allowed = static_cast<long>(std::floor(holeShare * double(ball.size())));
  for (long flat = 0; flat < m.Count(); ++flat)
  {
    if (!m.voxels[flat])
      continue;
    const auto [i, j, k] = m.Ijk(flat);
    long holes = 0;
    for (const auto& d : ball)
    {
      const long a = i + d[0], b = j + d[1], c = k + d[2];
      const bool inside =
        a >= 0 && b >= 0 && c >= 0 && a < m.size[0] && b < m.size[1] && c < m.size[2] && m.voxels[m.Flat(a, b, c)];
      if (!inside && ++holes > allowed)
        break;
    }
    if (holes <= allowed)
      return true;
  }
  return false;
}

/// The longest path, in mm along 26-neighbour steps inside the piece, from the piece's voxels
/// that touch the lumen (`touching`, local flat indices) to any of its voxels.
double ReachMm(const PieceBox& box, const std::vector<long>& touching, const itk::Vector<double, 3>& spacing)
{
  const MaskGrid& m = box.mask;
  std::vector<double> distance(static_cast<std::size_t>(m.Count()), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, long>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (long flat : touching)
  {
    distance[flat] = 0.0;
    queue.push({ 0.0, flat });
  }
  double farthest = 0.0;
  while (!queue.empty())
  {
    const auto [d, flat] = queue.top();
    queue.pop();
    if (d > distance[flat])
      continue;
    farthest = std::max(farthest, d);
    const auto [i, j, k] = m.Ijk(flat);
    for (int c = -1; c <= 1; ++c)
      for (int b = -1; b <= 1; ++b)
        for (int a = -1; a <= 1; ++a)
        {
          const long x = i + a, y = j + b, z = k + c;
          if ((a | b | c) == 0 || x < 0 || y < 0 || z < 0 || x >= m.size[0] || y >= m.size[1] || z >= m.size[2])
            continue;
          const long next = m.Flat(x, y, z);
          if (!m.voxels[next])
            continue;
          const double step = std::sqrt(a * a * spacing[0] * spacing[0] + b * b * spacing[1] * spacing[1] +
                                        c * c * spacing[2] * spacing[2]);
          if (d + step < distance[next])
          {
            distance[next] = d + step;
            queue.push({ d + step, next });
          }
        }
  }
  return farthest;
}

} // namespace

ThinBranchResult ContinueThinBranches(const CtImage& ct,
                                      LabelImage& lumen,
                                      const IndexBox& lumenBox,
                                      const std::function<double(long k)>& edgeHuOfSlice,
                                      const std::function<double(long k)>& lumenHuOfSlice,
                                      double upperHu,
                                      double calciumHu,
                                      const ThinBranchParams& params)
{
  ThinBranchResult result;
  if (lumenBox.Empty())
    return result;
  const auto size = ct.GetLargestPossibleRegion().GetSize();
  const Grid g{ long(size[0]), long(size[1]), long(size[2]) };
  const short* hu = ct.GetBufferPointer();
  unsigned char* mask = lumen.GetBufferPointer();
  const auto spacing = ct.GetSpacing();
  const double voxelMl = spacing[0] * spacing[1] * spacing[2] / 1000.0;
  const auto maxVoxels = static_cast<std::size_t>(std::floor(params.maxPieceMl / voxelMl));
  std::vector<double> edge(static_cast<std::size_t>(g.nz)), level(edge.size());
  for (long k = 0; k < g.nz; ++k)
  {
    edge[static_cast<std::size_t>(k)] = edgeHuOfSlice(k);
    level[static_cast<std::size_t>(k)] = lumenHuOfSlice(k);
  }

  // A voxel at the edge level or above, outside the lumen, is part of a piece when it lies in the
  // edge's window and beside no calcium or bone (GrowLumenRegion step 2); otherwise it is the
  // blurred rim of a plaque or bone (or the calcium itself), and a piece that meets one is
  // rejected: the rim of a calcified arc is thin and long, as a branch is.
  enum class Voxel
  {
    Other,
    Piece,
    Blocked
  };
  const auto classify = [&](long flat)
  {
    if (mask[flat] || hu[flat] < edge[static_cast<std::size_t>(flat / (g.nx * g.ny))])
      return Voxel::Other;
    if (hu[flat] > upperHu)
      return Voxel::Blocked;
    bool besideCalcium = false;
    g.ForFaceNeighbours(flat, [&](long n) { besideCalcium = besideCalcium || hu[n] > calciumHu; });
    return besideCalcium ? Voxel::Blocked : Voxel::Piece;
  };

  std::vector<long> seeds;
  ForEachInBox(lumenBox, size,
               [&](long, long image)
               {
                 if (mask[image])
                   g.ForFaceNeighbours(image,
                                       [&](long n)
                                       {
                                         if (classify(n) == Voxel::Piece)
                                           seeds.push_back(n);
                                       });
               });
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());

  // The ball's offsets farthest first: in a thin piece the test fails on the first few.
  std::vector<std::array<int, 3>> ball =
    PhysicalBallOffsets({ spacing[0], spacing[1], spacing[2] }, params.maxRadiusMm);
  const auto length = [&](const std::array<int, 3>& d)
  { return std::pow(d[0] * spacing[0], 2) + std::pow(d[1] * spacing[1], 2) + std::pow(d[2] * spacing[2], 2); };
  std::stable_sort(ball.begin(), ball.end(), [&](const auto& x, const auto& y) { return length(x) > length(y); });

  std::unordered_map<long, int> pieceOf; // every voxel a piece has taken, and that piece's number
  int pieceNumber = 0;
  for (long seed : seeds)
  {
    if (pieceOf.count(seed))
      continue;
    const int number = ++pieceNumber;
    std::vector<long> piece{ seed };
    pieceOf[seed] = number;
    bool rejected = false; // a flood, or a piece that meets calcium or bone
    for (std::size_t q = 0; q < piece.size() && !rejected; ++q)
      g.ForFaceNeighbours(piece[q],
                          [&](long n)
                          {
                            if (rejected)
                              return;
                            const Voxel kind = classify(n);
                            if (kind == Voxel::Other)
                              return;
                            const auto taken = pieceOf.find(n);
                            if (kind == Voxel::Blocked || (taken != pieceOf.end() && taken->second != number))
                            {
                              // Calcium's rim, or a piece rejected before (a finished piece is a
                              // whole component, so only a rejected one's remainder can be met).
                              rejected = true;
                              return;
                            }
                            if (taken != pieceOf.end())
                              return;
                            pieceOf[n] = number;
                            piece.push_back(n);
                            rejected = piece.size() > maxVoxels;
                          });
    if (rejected)
      continue;
    const PieceBox box = BoxOf(g, piece);
    std::vector<long> touching;
    for (long flat : piece)
    {
      bool touches = false;
      g.ForFaceNeighbours(flat, [&](long n) { touches = touches || mask[n] != 0; });
      if (touches)
        touching.push_back(box.Local(g, flat));
    }
    // The branch's core keeps lumen contrast (its blurred peak above half-way between the edge
    // and the lumen); an enhancing vein or a kidney at the edge level does not.
    std::vector<double> aboveCore;
    aboveCore.reserve(piece.size());
    for (long flat : piece)
    {
      const auto k = static_cast<std::size_t>(flat / (g.nx * g.ny));
      aboveCore.push_back(hu[flat] - 0.5 * (edge[k] + level[k]));
    }
    const auto p90 = aboveCore.begin() + static_cast<long>(0.9 * double(aboveCore.size() - 1));
    std::nth_element(aboveCore.begin(), p90, aboveCore.end());
    if (*p90 < 0.0 || ReachMm(box, touching, spacing) < params.minReachMm || HoldsBall(box, ball, params.ballHoleShare))
      continue;
    for (long flat : piece)
      mask[flat] = 1;
    ++result.pieces;
    result.addedMl += static_cast<double>(piece.size()) * voxelMl;
  }
  return result;
}

} // namespace sgp
