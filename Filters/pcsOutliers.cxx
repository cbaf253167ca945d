#include "pcsOutliers.h"

#include "pcsDuplicatePoints.h"
#include "pcsNearestNeighbors.h"
#include "pcsNormalEstimation.h"

#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace pcs
{
namespace
{
// The distinct positions among `ids` in lexicographic order (packed x, y, z), and for each entry
// of `ids` the index of its position (pcs::FindExactDuplicates).
void DistinctPositions(const double* xyz, const std::vector<int32_t>& ids,
  std::vector<double>& distinct, std::vector<int32_t>& positionOf)
{
  std::vector<int32_t> first, sorted;
  FindExactDuplicates(xyz, 3, ids.data(), static_cast<int32_t>(ids.size()), first, &sorted);
  distinct.clear();
  positionOf.assign(ids.size(), -1);
  for (const int32_t j : sorted)
  {
    if (first[j] == j)
    {
      const double* p = xyz + 3 * static_cast<size_t>(ids[j]);
      distinct.insert(distinct.end(), p, p + 3);
    }
    positionOf[j] = static_cast<int32_t>(distinct.size() / 3 - 1);
  }
}

// Whether the point i lies on the surface its k nearest points sample: all of them are sparse
// too, they form a flat disc (the smallest eigenvalue of their covariance under
// OutlierPlaneVariation of the sum, the middle one at least OutlierPlaneSpread of it: not a
// line) and the point is within OutlierPlaneHeight x its reach of their plane. A sparse part of a sampled surface
// (a region scanned from farther away, next to a much denser patch that holds most of the
// points) passes; a point off a surface (its nearest points a small disc below it) and clutter
// or a clump (nearest points spread in 3D) do not.
bool OnSampledPlane(const double* x, const int32_t* row, int k, int32_t i,
  const std::vector<double>& reach, double sparse)
{
  const double* p = &x[3 * static_cast<size_t>(i)];
  int sparseNeighbors = 0;
  for (int j = 0; j < k; ++j)
  {
    if (row[j] < 0)
    {
      return false;
    }
    sparseNeighbors += reach[row[j]] > sparse ? 1 : 0;
  }
  if (sparseNeighbors < k)
  {
    return false; // next to the dense sample: an isolated point or a clump beside the surface
  }
  double covariance[3][3];
  if (OffsetCovariance(x, p, row, k, false, covariance) < k)
  {
    return false;
  }
  double values[3], normal[3];
  SmallestEigenvector(covariance, values, normal);
  const double sum = values[0] + values[1] + values[2];
  if (!(sum > 0.0) || !(values[2] < OutlierPlaneVariation * sum) ||
    !(values[1] >= OutlierPlaneSpread * sum))
  {
    return false;
  }
  // The neighbours' centroid relative to p: the mean offset.
  double mean[3] = { 0, 0, 0 };
  for (int j = 0; j < k; ++j)
  {
    const double* q = &x[3 * static_cast<size_t>(row[j])];
    for (int c = 0; c < 3; ++c)
    {
      mean[c] += (q[c] - p[c]) / k;
    }
  }
  const double height = std::fabs(mean[0] * normal[0] + mean[1] * normal[1] + mean[2] * normal[2]);
  return height < OutlierPlaneHeight * reach[i];
}

double Median(std::vector<double> values)
{
  const auto middle = values.begin() + values.size() / 2;
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// A locator over the n points of xyz (packed x, y, z, not copied: xyz must outlive the locator)
// with the bin grid of a surface sample (SetSurfaceSampleDivisions).
vtkSmartPointer<vtkStaticPointLocator> SurfaceSampleLocator(const double* xyz, int32_t n)
{
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetArray(const_cast<double*>(xyz), 3 * static_cast<vtkIdType>(n), 1);
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  auto locator = vtkSmartPointer<vtkStaticPointLocator>::New();
  double bounds[6];
  points->GetBounds(bounds);
  SetSurfaceSampleDivisions(locator, bounds, n);
  locator->SetDataSet(cloud);
  locator->BuildLocator();
  return locator;
}

// The distance between the points a and b of x (packed x, y, z).
double PointDistance(const double* x, int32_t a, int32_t b)
{
  const double* p = &x[3 * static_cast<size_t>(a)];
  const double* q = &x[3 * static_cast<size_t>(b)];
  return std::sqrt(
    (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

// The diagonal of a bounding box (xmin, xmax, ymin, ymax, zmin, zmax).
double BoxDiagonal(const double* box)
{
  return std::sqrt((box[1] - box[0]) * (box[1] - box[0]) + (box[3] - box[2]) * (box[3] - box[2]) +
    (box[5] - box[4]) * (box[5] - box[4]));
}

// Whether the table can show a pile (NearCoincidentGroups), by three conditions of which every
// pile meets one (with d1 and dk a point's distances to the first and k-th point of its row):
// a pile of at most k points, or one a member's row leaves, has a member with d1 under
// OutlierPileRatio x dk (its row reaches a point outside, beyond the pile's diagonal / ratio);
// a larger pile that only rows of outside points reach has a member m in the row of an outside
// point r with dk(m) under OutlierPileRatio x dk(r); a pile no row reaches or leaves has dk
// under OutlierPileRatio x the cloud's diagonal. O(n k) lookups; on clean samples none holds.
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
        found[i] = PointDistance(x, i, row[0]) < OutlierPileRatio * farthest[i] ||
          farthest[i] < OutlierPileRatio * cloudDiagonal;
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
          found[i] = row[j] >= 0 && farthest[row[j]] < OutlierPileRatio * farthest[i];
        }
      }
    });
  return std::find(found.begin(), found.end(), 1) != found.end();
}

// Piles: groups of near-coincident points, each to count as one position (OutlierPileRatio).
// Single linkage over the graph of the k nearest neighbours (the first k entries of each row of
// `knn`), its edges taken shortest first: when an edge first leaves a group of two or more points
// (its shortest edge to the rest), the group is a pile if the diagonal of its bounding box is
// under OutlierPileRatio times that edge. A group no edge leaves (a separate part of the graph)
// is a pile if no other point lies within its diagonal x (1 + 1 / OutlierPileRatio) of one of its
// points. A point belongs to the largest pile that holds it. `groupOf` gets each point's group,
// numbered in the order of their first points; returns the number of groups (n: no pile, and
// `groupOf` is left empty). Cost: MayHoldPiles, and only when it holds, the edges gathered and
// sorted, and a radius query per separate part of the graph whose diagonal is under
// OutlierPileRatio times the cloud's.
int32_t NearCoincidentGroups(const double* x,
  int32_t n,
  const std::vector<int32_t>& knn,
  int width,
  int k,
  std::vector<int32_t>& groupOf)
{
  struct Edge
  {
    double Length;
    int32_t A, B;
  };
  auto inRow = [&](int32_t row, int32_t id)
  {
    const int32_t* r = &knn[static_cast<size_t>(row) * width];
    return std::find(r, r + k, id) != r + k;
  };
  double cloudBox[6];
  {
    vtkNew<vtkDoubleArray> coordinates;
    coordinates->SetNumberOfComponents(3);
    coordinates->SetArray(const_cast<double*>(x), 3 * static_cast<vtkIdType>(n), 1);
    coordinates->GetRange(cloudBox, 0);
    coordinates->GetRange(cloudBox + 2, 1);
    coordinates->GetRange(cloudBox + 4, 2);
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
  // under OutlierPileRatio x the longest no such group is a pile, and the order does not matter
  // (only separate parts of the graph can be piles).
  if (shortest < OutlierPileRatio * longest)
  {
    vtkSMPTools::Sort(edges.begin(),
      edges.end(),
      [](const Edge& a, const Edge& b)
      {
        return a.Length < b.Length ||
          (a.Length == b.Length && (a.A < b.A || (a.A == b.A && a.B < b.B)));
      });
  }
  // The merge tree: points 0..n-1, then one node per merge; `root` is the union-find over the
  // points, `top` the tree node of each union-find root.
  std::vector<int32_t> root(n), top(n), parent(n, -1);
  std::iota(root.begin(), root.end(), 0);
  std::iota(top.begin(), top.end(), 0);
  std::vector<double> box(6 * static_cast<size_t>(n));
  std::vector<int32_t> size(n, 1);
  for (int32_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      box[6 * i + 2 * c] = box[6 * i + 2 * c + 1] = x[3 * static_cast<size_t>(i) + c];
    }
  }
  auto findRoot = [&](int32_t i)
  {
    while (root[i] != i)
    {
      i = root[i] = root[root[i]];
    }
    return i;
  };
  auto diagonal = [&](int32_t r) { return BoxDiagonal(&box[6 * static_cast<size_t>(r)]); };
  std::vector<uint8_t> pile(n, 0); // by tree node
  for (const Edge& e : edges)
  {
    int32_t a = findRoot(e.A), b = findRoot(e.B);
    if (a == b)
    {
      continue;
    }
    for (const int32_t r : { a, b })
    {
      pile[top[r]] = pile[top[r]] || (size[r] > 1 && diagonal(r) < OutlierPileRatio * e.Length);
    }
    if (size[a] < size[b])
    {
      std::swap(a, b);
    }
    root[b] = a;
    size[a] += size[b];
    for (int c = 0; c < 3; ++c)
    {
      box[6 * a + 2 * c] = std::min(box[6 * a + 2 * c], box[6 * b + 2 * c]);
      box[6 * a + 2 * c + 1] = std::max(box[6 * a + 2 * c + 1], box[6 * b + 2 * c + 1]);
    }
    const int32_t node = static_cast<int32_t>(parent.size());
    parent[top[a]] = parent[top[b]] = node;
    parent.push_back(-1);
    pile.push_back(0);
    top[a] = node;
  }
  // Separate parts of the graph: their distance to the rest, by a radius query.
  std::vector<int32_t> partRoots;
  for (int32_t i = 0; i < n; ++i)
  {
    if (findRoot(i) == i)
    {
      partRoots.push_back(i);
    }
  }
  if (partRoots.size() > 1)
  {
    vtkSmartPointer<vtkStaticPointLocator> locator = SurfaceSampleLocator(x, n);
    vtkNew<vtkIdList> inside;
    for (const int32_t r : partRoots)
    {
      const double d = diagonal(r);
      if (size[r] > 1 && d < OutlierPileRatio * cloudDiagonal)
      {
        locator->FindPointsWithinRadius(
          d * (1.0 + 1.0 / OutlierPileRatio), &x[3 * static_cast<size_t>(r)], inside);
        pile[top[r]] = pile[top[r]] || inside->GetNumberOfIds() == size[r];
      }
    }
  }
  // Each point's largest pile (a node's parent is made after it: top-down from the last node).
  std::vector<int32_t> pileOf(parent.size(), -1);
  for (size_t node = parent.size(); node-- > 0;)
  {
    const int32_t up = parent[node] >= 0 ? pileOf[parent[node]] : -1;
    pileOf[node] = up >= 0 ? up : (pile[node] ? static_cast<int32_t>(node) : -1);
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

// The rule of FlagOutliers on points without piles.
int64_t FlagOutliersOfPositions(const double* x,
  int32_t n,
  const std::vector<int32_t>& knn,
  int width,
  double factor,
  std::vector<uint8_t>& far)
{
  far.assign(n, 0);
  const int k = OutlierNeighbors;
  // Reach: mean distance to the k nearest distinct points.
  std::vector<double> reach(n);
  vtkSMPTools::For(0, n, [&](int32_t begin, int32_t end) {
    for (int32_t i = begin; i < end; ++i)
    {
      double sum = 0.0;
      for (int j = 0; j < k; ++j)
      {
        sum += PointDistance(x, i, knn[static_cast<size_t>(i) * width + j]);
      }
      reach[i] = sum / k;
    }
  });
  // Candidates: sparser than OutlierSparseFactor x the cloud's median reach. Each is compared
  // with the median reach of its OutlierNeighbors nearest dense points (the others): next to a
  // sparse region of a graded sample these are at the edge of the sparse region (reach about
  // OutlierSparseFactor x the median), next to an outlier or clutter they are the sampled
  // surface.
  const double sparse = OutlierSparseFactor * Median(reach);
  // Sparse points on the flat sample of their own nearest points; one counts as a sampled part of
  // the surface (never an outlier) when at least half of its nearest points are too: a point of
  // clutter whose nearest points happen to lie flat around it has neighbours that do not.
  std::vector<uint8_t> flat(n, 0);
  vtkSMPTools::For(0, n, [&](int32_t begin, int32_t end) {
    for (int32_t i = begin; i < end; ++i)
    {
      flat[i] = reach[i] > sparse &&
        OnSampledPlane(x, &knn[static_cast<size_t>(i) * width], k, i, reach, sparse);
    }
  });
  auto onSampledSurface = [&](int32_t i) {
    if (!flat[i])
    {
      return false; // (a flat point's row is complete: OnSampledPlane checked it)
    }
    int flatNeighbors = 0;
    for (int j = 0; j < k; ++j)
    {
      flatNeighbors += flat[knn[static_cast<size_t>(i) * width + j]];
    }
    return 2 * flatNeighbors >= k;
  };
  std::vector<int32_t> denseIds;
  for (int32_t i = 0; i < n; ++i)
  {
    if (!(reach[i] > sparse))
    {
      denseIds.push_back(i);
    }
  }
  if (denseIds.size() == static_cast<size_t>(n) || denseIds.empty())
  {
    return 0;
  }
  std::vector<double> denseXyz;
  denseXyz.reserve(3 * denseIds.size());
  for (const int32_t i : denseIds)
  {
    const double* p = &x[3 * static_cast<size_t>(i)];
    denseXyz.insert(denseXyz.end(), p, p + 3);
  }
  vtkSmartPointer<vtkStaticPointLocator> denseLocator =
    SurfaceSampleLocator(denseXyz.data(), static_cast<int32_t>(denseIds.size()));
  const int nearest = std::min<int>(k, static_cast<int>(denseIds.size()));
  vtkSMPThreadLocal<std::vector<double>> aroundLocal;
  vtkSMPThreadLocalObject<vtkIdList> listLocal;
  vtkSMPTools::For(0, n, [&](int32_t begin, int32_t end) {
    std::vector<double>& around = aroundLocal.Local();
    vtkIdList* list = listLocal.Local();
    for (int32_t i = begin; i < end; ++i)
    {
      // (A point on a sampled surface is never an outlier: tested first, it needs no query. Where
      // the dense points are a few clumps, e.g. piles of near-coincident points, the sparse
      // points are the rest of the surface, and each query swept the empty bins out to a clump
      // and sorted its points.)
      if (!(reach[i] > sparse) || onSampledSurface(i))
      {
        continue;
      }
      denseLocator->FindClosestNPoints(nearest, &x[3 * static_cast<size_t>(i)], list);
      around.clear();
      for (vtkIdType j = 0; j < list->GetNumberOfIds(); ++j)
      {
        around.push_back(reach[denseIds[list->GetId(j)]]);
      }
      if (!around.empty())
      {
        std::nth_element(around.begin(), around.begin() + around.size() / 2, around.end());
        far[i] = reach[i] > factor * around[around.size() / 2];
      }
    }
  });
  int64_t count = 0;
  for (int32_t i = 0; i < n; ++i)
  {
    count += far[i];
  }
  return count;
}
}

int64_t FlagOutliers(const double* x,
  int32_t n,
  const std::vector<int32_t>& knn,
  int width,
  double factor,
  std::vector<uint8_t>& far)
{
  far.assign(static_cast<size_t>(std::max(n, 0)), 0);
  const int k = OutlierNeighbors;
  if (!(factor > 0.0) || n < 4 * k || width < k)
  {
    return 0;
  }
  std::vector<int32_t> groupOf;
  const int32_t groups = NearCoincidentGroups(x, n, knn, width, k, groupOf);
  if (groups == n)
  {
    return FlagOutliersOfPositions(x, n, knn, width, factor, far);
  }
  // Each pile as one position (its first point), with the table made again over the positions.
  if (groups < 4 * k)
  {
    return 0;
  }
  std::vector<double> positions(3 * static_cast<size_t>(groups));
  for (int32_t i = n; i-- > 0;)
  {
    std::copy_n(&x[3 * static_cast<size_t>(i)], 3, &positions[3 * static_cast<size_t>(groupOf[i])]);
  }
  std::vector<int32_t> positionKnn;
  std::vector<uint8_t> farPosition;
  if (!FindNearestNeighbors(
        SurfaceSampleLocator(positions.data(), groups), positions.data(), groups, k, positionKnn) ||
    FlagOutliersOfPositions(positions.data(), groups, positionKnn, k, factor, farPosition) == 0)
  {
    return 0;
  }
  int64_t count = 0;
  for (int32_t i = 0; i < n; ++i)
  {
    far[i] = farPosition[groupOf[i]];
    count += far[i];
  }
  return count;
}

int64_t FindOutliers(const double* xyz, const std::vector<int32_t>& ids, double factor,
  std::vector<uint8_t>& outlier, const std::function<bool(double)>& progress)
{
  outlier.assign(ids.size(), 0);
  if (!(factor > 0.0) || ids.size() < 4 * static_cast<size_t>(OutlierNeighbors))
  {
    return 0;
  }
  std::vector<double> x;
  std::vector<int32_t> positionOf;
  DistinctPositions(xyz, ids, x, positionOf);
  const int32_t n = static_cast<int32_t>(x.size() / 3);
  if (n < 4 * OutlierNeighbors)
  {
    return 0;
  }

  const int k = OutlierNeighbors;
  std::vector<int32_t> knn;
  if (!FindNearestNeighbors(SurfaceSampleLocator(x.data(), n), x.data(), n, k, knn, progress))
  {
    return 0;
  }

  std::vector<uint8_t> far;
  if (FlagOutliers(x.data(), n, knn, k, factor, far) == 0)
  {
    return 0;
  }
  int64_t count = 0;
  for (size_t j = 0; j < ids.size(); ++j)
  {
    outlier[j] = far[positionOf[j]];
    count += outlier[j];
  }
  return count;
}

int64_t RemoveOutliers(const double* xyz, std::vector<int32_t>& ids, double factor,
  const std::function<bool(double)>& progress)
{
  std::vector<uint8_t> outlier;
  const int64_t count = FindOutliers(xyz, ids, factor, outlier, progress);
  if (count > 0)
  {
    size_t kept = 0;
    for (size_t j = 0; j < ids.size(); ++j)
    {
      if (!outlier[j])
      {
        ids[kept++] = ids[j];
      }
    }
    ids.resize(kept);
  }
  return count;
}
}
