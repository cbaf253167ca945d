// Standalone test of the exact predicates of the private kernel (Filters/Kernel/pcsPredicates.h),
// compiled together with Filters/Kernel/pcsPredicates.cxx (no VTK).
//
// Every expected sign comes from an independent evaluation: the determinants written in the
// header's conventions are evaluated with exact rationals (CGAL::Exact_rational, GMP), and the
// signs are also compared with CGAL's exact-predicate kernel (Epick). The symbolic perturbation
// is checked against its definition in the header (the lifted coordinate of each point is
// raised by a positive infinitesimal that is larger for lexicographically larger points): the
// perturbed 5x5 (4x4 in 2D) determinant is linear in the lifted column, so its sign is that of
// the first non-zero cofactor of the lifted column, in decreasing lexicographic order.
//
// The inputs are built to be hard: points rounded onto a plane / sphere / line / circle and then
// moved by a few units in the last place, exactly coplanar / cospherical integer points, a
// large offset with a tiny extent. The test also checks that such inputs defeat a plain
// floating-point evaluation (otherwise it would not exercise the exact arithmetic).
#include "pcsKernelTest.h"
#include "pcsPredicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <vector>

namespace
{
namespace P = pcs::predicates;
using Rational = CGAL::Exact_rational;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vec3 = std::array<double, 3>;

using pcstest::Checks;
using pcstest::Failures;

std::ostream& operator<<(std::ostream& os, const Vec3& p)
{
  os.precision(17);
  return os << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
}

// ---------------------------------------------------------------------------------------------
// Exact reference: sign of the determinant of a small rational matrix (Gaussian elimination).
template <int N>
int DeterminantSign(std::array<std::array<Rational, N>, N> m)
{
  int sign = 1;
  for (int col = 0; col < N; ++col)
  {
    int pivot = -1;
    for (int row = col; row < N; ++row)
    {
      if (CGAL::sign(m[row][col]) != CGAL::ZERO)
      {
        pivot = row;
        break;
      }
    }
    if (pivot < 0)
    {
      return 0;
    }
    if (pivot != col)
    {
      std::swap(m[pivot], m[col]);
      sign = -sign;
    }
    sign *= CGAL::sign(m[col][col]) == CGAL::POSITIVE ? 1 : -1;
    for (int row = col + 1; row < N; ++row)
    {
      if (CGAL::sign(m[row][col]) == CGAL::ZERO)
      {
        continue;
      }
      const Rational factor = m[row][col] / m[col][col];
      for (int k = col; k < N; ++k)
      {
        m[row][k] -= factor * m[col][k];
      }
    }
  }
  return sign;
}

// The header's Orient3D: sign of det[a-d; b-d; c-d].
int RefOrient3D(const double* a, const double* b, const double* c, const double* d)
{
  std::array<std::array<Rational, 3>, 3> m;
  const double* rows[3] = { a, b, c };
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      m[i][j] = Rational(rows[i][j]) - Rational(d[j]);
    }
  }
  return DeterminantSign<3>(m);
}

// The header's Orient2D: sign of det[a-c; b-c].
int RefOrient2D(const double* a, const double* b, const double* c)
{
  std::array<std::array<Rational, 2>, 2> m;
  const double* rows[2] = { a, b };
  for (int i = 0; i < 2; ++i)
  {
    for (int j = 0; j < 2; ++j)
    {
      m[i][j] = Rational(rows[i][j]) - Rational(c[j]);
    }
  }
  return DeterminantSign<2>(m);
}

// Lifted matrix of `count` points in dimension `dim`: rows (coordinates, |p|^2 + lift[i], 1).
// The insphere (incircle) predicate is the sign of its determinant.
template <int N>
std::array<std::array<Rational, N>, N> LiftedMatrix(const double* const* p)
{
  constexpr int dim = N - 2;
  std::array<std::array<Rational, N>, N> m;
  for (int i = 0; i < N; ++i)
  {
    Rational lift(0);
    for (int j = 0; j < dim; ++j)
    {
      m[i][j] = Rational(p[i][j]);
      lift += m[i][j] * m[i][j];
    }
    m[i][dim] = lift;
    m[i][dim + 1] = Rational(1);
  }
  return m;
}

int RefInSphere(const double* a, const double* b, const double* c, const double* d, const double* e)
{
  const double* p[5] = { a, b, c, d, e };
  return DeterminantSign<5>(LiftedMatrix<5>(p));
}

int RefInCircle(const double* a, const double* b, const double* c, const double* d)
{
  const double* p[4] = { a, b, c, d };
  return DeterminantSign<4>(LiftedMatrix<4>(p));
}

