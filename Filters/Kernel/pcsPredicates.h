// Exact geometric predicates of PointCloudSurface (private kernel, not wrapped).
//
// Each predicate first evaluates its determinant in double precision and compares it with a
// proven forward error bound (the static "stage A" bounds of Shewchuk, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997); when the sign is not
// certain it recomputes the determinant exactly with floating-point expansions (sums of
// non-overlapping doubles built from error-free TwoSum / TwoProduct transformations). The sign
// returned is therefore always the sign of the exact determinant of the double inputs.
//
// The *SoS variants never return 0 for distinct points: they resolve cospherical (cocircular)
// configurations by symbolic perturbation of the lifted coordinate |p|^2 of each point, the
// perturbation being larger for points that are larger in lexicographic (x, y, z) order. The
// perturbation is a property of each point alone, so all decisions taken with it are the
// decisions of one well-defined (perturbed) Delaunay triangulation, independent of insertion
// order.
//
// Conventions (right-handed):
// - Orient3D(a,b,c,d) = det[a-d; b-d; c-d] > 0 when d lies below the plane of a,b,c seen with
//   a,b,c counter-clockwise (a positively oriented tetrahedron has Orient3D(v0,v1,v2,v3) > 0).
// - InSphere(a,b,c,d,e) > 0 when e lies inside the sphere through a,b,c,d, for a positively
//   oriented (a,b,c,d); its sign flips with the orientation.
// - Orient2D(a,b,c) > 0 when a,b,c turn counter-clockwise.
// - InCircle(a,b,c,d) > 0 when d lies inside the circle through a,b,c, counter-clockwise.
#ifndef pcsPredicates_h
#define pcsPredicates_h

namespace pcs
{
namespace predicates
{

/// Sign (-1, 0, +1) of det[a-d; b-d; c-d] (3D points).
int Orient3D(const double* a, const double* b, const double* c, const double* d);

/// Sign of the insphere determinant (may be 0 for cospherical points).
int InSphere(const double* a, const double* b, const double* c, const double* d, const double* e);

/// Insphere sign with symbolic perturbation: never 0 unless two of the points coincide or
/// a,b,c,d are coplanar. Same sign convention as InSphere.
int InSphereSoS(
  const double* a, const double* b, const double* c, const double* d, const double* e);

/// Side of q with respect to the circumcircle of the coplanar points a,b,c (within their
/// plane), with symbolic perturbation: +1 inside, -1 outside. `d` is any point not coplanar
/// with a,b,c (it only fixes the reference orientation); q must be coplanar with a,b,c.
int CoplanarInCircleSoS(
  const double* a, const double* b, const double* c, const double* d, const double* q);

/// Sign of det[a-c; b-c] (2D points, only x and y are read).
int Orient2D(const double* a, const double* b, const double* c);

/// Sign of the incircle determinant (2D points; may be 0 for cocircular points).
int InCircle(const double* a, const double* b, const double* c, const double* d);

/// Incircle sign with symbolic perturbation of the lifted coordinate (lexicographic (x, y)
/// ranks): never 0 unless two points coincide or a,b,c are collinear.
int InCircleSoS(const double* a, const double* b, const double* c, const double* d);

/// Lexicographic comparison of 3D (dim = 3) or 2D (dim = 2) points: -1, 0 or +1.
int CompareLexicographic(const double* a, const double* b, int dim);

} // namespace predicates
} // namespace pcs

#endif
