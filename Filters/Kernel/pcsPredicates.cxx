// Exact fallback of the predicates and their symbolic perturbation. See pcsPredicates.h.
//
// The inline filters of pcsPredicates.h call the *Exact functions below when the double
// evaluation cannot decide. Each of them is adaptive, after Shewchuk ("Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997), with three stages.
// The determinant D is a polynomial of degree n in the coordinate differences with the last
// point, each computed with an error-free TwoSum as head + tail (head = fl(difference)).
//
//   0. When every tail is zero (the differences are exact: the usual case for neighbouring
//      points) and the differences are integer multiples of one power of two spanning at most
//      24 bits (small integer coordinates, grids, single-precision data), the determinant is
//      evaluated exactly with 64/128-bit integers (compilers with __int128 only).
//   1. A double-double evaluation of D(heads), plus the part of D linear in the tails
//      evaluated in double precision. Its error is bounded by C eps^2 P (eps = 2^-53, P the
//      permanent of D at the heads: the sum of the absolute values of its monomials), with C
//      derived below for each predicate; the sign is returned when the estimate exceeds it.
//      Near-degenerate but non-degenerate inputs (points rounded onto a sphere, a plane...)
//      have |D| of the order of eps P and are decided here without any expansion arithmetic.
//   2. When every tail is zero, D(heads) is the determinant: it is evaluated exactly with
//      floating-point expansions.
//   3. Otherwise the determinant is evaluated exactly from the raw coordinates (the lifted
//      (n+1)x(n+1) determinant with a column of ones), which needs no differences.
//
// Expansions (non-overlapping doubles of increasing magnitude whose exact sum is the value)
// live in fixed-size stack buffers sized to the proven maximum length of each intermediate, so
// nothing is allocated. Sums are linear-time (Shewchuk's fast expansion sum with zero
// elimination), products use scale-expansion with zero elimination, and intermediate results
// are compressed (same value, never more components) to keep the following steps short.
//
// Error bounds of stage 1. A double-double value Q = (h, l) computed for a polynomial with
// permanent P_Q carries three constants: |h| <= A P_Q, |l| <= B eps P_Q and
// |Q - (h + l)| <= K eps^2 P_Q (first order in eps for A and B, second order for K; the margin
// of the final constants covers the higher-order terms). The operations and their constants:
//   products x y of doubles (TwoProduct):      A 1, B 1, K 0
//   minor x y - z w (TwoProduct, TwoSum):      A 1, B 2, K 3
//   z Q, z a double:                           A, A + B, K + A + 2B
//   Q1 +- Q2:                                  max A, max (A + B), max (K + A + 2B)
//   Q1 Q2:  A1 A2, A1 A2 + A1 B2 + B1 A2, K1 A2 + K2 A1 + B1 B2 + 3 (A1 B2 + B1 A2) + A1 A2.
// The tails are at most eps times their heads, so for a degree-n determinant the part linear
// in the tails is at most n eps P; evaluated through at most k roundings in a row its error is
// at most k n eps^2 P (to first order), and the terms of degree >= 2 in the tails are at most
// n (n - 1) / 2 eps^2 P. The final sum of the low part of D(heads) with the linear part adds
// (B + n) eps^2 P. The permanent is itself rounded (relative error below 16 eps).
//
// Requirements: IEEE-754 binary64 with round-to-nearest-even (SSE2 on x86-64; not the x87
// unit), no -ffast-math. TwoProduct uses a fused multiply-add when the target has one and
// Dekker's product otherwise (so floating-point contraction cannot break Dekker's splitting).
#include "pcsPredicates.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