bool LexLess(const double* a, const double* b, int dim)
{
  return std::lexicographical_compare(a, a + dim, b, b + dim);
}

// Perturbed lifted determinant: the lift of point i is raised by delta_i > 0, with
// delta_i >> delta_j whenever point i is lexicographically larger than point j. The
// determinant is linear in the lifted column, so the perturbed sign is the sign of the
// unperturbed determinant, or else that of the first non-zero cofactor of the lifted column in
// decreasing lexicographic order.
template <int N>
int RefPerturbed(const double* const* p)
{
  constexpr int dim = N - 2;
  const auto m = LiftedMatrix<N>(p);
  const int unperturbed = DeterminantSign<N>(m);
  if (unperturbed != 0)
  {
    return unperturbed;
  }
  std::array<int, N> order;
  for (int i = 0; i < N; ++i)
  {
    order[i] = i;
  }
  std::sort(order.begin(), order.end(),
    [p](int i, int j) { return LexLess(p[j], p[i], dim); }); // decreasing
  for (int i : order)
  {
    std::array<std::array<Rational, N - 1>, N - 1> minor;
    for (int r = 0, mr = 0; r < N; ++r)
    {
      if (r == i)
      {
        continue;
      }
      for (int c = 0, mc = 0; c < N; ++c)
      {
        if (c != dim)
        {
          minor[mr][mc++] = m[r][c];
        }
      }
      ++mr;
    }
    const int s = DeterminantSign<N - 1>(minor);
    if (s != 0)
    {
      return ((i + dim) % 2 == 0) ? s : -s; // cofactor sign (-1)^(i + dim)
    }
  }
  return 0;
}

int RefInSphereSoS(
  const double* a, const double* b, const double* c, const double* d, const double* e)
{
  const double* p[5] = { a, b, c, d, e };
  return RefPerturbed<5>(p);
}

int RefInCircleSoS(const double* a, const double* b, const double* c, const double* d)
{
  const double* p[4] = { a, b, c, d };
  return RefPerturbed<4>(p);
}

// CGAL's signs, in CGAL's conventions (see the conversions where they are used).
int CGALOrientation(const double* a, const double* b, const double* c, const double* d)
{
  return static_cast<int>(CGAL::orientation(Epick::Point_3(a[0], a[1], a[2]),
    Epick::Point_3(b[0], b[1], b[2]), Epick::Point_3(c[0], c[1], c[2]),
    Epick::Point_3(d[0], d[1], d[2])));
}

int CGALSideOfOrientedSphere(
  const double* a, const double* b, const double* c, const double* d, const double* e)
{
  return static_cast<int>(CGAL::side_of_oriented_sphere(Epick::Point_3(a[0], a[1], a[2]),
    Epick::Point_3(b[0], b[1], b[2]), Epick::Point_3(c[0], c[1], c[2]),
    Epick::Point_3(d[0], d[1], d[2]), Epick::Point_3(e[0], e[1], e[2])));
}

int CGALOrientation2(const double* a, const double* b, const double* c)
{
  return static_cast<int>(CGAL::orientation(
    Epick::Point_2(a[0], a[1]), Epick::Point_2(b[0], b[1]), Epick::Point_2(c[0], c[1])));
}

int CGALSideOfOrientedCircle(const double* a, const double* b, const double* c, const double* d)
{
  return static_cast<int>(CGAL::side_of_oriented_circle(Epick::Point_2(a[0], a[1]),
    Epick::Point_2(b[0], b[1]), Epick::Point_2(c[0], c[1]), Epick::Point_2(d[0], d[1])));
}

// Plain double evaluations, only to show that the inputs defeat them.
int NaiveOrient3D(const double* a, const double* b, const double* c, const double* d)
{
  const double u[3] = { a[0] - d[0], a[1] - d[1], a[2] - d[2] };
  const double v[3] = { b[0] - d[0], b[1] - d[1], b[2] - d[2] };
  const double w[3] = { c[0] - d[0], c[1] - d[1], c[2] - d[2] };
  const double det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
    u[2] * (v[0] * w[1] - v[1] * w[0]);
  return (det > 0) - (det < 0);
}

int NaiveOrient2D(const double* a, const double* b, const double* c)
{
  const double det = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]);
  return (det > 0) - (det < 0);
}

double Ulps(double x, int k)
{
  for (; k > 0; --k)
  {
    x = std::nextafter(x, HUGE_VAL);
  }
  for (; k < 0; ++k)
  {
    x = std::nextafter(x, -HUGE_VAL);
  }
  return x;
}

