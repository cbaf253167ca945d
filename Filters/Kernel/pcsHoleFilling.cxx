#include "pcsHoleFilling.h"

#include "pcsCoordinateScaling.h"
#include "pcsDuplicatePoints.h"
#include "pcsPredicates.h"
#include "pcsProjectedTests.h"
#include "pcsSurfaceMesh.h"

#include "vtkMath.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_set>

namespace pcs
{
namespace holes
{
namespace
{
using predicates::Orient2D;

inline int Sign(double x)
{
  return (x > 0) - (x < 0);
}

// x is collinear with p and q: is it on the closed segment pq? (exact comparisons)
inline bool OnClosedSegment(const double* p, const double* q, const double* x)
{
  return std::min(p[0], q[0]) <= x[0] && x[0] <= std::max(p[0], q[0]) &&
    std::min(p[1], q[1]) <= x[1] && x[1] <= std::max(p[1], q[1]);
}

inline bool SamePoint(const double* a, const double* b)
{
  return a[0] == b[0] && a[1] == b[1];
}

// a, b, d collinear, b != a, d != a: do b and d lie on the same side of a?
inline bool SameDirection(const double* a, const double* b, const double* d)
{
  return Sign(b[0] - a[0]) * Sign(d[0] - a[0]) > 0 || Sign(b[1] - a[1]) * Sign(d[1] - a[1]) > 0;
}

// Segments a-b and a-d sharing the end point a: do they overlap beyond a?
inline bool OverlapAtSharedEnd(const double* a, const double* b, const double* d)
{
  return Orient2D(a, b, d) == 0 && SameDirection(a, b, d);
}

// p strictly inside the open segment ab (p distinct from a and b).
inline bool OnOpenSegment(const double* a, const double* b, const double* p)
{
  return !SamePoint(a, p) && !SamePoint(b, p) && Orient2D(a, b, p) == 0 &&
    OnClosedSegment(a, b, p);
}

// Is the direction v -> q strictly inside the interior angle of the counter-clockwise polygon
// at v (previous vertex p, next vertex n)? Exact.
bool InsideWedge(const double* p, const double* v, const double* n, const double* q)
{
  const int turn = Orient2D(p, v, n);
  const int leftOfNext = Orient2D(v, n, q);     // interior side of the edge v -> n
  const int leftOfPrevious = Orient2D(p, v, q); // interior side of the edge p -> v
  if (turn > 0)
  {
    return leftOfNext > 0 && leftOfPrevious > 0;
  }
  if (turn < 0)
  {
    return leftOfNext > 0 || leftOfPrevious > 0;
  }
  // Straight vertex (n ahead of p): the interior is the open left half-plane.
  return SameDirection(v, n, p) ? false : leftOfNext > 0;
}

double Distance3(const double* a, const double* b)
{
  const double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

uint64_t EdgeKey(int32_t a, int32_t b)
{
  if (a > b)
  {
    std::swap(a, b);
  }
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

// Exact orientation of a simple polygon: the sign of the turn at its lexicographically smallest
// vertex (always a convex vertex).
int SimplePolygonOrientation(const std::vector<double>& uv)
{
  const size_t n = uv.size() / 2;
  size_t k = 0;
  for (size_t i = 1; i < n; ++i)
  {
    if (uv[2 * i] < uv[2 * k] || (uv[2 * i] == uv[2 * k] && uv[2 * i + 1] < uv[2 * k + 1]))
    {
      k = i;
    }
  }
  return Orient2D(&uv[2 * ((k + n - 1) % n)], &uv[2 * k], &uv[2 * ((k + 1) % n)]);
}
} // namespace

//------------------------------------------------------------------------------------------------
bool Plane::Fit(const double* xyz, const int32_t* ids, size_t count)
{
  if (count == 0)
  {
    return false;
  }
  // The sums run on coordinates scaled by a power of two when they are extreme (see
  // pcsCoordinateScaling.h; exact, 1 in the usual range): the squares of coordinates near 1e300
  // or 1e-300 would overflow or underflow.
  const double scale =
    std::ldexp(1.0, pcs::PredicateSafeExponent(xyz, 3, ids, count));
  double centroid[3] = { 0, 0, 0 };
  for (size_t k = 0; k < count; ++k)
  {
    const double* p = xyz + 3 * static_cast<int64_t>(ids[k]);
    centroid[0] += scale * p[0];
    centroid[1] += scale * p[1];
    centroid[2] += scale * p[2];
  }
  for (double& c : centroid)
  {
    c /= static_cast<double>(count);
  }
  double covariance[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
  for (size_t k = 0; k < count; ++k)
  {
    const double* p = xyz + 3 * static_cast<int64_t>(ids[k]);
    const double d[3] = { scale * p[0] - centroid[0], scale * p[1] - centroid[1],
      scale * p[2] - centroid[2] };
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        covariance[i][j] += d[i] * d[j];
      }
    }
  }
  double* rows[3] = { covariance[0], covariance[1], covariance[2] };
  double eigenvalues[3], storage[3][3];
  double* vectors[3] = { storage[0], storage[1], storage[2] };
  vtkMath::Jacobi(rows, eigenvalues, vectors); // decreasing eigenvalues, eigenvectors in columns
  for (int i = 0; i < 3; ++i)
  {
    this->Origin[i] = centroid[i] / scale;
    this->U[i] = vectors[i][0];
    this->V[i] = vectors[i][1];
  }
  vtkMath::Cross(this->U, this->V, this->N);
  return count >= 3 && std::isfinite(this->N[0]) && std::isfinite(this->N[1]) &&
    std::isfinite(this->N[2]);
}

void Plane::Project(const double* p, double uv[2]) const
{
  const double d[3] = { p[0] - this->Origin[0], p[1] - this->Origin[1], p[2] - this->Origin[2] };
  uv[0] = d[0] * this->U[0] + d[1] * this->U[1] + d[2] * this->U[2];
  uv[1] = d[0] * this->V[0] + d[1] * this->V[1] + d[2] * this->V[2];
}

void Plane::Lift(const double uv[2], double p[3]) const
{
  for (int i = 0; i < 3; ++i)
  {
    p[i] = this->Origin[i] + uv[0] * this->U[i] + uv[1] * this->V[i];
  }
}

double Plane::Distance(const double* p) const
{
  const double d[3] = { p[0] - this->Origin[0], p[1] - this->Origin[1], p[2] - this->Origin[2] };
  return d[0] * this->N[0] + d[1] * this->N[1] + d[2] * this->N[2];
}

void Plane::Flip()
{
  for (int i = 0; i < 3; ++i)
  {
    this->V[i] = -this->V[i];
    this->N[i] = -this->N[i];
  }
}

//------------------------------------------------------------------------------------------------
double SignedArea2(const std::vector<double>& uv)
{
  const size_t n = uv.size() / 2;
  double area = 0.0;
  for (size_t i = 0; i < n; ++i)
  {
    const size_t j = (i + 1) % n;
    area += uv[2 * i] * uv[2 * j + 1] - uv[2 * j] * uv[2 * i + 1];
  }
  return area;
}

bool SegmentsIntersect(const double* p, const double* q, const double* r, const double* s)
{
  const int o1 = Orient2D(p, q, r);
  const int o2 = Orient2D(p, q, s);
  const int o3 = Orient2D(r, s, p);
  const int o4 = Orient2D(r, s, q);
  if (o1 * o2 < 0 && o3 * o4 < 0)
  {
    return true;
  }
  return (o1 == 0 && OnClosedSegment(p, q, r)) || (o2 == 0 && OnClosedSegment(p, q, s)) ||
    (o3 == 0 && OnClosedSegment(r, s, p)) || (o4 == 0 && OnClosedSegment(r, s, q));
}

namespace
{
// Exact: the closed segment pq meets the closed triangle abc.
bool SegmentMeetsTriangle(const double* p,
  const double* q,
  const double* a,
  const double* b,
  const double* c)
{
  using predicates::Orient3D;
  const int sideP = Orient3D(a, b, c, p), sideQ = Orient3D(a, b, c, q);
  if (sideP * sideQ > 0)
  {
    return false;
  }
  if (sideP != 0 || sideQ != 0)
  {
    // The segment meets the plane at one point: on the line pq, inside the closed triangle
    // when the line does not pass strictly on both sides of its edges.
    const int s1 = Orient3D(p, q, a, b), s2 = Orient3D(p, q, b, c), s3 = Orient3D(p, q, c, a);
    const bool positive = s1 > 0 || s2 > 0 || s3 > 0, negative = s1 < 0 || s2 < 0 || s3 < 0;
    return !(positive && negative);
  }
  // Coplanar: on a coordinate plane where the triangle keeps a non-zero area (an affine map of
  // the common plane, which keeps every incidence).
  for (int drop = 2; drop >= 0; --drop)
  {
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    const double A[2] = { a[i], a[j] }, B[2] = { b[i], b[j] }, C[2] = { c[i], c[j] };
    const int turn = Orient2D(A, B, C);
    if (turn == 0)
    {
      continue;
    }
    const double P[2] = { p[i], p[j] }, Q[2] = { q[i], q[j] };
    auto inside = [&](const double* x)
    {
      return Orient2D(A, B, x) * turn >= 0 && Orient2D(B, C, x) * turn >= 0 &&
        Orient2D(C, A, x) * turn >= 0;
    };
    return inside(P) || inside(Q) || SegmentsIntersect(P, Q, A, B) ||
      SegmentsIntersect(P, Q, B, C) || SegmentsIntersect(P, Q, C, A);
  }
  return false; // zero-area triangle
}
} // namespace

bool TrianglesIntersect(const double* a,
  const double* b,
  const double* c,
  const double* d,
  const double* e,
  const double* f)
{
  if (projected::Collinear(a, b, c) || projected::Collinear(d, e, f))
  {
    return false;
  }
  return SegmentMeetsTriangle(a, b, d, e, f) || SegmentMeetsTriangle(b, c, d, e, f) ||
    SegmentMeetsTriangle(c, a, d, e, f) || SegmentMeetsTriangle(d, e, a, b, c) ||
    SegmentMeetsTriangle(e, f, a, b, c) || SegmentMeetsTriangle(f, d, a, b, c);
}

bool IsSimplePolygon(const std::vector<double>& uv)
{
  const size_t n = uv.size() / 2;
  if (n < 3)
  {
    return false;
  }
  auto P = [&uv](size_t i) { return &uv[2 * i]; };
  for (size_t i = 0; i < n; ++i)
  {
    const size_t next = (i + 1) % n, previous = (i + n - 1) % n;
    if (SamePoint(P(i), P(next)))
    {
      return false; // zero-length edge
    }
    // Adjacent edges meet only at their common vertex: no fold-back along a line.
    if (OverlapAtSharedEnd(P(i), P(previous), P(next)))
    {
      return false;
    }
  }
  // Non-adjacent edges must not meet: sweep over the edges sorted by their smallest u.
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto lo = [&](size_t e) { return std::min(P(e)[0], P((e + 1) % n)[0]); };
  auto hi = [&](size_t e) { return std::max(P(e)[0], P((e + 1) % n)[0]); };
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return lo(a) < lo(b); });
  for (size_t a = 0; a < n; ++a)
  {
    const size_t e = order[a];
    const double* e0 = P(e);
    const double* e1 = P((e + 1) % n);
    const double eHi = hi(e);
    const double eYLo = std::min(e0[1], e1[1]), eYHi = std::max(e0[1], e1[1]);
    for (size_t b = a + 1; b < n && lo(order[b]) <= eHi; ++b)
    {
      const size_t f = order[b];
      if (f == (e + 1) % n || e == (f + 1) % n)
      {
        continue; // adjacent: checked above
      }
      const double* f0 = P(f);
      const double* f1 = P((f + 1) % n);
      if (std::max(f0[1], f1[1]) < eYLo || std::min(f0[1], f1[1]) > eYHi)
      {
        continue;
      }
      if (SegmentsIntersect(e0, e1, f0, f1))
      {
        return false;
      }
    }
  }
  return true;
}

namespace
{
// p lies strictly inside an edge of the closed loop in space (exact).
bool OnLoopEdge3D(const double* xyz, const std::vector<int32_t>& loop, const double* p)
{
  const size_t n = loop.size();
  for (size_t i = 0; i < n; ++i)
  {
    if (pcs::projected::OnOpenSegment3D(xyz + 3 * static_cast<int64_t>(loop[i]),
          xyz + 3 * static_cast<int64_t>(loop[(i + 1) % n]),
          p))
    {
      return true;
    }
  }
  return false;
}
} // namespace

int PointInPolygon(const std::vector<double>& uv, const double* p)
{
  const size_t n = uv.size() / 2;
  int winding = 0;
  for (size_t i = 0; i < n; ++i)
  {
    const double* a = &uv[2 * i];
    const double* b = &uv[2 * ((i + 1) % n)];
    const bool inBox = std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
      std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
    const int o = (inBox || (a[1] <= p[1]) != (b[1] <= p[1])) ? Orient2D(a, b, p) : 0;
    if (inBox && o == 0)
    {
      return 0; // on the edge
    }
    if (a[1] <= p[1] && b[1] > p[1] && o > 0)
    {
      ++winding; // upward crossing, p on the left
    }
    else if (a[1] > p[1] && b[1] <= p[1] && o < 0)
    {
      --winding; // downward crossing, p on the right
    }
  }
  return winding != 0 ? 1 : -1;
}

//------------------------------------------------------------------------------------------------
bool GreedyTriangulation2D(const std::vector<double>& uv,
  const std::vector<double>& xyz,
  int n,
  const std::function<bool(int, int)>& forbidden,
  std::vector<int32_t>& triangles,
  const std::function<double(int, int)>& length2)
{
  const int count = static_cast<int>(uv.size() / 2);
  const int m = count - n;
  if (n < 3 || m < 0)
  {
    return false;
  }
  auto P = [&uv](int i) { return &uv[2 * i]; };
  auto isLoopEdge = [n](int i, int j) {
    return i < n && j < n && ((j == (i + 1) % n) || (i == (j + 1) % n));
  };

  std::vector<std::vector<int>> adjacency(count);
  std::vector<std::pair<int, int>> accepted;
  accepted.reserve(3 * static_cast<size_t>(count));
  for (int i = 0; i < n; ++i)
  {
    const int j = (i + 1) % n;
    accepted.emplace_back(i, j);
    adjacency[i].push_back(j);
    adjacency[j].push_back(i);
  }

  // Candidates: every other pair, by increasing 3D length (ties by ids: deterministic).
  struct Candidate
  {
    double Length2;
    int I, J;
  };
  std::vector<Candidate> candidates;
  candidates.reserve(static_cast<size_t>(count) * (count - 1) / 2);
  for (int i = 0; i < count; ++i)
  {
    for (int j = i + 1; j < count; ++j)
    {
      if (isLoopEdge(i, j))
      {
        continue;
      }
      if (j < n)
      {
        // Between two loop vertices: a diagonal leaves each end into the polygon.
        if (!InsideWedge(P((i + n - 1) % n), P(i), P((i + 1) % n), P(j)) ||
          !InsideWedge(P((j + n - 1) % n), P(j), P((j + 1) % n), P(i)))
        {
          continue;
        }
      }
      if (forbidden && forbidden(i, j))
      {
        continue;
      }
      const double* a = &xyz[3 * static_cast<size_t>(i)];
      const double* b = &xyz[3 * static_cast<size_t>(j)];
      const double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
      candidates.push_back(
        { length2 ? length2(i, j) : d[0] * d[0] + d[1] * d[1] + d[2] * d[2], i, j });
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.Length2 != b.Length2 ? a.Length2 < b.Length2
                                  : (a.I != b.I ? a.I < b.I : a.J < b.J);
  });

  // A triangulation of the polygon with its m interior points has 2n + 3m - 3 edges.
  const size_t complete = static_cast<size_t>(2 * n + 3 * m - 3);
  for (const Candidate& c : candidates)
  {
    if (accepted.size() >= complete)
    {
      break;
    }
    const double* a = P(c.I);
    const double* b = P(c.J);
    const double minU = std::min(a[0], b[0]), maxU = std::max(a[0], b[0]);
    const double minV = std::min(a[1], b[1]), maxV = std::max(a[1], b[1]);
    bool compatible = true;
    const double* a3 = &xyz[3 * static_cast<size_t>(c.I)];
    const double* b3 = &xyz[3 * static_cast<size_t>(c.J)];
    for (int k = 0; k < count && compatible; ++k)
    {
      if (k != c.I && k != c.J && P(k)[0] >= minU && P(k)[0] <= maxU && P(k)[1] >= minV &&
        P(k)[1] <= maxV && OnOpenSegment(a, b, P(k)))
      {
        compatible = false; // passes through a point
      }
      else if (k != c.I && k != c.J &&
        pcs::projected::OnOpenSegment3D(a3, b3, &xyz[3 * static_cast<size_t>(k)]))
      {
        // Through a point in space: its rounded projection may miss the segment, and the edge
        // would close a zero-area triangle (points on a grid, quantised coordinates).
        compatible = false;
      }
    }
    for (size_t e = 0; e < accepted.size() && compatible; ++e)
    {
      const int r = accepted[e].first, s = accepted[e].second;
      const double* pr = P(r);
      const double* ps = P(s);
      if (std::max(pr[0], ps[0]) < minU || std::min(pr[0], ps[0]) > maxU ||
        std::max(pr[1], ps[1]) < minV || std::min(pr[1], ps[1]) > maxV)
      {
        continue;
      }
      const bool sharesI = (r == c.I || s == c.I), sharesJ = (r == c.J || s == c.J);
      if (sharesI && sharesJ)
      {
        compatible = false; // already accepted (cannot happen: pairs are unique)
      }
      else if (sharesI)
      {
        compatible = !OverlapAtSharedEnd(a, b, r == c.I ? ps : pr);
      }
      else if (sharesJ)
      {
        compatible = !OverlapAtSharedEnd(b, a, r == c.J ? ps : pr);
      }
      else
      {
        compatible = !SegmentsIntersect(a, b, pr, ps);
      }
    }
    if (compatible)
    {
      accepted.emplace_back(c.I, c.J);
      adjacency[c.I].push_back(c.J);
      adjacency[c.J].push_back(c.I);
    }
  }

  // Triangles: the empty 3-cycles of accepted edges (each found once, from its smallest id).
  int found = 0;
  for (int u = 0; u < count; ++u)
  {
    for (int v : adjacency[u])
    {
      if (v <= u)
      {
        continue;
      }
      for (int w : adjacency[v])
      {
        if (w <= v || std::find(adjacency[u].begin(), adjacency[u].end(), w) == adjacency[u].end())
        {
          continue;
        }
        const int o = Orient2D(P(u), P(v), P(w));
        if (o == 0 ||
          pcs::projected::Collinear(&xyz[3 * static_cast<size_t>(u)],
            &xyz[3 * static_cast<size_t>(v)],
            &xyz[3 * static_cast<size_t>(w)]))
        {
          continue; // zero area in space, whatever its rounded projection
        }
        const int t[3] = { u, o > 0 ? v : w, o > 0 ? w : v };
        bool empty = true;
        for (int k = 0; k < count && empty; ++k)
        {
          if (k != u && k != v && k != w && Orient2D(P(t[0]), P(t[1]), P(k)) > 0 &&
            Orient2D(P(t[1]), P(t[2]), P(k)) > 0 && Orient2D(P(t[2]), P(t[0]), P(k)) > 0)
          {
            empty = false;
          }
        }
        if (empty)
        {
          triangles.insert(triangles.end(), { t[0], t[1], t[2] });
          ++found;
        }
      }
    }
  }
  return found == n + 2 * m - 2;
}

//------------------------------------------------------------------------------------------------
struct HoleFiller::Piece
{
  std::vector<int32_t> Loop;
  std::vector<double> Vectors; // 3 per loop vertex
  std::unordered_set<uint64_t>* Created = nullptr; // edges made by earlier pieces of the hole
};

bool HoleFiller::HasUnambiguousProjection(const double* xyz, const std::vector<int32_t>& loop,
  const std::vector<double>& boundaryVectors, Plane& plane) const
{
  const size_t n = loop.size();
  if (n < 3 || !plane.Fit(xyz, loop.data(), n))
  {
    return false;
  }
  std::vector<double> uv(2 * n);
  for (size_t i = 0; i < n; ++i)
  {
    plane.Project(xyz + 3 * static_cast<int64_t>(loop[i]), &uv[2 * i]);
  }
  if (SignedArea2(uv) < 0)
  {
    plane.Flip();
    for (size_t i = 0; i < n; ++i)
    {
      uv[2 * i + 1] = -uv[2 * i + 1];
    }
  }
  if (!IsSimplePolygon(uv) || SimplePolygonOrientation(uv) <= 0)
  {
    return false;
  }
  if (this->AuxiliaryDistance > 0 && boundaryVectors.size() >= 3 * n)
  {
    for (size_t i = 0; i < n; ++i)
    {
      const double* v = &boundaryVectors[3 * i];
      const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      if (!(length > 0) || !std::isfinite(length))
      {
        continue;
      }
      const double* p = xyz + 3 * static_cast<int64_t>(loop[i]);
      const double scale = this->AuxiliaryDistance / length;
      const double auxiliary[3] = { p[0] + scale * v[0], p[1] + scale * v[1],
        p[2] + scale * v[2] };
      double q[2];
      plane.Project(auxiliary, q);
      if (PointInPolygon(uv, q) >= 0)
      {
        return false; // the surrounding mesh folds over the hole in this projection
      }
    }
  }
  return true;
}

bool HoleFiller::ProjectsToSimplePolygon(
  const double* xyz, const std::vector<int32_t>& loop, Plane& plane) const
{
  const size_t n = loop.size();
  if (n < 3 || !plane.Fit(xyz, loop.data(), n))
  {
    return false;
  }
  std::vector<double> uv(2 * n);
  for (size_t i = 0; i < n; ++i)
  {
    plane.Project(xyz + 3 * static_cast<int64_t>(loop[i]), &uv[2 * i]);
  }
  if (!IsSimplePolygon(uv))
  {
    return false;
  }
  if (SimplePolygonOrientation(uv) < 0)
  {
    plane.Flip();
  }
  return true;
}

// Split a piece by a chord (plane == nullptr: step 5, chosen in 3D) or by a diagonal of its
// projection `uv` (a piece too large for one greedy triangulation).
bool HoleFiller::SplitPiece(const double* xyz, const Piece& piece, const Plane* plane,
  const std::vector<double>* uv, Piece& first, Piece& second) const
{
  const std::vector<int32_t>& loop = piece.Loop;
  const int n = static_cast<int>(loop.size());
  if (n < 4)
  {
    return false;
  }
  auto X = [xyz, &loop](int i) { return xyz + 3 * static_cast<int64_t>(loop[i]); };
  std::vector<double> arc(n + 1, 0.0);
  for (int i = 0; i < n; ++i)
  {
    arc[i + 1] = arc[i] + Distance3(X(i), X((i + 1) % n));
  }
  const double perimeter = arc[n];

  struct Chord
  {
    double Score;
    int I, J;
  };
  std::vector<Chord> chords;
  for (int i = 0; i < n; ++i)
  {
    for (int j = i + 2; j < n; ++j)
    {
      if ((i == 0 && j == n - 1) || loop[i] == loop[j])
      {
        continue;
      }
      const double along = arc[j] - arc[i];
      const double shorter = std::min(along, perimeter - along);
      const double length = Distance3(X(i), X(j));
      chords.push_back({ shorter > 0 ? length / shorter : std::numeric_limits<double>::max(), i,
        j });
    }
  }
  // The chords in increasing score (ties by I, then J), taken from a heap as the passes reach
  // them: the first acceptable chord usually comes early, so the whole list is rarely sorted.
  auto later = [](const Chord& a, const Chord& b)
  { return a.Score != b.Score ? a.Score > b.Score : (a.I != b.I ? a.I > b.I : a.J > b.J); };
  std::make_heap(chords.begin(), chords.end(), later);
  std::vector<Chord> ordered;
  auto chordAt = [&](size_t k) -> const Chord*
  {
    while (ordered.size() <= k && !chords.empty())
    {
      std::pop_heap(chords.begin(), chords.end(), later);
      ordered.push_back(chords.back());
      chords.pop_back();
    }
    return k < ordered.size() ? &ordered[k] : nullptr;
  };

  auto forbidden = [this, &piece](int32_t a, int32_t b) {
    return (this->EdgeExists && this->EdgeExists(a, b)) ||
      (piece.Created && piece.Created->count(EdgeKey(a, b)));
  };
  auto towardsHole = [&](int i, int j) {
    const double* v = &piece.Vectors[3 * static_cast<size_t>(i)];
    const double* a = X(i);
    const double* b = X(j);
    const double d = v[0] * (b[0] - a[0]) + v[1] * (b[1] - a[1]) + v[2] * (b[2] - a[2]);
    return !(v[0] != 0 || v[1] != 0 || v[2] != 0) || d < 0;
  };
  auto isDiagonal = [&](int i, int j) {
    const std::vector<double>& q = *uv;
    auto P = [&q](int k) { return &q[2 * static_cast<size_t>(k)]; };
    if (!InsideWedge(P((i + n - 1) % n), P(i), P((i + 1) % n), P(j)) ||
      !InsideWedge(P((j + n - 1) % n), P(j), P((j + 1) % n), P(i)))
    {
      return false;
    }
    for (int e = 0; e < n; ++e)
    {
      const int f = (e + 1) % n;
      const bool atI = (e == i || f == i), atJ = (e == j || f == j);
      if (atI && atJ)
      {
        continue;
      }
      if (atI)
      {
        if (OverlapAtSharedEnd(P(i), P(j), P(e == i ? f : e)))
        {
          return false;
        }
      }
      else if (atJ)
      {
        if (OverlapAtSharedEnd(P(j), P(i), P(e == j ? f : e)))
        {
          return false;
        }
      }
      else if (SegmentsIntersect(P(i), P(j), P(e), P(f)))
      {
        return false;
      }
    }
    return true;
  };

  for (int pass = 0; pass < 2; ++pass)
  {
    for (size_t next = 0; const Chord* chord = chordAt(next); ++next)
    {
      const Chord& c = *chord;
      if (forbidden(loop[c.I], loop[c.J]))
      {
        continue;
      }
      if (plane)
      {
        if (!isDiagonal(c.I, c.J))
        {
          continue;
        }
      }
      else if (pass == 0 && (!towardsHole(c.I, c.J) || !towardsHole(c.J, c.I)))
      {
        continue;
      }
      first = Piece();
      second = Piece();
      first.Created = second.Created = piece.Created;
      for (int k = c.I; k <= c.J; ++k)
      {
        first.Loop.push_back(loop[k]);
        first.Vectors.insert(first.Vectors.end(), &piece.Vectors[3 * k], &piece.Vectors[3 * k + 3]);
      }
      for (int k = c.J; k != c.I + n + 1; ++k)
      {
        const int kk = k % n;
        second.Loop.push_back(loop[kk]);
        second.Vectors.insert(
          second.Vectors.end(), &piece.Vectors[3 * kk], &piece.Vectors[3 * kk + 3]);
      }
      return true;
    }
    if (plane)
    {
      break; // a diagonal always exists in a simple polygon, unless all are forbidden
    }
  }
  return false;
}

bool HoleFiller::FillPiece(const double* xyz, Piece& piece, std::vector<char>& taken,
  const std::vector<int32_t>& candidates, FillResult& result, int depth) const
{
  std::vector<int32_t>& loop = piece.Loop;
  // Consecutive repeats (a zero-length edge) are dropped.
  for (size_t i = 0; loop.size() > 1 && i < loop.size();)
  {
    const size_t next = (i + 1) % loop.size();
    if (loop[i] == loop[next])
    {
      loop.erase(loop.begin() + next);
      piece.Vectors.erase(piece.Vectors.begin() + 3 * next, piece.Vectors.begin() + 3 * next + 3);
      i = 0;
      continue;
    }
    ++i;
  }
  const int n = static_cast<int>(loop.size());
  if (n < 3)
  {
    return true; // a slit or a point: nothing to fill
  }
  if (n == 3 &&
    pcs::projected::Collinear(xyz + 3 * static_cast<int64_t>(loop[0]),
      xyz + 3 * static_cast<int64_t>(loop[1]), xyz + 3 * static_cast<int64_t>(loop[2])))
  {
    ++result.NumberOfFailedPieces; // three collinear points: only a zero-area triangle would fill
    return false;
  }
  if (depth > 4 * n + 64)
  {
    ++result.NumberOfFailedPieces;
    return false;
  }
  // A vertex met twice: the hole touches itself there; split it into two loops.
  for (int i = 0; i < n && this->SplitAtRepeatedVertices; ++i)
  {
    for (int j = i + 1; j < n; ++j)
    {
      if (loop[i] == loop[j])
      {
        Piece a, b;
        a.Created = b.Created = piece.Created;
        for (int k = i; k < j; ++k)
        {
          a.Loop.push_back(loop[k]);
          a.Vectors.insert(a.Vectors.end(), &piece.Vectors[3 * k], &piece.Vectors[3 * k + 3]);
        }
        for (int k = j; k != i + n; ++k)
        {
          const int kk = k % n;
          b.Loop.push_back(loop[kk]);
          b.Vectors.insert(b.Vectors.end(), &piece.Vectors[3 * kk], &piece.Vectors[3 * kk + 3]);
        }
        const bool okA = this->FillPiece(xyz, a, taken, candidates, result, depth + 1);
        const bool okB = this->FillPiece(xyz, b, taken, candidates, result, depth + 1);
        return okA && okB;
      }
    }
  }

  auto splitAndFill = [&](const Plane* plane, const std::vector<double>* uv) {
    Piece a, b;
    if (!this->SplitPiece(xyz, piece, plane, uv, a, b))
    {
      ++result.NumberOfFailedPieces;
      return false;
    }
    result.Chords.push_back({ a.Loop.front(), a.Loop.back() });
    if (piece.Created)
    {
      piece.Created->insert(EdgeKey(a.Loop.front(), a.Loop.back()));
    }
    const bool okA = this->FillPiece(xyz, a, taken, candidates, result, depth + 1);
    const bool okB = this->FillPiece(xyz, b, taken, candidates, result, depth + 1);
    return okA && okB;
  };

  // Step 5: split until the projection is unambiguous. A piece that cannot be split is
  // triangulated all the same when its projection is at least a simple polygon (the auxiliary
  // point test is a heuristic; a triangle is its own only triangulation).
  Plane plane;
  if (!this->HasUnambiguousProjection(xyz, loop, piece.Vectors, plane))
  {
    Piece a, b;
    const bool simple = n == 3 || this->ProjectsToSimplePolygon(xyz, loop, plane);
    if (!simple || (n > 3 && this->SplitPiece(xyz, piece, nullptr, nullptr, a, b)))
    {
      return splitAndFill(nullptr, nullptr);
    }
    if (n == 3)
    {
      plane.Fit(xyz, loop.data(), 3);
      std::vector<double> q(6);
      for (int i = 0; i < 3; ++i)
      {
        plane.Project(xyz + 3 * static_cast<int64_t>(loop[i]), &q[2 * i]);
      }
      if (SignedArea2(q) < 0)
      {
        plane.Flip();
      }
    }
  }

  std::vector<double> uv(2 * static_cast<size_t>(n));
  double radius = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const double* p = xyz + 3 * static_cast<int64_t>(loop[i]);
    plane.Project(p, &uv[2 * static_cast<size_t>(i)]);
    radius = std::max(radius, Distance3(p, plane.Origin));
  }