namespace pcs
{
namespace predicates
{
namespace
{

// 2^-53 (half an ulp of 1) and its square, both exact.
constexpr double Epsilon = 1.1102230246251565404e-16;
constexpr double EpsilonSquared = Epsilon * Epsilon;

// ---------------------------------------------------------------------------------------------
// Error-free transformations.

// x + y = a + b exactly, x = fl(a + b) (Knuth).
inline void TwoSum(double a, double b, double& x, double& y)
{
  x = a + b;
  const double bVirtual = x - a;
  const double aVirtual = x - bVirtual;
  y = (a - aVirtual) + (b - bVirtual);
}

// Same result as TwoSum when |a| >= |b| or a == 0 (Dekker).
inline void FastTwoSum(double a, double b, double& x, double& y)
{
  x = a + b;
  y = b - (x - a);
}

// x + y = a * b exactly, x = fl(a * b).
#if defined(__FMA__) || defined(__FMA4__)
inline void TwoProduct(double a, double b, double& x, double& y)
{
  x = a * b;
  y = std::fma(a, b, -x);
}
#else
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
#endif

// ---------------------------------------------------------------------------------------------
// Expansions: arrays of non-overlapping doubles sorted by increasing magnitude, without zero
// components (length 0 is the value 0), whose exact sum is the value. The sign of the value is
// the sign of the last (largest) component. Outputs never alias inputs unless stated.

inline int Sign(int n, const double* e)
{
  return n == 0 ? 0 : (e[n - 1] > 0.0 ? 1 : -1);
}

inline void Negate(int n, double* e)
{
  for (int i = 0; i < n; ++i)
  {
    e[i] = -e[i];
  }
}

// h = a * b - c * d exactly (at most 4 components).
inline int ProductDifference(double a, double b, double c, double d, double* h)
{
  double p1, p0, q1, q0;
  TwoProduct(a, b, p1, p0);
  TwoProduct(c, d, q1, q0);
  // (p1 + p0) - (q1 + q0): Shewchuk's Two-Two-Diff, then zero elimination.
  double x0, i, j, x1, k, x2, x3;
  TwoSum(p0, -q0, i, x0);
  TwoSum(p1, i, j, k);
  TwoSum(k, -q1, i, x1);
  TwoSum(j, i, x3, x2);
  int n = 0;
  if (x0 != 0.0)
  {
    h[n++] = x0;
  }
  if (x1 != 0.0)
  {
    h[n++] = x1;
  }
  if (x2 != 0.0)
  {
    h[n++] = x2;
  }
  if (x3 != 0.0)
  {
    h[n++] = x3;
  }
  return n;
}

// h = a^2 + b^2 (+ c^2) exactly.
inline int SumOfSquares(double a, double b, double* h)
{
  double a1, a0, b1, b0;
  TwoProduct(a, a, a1, a0);
  TwoProduct(b, b, b1, b0);
  double x0, i, j, x1, k, x2, x3;
  TwoSum(a0, b0, i, x0);
  TwoSum(a1, i, j, k);
  TwoSum(k, b1, i, x1);
  TwoSum(j, i, x3, x2);
  int n = 0;
  if (x0 != 0.0)
  {
    h[n++] = x0;
  }
  if (x1 != 0.0)
  {
    h[n++] = x1;
  }
  if (x2 != 0.0)
  {
    h[n++] = x2;
  }
  if (x3 != 0.0)
  {
    h[n++] = x3;
  }
  return n;
}

// h = e + f (Shewchuk's Fast-Expansion-Sum with zero elimination; at most ne + nf components).
int Sum(int ne, const double* e, int nf, const double* f, double* h)
{
  if (ne == 0)
  {
    std::copy(f, f + nf, h);
    return nf;
  }
  if (nf == 0)
  {
    std::copy(e, e + ne, h);
    return ne;
  }
  int i = 0, j = 0, n = 0;
  double ei = e[0], fj = f[0];
  double q;
  // Take the components of e and f in order of increasing magnitude.
  if (std::fabs(fj) > std::fabs(ei))
  {
    q = ei;
    ++i;
  }
  else
  {
    q = fj;
    ++j;
  }
  double s, err;
  if (i < ne && j < nf)
  {
    ei = e[i];
    fj = f[j];
    if (std::fabs(fj) > std::fabs(ei))
    {
      FastTwoSum(ei, q, s, err);
      ++i;
    }
    else
    {
      FastTwoSum(fj, q, s, err);
      ++j;
    }
    q = s;
    if (err != 0.0)
    {
      h[n++] = err;
    }
    while (i < ne && j < nf)
    {
      ei = e[i];
      fj = f[j];
      if (std::fabs(fj) > std::fabs(ei))
      {
        TwoSum(q, ei, s, err);
        ++i;
      }
      else
      {
        TwoSum(q, fj, s, err);
        ++j;
      }
      q = s;
      if (err != 0.0)
      {
        h[n++] = err;
      }
    }
  }
  for (; i < ne; ++i)
  {
    TwoSum(q, e[i], s, err);
    q = s;
    if (err != 0.0)
    {
      h[n++] = err;
    }
  }
  for (; j < nf; ++j)
  {
    TwoSum(q, f[j], s, err);
    q = s;
    if (err != 0.0)
    {
      h[n++] = err;
    }
  }
  if (q != 0.0)
  {
    h[n++] = q;
  }
  return n;
}

// h = e * b (Shewchuk's Scale-Expansion with zero elimination; at most 2 ne components).
int Scale(int ne, const double* e, double b, double* h)
{
  if (ne == 0 || b == 0.0)
  {
    return 0;
  }
  int n = 0;
  double q, err;
  TwoProduct(e[0], b, q, err);
  if (err != 0.0)
  {
    h[n++] = err;
  }
  for (int i = 1; i < ne; ++i)
  {
    double p1, p0, s;
    TwoProduct(e[i], b, p1, p0);
    TwoSum(q, p0, s, err);
    if (err != 0.0)
    {
      h[n++] = err;
    }
    FastTwoSum(p1, s, q, err);
    if (err != 0.0)
    {
      h[n++] = err;
    }
  }
  if (q != 0.0)
  {
    h[n++] = q;
  }
  return n;
}

// Shewchuk's Compress, in place: same value, usually far fewer components, never more.
int Compress(int ne, double* e)
{
  if (ne <= 1)
  {
    return ne;
  }
  int bottom = ne - 1;
  double q = e[bottom];
  for (int i = ne - 2; i >= 0; --i)
  {
    double s, err;
    FastTwoSum(q, e[i], s, err);
    if (err != 0.0)
    {
      e[bottom--] = s;
      q = err;
    }
    else
    {
      q = s;
    }
  }
  int top = 0;
  for (int i = bottom + 1; i < ne; ++i)
  {
    double s, err;
    FastTwoSum(e[i], q, s, err);
    if (err != 0.0)
    {
      e[top++] = err;
    }
    q = s;
  }
  if (q != 0.0)
  {
    e[top++] = q;
  }
  return top;
}

// h = e * f; `work` holds 2 ne (nf + 1) doubles; h holds 2 ne nf.
int Product(int ne, const double* e, int nf, const double* f, double* h, double* work)
{
  if (ne == 0 || nf == 0)
  {
    return 0;
  }
  double* scaled = work;
  double* other = work + 2 * ne;
  // nf - 1 sums alternate between h and `other`: start where the last one lands in h.
  double* current = ((nf - 1) % 2 == 0) ? h : other;
  double* next = current == h ? other : h;
  int n = Scale(ne, e, f[0], current);
  for (int j = 1; j < nf; ++j)
  {
    const int ns = Scale(ne, e, f[j], scaled);
    n = Sum(n, current, ns, scaled, next);
    std::swap(current, next);
  }
  return n;
}

// h = x^2 + y^2 + z^2 exactly, compressed (at most 6 components).
inline int Lift(double x, double y, double z, double* h)
{
  double xy[4], z2[2];
  const int nxy = SumOfSquares(x, y, xy);
  int nz2 = 0;
  double hi, lo;
  TwoProduct(z, z, hi, lo);
  if (lo != 0.0)
  {
    z2[nz2++] = lo;
  }
  if (hi != 0.0)
  {
    z2[nz2++] = hi;
  }
  return Compress(Sum(nxy, xy, nz2, z2, h), h);
}

// ---------------------------------------------------------------------------------------------
// Raw-coordinate building blocks of stage 3.

// det [px py 1; qx qy 1; rx ry 1] = m(q,r) - m(p,r) + m(p,q), m(u,v) = ux vy - vx uy.
// `m` holds the 2x2 minors m(p,q), m(p,r), m(q,r) (4 components each). At most 12 components.
int Triangle(int npq, const double* mpq, int npr, const double* mpr, int nqr,
  const double* mqr, double* h)
{
  double negated[4] = {};
  for (int i = 0; i < npr; ++i)
  {
    negated[i] = -mpr[i];
  }
  double t[8];
  const int nt = Sum(nqr, mqr, npr, negated, t);
  return Sum(nt, t, npq, mpq, h);
}

// det [px py pz 1; ...; sx sy sz 1] from the four triangle determinants (rows x y 1) of the
// triples without p, q, r, s respectively:
//   pz T(q,r,s) - qz T(p,r,s) + rz T(p,q,s) - sz T(p,q,r). At most 96 components.
int Tetrahedron(double pz, double qz, double rz, double sz, int n0, const double* t0, int n1,
  const double* t1, int n2, const double* t2, int n3, const double* t3, double* h)
{
  double a[24], b[24], ab[48], c[24], d[24], cd[48];
  const int na = Scale(n0, t0, pz, a);
  const int nb = Scale(n1, t1, -qz, b);
  const int nab = Sum(na, a, nb, b, ab);
  const int nc = Scale(n2, t2, rz, c);
  const int nd = Scale(n3, t3, -sz, d);
  const int ncd = Sum(nc, c, nd, d, cd);
  return Sum(nab, ab, ncd, cd, h);
}

// ---------------------------------------------------------------------------------------------
// Double-double values of stage 1 (not normalized; see the error constants at the top).
struct DD
{
  double H, L;
};

// x^2 (A 1, B 1, K 0).
inline DD DDSquare(double x)
{
  DD r;
  TwoProduct(x, x, r.H, r.L);
  return r;
}

// a b - c d (A 1, B 2, K 3).
inline DD DDMinor(double a, double b, double c, double d)
{
  double p1, p0, q1, q0;
  TwoProduct(a, b, p1, p0);
  TwoProduct(c, d, q1, q0);
  DD r;
  double s0;
  TwoSum(p1, -q1, r.H, s0);
  r.L = (p0 - q0) + s0;
  return r;
}

// z q, z a double (A, A + B, K + A + 2B).
inline DD DDScale(const DD& q, double z)
{
  DD r;
  double r0;
  TwoProduct(z, q.H, r.H, r0);
  r.L = r0 + z * q.L;
  return r;
}

// p + q (max A, max (A + B), max (K + A + 2B)).
inline DD DDAdd(const DD& p, const DD& q)
{
  DD r;
  double s0;
  TwoSum(p.H, q.H, r.H, s0);
  r.L = s0 + (p.L + q.L);
  return r;
}

inline DD DDSubtract(const DD& p, const DD& q)
{
  return DDAdd(p, DD{ -q.H, -q.L });
}

// p q (A1 A2, A1 A2 + A1 B2 + B1 A2, K1 A2 + K2 A1 + B1 B2 + 3 (A1 B2 + B1 A2) + A1 A2).
inline DD DDMultiply(const DD& p, const DD& q)
{
  DD r;
  double r0;
  TwoProduct(p.H, q.H, r.H, r0);
  r.L = r0 + (p.H * q.L + p.L * q.H);
  return r;
}

// ---------------------------------------------------------------------------------------------
// Stage 1 estimates: Value approximates the determinant of the differences head + tail with an
// error at most Bound * Permanent (Bound in units of eps^2, see the top of the file).
struct Estimate
{
  double Value;
  double Permanent;
};

inline int DecidedSign(const Estimate& estimate, double bound)
{
  const double limit = bound * estimate.Permanent;
  if (estimate.Value > limit)
  {
    return 1;
  }
  if (-estimate.Value > limit)
  {
    return -1;
  }
  return 0;
}

// Orient3D: D(heads) through minors (A 1, B 2, K 3), scaled (1, 3, 8) and summed (1, 5, 24).
// Error: 24 (double-double) + 7 * 3 (linear part, 7 roundings in a row) + 3 (higher order)
// + 5 + 3 (final sum) = 56 eps^2 P.
constexpr double Orient3DBound = 64.0 * EpsilonSquared;

Estimate Orient3DEstimate(const double x[3][3], const double t[3][3], bool tailsZero)
{
  const DD mbc = DDMinor(x[1][0], x[2][1], x[2][0], x[1][1]);
  const DD mac = DDMinor(x[0][0], x[2][1], x[2][0], x[0][1]);
  const DD mab = DDMinor(x[0][0], x[1][1], x[1][0], x[0][1]);
  const DD det =
    DDAdd(DDAdd(DDScale(mbc, x[0][2]), DDScale(mac, -x[1][2])), DDScale(mab, x[2][2]));
  double first = 0.0;
  if (!tailsZero)
  {
    const double dbc =
      (x[1][0] * t[2][1] + t[1][0] * x[2][1]) - (x[2][0] * t[1][1] + t[2][0] * x[1][1]);
    const double dac =
      (x[0][0] * t[2][1] + t[0][0] * x[2][1]) - (x[2][0] * t[0][1] + t[2][0] * x[0][1]);
    const double dab =
      (x[0][0] * t[1][1] + t[0][0] * x[1][1]) - (x[1][0] * t[0][1] + t[1][0] * x[0][1]);
    first = ((t[0][2] * mbc.H - t[1][2] * mac.H) + t[2][2] * mab.H) +
      ((x[0][2] * dbc - x[1][2] * dac) + x[2][2] * dab);
  }
  Estimate r;
  r.Value = det.H + (det.L + first);
  r.Permanent =
    (std::fabs(x[1][0] * x[2][1]) + std::fabs(x[2][0] * x[1][1])) * std::fabs(x[0][2]) +
    (std::fabs(x[0][0] * x[2][1]) + std::fabs(x[2][0] * x[0][1])) * std::fabs(x[1][2]) +
    (std::fabs(x[0][0] * x[1][1]) + std::fabs(x[1][0] * x[0][1])) * std::fabs(x[2][2]);
  return r;
}

// The three points of the 3x3 determinant T_l of InSphere (all but point l).
const int InSphereTriples[4][3] = { { 1, 2, 3 }, { 0, 2, 3 }, { 0, 1, 3 }, { 0, 1, 2 } };

// InSphere: minors (1, 2, 3), T (1, 5, 24), lifts (1, 3, 8), L T (1, 9, 72), D (1, 11, 112).
// Error: 112 (double-double) + 11 * 5 (linear part) + 10 (higher order) + 11 + 5 (final sum)
// = 193 eps^2 P.
constexpr double InSphereBound = 256.0 * EpsilonSquared;

Estimate InSphereEstimate(const double x[4][3], const double t[4][3], bool tailsZero)
{
  DD m[4][4];
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      m[i][j] = DDMinor(x[i][0], x[j][1], x[j][0], x[i][1]);
    }
  }
  DD terms[4];
  double firsts[4], perms[4];
  for (int l = 0; l < 4; ++l)
  {
    const int u = InSphereTriples[l][0], v = InSphereTriples[l][1], w = InSphereTriples[l][2];
    const DD tri = DDAdd(
      DDAdd(DDScale(m[v][w], x[u][2]), DDScale(m[u][w], -x[v][2])), DDScale(m[u][v], x[w][2]));
    const DD lift = DDAdd(DDAdd(DDSquare(x[l][0]), DDSquare(x[l][1])), DDSquare(x[l][2]));
    terms[l] = DDMultiply(lift, tri);
    perms[l] = lift.H *
      ((std::fabs(x[v][0] * x[w][1]) + std::fabs(x[w][0] * x[v][1])) * std::fabs(x[u][2]) +
        (std::fabs(x[u][0] * x[w][1]) + std::fabs(x[w][0] * x[u][1])) * std::fabs(x[v][2]) +
        (std::fabs(x[u][0] * x[v][1]) + std::fabs(x[v][0] * x[u][1])) * std::fabs(x[w][2]));
    if (!tailsZero)
    {
      // Linear part of L_l T_l in the tails (at most 9 roundings in a row).
      const double dvw =
        (x[v][0] * t[w][1] + t[v][0] * x[w][1]) - (x[w][0] * t[v][1] + t[w][0] * x[v][1]);
      const double duw =
        (x[u][0] * t[w][1] + t[u][0] * x[w][1]) - (x[w][0] * t[u][1] + t[w][0] * x[u][1]);
      const double duv =
        (x[u][0] * t[v][1] + t[u][0] * x[v][1]) - (x[v][0] * t[u][1] + t[v][0] * x[u][1]);
      const double triFirst =
        ((t[u][2] * m[v][w].H - t[v][2] * m[u][w].H) + t[w][2] * m[u][v].H) +
        ((x[u][2] * dvw - x[v][2] * duw) + x[w][2] * duv);
      const double liftFirst =
        2.0 * ((x[l][0] * t[l][0] + x[l][1] * t[l][1]) + x[l][2] * t[l][2]);
      firsts[l] = liftFirst * tri.H + lift.H * triFirst;
    }
  }
  const DD det = DDAdd(DDSubtract(terms[3], terms[2]), DDSubtract(terms[1], terms[0]));
  const double first = tailsZero ? 0.0 : (firsts[3] - firsts[2]) + (firsts[1] - firsts[0]);
  Estimate r;
  r.Value = det.H + (det.L + first);
  r.Permanent = (perms[3] + perms[2]) + (perms[1] + perms[0]);
  return r;
}

// Orient2D: the minor (1, 2, 3). Error: 3 + 3 * 2 (linear part, 3 roundings in a row) + 1
// (higher order) + 2 + 2 (final sum) = 14 eps^2 P.
constexpr double Orient2DBound = 16.0 * EpsilonSquared;

Estimate Orient2DEstimate(const double x[2][2], const double t[2][2])
{
  const DD det = DDMinor(x[0][0], x[1][1], x[0][1], x[1][0]);
  const double first =
    (x[0][0] * t[1][1] + t[0][0] * x[1][1]) - (x[0][1] * t[1][0] + t[0][1] * x[1][0]);
  Estimate r;
  r.Value = det.H + (det.L + first);
  r.Permanent = std::fabs(x[0][0] * x[1][1]) + std::fabs(x[0][1] * x[1][0]);
  return r;
}

// The two points of the minor m_l of InCircle (all but point l).
const int InCirclePairs[3][2] = { { 1, 2 }, { 0, 2 }, { 0, 1 } };

// InCircle: minors (1, 2, 3), lifts (1, 2, 3), L m (1, 5, 23), D (1, 7, 47). Error: 47
// (double-double) + 7 * 4 (linear part) + 6 (higher order) + 7 + 4 (final sum) = 92 eps^2 P.
constexpr double InCircleBound = 128.0 * EpsilonSquared;

Estimate InCircleEstimate(const double x[3][2], const double t[3][2], bool tailsZero)
{
  DD terms[3];
  double firsts[3], perms[3];
  for (int l = 0; l < 3; ++l)
  {
    const int u = InCirclePairs[l][0], v = InCirclePairs[l][1];
    const DD minor = DDMinor(x[u][0], x[v][1], x[v][0], x[u][1]);
    const DD lift = DDAdd(DDSquare(x[l][0]), DDSquare(x[l][1]));
    terms[l] = DDMultiply(lift, minor);
    perms[l] = (std::fabs(x[u][0] * x[v][1]) + std::fabs(x[v][0] * x[u][1])) * lift.H;
    if (!tailsZero)
    {
      // Linear part of L_l m_l in the tails (at most 5 roundings in a row).
      const double minorFirst =
        (x[u][0] * t[v][1] + t[u][0] * x[v][1]) - (x[v][0] * t[u][1] + t[v][0] * x[u][1]);
      const double liftFirst = 2.0 * (x[l][0] * t[l][0] + x[l][1] * t[l][1]);
      firsts[l] = liftFirst * minor.H + lift.H * minorFirst;
    }
  }
  const DD det = DDAdd(DDSubtract(terms[0], terms[1]), terms[2]);
  const double first = tailsZero ? 0.0 : (firsts[0] - firsts[1]) + firsts[2];
  Estimate r;
  r.Value = det.H + (det.L + first);
  r.Permanent = (perms[0] + perms[1]) + perms[2];
  return r;
}

// ---------------------------------------------------------------------------------------------
// Integer path of stage 2 (compilers with a 128-bit integer type). When the exact differences
// are all integer multiples of one power of two and span at most 24 bits (small integer
// coordinates, grids, coordinates that come from single precision), they are scaled to
// integers below 2^24 in magnitude and the determinant is evaluated exactly in 64/128-bit
// integer arithmetic.
#if defined(__SIZEOF_INT128__)
#define PCS_PREDICATES_INTEGER_PATH 1
using Int128 = __int128;

// v[i] = h[i] 2^s, with s such that the largest |h[i]| lies in [2^23, 2^24); false when one
// of them is then not an integer (or when 2^s is out of range).
inline bool ScaleToIntegers(const double* h, int n, int64_t* v)
{
  double largest = 0.0;
  for (int i = 0; i < n; ++i)
  {
    largest = std::max(largest, std::fabs(h[i]));
  }
  if (largest == 0.0)
  {
    std::fill(v, v + n, int64_t(0));
    return true;
  }
  uint64_t bits;
  std::memcpy(&bits, &largest, sizeof(bits));
  const int exponent = static_cast<int>(bits >> 52) - 1022; // largest in [2^(e-1), 2^e)
  const int biased = 1023 + 24 - exponent;                  // of the factor 2^(24 - e)
  if ((bits >> 52) == 0 || biased < 1 || biased > 2046)
  {
    return false;
  }
  const uint64_t factorBits = static_cast<uint64_t>(biased) << 52;
  double factor;
  std::memcpy(&factor, &factorBits, sizeof(factor));
  for (int i = 0; i < n; ++i)
  {
    const double scaled = h[i] * factor; // exact, |scaled| < 2^24
    const int64_t k = static_cast<int64_t>(scaled);
    if (static_cast<double>(k) != scaled)
    {
      return false;
    }
    v[i] = k;
  }
  return true;
}

inline int SignOf(Int128 v)
{
  return (v > 0) - (v < 0);
}

// |v| < 2^24: minors < 2^49, D < 3 2^73.
int Orient3DInteger(const int64_t v[3][3])
{
  const int64_t mbc = v[1][0] * v[2][1] - v[2][0] * v[1][1];
  const int64_t mac = v[0][0] * v[2][1] - v[2][0] * v[0][1];
  const int64_t mab = v[0][0] * v[1][1] - v[1][0] * v[0][1];
  return SignOf(
    Int128(v[0][2]) * mbc - Int128(v[1][2]) * mac + Int128(v[2][2]) * mab);
}

// |v| < 2^24: minors < 2^49, T < 3 2^73, lifts < 3 2^48, L T < 9 2^121, D < 36 2^121 < 2^127.
int InSphereInteger(const int64_t v[4][3])
{
  int64_t m[4][4];
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      m[i][j] = v[i][0] * v[j][1] - v[j][0] * v[i][1];
    }
  }
  Int128 det = 0;
  for (int l = 0; l < 4; ++l)
  {
    const int p = InSphereTriples[l][0], q = InSphereTriples[l][1], r = InSphereTriples[l][2];
    const Int128 tri =
      Int128(v[p][2]) * m[q][r] - Int128(v[q][2]) * m[p][r] + Int128(v[r][2]) * m[p][q];
    const int64_t lift = v[l][0] * v[l][0] + v[l][1] * v[l][1] + v[l][2] * v[l][2];
    const Int128 term = tri * lift;
    det = (l % 2 == 0) ? det - term : det + term;
  }
  return SignOf(det);
}

