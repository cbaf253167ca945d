// Spatially coherent insertion order (private kernel). See pcsSpatialSort.h.
//
// Each point gets a Hilbert index on a 2^16 grid per axis over the bounding box of the
// referenced points (48 bits in 3D, 32 bits in 2D). The index is computed with Skilling's
// transpose formulation ("Programming the Hilbert curve", AIP Conf. Proc. 707, 2004): the grid
// coordinates are turned into the transposed Hilbert index by undoing the rotations level by
// level and Gray-encoding the result; the bits are then interleaved into one integer key. Sorting
// by key gives the curve order. Keys and sorts run in parallel (vtkSMPTools).
#include "pcsSpatialSort.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>

namespace pcs
{
namespace
{
// 16 levels (65536 cells per axis) separate far more points than a triangulation holds near
// any one cell; finer levels would only cost time.
constexpr int BitsPerAxis = 16;

// Spread the 16 low bits of v so that bit i moves to bit dim * i.
uint64_t Spread(uint32_t v, int dim)
{
  uint64_t x = v & 0xffffu;
  if (dim == 2)
  {
    x = (x | (x << 8)) & 0x00ff00ffull;
    x = (x | (x << 4)) & 0x0f0f0f0full;
    x = (x | (x << 2)) & 0x33333333ull;
    x = (x | (x << 1)) & 0x55555555ull;
    return x;
  }
  x = (x | (x << 16)) & 0x0000ff0000ffull;
  x = (x | (x << 8)) & 0x00f00f00f00full;
  x = (x | (x << 4)) & 0x0c30c30c30c3ull;
  x = (x | (x << 2)) & 0x249249249249ull;
  return x;
}

// Hilbert index of the grid point x (dim = 2 or 3 coordinates of BitsPerAxis bits). The
// coordinates are kept in local variables (no aliasing through memory) and every step is
// branch-free: the bit tested at each level is random, so branches would mispredict half of the
// time.
template <int Dim>
uint64_t HilbertKey(const uint32_t* input)
{
  uint32_t x[Dim];
  for (int i = 0; i < Dim; ++i)
  {
    x[i] = input[i];
  }
  // Undo the rotations (inverse of the curve's recursive construction): for each level q and
  // axis i, when bit q of x[i] is set invert the low bits of x[0], else exchange the low bits of
  // x[0] and x[i].
  for (uint32_t q = 1u << (BitsPerAxis - 1); q > 1; q >>= 1)
  {
    const uint32_t lower = q - 1;
    x[0] ^= lower & (0u - ((x[0] & q) != 0));
    for (int i = 1; i < Dim; ++i)
    {
      const uint32_t set = 0u - static_cast<uint32_t>((x[i] & q) != 0);
      const uint32_t t = (x[0] ^ x[i]) & lower & ~set;
      x[0] ^= (lower & set) | t;
      x[i] ^= t;
    }
  }
  // Gray encode.
  for (int i = 1; i < Dim; ++i)
  {
    x[i] ^= x[i - 1];
  }
  uint32_t t = 0;
  for (uint32_t q = 1u << (BitsPerAxis - 1); q > 1; q >>= 1)
  {
    t ^= (q - 1) & (0u - static_cast<uint32_t>((x[Dim - 1] & q) != 0));
  }
  // Interleave: at every level, axis 0 gives the most significant bit.
  uint64_t key = 0;
  for (int i = 0; i < Dim; ++i)
  {
    key |= Spread(x[i] ^ t, Dim) << (Dim - 1 - i);
  }
  return key;
}
} // namespace

// Large ranges: a least-significant-digit radix sort on the key bits in use (16-bit digits:
// three linear passes for 48-bit keys, where a comparison sort needs about 20 passes' worth of
// comparisons); it is stable, so a final scan only has to order the rare runs of equal keys
// (points in one grid cell) by id.
void SortKeys(std::vector<KeyedId>::iterator first,
  std::vector<KeyedId>::iterator last,
  int keyBits,
  std::vector<KeyedId>& scratch,
  int digitBits)
{
  const size_t n = static_cast<size_t>(last - first);
  if (n < 2048)
  {
    std::sort(first, last);
    return;
  }
  scratch.resize(n);
  KeyedId* source = &*first;
  KeyedId* target = scratch.data();
  const size_t digits = size_t(1) << digitBits;
  const uint64_t mask = digits - 1;
  std::vector<size_t> count(digits + 1);
  int passes = 0;
  for (int shift = 0; shift < keyBits; shift += digitBits, ++passes)
  {
    std::fill(count.begin(), count.end(), 0);
    for (size_t i = 0; i < n; ++i)
    {
      ++count[((source[i].first >> shift) & mask) + 1];
    }
    for (size_t d = 0; d < digits; ++d)
    {
      count[d + 1] += count[d];
    }
    for (size_t i = 0; i < n; ++i)
    {
      target[count[(source[i].first >> shift) & mask]++] = source[i];
    }
    std::swap(source, target);
  }
  if (passes % 2 == 1)
  {
    std::copy(source, source + n, &*first);
  }
  // Equal keys (points in one grid cell): order by id, as std::sort on the pairs would.
  for (auto run = first; run != last;)
  {
    auto end = run + 1;
    while (end != last && end->first == run->first)
    {
      ++end;
    }
    if (end - run > 1 && !std::is_sorted(run, end)) // (ids given in order stay in order)
    {
      std::sort(run, end);
    }
    run = end;
  }
}

namespace
{
// Keys of the points `begin..end` (in that order) over their own bounding box.
void ComputeKeys(const double* coords,
  int dim,
  const int32_t* begin,
  const int32_t* end,
  std::vector<KeyedId>& keyed)
{
  double lo[3] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max() };
  double hi[3] = { -lo[0], -lo[1], -lo[2] };
  for (const int32_t* it = begin; it != end; ++it)
  {
    const double* p = coords + static_cast<int64_t>(dim) * *it;
    for (int i = 0; i < dim; ++i)
    {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  }
  // One common scale for all axes keeps the curve's cells cubic (a flat cloud stays local).
  double extent = 0.0;
  for (int i = 0; i < dim; ++i)
  {
    extent = std::max(extent, hi[i] - lo[i]);
  }
  const double cells = static_cast<double>((1u << BitsPerAxis) - 1);
  const double scale = extent > 0.0 && std::isfinite(extent) ? cells / extent : 0.0;

  const int64_t count = end - begin;
  keyed.resize(count);
  vtkSMPTools::For(0, count, 4096, [&](int64_t first, int64_t last) {
    for (int64_t i = first; i < last; ++i)
    {
      const int32_t id = begin[i];
      const double* p = coords + static_cast<int64_t>(dim) * id;
      uint32_t x[3] = { 0, 0, 0 };
      for (int k = 0; k < dim; ++k)
      {
        const double g = (p[k] - lo[k]) * scale;
        x[k] = static_cast<uint32_t>(std::min(std::max(g, 0.0), cells));
      }
      keyed[i] = std::make_pair(dim == 3 ? HilbertKey<3>(x) : HilbertKey<2>(x), id);
    }
  });
}
} // namespace

//------------------------------------------------------------------------------------------------
void HilbertSort(const double* coords, int dim, int32_t* begin, int32_t* end)
{
  if (end - begin < 2)
  {
    return;
  }
  std::vector<std::pair<uint64_t, int32_t>> keyed;
  ComputeKeys(coords, dim, begin, end, keyed);
  std::vector<KeyedId> scratch;
  SortKeys(keyed.begin(), keyed.end(), dim * BitsPerAxis, scratch);
  for (const auto& k : keyed)
  {
    *begin++ = k.second;
  }
}

//------------------------------------------------------------------------------------------------
void BRIOHilbertOrder(const double* coords, int dim, std::vector<int32_t>& ids, unsigned int seed,
  int32_t minimumRoundSize)
{
  const int64_t n = static_cast<int64_t>(ids.size());
  if (n < 2)
  {
    return;
  }
  // Keys over the bounding box of the whole set, so that every round follows the same curve.
  std::vector<std::pair<uint64_t, int32_t>> keyed;
  ComputeKeys(coords, dim, ids.data(), ids.data() + n, keyed);

  std::mt19937_64 rng(seed);
  std::shuffle(keyed.begin(), keyed.end(), rng);
  std::vector<KeyedId> scratch;

  // Rounds: [0, n0) [n0, n1) ... [n_k, n), each holding 7/8 of the points up to its end.
  const int64_t minimum = std::max<int64_t>(minimumRoundSize, 1);
  int64_t end = n;
  while (end > 0)
  {
    const int64_t begin = end > minimum ? end / 8 : 0;
    SortKeys(keyed.begin() + begin, keyed.begin() + end, dim * BitsPerAxis, scratch);
    end = begin;
  }
  for (int64_t i = 0; i < n; ++i)
  {
    ids[i] = keyed[i].second;
  }
}
} // namespace pcs
