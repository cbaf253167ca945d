// Randomized exactness test of the exact predicates of the private kernel
// (Filters/Kernel/pcsPredicates.h), compiled together with Filters/Kernel/pcsPredicates.cxx.
//
// More than 10^6 hard inputs (near-degenerate and exactly degenerate point sets, coordinates of
// mixed magnitudes 1e-8 .. 1e8, power-of-two scalings up to 2^+-60, differences that are and
// are not representable) are checked against two exact references:
//  - the determinants as the header defines them, evaluated with CGAL::Mpzf (exact
//    multi-precision ring arithmetic on doubles): the differences with the last point are
//    formed exactly and the determinant expanded by cofactors;
//  - CGAL's exact predicates (Epick: orientation, side_of_oriented_sphere / circle), which
//    also pins the sign conventions.
// Every predicate is checked twice: the inline filtered version and the *Exact fallback alone.
// The symbolic perturbation is checked against its definition (first non-zero cofactor of the
// lifted column in decreasing lexicographic order), for consistency with the unperturbed
// predicate, for never returning 0 on non-degenerate input, and for antisymmetry under
// exchanges of two points.
//
// Usage: pcsTestPredicatesExact [cases per family = 20000] [seed = 1]. Returns 0 on success.
#include "pcsPredicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mpzf.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace
{
namespace P = pcs::predicates;
using Exact = CGAL::Mpzf;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vec3 = std::array<double, 3>;

long long Checks = 0;
long long Failures = 0;
long long Cases = 0;
long long ZeroCases = 0;

std::ostream& operator<<(std::ostream& os, const Vec3& p)
{
  os.precision(17);
  return os << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
}

std::map<std::string, long long> FailuresByCheck;

void Report(const std::string& what, const std::string& family, const std::vector<Vec3>& points,
  int got, int expected)
{
  ++FailuresByCheck[what + " [" + family + "]"];
  if (Failures++ < 30)
  {
    std::cerr << "FAIL " << what << " [" << family << "] got " << got << " expected " << expected
              << " points:";
    for (const Vec3& p : points)
    {
      std::cerr << " " << p;
    }
    std::cerr << std::endl;
  }
}

#define CHECK_EQ(what, family, points, got, expected)                                             \
  do                                                                                               \
  {                                                                                                \
    ++Checks;                                                                                      \
    const int g_ = (got), e_ = (expected);                                                         \
    if (g_ != e_)                                                                                  \
    {                                                                                              \
      Report(what, family, points, g_, e_);                                                        \
    }                                                                                              \
  } while (false)

int SignOf(const Exact& v)
{
  return static_cast<int>(v.sign());
}

// ---------------------------------------------------------------------------------------------
// Exact references (header definitions, Mpzf).

// Determinant of an N x N matrix of exact values by cofactor expansion along the first row.
template <int N>
Exact Determinant(const std::array<std::array<Exact, N>, N>& m)
{
  if constexpr (N == 1)
  {
    return m[0][0];
  }
  else
  {
    Exact result(0.0);
    for (int col = 0; col < N; ++col)
    {
      std::array<std::array<Exact, N - 1>, N - 1> minor;
      for (int i = 1; i < N; ++i)
      {
        for (int j = 0, k = 0; j < N; ++j)
        {
          if (j != col)
          {
            minor[i - 1][k++] = m[i][j];
          }
        }
      }
      const Exact term = m[0][col] * Determinant<N - 1>(minor);
      result = (col % 2 == 0) ? result + term : result - term;
    }
    return result;
  }
}

// sign det [p_i - q] (i < dim), rows of differences; with `lifted`, an extra column |p_i - q|^2.
template <int Dim, bool Lifted>
int RefDeterminant(const Vec3* const* p, const Vec3& q)
{
  constexpr int N = Lifted ? Dim + 1 : Dim;
  std::array<std::array<Exact, N>, N> m;
  for (int i = 0; i < N; ++i)
  {
    Exact lift(0.0);
    for (int k = 0; k < Dim; ++k)
    {
      const Exact diff = Exact((*p[i])[k]) - Exact(q[k]);
      m[i][k] = diff;
      lift = lift + diff * diff;
    }
    if (Lifted)
    {
      m[i][N - 1] = lift;
    }
  }
  return SignOf(Determinant<N>(m));
}

int RefOrient3D(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  const Vec3* p[3] = { &a, &b, &c };
  return RefDeterminant<3, false>(p, d);
}

int RefInSphere(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e)
{
  const Vec3* p[4] = { &a, &b, &c, &d };
  return RefDeterminant<3, true>(p, e);
}

int RefOrient2D(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3* p[2] = { &a, &b };
  return RefDeterminant<2, false>(p, c);
}

int RefInCircle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  const Vec3* p[3] = { &a, &b, &c };
  return RefDeterminant<2, true>(p, d);
}