// |v| < 2^24: minors < 2^49, lifts < 2^49, D < 3 2^98.
int InCircleInteger(const int64_t v[3][2])
{
  Int128 det = 0;
  for (int l = 0; l < 3; ++l)
  {
    const int p = InCirclePairs[l][0], q = InCirclePairs[l][1];
    const int64_t minor = v[p][0] * v[q][1] - v[q][0] * v[p][1];
    const int64_t lift = v[l][0] * v[l][0] + v[l][1] * v[l][1];
    const Int128 term = Int128(minor) * lift;
    det = (l == 1) ? det - term : det + term;
  }
  return SignOf(det);
}
#endif

} // namespace

// -----------------------------------------------------------------------------------------------
// Orient3D, differences with d: D = adz m(b,c) - bdz m(a,c) + cdz m(a,b),
// m(u,v) = udx vdy - vdx udy. Degree 3, 6 monomials.
int Orient3DExact(const double* a, const double* b, const double* c, const double* d)
{
  double x[3][3], t[3][3];
  const double* p[3] = { a, b, c };
  bool tailsZero = true;
  for (int i = 0; i < 3; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      TwoSum(p[i][k], -d[k], x[i][k], t[i][k]);
      tailsZero = tailsZero && t[i][k] == 0.0;
    }
  }

