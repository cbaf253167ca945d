// Projected point and edge tests of the constrained Delaunay advancing front (private kernel,
// plain C++, not wrapped). See vtkCDTAdvancingFront.h for the algorithm; the tests are those of
// Huang & Wischgoll, "A Constrained Delaunay Triangle Mesh Method for Three-Dimensional
// Unstructured Boundary Point Cloud" (paper 003), sections II.B, II.C.3, II.D.1, II.D.2, II.E.
//
// Every topological decision below is a sign of an exact predicate of pcsPredicates.h (no
// epsilon): the side of a point with respect to a line or a plane, the crossing of a line and a
// triangle. Where the paper projects points along their normals onto a triangle's plane, the
// projected point is constructed in floating point (as the paper defines it) and the decisions
// are then exact for that constructed point. Distances (the ray length of section II.D) and the
// triangle area (section II.E) are metric thresholds, computed in floating point.
#ifndef pcsProjectedTests_h
#define pcsProjectedTests_h

#include <cmath>

namespace pcs
{
namespace projected
{

/// True when a, b and c are exactly collinear (or two of them coincide): the three orientations
/// of their projections onto the coordinate planes are all zero (exact predicates).
bool Collinear(const double* a, const double* b, const double* c);

/// True when p lies strictly inside the segment a b in space: p distinct from a and b, each of
/// its coordinates between those of a and b, and the three points Collinear (exact). A triangle
/// with the edge a b and the vertex p would have zero area.
bool OnOpenSegment3D(const double* a, const double* b, const double* p);

/// Paper 003, section II.D.1, as a crossing test: the projection of p along the direction n (or
/// its reverse) onto the plane of the triangle abc falls strictly inside the triangle. This is
/// the crossing of the open triangle by the line through p and q = p + 2^k n (q rounded once;
/// 2^k makes 2^k n about as large as p's largest coordinate when n is shorter, so that a short n
/// far from the origin is not rounded away), decided exactly: the three orientations (p, q, a, b), (p, q, b, c), (p, q, c, a) have the
/// same non-zero sign. A line parallel to the plane, or through an edge or a vertex, does not
/// cross.
bool LineCrossesTriangle(
  const double* p, const double* n, const double* a, const double* b, const double* c);

/// Parameter t of the point p + t n of the plane through `origin` with normal `planeNormal`
/// (floating point). Returns false (t untouched) when n is parallel to the plane (n . N = 0) or
/// the result is not finite.
/// (Inline: the projection tests call it for most points near each candidate triangle.)
inline bool RayParameter(const double* p,
  const double* n,
  const double* origin,
  const double* planeNormal,
  double& t)
{
  const double along = n[0] * planeNormal[0] + n[1] * planeNormal[1] + n[2] * planeNormal[2];
  if (along == 0.0)
  {
    return false;
  }
  const double offset = (origin[0] - p[0]) * planeNormal[0] + (origin[1] - p[1]) * planeNormal[1] +
    (origin[2] - p[2]) * planeNormal[2];
  const double value = offset / along;
  if (!std::isfinite(value))
  {
    return false;
  }
  t = value;
  return true;
}

/// Paper 003, section II.C.3: side of x with respect to the edge plane of the edge ab, the plane
/// through a and b perpendicular to the plane of a triangle with normal `normal` (the plane
/// through a, b and a + 2^k normal, that point rounded once, 2^k as in LineCrossesTriangle): +1,
/// -1, or 0 on the plane. Exact for
/// that plane. Two points are on different sides when the product of their sides is negative.
int EdgePlaneSide(const double* a, const double* b, const double* normal, const double* x);

/// How a projected segment p4 p5 meets the triangle p1 p2 p3 in the triangle's plane (paper 003,
/// section II.B, Fig. 1). The segment crosses the triangle when it has a point in the open
/// triangle; the separating-line form below decides exactly the cases of Fig. 1:
enum class SegmentCase
{
  /// Both end points on the closed outer side of one triangle edge (Fig. 1a): no crossing.
  SeparatedByTriangleEdge = 0,
  /// The three triangle vertices on one closed side of the segment's line: no crossing. The
  /// "virtual triangle" normals of Fig. 1b/1e (n . n_virtual <= 0 for a vertex), and Fig. 1g
  /// (the segment's line through a vertex, no end point inside the vertex's wedge).
  SeparatedBySegmentLine = 1,
  /// The segment has a point in the open triangle: an end point inside, or the segment passes
  /// through it (Fig. 1c, 1d, and 1f: through a vertex with an end point inside its wedge).
  Crossing = 2
};

/// (b - a) x (c - a) in floating point (`normal`): the paper's triangle normal, not normalized
/// (TrianglePlane::GetNormal gives the same values).
inline void TriangleNormal(const double* a, const double* b, const double* c, double normal[3])
{
  const double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  normal[0] = e1[1] * e2[2] - e1[2] * e2[1];
  normal[1] = e1[2] * e2[0] - e1[0] * e2[2];
  normal[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

/// The plane of a non-degenerate triangle with exact in-plane sides. Points of (or projected
/// onto) the plane are compared in the two coordinates kept when the axis of the largest
/// component of the triangle's normal is dropped: a parallel projection along a coordinate
/// axis, exact (no arithmetic) and orientation preserving up to a sign the class records.
class TrianglePlane
{
public:
  /// Sets the triangle; returns false when a, b, c are exactly collinear (no plane).
  bool Set(const double* a, const double* b, const double* c);

  /// (b - a) x (c - a), floating point: the paper's triangle normal (not normalized).
  const double* GetNormal() const { return this->Normal; }

  /// Vertex i (0, 1, 2) of the triangle.
  const double* GetVertex(int i) const { return this->Vertices[i]; }

  /// Side of p with respect to the line of edge e (0: v0 v1, 1: v1 v2, 2: v2 v0) within the
  /// plane: +1 on the triangle's side, -1 on the other, 0 on the line. Exact for p's kept
  /// coordinates (p is meant to lie in the plane, e.g. a projected point).
  int Side(int e, const double* p) const;

  /// p strictly inside the triangle (all three sides +1).
  bool ContainsStrictly(const double* p) const;

  /// Paper 003, section II.B: how the segment p4 p5 (points of the plane) meets the triangle.
  SegmentCase ClassifySegment(const double* p4, const double* p5) const;

  /// ClassifySegment(p4, p5) == SegmentCase::Crossing.
  bool SegmentCrosses(const double* p4, const double* p5) const
  {
    return this->ClassifySegment(p4, p5) == SegmentCase::Crossing;
  }

private:
  double Vertices[3][3];
  double Normal[3];
  int U = 0, V = 1; // the kept coordinates
  int Sign = 1;     // orientation of (v0, v1, v2) in (U, V)
  double Flat[3][2];

  int Orient(const double* a2, const double* b2, const double* c2) const;
};

} // namespace projected
} // namespace pcs

#endif
