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

#include <cmath>

namespace pcs
{
namespace predicates
{

/// Exact signs, called when the floating-point filter cannot decide.
int Orient3DExact(const double* a, const double* b, const double* c, const double* d);
int InSphereExact(
  const double* a, const double* b, const double* c, const double* d, const double* e);
int Orient2DExact(const double* a, const double* b, const double* c);
int InCircleExact(const double* a, const double* b, const double* c, const double* d);

/// Largest magnitude of four finite doubles.
inline double MaxAbs4(double a, double b, double c, double d)
{
  a = std::fabs(a);
  b = std::fabs(b);
  c = std::fabs(c);
  d = std::fabs(d);
  const double ab = a > b ? a : b;
  const double cd = c > d ? c : d;
  return ab > cd ? ab : cd;
}

/// Static-filter part of Orient3D only: +1 or -1 when |det| exceeds `staticBound` (see
/// Orient3D), 0 when undecided (then call Orient3D). Small enough to be inlined in hot loops.
inline int Orient3DStatic(
  const double* a, const double* b, const double* c, const double* d, double staticBound)
{
  const double adx = a[0] - d[0], ady = a[1] - d[1], adz = a[2] - d[2];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1], bdz = b[2] - d[2];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1], cdz = c[2] - d[2];
  const double det = adz * (bdx * cdy - cdx * bdy) + bdz * (cdx * ady - adx * cdy) +
    cdz * (adx * bdy - bdx * ady);
  return staticBound > 0.0 && det > staticBound ? 1
    : staticBound > 0.0 && -det > staticBound  ? -1
                                               : 0;
}