#ifdef PCS_PREDICATES_INTEGER_PATH
  // Stage 0.
  int64_t scaled[3][3];
  if (tailsZero && ScaleToIntegers(&x[0][0], 9, &scaled[0][0]))
  {
    return Orient3DInteger(scaled);
  }
#endif
  // Stage 1.
  const Estimate estimate = Orient3DEstimate(x, t, tailsZero);
  const int sign = DecidedSign(estimate, Orient3DBound);
  if (sign != 0)
  {
    return sign;
  }

  if (tailsZero)
  {
    // Stage 2: exact D(heads), at most 24 components.
    double bc[4], ac[4], ab[4];
    const int nbc = ProductDifference(x[1][0], x[2][1], x[2][0], x[1][1], bc);
    const int nac = ProductDifference(x[0][0], x[2][1], x[2][0], x[0][1], ac);
    const int nab = ProductDifference(x[0][0], x[1][1], x[1][0], x[0][1], ab);
    double s1[8], s2[8], s12[16], s3[8], exact[24];
    const int n1 = Scale(nbc, bc, x[0][2], s1);
    const int n2 = Scale(nac, ac, -x[1][2], s2);
    const int n12 = Sum(n1, s1, n2, s2, s12);
    const int n3 = Scale(nab, ab, x[2][2], s3);
    return Sign(Sum(n12, s12, n3, s3, exact), exact);
  }

  // Stage 3: det [x y z 1] of the raw coordinates, at most 96 components.
  double mab0[4], mac0[4], mad0[4], mbc0[4], mbd0[4], mcd0[4];
  const int n_ab = ProductDifference(a[0], b[1], b[0], a[1], mab0);
  const int n_ac = ProductDifference(a[0], c[1], c[0], a[1], mac0);
  const int n_ad = ProductDifference(a[0], d[1], d[0], a[1], mad0);
  const int n_bc = ProductDifference(b[0], c[1], c[0], b[1], mbc0);
  const int n_bd = ProductDifference(b[0], d[1], d[0], b[1], mbd0);
  const int n_cd = ProductDifference(c[0], d[1], d[0], c[1], mcd0);
  double tbcd[12], tacd[12], tabd[12], tabc[12];
  const int n_bcd = Triangle(n_bc, mbc0, n_bd, mbd0, n_cd, mcd0, tbcd);
  const int n_acd = Triangle(n_ac, mac0, n_ad, mad0, n_cd, mcd0, tacd);
  const int n_abd = Triangle(n_ab, mab0, n_ad, mad0, n_bd, mbd0, tabd);
  const int n_abc = Triangle(n_ab, mab0, n_ac, mac0, n_bc, mbc0, tabc);
  double full[96];
  const int nfull = Tetrahedron(
    a[2], b[2], c[2], d[2], n_bcd, tbcd, n_acd, tacd, n_abd, tabd, n_abc, tabc, full);
  return Sign(nfull, full);
}

