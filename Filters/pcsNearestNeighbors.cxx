#include "pcsNearestNeighbors.h"

#include "pcsDuplicatePoints.h"
#include "pcsNormalEstimation.h"

#include "vtkDataSet.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <utility>

namespace pcs
{
namespace
{
inline double Distance2(const double* a, const double* b)
{
  const double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
  return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
}

// Whether the nearest half of the neighbours `row` (k ids, nearest first, -1 for none) of point
// p spread along one direction only, none off that line (see AddOffLineNeighbors); if so, that
// direction (unit) and the distance to the farthest of all k.
bool SpreadsAlongCurve(const double* xyz,
  const double* p,
  const int32_t* row,
  int k,
  double linearity,
  double direction[3],
  double& reach)
{
  if (!IsFinitePosition(p, 3))
  {
    return false;
  }
  // The covariance of the offsets from p to its nearest half (pcs::OffsetCovariance).
  const int nearest = std::max(2, k / 2);
  double covariance[3][3];
  if (OffsetCovariance(xyz, p, row, std::min(nearest, k), false, covariance) < 2.0)
  {
    return false;
  }
  // trace^2 - |C|_F^2 = 2 (l1 l2 + l1 l3 + l2 l3): no eigenvalue needed for the test.
  const double trace = covariance[0][0] + covariance[1][1] + covariance[2][2];
  double frobenius2 = 0.0;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      frobenius2 += covariance[r][c] * covariance[r][c];
    }
  }
  if (!(trace > 0.0) || !std::isfinite(trace) ||
    0.5 * (trace * trace - frobenius2) > linearity * trace * trace)
  {
    return false;
  }
  double values[3];
  LargestEigenvector(covariance, values, direction);
  // Confined to a curve through p: none of them off the line p + t direction (see
  // AddOffLineNeighbors for "off").
  for (int j = 0; j < nearest && j < k; ++j)
  {
    if (row[j] >= 0)
    {
      const double* q = xyz + 3 * static_cast<size_t>(row[j]);
      const double d[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
      const double along = vtkMath::Dot(d, direction);
      if (vtkMath::Dot(d, d) - along * along > along * along)
      {
        return false;
      }
    }
  }
  double reach2 = 0.0; // (the distances only for the points that pass: most do not)
  for (int j = 0; j < k; ++j)
  {
    if (row[j] >= 0)
    {
      reach2 = std::max(reach2, Distance2(p, xyz + 3 * static_cast<size_t>(row[j])));
    }
  }
  reach = std::sqrt(reach2);
  return reach > 0.0;
}
}

void PointBins::Build(vtkStaticPointLocator* locator,
  const double* xyz,
  int32_t n,
  bool withCoordinates)
{
  locator->GetDivisions(this->Divisions);
  const double* bounds = locator->GetBounds();
  double grid[6];
  BulkBounds(xyz, n, bounds, grid);
  if (!std::equal(grid, grid + 6, bounds))
  {
    // A few points far from the rest: the locator's buckets over the whole box would put the
    // rest into a few of them. As many buckets over the bulk box instead (see BulkBounds).
    const double buckets =
      static_cast<double>(this->Divisions[0]) * this->Divisions[1] * this->Divisions[2];
    int divisions[3];
    SurfaceSampleDivisions(grid, n, buckets / std::max<int32_t>(n, 1), divisions);
    this->Build(grid, divisions, xyz, n, withCoordinates);
    return;
  }
  double spacing[3];
  locator->GetSpacing(spacing);
  for (int c = 0; c < 3; ++c)
  {
    this->Origin[c] = bounds[2 * c];
    this->Inverse[c] = spacing[c] > 0.0 ? 1.0 / spacing[c] : 0.0;
  }
  this->Fill(xyz, n, withCoordinates);
}

void PointBins::Build(const double bounds[6],
  const int divisions[3],
  const double* xyz,
  int32_t n,
  bool withCoordinates)
{
  for (int c = 0; c < 3; ++c)
  {
    const double extent = bounds[2 * c + 1] - bounds[2 * c];
    this->Divisions[c] = std::max(1, divisions[c]);
    this->Origin[c] = std::isfinite(bounds[2 * c]) ? bounds[2 * c] : 0.0;
    this->Inverse[c] = extent > 0.0 && std::isfinite(extent) ? this->Divisions[c] / extent : 0.0;
  }
  this->Fill(xyz, n, withCoordinates);
}

void PointBins::Fill(const double* xyz, int32_t n, bool withCoordinates)
{
  const int64_t nx = this->Divisions[0];
  const int64_t nxy = nx * this->Divisions[1];
  const int64_t buckets = nxy * this->Divisions[2];
  std::vector<int64_t> bucketOf(static_cast<size_t>(std::max(n, 0)));
  this->Offsets.assign(static_cast<size_t>(buckets) + 1, 0);
  for (int32_t i = 0; i < n; ++i)
  {
    const double* p = xyz + 3 * static_cast<size_t>(i);
    bucketOf[i] = this->BucketIndex(p[0], 0) + nx * this->BucketIndex(p[1], 1) +
      nxy * this->BucketIndex(p[2], 2);
    ++this->Offsets[bucketOf[i] + 1];
  }
  std::partial_sum(this->Offsets.begin(), this->Offsets.end(), this->Offsets.begin());
  std::vector<int32_t> fill(this->Offsets.begin(), this->Offsets.end() - 1);
  this->Ids.resize(static_cast<size_t>(std::max(n, 0)));
  this->XYZ.resize(withCoordinates ? 3 * this->Ids.size() : 0);
  for (int32_t i = 0; i < n; ++i)
  {
    const int32_t slot = fill[bucketOf[i]]++;
    this->Ids[slot] = i;
    if (withCoordinates)
    {
      std::copy_n(xyz + 3 * static_cast<size_t>(i), 3, &this->XYZ[3 * static_cast<size_t>(slot)]);
    }
  }
}