// Scales and offsets of the random configurations: unit, tiny, huge, large offset + tiny extent.
struct Frame
{
  double Scale;
  double Offset;
};
const Frame Frames[] = { { 1.0, 0.0 }, { 1e-7, 0.0 }, { 1e9, 0.0 }, { 1e-3, 1e6 },
  { 1.0, -1024.0 } };

// ---------------------------------------------------------------------------------------------
void TestConventions()
{
  const double o[3] = { 0, 0, 0 }, ex[3] = { 1, 0, 0 }, ey[3] = { 0, 1, 0 }, ez[3] = { 0, 0, 1 };
  const double below[3] = { 0.25, 0.25, -1 }, above[3] = { 0.25, 0.25, 1 };
  // det[a-d; b-d; c-d] with (o, ex, ey, ez): rows (0,0,-1), (1,0,-1), (0,1,-1): determinant -1.
  EXPECT(P::Orient3D(o, ex, ey, ez) == -1, "det[a-d;b-d;c-d] of (o, ex, ey, ez) is -1");
  EXPECT(P::Orient3D(ex, o, ey, ez) == 1, "odd permutation flips the sign");
  // "d below the plane of a,b,c seen with a,b,c counter-clockwise" (seen from +z).
  EXPECT(P::Orient3D(o, ex, ey, below) == 1, "point below a counter-clockwise triangle");
  EXPECT(P::Orient3D(o, ex, ey, above) == -1, "point above a counter-clockwise triangle");
  EXPECT(P::Orient3D(o, ex, ey, o) == 0, "repeated point");
  const double inPlane[3] = { 7, -3, 0 };
  EXPECT(P::Orient3D(o, ex, ey, inPlane) == 0, "coplanar");

  // The regular-ish tetrahedron on the unit sphere, ordered so that Orient3D > 0.
  const double a[3] = { 1, 0, 0 }, b[3] = { 0, 1, 0 }, c[3] = { 0, 0, 1 }, d[3] = { 0, 0, -1 };
  const double* t[4] = { a, b, c, d };
  if (RefOrient3D(t[0], t[1], t[2], t[3]) < 0)
  {
    std::swap(t[0], t[1]);
  }
  EXPECT(P::Orient3D(t[0], t[1], t[2], t[3]) == 1, "positively oriented tetrahedron");
  const double centre[3] = { 0, 0, 0 }, outside[3] = { 2, 0, 0 }, onSphere[3] = { -1, 0, 0 };
  const double nearInside[3] = { 0, -0.999999999999, 0 };
  EXPECT(P::InSphere(t[0], t[1], t[2], t[3], centre) == 1, "centre is inside (+1)");
  EXPECT(P::InSphere(t[0], t[1], t[2], t[3], nearInside) == 1, "just inside");
  EXPECT(P::InSphere(t[0], t[1], t[2], t[3], outside) == -1, "outside is -1");
  EXPECT(P::InSphere(t[0], t[1], t[2], t[3], onSphere) == 0, "on the sphere is 0");
  EXPECT(P::InSphere(t[1], t[0], t[2], t[3], centre) == -1, "sign flips with the orientation");
  EXPECT(P::InSphereSoS(t[0], t[1], t[2], t[3], centre) == 1, "SoS agrees when not cospherical");

  // 2D: counter-clockwise is positive, inside the circle of a counter-clockwise triangle too.
  const double p0[2] = { 0, 0 }, p1[2] = { 1, 0 }, p2[2] = { 0, 1 };
  EXPECT(P::Orient2D(p0, p1, p2) == 1, "counter-clockwise");
  EXPECT(P::Orient2D(p1, p0, p2) == -1, "clockwise");
  const double q[2] = { 2, -1 };
  EXPECT(P::Orient2D(p1, p2, q) == 0, "collinear (x + y = 1)");
  const double u0[2] = { 1, 0 }, u1[2] = { 0, 1 }, u2[2] = { -1, 0 };
  const double c2[2] = { 0, 0 }, out2[2] = { 0, 1.5 }, on2[2] = { 0, -1 };
  EXPECT(P::InCircle(u0, u1, u2, c2) == 1, "centre inside (+1)");
  EXPECT(P::InCircle(u0, u1, u2, out2) == -1, "outside (-1)");
  EXPECT(P::InCircle(u0, u1, u2, on2) == 0, "cocircular (0)");
  EXPECT(P::InCircle(u1, u0, u2, c2) == -1, "clockwise triangle flips the sign");

  // Lexicographic comparison.
  const double l0[3] = { 1, 2, 3 }, l1[3] = { 1, 2, 4 }, l2[3] = { 0, 9, 9 };
  EXPECT(P::CompareLexicographic(l0, l1, 3) == -1, "z decides");
  EXPECT(P::CompareLexicographic(l0, l1, 2) == 0, "2D ignores z");
  EXPECT(P::CompareLexicographic(l0, l2, 3) == 1, "x decides");
  EXPECT(P::CompareLexicographic(l1, l1, 3) == 0, "equal");
}

