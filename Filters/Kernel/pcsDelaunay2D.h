// Incremental 2D Delaunay triangulation with Lawson edge flips (private kernel).
//
// Paper 002 (Cocias et al.), section 3.1 "Randomized incremental algorithm": each new point
// splits the triangle that contains it (or the two triangles sharing the edge it lies on) and
// illegal edges are flipped until every edge is locally Delaunay. Decisions use the exact
// predicates of pcsPredicates.h with symbolic perturbation (InCircleSoS), so cocircular inputs
// give a valid, insertion-order independent triangulation. The triangulation is closed by an
// infinite vertex (-1), so the convex hull is exact; only finite triangles are reported.
#ifndef pcsDelaunay2D_h
#define pcsDelaunay2D_h

#include <cstdint>
#include <functional>
#include <vector>

namespace pcs
{
class Delaunay2D
{
public:
  /// Progress/abort callback: receives a fraction in [0, 1]; returning false aborts.
  using ProgressFunction = std::function<bool(double)>;

  /// Triangulate the points `ids` of `xy` (packed x,y pairs). The referenced points must be
  /// finite and pairwise distinct (the caller merges duplicates). Returns false when fewer than
  /// 3 non-collinear points are given or when the progress callback aborted; the triangle
  /// list is then empty.
  bool Triangulate(const double* xy, const std::vector<int32_t>& ids,
    const ProgressFunction& progress = ProgressFunction());

  /// Finite triangles, 3 point ids each (ids into xy), counter-clockwise.
  const std::vector<int32_t>& GetTriangles() const { return this->Triangles; }

  /// For each finite triangle t and each edge i (opposite vertex i), the adjacent finite
  /// triangle, or -1 on the convex hull.
  const std::vector<int32_t>& GetNeighbors() const { return this->Neighbors; }

  /// Number of Lawson flips performed by the last Triangulate call.
  int64_t GetNumberOfFlips() const { return this->NumberOfFlips; }

private:
  std::vector<int32_t> Triangles;
  std::vector<int32_t> Neighbors;
  int64_t NumberOfFlips = 0;
};
} // namespace pcs

#endif