void PointBins::FileCoordinates(const double* xyz)
{
  if (this->XYZ.size() == 3 * this->Ids.size())
  {
    return;
  }
  this->XYZ.resize(3 * this->Ids.size());
  for (size_t slot = 0; slot < this->Ids.size(); ++slot)
  {
    std::copy_n(xyz + 3 * static_cast<size_t>(this->Ids[slot]), 3, &this->XYZ[3 * slot]);
  }
}

bool FindNearestNeighbors(vtkStaticPointLocator* locator, const double* xyz, int32_t n, int k,
  std::vector<int32_t>& neighbors, const std::function<bool(double)>& progress)
{
  PointBins bins;
  if (n >= 2 && k >= 1)
  {
    bins.Build(locator, xyz, n, /*withCoordinates=*/false);
  }
  return FindNearestNeighbors(bins, xyz, n, k, neighbors, progress);
}

namespace
{
// The k-nearest search of FindNearestNeighbors (see there), on points filed into PointBins: the
// candidate points (all the points of the bins, or those flagged in `candidates`) filed again by
// bucket with each run of exact copies as one entry, and the query of one point's k nearest other
// candidates. Used for every point (FindNearestNeighbors) and for the short rows of the distinct
// positions (DistinctNeighbors: the positions' first copies, on the bins of all the points).
class NearestSearch
{
public:
  NearestSearch(const PointBins& bins,
    const double* xyz,
    int32_t n,
    int k,
    const std::vector<uint8_t>* candidates);

  // The candidates in bucket order: consecutive queries in this order are close in space.
  const std::vector<int32_t>& GetMembers() const { return this->Members; }

  // For each point i of `ids` (candidates), its k nearest other candidates as (squared distance,
  // id) pairs, nearest first, ties by the smaller id: row(i, found, count) with the first count
  // entries of found (count < k only where fewer candidates exist). Threaded (vtkSMPTools, in
  // blocks); row is called once per point, from any thread. `progress` as for
  // FindNearestNeighbors (returns false when it stopped the search).
  template<typename Row>
  bool ForEach(const std::vector<int32_t>& ids,
    Row&& row,
    const std::function<bool(double)>& progress) const
  {
    // Each thread carries its radius from one query to the next (see Query).
    vtkSMPThreadLocal<double> radii(this->Start);
    const int32_t count = static_cast<int32_t>(ids.size());
    const int32_t block = 65536;
    for (int32_t first = 0; first < count; first += block)
    {
      if (progress && !progress(static_cast<double>(first) / count))
      {
        return false;
      }
      const int32_t last = std::min<int32_t>(first + block, count);
      vtkSMPTools::For(first,
        last,
        [&](int32_t begin, int32_t end)
        {
          double& radius = radii.Local();
          std::vector<std::pair<double, int32_t>> found;
          for (int32_t q = begin; q < end; ++q)
          {
            const size_t keep = this->Query(ids[q], radius, found);
            row(ids[q], found.data(), keep);
          }
        });
    }
    return !progress || progress(1.0);
  }

private:
  double StartRadius(const std::vector<uint8_t>* candidates) const;
  void FileEntries(const std::vector<uint8_t>* candidates);
  double GapTo(double f, int j, int c) const;
  size_t Query(int32_t i, double& radius, std::vector<std::pair<double, int32_t>>& found) const;