// CGAL's exact predicates with the header's conventions.
Epick::Point_3 P3(const Vec3& p)
{
  return Epick::Point_3(p[0], p[1], p[2]);
}

Epick::Point_2 P2(const Vec3& p)
{
  return Epick::Point_2(p[0], p[1]);
}

int CgalOrient3D(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  // CGAL: sign det [b-a; c-a; d-a] = -det [a-d; b-d; c-d].
  return -static_cast<int>(CGAL::orientation(P3(a), P3(b), P3(c), P3(d)));
}

int CgalInSphere(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e)
{
  // CGAL: positive inside for CGAL-positive (header-negative) tetrahedra.
  return -static_cast<int>(CGAL::side_of_oriented_sphere(P3(a), P3(b), P3(c), P3(d), P3(e)));
}

int CgalOrient2D(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return static_cast<int>(CGAL::orientation(P2(a), P2(b), P2(c)));
}

int CgalInCircle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  return static_cast<int>(CGAL::side_of_oriented_circle(P2(a), P2(b), P2(c), P2(d)));
}

// Symbolic perturbation by definition: the lifted coordinate of each point is raised by
// eps^(rank), larger for lexicographically larger points; the sign is the one of the first
// non-zero cofactor of the lifted column, (-1)^(i+dim) * orientation(others), in decreasing
// lexicographic order of the point i.
int RefInSphereSoS(const Vec3* p)
{
  const int exact = RefInSphere(p[0], p[1], p[2], p[3], p[4]);
  if (exact != 0)
  {
    return exact;
  }
  int order[5] = { 0, 1, 2, 3, 4 };
  std::sort(order, order + 5, [p](int i, int j) { return p[i] > p[j]; });
  for (int i : order)
  {
    const Vec3* o[4];
    for (int j = 0, k = 0; j < 5; ++j)
    {
      if (j != i)
      {
        o[k++] = &p[j];
      }
    }
    const int minor = RefOrient3D(*o[0], *o[1], *o[2], *o[3]);
    if (minor != 0)
    {
      return (i % 2 == 1) ? minor : -minor;
    }
  }
  return 0;
}

int RefInCircleSoS(const Vec3* p)
{
  const int exact = RefInCircle(p[0], p[1], p[2], p[3]);
  if (exact != 0)
  {
    return exact;
  }
  int order[4] = { 0, 1, 2, 3 };
  std::sort(order, order + 4, [p](int i, int j) {
    return std::make_pair(p[i][0], p[i][1]) > std::make_pair(p[j][0], p[j][1]);
  });
  for (int i : order)
  {
    const Vec3* o[3];
    for (int j = 0, k = 0; j < 4; ++j)
    {
      if (j != i)
      {
        o[k++] = &p[j];
      }
    }
    const int minor = RefOrient2D(*o[0], *o[1], *o[2]);
    if (minor != 0)
    {
      return (i % 2 == 0) ? minor : -minor;
    }
  }
  return 0;
}

// ---------------------------------------------------------------------------------------------
// Generators of hard inputs.
class Generator
{
public:
  explicit Generator(unsigned seed)
    : Rng(seed)
  {
  }

