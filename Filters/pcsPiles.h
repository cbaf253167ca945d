// Piles of near-coincident points: the one definition shared by the surface filters (private
// helper, not wrapped).
#ifndef pcsPiles_h
#define pcsPiles_h

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pcs
{
/// The distance between the points a and b of x (packed x, y, z).
inline double PointDistance(const double* x, int32_t a, int32_t b)
{
  const double* p = &x[3 * static_cast<size_t>(a)];
  const double* q = &x[3 * static_cast<size_t>(b)];
  return std::sqrt(
    (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

/// The nearest neighbours per point of the table a pile is found on (FindPiles).
constexpr int PileNeighbors = 8;
/// A pile is a group of points whose extent (the diagonal of its bounding box) is under PileRatio
/// times its distance to the rest of the cloud (FindPiles). The tolerance is relative: it scales
/// with the gap around the group, i.e. with the sampling where the group lies, and no absolute
/// distance enters (a global scale such as a fraction of the cloud's diagonal over the square
/// root of the number of points merges the distinct points of a densely sampled part of a cloud
/// with a large bounding box, and misses piles whose points are farther apart than that fraction
/// but still unresolvable by the sampling around them).
constexpr double PileRatio = 1e-4;

/// Piles: groups of near-coincident points (a scanner's repeated returns at one spot, points
/// merged from overlapping scans, jittered copies), each of which a filter treats as one sample
/// point. Seen from the rest of the cloud such a group is one point: its internal structure is
/// at a scale the sampling around it cannot resolve.
///
/// Input: `n` distinct points `x` (packed x, y, z; exact copies already merged, e.g. by
/// pcs::FindExactDuplicates) and their table of nearest neighbours `knn`: `width` >= k ids per
/// point, nearest first (pcs::FindNearestNeighbors; -1 for missing entries), of which the first
/// `k` (PileNeighbors by default) are used. A table whose rows were extended by
/// pcs::AddOffLineNeighbors (some far entries replaced by farther off-line points, still sorted)
/// serves too: a pile's rows are not lines and keep their nearest points.
///
/// Definition (single linkage over the graph of the table's edges, shortest first): when an edge
/// first leaves a group of two or more points (its shortest edge to the rest), the group is a
/// pile if the diagonal of its bounding box is under PileRatio times that edge. A group no edge
/// leaves (a separate part of the graph) is a pile if no other point lies within its diagonal x
/// (1 + 1 / PileRatio) of one of its points. A group holding more than half of the `n` points is
/// never a pile (it is most of the cloud; the far points beyond its gap are strays for the
/// outlier rule). A point belongs to the largest pile that holds it.
///
/// Output: `groupOf` gets each point's group, numbered in the order of their first points (a
/// point in no pile is a group of its own); returns the number of groups. n (no pile) leaves
/// `groupOf` empty. The result does not depend on the number of threads.
///
/// Cost: O(n k) lookups in the table to check three conditions of which every pile meets one
/// (with d1 and dk a point's distances to the first and k-th point of its row: a member with d1
/// under PileRatio x dk; a member m in the row of an outside point r with dk(m) under PileRatio x
/// dk(r); dk under PileRatio x the cloud's diagonal); on clean samples none holds and nothing
/// else is done. Only when one holds: the edges gathered and, when the shortest is under
/// PileRatio x the longest, sorted, and a radius query per separate part of the graph whose
/// diagonal is under PileRatio times the cloud's.
int32_t FindPiles(const double* x,
  int32_t n,
  const std::vector<int32_t>& knn,
  int width,
  std::vector<int32_t>& groupOf,
  int k = PileNeighbors);

/// Piles as duplicates (every filter meshes one point per pile, as one copy of exact duplicates):
/// from FindPiles' `groupOf` over `n` points (empty: no pile), `firstOf[i]` gets the first point
/// (smallest index) of point i's pile, i itself for a point in no pile and for each pile's first
/// point. Returns the number of points that are not their pile's first (the copies a filter
/// leaves unused and counts as duplicates); 0 leaves `firstOf` empty.
int32_t FirstOfPiles(const std::vector<int32_t>& groupOf, std::vector<int32_t>& firstOf);

/// Each point represented by a pile copy is represented by the copy's pile's first instead (the
/// filters map every point to the point that meshes it: itself, the copy of smallest id of its
/// exact copies, and a pile's first for the points of a pile). `representative`: one id per point
/// of `n` (-1: none, e.g. an outlier); `pileCopies`: (copy, first) pairs over the same ids, as
/// pcs::RemoveOutliersAndPiles and pcs::DropOutliersAndPilesByTable give them (a copy's first is
/// never a copy). Returns the number of points that represented themselves and no longer do
/// (the pile copies: they join the filter's duplicates).
template<typename Id, typename PairId>
int64_t RepresentPilesByFirst(Id* representative,
  int64_t n,
  const std::vector<std::pair<PairId, PairId>>& pileCopies)
{
  if (pileCopies.empty())
  {
    return 0;
  }
  // In the pairs' own id type (int32_t for every filter today): half the memory of vtkIdType.
  std::vector<PairId> firstOfCopy(static_cast<size_t>(n), -1);
  for (const auto& copy : pileCopies)
  {
    firstOfCopy[copy.first] = copy.second;
  }
  int64_t copies = 0;
  for (int64_t i = 0; i < n; ++i)
  {
    const Id r = representative[i];
    if (r >= 0 && firstOfCopy[r] >= 0)
    {
      representative[i] = static_cast<Id>(firstOfCopy[r]);
      copies += r == i ? 1 : 0;
    }
  }
  return copies;
}

/// The filters' warning on their duplicates (one wording for all): "Ignored `count` duplicate
/// point(s): exact copies, or points of a pile (...); `kept`." (`kept`: which point of each
/// group the filter meshes).
std::string DuplicatesWarning(int64_t count, const std::string& kept);
}

#endif