  const PointBins& Bins;
  const double* XYZ;
  int32_t N;     // the points of the bins
  int32_t Count; // the candidates among them
  int K;
  double Start;
  // Entry e (one candidate position) has the members Members[EntryStart[e], EntryStart[e + 1])
  // (ascending ids) at EntryXYZ[3 e]; bucket b holds the entries [BucketStart[b],
  // BucketStart[b + 1]).
  std::vector<int32_t> BucketStart;
  std::vector<int32_t> EntryStart;
  std::vector<int32_t> Members;
  std::vector<double> EntryXYZ;
};

NearestSearch::NearestSearch(const PointBins& bins,
  const double* xyz,
  int32_t n,
  int k,
  const std::vector<uint8_t>* candidates)
  : Bins(bins)
  , XYZ(xyz)
  , N(n)
  , Count(
      candidates ? static_cast<int32_t>(std::count(candidates->begin(), candidates->end(), 1)) : n)
  , K(k)
{
  this->Start = this->StartRadius(candidates);
  this->FileEntries(candidates);
}

double NearestSearch::StartRadius(const std::vector<uint8_t>* candidates) const
{
  // Starting radius: the k-th neighbour of a surface sample lies about sqrt(k) nearest-neighbour
  // distances away; the mean nearest-neighbour distance comes from a few hundred candidates, each
  // searched in the bins within one, then two bucket widths (a copy of the point counts, at
  // distance 0; a point with no other that near is left out). The radius only sets where the
  // queries start, never what they find.
  const PointBins& bins = this->Bins;
  const double* xyz = this->XYZ;
  const int32_t n = this->N;
  double sum = 0.0;
  int samples = 0;
  {
    const double reach =
      std::max({ bins.GetBucketWidth(0), bins.GetBucketWidth(1), bins.GetBucketWidth(2) });
    const int* grid = bins.GetDivisions();
    const int32_t* offsets = bins.GetOffsets();
    const int32_t* ids = bins.GetIds();
    auto isCandidate = [candidates](int32_t id) { return !candidates || (*candidates)[id]; };
    const int32_t step = std::max<int32_t>(1, n / 256);
    for (int32_t i = 0; i < n; i += step)
    {
      if (!isCandidate(i))
      {
        continue;
      }
      const double* p = xyz + 3 * static_cast<size_t>(i);
      for (double radius = reach; radius <= 2.0 * reach; radius *= 2.0)
      {
        int lo[3], hi[3];
        bins.BucketRange(p, radius, lo, hi);
        double best = std::numeric_limits<double>::infinity();
        for (int bz = lo[2]; bz <= hi[2] && best > 0.0; ++bz)
        {
          for (int by = lo[1]; by <= hi[1] && best > 0.0; ++by)
          {
            const int64_t row = grid[0] * (by + static_cast<int64_t>(grid[1]) * bz);
            for (int32_t m = offsets[row + lo[0]]; m < offsets[row + hi[0] + 1] && best > 0.0; ++m)
            {
              if (ids[m] != i && isCandidate(ids[m]))
              {
                best = std::min(best, Distance2(p, xyz + 3 * static_cast<size_t>(ids[m])));
              }
            }
          }
        }
        if (best <= radius * radius)
        {
          sum += std::sqrt(best);
          ++samples;
          break;
        }
      }
    }
  }
  double start = samples > 0 ? 1.5 * std::sqrt(static_cast<double>(this->K)) * sum / samples : 0.0;
  if (!(start > 0) || !std::isfinite(start))
  {
    start = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      start = std::max(start, bins.GetBucketWidth(c) * bins.GetDivisions()[c]);
    }
    start = start > 0 && std::isfinite(start) ? start * 1e-3 : 1.0;
  }
  return start;
}

void NearestSearch::FileEntries(const std::vector<uint8_t>* candidates)
{
  // The candidates of a query are read from the bucket grid directly (PointBins): the points of
  // the buckets that the ball overlaps, with their distances computed here on the packed
  // coordinates. The ball is large enough when it holds more than k points
  // (the query point included): the k nearest others are then among the candidates, whatever the
  // buckets add beyond the ball. This is the bucket walk of FindPointsWithinRadius without its
  // per-point virtual GetPoint and per-query BuildLocator (modification time) calls, which took
  // about two thirds of the search's time.
  // Exact duplicates share one entry: the candidates of a bucket are sorted by coordinates (then
  // id) and each run of equal points becomes one entry with its member ids in ascending order. A
  // query meets a pile of d copies as one candidate position and takes at most k of its members
  // (the smallest ids: ties are broken by id), so a cloud with 10^6 copies of one point costs
  // O(n k), not O(d^2). Non-finite points stay single entries, in id order.
  const PointBins& bins = this->Bins;
  const double* xyz = this->XYZ;
  const vtkIdType numberOfBuckets = bins.GetNumberOfBuckets();
  this->BucketStart.assign(static_cast<size_t>(numberOfBuckets) + 1, 0);
  this->Members.reserve(static_cast<size_t>(this->Count));
  std::vector<int32_t> byBucket(bins.GetIds(), bins.GetIds() + this->N);
  auto before = [xyz](int32_t a, int32_t b)
  {
    const int c =
      ComparePositions(xyz + 3 * static_cast<size_t>(a), xyz + 3 * static_cast<size_t>(b), 3);
    return c != 0 ? c < 0 : a < b;
  };
  // Bucket b holds byBucket[first, last); BucketStart[b + 1] gets its last entry index + 1.
  int32_t first = 0;
  for (vtkIdType b = 0; b < numberOfBuckets; ++b)
  {
    const int32_t last = bins.GetOffsets()[b + 1];
    int32_t* ids = byBucket.data() + first;
    int32_t count = last - first;
    if (candidates)
    {
      count = static_cast<int32_t>(
        std::remove_if(ids, ids + count, [candidates](int32_t id) { return !(*candidates)[id]; }) -
        ids);
    }
    if (count > 1)
    {
      std::sort(ids, ids + count, before);
    }
    for (int32_t j = 0; j < count; ++j)
    {
      const double* q = xyz + 3 * static_cast<size_t>(ids[j]);
      const bool same = j > 0 && SamePosition(q, xyz + 3 * static_cast<size_t>(ids[j - 1]), 3);
      if (!same)
      {
        this->EntryStart.push_back(static_cast<int32_t>(this->Members.size()));
        this->EntryXYZ.insert(this->EntryXYZ.end(), q, q + 3);
      }
      this->Members.push_back(ids[j]);
    }
    this->BucketStart[b + 1] = static_cast<int32_t>(this->EntryStart.size());
    first = last;
  }
  this->EntryStart.push_back(static_cast<int32_t>(this->Members.size()));
}