  // The lost points inside the piece: strictly inside its projection, near its plane, not
  // coinciding in projection with another point.
  std::vector<int32_t> inside;
  std::vector<double> insideUV;
  std::vector<double> insideHeight; // distance to the plane
  for (size_t k = 0; k < candidates.size(); ++k)
  {
    if (taken[k])
    {
      continue;
    }
    const double* p = xyz + 3 * static_cast<int64_t>(candidates[k]);
    const double height = std::fabs(plane.Distance(p));
    if (!(height <= 0.5 * radius))
    {
      continue;
    }
    double q[2];
    plane.Project(p, q);
    if (PointInPolygon(uv, q) <= 0)
    {
      continue;
    }
    if (OnLoopEdge3D(xyz, loop, p))
    {
      continue; // only a zero-area triangle would join it to that edge
    }
    inside.push_back(static_cast<int32_t>(k));
    insideUV.insert(insideUV.end(), { q[0], q[1] });
    insideHeight.push_back(height);
  }
  // Points coinciding in projection: the first in candidate order is used, the others stay lost.
  {
    std::vector<int32_t> first;
    const int32_t count = static_cast<int32_t>(inside.size());
    if (FindExactDuplicates(insideUV.data(), 2, nullptr, count, first) < count)
    {
      size_t kept = 0;
      for (int32_t j = 0; j < count; ++j)
      {
        if (first[j] == j)
        {
          inside[kept] = inside[j];
          insideUV[2 * kept] = insideUV[2 * static_cast<size_t>(j)];
          insideUV[2 * kept + 1] = insideUV[2 * static_cast<size_t>(j) + 1];
          insideHeight[kept++] = insideHeight[j];
        }
      }
      inside.resize(kept);
      insideUV.resize(2 * kept);
      insideHeight.resize(kept);
    }
  }

