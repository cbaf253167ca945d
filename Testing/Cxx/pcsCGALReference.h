// CGAL references for the verification tests (tests only; the library never uses CGAL).
#ifndef pcsCGALReference_h
#define pcsCGALReference_h

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <set>
#include <vector>

namespace pcstest
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<long long, Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_3<VertexBase>;
using CGALDelaunay3 = CGAL::Delaunay_triangulation_3<Kernel, DataStructure>;

inline Point3 ToPoint(const double* p)
{
  return Point3(p[0], p[1], p[2]);
}

/// CGAL's Delaunay tetrahedra and hull triangles of packed points, as sorted id tuples.
inline void CGALDelaunay(const std::vector<double>& xyz, std::set<std::array<long long, 4>>& tets,
  std::set<std::array<long long, 3>>& hull)
{
  std::vector<std::pair<Point3, long long>> points;
  for (size_t i = 0; i < xyz.size() / 3; ++i)
  {
    points.emplace_back(ToPoint(&xyz[3 * i]), static_cast<long long>(i));
  }
  CGALDelaunay3 dt(points.begin(), points.end());
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
  {
    std::array<long long, 4> t;
    for (int j = 0; j < 4; ++j)
    {
      t[j] = c->vertex(j)->info();
    }
    std::sort(t.begin(), t.end());
    tets.insert(t);
  }
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c)
  {
    if (!dt.is_infinite(c))
    {
      continue;
    }
    std::array<long long, 3> f;
    int k = 0;
    for (int j = 0; j < 4; ++j)
    {
      if (!dt.is_infinite(c->vertex(j)))
      {
        f[k++] = c->vertex(j)->info();
      }
    }
    std::sort(f.begin(), f.end());
    hull.insert(f);
  }
}
} // namespace pcstest

#endif