  double Uniform(double lo, double hi)
  {
    return std::uniform_real_distribution<double>(lo, hi)(this->Rng);
  }
  int Integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(this->Rng); }
  double Normal() { return std::normal_distribution<double>()(this->Rng); }
  // 10^u, u uniform in [lo, hi]: magnitudes spread over many orders.
  double Magnitude(double lo, double hi) { return std::pow(10.0, this->Uniform(lo, hi)); }
  double Sign() { return this->Integer(0, 1) ? 1.0 : -1.0; }

  // Moves v by up to `ulps` units in the last place (each direction equally likely).
  double Nudge(double v, int ulps)
  {
    const int k = this->Integer(-ulps, ulps);
    for (int i = 0; i < std::abs(k); ++i)
    {
      v = std::nextafter(v, k > 0 ? HUGE_VAL : -HUGE_VAL);
    }
    return v;
  }

  void MaybeNudge(std::vector<Vec3>& points, int dim)
  {
    const int mode = this->Integer(0, 3);
    if (mode == 0)
    {
      return; // rounded only
    }
    if (mode == 1)
    {
      // One coordinate of one point.
      Vec3& p = points[this->Integer(0, static_cast<int>(points.size()) - 1)];
      const int k = this->Integer(0, dim - 1);
      p[k] = this->Nudge(p[k], 2);
      return;
    }
    for (Vec3& p : points)
    {
      for (int k = 0; k < dim; ++k)
      {
        p[k] = this->Nudge(p[k], mode == 2 ? 1 : 4);
      }
    }
  }

  Vec3 Center(int dim)
  {
    const double scale = this->Integer(0, 4) == 0 ? 0.0 : this->Magnitude(-8, 8);
    Vec3 c = { 0.0, 0.0, 0.0 };
    for (int k = 0; k < dim; ++k)
    {
      // Per-axis magnitudes differ too.
      c[k] = this->Normal() * scale * (this->Integer(0, 2) == 0 ? this->Magnitude(-4, 0) : 1.0);
    }
    return c;
  }

  // Points rounded onto a sphere (dim 3) or circle (dim 2) of random center and radius.
  std::vector<Vec3> OnSphere(int count, int dim)
  {
    const Vec3 c = this->Center(dim);
    const double radius = this->Magnitude(-8, 8);
    // Points clustered on a cap half the time (neighbouring points, as in a triangulation).
    const bool cap = this->Integer(0, 1) == 1;
    const double spread = cap ? this->Magnitude(-6, -1) : 1.0;
    Vec3 axis = { this->Normal(), this->Normal(), dim == 3 ? this->Normal() : 0.0 };
    std::vector<Vec3> points(count, Vec3{ 0.0, 0.0, 0.0 });
    for (Vec3& p : points)
    {
      Vec3 u = { 0.0, 0.0, 0.0 };
      double norm = 0.0;
      for (int k = 0; k < dim; ++k)
      {
        u[k] = axis[k] + spread * this->Normal();
        norm += u[k] * u[k];
      }
      norm = std::sqrt(norm);
      for (int k = 0; k < dim; ++k)
      {
        p[k] = c[k] + radius * (u[k] / norm);
      }
    }
    this->MaybeNudge(points, dim);
    return points;
  }

  // Points rounded onto a random plane (dim 3) or line (dim 2).
  std::vector<Vec3> OnPlane(int count, int dim)
  {
    const Vec3 c = this->Center(dim);
    const double extent = this->Magnitude(-8, 8);
    Vec3 u = { 0.0, 0.0, 0.0 }, v = { 0.0, 0.0, 0.0 };
    for (int k = 0; k < dim; ++k)
    {
      u[k] = this->Normal() * (this->Integer(0, 3) == 0 ? this->Magnitude(-6, 0) : 1.0);
      v[k] = this->Normal() * (this->Integer(0, 3) == 0 ? this->Magnitude(-6, 0) : 1.0);
    }
    std::vector<Vec3> points(count, Vec3{ 0.0, 0.0, 0.0 });
    for (Vec3& p : points)
    {
      const double s = extent * this->Normal(), t = dim == 3 ? extent * this->Normal() : 0.0;
      for (int k = 0; k < dim; ++k)
      {
        p[k] = c[k] + s * u[k] + t * v[k];
      }
    }
    this->MaybeNudge(points, dim);
    return points;
  }

  // Exactly cospherical (cocircular) integer points: lattice points of the sphere of radius 63
  // (circle of radius 65) times an odd multiplier, plus an integer translation, times a power
  // of two. With a large multiplier the coordinates fill the 53 bits and many differences are
  // not representable (non-zero tails), with a small one they are; a third of the sets are
  // translated so that one of their points is the origin (see TinyNudge).
  std::vector<Vec3> Cospherical(int count, int dim)
  {
    static const std::vector<Vec3> sphere = LatticePoints(63, 3);
    static const std::vector<Vec3> circle = LatticePoints(65, 2);
    const std::vector<Vec3>& lattice = dim == 3 ? sphere : circle;
    std::vector<Vec3> chosen(count);
    for (Vec3& q : chosen)
    {
      q = lattice[this->Integer(0, static_cast<int>(lattice.size()) - 1)];
    }
    double multiplier = 1.0, translation[3] = { 0.0, 0.0, 0.0 };
    const int mode = this->Integer(0, 2);
    if (mode == 0)
    {
      // |coordinates| <= 65 multiplier < 2^53.
      multiplier = 2.0 * std::floor(this->Uniform(1.0, 4503599627370496.0 / 65.0)) + 1.0;
    }
    else if (mode == 1)
    {
      // One point moved to the origin: |coordinates| <= 130 multiplier < 2^53.
      multiplier = 2.0 * std::floor(this->Uniform(1.0, 4503599627370496.0 / 130.0)) + 1.0;
      const Vec3 origin = chosen[this->Integer(0, count - 1)];
      for (int k = 0; k < dim; ++k)
      {
        translation[k] = -origin[k] * multiplier;
      }
    }
    else
    {
      multiplier = this->Integer(0, 2) == 0 ? 1.0 : 2.0 * this->Integer(0, 1 << 20) + 1.0;
      for (int k = 0; k < dim; ++k)
      {
        translation[k] = this->Integer(-(1 << 30), 1 << 30);
      }
    }
    const double scale = std::ldexp(1.0, this->Integer(-60, 60));
    std::vector<Vec3> points(count, Vec3{ 0.0, 0.0, 0.0 });
    for (int i = 0; i < count; ++i)
    {
      for (int k = 0; k < dim; ++k)
      {
        points[i][k] = (chosen[i][k] * multiplier + translation[k]) * scale; // exact
      }
    }
    return points;
  }

  // Exactly coplanar (collinear) points of arbitrary magnitudes: the plane (line) w = s u + t v
  // (w = s u) with s, t in {-1, 0, 1} on randomly permuted axes (e.g. z = x, z = -y, x = 0),
  // keeping only the points whose w is exact.
  std::vector<Vec3> Coplanar(int count, int dim)
  {
    const int s = this->Integer(-1, 1), t = this->Integer(-1, 1);
    int axes[3] = { 0, 1, 2 };
    std::shuffle(axes, axes + dim, this->Rng);
    std::vector<Vec3> points;
    while (static_cast<int>(points.size()) < count)
    {
      const double u = this->Sign() * this->Magnitude(-8, 8);
      const double v = dim == 3 ? this->Sign() * this->Magnitude(-8, 8) : 0.0;
      double w = 0.0;
      if (dim == 3)
      {
        // s u + t v when exact (one of s, t zero, or a representable sum).
        const double su = s * u, tv = t * v;
        w = su + tv;
        if (w - su != tv || w - tv != su)
        {
          continue;
        }
      }
      else
      {
        w = s * u;
      }
      Vec3 p = { 0.0, 0.0, 0.0 };
      if (dim == 3)
      {
        p[axes[0]] = u;
        p[axes[1]] = v;
        p[axes[2]] = w;
      }
      else
      {
        p[axes[0]] = u;
        p[axes[1]] = w;
      }
      points.push_back(p);
    }
    if (this->Integer(0, 1) == 0)
    {
      points[this->Integer(0, count - 1)] = Vec3{ 0.0, 0.0, 0.0 }; // on every such plane
    }
    return points;
  }

  // Exactly degenerate sets nudged by a tiny amount: a zero coordinate (preferably; the sets
  // above often contain the origin) is replaced by a value 2^-j times the largest coordinate
  // (j in 20..120), so the determinant is about 2^-j times its permanent while the other
  // coordinates fill their 53 bits: this crosses the error bounds of the adaptive stages.
  std::vector<Vec3> TinyNudge(int count, int dim, bool sphere)
  {
    std::vector<Vec3> points = sphere ? this->Cospherical(count, dim) : this->Coplanar(count, dim);
    double extent = 0.0;
    std::vector<std::pair<int, int>> zeros;
    for (int i = 0; i < count; ++i)
    {
      for (int k = 0; k < dim; ++k)
      {
        extent = std::max(extent, std::fabs(points[i][k]));
        if (points[i][k] == 0.0)
        {
          zeros.emplace_back(i, k);
        }
      }
    }
    if (extent == 0.0)
    {
      return points;
    }
    std::pair<int, int> target(this->Integer(0, count - 1), this->Integer(0, dim - 1));
    if (!zeros.empty() && this->Integer(0, 3) != 0)
    {
      target = zeros[this->Integer(0, static_cast<int>(zeros.size()) - 1)];
    }
    double& v = points[target.first][target.second];
    const double tiny = this->Sign() * std::ldexp(extent, -this->Integer(20, 120)) *
      (1.0 + this->Uniform(0.0, 1.0));
    v = v == 0.0 ? tiny : this->Nudge(v + tiny, 1);
    return points;
  }

  // Exactly degenerate sets through the origin plus a point very close to the origin, nearly
  // on the line / plane / circle / sphere. The determinant is then tiny compared with its
  // permanent (down to eps^2 and below) while its terms are not: a line through a and b = k a
  // (k in {-1, 2, -2, 1/2}), a plane through a, b and c = k a or k b, or the cospherical lattice
  // sets moved so that one point is the origin, that point being replaced by t v (t tiny, v on
  // the line / plane or tangent to the circle / sphere), rounded and nudged by a few ulps.
  std::vector<Vec3> NearOrigin(int count, int dim, bool sphere)
  {
    std::vector<Vec3> points;
    Vec3 direction = { 0.0, 0.0, 0.0 };
    if (sphere)
    {
      // Cospherical set with one point at the origin: the set is (q - q0) m for lattice points
      // q, so the center is -q0 m and the tangent plane at the origin is normal to q0.
      static const std::vector<Vec3> sphereLattice = LatticePoints(63, 3);
      static const std::vector<Vec3> circleLattice = LatticePoints(65, 2);
      const std::vector<Vec3>& lattice = dim == 3 ? sphereLattice : circleLattice;
      const double multiplier =
        2.0 * std::floor(this->Uniform(1.0, 4503599627370496.0 / 130.0)) + 1.0;
      const Vec3 q0 = lattice[this->Integer(0, static_cast<int>(lattice.size()) - 1)];
      for (int i = 0; i < count; ++i)
      {
        const Vec3& q = lattice[this->Integer(0, static_cast<int>(lattice.size()) - 1)];
        Vec3 p = { 0.0, 0.0, 0.0 };
        for (int k = 0; k < dim; ++k)
        {
          p[k] = (q[k] - q0[k]) * multiplier; // exact
        }
        points.push_back(p);
      }
      // A tangent direction at the origin: orthogonal to q0.
      if (dim == 2)
      {
        direction = { -q0[1], q0[0], 0.0 };
      }
      else
      {
        const Vec3 r = { this->Normal(), this->Normal(), this->Normal() };
        direction = { q0[1] * r[2] - q0[2] * r[1], q0[2] * r[0] - q0[0] * r[2],
          q0[0] * r[1] - q0[1] * r[0] };
      }
    }
    else
    {
      Vec3 u = { 0.0, 0.0, 0.0 }, v = { 0.0, 0.0, 0.0 };
      for (int k = 0; k < dim; ++k)
      {
        u[k] = this->Sign() * this->Magnitude(-8, 8);
        v[k] = dim == 3 ? this->Sign() * this->Magnitude(-8, 8) : 0.0;
      }
      static const double factors[4] = { -1.0, 2.0, -2.0, 0.5 };
      const double k = factors[this->Integer(0, 3)];
      Vec3 w = { 0.0, 0.0, 0.0 };
      const Vec3& base = (dim == 2 || this->Integer(0, 1) == 0) ? u : v;
      for (int i = 0; i < dim; ++i)
      {
        w[i] = k * base[i]; // exact
      }
      points.push_back(u);
      points.push_back(w);
      if (dim == 3)
      {
        points.push_back(v);
      }
      const double alpha = this->Normal(), beta = dim == 3 ? this->Normal() : 0.0;
      for (int i = 0; i < dim; ++i)
      {
        direction[i] = alpha * u[i] + beta * v[i];
      }
      // The remaining points: exactly on the line / plane when possible (multiples of u).
      while (static_cast<int>(points.size()) < count)
      {
        const double f = factors[this->Integer(0, 3)] * (this->Integer(0, 1) ? 1.0 : 4.0);
        Vec3 p = { 0.0, 0.0, 0.0 };
        for (int i = 0; i < dim; ++i)
        {
          p[i] = f * u[i];
        }
        points.push_back(p);
      }
    }
    // The point near the origin.
    Vec3& p = points[this->Integer(0, count - 1)];
    double norm = 0.0;
    for (int k = 0; k < dim; ++k)
    {
      norm = std::max(norm, std::fabs(direction[k]));
    }
    double extent = 0.0;
    for (const Vec3& q : points)
    {
      for (int k = 0; k < dim; ++k)
      {
        extent = std::max(extent, std::fabs(q[k]));
      }
    }
    if (norm == 0.0 || extent == 0.0)
    {
      return points;
    }
    const double t = std::ldexp(extent / norm, -this->Integer(0, 90)) * this->Uniform(0.5, 1.0);
    for (int k = 0; k < dim; ++k)
    {
      p[k] = this->Nudge(t * direction[k], this->Integer(0, 1) ? 0 : 2);
    }
    std::shuffle(points.begin(), points.end(), this->Rng);
    return points;
  }

  // Duplicated points (exactly zero determinants) among points of mixed magnitudes.
  std::vector<Vec3> Duplicates(int count, int dim)
  {
    std::vector<Vec3> points = this->OnSphere(count, dim);
    const int i = this->Integer(0, count - 1);
    int j = this->Integer(0, count - 2);
    j += j >= i;
    points[j] = points[i];
    if (this->Integer(0, 1) == 0)
    {
      for (int k = 0; k < dim; ++k)
      {
        points[(j + 1) % count][k] = this->Sign() * this->Magnitude(-8, 8);
      }
    }
    return points;
  }

  // Points of a grid with a non-representable spacing (exactly cospherical in reals, not in
  // doubles) or a representable one.
  std::vector<Vec3> Grid(int count, int dim)
  {
    const double spacing = this->Integer(0, 1) ? 0.1 * this->Magnitude(-8, 8)
                                               : std::ldexp(1.0, this->Integer(-40, 40));
    const Vec3 origin = this->Center(dim);
    std::vector<Vec3> points(count, Vec3{ 0.0, 0.0, 0.0 });
    for (Vec3& p : points)
    {
      for (int k = 0; k < dim; ++k)
      {
        p[k] = origin[k] + spacing * this->Integer(-2, 2);
      }
    }
    return points;
  }

  std::vector<Vec3> Family(int family, int count, int dim)
  {
    switch (family)
    {
      case 0:
        return this->OnSphere(count, dim);
      case 1:
        return this->OnPlane(count, dim);
      case 2:
        return this->Cospherical(count, dim);
      case 3:
        return this->Coplanar(count, dim);
      case 4:
        return this->TinyNudge(count, dim, true);
      case 5:
        return this->TinyNudge(count, dim, false);
      case 6:
        return this->Duplicates(count, dim);
      case 7:
        return this->Grid(count, dim);
      case 8:
        return this->NearOrigin(count, dim, false);
      default:
        return this->NearOrigin(count, dim, true);
    }
  }

  std::mt19937_64 Rng;

