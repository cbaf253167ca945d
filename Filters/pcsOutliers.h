// Far outliers of a point cloud: the one rule shared by the surface filters (private helper, not
// wrapped).
#ifndef pcsOutliers_h
#define pcsOutliers_h

#include <algorithm>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace pcs
{
/// Neighbours of a point's reach (below), and dense points a candidate is compared with.
constexpr int OutlierNeighbors = 8;
/// Only points whose reach exceeds this factor times the cloud's median reach are candidates.
constexpr double OutlierSparseFactor = 4.0;
/// A sparse point whose OutlierNeighbors nearest points are all sparse and form a flat disc
/// (eigenvalues of their covariance: the smallest under OutlierPlaneVariation of the sum, the
/// middle at least OutlierPlaneSpread of it) and whose height over their plane is under
/// OutlierPlaneHeight x its reach, and at least half of whose nearest points pass the same
/// test, lies on a sparsely sampled part of the surface: never a far outlier, however much denser
/// the rest of the cloud. The height bound is 0.3 (0.1 until 2026-11-25): on a curved sparse
/// part the point stands above its neighbours' plane by the sagitta, 0.11 to 0.26 reaches at the
/// sparse pole of a sphere whose density falls by 10^4 (5 to 7 of its points were flagged there;
/// now 1 or 2), while the false positives and the outliers found on the benchmark of
/// Benchmarks/run_outlier_comparison.py are the same with either bound (Benchmarks/results/
/// robustness.md). A point within 0.3 reach of the plane of its sparse neighbours is a noisy or
/// curved sample of them, not a far outlier.
constexpr double OutlierPlaneVariation = 0.02;
constexpr double OutlierPlaneSpread = 0.1;
constexpr double OutlierPlaneHeight = 0.3;
/// Near-coincident points (a pile: repeated measurements, jittered copies; pcs::FindPiles, the
/// definition of the duplicates of every surface filter) count as one position. Seen from the
/// rest of the cloud such a group is one point; without this, piles holding most of the points
/// made the cloud's median reach a pile's and the surface "sparse". The piles are found on the
/// rule's table once and also returned to the filters, which mesh one point per pile (the
/// others are duplicates, like exact copies).

/// Flags the far outliers among the points `ids` of `xyz` (packed x, y, z): `outlier` gets one
/// byte per entry of `ids` (1: outlier) and the function returns how many are flagged.
///
/// A point's reach is the mean distance to its OutlierNeighbors nearest distinct positions
/// (pcs::FindNearestNeighbors; exact copies of a point count as that point, and so do the points
/// of a pile (pcs::FindPiles) as one position, with its first point's coordinates: they share
/// its verdict). A point is sparse when its reach exceeds OutlierSparseFactor times the median
/// reach of the cloud, dense otherwise. A sparse point is an outlier when its reach also exceeds
/// `factor` times the median reach of its OutlierNeighbors nearest dense points, unless it lies
/// on the flat sample of its own nearest points (OutlierPlaneVariation, OutlierPlaneHeight:
/// a sparse part of the surface far from the dense part, e.g. a region scanned from farther
/// away; without this a patch holding most of the points made the rest "outliers"). In a graded
/// sample the dense points nearest to a sparse region lie at its edge, where the density has
/// fallen gradually to the sparse limit (their reach is close to it); next to an isolated point,
/// a clump or sparse clutter they are the sampled surface, however far, so that clutter whose
/// points are each other's neighbours is found too. `factor` <= 0 turns the rule off (nothing
/// flagged). Clouds of fewer than 4 x OutlierNeighbors distinct points are too small to judge:
/// nothing is flagged. The result does not depend on the order of `ids` nor on the number of
/// threads (vtkSMPTools). Cost: one k-nearest-neighbour search (k = OutlierNeighbors), a locator
/// over the dense points and one query per sparse point. The pile search (pcs::FindPiles) costs
/// O(n k) lookups in the table on clean samples; when there are piles, a second search over the
/// positions. `progress` as for FindNearestNeighbors (false: stopped, nothing flagged).
///
/// Piles as duplicates: the same table gives the piles the filters mesh once. `firstOf` gets,
/// per entry of `ids`, the first entry (in the order of `ids`) holding a point of the entry's
/// pile, for the entries of the piles that are not outliers (a far pile is flagged whole), the
/// entry itself otherwise (exact copies of a position in no pile included: they are the
/// caller's exact duplicates, unless `withExactCopies`: then the copies of a position that is not
/// an outlier get its first entry too, as the search has found them anyway); `copies` gets the
/// number of entries whose first is another entry (0: `firstOf` left empty). The table is
/// searched for the piles also when `factor` <= 0 or the cloud is too small for the outlier rule
/// (more than PileNeighbors distinct points; with fewer, nothing is flagged or merged).
int64_t FindOutliersAndPiles(const double* xyz,
  const std::vector<int32_t>& ids,
  double factor,
  std::vector<uint8_t>& outlier,
  std::vector<int32_t>& firstOf,
  int64_t& copies,
  const std::function<bool(double)>& progress = nullptr,
  bool withExactCopies = false);

/// The rule of FindOutliersAndPiles on `n` distinct points `x` (packed x, y, z) whose nearest
/// neighbours are known: `knn` holds `width` >= OutlierNeighbors ids per point, nearest first
/// (pcs::FindNearestNeighbors), of which the first OutlierNeighbors are used. `far` gets one byte
/// per point (1: outlier); returns their number (0 when `width` is too small). Piles are found
/// from the table once (pcs::FindPiles); when there are some, the outlier rule runs on a table
/// searched again over the positions. `firstOf` and `copies`: as pcs::FirstOfPiles over the
/// points, for the piles that are not outliers (the first point of a pile: its smallest index).
int64_t FlagOutliersAndPiles(const double* x,
  int32_t n,
  const std::vector<int32_t>& knn,
  int width,
  double factor,
  std::vector<uint8_t>& far,
  std::vector<int32_t>& firstOf,
  int64_t& copies);

/// FlagOutliersAndPiles on the table of the points `x` (packed x, y, z, one per entry of `ids`),
/// then the flagged points and the pile copies (the points of a pile but its first) removed from
/// `ids` and `x` (order kept): the caller then searches its table again without them
/// (vtkGreedySurfaceTriangulation, vtkLocalOptimumGrowth). `far` keeps the flags by the old
/// index; `pileCopies` gets, for each removed pile copy in the order of `ids`, the pair (its id,
/// the id of its pile's first point), the form of pcs::MergeExactDuplicates (cleared first).
/// Returns the number of outliers.
template<typename IdType>
int64_t DropOutliersAndPilesByTable(std::vector<double>& x,
  std::vector<IdType>& ids,
  const std::vector<int32_t>& knn,
  int width,
  double factor,
  std::vector<uint8_t>& far,
  std::vector<std::pair<IdType, IdType>>& pileCopies)
{
  const int32_t n = static_cast<int32_t>(ids.size());
  std::vector<int32_t> firstOf;
  int64_t copies = 0;
  const int64_t count = FlagOutliersAndPiles(x.data(), n, knn, width, factor, far, firstOf, copies);
  pileCopies.clear();
  if (count > 0 || copies > 0)
  {
    // The pairs first: the compaction below moves the ids (a pile's first point may have moved
    // to an earlier slot by the time one of its copies is reached).
    for (int32_t i = 0; i < n && copies > 0; ++i)
    {
      if (firstOf[i] != i)
      {
        pileCopies.emplace_back(ids[i], ids[firstOf[i]]);
      }
    }
    int32_t kept = 0;
    for (int32_t i = 0; i < n; ++i)
    {
      if (copies > 0 && firstOf[i] != i)
      {
        continue;
      }
      if (!far[i])
      {
        std::copy_n(&x[3 * static_cast<size_t>(i)], 3, &x[3 * static_cast<size_t>(kept)]);
        ids[kept++] = ids[i];
      }
    }
    x.resize(3 * static_cast<size_t>(kept));
    ids.resize(kept);
  }
  return count;
}

/// FindOutliersAndPiles, then the flagged points and the pile copies (the entries of a pile but
/// its first) are removed from `ids` (order kept); `pileCopies` gets, for each removed pile copy
/// in the order of `ids`, the pair (its id, the id of its pile's first entry), the form of
/// pcs::MergeExactDuplicates (cleared first); with `withExactCopies` the exact copies too (see
/// FindOutliersAndPiles). Returns the number of outliers. The filters' OutlierFactor.
int64_t RemoveOutliersAndPiles(const double* xyz,
  std::vector<int32_t>& ids,
  double factor,
  std::vector<std::pair<int32_t, int32_t>>& pileCopies,
  const std::function<bool(double)>& progress = nullptr,
  bool withExactCopies = false);
}

#endif
