// The front expansion of vtkLocalOptimumGrowth (paper 004), usable on a mesh made by another
// filter (private helper, not wrapped; implemented in vtkLocalOptimumGrowth.cxx, where the growth
// lives).
#ifndef pcsFrontGrowth_h
#define pcsFrontGrowth_h

#include <cstdint>
#include <vector>

class vtkAlgorithm;

namespace pcs
{
class SurfaceMesh;

/// The constraints of the expansion, as vtkLocalOptimumGrowth's parameters of the same names
/// (its class documentation, step 3; the defaults are its defaults).
struct FrontGrowthParameters
{
  double MaximumNormalAngle = 60.0; // degrees
  double MinimumEdgeRatio = 1.0 / 3.0;
  double MaximumEdgeRatio = 3.0;
  double MaximumBaseAngle = 120.0; // degrees
  int MaximumHoleEdges = 8;        // vtkLocalOptimumGrowth's hole closing only
  bool RelaxConstraints = true;
};

/// Grows `mesh` into its free points with vtkLocalOptimumGrowth's expansion (its steps 3 and 4:
/// every front edge expanded by its locally optimal candidate, deferred edges retried, the
/// constraints relaxed in stages when RelaxConstraints is on), from the front the mesh has; when
/// it has stalled, new parts are started from seed triangles at the free points of `seeds`, tried
/// in that order (its step 2; empty: none). No hole is closed, no point inserted. The triangles already in `mesh` keep their
/// ids; new ones get ids after them (a part may be reversed to join another one consistently).
/// `x`: the `n` points (packed x, y, z); `knn`: `k` neighbour ids per point, nearest first, -1
/// padded; `stretch`: the scan-line stretch of pcs::AddOffLineNeighbors (3 per point) or empty.
/// `algorithm` gets progress from `progressBegin` to `progressEnd` and is asked for abort (true:
/// aborted). Returns the number of triangles added.
int64_t GrowFront(SurfaceMesh& mesh, const double* x, int32_t n, const std::vector<int32_t>& knn,
  int k, const std::vector<double>& stretch, bool expandFront, const std::vector<int32_t>& seeds,
  const FrontGrowthParameters& parameters, vtkAlgorithm* algorithm, double progressBegin,
  double progressEnd, bool& aborted);
}

#endif
