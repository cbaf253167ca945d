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
  double reach2 = 0.0;
  for (int j = 0; j < k; ++j)
  {
    if (row[j] >= 0)
    {
      reach2 = std::max(reach2, Distance2(p, xyz + 3 * static_cast<size_t>(row[j])));
    }
  }
  // The covariance of the offsets from p to its nearest half (pcs::OffsetCovariance).
  const int nearest = std::max(2, k / 2);
  double covariance[3][3];
  if (OffsetCovariance(xyz, p, row, std::min(nearest, k), false, covariance) < 2.0)
  {
    return false;
  }
  reach = std::sqrt(reach2);
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
  double* rows[3] = { covariance[0], covariance[1], covariance[2] };
  double values[3], column0[3], column1[3], column2[3];
  double* vectors[3] = { column0, column1, column2 };
  vtkMath::Jacobi(rows, values, vectors); // decreasing eigenvalues, eigenvectors in columns
  for (int c = 0; c < 3; ++c)
  {
    direction[c] = vectors[c][0];
  }
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
  double spacing[3];
  locator->GetSpacing(spacing);
  for (int c = 0; c < 3; ++c)
  {
    this->Origin[c] = bounds[2 * c];
    this->Inverse[c] = spacing[c] > 0.0 ? 1.0 / spacing[c] : 0.0;
  }
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

