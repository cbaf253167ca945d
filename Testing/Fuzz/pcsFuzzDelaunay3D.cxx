// Fuzz target of the 3D Delaunay kernel (pcs::Delaunay3D): a small cloud from the bytes
// (pcsFuzzInput.h), triangulated, then every invariant checked with the exact predicates:
// - every point is a vertex, or a listed duplicate of a vertex with the same coordinates;
// - finite cells are positively oriented; links are symmetric (neighbour of the neighbour);
// - every facet between two finite cells is locally Delaunay (the opposite vertex is not strictly
//   inside the circumsphere);
// - when the kernel refuses (returns false), the points really are coplanar or fewer than 4
//   distinct ones.
// A violated invariant aborts (the fuzzer reports it and saves the input).
#include "pcsDelaunay3D.h"
#include "pcsFuzzInput.h"
#include "pcsPredicates.h"

#include <cstdio>
#include <cstdlib>
#include <set>

namespace
{
void Fail(const char* what)
{
  std::fprintf(stderr, "pcsFuzzDelaunay3D: invariant violated: %s\n", what);
  std::abort();
}

bool SamePoint(const double* a, const double* b)
{
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

// Whether the points are all coplanar (or fewer than 4 distinct): brute force.
bool Flat(const std::vector<double>& xyz)
{
  const int n = static_cast<int>(xyz.size() / 3);
  const double* p = xyz.data();
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      for (int c = b + 1; c < n; ++c)
        for (int d = c + 1; d < n; ++d)
          if (pcs::predicates::Orient3D(p + 3 * a, p + 3 * b, p + 3 * c, p + 3 * d) != 0)
            return false;
  return true;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::vector<double> xyz = pcsfuzz::Cloud(data, size, 3);
  const int n = static_cast<int>(xyz.size() / 3);
  std::vector<int32_t> ids(n);
  for (int i = 0; i < n; ++i)
  {
    ids[i] = i;
  }
  auto P = [&xyz](int32_t i) { return xyz.data() + 3 * static_cast<size_t>(i); };
  pcs::Delaunay3D dt;
  dt.SetComputeCircumradii(true);
  if (!dt.Triangulate(xyz.data(), ids))
  {
    if (!Flat(xyz))
    {
      Fail("refused a cloud with 4 affinely independent points");
    }
    return 0;
  }
  std::vector<char> vertex(n, 0);
  const int64_t cells = dt.GetNumberOfCells();
  int64_t finite = 0;
  for (int64_t c = 0; c < cells; ++c)
  {
    const int32_t* v = dt.CellVertices(c);
    for (int j = 0; j < 4; ++j)
    {
      if (v[j] >= n || v[j] < pcs::Delaunay3D::Infinite)
      {
        Fail("vertex id out of range");
      }
      if (v[j] >= 0)
      {
        vertex[v[j]] = 1;
      }
      const int64_t m = dt.Neighbor(c, j);
      if (m < 0 || m >= cells || dt.Neighbor(m, dt.MirrorIndex(c, j)) != c)
      {
        Fail("asymmetric link");
      }
    }
    if (dt.IsInfinite(c))
    {
      continue;
    }
    ++finite;
    if (pcs::predicates::Orient3D(P(v[0]), P(v[1]), P(v[2]), P(v[3])) <= 0)
    {
      Fail("finite cell not positively oriented");
    }
    for (int j = 0; j < 4; ++j)
    {
      const int64_t m = dt.Neighbor(c, j);
      if (dt.IsInfinite(m))
      {
        continue;
      }
      const int32_t q = dt.Vertex(m, dt.MirrorIndex(c, j));
      if (pcs::predicates::InSphere(P(v[0]), P(v[1]), P(v[2]), P(v[3]), P(q)) > 0)
      {
        Fail("facet not locally Delaunay");
      }
    }
  }
  if (dt.GetNumberOfFiniteCells() != finite || !dt.GetCircumradii())
  {
    Fail("finite cell count or radii");
  }
  for (const auto& duplicate : dt.GetDuplicates())
  {
    if (duplicate.first < 0 || duplicate.first >= n || !vertex[duplicate.second] ||
      !SamePoint(P(duplicate.first), P(duplicate.second)))
    {
      Fail("bad duplicate record");
    }
    vertex[duplicate.first] = 1;
  }
  for (int i = 0; i < n; ++i)
  {
    if (!vertex[i])
    {
      Fail("a point is neither a vertex nor a duplicate");
    }
  }
  return 0;
}