// A lower bound of |q[c] - p[c]| for every point q of the buckets of index j along axis c, from
// p's position f in bucket units (PointBins::BucketCoordinate): the whole buckets between them,
// less 10^-6 of a bucket for the rounding of the index formula. 0 next to p, in the clamped
// first and last buckets, and on an axis of one bucket.
inline double NearestSearch::GapTo(double f, int j, int c) const
{
  double units = 0.0;
  if (j + 1 < f && j + 1 < this->Bins.GetDivisions()[c])
  {
    units = f - (j + 1);
  }
  else if (j > f && j > 0)
  {
    units = j - f;
  }
  return units > 1e-6 ? (units - 1e-6) * this->Bins.GetBucketWidth(c) : 0.0;
}

// One query: the k nearest other candidates of point i, as (squared distance, id) pairs, nearest
// first, in `found` (its first min(k, size) entries; returns that count). The ball starts at
// `radius` and grows until it holds more than k candidates; `radius` is left a little beyond the
// k-th neighbour (or at Start after a pile of copies), to start the next query.
// Only the candidates inside the ball are kept: once the ball holds more than k points, the
// k nearest others are inside it, ties at its radius included. A row of buckets (fixed y and
// z) is walked only where the ball reaches it: over the x range of the ball's section there
// (the rows' y and z distances to p bounded from below by GapTo). After the last allowed growth
// (a degenerate cloud) every candidate of the whole box of buckets is kept, as the ball may not
// hold k others.
size_t NearestSearch::Query(int32_t i,
  double& radius,
  std::vector<std::pair<double, int32_t>>& found) const
{
  const PointBins& bins = this->Bins;
  const int kk = this->K;
  const int* divisions = bins.GetDivisions();
  const int32_t* bucketStart = this->BucketStart.data();
  const int32_t* entryStart = this->EntryStart.data();
  const int32_t* members = this->Members.data();
  const double* entryXYZ = this->EntryXYZ.data();
  const double* p = this->XYZ + 3 * static_cast<size_t>(i);
  double f[3];
  for (int c = 0; c < 3; ++c)
  {
    f[c] = bins.BucketCoordinate(p[c], c);
  }
  bool all = false;
  // found[0, size) are the candidates; found is a buffer that only grows (resized ahead of each
  // row of buckets), so that a candidate is written without a branch on whether it is kept.
  size_t size = 0;
  for (int attempt = 0;; ++attempt)
  {
    all = attempt > 200;
    size = 0;
    int lo[3], hi[3];
    bins.BucketRange(p, radius, lo, hi);
    const double r2 = radius * radius;
    int64_t inside = 0;
    for (int bz = lo[2]; bz <= hi[2]; ++bz)
    {
      const double gz = all ? 0.0 : this->GapTo(f[2], bz, 2);
      for (int by = lo[1]; by <= hi[1]; ++by)
      {
        const double gy = all ? 0.0 : this->GapTo(f[1], by, 1);
        const double g2 = gy * gy + gz * gz;
        if (g2 > r2)
        {
          continue;
        }
        int xlo = lo[0], xhi = hi[0];
        if (g2 > 0.0)
        {
          const double margin = (std::sqrt(r2 - g2) + 1e-6 * radius) * (1.0 + 1e-9) + 1e-300;
          xlo = bins.BucketIndex(p[0] - margin, 0);
          xhi = bins.BucketIndex(p[0] + margin, 0);
        }
        const int64_t row = divisions[0] * (by + static_cast<int64_t>(divisions[1]) * bz);
        const int32_t first = bucketStart[row + xlo], last = bucketStart[row + xhi + 1];
        if (found.size() < size + static_cast<size_t>(last - first))
        {
          found.resize(2 * (size + static_cast<size_t>(last - first)));
        }
        for (int32_t e = first; e < last; ++e)
        {
          const double d2 = Distance2(p, &entryXYZ[3 * static_cast<size_t>(e)]);
          const int32_t copies = entryStart[e + 1] - entryStart[e];
          if (copies == 1 && !all)
          {
            // A single point (the usual entry): written, kept when inside and not p itself.
            const int32_t id = members[entryStart[e]];
            const bool in = d2 <= r2;
            found[size] = { d2, id };
            size += static_cast<size_t>(in & (id != i));
            inside += static_cast<int64_t>(in);
          }
          else if (d2 <= r2 || all)
          {
            inside += d2 <= r2 ? copies : 0;
            // Room for up to kk of the pile and one candidate per entry left in the row: the
            // single points after it are written without a check.
            const size_t need = size + static_cast<size_t>(kk) + static_cast<size_t>(last - e);
            if (found.size() < need)
            {
              found.resize(2 * need);
            }
            int taken = 0;
            for (int32_t m = entryStart[e]; m < entryStart[e + 1] && taken < kk; ++m)
            {
              if (members[m] != i)
              {
                found[size++] = { d2, members[m] };
                ++taken;
              }
            }
          }
        }
      }
    }
    if (inside > kk || inside >= this->Count || attempt > 200)
    {
      break;
    }
    radius *= inside > 1 ? std::min(2.0, 1.1 * std::sqrt((kk + 1.0) / inside)) : 2.0;
  }
  const size_t keep = std::min<size_t>(kk, size);
  if (!all && size <= 32)
  {
    // The usual case (the carried radius holds about 1.2 k points): a short list is sorted
    // whole by insertion, cheaper than the partial sort. Same order: the entries (squared
    // distance, id) are distinct and, inside the ball, not NaN.
    for (size_t j = 1; j < size; ++j)
    {
      const std::pair<double, int32_t> entry = found[j];
      size_t to = j;
      for (; to > 0 && entry < found[to - 1]; --to)
      {
        found[to] = found[to - 1];
      }
      found[to] = entry;
    }
  }
  else
  {
    if (keep < size)
    {
      std::nth_element(found.begin(), found.begin() + keep, found.begin() + size);
    }
    std::sort(found.begin(), found.begin() + keep);
  }
  // The next query starts a little beyond this point's kk-th neighbour; after a point whose
  // kk nearest are all copies of it, from Start (keeping the radius of the previous distinct
  // point, far larger than a pile's, made every copy's query walk a box of up to all the
  // bins: hours for 300,000 copies on a grid of 4 bins per point).
  if (keep > 0)
  {
    radius = found[keep - 1].first > 0 ? 1.1 * std::sqrt(found[keep - 1].first) : this->Start;
  }
  return keep;
}
}

