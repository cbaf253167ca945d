// K nearest neighbours of every point of a cloud through vtkStaticPointLocator (private helper of
// the surface filters, not wrapped).
#ifndef pcsNearestNeighbors_h
#define pcsNearestNeighbors_h

#include <cstdint>
#include <functional>
#include <vector>

class vtkStaticPointLocator;

namespace pcs
{
/// For each of the `n` points of `xyz` (packed x, y, z; `locator` built on exactly these points,
/// in this order), its `k` nearest other points, nearest first, ties broken by the smaller id:
/// `neighbors` gets n * k ids (-1 where a point has fewer than k others). Exact duplicates of a
/// point are neighbours like any other point; the copies at one position are one candidate of
/// the bucket walk, of which at most k ids are taken, so a pile of d copies costs O(k) per query
/// instead of O(d) (10^6 copies of one point: O(n k) in all).
///
/// The search uses radius queries on the locator's buckets, several times faster than
/// FindClosestNPoints for surface samples: each query starts from a radius a little beyond the
/// previous point's k-th neighbour (the first from the mean nearest-neighbour distance of a
/// sample) and grows until the ball holds k other points. The buckets' point lists are copied
/// once from the locator (GetBucketIds) and the buckets a ball overlaps are walked directly on
/// `xyz`, as FindPointsWithinRadius does but without its per-point virtual GetPoint and
/// per-call BuildLocator checks (2.2x fewer instructions on a 2 x 10^4-point sphere). The
/// coordinates are copied once in bucket order, the queries run in that order (neighbouring
/// queries one after the other), and only the candidates inside the ball are kept for the
/// partial sort. The result does not depend on those radii, on the query order, nor on the
/// number of threads (vtkSMPTools, in blocks). `progress` (optional) receives the fraction done
/// between blocks; returning false stops the search (the function then returns false and the
/// table is incomplete).
bool FindNearestNeighbors(vtkStaticPointLocator* locator, const double* xyz, int32_t n, int k,
  std::vector<int32_t>& neighbors, const std::function<bool(double)>& progress = nullptr);

/// Bin grid of `locator` (divisions set, Automatic off) for a sample of a surface: `n` points in
/// the box `bounds`, about `binsPerPoint` bins per point over the box's volume (its area when
/// flat, its length when straight). VTK's automatic grid aims at a few points per bin of the box,
/// but a surface sample occupies only a thin layer of those bins, so the bins it does occupy
/// hold many points; finer bins keep the radius queries of FindNearestNeighbors short. Call it
/// before BuildLocator; zero or non-finite extents give one division on that axis.
void SetSurfaceSampleDivisions(
  vtkStaticPointLocator* locator, const double bounds[6], int32_t n, double binsPerPoint = 4.0);
}

#endif