// -----------------------------------------------------------------------------------------------
// InSphere, differences with e: D = L_d T(a,b,c) - L_c T(a,b,d) + L_b T(a,c,d) - L_a T(b,c,d),
// T(u,v,w) = uz m(v,w) - vz m(u,w) + wz m(u,v), m(u,v) = ux vy - vx uy, L_u = |u|^2.
// Degree 5, 72 monomials.
int InSphereExact(
  const double* a, const double* b, const double* c, const double* d, const double* e)
{
  const double* p[4] = { a, b, c, d };
  double x[4][3], t[4][3];
  bool tailsZero = true;
  for (int i = 0; i < 4; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      TwoSum(p[i][k], -e[k], x[i][k], t[i][k]);
      tailsZero = tailsZero && t[i][k] == 0.0;
    }
  }

#ifdef PCS_PREDICATES_INTEGER_PATH
  // Stage 0.
  int64_t scaled[4][3];
  if (tailsZero && ScaleToIntegers(&x[0][0], 12, &scaled[0][0]))
  {
    return InSphereInteger(scaled);
  }
#endif
  // Stage 1.
  const Estimate estimate = InSphereEstimate(x, t, tailsZero);
  const int sign = DecidedSign(estimate, InSphereBound);
  if (sign != 0)
  {
    return sign;
  }

  if (tailsZero)
  {
    // Stage 2: exact D(heads). Lengths: m 4, T 24, L 6, L T 288, D 1152.
    double m[4][4][4];
    int nm[4][4];
    for (int i = 0; i < 4; ++i)
    {
      for (int j = i + 1; j < 4; ++j)
      {
        nm[i][j] = ProductDifference(x[i][0], x[j][1], x[j][0], x[i][1], m[i][j]);
      }
    }
    double acc1[1152], acc2[1152];
    double* current = acc1;
    double* next = acc2;
    int ndet = 0;
    for (int l = 0; l < 4; ++l)
    {
      const int u = InSphereTriples[l][0], v = InSphereTriples[l][1], w = InSphereTriples[l][2];
      double s1[8], s2[8], s12[16], s3[8], tri[24];
      const int n1 = Scale(nm[v][w], m[v][w], x[u][2], s1);
      const int n2 = Scale(nm[u][w], m[u][w], -x[v][2], s2);
      const int n12 = Sum(n1, s1, n2, s2, s12);
      const int n3 = Scale(nm[u][v], m[u][v], x[w][2], s3);
      const int ntri = Compress(Sum(n12, s12, n3, s3, tri), tri);
      double lift[6];
      const int nlift = Lift(x[l][0], x[l][1], x[l][2], lift);
      if (l % 2 == 0)
      {
        Negate(nlift, lift);
      }
      double term[288], work[2 * 24 * 7];
      const int nterm = Compress(Product(ntri, tri, nlift, lift, term, work), term);
      ndet = Sum(ndet, current, nterm, term, next);
      std::swap(current, next);
    }
    return Sign(ndet, current);
  }

  // Stage 3: det [x y z |p|^2 1] of the raw coordinates of a, b, c, d, e:
  //   sum over l of (-1)^(l+3) |p_l|^2 O(others of l), O = det [x y z 1] (at most 96
  // components), products at most 1152, total at most 5760.
  const double* q[5] = { a, b, c, d, e };
  double rm[5][5][4];
  int nrm[5][5];
  for (int i = 0; i < 5; ++i)
  {
    for (int j = i + 1; j < 5; ++j)
    {
      nrm[i][j] = ProductDifference(q[i][0], q[j][1], q[j][0], q[i][1], rm[i][j]);
    }
  }
  double rt[5][5][5][12];
  int nrt[5][5][5];
  for (int i = 0; i < 5; ++i)
  {
    for (int j = i + 1; j < 5; ++j)
    {
      for (int k = j + 1; k < 5; ++k)
      {
        nrt[i][j][k] = Compress(Triangle(nrm[i][j], rm[i][j], nrm[i][k], rm[i][k], nrm[j][k],
                                  rm[j][k], rt[i][j][k]),
          rt[i][j][k]);
      }
    }
  }
  double total1[5760], total2[4608];
  double* current = total2;
  int ntotal = 0;
  for (int l = 0; l < 5; ++l)
  {
    int o[4];
    for (int j = 0, k = 0; j < 5; ++j)
    {
      if (j != l)
      {
        o[k++] = j;
      }
    }
    double tet[96];
    const int ntet = Compress(Tetrahedron(q[o[0]][2], q[o[1]][2], q[o[2]][2], q[o[3]][2],
                                nrt[o[1]][o[2]][o[3]], rt[o[1]][o[2]][o[3]],
                                nrt[o[0]][o[2]][o[3]], rt[o[0]][o[2]][o[3]],
                                nrt[o[0]][o[1]][o[3]], rt[o[0]][o[1]][o[3]],
                                nrt[o[0]][o[1]][o[2]], rt[o[0]][o[1]][o[2]], tet),
      tet);
    double lift[6];
    const int nlift = Lift(q[l][0], q[l][1], q[l][2], lift);
    if (l % 2 == 0)
    {
      Negate(nlift, lift);
    }
    double term[1152], work[2 * 96 * 7];
    const int nterm = Compress(Product(ntet, tet, nlift, lift, term, work), term);
    // Running sums of at most 1152 (l + 1) components: 1152, 3456 and 5760 land in total1,
    // 2304 and 4608 in total2.
    double* next = (l % 2 == 0) ? total1 : total2;
    ntotal = Sum(ntotal, current, nterm, term, next);
    current = next;
  }
  return Sign(ntotal, current);
}

