#include "pcsPointInsertion.h"

#include "pcsDisjointSets.h"
#include "pcsProjectedTests.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcs
{
namespace
{
inline void Sub(const double* a, const double* b, double* r)
{
  r[0] = a[0] - b[0];
  r[1] = a[1] - b[1];
  r[2] = a[2] - b[2];
}
inline double Dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline void Cross(const double* a, const double* b, double* r)
{
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}
inline const double* P(const double* xyz, int32_t v)
{
  return xyz + 3 * static_cast<size_t>(v);
}
// Normal (not normalized) of the triangle (a, b, c).
inline void Normal(const double* xyz, int32_t a, int32_t b, int32_t c, double* n)
{
  double u[3], w[3];
  Sub(P(xyz, b), P(xyz, a), u);
  Sub(P(xyz, c), P(xyz, a), w);
  Cross(u, w, n);
}
// Distance from x to the segment st.
double SegmentDistance(const double* x, const double* s, const double* t)
{
  double d[3], w[3];
  Sub(t, s, d);
  Sub(x, s, w);
  const double dd = Dot(d, d);
  const double f = dd > 0 ? std::min(1.0, std::max(0.0, Dot(w, d) / dd)) : 0.0;
  const double c[3] = { s[0] + f * d[0] - x[0], s[1] + f * d[1] - x[1], s[2] + f * d[2] - x[2] };
  return std::sqrt(Dot(c, c));
}
} // namespace

bool InsertFreePoint(SurfaceMesh& mesh, const double* xyz, int32_t q, const int32_t* neighbors,
  int count, bool attachToBoundary, PointInsertionResult& result)
{
  result.Added.clear();
  result.OldEdges.clear();
  result.Restored.clear();
  if (!mesh.IsFree(q))
  {
    return false;
  }
  const double* x = P(xyz, q);
  int64_t best = -1;
  int bestEdge = -1; // the edge tri[e] -> tri[e + 1] q is nearest to, when outside
  bool bestInside = false;
  double bestDistance = std::numeric_limits<double>::infinity();
  std::vector<int64_t> seen;
  int64_t around[64];
  for (int j = 0; j < count; ++j)
  {
    const int32_t v = neighbors[j];
    if (v < 0 || v == q || mesh.IsFree(v))
    {
      continue;
    }
    const int found = std::min(mesh.GetVertexTriangles(v, around, 64), 64);
    for (int i = 0; i < found; ++i)
    {
      const int64_t t = around[i];
      if (std::find(seen.begin(), seen.end(), t) != seen.end())
      {
        continue;
      }
      seen.push_back(t);
      const int32_t* tri = mesh.GetTriangle(t);
      double n[3];
      Normal(xyz, tri[0], tri[1], tri[2], n);
      const double area2 = std::sqrt(Dot(n, n));
      double reach = 0.0;
      for (int e = 0; e < 3; ++e)
      {
        double d[3];
        Sub(P(xyz, tri[(e + 1) % 3]), P(xyz, tri[e]), d);
        reach = std::max(reach, std::sqrt(Dot(d, d)));
      }
      if (!(area2 > 0) || !(reach > 0))
      {
        continue;
      }
      // The normal scaled to the longest edge: the line's second point is well separated.
      const double scaled[3] = { n[0] * reach / area2, n[1] * reach / area2, n[2] * reach / area2 };
      const bool inside = pcs::projected::LineCrossesTriangle(
        x, scaled, P(xyz, tri[0]), P(xyz, tri[1]), P(xyz, tri[2]));
      double distance;
      int edge = -1;
      if (inside)
      {
        double w[3];
        Sub(x, P(xyz, tri[0]), w);
        distance = std::fabs(Dot(w, n)) / area2;
      }
      else
      {
        distance = std::numeric_limits<double>::infinity();
        for (int e = 0; e < 3; ++e)
        {
          const double d = SegmentDistance(x, P(xyz, tri[e]), P(xyz, tri[(e + 1) % 3]));
          if (d < distance)
          {
            distance = d;
            edge = e;
          }
        }
      }
      if (distance <= reach && distance < bestDistance)
      {
        best = t;
        bestDistance = distance;
        bestInside = inside;
        bestEdge = edge;
      }
    }
  }
  if (best < 0)
  {
    return false;
  }
  const int32_t t3[3] = { mesh.GetTriangle(best)[0], mesh.GetTriangle(best)[1],
    mesh.GetTriangle(best)[2] };
  if (bestInside)
  {
    // Almost on an edge: the angle at q over that edge beyond 150 degrees.
    double widest = -0.8660254037844386;
    for (int e = 0; e < 3; ++e)
    {
      double e1[3], e2[3];
      Sub(P(xyz, t3[e]), x, e1);
      Sub(P(xyz, t3[(e + 1) % 3]), x, e2);
      const double lengths = std::sqrt(Dot(e1, e1) * Dot(e2, e2));
      const double c = lengths > 0 ? Dot(e1, e2) / lengths : 1.0;
      if (c < widest)
      {
        widest = c;
        bestEdge = e;
      }
    }
  }
  // q exactly on an edge in space (points on lattice lines): that edge must be split, as any
  // triangle joining q to it would have zero area.
  bool onEdge = false;
  for (int e = 0; e < 3 && !onEdge; ++e)
  {
    if (pcs::projected::OnOpenSegment3D(P(xyz, t3[e]), P(xyz, t3[(e + 1) % 3]), x))
    {
      onEdge = true;
      bestEdge = e;
    }
  }
  // The normal each new triangle must agree with: that of the triangle it replaces (or is
  // attached to); the last two of an edge split replace the second triangle.
  double oldNormal[3], otherNormal[3];
  Normal(xyz, t3[0], t3[1], t3[2], oldNormal);
  std::copy_n(oldNormal, 3, otherNormal);

  // The replacement: triangles removed and added.
  std::vector<int64_t> removed;
  std::vector<std::array<int32_t, 3>> added;
  if (bestEdge >= 0)
  {
    const int32_t a = t3[bestEdge], b = t3[(bestEdge + 1) % 3], c = t3[(bestEdge + 2) % 3];
    const int64_t other = mesh.FindTriangle(b, a);
    if (other >= 0)
    {
      const int32_t d = mesh.OppositeVertex(b, a);
      Normal(xyz, b, a, d, otherNormal);
      removed = { best, other };
      added = { { { a, q, c } }, { { q, b, c } }, { { b, q, d } }, { { q, a, d } } };
      result.OldEdges = { { { b, c } }, { { c, a } }, { { a, d } }, { { d, b } } };
    }
    else if (bestInside || onEdge)
    {
      removed = { best };
      added = { { { a, q, c } }, { { q, b, c } } };
      result.OldEdges = { { { b, c } }, { { c, a } } };
    }
    else if (attachToBoundary)
    {
      added = { { { b, a, q } } };
      result.OldEdges = { { { a, b } } };
    }
  }
  else
  {
    removed = { best };
    added = { { { t3[0], t3[1], q } }, { { t3[1], t3[2], q } }, { { t3[2], t3[0], q } } };
    result.OldEdges = { { { t3[0], t3[1] } }, { { t3[1], t3[2] } }, { { t3[2], t3[0] } } };
  }
  if (added.empty())
  {
    result.OldEdges.clear();
    return false;
  }
  // Proper triangles that do not fold back over the ones they replace (or attach to).
  for (size_t i = 0; i < added.size(); ++i)
  {
    const auto& t = added[i];
    double n[3];
    Normal(xyz, t[0], t[1], t[2], n);
    if (pcs::projected::Collinear(P(xyz, t[0]), P(xyz, t[1]), P(xyz, t[2])) ||
      !(Dot(n, i < 2 ? oldNormal : otherNormal) > 0))
    {
      result.OldEdges.clear();
      return false;
    }
  }
  std::vector<std::array<int32_t, 3>> restore;
  for (int64_t t : removed)
  {
    const int32_t* tri = mesh.GetTriangle(t);
    restore.push_back({ { tri[0], tri[1], tri[2] } });
    mesh.RemoveTriangle(t);
  }
  // Added one by one, the triangles around q may pinch a vertex until the last one closes its
  // fan (SurfaceMesh allows that deliberately): the manifold is checked once all are in.
  bool ok = true;
  for (const auto& t : added)
  {
    const SurfaceMesh::Check check = mesh.CanAddTriangle(t[0], t[1], t[2]);
    const int64_t id = check == SurfaceMesh::Check::Ok ||
        check == SurfaceMesh::Check::NonManifoldVertex
      ? mesh.AddTriangle(t[0], t[1], t[2])
      : -1;
    if (id < 0)
    {
      ok = false;
      break;
    }
    result.Added.push_back(id);
  }
  for (size_t i = 0; i < added.size() && ok; ++i)
  {
    for (int j = 0; j < 3 && ok; ++j)
    {
      ok = mesh.GetNumberOfFans(added[i][j]) == 1;
    }
  }
  if (!ok)
  {
    for (int64_t t : result.Added)
    {
      mesh.RemoveTriangle(t);
    }
    for (size_t i = 0; i < restore.size(); ++i)
    {
      const auto& t = restore[i];
      result.Restored.emplace_back(removed[i], mesh.AddTriangle(t[0], t[1], t[2]));
    }
    result.Added.clear();
    result.OldEdges.clear();
    return false;
  }
  result.Removed = std::move(restore);
  return true;
}

//------------------------------------------------------------------------------------------------
void TakeOutStrips(SurfaceMesh& mesh, TakenStrips& taken)
{
  taken = TakenStrips();
  const int32_t n = mesh.GetNumberOfVertices();
  const int64_t count = mesh.GetNumberOfTriangleIds();
  pcs::DisjointSets<int32_t> parts(n);
  for (int64_t t = 0; t < count; ++t)
  {
    if (!mesh.IsTriangleRemoved(t))
    {
      const int32_t* v = mesh.GetTriangle(t);
      parts.Union(v[0], v[1]);
      parts.Union(v[1], v[2]);
    }
  }
  // A part is a strip when none of its vertices is interior.
  std::vector<char> patch(static_cast<size_t>(n), 0);
  for (int32_t v = 0; v < n; ++v)
  {
    if (mesh.IsInterior(v))
    {
      patch[parts.Find(v)] = 1;
    }
  }
  std::vector<std::vector<int64_t>> strips;
  std::vector<int32_t> index(static_cast<size_t>(n), -1);
  for (int64_t t = 0; t < count; ++t)
  {
    if (mesh.IsTriangleRemoved(t))
    {
      continue;
    }
    const int32_t root = parts.Find(mesh.GetTriangle(t)[0]);
    if (patch[root])
    {
      continue;
    }
    if (index[root] < 0)
    {
      index[root] = static_cast<int32_t>(strips.size());
      strips.emplace_back();
    }
    strips[index[root]].push_back(t);
  }
  for (const auto& strip : strips)
  {
    taken.Starts.push_back(taken.Ids.size());
    for (int64_t t : strip)
    {
      const int32_t* v = mesh.GetTriangle(t);
      taken.Triangles.insert(taken.Triangles.end(), { v[0], v[1], v[2] });
      taken.Ids.push_back(t);
    }
  }
  taken.Starts.push_back(taken.Ids.size());
  for (int64_t t : taken.Ids)
  {
    mesh.RemoveTriangle(t);
  }
  std::vector<int32_t> points(taken.Triangles);
  std::sort(points.begin(), points.end());
  taken.NumberOfPoints =
    static_cast<int64_t>(std::unique(points.begin(), points.end()) - points.begin());
}

int64_t PutBackStrips(
  SurfaceMesh& mesh, const TakenStrips& taken, std::vector<std::pair<int64_t, int64_t>>& restored)
{
  int64_t used = 0;
  for (size_t s = 0; s + 1 < taken.Starts.size(); ++s)
  {
    // Decided before any of the strip's triangles is back: which of them keep all three points
    // free (every one, when no point of the strip was inserted).
    std::vector<size_t> back;
    for (size_t t = taken.Starts[s]; t < taken.Starts[s + 1]; ++t)
    {
      const int32_t* v = &taken.Triangles[3 * t];
      if (mesh.IsFree(v[0]) && mesh.IsFree(v[1]) && mesh.IsFree(v[2]))
      {
        back.push_back(t);
      }
    }
    std::vector<int32_t> vertices;
    for (size_t t : back)
    {
      vertices.insert(vertices.end(), &taken.Triangles[3 * t], &taken.Triangles[3 * t] + 3);
    }
    std::vector<int64_t> added;
    if (!back.empty() && !mesh.AddTriangles(vertices.data(), back.size(), added))
    {
      // Not a manifold piece on its own (a subset of a strip pinched at a vertex): one by one,
      // those that fit.
      added.assign(back.size(), -1);
      for (size_t k = 0; k < back.size(); ++k)
      {
        const int32_t* v = &vertices[3 * k];
        if (mesh.CanAddTriangle(v[0], v[1], v[2]) == SurfaceMesh::Check::Ok)
        {
          added[k] = mesh.AddTriangle(v[0], v[1], v[2]);
        }
      }
    }
    std::vector<int32_t> points;
    for (size_t k = 0; k < added.size(); ++k)
    {
      if (added[k] >= 0)
      {
        restored.emplace_back(taken.Ids[back[k]], added[k]);
        points.insert(points.end(), &vertices[3 * k], &vertices[3 * k] + 3);
      }
    }
    std::sort(points.begin(), points.end());
    used += static_cast<int64_t>(std::unique(points.begin(), points.end()) - points.begin());
  }
  return used;
}

} // namespace pcs