// ---------------------------------------------------------------------------------------------
// Near-coplanar quadruples: d is rounded onto the plane of a, b, c and moved by a few ulps.
void TestOrient3DNearDegenerate(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0), st(-1.0, 2.0);
  std::uniform_int_distribution<int> ulps(-2, 2), axis(0, 2);
  long long zeros = 0, naiveWrong = 0, cases = 0;
  for (const Frame& frame : Frames)
  {
    for (int n = 0; n < 4000; ++n)
    {
      Vec3 a, b, c, d;
      for (int i = 0; i < 3; ++i)
      {
        a[i] = frame.Offset + frame.Scale * u(rng);
        b[i] = frame.Offset + frame.Scale * u(rng);
        c[i] = frame.Offset + frame.Scale * u(rng);
      }
      const double s = st(rng), t = st(rng);
      for (int i = 0; i < 3; ++i)
      {
        d[i] = a[i] + s * (b[i] - a[i]) + t * (c[i] - a[i]);
      }
      if (n % 2)
      {
        const int i = axis(rng);
        d[i] = Ulps(d[i], ulps(rng));
      }
      const int expected = RefOrient3D(a.data(), b.data(), c.data(), d.data());
      const int ours = P::Orient3D(a.data(), b.data(), c.data(), d.data());
      EXPECT(ours == expected, "Orient3D" << a << b << c << d << " = " << ours << ", exact "
                                          << expected);
      // CGAL::orientation is the sign of det[b-a; c-a; d-a] = -det[a-d; b-d; c-d].
      EXPECT(ours == -CGALOrientation(a.data(), b.data(), c.data(), d.data()),
        "Orient3D vs CGAL::orientation" << a << b << c << d);
      EXPECT(P::Orient3D(b.data(), a.data(), c.data(), d.data()) == -ours, "antisymmetry");
      EXPECT(P::Orient3D(b.data(), c.data(), d.data(), a.data()) == -ours,
        "cyclic shift of four points is an odd permutation");
      zeros += expected == 0;
      naiveWrong += NaiveOrient3D(a.data(), b.data(), c.data(), d.data()) != expected;
      ++cases;
    }
  }
  // Exactly coplanar integer configurations (d = a + i (b - a) + j (c - a)).
  std::uniform_int_distribution<int> small(-1000, 1000), coefficient(-5, 5);
  for (int n = 0; n < 2000; ++n)
  {
    Vec3 a, b, c, d;
    const int i = coefficient(rng), j = coefficient(rng);
    for (int k = 0; k < 3; ++k)
    {
      a[k] = small(rng);
      b[k] = small(rng);
      c[k] = small(rng);
      d[k] = a[k] + i * (b[k] - a[k]) + j * (c[k] - a[k]);
    }
    EXPECT(P::Orient3D(a.data(), b.data(), c.data(), d.data()) == 0,
      "exactly coplanar" << a << b << c << d);
    ++cases;
  }
  std::cout << "Orient3D: " << cases << " near-degenerate cases, " << zeros
            << " exactly coplanar after rounding, plain double evaluation wrong in "
            << naiveWrong << std::endl;
  EXPECT(naiveWrong > 100, "the near-coplanar cases defeat a plain double evaluation");
}

// A unit vector of uniformly random direction.
Vec3 RandomDirection(std::mt19937_64& rng)
{
  std::normal_distribution<double> g;
  Vec3 v;
  double r;
  do
  {
    v = { g(rng), g(rng), g(rng) };
    r = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  } while (r < 1e-3);
  return { v[0] / r, v[1] / r, v[2] / r };
}

