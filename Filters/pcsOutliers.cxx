#include "pcsOutliers.h"

#include "pcsDuplicatePoints.h"
#include "pcsNearestNeighbors.h"
#include "pcsNormalEstimation.h"
#include "pcsPiles.h"

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

// The rule of FlagOutliersAndPiles on points without piles.
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

int64_t FlagOutliersAndPiles(const double* x,
  int32_t n,
  const std::vector<int32_t>& knn,
  int width,
  double factor,
  std::vector<uint8_t>& far,
  std::vector<int32_t>& firstOf,
  int64_t& copies)
{
  far.assign(static_cast<size_t>(std::max(n, 0)), 0);
  firstOf.clear();
  copies = 0;
  const int k = OutlierNeighbors;
  static_assert(PileNeighbors <= OutlierNeighbors, "the table holds the piles' neighbours");
  std::vector<int32_t> groupOf;
  const int32_t groups = n > PileNeighbors ? FindPiles(x, n, knn, width, groupOf) : n;
  int64_t count = 0;
  if (!(factor > 0.0) || n < 4 * k || width < k)
  {
    // (no outlier rule)
  }
  else if (groups == n)
  {
    count = FlagOutliersOfPositions(x, n, knn, width, factor, far);
  }
  else if (groups >= 4 * k)
  {
    // Each pile as one position (its first point), with the table made again over the positions.
    std::vector<double> positions(3 * static_cast<size_t>(groups));
    for (int32_t i = n; i-- > 0;)
    {
      std::copy_n(
        &x[3 * static_cast<size_t>(i)], 3, &positions[3 * static_cast<size_t>(groupOf[i])]);
    }
    std::vector<int32_t> positionKnn;
    std::vector<uint8_t> farPosition;
    if (FindNearestNeighbors(SurfaceSampleLocator(positions.data(), groups),
          positions.data(),
          groups,
          k,
          positionKnn) &&
      FlagOutliersOfPositions(positions.data(), groups, positionKnn, k, factor, farPosition) > 0)
    {
      for (int32_t i = 0; i < n; ++i)
      {
        far[i] = farPosition[groupOf[i]];
        count += far[i];
      }
    }
  }
  // The piles that are not outliers, as duplicates (a far pile is flagged whole).
  if (groups < n && FirstOfPiles(groupOf, firstOf) > 0)
  {
    for (int32_t i = 0; i < n; ++i)
    {
      firstOf[i] = far[i] ? i : firstOf[i];
      copies += firstOf[i] != i ? 1 : 0;
    }
    if (copies == 0)
    {
      firstOf.clear();
    }
  }
  return count;
}

int64_t FindOutliersAndPiles(const double* xyz,
  const std::vector<int32_t>& ids,
  double factor,
  std::vector<uint8_t>& outlier,
  std::vector<int32_t>& firstOf,
  int64_t& copies,
  const std::function<bool(double)>& progress,
  bool withExactCopies)
{
  outlier.assign(ids.size(), 0);
  firstOf.clear();
  copies = 0;
  if (ids.size() <= static_cast<size_t>(PileNeighbors))
  {
    return 0;
  }
  std::vector<double> x;
  std::vector<int32_t> positionOf;
  DistinctPositions(xyz, ids, x, positionOf);
  const int32_t n = static_cast<int32_t>(x.size() / 3);
  if (n <= PileNeighbors)
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
  std::vector<int32_t> firstPosition;
  int64_t positionCopies = 0;
  const int64_t flagged =
    FlagOutliersAndPiles(x.data(), n, knn, k, factor, far, firstPosition, positionCopies);
  int64_t count = 0;
  if (flagged > 0)
  {
    for (size_t j = 0; j < ids.size(); ++j)
    {
      outlier[j] = far[positionOf[j]];
      count += outlier[j];
    }
  }
  const int32_t entries = static_cast<int32_t>(ids.size());
  const bool exact = withExactCopies && n < entries;
  if (positionCopies > 0 || exact)
  {
    // The positions in a pile, and the first entry of each pile (indexed by its first position):
    // the first entry that holds one of its positions. With exact copies, the first entry of
    // each position too (an outlier's copies stay outliers).
    std::vector<uint8_t> inPile(n, 0);
    for (int32_t p = 0; p < n && positionCopies > 0; ++p)
    {
      if (firstPosition[p] != p)
      {
        inPile[p] = inPile[firstPosition[p]] = 1;
      }
    }
    std::vector<int32_t> firstEntry(n, -1);
    firstOf.resize(entries);
    for (int32_t j = 0; j < entries; ++j)
    {
      const int32_t p = positionOf[j];
      int32_t& first = firstEntry[positionCopies > 0 ? firstPosition[p] : p];
      first = first >= 0 ? first : j;
      firstOf[j] = inPile[p] || (exact && !outlier[j]) ? first : j;
      copies += firstOf[j] != j ? 1 : 0;
    }
    if (copies == 0)
    {
      firstOf.clear();
    }
  }
  return count;
}

int64_t RemoveOutliersAndPiles(const double* xyz,
  std::vector<int32_t>& ids,
  double factor,
  std::vector<std::pair<int32_t, int32_t>>& pileCopies,
  const std::function<bool(double)>& progress,
  bool withExactCopies)
{
  std::vector<uint8_t> outlier;
  std::vector<int32_t> firstOf;
  int64_t copies = 0;
  pileCopies.clear();
  const int64_t count =
    FindOutliersAndPiles(xyz, ids, factor, outlier, firstOf, copies, progress, withExactCopies);
  if (count > 0 || copies > 0)
  {
    // The pairs first: the compaction below moves the ids (a pile's first point may have moved
    // to an earlier slot by the time one of its copies is reached).
    for (size_t j = 0; j < ids.size() && copies > 0; ++j)
    {
      if (firstOf[j] != static_cast<int32_t>(j))
      {
        pileCopies.emplace_back(ids[j], ids[firstOf[j]]);
      }
    }
    size_t kept = 0;
    for (size_t j = 0; j < ids.size(); ++j)
    {
      if (copies > 0 && firstOf[j] != static_cast<int32_t>(j))
      {
        continue;
      }
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
