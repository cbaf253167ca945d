// Exact fallback of the predicates and their symbolic perturbation. See pcsPredicates.h.
#include "pcsPredicates.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace pcs
{
namespace predicates
{
namespace
{

// ---------------------------------------------------------------------------------------------
// Error-free transformations (Knuth's TwoSum, Dekker's TwoProduct with Veltkamp's split).
inline void TwoSum(double a, double b, double& x, double& y)
{
  x = a + b;
  const double bVirtual = x - a;
  const double aVirtual = x - bVirtual;
  y = (a - aVirtual) + (b - bVirtual);
}

inline void Split(double a, double& high, double& low)
{
  const double c = 134217729.0 * a; // 2^27 + 1
  high = c - (c - a);
  low = a - high;
}

inline void TwoProduct(double a, double b, double& x, double& y)
{
  x = a * b;
  double ah, al, bh, bl;
  Split(a, ah, al);
  Split(b, bh, bl);
  y = al * bl - (((x - ah * bh) - al * bh) - ah * bl);
}

// ---------------------------------------------------------------------------------------------
// A floating-point expansion: the exact value is the sum of its components, which are
// non-overlapping and sorted by increasing magnitude (Shewchuk 1997, section 2). Zero
// components are eliminated, so the sign of the value is the sign of the last component.
class Expansion
{
public:
  Expansion() = default;
  explicit Expansion(double value)
  {
    if (value != 0.0)
    {
      this->C.push_back(value);
    }
  }

  static Expansion Difference(double a, double b)
  {
    Expansion r;
    double x, y;
    TwoSum(a, -b, x, y);
    if (y != 0.0)
    {
      r.C.push_back(y);
    }
    if (x != 0.0)
    {
      r.C.push_back(x);
    }
    return r;
  }

  int Sign() const
  {
    if (this->C.empty())
    {
      return 0;
    }
    return this->C.back() > 0.0 ? 1 : -1;
  }

  Expansion operator-() const
  {
    Expansion r(*this);
    for (double& c : r.C)
    {
      c = -c;
    }
    return r;
  }

  // Add one double (Shewchuk's Grow-Expansion with zero elimination).
  Expansion Grow(double b) const
  {
    Expansion r;
    r.C.reserve(this->C.size() + 1);
    double q = b;
    for (double e : this->C)
    {
      double sum, err;
      TwoSum(q, e, sum, err);
      if (err != 0.0)
      {
        r.C.push_back(err);
      }
      q = sum;
    }
    if (q != 0.0)
    {
      r.C.push_back(q);
    }
    return r;
  }

  Expansion operator+(const Expansion& f) const
  {
    // Repeated growth keeps the invariant; the fallback is rare, simplicity wins here.
    const Expansion* big = this->C.size() >= f.C.size() ? this : &f;
    const Expansion* small = big == this ? &f : this;
    Expansion r = *big;
    for (double c : small->C)
    {
      r = r.Grow(c);
    }
    return r;
  }

  Expansion operator-(const Expansion& f) const { return *this + (-f); }

  // Multiply by one double (Shewchuk's Scale-Expansion with zero elimination).
  Expansion Scale(double b) const
  {
    Expansion r;
    if (this->C.empty() || b == 0.0)
    {
      return r;
    }
    r.C.reserve(2 * this->C.size());
    double q, err;
    TwoProduct(this->C[0], b, q, err);
    if (err != 0.0)
    {
      r.C.push_back(err);
    }
    for (size_t i = 1; i < this->C.size(); ++i)
    {
      double p1, p0;
      TwoProduct(this->C[i], b, p1, p0);
      double sum;
      TwoSum(q, p0, sum, err);
      if (err != 0.0)
      {
        r.C.push_back(err);
      }
      // p1 is at least as large as sum: a plain TwoSum keeps this branch-free and exact.
      TwoSum(p1, sum, q, err);
      if (err != 0.0)
      {
        r.C.push_back(err);
      }
    }
    if (q != 0.0)
    {
      r.C.push_back(q);
    }
    return r;
  }

  Expansion operator*(const Expansion& f) const
  {
    Expansion r;
    for (double c : f.C)
    {
      r = r + this->Scale(c);
    }
    return r;
  }

private:
  std::vector<double> C;
};

inline int SignOf(double v)
{
  return (v > 0.0) - (v < 0.0);
}

} // namespace

// -----------------------------------------------------------------------------------------------
int Orient3DExact(const double* a, const double* b, const double* c, const double* d)
{
  const Expansion adx = Expansion::Difference(a[0], d[0]);
  const Expansion ady = Expansion::Difference(a[1], d[1]);
  const Expansion adz = Expansion::Difference(a[2], d[2]);
  const Expansion bdx = Expansion::Difference(b[0], d[0]);
  const Expansion bdy = Expansion::Difference(b[1], d[1]);
  const Expansion bdz = Expansion::Difference(b[2], d[2]);
  const Expansion cdx = Expansion::Difference(c[0], d[0]);
  const Expansion cdy = Expansion::Difference(c[1], d[1]);
  const Expansion cdz = Expansion::Difference(c[2], d[2]);
  const Expansion det = adz * (bdx * cdy - cdx * bdy) + bdz * (cdx * ady - adx * cdy) +
    cdz * (adx * bdy - bdx * ady);
  return det.Sign();
}

// -----------------------------------------------------------------------------------------------
int InSphereExact(
  const double* a, const double* b, const double* c, const double* d, const double* e)
{
  const Expansion aex = Expansion::Difference(a[0], e[0]);
  const Expansion aey = Expansion::Difference(a[1], e[1]);
  const Expansion aez = Expansion::Difference(a[2], e[2]);
  const Expansion bex = Expansion::Difference(b[0], e[0]);
  const Expansion bey = Expansion::Difference(b[1], e[1]);
  const Expansion bez = Expansion::Difference(b[2], e[2]);
  const Expansion cex = Expansion::Difference(c[0], e[0]);
  const Expansion cey = Expansion::Difference(c[1], e[1]);
  const Expansion cez = Expansion::Difference(c[2], e[2]);
  const Expansion dex = Expansion::Difference(d[0], e[0]);
  const Expansion dey = Expansion::Difference(d[1], e[1]);
  const Expansion dez = Expansion::Difference(d[2], e[2]);
  const Expansion ab = aex * bey - bex * aey;
  const Expansion bc = bex * cey - cex * bey;
  const Expansion cd = cex * dey - dex * cey;
  const Expansion da = dex * aey - aex * dey;
  const Expansion ac = aex * cey - cex * aey;
  const Expansion bd = bex * dey - dex * bey;
  const Expansion abc = aez * bc - bez * ac + cez * ab;
  const Expansion bcd = bez * cd - cez * bd + dez * bc;
  const Expansion cda = cez * da + dez * ac + aez * cd;
  const Expansion dab = dez * ab + aez * bd + bez * da;
  const Expansion alift = aex * aex + aey * aey + aez * aez;
  const Expansion blift = bex * bex + bey * bey + bez * bez;
  const Expansion clift = cex * cex + cey * cey + cez * cez;
  const Expansion dlift = dex * dex + dey * dey + dez * dez;
  const Expansion det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
  return det.Sign();
}

// -----------------------------------------------------------------------------------------------
int Orient2DExact(const double* a, const double* b, const double* c)
{
  const Expansion acx = Expansion::Difference(a[0], c[0]);
  const Expansion acy = Expansion::Difference(a[1], c[1]);
  const Expansion bcx = Expansion::Difference(b[0], c[0]);
  const Expansion bcy = Expansion::Difference(b[1], c[1]);
  return (acx * bcy - acy * bcx).Sign();
}

// -----------------------------------------------------------------------------------------------
int InCircleExact(const double* a, const double* b, const double* c, const double* d)
{
  const Expansion adx = Expansion::Difference(a[0], d[0]);
  const Expansion ady = Expansion::Difference(a[1], d[1]);
  const Expansion bdx = Expansion::Difference(b[0], d[0]);
  const Expansion bdy = Expansion::Difference(b[1], d[1]);
  const Expansion cdx = Expansion::Difference(c[0], d[0]);
  const Expansion cdy = Expansion::Difference(c[1], d[1]);
  const Expansion alift = adx * adx + ady * ady;
  const Expansion blift = bdx * bdx + bdy * bdy;
  const Expansion clift = cdx * cdx + cdy * cdy;
  const Expansion det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
    clift * (adx * bdy - bdx * ady);
  return det.Sign();
}

// -----------------------------------------------------------------------------------------------
int CompareLexicographic(const double* a, const double* b, int dim)
{
  for (int i = 0; i < dim; ++i)
  {
    if (a[i] < b[i])
    {
      return -1;
    }
    if (a[i] > b[i])
    {
      return 1;
    }
  }
  return 0;
}

// -----------------------------------------------------------------------------------------------
// Symbolic perturbation. The insphere determinant is the 5x5 determinant whose rows are
// (x, y, z, |p|^2, 1) for the five points. It is linear in the lifted column, so perturbing the
// lift of point i by delta_i adds delta_i times the cofactor of that entry:
//   (-1)^(i+3) * det[(x, y, z, 1) of the four other points] = (-1)^(i+3) * Orient3D(others).
// With delta_i = eps^(rank of i) the lexicographically largest point has the dominant
// perturbation; the first non-zero cofactor, in decreasing lexicographic order, gives the sign.
int InSphereSoS(
  const double* a, const double* b, const double* c, const double* d, const double* e)
{
  const int exact = InSphere(a, b, c, d, e);
  if (exact != 0)
  {
    return exact;
  }
  const double* p[5] = { a, b, c, d, e };
  int order[5] = { 0, 1, 2, 3, 4 };
  std::sort(order, order + 5,
    [&p](int i, int j) { return CompareLexicographic(p[i], p[j], 3) > 0; });
  for (int k = 0; k < 5; ++k)
  {
    const int i = order[k];
    const double* o[4];
    for (int j = 0, m = 0; j < 5; ++j)
    {
      if (j != i)
      {
        o[m++] = p[j];
      }
    }
    const int minor = Orient3D(o[0], o[1], o[2], o[3]);
    if (minor != 0)
    {
      return (i % 2 == 1) ? minor : -minor; // (-1)^(i+3)
    }
  }
  return 0;
}

// -----------------------------------------------------------------------------------------------
// For q in the plane of a,b,c and d off that plane, the sphere through a,b,c,d cuts the plane
// along the circumcircle of a,b,c, so the in-circle side is the insphere side corrected by the
// orientation of (a,b,c,d). Expanding the 5x5 determinant along the z-like direction of d shows
// that the perturbed insphere determinant is the perturbed in-plane incircle determinant times
// a fixed factor, so the perturbation is the one of the 3D triangulation.
int CoplanarInCircleSoS(
  const double* a, const double* b, const double* c, const double* d, const double* q)
{
  return InSphereSoS(a, b, c, d, q) * Orient3D(a, b, c, d);
}

// -----------------------------------------------------------------------------------------------
// 2D version of the perturbation: rows (x, y, |p|^2, 1); the cofactor of the lift of point i is
// (-1)^(i+2) * Orient2D(others).
int InCircleSoS(const double* a, const double* b, const double* c, const double* d)
{
  const int exact = InCircle(a, b, c, d);
  if (exact != 0)
  {
    return exact;
  }
  const double* p[4] = { a, b, c, d };
  int order[4] = { 0, 1, 2, 3 };
  std::sort(order, order + 4,
    [&p](int i, int j) { return CompareLexicographic(p[i], p[j], 2) > 0; });
  for (int k = 0; k < 4; ++k)
  {
    const int i = order[k];
    const double* o[3];
    for (int j = 0, m = 0; j < 4; ++j)
    {
      if (j != i)
      {
        o[m++] = p[j];
      }
    }
    const int minor = Orient2D(o[0], o[1], o[2]);
    if (minor != 0)
    {
      return (i % 2 == 0) ? minor : -minor; // (-1)^(i+2)
    }
  }
  return 0;
}

} // namespace predicates
} // namespace pcs