/// Sign (-1, 0, +1) of det[a-d; b-d; c-d] (3D points).
/// `staticBound`: as for InSphere, Orient3DStaticBound(E) for differences at most E; 0 disables.
inline int Orient3D(
  const double* a, const double* b, const double* c, const double* d, double staticBound = 0.0)
{
  const double adx = a[0] - d[0], ady = a[1] - d[1], adz = a[2] - d[2];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1], bdz = b[2] - d[2];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1], cdz = c[2] - d[2];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det =
    adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  if (staticBound > 0.0 && std::fabs(det) > staticBound)
  {
    return det > 0 ? 1 : -1;
  }
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
    (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
    (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
  // Shewchuk's o3derrboundA = (7 + 56 eps) eps with eps = 2^-53.
  const double bound = 7.7715611723761027e-16 * permanent;
  if (det > bound)
  {
    return 1;
  }
  if (-det > bound)
  {
    return -1;
  }
  return Orient3DExact(a, b, c, d);
}

/// Static-filter part of InSphere only: +1 or -1 when |det| exceeds `staticBound` (see
/// InSphere), 0 when undecided (then call InSphere). Small enough to be inlined in hot loops.
inline int InSphereStatic(const double* a, const double* b, const double* c, const double* d,
  const double* e, double staticBound)
{
  const double aex = a[0] - e[0], aey = a[1] - e[1], aez = a[2] - e[2];
  const double bex = b[0] - e[0], bey = b[1] - e[1], bez = b[2] - e[2];
  const double cex = c[0] - e[0], cey = c[1] - e[1], cez = c[2] - e[2];
  const double dex = d[0] - e[0], dey = d[1] - e[1], dez = d[2] - e[2];
  const double ab = aex * bey - bex * aey, bc = bex * cey - cex * bey;
  const double cd = cex * dey - dex * cey, da = dex * aey - aex * dey;
  const double ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
  const double abc = aez * bc - bez * ac + cez * ab;
  const double bcd = bez * cd - cez * bd + dez * bc;
  const double cda = cez * da + dez * ac + aez * cd;
  const double dab = dez * ab + aez * bd + bez * da;
  const double alift = aex * aex + aey * aey + aez * aez;
  const double blift = bex * bex + bey * bey + bez * bez;
  const double clift = cex * cex + cey * cey + cez * cez;
  const double dlift = dex * dex + dey * dey + dez * dez;
  const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
  // A zero bound (unknown extent) decides nothing.
  return staticBound > 0.0 && det > staticBound ? 1
    : staticBound > 0.0 && -det > staticBound  ? -1
                                               : 0;
}

/// Sign of the insphere determinant (may be 0 for cospherical points).
///
/// `staticBound` (optional) is a static filter for callers that know a bound E on every
/// coordinate difference (e.g. the extent of the bounding box of all points): pass
/// InSphereStaticBound(E) and a determinant larger than it in magnitude is decided without the
/// per-call bounds below. 0 (the default) disables it.
inline int InSphere(const double* a, const double* b, const double* c, const double* d,
  const double* e, double staticBound = 0.0)
{
  const double aex = a[0] - e[0], aey = a[1] - e[1], aez = a[2] - e[2];
  const double bex = b[0] - e[0], bey = b[1] - e[1], bez = b[2] - e[2];
  const double cex = c[0] - e[0], cey = c[1] - e[1], cez = c[2] - e[2];
  const double dex = d[0] - e[0], dey = d[1] - e[1], dez = d[2] - e[2];
  const double aexbey = aex * bey, bexaey = bex * aey;
  const double bexcey = bex * cey, cexbey = cex * bey;
  const double cexdey = cex * dey, dexcey = dex * cey;
  const double dexaey = dex * aey, aexdey = aex * dey;
  const double aexcey = aex * cey, cexaey = cex * aey;
  const double bexdey = bex * dey, dexbey = dex * bey;
  const double ab = aexbey - bexaey, bc = bexcey - cexbey, cd = cexdey - dexcey;
  const double da = dexaey - aexdey, ac = aexcey - cexaey, bd = bexdey - dexbey;
  const double abc = aez * bc - bez * ac + cez * ab;
  const double bcd = bez * cd - cez * bd + dez * bc;
  const double cda = cez * da + dez * ac + aez * cd;
  const double dab = dez * ab + aez * bd + bez * da;
  const double alift = aex * aex + aey * aey + aez * aez;
  const double blift = bex * bex + bey * bey + bez * bez;
  const double clift = cex * cex + cey * cey + cez * cez;
  const double dlift = dex * dex + dey * dey + dez * dez;
  const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
  if (staticBound > 0.0 && std::fabs(det) > staticBound)
  {
    return det > 0 ? 1 : -1;
  }
  {
    // Cheaper bound first: each of the 24 products of the permanent below is at most
    // mx * my * mz * (mx^2 + my^2 + mz^2), with m* the largest difference magnitude per axis;
    // the factor 1 + 2^-40 covers the rounding of this product.
    const double mx = MaxAbs4(aex, bex, cex, dex);
    const double my = MaxAbs4(aey, bey, cey, dey);
    const double mz = MaxAbs4(aez, bez, cez, dez);
    const double coarse = 24.0 * 1.7763568394002532e-15 * (1.0 + 9.0949470177292824e-13) *
      (mx * my * mz) * (mx * mx + my * my + mz * mz);
    if (std::fabs(det) > coarse)
    {
      return det > 0 ? 1 : -1;
    }
  }
  const double aezp = std::fabs(aez), bezp = std::fabs(bez);
  const double cezp = std::fabs(cez), dezp = std::fabs(dez);
  const double aexbeyp = std::fabs(aexbey), bexaeyp = std::fabs(bexaey);
  const double bexceyp = std::fabs(bexcey), cexbeyp = std::fabs(cexbey);
  const double cexdeyp = std::fabs(cexdey), dexceyp = std::fabs(dexcey);
  const double dexaeyp = std::fabs(dexaey), aexdeyp = std::fabs(aexdey);
  const double aexceyp = std::fabs(aexcey), cexaeyp = std::fabs(cexaey);
  const double bexdeyp = std::fabs(bexdey), dexbeyp = std::fabs(dexbey);
  const double permanent =
    ((cexdeyp + dexceyp) * bezp + (dexbeyp + bexdeyp) * cezp + (bexceyp + cexbeyp) * dezp) *
      alift +
    ((dexaeyp + aexdeyp) * cezp + (aexceyp + cexaeyp) * dezp + (cexdeyp + dexceyp) * aezp) *
      blift +
    ((aexbeyp + bexaeyp) * dezp + (bexdeyp + dexbeyp) * aezp + (dexaeyp + aexdeyp) * bezp) *
      clift +
    ((bexceyp + cexbeyp) * aezp + (cexaeyp + aexceyp) * bezp + (aexbeyp + bexaeyp) * cezp) *
      dlift;
  // Shewchuk's isperrboundA = (16 + 224 eps) eps.
  const double bound = 1.7763568394002532e-15 * permanent;
  if (det > bound)
  {
    return 1;
  }
  if (-det > bound)
  {
    return -1;
  }
  return InSphereExact(a, b, c, d, e);
}

/// The static orientation bound for coordinate differences at most `extent` in magnitude: each
/// of the 6 products of the permanent is at most extent^3 (0 when it under/overflows).
inline double Orient3DStaticBound(double extent)
{
  const double bound =
    6.0 * 7.7715611723761027e-16 * (1.0 + 9.0949470177292824e-13) * (extent * extent * extent);
  return std::isfinite(bound) && bound >= 1e-290 ? bound : 0.0;
}

/// The static insphere bound for coordinate differences at most `extent` in magnitude: the
/// semi-static bound of InSphere with mx = my = mz = extent (0 when it underflows or overflows,
/// which disables the static filter).
inline double InSphereStaticBound(double extent)
{
  const double e2 = extent * extent;
  const double bound =
    24.0 * 1.7763568394002532e-15 * (1.0 + 9.0949470177292824e-13) * (e2 * extent) * (3.0 * e2);
  return std::isfinite(bound) && bound >= 1e-290 ? bound : 0.0;
}

/// Sign of det[a-c; b-c] (2D points, only x and y are read).
inline int Orient2D(const double* a, const double* b, const double* c)
{
  const double detleft = (a[0] - c[0]) * (b[1] - c[1]);
  const double detright = (a[1] - c[1]) * (b[0] - c[0]);
  const double det = detleft - detright;
  // Shewchuk's ccwerrboundA = (3 + 16 eps) eps.
  const double bound = 3.3306690738754716e-16 * (std::fabs(detleft) + std::fabs(detright));
  // The filtered sign without a branch on it (callers' signs are often unpredictable); the one
  // branch left, to the exact determinant, is rarely taken.
  const int sign = static_cast<int>(det > bound) - static_cast<int>(-det > bound);
  return sign != 0 ? sign : Orient2DExact(a, b, c);
}

/// Sign of the incircle determinant (2D points; may be 0 for cocircular points).
inline int InCircle(const double* a, const double* b, const double* c, const double* d)
{
  const double adx = a[0] - d[0], ady = a[1] - d[1];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det =
    alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
    (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
    (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
  // Shewchuk's iccerrboundA = (10 + 96 eps) eps.
  const double bound = 1.1102230246251577e-15 * permanent;
  const int sign = static_cast<int>(det > bound) - static_cast<int>(-det > bound); // (Orient2D)
  return sign != 0 ? sign : InCircleExact(a, b, c, d);
}

/// Insphere sign with symbolic perturbation: never 0 unless two of the points coincide or
/// a,b,c,d are coplanar. Same sign convention as InSphere.
int InSphereSoS(
  const double* a, const double* b, const double* c, const double* d, const double* e);

/// Side of q with respect to the circumcircle of the coplanar points a,b,c (within their
/// plane), with the same symbolic perturbation: +1 inside, -1 outside. `d` is any point not
/// coplanar with a,b,c (it only fixes the reference orientation); q must be coplanar with a,b,c.
int CoplanarInCircleSoS(
  const double* a, const double* b, const double* c, const double* d, const double* q);

/// Incircle sign with symbolic perturbation of the lifted coordinate (lexicographic (x, y)
/// ranks): never 0 unless two points coincide or a,b,c are collinear.
int InCircleSoS(const double* a, const double* b, const double* c, const double* d);

/// Lexicographic comparison of 3D (dim = 3) or 2D (dim = 2) points: -1, 0 or +1.
int CompareLexicographic(const double* a, const double* b, int dim);

} // namespace predicates
} // namespace pcs

#endif
