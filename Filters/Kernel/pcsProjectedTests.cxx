#include "pcsProjectedTests.h"

#include "pcsPredicates.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace pcs
{
namespace projected
{
namespace
{
// The second point q = p + s d of the line through p along d, with s a power of two (exact) that
// makes s d about as large as p's largest coordinate when d is shorter than that. The rounding of
// the sum then tilts the line by a few units in the last place, however short d is: a short
// direction added to large coordinates (a small object far from the origin, a cross product of
// short edges) would otherwise be rounded away or turned.
void PointAlong(const double* p, const double* d, double* q)
{
  const double largestP = std::max({ std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2]) });
  const double largestD = std::max({ std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2]) });
  if (!(largestD < largestP) || !(largestD >= std::numeric_limits<double>::min()) ||
    !std::isfinite(largestP))
  {
    for (int c = 0; c < 3; ++c)
    {
      q[c] = p[c] + d[c];
    }
    return;
  }
  // 2^(exponent of largestP - exponent of largestD), from the bits (both normal, positive): the
  // filters call this for most candidate points, and frexp / ldexp are library calls.
  auto exponentOf = [](double x)
  {
    uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    return static_cast<int>((bits >> 52) & 0x7ff);
  };
  const int shift = std::min(exponentOf(largestP) - exponentOf(largestD), 1023);
  const uint64_t scaleBits = static_cast<uint64_t>(shift + 1023) << 52;
  double scale;
  std::memcpy(&scale, &scaleBits, sizeof scale);
  for (int c = 0; c < 3; ++c)
  {
    q[c] = p[c] + d[c] * scale;
  }
}
} // namespace

bool Collinear(const double* a, const double* b, const double* c)
{
  // a, b, c are collinear exactly when their projections onto the three coordinate planes are.
  for (int axis = 0; axis < 3; ++axis)
  {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const double a2[2] = { a[u], a[v] }, b2[2] = { b[u], b[v] }, c2[2] = { c[u], c[v] };
    if (predicates::Orient2D(a2, b2, c2) != 0)
    {
      return false;
    }
  }
  return true;
}

bool OnOpenSegment3D(const double* a, const double* b, const double* p)
{
  for (int c = 0; c < 3; ++c)
  {
    if (p[c] < std::min(a[c], b[c]) || p[c] > std::max(a[c], b[c]))
    {
      return false;
    }
  }
  const bool atA = p[0] == a[0] && p[1] == a[1] && p[2] == a[2];
  const bool atB = p[0] == b[0] && p[1] == b[1] && p[2] == b[2];
  return !atA && !atB && Collinear(a, b, p);
}

bool LineCrossesTriangle(
  const double* p, const double* n, const double* a, const double* b, const double* c)
{
  double q[3];
  PointAlong(p, n, q);
  if (q[0] == p[0] && q[1] == p[1] && q[2] == p[2])
  {
    return false; // no direction
  }
  const int ab = predicates::Orient3D(p, q, a, b);
  if (ab == 0)
  {
    return false;
  }
  const int bc = predicates::Orient3D(p, q, b, c);
  if (bc != ab)
  {
    return false;
  }
  return predicates::Orient3D(p, q, c, a) == ab;
}

int EdgePlaneSide(const double* a, const double* b, const double* normal, const double* x)
{
  double m[3];
  PointAlong(a, normal, m);
  return predicates::Orient3D(a, b, m, x);
}

//------------------------------------------------------------------------------------------------
bool TrianglePlane::Set(const double* a, const double* b, const double* c)
{
  const double* v[3] = { a, b, c };
  for (int i = 0; i < 3; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Vertices[i][k] = v[i][k];
    }
  }
  TriangleNormal(a, b, c, this->Normal);

  // Drop the axis of the largest normal component; should the exact orientation of the
  // flattened triangle be zero there (a sliver whose rounded normal misleads), try the others.
  int order[3] = { 0, 1, 2 };
  for (int i = 0; i < 3; ++i)
  {
    for (int j = i + 1; j < 3; ++j)
    {
      if (std::fabs(this->Normal[order[j]]) > std::fabs(this->Normal[order[i]]))
      {
        const int swap = order[i];
        order[i] = order[j];
        order[j] = swap;
      }
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    const int axis = order[k];
    this->U = (axis + 1) % 3;
    this->V = (axis + 2) % 3;
    for (int i = 0; i < 3; ++i)
    {
      this->Flat[i][0] = this->Vertices[i][this->U];
      this->Flat[i][1] = this->Vertices[i][this->V];
    }
    this->Sign = 1;
    const int orientation = predicates::Orient2D(this->Flat[0], this->Flat[1], this->Flat[2]);
    if (orientation != 0)
    {
      this->Sign = orientation;
      return true;
    }
  }
  return false;
}

int TrianglePlane::Orient(const double* a2, const double* b2, const double* c2) const
{
  return this->Sign * predicates::Orient2D(a2, b2, c2);
}

int TrianglePlane::Side(int e, const double* p) const
{
  const double p2[2] = { p[this->U], p[this->V] };
  return this->Orient(this->Flat[e], this->Flat[(e + 1) % 3], p2);
}

bool TrianglePlane::ContainsStrictly(const double* p) const
{
  return this->Side(0, p) > 0 && this->Side(1, p) > 0 && this->Side(2, p) > 0;
}

SegmentCase TrianglePlane::ClassifySegment(const double* p4, const double* p5) const
{
  const double q4[2] = { p4[this->U], p4[this->V] };
  const double q5[2] = { p5[this->U], p5[this->V] };
  // Fig. 1a: a triangle edge whose closed outer half-plane holds the segment separates it from
  // the open triangle.
  for (int e = 0; e < 3; ++e)
  {
    const double* from = this->Flat[e];
    const double* to = this->Flat[(e + 1) % 3];
    if (this->Orient(from, to, q4) <= 0 && this->Orient(from, to, q5) <= 0)
    {
      return SegmentCase::SeparatedByTriangleEdge;
    }
  }
  if (q4[0] == q5[0] && q4[1] == q5[1])
  {
    return SegmentCase::Crossing; // a point on the inner side of every edge: inside
  }
  // Fig. 1b-1g: the "virtual triangles" (p4, p5, vertex) -- the side of each vertex with respect
  // to the segment's line. The open triangle misses the segment exactly when its three vertices
  // are on one closed side of that line (the separating axis theorem for a segment and a
  // triangle: the candidate separating lines are the three edge lines and the segment's line).
  int positive = 0, negative = 0;
  for (int i = 0; i < 3; ++i)
  {
    const int side = predicates::Orient2D(q4, q5, this->Flat[i]);
    positive += side > 0 ? 1 : 0;
    negative += side < 0 ? 1 : 0;
  }
  if (positive == 0 || negative == 0)
  {
    return SegmentCase::SeparatedBySegmentLine;
  }
  return SegmentCase::Crossing;
}

} // namespace projected
} // namespace pcs