  const int maximum = std::max(this->MaximumGreedyPoints, 3);
  if (n + static_cast<int>(inside.size()) > maximum)
  {
    if (n >= 4)
    {
      return splitAndFill(&plane, &uv);
    }
    // A triangle cannot be split further: it keeps the points nearest its plane, up to the
    // bound; the others stay lost (a dense cluster inside one triangle would otherwise make
    // the quadratic triangulation below unbounded).
    std::vector<size_t> order(inside.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
      [&insideHeight](size_t a, size_t b) { return insideHeight[a] < insideHeight[b]; });
    order.resize(static_cast<size_t>(maximum - n));
    std::sort(order.begin(), order.end());
    std::vector<int32_t> keptInside;
    std::vector<double> keptUV;
    for (size_t s : order)
    {
      keptInside.push_back(inside[s]);
      keptUV.insert(keptUV.end(), { insideUV[2 * s], insideUV[2 * s + 1] });
    }
    inside.swap(keptInside);
    insideUV.swap(keptUV);
  }

  // Step 6: the greedy triangulation of the projected piece and its points.
  std::vector<int32_t> ids(loop);
  std::vector<double> local3(3 * static_cast<size_t>(n));
  for (int i = 0; i < n; ++i)
  {
    std::copy_n(xyz + 3 * static_cast<int64_t>(loop[i]), 3, &local3[3 * static_cast<size_t>(i)]);
  }
  for (size_t s = 0; s < inside.size(); ++s)
  {
    const int32_t id = candidates[inside[s]];
    ids.push_back(id);
    uv.insert(uv.end(), { insideUV[2 * s], insideUV[2 * s + 1] });
    local3.insert(local3.end(), xyz + 3 * static_cast<int64_t>(id), xyz + 3 * static_cast<int64_t>(id) + 3);
  }
  auto forbidden = [this, &ids, &piece](int i, int j) {
    return (this->EdgeExists && this->EdgeExists(ids[i], ids[j])) ||
      (piece.Created && piece.Created->count(EdgeKey(ids[i], ids[j])));
  };
  std::function<double(int, int)> length2;
  if (this->Length2)
  {
    length2 = [this, &ids, &local3](int i, int j)
    {
      const double given = this->Length2(ids[i], ids[j]);
      const double* a = &local3[3 * static_cast<size_t>(i)];
      const double* b = &local3[3 * static_cast<size_t>(j)];
      const double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
      return given >= 0.0 ? given : d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    };
  }
  std::vector<int32_t> local;
  const bool complete = GreedyTriangulation2D(uv, local3, n, forbidden, local, length2);
  std::vector<char> usedLocal(ids.size(), 0);
  for (size_t t = 0; t < local.size(); t += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      result.Triangles.push_back(ids[local[t + k]]);
      usedLocal[local[t + k]] = 1;
      if (piece.Created)
      {
        piece.Created->insert(EdgeKey(ids[local[t + k]], ids[local[t + (k + 1) % 3]]));
      }
    }
  }
  for (size_t s = 0; s < inside.size(); ++s)
  {
    if (usedLocal[n + s])
    {
      taken[inside[s]] = 1;
      result.UsedPoints.push_back(ids[n + s]);
    }
  }
  ++result.NumberOfPieces;
  if (!complete)
  {
    ++result.NumberOfFailedPieces;
  }
  return complete;
}