// Near-cospherical quintuples: all five points rounded onto one sphere, e moved by a few ulps.
void TestInSphereNearDegenerate(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0), radius(0.1, 1.0);
  std::uniform_int_distribution<int> ulps(-2, 2), axis(0, 2);
  long long naiveWrong = 0, cases = 0;
  for (const Frame& frame : Frames)
  {
    for (int n = 0; n < 2000; ++n)
    {
      const Vec3 centre = { frame.Offset + frame.Scale * u(rng),
        frame.Offset + frame.Scale * u(rng), frame.Offset + frame.Scale * u(rng) };
      const double r = frame.Scale * radius(rng);
      Vec3 p[5];
      for (Vec3& q : p)
      {
        const Vec3 v = RandomDirection(rng);
        q = { centre[0] + r * v[0], centre[1] + r * v[1], centre[2] + r * v[2] };
      }
      if (n % 2)
      {
        const int i = axis(rng);
        p[4][i] = Ulps(p[4][i], ulps(rng));
      }
      const double *a = p[0].data(), *b = p[1].data(), *c = p[2].data(), *d = p[3].data(),
                   *e = p[4].data();
      if (RefOrient3D(a, b, c, d) == 0)
      {
        continue;
      }
      const int expected = RefInSphere(a, b, c, d, e);
      const int ours = P::InSphere(a, b, c, d, e);
      EXPECT(ours == expected,
        "InSphere" << p[0] << p[1] << p[2] << p[3] << p[4] << " = " << ours << ", exact "
                   << expected);
      // CGAL: ON_POSITIVE_SIDE is the inside for a CGAL-positive (a,b,c,d), and CGAL-positive
      // is Orient3D < 0: the two signs are opposite.
      EXPECT(ours == -CGALSideOfOrientedSphere(a, b, c, d, e), "InSphere vs CGAL" << p[4]);
      EXPECT(P::InSphere(b, a, c, d, e) == -ours, "InSphere antisymmetry");
      // A plain double evaluation of the same formula, with differences to e.
      {
        double m[4][4];
        for (int i = 0; i < 4; ++i)
        {
          for (int j = 0; j < 3; ++j)
          {
            m[i][j] = p[i][j] - p[4][j];
          }
          m[i][3] = m[i][0] * m[i][0] + m[i][1] * m[i][1] + m[i][2] * m[i][2];
        }
        // Laplace expansion along the last column.
        double det = 0.0;
        for (int i = 0; i < 4; ++i)
        {
          int r[3], k = 0;
          for (int j = 0; j < 4; ++j)
          {
            if (j != i)
            {
              r[k++] = j;
            }
          }
          const double minor = m[r[0]][0] * (m[r[1]][1] * m[r[2]][2] - m[r[1]][2] * m[r[2]][1]) -
            m[r[0]][1] * (m[r[1]][0] * m[r[2]][2] - m[r[1]][2] * m[r[2]][0]) +
            m[r[0]][2] * (m[r[1]][0] * m[r[2]][1] - m[r[1]][1] * m[r[2]][0]);
          det += ((i + 3) % 2 == 0 ? 1 : -1) * m[i][3] * minor;
        }
        // The 4x4 determinant of differences equals the 5x5 lifted determinant.
        naiveWrong += ((det > 0) - (det < 0)) != expected;
      }
      ++cases;
    }
  }
  // Exactly cospherical integer points: x^2 + y^2 + z^2 = 2 * 3^2 * 5^2 = 450 has many
  // solutions; shifted by a random integer centre.
  std::vector<Vec3> sphere;
  for (int x = -21; x <= 21; ++x)
    for (int y = -21; y <= 21; ++y)
      for (int z = -21; z <= 21; ++z)
      {
        if (x * x + y * y + z * z == 450)
        {
          sphere.push_back({ double(x), double(y), double(z) });
        }
      }
  std::uniform_int_distribution<size_t> pick(0, sphere.size() - 1);
  std::uniform_int_distribution<int> shift(-100000, 100000);
  int cospherical = 0;
  for (int n = 0; n < 2000; ++n)
  {
    const Vec3 centre = { double(shift(rng)), double(shift(rng)), double(shift(rng)) };
    Vec3 p[5];
    for (Vec3& q : p)
    {
      const Vec3& s = sphere[pick(rng)];
      q = { centre[0] + s[0], centre[1] + s[1], centre[2] + s[2] };
    }
    if (RefOrient3D(p[0].data(), p[1].data(), p[2].data(), p[3].data()) == 0)
    {
      continue;
    }
    EXPECT(P::InSphere(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data()) == 0,
      "exactly cospherical" << p[0] << p[1] << p[2] << p[3] << p[4]);
    ++cospherical;
  }
  std::cout << "InSphere: " << cases << " near-cospherical cases (plain double evaluation wrong in "
            << naiveWrong << "), " << cospherical << " exactly cospherical cases ("
            << sphere.size() << " integer points on the sphere)" << std::endl;
  EXPECT(naiveWrong > 100, "the near-cospherical cases defeat a plain double evaluation");
  EXPECT(cospherical > 1000, "enough exactly cospherical cases");
}

