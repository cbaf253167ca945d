#include "pcsPiles.h"

#include "pcsDisjointSets.h"
#include "pcsNearestNeighbors.h"
#include "pcsSpatialSort.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <sstream>

namespace pcs
{
namespace
{
// The diagonal of a bounding box (xmin, xmax, ymin, ymax, zmin, zmax).
double BoxDiagonal(const double* box)
{
  return std::sqrt((box[1] - box[0]) * (box[1] - box[0]) + (box[3] - box[2]) * (box[3] - box[2]) +
    (box[5] - box[4]) * (box[5] - box[4]));
}

// Whether the table can show a pile (FindPiles), by three conditions of which every
// pile meets one (with d1 and dk a point's distances to the first and k-th point of its row):
// a pile of at most k points, or one a member's row leaves, has a member with d1 under
// PileRatio x dk (its row reaches a point outside, beyond the pile's diagonal / ratio);
// a larger pile that only rows of outside points reach has a member m in the row of an outside
// point r with dk(m) under PileRatio x dk(r); a pile no row reaches or leaves has dk
// under PileRatio x the cloud's diagonal. O(n k) lookups; on clean samples none holds.
bool MayHoldPiles(const double* x,
  int32_t n,
  const std::vector<int32_t>& knn,
  int width,
  int k,
  double cloudDiagonal)
{
  std::vector<double> farthest(n);
  std::vector<uint8_t> found(n, 0);
  vtkSMPTools::For(0,
    n,
    [&](int32_t begin, int32_t end)
    {
      for (int32_t i = begin; i < end; ++i)
      {
        const int32_t* row = &knn[static_cast<size_t>(i) * width];
        if (row[0] < 0 || row[k - 1] < 0)
        {
          farthest[i] = std::numeric_limits<double>::infinity(); // (an incomplete row)
          continue;
        }
        farthest[i] = PointDistance(x, i, row[k - 1]);
        found[i] = PointDistance(x, i, row[0]) < PileRatio * farthest[i] ||
          farthest[i] < PileRatio * cloudDiagonal;
      }
    });
  vtkSMPTools::For(0,
    n,
    [&](int32_t begin, int32_t end)
    {
      for (int32_t i = begin; i < end; ++i)
      {
        const int32_t* row = &knn[static_cast<size_t>(i) * width];
        for (int j = 0; j < k && !found[i]; ++j)
        {
          found[i] = row[j] >= 0 && farthest[row[j]] < PileRatio * farthest[i];
        }
      }
    });
  return std::find(found.begin(), found.end(), 1) != found.end();
}

// An edge of the table's graph: its ends A < B.
struct Edge
{
  double Length;
  int32_t A, B;
};

// Sorts the edges by length, then A, then B: radix-sorted by the bits of their lengths (SortKeys;
// non-negative doubles order as their bits do), then each run of equal lengths by its ends.
void SortByLength(std::vector<Edge>& edges)
{
  auto shorter = [](const Edge& a, const Edge& b)
  {
    return a.Length < b.Length ||
      (a.Length == b.Length && (a.A < b.A || (a.A == b.A && a.B < b.B)));
  };
  if (edges.size() > static_cast<size_t>(std::numeric_limits<int32_t>::max()))
  {
    std::sort(edges.begin(), edges.end(), shorter); // (more edges than SortKeys' ids hold)
    return;
  }
  std::vector<KeyedId> keyed(edges.size());
  for (size_t e = 0; e < edges.size(); ++e)
  {
    uint64_t bits;
    std::memcpy(&bits, &edges[e].Length, sizeof bits);
    keyed[e] = { bits, static_cast<int32_t>(e) };
  }
  std::vector<KeyedId> scratch;
  SortKeys(keyed.begin(), keyed.end(), 64, scratch);
  std::vector<Edge> sorted(edges.size());
  for (size_t e = 0; e < edges.size(); ++e)
  {
    sorted[e] = edges[keyed[e].second];
  }
  for (auto run = sorted.begin(); run != sorted.end();)
  {
    auto end = run + 1;
    while (end != sorted.end() && end->Length == run->Length)
    {
      ++end;
    }
    if (end - run > 1)
    {
      std::sort(run, end, shorter);
    }
    run = end;
  }
  edges.swap(sorted);
}
}

int32_t FindPiles(const double* x,
  int32_t n,
  const std::vector<int32_t>& knn,
  int width,
  std::vector<int32_t>& groupOf,
  int k)
{
  if (n < 2 || k < 1 || width < k)
  {
    groupOf.clear();
    return n;
  }
  auto inRow = [&](int32_t row, int32_t id)
  {
    const int32_t* r = &knn[static_cast<size_t>(row) * width];
    return std::find(r, r + k, id) != r + k;
  };
  double cloudBox[6];
  for (int c = 0; c < 3; ++c)
  {
    cloudBox[2 * c] = cloudBox[2 * c + 1] = x[c];
  }
  for (int32_t i = 1; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      cloudBox[2 * c] = std::min(cloudBox[2 * c], x[3 * static_cast<size_t>(i) + c]);
      cloudBox[2 * c + 1] = std::max(cloudBox[2 * c + 1], x[3 * static_cast<size_t>(i) + c]);
    }
  }
  const double cloudDiagonal = BoxDiagonal(cloudBox);
  if (!MayHoldPiles(x, n, knn, width, k, cloudDiagonal))
  {
    groupOf.clear();
    return n;
  }
  std::vector<Edge> edges;
  edges.reserve(static_cast<size_t>(n) * k);
  double shortest = std::numeric_limits<double>::infinity(), longest = 0.0;
  for (int32_t i = 0; i < n; ++i)
  {
    for (int j = 0; j < k; ++j)
    {
      const int32_t q = knn[static_cast<size_t>(i) * width + j];
      if (q < 0 || q == i || (q < i && inRow(q, i)))
      {
        continue; // (an edge in both rows is taken once, from the row of its smaller end)
      }
      edges.push_back({ PointDistance(x, i, q), std::min(i, q), std::max(i, q) });
      shortest = std::min(shortest, edges.back().Length);
      longest = std::max(longest, edges.back().Length);
    }
  }
  // A group an edge leaves has a diagonal of at least the shortest edge (two of its points are
  // joined by one) and is left by an edge no longer than the longest: unless the shortest edge is
  // under PileRatio x the longest no such group is a pile, and the order does not matter
  // (only separate parts of the graph can be piles).
  if (shortest < PileRatio * longest)
  {
    SortByLength(edges);
  }
  // The merge tree: points 0..n-1, then one node per merge; `sets` is the union-find over the
  // points, `top` the tree node of each union-find root.
  DisjointSets<int32_t> sets(n);
  std::vector<int32_t> top(n), parent(n, -1);
  std::iota(top.begin(), top.end(), 0);
  std::vector<double> box(6 * static_cast<size_t>(n));
  for (int32_t i = 0; i < n; ++i)
  {
    double* bi = &box[6 * static_cast<size_t>(i)];
    for (int c = 0; c < 3; ++c)
    {
      bi[2 * c] = bi[2 * c + 1] = x[3 * static_cast<size_t>(i) + c];
    }
  }
  auto diagonal = [&](int32_t r) { return BoxDiagonal(&box[6 * static_cast<size_t>(r)]); };
  // A group holding more than half of the points is never a pile: it is most of the cloud, and
  // what lies beyond its gap are stray points (the outlier rule's to judge), not the other way
  // round. Without this one far point (a scanner's failed return at 10^12) made the whole
  // sampled object one "pile", and no surface was made.
  auto mayBePile = [n](int32_t size) { return 2 * static_cast<int64_t>(size) <= n; };
  std::vector<uint8_t> pile(n, 0); // by tree node
  for (const Edge& e : edges)
  {
    const int32_t a = sets.Find(e.A), b = sets.Find(e.B);
    if (a == b)
    {
      continue;
    }
    for (const int32_t r : { a, b })
    {
      pile[top[r]] = pile[top[r]] ||
        (sets.GetSize(r) > 1 && mayBePile(sets.GetSize(r)) && diagonal(r) < PileRatio * e.Length);
    }
    const int32_t kept = sets.Link(a, b);
    const int32_t absorbed = kept == a ? b : a;
    double* into = &box[6 * static_cast<size_t>(kept)];
    const double* from = &box[6 * static_cast<size_t>(absorbed)];
    for (int c = 0; c < 3; ++c)
    {
      into[2 * c] = std::min(into[2 * c], from[2 * c]);
      into[2 * c + 1] = std::max(into[2 * c + 1], from[2 * c + 1]);
    }
    const int32_t node = static_cast<int32_t>(parent.size());
    parent[top[a]] = parent[top[b]] = node;
    parent.push_back(-1);
    pile.push_back(0);
    top[kept] = node;
  }
  // Each point's largest pile (a node's parent is made after it: top-down from the last node).
  std::vector<int32_t> pileOf(parent.size(), -1);
  auto findLargestPiles = [&]()
  {
    for (size_t node = parent.size(); node-- > 0;)
    {
      const int32_t up = parent[node] >= 0 ? pileOf[parent[node]] : -1;
      pileOf[node] = up >= 0 ? up : (pile[node] ? static_cast<int32_t>(node) : -1);
    }
  };
  findLargestPiles();
  // Separate parts of the graph: a pile if its diagonal is under PileRatio times both its
  // distance to the rest (a radius query) and the sampling of the rest (the median, over the
  // points outside the part and in no pile, of the distance to the k-th point of their row).
  // Without the second condition a separately sampled object far from the rest (two scanned
  // objects 10^4 of their size apart) would be one "pile": a gap alone does not make a sampled
  // surface unresolvable. A cloud made of such parts only is judged by the gaps.
  std::vector<int32_t> partRoots;
  for (int32_t i = 0; i < n; ++i)
  {
    if (sets.Find(i) == i && sets.GetSize(i) > 1 && mayBePile(sets.GetSize(i)) &&
      diagonal(i) < PileRatio * cloudDiagonal)
    {
      partRoots.push_back(i);
    }
  }
  if (!partRoots.empty())
  {
    // The reach (k-th distance) of the points in no pile: all sorted, and by part.
    std::vector<double> all;
    std::vector<std::vector<double>> byPart(partRoots.size());
    std::vector<int32_t> partOf(n, -1); // by union-find root
    for (size_t p = 0; p < partRoots.size(); ++p)
    {
      partOf[partRoots[p]] = static_cast<int32_t>(p);
    }
    for (int32_t i = 0; i < n; ++i)
    {
      const int32_t last = knn[static_cast<size_t>(i) * width + k - 1];
      if (pileOf[i] < 0 && last >= 0)
      {
        all.push_back(PointDistance(x, i, last));
        const int32_t p = partOf[sets.Find(i)];
        if (p >= 0)
        {
          byPart[p].push_back(all.back());
        }
      }
    }
    std::sort(all.begin(), all.end());
    PointBins bins;
    double bounds[6];
    BuildSurfaceSampleBins(bins, x, n, /*withCoordinates=*/true, bounds);
    for (size_t p = 0; p < partRoots.size(); ++p)
    {
      // The median of `all` without the part's values: the first entry of `all` with more than
      // half of the others' count at or below it, not counting the part's.
      std::vector<double>& own = byPart[p];
      std::sort(own.begin(), own.end());
      const size_t others = all.size() - own.size();
      double sampling = std::numeric_limits<double>::infinity();
      if (others > 0)
      {
        size_t low = 0, high = all.size() - 1;
        while (low < high)
        {
          const size_t mid = (low + high) / 2;
          const size_t ownAtOrBelow =
            std::upper_bound(own.begin(), own.end(), all[mid]) - own.begin();
          if (mid + 1 - std::min(mid + 1, ownAtOrBelow) > others / 2)
          {
            high = mid;
          }
          else
          {
            low = mid + 1;
          }
        }
        sampling = all[low];
      }
      const int32_t r = partRoots[p];
      const double d = diagonal(r);
      if (d < PileRatio * sampling)
      {
        int32_t inside = 0; // (the walk stops at the first point beyond the part's own)
        bins.ForEachPointWithinRadius(d * (1.0 + 1.0 / PileRatio),
          &x[3 * static_cast<size_t>(r)],
          [&](int32_t, double) { return ++inside <= sets.GetSize(r); });
        pile[top[r]] = pile[top[r]] || inside == sets.GetSize(r);
      }
    }
    findLargestPiles();
  }
  groupOf.assign(n, -1);
  std::vector<int32_t> groupOfPile(parent.size(), -1);
  int32_t groups = 0;
  for (int32_t i = 0; i < n; ++i)
  {
    if (pileOf[i] < 0)
    {
      groupOf[i] = groups++;
    }
    else
    {
      int32_t& g = groupOfPile[pileOf[i]];
      g = g >= 0 ? g : groups++;
      groupOf[i] = g;
    }
  }
  return groups;
}

int32_t FirstOfPiles(const std::vector<int32_t>& groupOf, std::vector<int32_t>& firstOf)
{
  const int32_t n = static_cast<int32_t>(groupOf.size());
  // Groups are numbered in the order of their first points.
  std::vector<int32_t> firstOfGroup;
  int32_t copies = 0;
  firstOf.resize(n);
  for (int32_t i = 0; i < n; ++i)
  {
    const int32_t g = groupOf[i];
    if (g == static_cast<int32_t>(firstOfGroup.size()))
    {
      firstOfGroup.push_back(i);
    }
    firstOf[i] = firstOfGroup[g];
    copies += firstOf[i] != i ? 1 : 0;
  }
  if (copies == 0)
  {
    firstOf.clear();
  }
  return copies;
}

std::string DuplicatesWarning(int64_t count, const std::string& kept)
{
  std::ostringstream text;
  text << "Ignored " << count
       << " duplicate point(s): exact copies, or points of a pile (a group whose extent is under "
       << PileRatio << " times its distance to the rest of the cloud); " << kept << ".";
  return text.str();
}
}
