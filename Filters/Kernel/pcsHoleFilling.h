// Hole triangulation by projection (private kernel, plain C++, not wrapped): steps 5 and 6 of
// Emelyanov & Skala, "Surface Reconstruction from Problem Point Clouds" (paper 001, section
// 3.2), used by vtkGreedySurfaceTriangulation.
//
// A hole is a closed loop of mesh vertices (the boundary of a region the mesh does not cover)
// together with the "lost" points that may lie inside it. HoleFiller triangulates it:
// - step 5: the loop is projected onto its average plane (least-squares plane of its points).
//   The projection is unambiguous when the projected loop is a simple polygon and the
//   auxiliary boundary point of every loop vertex -- the vertex moved by a small distance along
//   its boundary vector, i.e. into the surrounding mesh -- projects strictly outside it
//   (paper Fig. 12, 13). A loop that is not unambiguous is split by a chord between two of its
//   vertices into two loops, recursively, until every piece is (paper: "recursive binary
//   subdivision"). The chord is the one with the smallest ratio of its 3D length to the shorter
//   of the two loop arcs it cuts off (the narrowest neck of the hole), among the chords that
//   leave both end points towards the hole (against the boundary vectors), are not mesh edges
//   already and leave at least three vertices on each side. A chord end point is shared by the
//   two pieces (the paper's duplicated points A, A', merged back in its step 7). A piece with
//   more points than MaximumGreedyPoints is split the same way by a diagonal of its projection,
//   so the quadratic greedy triangulation below stays cheap; a triangle, which cannot be split,
//   keeps the lost points nearest its plane up to that bound (the others stay lost).
// - step 6: each piece is triangulated with the lost points that project strictly inside it
//   (and lie within half the piece's radius of its plane, and not exactly on one of its edges in
//   space: only a zero-area triangle could join such a point to that edge, so it stays lost)
//   by the 2D greedy triangulation of Bern & Eppstein (the paper's [BE95]): every pair of
//   points is a candidate edge, candidates are taken by increasing 3D length (the paper's
//   variant: 3D distances, 2D compatibility) and an edge is accepted when it crosses or touches
//   no accepted edge (the loop edges are accepted first) and, between two loop vertices, is a
//   diagonal of the polygon. The
//   triangles are the empty 3-cycles of accepted edges whose points are not collinear in space
//   (exact; the projection, rounded, may not show it).
//
// Every decision on the projected points -- polygon simplicity, point in polygon, segment
// crossings, diagonal tests, triangle orientation and emptiness -- is an exact orientation
// predicate (pcsPredicates.h) on the projected coordinates, which are constructed once in
// floating point: the decisions are exact for those constructed points and no epsilon decides
// topology. The triangles are oriented like the loop: a loop v0 -> v1 -> ... gives triangles that
// traverse each loop edge in the loop's direction.
#ifndef pcsHoleFilling_h
#define pcsHoleFilling_h

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace pcs
{
class SurfaceMesh;

namespace holes
{

/// A plane with an orthonormal frame: origin, in-plane axes U and V, normal N = U x V.
struct Plane
{
  double Origin[3] = { 0, 0, 0 };
  double U[3] = { 1, 0, 0 };
  double V[3] = { 0, 1, 0 };
  double N[3] = { 0, 0, 1 };

  /// Least-squares plane of the points `ids` of `xyz` (centroid, principal axes of largest
  /// variance; with 1 or 2 points the centroid and an axis along them). Returns false when there
  /// are fewer than 3 points or the frame is not finite.
  bool Fit(const double* xyz, const int32_t* ids, size_t count);
  /// In-plane coordinates of p.
  void Project(const double* p, double uv[2]) const;
  /// The point of the plane with in-plane coordinates uv (the inverse of Project on the plane).
  void Lift(const double uv[2], double p[3]) const;
  /// Signed distance of p to the plane (along N).
  double Distance(const double* p) const;
  /// Reverse the orientation of the frame (V and N change sign).
  void Flip();
};

/// Twice the signed area of the polygon (2 coordinates per vertex), floating point.
double SignedArea2(const std::vector<double>& uv);

/// Exact: the closed polygon (2 coordinates per vertex, at least 3 vertices) is simple: no two
/// edges meet except adjacent edges at their shared vertex, and no edge has zero length.
bool IsSimplePolygon(const std::vector<double>& uv);

/// Exact: +1 when p is strictly inside the closed polygon (non-zero winding number), 0 when it
/// is on its boundary, -1 outside.
int PointInPolygon(const std::vector<double>& uv, const double* p);

/// Exact: the closed segments pq and rs have a common point.
bool SegmentsIntersect(const double* p, const double* q, const double* r, const double* s);

/// 2D greedy triangulation (paper 001 step 6, [BE95]) of a simple counter-clockwise polygon
/// (points 0..n-1 in order) with interior points n..n+m-1 (which must lie strictly inside and be
/// pairwise distinct in 2D). `uv`: 2 coordinates per point; `xyz`: 3 per point (the lengths that
/// order the candidates). `forbidden(i, j)` (optional) rejects an interior edge between local
/// points i and j. `length2(i, j)` (optional) replaces the squared 3D length that orders the
/// candidates (a sampling's metric). Triangles (local ids, counter-clockwise) are appended to
/// `triangles`. Returns true when the result is a complete triangulation (n + 2m - 2 triangles).
bool GreedyTriangulation2D(const std::vector<double>& uv,
  const std::vector<double>& xyz,
  int n,
  const std::function<bool(int, int)>& forbidden,
  std::vector<int32_t>& triangles,
  const std::function<double(int, int)>& length2 = nullptr);

/// Exact: the closed triangles abc and def have a common point (crossing, touching at a point
/// or along an edge, or overlapping in a common plane). Two closed triangles meet exactly when an
/// edge of one meets the other, which is decided with orientation predicates (pcsPredicates.h)
/// on the input coordinates; coplanar cases are decided on a coordinate plane onto which the
/// triangle projects with non-zero area. A triangle of zero area is met by nothing (false).
bool TrianglesIntersect(const double* a,
  const double* b,
  const double* c,
  const double* d,
  const double* e,
  const double* f);

/// Result of HoleFiller::Fill.
struct FillResult
{
  std::vector<int32_t> Triangles;                 ///< point ids, 3 per triangle
  std::vector<int32_t> UsedPoints;                ///< interior (lost) points used, point ids
  std::vector<std::array<int32_t, 2>> Chords;     ///< chords inserted (step 5 and size splits)
  int NumberOfPieces = 0;                         ///< pieces triangulated
  int NumberOfFailedPieces = 0;                   ///< pieces left untriangulated
  bool Complete = false;                          ///< every piece completely triangulated
};

/// Steps 5 and 6 on one hole.
class HoleFiller
{
public:
  /// Distance of the auxiliary boundary points from their vertices (the paper's epsilon), in
  /// the units of the coordinates. 0 disables the auxiliary point test.
  double AuxiliaryDistance = 0.0;

  /// Pieces with more points (loop + interior) than this are split by a diagonal before the
  /// greedy triangulation, whose cost grows with the square of the point count.
  int MaximumGreedyPoints = 256;

  /// Optional: true when the mesh already has the edge {a, b} (point ids): such an edge may not
  /// be created inside the hole (it would get a third triangle).
  std::function<bool(int32_t, int32_t)> EdgeExists;

  /// Optional: the squared length of the edge between points a and b (point ids) that orders
  /// step 6's candidate edges instead of the 3D length (a sampling's metric, e.g. scan lines in
  /// vtkGreedySurfaceTriangulation); a negative value falls back to the 3D length.
  std::function<double(int32_t, int32_t)> Length2;

  /// A vertex met twice by the loop: true (default), the loop is cut there into two loops (a
  /// hole touching itself at a vertex); false, the two occurrences are distinct boundary points
  /// at the same place -- the paper's duplicated bridge end points A and A' -- and, since the
  /// projection of such a loop is never simple, step 5 separates them with chords.
  bool SplitAtRepeatedVertices = true;

  /// Triangulate the hole bounded by `loop` (point ids; the triangles follow its direction, see
  /// above). `boundaryVectors`: 3 per loop vertex, the direction from the vertex into the mesh
  /// around the hole (zero when unknown). `candidates`: ids of points that may lie inside the
  /// hole (each is used at most once, by the first piece that contains its projection).
  /// Repeated vertices: see SplitAtRepeatedVertices. Returns false when nothing could be
  /// triangulated.
  bool Fill(const double* xyz, const std::vector<int32_t>& loop,
    const std::vector<double>& boundaryVectors, const std::vector<int32_t>& candidates,
    FillResult& result) const;

  /// Step 5 test alone: the piece `loop` has an unambiguous projection onto `plane` (fitted
  /// and oriented by the call so that the loop turns counter-clockwise). Exposed for the tests.
  bool HasUnambiguousProjection(const double* xyz, const std::vector<int32_t>& loop,
    const std::vector<double>& boundaryVectors, Plane& plane) const;

  /// The projection of `loop` onto its average plane is a simple polygon; `plane` is fitted
  /// and oriented so that the loop turns counter-clockwise.
  bool ProjectsToSimplePolygon(
    const double* xyz, const std::vector<int32_t>& loop, Plane& plane) const;

private:
  struct Piece;
  bool FillPiece(const double* xyz, Piece& piece, std::vector<char>& taken,
    const std::vector<int32_t>& candidates, FillResult& result, int depth) const;
  bool SplitPiece(const double* xyz, const Piece& piece, const Plane* plane,
    const std::vector<double>* uv, Piece& first, Piece& second) const;
};

/// The longest loop LeastDihedralFill triangulates (its cost is cubic in the loop's length); the
/// callers that close loops with it (vtkLocalOptimumGrowth, vtkCDTAdvancingFront) refuse longer
/// loops before any other work.
constexpr size_t MaximumFillLoopEdges = 400;

/// The vector area of a closed polygon (the loop's vertices in the given order; half the sum of
/// the cross products of consecutive edges from loop[0], so that coordinates far from the origin
/// do not cancel it).
void LoopVectorArea(const double* xyz, const std::vector<int32_t>& loop, double area[3]);

/// Triangulation of a loop by its own vertices (vtkGreedySurfaceTriangulation's fallback when the
/// projected fill fails): the triangulation of the loop polygon (its vertices only) that minimises
/// first the largest dihedral angle (between adjacent fill triangles, and between a fill triangle
/// and the mesh triangle across a loop edge) and then the area, by dynamic programming over the
/// sub-polygons (Liepa, "Filling Holes in Meshes", SGP 2003, section 3.1). A diagonal that is an
/// edge of the mesh already and an exactly degenerate triangle are forbidden. `across(e)` gives the
/// unit normal of the mesh triangle on the loop edge loop[e] -> loop[e + 1] (false when none).
/// Triangles in loop order are appended to `triangles`; the largest dihedral angle (radians) is
/// returned, or a negative value when there is no triangulation (or the loop has more than
/// MaximumFillLoopEdges vertices: the cost is cubic). A caller that refuses fills whose angle exceeds `maximumAngle`
/// (radians) passes it: no sub-polygon's triangulation beyond it (and the 1e-9 tie tolerance)
/// is kept, which prunes the programme; the result is then negative, or above `maximumAngle`,
/// when every triangulation exceeds it. Splits that cannot be taken (their parts or their
/// normals already beyond the best split's angle, or not better and with no less area) are
/// skipped before their angles are computed: the result of the plain recurrence, in a fraction
/// of the time on noisy loops.
double LeastDihedralFill(const double* xyz,
  const std::vector<int32_t>& loop,
  const std::function<bool(int32_t, int32_t)>& edgeExists,
  const std::function<bool(int, double[3])>& across,
  std::vector<int32_t>& triangles,
  double maximumAngle = std::numeric_limits<double>::infinity());

/// A loop of `mesh`'s boundary closed by LeastDihedralFill, kept only when the fill stays on the
/// sampled surface (the loop closers of vtkLocalOptimumGrowth and vtkCDTAdvancingFront, each
/// with its own `reach` and near-point query). `boundary`: the loop of boundary half-edges
/// (boundary[i] -> boundary[i + 1] has a mesh triangle on one side only); the fill is that of
/// the loop walked backwards, so its triangles own the twins of those half-edges. Refused:
/// - a loop whose vector area exceeds 2 x perimeter x reach (a region whose points all lie
///   within `reach` of the loop has at most perimeter x reach of area): a wide open border,
///   refused before the cubic fill;
/// - no fill, or one whose largest dihedral angle exceeds `maximumDihedral` (radians; pass
///   infinity for no bound);
/// - a fill triangle that is exactly collinear or is a mesh triangle reversed (the loop of a
///   lone triangle);
/// - a fill triangle whose centroid, or the midpoint of one of its new edges (not in the mesh),
///   has no input point within `reach`: `nearSomePoint(x, reach)` answers that.
/// - a fill that is not a small part of the surface it completes (FillIsSmallPartOfSurface): the
///   lid of a bowl, or the second layer that "closes" a flat patch back to back.
/// A sampling gap on a thin or sharply bent feature passes; a membrane across an open border, a
/// slit, or between parts that only come close passes through empty space and is refused.
/// On success the triangles (point ids, 3 per triangle) are in `fill` and true is returned;
/// `mesh` is not changed.
bool FillLoopNearSamples(const double* xyz,
  const std::vector<int32_t>& boundary,
  const SurfaceMesh& mesh,
  double reach,
  double maximumDihedral,
  const std::function<bool(const double*, double)>& nearSomePoint,
  std::vector<int32_t>& fill);

/// Does a fill (point ids, 3 per triangle, each triangle across at least one loop edge from a
/// triangle of `mesh`, or inside the fill) close a true hole? A hole is a gap in a surface: its
/// fill is a small part of the surface it completes. The border of an open patch is not one: its
/// least-dihedral fill is a lid over a bowl or a second layer back to back with a flat or saddle
/// patch (a closed component of no volume, a "pillow"), and either is about as large as the patch
/// itself. Rule: true when the mesh triangles reached from the fill's loop edges, walking across
/// edges, have more than `ratio` times the fill's area (default 2: the fill at most a third of the
/// closed surface). The walk stops as soon as that area is reached, so its cost is bounded by the
/// size of the fill rather than of the mesh. A fill with no triangle across a mesh edge, or of
/// zero or non-finite area, is not small (false).
bool FillIsSmallPartOfSurface(
  const double* xyz, const SurfaceMesh& mesh, const std::vector<int32_t>& fill, double ratio = 2.0);

/// Is the boundary loop through the half-edge a -> b of `mesh` (coordinates `xyz`) a hole: at
/// most `maxEdges` edges, or shorter than `maxLength`? The bound shared by the growing filters'
/// handle rules (vtkLocalOptimumGrowth step 4, vtkCDTAdvancingFront's KeepsGenus): by its length
/// alone a loop around a tube of radius below 2 spacings (4 pi spacings long) cannot be told from
/// a sampling gap; JoinsLoopsAroundTube tells them apart by their shape. The
/// walk (NextBoundaryVertex) stops as soon as the loop has more edges and is longer, so it costs
/// at most a short loop's length. False when the walk meets the half-edge `avoidTail` ->
/// `avoidHead` (the same loop as that one) or leaves the boundary.
bool IsShortLoop(const SurfaceMesh& mesh, const double* xyz, int32_t a, int32_t b, int64_t maxEdges,
  double maxLength, int32_t avoidTail = -1, int32_t avoidHead = -1);

/// The least loop alignment LV of a loop around a tube (JoinsLoopsAroundTube).
constexpr double TubeLoopAlignment = 0.9;

/// Do the boundary loops through the half-edges a -> b and c -> d of `mesh` (coordinates `xyz`)
/// both go around a tube, so that a triangle joining them closes the surface around that tube (a
/// true handle) rather than joining a hole to the rest of the front? The exception to the hole
/// bound (IsShortLoop) of the growing filters' handle rules (vtkLocalOptimumGrowth step 4,
/// vtkCDTAdvancingFront's KeepsGenus; ours): a loop around a tube is not a hole, whatever its
/// length. The centroid of a loop around a tube lies on the tube's axis, along the surface
/// normals at the loop; the centroid of a hole or a crack lies in the surface beside its rim,
/// across the normals. Measure: the loop alignment LV = sum over the loop's edges of
/// abs(n . (centroid - m)) / sum of abs(centroid - m), with m the edge's midpoint, n the unit
/// normal of the mesh triangle on the edge, and the centroid that of the loop's vertices (1 for a
/// circle around a cylinder, 0 for a planar hole). True when both loops have at most
/// MaximumFillLoopEdges edges and LV >= TubeLoopAlignment (0.9). Measured (Benchmarks/results/
/// cdt.md, "Loops around thin tubes"): joins between loops around thin tubes (knot and torus tubes
/// of 8 to 12 points around) 0.94 - 1.00; joins refused by the hole bound on CGAL's mesh vertex
/// sets, random spheres and tori, clean and noisy, at most 0.77 (the triangles beside the holes of
/// noisy clouds stand up across the surface). A floating-point threshold on a shape, like the
/// length bound of IsShortLoop; it decides no predicate of the mesh. Cost: two walks of each loop.
bool JoinsLoopsAroundTube(
  const SurfaceMesh& mesh, const double* xyz, int32_t a, int32_t b, int32_t c, int32_t d);

} // namespace holes
} // namespace pcs

#endif