// Near-collinear and near-cocircular 2D cases (only x, y are read by the 2D predicates; the
// third coordinate is set to garbage to check that).
void TestPredicates2DNearDegenerate(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0), st(-1.0, 2.0), angle(0.0, 6.283185307179586);
  std::uniform_int_distribution<int> ulps(-2, 2), axis(0, 1);
  long long naiveWrong = 0, cases = 0;
  for (const Frame& frame : Frames)
  {
    for (int n = 0; n < 4000; ++n)
    {
      Vec3 a, b, c;
      for (int i = 0; i < 2; ++i)
      {
        a[i] = frame.Offset + frame.Scale * u(rng);
        b[i] = frame.Offset + frame.Scale * u(rng);
      }
      const double t = st(rng);
      c[0] = a[0] + t * (b[0] - a[0]);
      c[1] = a[1] + t * (b[1] - a[1]);
      if (n % 2)
      {
        const int i = axis(rng);
        c[i] = Ulps(c[i], ulps(rng));
      }
      a[2] = std::nan("");
      b[2] = 1e300;
      c[2] = -1e300;
      const int expected = RefOrient2D(a.data(), b.data(), c.data());
      const int ours = P::Orient2D(a.data(), b.data(), c.data());
      EXPECT(ours == expected, "Orient2D" << a << b << c << " = " << ours);
      EXPECT(ours == CGALOrientation2(a.data(), b.data(), c.data()), "Orient2D vs CGAL");
      naiveWrong += NaiveOrient2D(a.data(), b.data(), c.data()) != expected;
      ++cases;
    }
    for (int n = 0; n < 4000; ++n)
    {
      const double cx = frame.Offset + frame.Scale * u(rng),
                   cy = frame.Offset + frame.Scale * u(rng);
      const double r = frame.Scale * (0.1 + std::fabs(u(rng)));
      Vec3 p[4];
      for (Vec3& q : p)
      {
        const double phi = angle(rng);
        q = { cx + r * std::cos(phi), cy + r * std::sin(phi), 0.0 };
      }
      if (n % 2)
      {
        const int i = axis(rng);
        p[3][i] = Ulps(p[3][i], ulps(rng));
      }
      if (RefOrient2D(p[0].data(), p[1].data(), p[2].data()) == 0)
      {
        continue;
      }
      const int expected = RefInCircle(p[0].data(), p[1].data(), p[2].data(), p[3].data());
      const int ours = P::InCircle(p[0].data(), p[1].data(), p[2].data(), p[3].data());
      EXPECT(ours == expected, "InCircle" << p[0] << p[1] << p[2] << p[3] << " = " << ours);
      // CGAL: ON_POSITIVE_SIDE is the inside for a counter-clockwise triangle, as here.
      EXPECT(ours == CGALSideOfOrientedCircle(p[0].data(), p[1].data(), p[2].data(), p[3].data()),
        "InCircle vs CGAL");
      ++cases;
    }
  }
  // Exactly cocircular integer points: x^2 + y^2 = 5^4 = 625 (12 + 4 lattice points).
  std::vector<Vec3> circle;
  for (int x = -25; x <= 25; ++x)
    for (int y = -25; y <= 25; ++y)
    {
      if (x * x + y * y == 625)
      {
        circle.push_back({ double(x), double(y), 0.0 });
      }
    }
  std::uniform_int_distribution<size_t> pick(0, circle.size() - 1);
  for (int n = 0; n < 2000; ++n)
  {
    const double dx = std::ldexp(1.0, 20) + n, dy = -std::ldexp(1.0, 21) + 3 * n;
    Vec3 p[4];
    for (Vec3& q : p)
    {
      const Vec3& s = circle[pick(rng)];
      q = { s[0] + dx, s[1] + dy, 0.0 };
    }
    if (RefOrient2D(p[0].data(), p[1].data(), p[2].data()) == 0)
    {
      continue;
    }
    EXPECT(P::InCircle(p[0].data(), p[1].data(), p[2].data(), p[3].data()) == 0,
      "exactly cocircular");
    ++cases;
  }
  std::cout << "Orient2D / InCircle: " << cases << " near-degenerate cases, plain Orient2D wrong in "
            << naiveWrong << std::endl;
  EXPECT(naiveWrong > 100, "the near-collinear cases defeat a plain double evaluation");
}