bool HoleFiller::Fill(const double* xyz, const std::vector<int32_t>& loop,
  const std::vector<double>& boundaryVectors, const std::vector<int32_t>& candidates,
  FillResult& result) const
{
  result = FillResult();
  std::unordered_set<uint64_t> created;
  Piece piece;
  piece.Loop = loop;
  piece.Vectors = boundaryVectors;
  piece.Vectors.resize(3 * loop.size(), 0.0);
  piece.Created = &created;
  // The loop's own edges (bridges among them, which the mesh does not have yet) are never
  // created again inside the hole.
  for (size_t i = 0; i < loop.size(); ++i)
  {
    created.insert(EdgeKey(loop[i], loop[(i + 1) % loop.size()]));
  }
  std::vector<char> taken(candidates.size(), 0);
  result.Complete = this->FillPiece(xyz, piece, taken, candidates, result, 0);
  return !result.Triangles.empty();
}

//------------------------------------------------------------------------------------------------
// Triangulation of a loop by its own vertices (vtkGreedySurfaceTriangulation's fallback when the
// projected fill fails): the triangulation of the loop polygon (its vertices only) that minimises
// first the largest dihedral angle (between adjacent fill triangles, and between a fill triangle
// and the mesh triangle across a loop edge) and then the area, by dynamic programming over the
// sub-polygons (Liepa, "Filling Holes in Meshes", SGP 2003, section 3.1). A diagonal that is an
// edge of the mesh already and an exactly degenerate triangle are forbidden. `across(e)` gives the
// unit normal of the mesh triangle on the loop edge loop[e] -> loop[e + 1] (false when none).
// Triangles in loop order are appended to `triangles`; the largest dihedral angle (radians) is
// returned, or a negative value when there is no triangulation (or the loop has more than 400
// vertices: the cost is cubic). No sub-polygon's triangulation whose angle exceeds `maximumAngle`
// (beyond the tie tolerance) is kept: the caller refuses such fills anyway.
void LoopVectorArea(const double* xyz, const std::vector<int32_t>& loop, double area[3])
{
  area[0] = area[1] = area[2] = 0.0;
  if (loop.empty())
  {
    return;
  }
  const double* origin = xyz + 3 * static_cast<size_t>(loop[0]);
  for (size_t i = 1; i + 1 < loop.size(); ++i)
  {
    const double* p = xyz + 3 * static_cast<size_t>(loop[i]);
    const double* q = xyz + 3 * static_cast<size_t>(loop[i + 1]);
    const double u[3] = { p[0] - origin[0], p[1] - origin[1], p[2] - origin[2] };
    const double v[3] = { q[0] - origin[0], q[1] - origin[1], q[2] - origin[2] };
    double c[3];
    vtkMath::Cross(u, v, c);
    for (int k = 0; k < 3; ++k)
    {
      area[k] += 0.5 * c[k];
    }
  }
}