private:
  static std::vector<Vec3> LatticePoints(int radius, int dim)
  {
    std::vector<Vec3> points;
    for (int x = -radius; x <= radius; ++x)
    {
      for (int y = -radius; y <= radius; ++y)
      {
        if (dim == 2)
        {
          if (x * x + y * y == radius * radius)
          {
            points.push_back(Vec3{ double(x), double(y), 0.0 });
          }
          continue;
        }
        for (int z = -radius; z <= radius; ++z)
        {
          if (x * x + y * y + z * z == radius * radius)
          {
            points.push_back(Vec3{ double(x), double(y), double(z) });
          }
        }
      }
    }
    return points;
  }
};

const char* const FamilyNames[10] = { "rounded onto sphere/circle", "rounded onto plane/line",
  "exactly cospherical/cocircular", "exactly coplanar/collinear", "cospherical + tiny nudge",
  "coplanar + tiny nudge", "duplicated points", "grid", "plane/line through origin + point near it",
  "sphere/circle through origin + point near it" };
constexpr int FamilyCount = 10;

// ---------------------------------------------------------------------------------------------
void Test3D(Generator& gen, int family, int cases)
{
  const std::string name = FamilyNames[family];
  for (int n = 0; n < cases; ++n)
  {
    std::vector<Vec3> p = gen.Family(family, 5, 3);
    const Vec3 &a = p[0], &b = p[1], &c = p[2], &d = p[3], &e = p[4];
    ++Cases;

    // Orient3D.
    const int o = RefOrient3D(a, b, c, d);
    ZeroCases += o == 0;
    CHECK_EQ("Orient3D", name, p, P::Orient3D(a.data(), b.data(), c.data(), d.data()), o);
    CHECK_EQ("Orient3DExact", name, p, P::Orient3DExact(a.data(), b.data(), c.data(), d.data()), o);
    CHECK_EQ("CGAL orientation", name, p, CgalOrient3D(a, b, c, d), o);

    // InSphere.
    const int s = RefInSphere(a, b, c, d, e);
    ZeroCases += s == 0;
    CHECK_EQ("InSphere", name, p, P::InSphere(a.data(), b.data(), c.data(), d.data(), e.data()), s);
    CHECK_EQ("InSphereExact", name, p,
      P::InSphereExact(a.data(), b.data(), c.data(), d.data(), e.data()), s);
    CHECK_EQ("CGAL side_of_oriented_sphere", name, p, CgalInSphere(a, b, c, d, e), s);

    // Static filters, with the bounds of the points' own extent: either undecided (0) or exact.
    {
      double extent = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        double lo = p[0][k], hi = p[0][k];
        for (const Vec3& q : p)
        {
          lo = std::min(lo, q[k]);
          hi = std::max(hi, q[k]);
        }
        extent = std::max(extent, hi - lo);
      }
      const double orientBound = P::Orient3DStaticBound(extent);
      const double sphereBound = P::InSphereStaticBound(extent);
      const int os = P::Orient3DStatic(a.data(), b.data(), c.data(), d.data(), orientBound);
      if (os != 0)
      {
        CHECK_EQ("Orient3DStatic", name, p, os, o);
      }
      CHECK_EQ("Orient3D static", name, p,
        P::Orient3D(a.data(), b.data(), c.data(), d.data(), orientBound), o);
      const int ss =
        P::InSphereStatic(a.data(), b.data(), c.data(), d.data(), e.data(), sphereBound);
      if (ss != 0)
      {
        CHECK_EQ("InSphereStatic", name, p, ss, s);
      }
      CHECK_EQ("InSphere static", name, p,
        P::InSphere(a.data(), b.data(), c.data(), d.data(), e.data(), sphereBound), s);
    }

    // Symbolic perturbation.
    // (The perturbation is defined for distinct points: equal points have equal ranks.)
    const int sos = P::InSphereSoS(a.data(), b.data(), c.data(), d.data(), e.data());
    if (s != 0)
    {
      CHECK_EQ("InSphereSoS == InSphere", name, p, sos, s);
    }
    bool distinct = true;
    for (int i = 0; i < 5; ++i)
    {
      for (int j = i + 1; j < 5; ++j)
      {
        distinct = distinct && p[i] != p[j];
      }
    }
    if (distinct)
    {
      CHECK_EQ("InSphereSoS definition", name, p, sos, RefInSphereSoS(p.data()));
    }
    if (distinct && o != 0)
    {
      CHECK_EQ("InSphereSoS != 0", name, p, sos != 0, 1);
    }
    // Antisymmetry: every exchange of two of the five points negates the perturbed
    // determinant (the perturbation belongs to the points, not to their positions).
    for (int i = 0; i < 5 && distinct; ++i)
    {
      for (int j = i + 1; j < 5; ++j)
      {
        std::vector<Vec3> q = p;
        std::swap(q[i], q[j]);
        CHECK_EQ("InSphereSoS antisymmetry", name, p,
          P::InSphereSoS(q[0].data(), q[1].data(), q[2].data(), q[3].data(), q[4].data()), -sos);
      }
    }
    // Exchanges also negate the unperturbed predicates (a different last point).
    {
      std::vector<Vec3> q = p;
      const int i = gen.Integer(0, 3);
      std::swap(q[i], q[4]);
      CHECK_EQ("InSphereExact exchange", name, p,
        P::InSphereExact(q[0].data(), q[1].data(), q[2].data(), q[3].data(), q[4].data()), -s);
      std::swap(q[4], q[3]);
      const int oq = RefOrient3D(q[0], q[1], q[2], q[3]);
      CHECK_EQ("Orient3DExact permuted", name, q,
        P::Orient3DExact(q[0].data(), q[1].data(), q[2].data(), q[3].data()), oq);
    }
  }
}