// ---------------------------------------------------------------------------------------------
// Symbolic perturbation on grids, where cospherical (cocircular) configurations abound.
void TestSoS(std::mt19937_64& rng)
{
  // Points of a 3 x 3 x 3 grid, with a large offset on x for half of the runs (the
  // lexicographic order and the exact signs must not care).
  std::vector<Vec3> grid;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
      {
        grid.push_back({ double(i), double(j), double(k) });
      }
  std::uniform_int_distribution<size_t> pick(0, grid.size() - 1);
  long long cospherical = 0, cases = 0;
  for (int n = 0; n < 30000; ++n)
  {
    size_t id[5];
    for (int i = 0; i < 5; ++i)
    {
      bool repeated;
      do
      {
        id[i] = pick(rng);
        repeated = std::find(id, id + i, id[i]) != id + i;
      } while (repeated);
    }
    Vec3 p[5];
    const double offset = (n % 2) ? 1e6 : 0.0;
    for (int i = 0; i < 5; ++i)
    {
      p[i] = grid[id[i]];
      p[i][0] += offset;
      p[i][1] -= offset;
    }
    const double *a = p[0].data(), *b = p[1].data(), *c = p[2].data(), *d = p[3].data(),
                 *e = p[4].data();
    if (RefOrient3D(a, b, c, d) == 0)
    {
      continue;
    }
    ++cases;
    const int plain = P::InSphere(a, b, c, d, e);
    const int s = P::InSphereSoS(a, b, c, d, e);
    cospherical += plain == 0;
    EXPECT(s != 0, "InSphereSoS is 0 for distinct points" << p[0] << p[1] << p[2] << p[3] << p[4]);
    EXPECT(plain == 0 || s == plain, "InSphereSoS disagrees with a non-zero InSphere");
    EXPECT(s == RefInSphereSoS(a, b, c, d, e),
      "InSphereSoS differs from the lexicographic perturbation" << p[0] << p[1] << p[2] << p[3]
                                                                << p[4]);
    // Antisymmetric under every transposition of two of the first four points.
    EXPECT(P::InSphereSoS(b, a, c, d, e) == -s, "swap a b");
    EXPECT(P::InSphereSoS(c, b, a, d, e) == -s, "swap a c");
    EXPECT(P::InSphereSoS(d, b, c, a, e) == -s, "swap a d");
    EXPECT(P::InSphereSoS(a, c, b, d, e) == -s, "swap b c");
    EXPECT(P::InSphereSoS(a, d, c, b, e) == -s, "swap b d");
    EXPECT(P::InSphereSoS(a, b, d, c, e) == -s, "swap c d");
    // The perturbed sphere is one geometric object: with e swapped into the sphere points the
    // perturbed 5x5 determinant changes sign (a transposition of two rows).
    if (RefOrient3D(a, b, c, e) != 0)
    {
      EXPECT(P::InSphereSoS(a, b, c, e, d) == -s, "swap d e");
    }
  }
  std::cout << "InSphereSoS: " << cases << " grid cases, " << cospherical
            << " of them cospherical" << std::endl;
  EXPECT(cospherical > 3000, "enough cospherical grid cases");

  // 2D: a 4 x 4 grid.
  std::vector<Vec3> grid2;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
    {
      grid2.push_back({ double(i), double(j), 0.0 });
    }
  std::uniform_int_distribution<size_t> pick2(0, grid2.size() - 1);
  long long cocircular = 0, cases2 = 0;
  for (int n = 0; n < 20000; ++n)
  {
    size_t id[4];
    for (int i = 0; i < 4; ++i)
    {
      bool repeated;
      do
      {
        id[i] = pick2(rng);
        repeated = std::find(id, id + i, id[i]) != id + i;
      } while (repeated);
    }
    Vec3 p[4];
    for (int i = 0; i < 4; ++i)
    {
      p[i] = grid2[id[i]];
      p[i][1] += (n % 2) ? 4096.0 : 0.0;
    }
    const double *a = p[0].data(), *b = p[1].data(), *c = p[2].data(), *d = p[3].data();
    if (RefOrient2D(a, b, c) == 0)
    {
      continue;
    }
    ++cases2;
    const int plain = P::InCircle(a, b, c, d);
    const int s = P::InCircleSoS(a, b, c, d);
    cocircular += plain == 0;
    EXPECT(s != 0, "InCircleSoS is 0 for distinct points");
    EXPECT(plain == 0 || s == plain, "InCircleSoS disagrees with a non-zero InCircle");
    EXPECT(s == RefInCircleSoS(a, b, c, d),
      "InCircleSoS differs from the lexicographic perturbation" << p[0] << p[1] << p[2] << p[3]);
    EXPECT(P::InCircleSoS(b, a, c, d) == -s, "swap a b");
    EXPECT(P::InCircleSoS(a, c, b, d) == -s, "swap b c");
    EXPECT(P::InCircleSoS(c, b, a, d) == -s, "swap a c");
    if (RefOrient2D(a, b, d) != 0)
    {
      EXPECT(P::InCircleSoS(a, b, d, c) == -s, "swap c d");
    }
  }
  std::cout << "InCircleSoS: " << cases2 << " grid cases, " << cocircular << " of them cocircular"
            << std::endl;
  EXPECT(cocircular > 1000, "enough cocircular grid cases");
}