double LeastDihedralFill(const double* xyz,
  const std::vector<int32_t>& loop,
  const std::function<bool(int32_t, int32_t)>& edgeExists,
  const std::function<bool(int, double[3])>& across,
  std::vector<int32_t>& triangles,
  double maximumAngle)
{
  const int n = static_cast<int>(loop.size());
  if (n < 3 || n > static_cast<int>(MaximumFillLoopEdges))
  {
    return -1.0;
  }
  const double inf = std::numeric_limits<double>::infinity();
  auto at = [n](int i, int j) { return static_cast<size_t>(i) * n + j; };
  std::vector<double> angle(static_cast<size_t>(n) * n, inf), area(angle);
  std::vector<int> best(static_cast<size_t>(n) * n, -1);
  auto point = [&](int i) { return xyz + 3 * static_cast<size_t>(loop[i]); };
  auto unitNormal = [&](int a, int b, int c, double nrm[3]) {
    double u[3], v[3];
    vtkMath::Subtract(point(b), point(a), u);
    vtkMath::Subtract(point(c), point(a), v);
    vtkMath::Cross(u, v, nrm);
    return 0.5 * vtkMath::Normalize(nrm);
  };
  // The unit normal of the triangle on the side (i, j) of the sub-polygon i..j, once (i, j) is
  // solved: the mesh triangle across the loop edge when j = i + 1, else the sub-polygon's triangle
  // on (i, j). `hasSide` is 0 where there is none.
  std::vector<double> sideNormal(3 * static_cast<size_t>(n) * n, 0.0);
  std::vector<char> hasSide(static_cast<size_t>(n) * n, 0);
  // The cosine of each solved sub-polygon's angle (1 for a loop edge's 0).
  std::vector<double> cosine(static_cast<size_t>(n) * n, 1.0);
  for (int i = 0; i + 1 < n; ++i)
  {
    angle[at(i, i + 1)] = 0.0;
    area[at(i, i + 1)] = 0.0;
    hasSide[at(i, i + 1)] = across(i, &sideNormal[3 * at(i, i + 1)]) ? 1 : 0;
  }
  double outerNormal[3];
  const bool hasOuter = across(n - 1, outerNormal);
  const double capCut =
    maximumAngle < inf ? std::cos(std::min(maximumAngle + 1e-9, vtkMath::Pi())) - 1e-12 : -inf;
  for (int span = 2; span < n; ++span)
  {
    for (int i = 0; i + span < n; ++i)
    {
      const int j = i + span;
      // (i, j) is a diagonal unless it is the loop edge (0, n - 1).
      const bool outer = i == 0 && j == n - 1;
      if (!outer && edgeExists && edgeExists(loop[i], loop[j]))
      {
        continue;
      }
      // The best candidate so far; a candidate whose angle with a neighbour exceeds `current`
      // (or `maximumAngle`) by more than the tie tolerance cannot be kept: its cosine is below
      // `cosineCut` (a margin of 1e-12 in cosine is more than 1e-12 radians, far above the
      // rounding of cos and acos).
      double current = inf, ceiling = maximumAngle, cosineCut = capCut;
      for (int k = i + 1; k < j; ++k)
      {
        // The sub-polygons' angles bound the candidate's from below: a candidate that cannot
        // beat the current best even on a tie is passed over before any normal is computed, and
        // the exact degeneracy test is made only for a candidate that would be kept.
        const double atLeast = std::max(angle[at(i, k)], angle[at(k, j)]);
        if (!(atLeast < inf) || atLeast > ceiling + 1e-9)
        {
          continue;
        }
        // Nor can one that is not clearly better by its sub-polygons and whose sub-polygons alone
        // have at least the best one's area (its triangle's area only adds to it).
        const double partsArea = area[at(i, k)] + area[at(k, j)];
        if (atLeast >= current - 1e-9 && partsArea >= area[at(i, j)])
        {
          continue;
        }
        double nrm[3];
        const double a = partsArea + unitNormal(i, k, j, nrm);
        const double* neighbours[3] = { hasSide[at(i, k)] ? &sideNormal[3 * at(i, k)] : nullptr,
          hasSide[at(k, j)] ? &sideNormal[3 * at(k, j)] : nullptr,
          outer && hasOuter ? outerNormal : nullptr };
        // The dihedral angles with the neighbours on its sides: the largest is the angle of the
        // smallest dot product (acos is decreasing: one acos per triangle).
        double smallestDot = inf;
        for (const double* neighbour : neighbours)
        {
          if (neighbour)
          {
            smallestDot = std::min(smallestDot, vtkMath::Dot(nrm, neighbour));
          }
        }
        if (smallestDot < cosineCut)
        {
          continue;
        }
        // A dot product above the sub-polygons' cosine (by the same margin) is an angle below
        // their largest one, which it does not change: no acos then.
        double worst = atLeast;
        const double atLeastCosine = std::min(cosine[at(i, k)], cosine[at(k, j)]) + 1e-12;
        if (smallestDot < inf && !(smallestDot > atLeastCosine))
        {
          worst = std::max(worst, std::acos(std::max(-1.0, std::min(1.0, smallestDot))));
        }
        // Lexicographic: the largest angle first (ties within 1e-9 radians), then the area.
        if ((worst < current - 1e-9 || (worst <= current + 1e-9 && a < area[at(i, j)])) &&
          !pcs::projected::Collinear(point(i), point(k), point(j)))
        {
          angle[at(i, j)] = current = worst;
          area[at(i, j)] = a;
          best[at(i, j)] = k;
          ceiling = std::min(current, maximumAngle);
          cosineCut = std::cos(std::min(ceiling + 1e-9, vtkMath::Pi())) - 1e-12;
        }
      }
      if (best[at(i, j)] >= 0)
      {
        unitNormal(i, best[at(i, j)], j, &sideNormal[3 * at(i, j)]);
        hasSide[at(i, j)] = 1;
        cosine[at(i, j)] = std::cos(angle[at(i, j)]);
      }
    }
  }
  if (best[at(0, n - 1)] < 0)
  {
    return -1.0;
  }
  std::vector<std::array<int, 2>> stack{ { 0, n - 1 } };
  while (!stack.empty())
  {
    const auto range = stack.back();
    stack.pop_back();
    const int k = best[at(range[0], range[1])];
    if (k < 0)
    {
      continue; // a loop edge
    }
    triangles.insert(triangles.end(), { loop[range[0]], loop[k], loop[range[1]] });
    stack.push_back({ range[0], k });
    stack.push_back({ k, range[1] });
  }
  return angle[at(0, n - 1)];
}