void Test2D(Generator& gen, int family, int cases)
{
  const std::string name = FamilyNames[family];
  for (int n = 0; n < cases; ++n)
  {
    std::vector<Vec3> p = gen.Family(family, 4, 2);
    // Half of the cases carry a z coordinate, which the 2D predicates must ignore.
    const double z0 = gen.Integer(0, 1) ? gen.Sign() * gen.Magnitude(-8, 8) : 0.0;
    for (Vec3& v : p)
    {
      v[2] = z0;
    }
    const Vec3 &a = p[0], &b = p[1], &c = p[2], &d = p[3];
    ++Cases;

    const int o = RefOrient2D(a, b, c);
    ZeroCases += o == 0;
    CHECK_EQ("Orient2D", name, p, P::Orient2D(a.data(), b.data(), c.data()), o);
    CHECK_EQ("Orient2DExact", name, p, P::Orient2DExact(a.data(), b.data(), c.data()), o);
    CHECK_EQ("CGAL orientation 2D", name, p, CgalOrient2D(a, b, c), o);

    const int s = RefInCircle(a, b, c, d);
    ZeroCases += s == 0;
    CHECK_EQ("InCircle", name, p, P::InCircle(a.data(), b.data(), c.data(), d.data()), s);
    CHECK_EQ("InCircleExact", name, p, P::InCircleExact(a.data(), b.data(), c.data(), d.data()), s);
    CHECK_EQ("CGAL side_of_oriented_circle", name, p, CgalInCircle(a, b, c, d), s);

    const int sos = P::InCircleSoS(a.data(), b.data(), c.data(), d.data());
    if (s != 0)
    {
      CHECK_EQ("InCircleSoS == InCircle", name, p, sos, s);
    }
    bool distinct = true;
    for (int i = 0; i < 4; ++i)
    {
      for (int j = i + 1; j < 4; ++j)
      {
        distinct = distinct && (p[i][0] != p[j][0] || p[i][1] != p[j][1]);
      }
    }
    if (distinct)
    {
      CHECK_EQ("InCircleSoS definition", name, p, sos, RefInCircleSoS(p.data()));
    }
    if (distinct && o != 0)
    {
      CHECK_EQ("InCircleSoS != 0", name, p, sos != 0, 1);
    }
    for (int i = 0; i < 4 && distinct; ++i)
    {
      for (int j = i + 1; j < 4; ++j)
      {
        std::vector<Vec3> q = p;
        std::swap(q[i], q[j]);
        CHECK_EQ("InCircleSoS antisymmetry", name, p,
          P::InCircleSoS(q[0].data(), q[1].data(), q[2].data(), q[3].data()), -sos);
      }
    }
    {
      std::vector<Vec3> q = p;
      std::swap(q[gen.Integer(0, 2)], q[3]);
      CHECK_EQ("InCircleExact exchange", name, p,
        P::InCircleExact(q[0].data(), q[1].data(), q[2].data(), q[3].data()), -s);
      const int oq = RefOrient2D(q[0], q[1], q[2]);
      CHECK_EQ("Orient2DExact permuted", name, q,
        P::Orient2DExact(q[0].data(), q[1].data(), q[2].data()), oq);
    }

    // The same points in the plane z = z0, seen from a point off the plane: the in-plane
    // circle side of q w.r.t. a, b, c (inside = +1) is InCircleSoS times the orientation.
    if (o != 0 && distinct)
    {
      const Vec3 apex = { gen.Normal(), gen.Normal(), z0 + gen.Sign() * gen.Magnitude(-3, 3) };
      if (apex[2] != z0)
      {
        CHECK_EQ("CoplanarInCircleSoS", name, p,
          P::CoplanarInCircleSoS(a.data(), b.data(), c.data(), apex.data(), d.data()), sos * o);
      }
    }
  }
}

} // namespace