bool FindNearestNeighbors(vtkStaticPointLocator* locator, const double* xyz, int32_t n, int k,
  std::vector<int32_t>& neighbors, const std::function<bool(double)>& progress)
{
  neighbors.assign(static_cast<size_t>(std::max(n, 0)) * std::max(k, 0), -1);
  if (n < 2 || k < 1)
  {
    return true;
  }
  PointBins bins;
  bins.Build(locator, xyz, n, /*withCoordinates=*/false);
  // Starting radius: the k-th neighbour of a surface sample lies about sqrt(k) nearest-neighbour
  // distances away; the mean nearest-neighbour distance comes from a few hundred points, each
  // searched in the bins within one, then two bucket widths (a copy of the point counts, at
  // distance 0; a point with no other that near is left out). The radius only sets where the
  // queries start, never what they find.
  double sum = 0.0;
  int samples = 0;
  {
    double width[3];
    locator->GetSpacing(width);
    const double reach = std::max({ width[0], width[1], width[2] });
    const int* grid = bins.GetDivisions();
    const int32_t* offsets = bins.GetOffsets();
    const int32_t* ids = bins.GetIds();
    const int32_t step = std::max<int32_t>(1, n / 256);
    for (int32_t i = 0; i < n; i += step)
    {
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
              if (ids[m] != i)
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
  double start = samples > 0 ? 1.5 * std::sqrt(static_cast<double>(k)) * sum / samples : 0.0;
  if (!(start > 0) || !std::isfinite(start))
  {
    double bounds[6];
    locator->GetDataSet()->GetBounds(bounds);
    start = std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
    start = start > 0 && std::isfinite(start) ? start * 1e-3 : 1.0;
  }

  // The candidates of a query are read from the locator's bucket grid directly (PointBins): all
  // points of the buckets that the cube around the ball overlaps, with their distances computed
  // here on the packed coordinates. The ball is large enough when it holds more than k points
  // (the query point included): the k nearest others are then among the candidates, whatever the
  // cube adds beyond the ball. This is the bucket walk of FindPointsWithinRadius without its
  // per-point virtual GetPoint and per-query BuildLocator (modification time) calls, which took
  // about two thirds of the search's time.
  const int* divisions = bins.GetDivisions();
  const vtkIdType numberOfBuckets = bins.GetNumberOfBuckets();
  std::vector<int32_t> bucketStart(static_cast<size_t>(numberOfBuckets) + 1, 0);
  // Exact duplicates share one entry: the points of a bucket are sorted by coordinates (then id)
  // and each run of equal points becomes one entry with its member ids in ascending order. A
  // query meets a pile of d copies as one candidate position and takes at most k of its members
  // (the smallest ids: ties are broken by id), so a cloud with 10^6 copies of one point costs
  // O(n k), not O(d^2). Non-finite points stay single entries, in id order.
  std::vector<int32_t> entryStart; // members of entry e: members[entryStart[e], entryStart[e+1])
  std::vector<int32_t> members;
  std::vector<double> entryXYZ;
  members.reserve(static_cast<size_t>(n));
  {
    std::vector<int32_t> byBucket(bins.GetIds(), bins.GetIds() + n);
    auto before = [xyz](int32_t a, int32_t b)
    {
      const int c =
        ComparePositions(xyz + 3 * static_cast<size_t>(a), xyz + 3 * static_cast<size_t>(b), 3);
      return c != 0 ? c < 0 : a < b;
    };
    // Bucket b holds byBucket[first, last); bucketStart[b + 1] gets its last entry index + 1.
    int32_t first = 0;
    for (vtkIdType b = 0; b < numberOfBuckets; ++b)
    {
      const int32_t last = bins.GetOffsets()[b + 1];
      int32_t* ids = byBucket.data() + first;
      const int32_t count = last - first;
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
          entryStart.push_back(static_cast<int32_t>(members.size()));
          entryXYZ.insert(entryXYZ.end(), q, q + 3);
        }
        members.push_back(ids[j]);
      }
      bucketStart[b + 1] = static_cast<int32_t>(entryStart.size());
      first = last;
    }
    entryStart.push_back(static_cast<int32_t>(members.size()));
  }
  // The queries run in bucket order (entry by entry; members holds every point once):
  // consecutive queries are then close in space, which keeps the carried radius apt and the
  // buckets they read in cache. The order does not change the result.

  vtkSMPThreadLocal<double> radii(start);
  const int32_t block = 65536;
  for (int32_t first = 0; first < n; first += block)
  {
    if (progress && !progress(static_cast<double>(first) / n))
    {
      return false;
    }
    const int32_t last = std::min<int32_t>(first + block, n);
    vtkSMPTools::For(first, last, [&](int32_t begin, int32_t end) {
      double& radius = radii.Local();
      std::vector<std::pair<double, int32_t>> found;
      for (int32_t position = begin; position < end; ++position)
      {
        const int32_t i = members[position];
        const double* p = xyz + 3 * static_cast<size_t>(i);
        // Only the candidates inside the ball are kept: once the ball holds more than k points,
        // the k nearest others are inside it, ties at its radius included. After the last
        // allowed growth (a degenerate cloud) every candidate is kept, as the ball may not hold
        // k others.
        bool all = false;
        for (int attempt = 0;; ++attempt)
        {
          all = attempt > 200;
          found.clear();
          int lo[3], hi[3];
          bins.BucketRange(p, radius, lo, hi);
          const double r2 = radius * radius;
          vtkIdType inside = 0;
          for (int bz = lo[2]; bz <= hi[2]; ++bz)
          {
            for (int by = lo[1]; by <= hi[1]; ++by)
            {
              for (int bx = lo[0]; bx <= hi[0]; ++bx)
              {
                const vtkIdType bucket =
                  bx + divisions[0] * (by + static_cast<vtkIdType>(divisions[1]) * bz);
                for (int32_t e = bucketStart[bucket]; e < bucketStart[bucket + 1]; ++e)
                {
                  const double d2 = Distance2(p, &entryXYZ[3 * static_cast<size_t>(e)]);
                  if (d2 <= r2 || all)
                  {
                    inside += d2 <= r2 ? entryStart[e + 1] - entryStart[e] : 0;
                    int taken = 0;
                    for (int32_t m = entryStart[e]; m < entryStart[e + 1] && taken < k; ++m)
                    {
                      if (members[m] != i)
                      {
                        found.emplace_back(d2, members[m]);
                        ++taken;
                      }
                    }
                  }
                }
              }
            }
          }
          if (inside > k || inside >= n || attempt > 200)
          {
            break;
          }
          radius *= inside > 1 ? std::min(2.0, 1.1 * std::sqrt((k + 1.0) / inside)) : 2.0;
        }
        const size_t keep = std::min<size_t>(k, found.size());
        if (!all && found.size() <= 32)
        {
          // The usual case (the carried radius holds about 1.2 k points): a short list is sorted
          // whole by insertion, cheaper than the partial sort. Same order: the entries (squared
          // distance, id) are distinct and, inside the ball, not NaN.
          for (size_t j = 1; j < found.size(); ++j)
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
          if (keep < found.size())
          {
            std::nth_element(found.begin(), found.begin() + keep, found.end());
          }
          std::sort(found.begin(), found.begin() + keep);
        }
        int32_t* out = &neighbors[static_cast<size_t>(i) * k];
        for (size_t j = 0; j < keep; ++j)
        {
          out[j] = found[j].second;
        }
        // The next query starts a little beyond this point's k-th neighbour; after a point whose
        // k nearest are all copies of it, from the initial radius (keeping the radius of the
        // previous distinct point, far larger than a pile's, made every copy's query walk a box
        // of up to all the bins: hours for 300,000 copies on a grid of 4 bins per point).
        if (keep > 0)
        {
          radius = found[keep - 1].first > 0 ? 1.1 * std::sqrt(found[keep - 1].first) : start;
        }
      }
    });
  }
  return !progress || progress(1.0);
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
  if (stretch)
  {
    stretch->assign(3 * static_cast<size_t>(std::max(n, 0)), 0.0);
  }
  if (n < 3 || k < 2 || neighbors.size() < static_cast<size_t>(n) * k || !(radiusFactor > 0.0))
  {
    return 0;
  }
  const int perSide = std::max(1, k / 4);
  // The points confined to a curve, all of them first when a share of confined neighbours is
  // asked for (then the test is made again, on the same row, where it passed).
  std::vector<uint8_t> confined;
  if (minimumShare > 0.0)
  {
    confined.assign(static_cast<size_t>(n), 0);
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
  }
  // The balls of the confined points are searched in the locator's bins (PointBins: no virtual
  // call per point, less than half the instructions of FindPointsWithinRadius on the camel's
  // scan-line patch) when the first pass found some; else the locator answers the queries.
  PointBins bins;
  const bool useBins =
    !confined.empty() && std::find(confined.begin(), confined.end(), 1) != confined.end();
  if (useBins)
  {
    bins.Build(locator, xyz, n);
  }
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
        vtkNew<vtkIdList> ball;
        std::vector<Candidate> offLine, row;
        std::vector<int32_t> wanted;
        int32_t rowsChanged = 0;
        for (int32_t i = begin; i < end; ++i)
        {
          const double* p = xyz + 3 * static_cast<size_t>(i);
          int32_t* table = &neighbors[static_cast<size_t>(i) * k];
          double e[3], reach;
          if ((!confined.empty() && (!confined[i] || !enoughConfined(table))) ||
            !SpreadsAlongCurve(xyz, p, table, k, linearity, e, reach))
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
            if (useBins)
            {
              bins.ForEachPointWithinRadius(
                radius, p, [&](int32_t id, double) { return consider(id); });
              return;
            }
            locator->FindPointsWithinRadius(radius, p, ball);
            for (vtkIdType j = 0; j < ball->GetNumberOfIds(); ++j)
            {
              consider(static_cast<int32_t>(ball->GetId(j)));
            }
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
          std::sort(offLine.begin(), offLine.end());
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
          int taken[2] = { 0, 0 };
          for (const Candidate& candidate : offLine)
          {
            const int side = vtkMath::Dot(candidate.Across, offLine[0].Across) >= 0.0 ? 0 : 1;
            if (taken[side] < perSide)
            {
              ++taken[side];
              wanted.push_back(candidate.Id);
            }
            if (taken[0] == perSide && taken[1] == perSide)
            {
              break;
            }
          }
          // The row: the wanted points and the nearest of the others, k in all, nearest first.
          row.clear();
          for (const Candidate& candidate : offLine)
          {
            if (std::find(wanted.begin(), wanted.end(), candidate.Id) != wanted.end())
            {
              row.push_back(candidate);
            }
          }
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

bool OnOneScanLine(const double* xyz, const double* stretch, int32_t a, int32_t b, int32_t c)
{
  // Each edge needs an end with a stretch: at least two of the three points. (Most points of
  // a cloud have none: the usual answer, without the products.)
  auto stretched = [stretch](int32_t p)
  {
    const double* s = stretch + 3 * static_cast<size_t>(p);
    return s[0] != 0.0 || s[1] != 0.0 || s[2] != 0.0;
  };
  if ((stretched(a) ? 1 : 0) + (stretched(b) ? 1 : 0) + (stretched(c) ? 1 : 0) < 2)
  {
    return false;
  }
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

void SetSurfaceSampleDivisions(
  vtkStaticPointLocator* locator, const double bounds[6], int32_t n, double binsPerPoint)
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
  int divisions[3] = { 1, 1, 1 };
  for (int i = 0; i < 3; ++i)
  {
    if (active[i] && h > 0.0)
    {
      divisions[i] = static_cast<int>(
        std::min(std::ceil((bounds[2 * i + 1] - bounds[2 * i]) / h), std::ceil(bins)));
    }
  }
  locator->AutomaticOff();
  locator->SetDivisions(divisions);
}
}