//------------------------------------------------------------------------------------------------
bool FillLoopNearSamples(const double* xyz,
  const std::vector<int32_t>& boundary,
  const SurfaceMesh& mesh,
  double reach,
  double maximumDihedral,
  const std::function<bool(const double*, double)>& nearSomePoint,
  std::vector<int32_t>& fill)
{
  fill.clear();
  const size_t m = boundary.size();
  if (m < 3)
  {
    return false;
  }
  auto point = [xyz](int32_t v) { return xyz + 3 * static_cast<size_t>(v); };
  const std::vector<int32_t> loop(boundary.rbegin(), boundary.rend());
  double perimeter = 0.0, area[3];
  for (size_t i = 0; i < m; ++i)
  {
    perimeter +=
      std::sqrt(vtkMath::Distance2BetweenPoints(point(loop[i]), point(loop[(i + 1) % m])));
  }
  LoopVectorArea(xyz, loop, area);
  if (!(std::sqrt(vtkMath::Dot(area, area)) <= 2.0 * perimeter * reach))
  {
    return false;
  }
  auto across = [&](int e, double n[3])
  {
    const int32_t a = loop[e], b = loop[(static_cast<size_t>(e) + 1) % m];
    const int32_t x = mesh.OppositeVertex(b, a); // the mesh triangle (b, a, x)
    if (x < 0)
    {
      return false;
    }
    pcs::projected::TriangleNormal(point(b), point(a), point(x), n);
    const double length = std::sqrt(vtkMath::Dot(n, n));
    if (!(length > 0.0) || !std::isfinite(length))
    {
      return false;
    }
    for (int k = 0; k < 3; ++k)
    {
      n[k] /= length;
    }
    return true;
  };
  auto exists = [&mesh](int32_t a, int32_t b) { return mesh.GetEdgeValence(a, b) > 0; };
  const double dihedral = LeastDihedralFill(xyz, loop, exists, across, fill);
  if (dihedral < 0.0 || dihedral > maximumDihedral || fill.empty())
  {
    fill.clear();
    return false;
  }
  for (size_t t = 0; t + 2 < fill.size(); t += 3)
  {
    const int32_t* v = &fill[t];
    const double* q[3] = { point(v[0]), point(v[1]), point(v[2]) };
    bool near =
      !pcs::projected::Collinear(q[0], q[1], q[2]) && mesh.OppositeVertex(v[1], v[0]) != v[2];
    if (near)
    {
      const double centroid[3] = { (q[0][0] + q[1][0] + q[2][0]) / 3.0,
        (q[0][1] + q[1][1] + q[2][1]) / 3.0,
        (q[0][2] + q[1][2] + q[2][2]) / 3.0 };
      near = nearSomePoint(centroid, reach);
    }
    for (int j = 0; j < 3 && near; ++j)
    {
      if (mesh.GetEdgeValence(v[j], v[(j + 1) % 3]) == 0)
      {
        const double* r = q[(j + 1) % 3];
        const double middle[3] = {
          0.5 * (q[j][0] + r[0]), 0.5 * (q[j][1] + r[1]), 0.5 * (q[j][2] + r[2])
        };
        near = nearSomePoint(middle, reach);
      }
    }
    if (!near)
    {
      fill.clear();
      return false;
    }
  }
  if (!FillIsSmallPartOfSurface(xyz, mesh, fill))
  {
    fill.clear();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------------------------
bool FillIsSmallPartOfSurface(
  const double* xyz, const SurfaceMesh& mesh, const std::vector<int32_t>& fill, double ratio)
{
  auto point = [xyz](int32_t v) { return xyz + 3 * static_cast<size_t>(v); };
  auto area = [&](const int32_t* v)
  {
    double n[3];
    pcs::projected::TriangleNormal(point(v[0]), point(v[1]), point(v[2]), n);
    return 0.5 * std::sqrt(vtkMath::Dot(n, n));
  };
  double fillArea = 0.0;
  std::vector<int64_t> stack;
  for (size_t t = 0; t + 2 < fill.size(); t += 3)
  {
    fillArea += area(&fill[t]);
    for (int j = 0; j < 3; ++j)
    {
      // The mesh triangle across the fill triangle's edge a -> b owns b -> a.
      const int64_t across = mesh.FindTriangle(fill[t + (j + 1) % 3], fill[t + j]);
      if (across >= 0)
      {
        stack.push_back(across);
      }
    }
  }
  const double wanted = ratio * fillArea;
  if (stack.empty() || !(fillArea > 0.0) || !std::isfinite(wanted))
  {
    return false;
  }
  std::unordered_set<int64_t> seen(stack.begin(), stack.end());
  double reached = 0.0;
  while (!stack.empty())
  {
    const int64_t t = stack.back();
    stack.pop_back();
    const int32_t* v = mesh.GetTriangle(t);
    reached += area(v);
    if (reached > wanted)
    {
      return true;
    }
    for (int j = 0; j < 3; ++j)
    {
      const int64_t next = mesh.FindTriangle(v[(j + 1) % 3], v[j]);
      if (next >= 0 && seen.insert(next).second)
      {
        stack.push_back(next);
      }
    }
  }
  return false;
}

//------------------------------------------------------------------------------------------------
namespace
{
// The loop alignment LV of the boundary loop through the half-edge a -> b (see
// JoinsLoopsAroundTube), or -1 when the loop has more than maxEdges edges, leaves the boundary or
// has no triangle of non-zero area on its edges.
double LoopAlignment(
  const SurfaceMesh& mesh, const double* xyz, int32_t a, int32_t b, int64_t maxEdges)
{
  // First walk: the centroid of the loop's vertices.
  double centroid[3] = { 0.0, 0.0, 0.0 };
  int64_t edges = 0;
  int32_t tail = a, head = b;
  do
  {
    if (head < 0 || edges >= maxEdges)
    {
      return -1.0;
    }
    vtkMath::Add(centroid, xyz + 3 * static_cast<size_t>(tail), centroid);
    ++edges;
    const int32_t next = mesh.NextBoundaryVertex(tail, head);
    tail = head;
    head = next;
  } while (!(tail == a && head == b));
  vtkMath::MultiplyScalar(centroid, 1.0 / static_cast<double>(edges));
  // Second walk: per edge, abs(n . (centroid - m)) and abs(centroid - m), with m the edge's
  // midpoint and n the unit normal of the mesh triangle on the edge.
  double along = 0.0, total = 0.0;
  do
  {
    const double* p = xyz + 3 * static_cast<size_t>(tail);
    const double* q = xyz + 3 * static_cast<size_t>(head);
    const int32_t opposite = mesh.OppositeVertex(tail, head);
    if (opposite < 0)
    {
      return -1.0;
    }
    double edge[3], side[3], normal[3], toCentroid[3];
    vtkMath::Subtract(q, p, edge);
    vtkMath::Subtract(xyz + 3 * static_cast<size_t>(opposite), p, side);
    vtkMath::Cross(edge, side, normal);
    for (int k = 0; k < 3; ++k)
    {
      toCentroid[k] = centroid[k] - 0.5 * (p[k] + q[k]);
    }
    const double area2 = vtkMath::Norm(normal);
    if (area2 > 0.0)
    {
      along += std::fabs(vtkMath::Dot(normal, toCentroid)) / area2;
      total += vtkMath::Norm(toCentroid);
    }
    const int32_t next = mesh.NextBoundaryVertex(tail, head);
    tail = head;
    head = next;
  } while (!(tail == a && head == b));
  if (!(total > 0.0))
  {
    return -1.0;
  }
  const double alignment = along / total;
  return std::isfinite(alignment) ? alignment : -1.0;
}
} // namespace

bool JoinsLoopsAroundTube(
  const SurfaceMesh& mesh, const double* xyz, int32_t a, int32_t b, int32_t c, int32_t d)
{
  const int64_t maxEdges = static_cast<int64_t>(MaximumFillLoopEdges);
  return LoopAlignment(mesh, xyz, a, b, maxEdges) >= TubeLoopAlignment &&
    LoopAlignment(mesh, xyz, c, d, maxEdges) >= TubeLoopAlignment;
}

//------------------------------------------------------------------------------------------------
bool IsShortLoop(const SurfaceMesh& mesh, const double* xyz, int32_t a, int32_t b, int64_t maxEdges,
  double maxLength, int32_t avoidTail, int32_t avoidHead)
{
  double length = 0.0;
  int32_t tail = a, head = b;
  const int64_t steps = mesh.GetNumberOfBoundaryHalfEdges() + 1;
  for (int64_t edges = 1; edges <= steps; ++edges)
  {
    double d[3];
    vtkMath::Subtract(xyz + 3 * static_cast<size_t>(head), xyz + 3 * static_cast<size_t>(tail), d);
    length += std::sqrt(vtkMath::Dot(d, d));
    if (edges > maxEdges && !(length < maxLength))
    {
      return false;
    }
    const int32_t next = mesh.NextBoundaryVertex(tail, head);
    tail = head;
    head = next;
    if (next < 0 || (tail == avoidTail && head == avoidHead))
    {
      return false;
    }
    if (tail == a && head == b)
    {
      return true;
    }
  }
  return false;
}

} // namespace holes
} // namespace pcs
