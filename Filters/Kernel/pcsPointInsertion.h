// Insertion of a free point into the nearest triangle of a surface mesh (private kernel, plain
// C++, not wrapped), used by vtkGreedySurfaceTriangulation to connect the lost points that no
// hole contains (thin features: legs, ears, fins), and by vtkLocalOptimumGrowth to insert the
// free points its growth left under triangles.
//
// A free point q (a vertex of the mesh without triangles) that lies near the mesh is connected
// to it by local topological operations that keep an oriented 2-manifold (pcs::SurfaceMesh):
// - the nearest triangle among those at the given neighbours of q: its plane's distance to q when
//   q projects inside it (decided exactly: the line through q along the triangle's normal crosses
//   the open triangle, pcs::projected::LineCrossesTriangle), otherwise the distance from q to
//   the triangle's nearest edge. A triangle farther than its longest edge is not a candidate:
//   the point is not on that part of the surface (it may become reachable once its own
//   neighbours are inserted);
// - inside, the triangle (a, b, c) is split into (a, b, q), (b, c, q), (c, a, q), unless the
//   angle at q over one edge exceeds 150 degrees (q almost on that edge: the split would leave
//   a needle), in which case that edge is split as below;
// - beyond (or almost, or exactly on) the edge a -> b of the triangle (a, b, c): when the edge
//   has a second triangle (b, a, d), both are replaced by the four triangles around q; when
//   a -> b is a boundary edge, the triangle (b, a, q) is attached across it when q is beyond the
//   edge, or the triangle is split into (q, b, c), (a, q, c) when q is almost or exactly on it
//   (the boundary then runs a -> q -> b). Exactly on an edge is decided exactly
//   (pcs::projected::OnOpenSegment3D): any triangle joining q to that edge would have zero area.
// No new triangle may be exactly degenerate (pcs::projected::Collinear) or face against the
// triangle it replaces. Each operation is applied (its triangles may pinch a vertex until the
// last one is in) and undone when it breaks the manifold: a half-edge used twice, or a vertex
// left with more than one fan.
//
// The decisions of "inside" and of degeneracy are exact predicates; the distances that choose
// the nearest triangle and the reach (longest edge) are metric thresholds in floating point.
#ifndef pcsPointInsertion_h
#define pcsPointInsertion_h

#include "pcsSurfaceMesh.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace pcs
{

/// What InsertFreePoint did.
struct PointInsertionResult
{
  /// Ids of the triangles added (the replaced ones are removed from the mesh).
  std::vector<int64_t> Added;
  /// The edges of the replaced (or attached-to) triangles that remain in the mesh: the caller
  /// may swap them for the shorter diagonal of their two triangles.
  std::vector<std::array<int32_t, 2>> OldEdges;
  /// When an operation had to be undone: (old id, new id) of each triangle put back (the mesh
  /// never reuses ids), so that the caller can carry its per-triangle data over.
  std::vector<std::pair<int64_t, int64_t>> Restored;
  /// The triangles the added ones replaced (vertex ids, as they were), for a caller that may
  /// undo the insertion: remove the added triangles, add these back.
  std::vector<std::array<int32_t, 3>> Removed;
};

/// Connect the free vertex q of `mesh` (coordinates `xyz`, 3 per vertex) to the nearest
/// triangle at its `count` neighbours (`neighbors`, point ids; negative ids are ignored), as
/// described above. `attachToBoundary`: whether a triangle may be attached across a boundary
/// edge. Returns false, and leaves the mesh unchanged, when no triangle is within reach or the
/// operation would break the manifold.
bool InsertFreePoint(SurfaceMesh& mesh, const double* xyz, int32_t q, const int32_t* neighbors,
  int count, bool attachToBoundary, PointInsertionResult& result);

/// Pieces of a mesh that are not surface patches: the connected components (through shared
/// vertices) none of whose vertices is interior -- a lone triangle, or a strip one triangle wide
/// (a seed that could barely grow among points that another part of the mesh passes over).
/// TakeOutStrips removes them from the mesh so that their points can be inserted into the
/// surface under them (InsertFreePoint), and PutBackStrips restores what was not: a strip none of
/// whose points was inserted is put back whole; otherwise its triangles whose three vertices are
/// all still free are put back, and the caller tries its remaining free points again. Points that
/// no triangle takes are left unused (the filters report them).
struct TakenStrips
{
  std::vector<int32_t> Triangles; ///< 3 point ids per removed triangle
  std::vector<int64_t> Ids;       ///< each removed triangle's id in the mesh
  std::vector<size_t> Starts;     ///< first triangle of each strip, and the total at the end
  int64_t NumberOfPoints = 0;     ///< distinct points of the removed triangles
};

/// Remove the strips (see above) of `mesh` into `taken`.
void TakeOutStrips(SurfaceMesh& mesh, TakenStrips& taken);

/// Put back what `taken` holds as described above; `restored` gets (old id, new id) of each
/// triangle put back. Returns the number of distinct points that the put-back triangles use.
int64_t PutBackStrips(
  SurfaceMesh& mesh, const TakenStrips& taken, std::vector<std::pair<int64_t, int64_t>>& restored);

} // namespace pcs

#endif
