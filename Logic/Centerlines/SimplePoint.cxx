#include "Centerlines/SimplePoint.h"

#include <array>
#include <cstdlib>

namespace sgp
{

namespace
{

constexpr std::uint32_t centreBit = 1u << 13;
constexpr std::uint32_t all26 = ((1u << 27) - 1) & ~centreBit;

struct Offsets
{
  int i, j, k;
};

constexpr Offsets OffsetOf(int bit)
{
  return { bit % 3 - 1, (bit / 3) % 3 - 1, bit / 9 - 1 };
}

/// Adjacency masks within the 3×3×3 block, without the centre: adjacency26[b] holds the bits
/// 26-adjacent to bit b, adjacency6[b] those 6-adjacent.
struct AdjacencyTables
{
  std::array<std::uint32_t, 27> adjacency26{};
  std::array<std::uint32_t, 27> adjacency6{};
  std::uint32_t faces = 0; ///< the 6 face neighbours of the centre
  std::uint32_t n18 = 0;   ///< the 18 face and edge neighbours of the centre
  AdjacencyTables()
  {
    for (int a = 0; a < 27; ++a)
    {
      const Offsets p = OffsetOf(a);
      const int order = std::abs(p.i) + std::abs(p.j) + std::abs(p.k);
      if (order == 1)
        faces |= 1u << a;
      if (order == 1 || order == 2)
        n18 |= 1u << a;
      for (int b = 0; b < 27; ++b)
      {
        const Offsets q = OffsetOf(b);
        const int di = std::abs(p.i - q.i), dj = std::abs(p.j - q.j), dk = std::abs(p.k - q.k);
        if (a == b || a == 13 || b == 13 || di > 1 || dj > 1 || dk > 1)
          continue;
        adjacency26[a] |= 1u << b;
        if (di + dj + dk == 1)
          adjacency6[a] |= 1u << b;
      }
    }
  }
};

const AdjacencyTables& Tables()
{
  static const AdjacencyTables tables;
  return tables;
}

/// The component of `set` that contains bit `start`, grown through `adjacency`.
std::uint32_t Component(std::uint32_t set, int start, const std::array<std::uint32_t, 27>& adjacency)
{
  std::uint32_t component = 1u << start, frontier = component;
  while (frontier)
  {
    const int b = __builtin_ctz(frontier);
    frontier &= frontier - 1;
    const std::uint32_t grown = adjacency[b] & set & ~component;
    component |= grown;
    frontier |= grown;
  }
  return component;
}

/// Components of `set` through `adjacency` that contain a bit of `seeds`.
int CountComponents(std::uint32_t set, std::uint32_t seeds, const std::array<std::uint32_t, 27>& adjacency)
{
  int count = 0;
  std::uint32_t remaining = set;
  while (remaining & seeds)
  {
    const std::uint32_t component = Component(remaining, __builtin_ctz(remaining & seeds), adjacency);
    remaining &= ~component;
    ++count;
  }
  return count;
}

} // namespace

int CountNeighbours(std::uint32_t neighbourhood)
{
  return __builtin_popcount(neighbourhood & all26);
}

int ForegroundComponents26(std::uint32_t neighbourhood)
{
  const std::uint32_t set = neighbourhood & all26;
  return CountComponents(set, set, Tables().adjacency26);
}

int BackgroundComponents6(std::uint32_t neighbourhood)
{
  const AdjacencyTables& t = Tables();
  const std::uint32_t background = ~neighbourhood & t.n18;
  return CountComponents(background, t.faces, t.adjacency6);
}

bool IsSimplePoint(std::uint32_t neighbourhood)
{
  return ForegroundComponents26(neighbourhood) == 1 && BackgroundComponents6(neighbourhood) == 1;
}

} // namespace sgp