int main(int argc, char** argv)
{
  const int perFamily = argc > 1 ? std::atoi(argv[1]) : 20000;
  const unsigned seed = argc > 2 ? static_cast<unsigned>(std::atoi(argv[2])) : 1u;
  Generator gen(seed);
  const auto start = std::chrono::steady_clock::now();
  // Each case checks one 3D (or 2D) point set with all the predicates and their variants; the
  // 3D cases are weighted more (the 3D kernel relies on them).
  for (int family = 0; family < FamilyCount; ++family)
  {
    const long long before = Cases, zerosBefore = ZeroCases, failuresBefore = Failures;
    Test3D(gen, family, 4 * perFamily);
    Test2D(gen, family, 3 * perFamily);
    std::cout << "family " << family << " (" << FamilyNames[family] << "): " << Cases - before
              << " point sets, " << ZeroCases - zerosBefore << " exactly zero determinants, "
              << Failures - failuresBefore << " failures" << std::endl;
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << Cases << " point sets, " << Checks << " checks, " << ZeroCases
            << " exactly zero determinants, " << Failures << " failures (" << seconds << " s)"
            << std::endl;
  for (const auto& failure : FailuresByCheck)
  {
    std::cout << "  " << failure.second << " failures of " << failure.first << std::endl;
  }
  return Failures == 0 ? 0 : 1;
}
