// Fuzz target of the 2D Delaunay kernel (pcs::Delaunay2D): a small planar cloud from the bytes
// (pcsFuzzInput.h), duplicates removed as the filter does, triangulated, then checked with the
// exact predicates: every point in a triangle, triangles counter-clockwise, neighbour links
// symmetric, every interior edge locally Delaunay (the opposite vertex not strictly inside the
// circumcircle); a refusal only for collinear sets. A violated invariant aborts.
#include "pcsDelaunay2D.h"
#include "pcsFuzzInput.h"
#include "pcsPredicates.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <utility>

namespace
{
void Fail(const char* what)
{
  std::fprintf(stderr, "pcsFuzzDelaunay2D: invariant violated: %s\n", what);
  std::abort();
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::vector<double> xy = pcsfuzz::Cloud(data, size, 2);
  const int n = static_cast<int>(xy.size() / 2);
  auto P = [&xy](int32_t i) { return xy.data() + 2 * static_cast<size_t>(i); };
  std::set<std::pair<double, double>> seen;
  std::vector<int32_t> ids;
  for (int i = 0; i < n; ++i)
  {
    if (seen.insert({ xy[2 * i], xy[2 * i + 1] }).second)
    {
      ids.push_back(i);
    }
  }
  pcs::Delaunay2D dt;
  if (!dt.Triangulate(xy.data(), ids))
  {
    for (size_t a = 0; a < ids.size(); ++a)
      for (size_t b = a + 1; b < ids.size(); ++b)
        for (size_t c = b + 1; c < ids.size(); ++c)
          if (pcs::predicates::Orient2D(P(ids[a]), P(ids[b]), P(ids[c])) != 0)
            Fail("refused a cloud with 3 non-collinear points");
    return 0;
  }
  const std::vector<int32_t>& t = dt.GetTriangles();
  const std::vector<int32_t>& nb = dt.GetNeighbors();
  const size_t triangles = t.size() / 3;
  if (nb.size() != t.size())
  {
    Fail("neighbour array size");
  }
  std::vector<char> used(n, 0);
  for (size_t i = 0; i < triangles; ++i)
  {
    const int32_t* v = &t[3 * i];
    for (int j = 0; j < 3; ++j)
    {
      if (v[j] < 0 || v[j] >= n)
      {
        Fail("vertex id out of range");
      }
      used[v[j]] = 1;
    }
    if (pcs::predicates::Orient2D(P(v[0]), P(v[1]), P(v[2])) <= 0)
    {
      Fail("triangle not counter-clockwise");
    }
    for (int j = 0; j < 3; ++j)
    {
      const int32_t m = nb[3 * i + j];
      if (m < 0)
      {
        continue;
      }
      if (m >= static_cast<int32_t>(triangles))
      {
        Fail("neighbour out of range");
      }
      // The vertex of m not on the shared edge.
      const int32_t a = v[(j + 1) % 3], b = v[(j + 2) % 3];
      int32_t opposite = -1, back = -1;
      for (int k = 0; k < 3; ++k)
      {
        const int32_t w = t[3 * m + k];
        if (w != a && w != b)
        {
          opposite = w;
          back = nb[3 * m + k];
        }
      }
      if (opposite < 0 || back != static_cast<int32_t>(i))
      {
        Fail("asymmetric neighbour link");
      }
      if (pcs::predicates::InCircle(P(v[0]), P(v[1]), P(v[2]), P(opposite)) > 0)
      {
        Fail("edge not locally Delaunay");
      }
    }
  }
  for (int32_t id : ids)
  {
    if (!used[id])
    {
      Fail("a point is in no triangle");
    }
  }
  return 0;
}