bool FindNearestNeighbors(const PointBins& bins,
  const double* xyz,
  int32_t n,
  int k,
  std::vector<int32_t>& neighbors,
  const std::function<bool(double)>& progress)
{
  neighbors.assign(static_cast<size_t>(std::max(n, 0)) * std::max(k, 0), -1);
  if (n < 2 || k < 1)
  {
    return true;
  }
  // The queries run in bucket order (entry by entry; the members hold every point once):
  // consecutive queries are then close in space, which keeps the carried radius apt and the
  // buckets they read in cache. The order does not change the result.
  const NearestSearch search(bins, xyz, n, k, nullptr);
  return search.ForEach(
    search.GetMembers(),
    [&](int32_t i, const std::pair<double, int32_t>* found, size_t keep)
    {
      int32_t* out = &neighbors[static_cast<size_t>(i) * k];
      for (size_t j = 0; j < keep; ++j)
      {
        out[j] = found[j].second;
      }
    },
    progress);
}

void DistinctNeighbors(const PointBins& bins,
  const double* xyz,
  int32_t n,
  const std::vector<int32_t>& pointTable,
  int width,
  const std::vector<int32_t>& positionOf,
  const std::vector<int32_t>& positionIds,
  int k,
  std::vector<int32_t>& neighbors)
{
  const int32_t count = static_cast<int32_t>(positionIds.size());
  neighbors.assign(static_cast<size_t>(count) * std::max(k, 0), -1);
  if (count < 2 || k < 1)
  {
    return;
  }
  // The rows whose point row leaves fewer than k other positions: searched again below, all at
  // once when more than a quarter are.
  const size_t mostIncomplete = static_cast<size_t>(count) / 4;
  std::vector<uint8_t> incomplete(static_cast<size_t>(count), 0);
  size_t incompleteCount = 0;
  for (int32_t d = 0; d < count && incompleteCount <= mostIncomplete; ++d)
  {
    const int32_t* row = &pointTable[static_cast<size_t>(positionIds[d]) * width];
    int32_t* out = &neighbors[static_cast<size_t>(d) * k];
    int taken = 0;
    for (int j = 0; j < width && row[j] >= 0 && taken < k; ++j)
    {
      const int32_t e = positionOf[row[j]];
      if (e != d && std::find(out, out + taken, e) == out + taken)
      {
        out[taken++] = e;
      }
    }
    if (taken < k && width > 0 && row[width - 1] >= 0)
    {
      incomplete[d] = 1;
      ++incompleteCount;
    }
  }
  if (incompleteCount == 0)
  {
    return;
  }
  // Those rows (or all) searched on the bins of the points, among the positions' first copies
  // (the candidates; a position's coordinates are its first copy's), in bucket order.
  std::vector<uint8_t> isFirstCopy(static_cast<size_t>(n), 0);
  for (const int32_t id : positionIds)
  {
    isFirstCopy[id] = 1;
  }
  const NearestSearch search(bins, xyz, n, k, &isFirstCopy);
  std::vector<int32_t> searched;
  if (incompleteCount > mostIncomplete)
  {
    searched = search.GetMembers();
  }
  else
  {
    for (const int32_t id : search.GetMembers())
    {
      if (incomplete[positionOf[id]])
      {
        searched.push_back(id);
      }
    }
  }
  search.ForEach(
    searched,
    [&](int32_t i, const std::pair<double, int32_t>* found, size_t keep)
    {
      int32_t* out = &neighbors[static_cast<size_t>(positionOf[i]) * k];
      for (size_t j = 0; j < static_cast<size_t>(k); ++j)
      {
        out[j] = j < keep ? positionOf[found[j].second] : -1;
      }
    },
    nullptr);
}