// CoplanarInCircleSoS: +1 inside, -1 outside the (perturbed) circumcircle of a, b, c in their
// plane, whatever the order of a, b, c and the side of the reference point d.
void TestCoplanarInCircle(std::mt19937_64& rng)
{
  // Two planes: z = 0 (where the answer must be the 2D one) and the tilted plane z = x + 2y.
  for (int tilted = 0; tilted < 2; ++tilted)
  {
    std::vector<Vec3> plane;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
      {
        plane.push_back({ double(i), double(j), tilted ? double(i + 2 * j) : 0.0 });
      }
    std::uniform_int_distribution<size_t> pick(0, plane.size() - 1);
    long long cocircular = 0, cases = 0;
    for (int n = 0; n < 10000; ++n)
    {
      size_t id[4];
      for (int i = 0; i < 4; ++i)
      {
        bool repeated;
        do
        {
          id[i] = pick(rng);
          repeated = std::find(id, id + i, id[i]) != id + i;
        } while (repeated);
      }
      const double *a = plane[id[0]].data(), *b = plane[id[1]].data(), *c = plane[id[2]].data(),
                   *q = plane[id[3]].data();
      if (RefOrient2D(a, b, c) == 0) // collinear (the plane projects one-to-one onto x-y)
      {
        continue;
      }
      ++cases;
      // Reference points on both sides of the plane (normal (0,0,1) or (1,2,-1)).
      const double up[3] = { 1.5, 1.5, tilted ? 1.5 + 3.0 - 2.0 : 2.0 };
      const double down[3] = { 1.5, 1.5, tilted ? 1.5 + 3.0 + 2.0 : -2.0 };
      const int s = P::CoplanarInCircleSoS(a, b, c, up, q);
      EXPECT(s == 1 || s == -1, "CoplanarInCircleSoS must be +1 or -1");
      EXPECT(P::CoplanarInCircleSoS(a, b, c, down, q) == s, "independent of the side of d");
      EXPECT(P::CoplanarInCircleSoS(b, a, c, up, q) == s, "independent of the order of a b c");
      EXPECT(P::CoplanarInCircleSoS(c, a, b, down, q) == s, "independent of the order of a b c");
      // Not cocircular: the sphere through a, b, c, d cuts the plane along the circumcircle,
      // so the exact insphere side (for a positively oriented a, b, c, d) is the answer.
      const int sphere = RefInSphere(a, b, c, up, q) * RefOrient3D(a, b, c, up);
      if (sphere != 0)
      {
        EXPECT(s == sphere, "CoplanarInCircleSoS inside/outside");
      }
      else
      {
        ++cocircular;
      }
      if (!tilted)
      {
        // In the plane z = 0 the 3D lexicographic order is the 2D one and the lifted
        // coordinates are the 2D ones: the perturbed answer is the 2D perturbed answer.
        EXPECT(s == RefInCircleSoS(a, b, c, q) * RefOrient2D(a, b, c),
          "CoplanarInCircleSoS in z = 0 differs from the perturbed 2D incircle");
      }
    }
    std::cout << "CoplanarInCircleSoS (" << (tilted ? "tilted plane" : "z = 0") << "): " << cases
              << " cases, " << cocircular << " cocircular" << std::endl;
    EXPECT(cocircular > (tilted ? 100 : 500), "enough cocircular cases");
  }
}
} // namespace

int main()
{
  std::mt19937_64 rng(20261122);
  TestConventions();
  TestOrient3DNearDegenerate(rng);
  TestInSphereNearDegenerate(rng);
  TestPredicates2DNearDegenerate(rng);
  TestSoS(rng);
  TestCoplanarInCircle(rng);
  std::cout << Checks << " checks, " << Failures << " failures" << std::endl;
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