// -----------------------------------------------------------------------------------------------
// Orient2D, differences with c: D = acx bcy - acy bcx. Degree 2, 2 monomials.
int Orient2DExact(const double* a, const double* b, const double* c)
{
  // Two equal points: the determinant is exactly zero. The common undecided case of the filter
  // (e.g. the projected tests of vtkCDTAdvancingFront, where a segment ends at a vertex of the
  // triangle it is classified against), answered without the expansions.
  if ((a[0] == c[0] && a[1] == c[1]) || (b[0] == c[0] && b[1] == c[1]) ||
    (a[0] == b[0] && a[1] == b[1]))
  {
    return 0;
  }
  double x[2][2], t[2][2];
  TwoSum(a[0], -c[0], x[0][0], t[0][0]);
  TwoSum(a[1], -c[1], x[0][1], t[0][1]);
  TwoSum(b[0], -c[0], x[1][0], t[1][0]);
  TwoSum(b[1], -c[1], x[1][1], t[1][1]);
  if (t[0][0] == 0.0 && t[0][1] == 0.0 && t[1][0] == 0.0 && t[1][1] == 0.0)
  {
    // Stage 2 directly: the exact minor has at most 4 components.
    double det[4];
    return Sign(ProductDifference(x[0][0], x[1][1], x[0][1], x[1][0], det), det);
  }
  // Stage 1.
  const int sign = DecidedSign(Orient2DEstimate(x, t), Orient2DBound);
  if (sign != 0)
  {
    return sign;
  }
  // Stage 3: det [x y 1] of the raw coordinates, at most 12 components.
  double mab[4], mac[4], mbc[4], full[12];
  const int nab = ProductDifference(a[0], b[1], b[0], a[1], mab);
  const int nac = ProductDifference(a[0], c[1], c[0], a[1], mac);
  const int nbc = ProductDifference(b[0], c[1], c[0], b[1], mbc);
  return Sign(Triangle(nab, mab, nac, mac, nbc, mbc, full), full);
}