namespace
{
// AddOffLineNeighbors on the bins that `fileBins` gives (called once, only when a row is to be
// extended).
int32_t AddOffLineNeighborsIn(const std::function<const PointBins&()>& fileBins,
  const double* xyz,
  int32_t n,
  int k,
  std::vector<int32_t>& neighbors,
  std::vector<double>* stretch,
  double linearity,
  double radiusFactor,
  double minimumShare,
  const std::function<bool(double)>& progress)
{
  if (stretch)
  {
    stretch->assign(3 * static_cast<size_t>(std::max(n, 0)), 0.0);
  }
  if (n < 3 || k < 2 || neighbors.size() < static_cast<size_t>(n) * k || !(radiusFactor > 0.0))
  {
    return 0;
  }
  const int perSide = std::max(1, k / 4);
  // The points confined to a curve, all of them first (the test is made again, on the same row,
  // where it passed): the bins are filed only when a row is to be extended.
  std::vector<uint8_t> confined(static_cast<size_t>(n), 0);
  vtkSMPTools::For(0,
    n,
    [&](int32_t begin, int32_t end)
    {
      double e[3], reach;
      for (int32_t i = begin; i < end; ++i)
      {
        confined[i] = SpreadsAlongCurve(xyz,
                        xyz + 3 * static_cast<size_t>(i),
                        &neighbors[static_cast<size_t>(i) * k],
                        k,
                        linearity,
                        e,
                        reach)
          ? 1
          : 0;
      }
    });
  auto enoughConfined = [&](const int32_t* table)
  {
    int count = 0, share = 0;
    for (int j = 0; j < k; ++j)
    {
      count += table[j] >= 0 ? 1 : 0;
      share += table[j] >= 0 && confined[table[j]] ? 1 : 0;
    }
    return share >= minimumShare * count;
  };
  auto extended = [&](int32_t i)
  {
    return confined[i] &&
      (minimumShare <= 0.0 || enoughConfined(&neighbors[static_cast<size_t>(i) * k]));
  };
  int32_t firstExtended = 0;
  while (firstExtended < n && !extended(firstExtended))
  {
    ++firstExtended;
  }
  if (firstExtended == n)
  {
    return progress && !progress(1.0) ? -1 : 0;
  }
  // The balls of the confined points are searched in bins (PointBins: no virtual call per
  // point, less than half the instructions of FindPointsWithinRadius on the camel's scan-line
  // patch; the same points), filed once, before the threads read them.
  const PointBins& bins = fileBins();
  std::atomic<int32_t> changed(0);
  struct Candidate
  {
    double Distance2;
    int32_t Id;
    double Across[3]; // component of q - p normal to the line direction
    bool operator<(const Candidate& other) const
    {
      return this->Distance2 < other.Distance2 ||
        (this->Distance2 == other.Distance2 && this->Id < other.Id);
    }
  };
  const int32_t block = 65536;
  for (int32_t first = 0; first < n; first += block)
  {
    if (progress && !progress(static_cast<double>(first) / n))
    {
      return -1;
    }
    const int32_t last = std::min<int32_t>(first + block, n);
    vtkSMPTools::For(first,
      last,
      [&](int32_t begin, int32_t end)
      {
        std::vector<Candidate> offLine, row;
        std::vector<int32_t> wanted;
        int32_t rowsChanged = 0;
        for (int32_t i = begin; i < end; ++i)
        {
          const double* p = xyz + 3 * static_cast<size_t>(i);
          int32_t* table = &neighbors[static_cast<size_t>(i) * k];
          double e[3], reach;
          if (!extended(i) || !SpreadsAlongCurve(xyz, p, table, k, linearity, e, reach))
          {
            continue;
          }
          // The points off the line within `radius` of p.
          auto consider = [&](int32_t id)
          {
            const double* q = xyz + 3 * static_cast<size_t>(id);
            if (id == i || id < 0 || id >= n || !IsFinitePosition(q, 3))
            {
              return true;
            }
            Candidate candidate;
            candidate.Id = id;
            const double v[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
            const double along = vtkMath::Dot(v, e);
            for (int c = 0; c < 3; ++c)
            {
              candidate.Across[c] = v[c] - along * e[c];
            }
            if (vtkMath::Dot(candidate.Across, candidate.Across) > along * along)
            {
              candidate.Distance2 = vtkMath::Dot(v, v);
              offLine.push_back(candidate);
            }
            return true;
          };
          auto collectOffLine = [&](double radius)
          {
            offLine.clear();
            bins.ForEachPointWithinRadius(
              radius, p, [&](int32_t id, double) { return consider(id); });
          };
          // Within 4 dk first, and within radiusFactor dk only when no point is off the line
          // there: the same answer where the nearest lines are within 4 dk, a smaller ball.
          collectOffLine(std::min(4.0, radiusFactor) * reach);
          if (offLine.empty() && radiusFactor > 4.0)
          {
            collectOffLine(radiusFactor * reach);
          }
          if (offLine.empty())
          {
            continue;
          }
          // The nearest off-line point first, then the perSide - 1 nearest others on its side
          // and the perSide nearest on the other side (what the first of each side in the
          // order of distance, then id, are; the rest need no order).
          std::iter_swap(offLine.begin(), std::min_element(offLine.begin(), offLine.end()));
          const auto otherSide = std::partition(offLine.begin() + 1,
            offLine.end(),
            [&](const Candidate& candidate)
            { return vtkMath::Dot(candidate.Across, offLine[0].Across) >= 0.0; });
          auto nearestOf = [](std::vector<Candidate>::iterator first,
                             std::vector<Candidate>::iterator last,
                             int count)
          {
            const auto middle = first + std::min<std::ptrdiff_t>(count, last - first);
            std::partial_sort(first, middle, last);
            return middle;
          };
          const auto sameSideEnd = nearestOf(offLine.begin() + 1, otherSide, perSide - 1);
          const auto otherSideEnd = nearestOf(otherSide, offLine.end(), perSide);
          const double nearest =
            table[0] >= 0 ? Distance2(p, xyz + 3 * static_cast<size_t>(table[0])) : 0.0;
          if (stretch && nearest > 0.0 && offLine[0].Distance2 > nearest)
          {
            const double factor = std::sqrt(offLine[0].Distance2 / nearest - 1.0);
            for (int c = 0; c < 3; ++c)
            {
              (*stretch)[3 * static_cast<size_t>(i) + c] = factor * e[c];
            }
          }
          // The nearest off-line points of each side (the side of the nearest one, the other).
          wanted.clear();
          row.clear();
          for (auto range : { std::make_pair(offLine.begin(), sameSideEnd),
                 std::make_pair(otherSide, otherSideEnd) })
          {
            for (auto candidate = range.first; candidate != range.second; ++candidate)
            {
              wanted.push_back(candidate->Id);
              row.push_back(*candidate);
            }
          }
          // The row: the wanted points and the nearest of the others, k in all, nearest first.
          const size_t others = static_cast<size_t>(k) - row.size();
          size_t kept = 0;
          for (int j = 0; j < k && kept < others; ++j)
          {
            if (table[j] >= 0 && std::find(wanted.begin(), wanted.end(), table[j]) == wanted.end())
            {
              Candidate candidate;
              candidate.Id = table[j];
              candidate.Distance2 = Distance2(p, xyz + 3 * static_cast<size_t>(table[j]));
              row.push_back(candidate);
              ++kept;
            }
          }
          std::sort(row.begin(), row.end());
          bool same = true;
          for (int j = 0; j < k; ++j)
          {
            const int32_t id = j < static_cast<int>(row.size()) ? row[j].Id : -1;
            same = same && table[j] == id;
            table[j] = id;
          }
          rowsChanged += same ? 0 : 1;
        }
        changed += rowsChanged;
      });
  }
  if (progress && !progress(1.0))
  {
    return -1;
  }
  return changed;
}
}

int32_t AddOffLineNeighbors(vtkStaticPointLocator* locator,
  const double* xyz,
  int32_t n,
  int k,
  std::vector<int32_t>& neighbors,
  std::vector<double>* stretch,
  double linearity,
  double radiusFactor,
  double minimumShare,
  const std::function<bool(double)>& progress)
{
  // The locator is built only when a row is to be extended, its bins filed with coordinates.
  PointBins bins;
  auto fileBins = [&]() -> const PointBins&
  {
    locator->BuildLocator();
    bins.Build(locator, xyz, n);
    return bins;
  };
  return AddOffLineNeighborsIn(
    fileBins, xyz, n, k, neighbors, stretch, linearity, radiusFactor, minimumShare, progress);
}

int32_t AddOffLineNeighbors(PointBins& bins,
  const double* xyz,
  int32_t n,
  int k,
  std::vector<int32_t>& neighbors,
  std::vector<double>* stretch,
  double linearity,
  double radiusFactor,
  double minimumShare,
  const std::function<bool(double)>& progress)
{
  auto fileBins = [&]() -> const PointBins&
  {
    bins.FileCoordinates(xyz);
    return bins;
  };
  return AddOffLineNeighborsIn(
    fileBins, xyz, n, k, neighbors, stretch, linearity, radiusFactor, minimumShare, progress);
}

bool OnOneScanLine(const double* xyz, const double* stretch, int32_t a, int32_t b, int32_t c)
{
  // Each edge needs an end with a stretch: at least two of the three points. (Most points of
  // a cloud have none: the usual answer, without the products.)
  auto stretched = [stretch](int32_t p)
  {
    const double* s = stretch + 3 * static_cast<size_t>(p);
    return s[0] != 0.0 || s[1] != 0.0 || s[2] != 0.0;
  };
  return (stretched(a) ? 1 : 0) + (stretched(b) ? 1 : 0) + (stretched(c) ? 1 : 0) >= 2 &&
    EdgesAlongOneScanLine(xyz, stretch, a, b, c);
}

bool EdgesAlongOneScanLine(const double* xyz,
  const double* stretch,
  int32_t a,
  int32_t b,
  int32_t c)
{
  auto along = [&](int32_t p, int32_t q)
  {
    const double* pp = xyz + 3 * static_cast<size_t>(p);
    const double* pq = xyz + 3 * static_cast<size_t>(q);
    const double w[3] = { pq[0] - pp[0], pq[1] - pp[1], pq[2] - pp[2] };
    for (int32_t end : { p, q })
    {
      const double* s = stretch + 3 * static_cast<size_t>(end);
      double cross[3];
      vtkMath::Cross(w, s, cross);
      const double dot = vtkMath::Dot(w, s);
      if (dot != 0.0 && vtkMath::Dot(cross, cross) <= dot * dot)
      {
        return true;
      }
    }
    return false;
  };
  return along(a, b) && along(b, c) && along(c, a);
}

void SurfaceSampleDivisions(const double bounds[6],
  int32_t n,
  double binsPerPoint,
  int divisions[3])
{
  // Cubic bins of side h with prod(extent / h) = bins over the axes longer than h; an axis
  // shorter than h gets one division and leaves the product, and h is recomputed without it
  // (so that a nearly flat or straight cloud does not get bins^(3/2) bins).
  const double bins = std::max(1.0, binsPerPoint * std::max<int32_t>(n, 1));
  bool active[3];
  for (int i = 0; i < 3; ++i)
  {
    const double extent = bounds[2 * i + 1] - bounds[2 * i];
    active[i] = extent > 0.0 && std::isfinite(extent);
  }
  double h = 0.0;
  for (int pass = 0; pass < 3; ++pass)
  {
    double measure = 1.0;
    int dimension = 0;
    for (int i = 0; i < 3; ++i)
    {
      if (active[i])
      {
        measure *= bounds[2 * i + 1] - bounds[2 * i];
        ++dimension;
      }
    }
    h = dimension > 0 && measure > 0.0 && std::isfinite(measure)
      ? std::pow(measure / bins, 1.0 / dimension)
      : 0.0;
    bool changed = false;
    for (int i = 0; i < 3; ++i)
    {
      if (active[i] && !(bounds[2 * i + 1] - bounds[2 * i] >= h))
      {
        active[i] = false;
        changed = true;
      }
    }
    if (!changed)
    {
      break;
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    divisions[i] = 1;
    if (active[i] && h > 0.0)
    {
      divisions[i] = static_cast<int>(
        std::min(std::ceil((bounds[2 * i + 1] - bounds[2 * i]) / h), std::ceil(bins)));
    }
  }
}

void BuildSurfaceSampleBins(
  PointBins& bins, const double* xyz, int32_t n, bool withCoordinates, double bounds[6])
{
  for (int c = 0; c < 3; ++c)
  {
    bounds[2 * c] = n > 0 ? xyz[c] : 0.0;
    bounds[2 * c + 1] = bounds[2 * c];
  }
  for (int32_t k = 1; k < n; ++k)
  {
    const double* p = xyz + 3 * static_cast<size_t>(k);
    for (int c = 0; c < 3; ++c)
    {
      bounds[2 * c] = std::min(bounds[2 * c], p[c]);
      bounds[2 * c + 1] = std::max(bounds[2 * c + 1], p[c]);
    }
  }
  double grid[6];
  BulkBounds(xyz, n, bounds, grid);
  int divisions[3];
  SurfaceSampleDivisions(grid, n, 4.0, divisions);
  bins.Build(grid, divisions, xyz, n, withCoordinates);
}

void BulkBounds(const double* xyz, int32_t n, const double bounds[6], double grid[6])
{
  std::copy_n(bounds, 6, grid);
  constexpr int32_t sampleSize = 65536;
  const int32_t step = std::max<int32_t>(1, n / sampleSize);
  std::vector<double> values;
  values.reserve(static_cast<size_t>(n / step + 1));
  double low[3], high[3], widest = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    values.clear();
    for (int32_t i = 0; i < n; i += step)
    {
      const double v = xyz[3 * static_cast<size_t>(i) + c];
      if (std::isfinite(v))
      {
        values.push_back(v);
      }
    }
    if (values.size() < 100)
    {
      return; // (too few points to tell a bulk from strays)
    }
    const size_t first = values.size() / 100, last = values.size() - 1 - values.size() / 100;
    std::nth_element(values.begin(), values.begin() + first, values.end());
    low[c] = values[first];
    std::nth_element(values.begin() + first, values.begin() + last, values.end());
    high[c] = values[last];
    widest = std::max(widest, high[c] - low[c]);
  }
  if (!(widest > 0.0) || !std::isfinite(widest))
  {
    return; // (the bulk is one position: nothing to shrink to)
  }
  double bulk[6];
  bool shrinks = false;
  for (int c = 0; c < 3; ++c)
  {
    bulk[2 * c] = std::max(bounds[2 * c], low[c] - 0.5 * widest);
    bulk[2 * c + 1] = std::min(bounds[2 * c + 1], high[c] + 0.5 * widest);
    shrinks = shrinks || bulk[2 * c + 1] - bulk[2 * c] < 0.5 * (bounds[2 * c + 1] - bounds[2 * c]);
  }
  if (shrinks)
  {
    std::copy_n(bulk, 6, grid);
  }
}

void SetSurfaceSampleDivisions(vtkStaticPointLocator* locator,
  const double bounds[6],
  int32_t n,
  double binsPerPoint)
{
  int divisions[3];
  SurfaceSampleDivisions(bounds, n, binsPerPoint, divisions);
  locator->AutomaticOff();
  locator->SetDivisions(divisions);
}
}
