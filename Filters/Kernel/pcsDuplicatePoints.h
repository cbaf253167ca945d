// Exact duplicate points (private kernel): the one place where the filters decide that two
// points are the same point.
//
// Two points are the same position when all their coordinates compare equal as doubles (so
// +0.0 and -0.0 are one position: the predicates cannot tell them apart either). A point with a
// NaN or infinite coordinate is never the same position as any point, itself included: the
// filters skip such points and report them, and they must not be merged into anything.
#ifndef pcsDuplicatePoints_h
#define pcsDuplicatePoints_h

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace pcs
{
/// True when the `dim` coordinates at p are all finite.
inline bool IsFinitePosition(const double* p, int dim)
{
  for (int i = 0; i < dim; ++i)
  {
    if (!std::isfinite(p[i]))
    {
      return false;
    }
  }
  return true;
}

/// The order of positions used to group exact duplicates: lexicographic on the `dim`
/// coordinates, every finite position before every non-finite one. Returns -1, 0 or 1. It returns
/// 0 for two finite equal positions and for any two non-finite positions: callers break such
/// ties (by id, or by their own order), which makes a strict weak order of points.
int ComparePositions(const double* p, const double* q, int dim);

/// True when p and q are finite and the same position (see above).
inline bool SamePosition(const double* p, const double* q, int dim)
{
  for (int i = 0; i < dim; ++i)
  {
    if (!(p[i] == q[i]) || !std::isfinite(p[i]))
    {
      return false;
    }
  }
  return true;
}

/// Exact duplicates among n points. Entry j (0 <= j < n) is the point `ids[j]` of `coords`
/// (packed, `dim` = 2 or 3 doubles per point), or the point j when `ids` is null; `ids` may be
/// any subset of the points in any order (a sort along a curve, for instance).
///
/// Output: `first[j]` = the smallest entry j' whose point is the same position as entry j's, so
/// `first[j] == j` for the first copy of every position (entries with a non-finite point are
/// their own first copy). With `ids` in ascending order, the first copy is the copy of smallest
/// id; a caller that wants another representative passes its entries in the order it prefers.
/// When `sorted` is not null it receives the entries in the order of ComparePositions, ties
/// (copies) by entry: each group of copies is then a contiguous run that starts with its first
/// copy, finite positions in lexicographic order, non-finite entries last by entry.
/// Returns the number of entries that are their own first copy (the distinct positions, plus
/// the non-finite entries).
///
/// Cost: one O(n log n) sort of the entries (vtkSMPTools::Sort, in parallel), then O(n).
int32_t FindExactDuplicates(const double* coords,
  int dim,
  const int32_t* ids,
  int32_t n,
  std::vector<int32_t>& first,
  std::vector<int32_t>* sorted = nullptr);

/// FindExactDuplicates on `ids`, then removes from `ids` every entry that is not the first copy
/// of its position (the order of the kept entries is unchanged). `merged` receives, for each
/// removed entry in the order of `ids`, the pair (its id, the id of its first copy), the form
/// of pcs::Delaunay3D::GetDuplicates (cleared first). When `kept` is not null it receives the
/// kept ids in the order of ComparePositions (lexicographic, non-finite ones last). Returns the
/// number of entries removed.
int32_t MergeExactDuplicates(const double* coords,
  int dim,
  std::vector<int32_t>& ids,
  std::vector<std::pair<int32_t, int32_t>>& merged,
  std::vector<int32_t>* kept = nullptr);
} // namespace pcs

#endif