// -----------------------------------------------------------------------------------------------
// InCircle, differences with d: D = L_a m(b,c) - L_b m(a,c) + L_c m(a,b). Degree 4,
// 12 monomials.
int InCircleExact(const double* a, const double* b, const double* c, const double* d)
{
  const double* p[3] = { a, b, c };
  double x[3][2], t[3][2];
  bool tailsZero = true;
  for (int i = 0; i < 3; ++i)
  {
    for (int k = 0; k < 2; ++k)
    {
      TwoSum(p[i][k], -d[k], x[i][k], t[i][k]);
      tailsZero = tailsZero && t[i][k] == 0.0;
    }
  }

#ifdef PCS_PREDICATES_INTEGER_PATH
  // Stage 0.
  int64_t scaled[3][2];
  if (tailsZero && ScaleToIntegers(&x[0][0], 6, &scaled[0][0]))
  {
    return InCircleInteger(scaled);
  }
#endif
  // Stage 1.
  const Estimate estimate = InCircleEstimate(x, t, tailsZero);
  const int sign = DecidedSign(estimate, InCircleBound);
  if (sign != 0)
  {
    return sign;
  }

  if (tailsZero)
  {
    // Stage 2: exact D(heads). Lengths: m 4, L 4, L m 32, D 96.
    double acc1[96], acc2[96];
    double* current = acc1;
    double* next = acc2;
    int ndet = 0;
    for (int l = 0; l < 3; ++l)
    {
      const int u = InCirclePairs[l][0], v = InCirclePairs[l][1];
      double minor[4], lift[4], term[32], work[2 * 4 * 5];
      const int nminor = ProductDifference(x[u][0], x[v][1], x[v][0], x[u][1], minor);
      const int nlift = SumOfSquares(x[l][0], x[l][1], lift);
      if (l == 1)
      {
        Negate(nminor, minor);
      }
      const int nterm = Product(nminor, minor, nlift, lift, term, work);
      ndet = Sum(ndet, current, nterm, term, next);
      std::swap(current, next);
    }
    return Sign(ndet, current);
  }

  // Stage 3: det [x y |p|^2 1] of the raw coordinates of a, b, c, d:
  //   sum over l of (-1)^l |p_l|^2 T(others of l), T = det [x y 1] (12), products 96, total 384.
  const double* q[4] = { a, b, c, d };
  double rm[4][4][4];
  int nrm[4][4];
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      nrm[i][j] = ProductDifference(q[i][0], q[j][1], q[j][0], q[i][1], rm[i][j]);
    }
  }
  double total1[384], total2[288];
  double* current = total1;
  int ntotal = 0;
  for (int l = 0; l < 4; ++l)
  {
    int o[3];
    for (int j = 0, k = 0; j < 4; ++j)
    {
      if (j != l)
      {
        o[k++] = j;
      }
    }
    double tri[12];
    const int ntri = Compress(Triangle(nrm[o[0]][o[1]], rm[o[0]][o[1]], nrm[o[0]][o[2]],
                                rm[o[0]][o[2]], nrm[o[1]][o[2]], rm[o[1]][o[2]], tri),
      tri);
    double lift[4];
    const int nlift = SumOfSquares(q[l][0], q[l][1], lift);
    if (l % 2 == 1)
    {
      Negate(nlift, lift);
    }
    double term[96], work[2 * 12 * 5];
    const int nterm = Compress(Product(ntri, tri, nlift, lift, term, work), term);
    // Running sums of at most 96, 192, 288, 384 components: total2, total1, total2, total1.
    double* next = (l % 2 == 0) ? total2 : total1;
    ntotal = Sum(ntotal, current, nterm, term, next);
    current = next;
  }
  return Sign(ntotal, current);
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
