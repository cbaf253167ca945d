// Voronoi output (port 2) as the dual of the triangulation (port 1), checked without assuming
// any ordering of the output:
// - every Voronoi point is either a Voronoi vertex (on exactly dim + 1 lines: one per facet of
//   its cell) or the far end of a ray (on exactly one line), so the vertices are recognised from
//   the line structure alone; there is one vertex per Delaunay cell;
// - each vertex is matched to the cell whose circumcentre it is (computed here independently in
//   long double), the match is one-to-one, the vertex is equidistant from the cell's vertices
//   (relative 1e-9) and its point data Circumradius is that distance;
// - the bounded lines (Unbounded = 0) join the vertices of two cells sharing a facet, and there
//   is exactly one per interior facet;
// - the rays (Unbounded = 1) start at the vertex of a cell with a hull facet, leave along that
//   facet's outward normal, are one bounding-box diagonal long, and there is exactly one per
//   hull facet.
#include "vtkIncrementalDelaunay3D.h"

#include "pcsTestUtilities.h"

#include "vtkCellData.h"
#include "vtkMath.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>

namespace
{
using LD = long double;

// Circumcentre of 3 (2D, x-y) or 4 (3D) points, in long double: solve 2 (p_i - p_0) . c =
// |p_i|^2 - |p_0|^2 relative to p_0 by Cramer's rule.
void Circumcentre(const std::vector<const double*>& p, int dim, LD* centre)
{
  LD m[3][3], rhs[3];
  for (int i = 1; i <= dim; ++i)
  {
    rhs[i - 1] = 0;
    for (int j = 0; j < dim; ++j)
    {
      m[i - 1][j] = static_cast<LD>(p[i][j]) - p[0][j];
      rhs[i - 1] += m[i - 1][j] * m[i - 1][j];
    }
    rhs[i - 1] /= 2;
  }
  if (dim == 2)
  {
    const LD det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    centre[0] = p[0][0] + (rhs[0] * m[1][1] - m[0][1] * rhs[1]) / det;
    centre[1] = p[0][1] + (m[0][0] * rhs[1] - rhs[0] * m[1][0]) / det;
    centre[2] = 0;
    return;
  }
  auto det3 = [](LD a[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
      a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
      a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const LD det = det3(m);
  for (int k = 0; k < 3; ++k)
  {
    LD mk[3][3];
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        mk[i][j] = j == k ? rhs[i] : m[i][j];
      }
    }
    centre[k] = p[0][k] + det3(mk) / det;
  }
}

LD Distance(const double* a, const LD* b, int dim)
{
  LD s = 0;
  for (int i = 0; i < dim; ++i)
  {
    s += (a[i] - b[i]) * (a[i] - b[i]);
  }
  return std::sqrt(s);
}

bool CheckVoronoi(int dimension, int n, unsigned seed)
{
  const char* label = dimension == 3 ? "Voronoi 3D" : "Voronoi 2D";
  const int size = dimension + 1; // vertices per cell
  std::vector<double> xyz = pcstest::UniformCube(n, seed);
  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  delaunay->SetInputData(pcstest::MakeCloud(xyz));
  delaunay->SetDimension(dimension);
  delaunay->GenerateVoronoiOn();
  delaunay->Update();
  vtkPolyData* voronoi = delaunay->GetVoronoiOutput();
  auto X = [&xyz](vtkIdType i) { return &xyz[3 * i]; };

  // Delaunay cells and their facets.
  std::vector<std::vector<vtkIdType>> cells;
  for (const auto& t : pcstest::CellTuples<4>(delaunay->GetTetrahedraOutput()))
  {
    cells.emplace_back(t.begin(), t.begin() + size);
  }
  const size_t numberOfCells = cells.size();
  PCS_CHECK(numberOfCells > 0, label << ": cells");
  std::map<std::vector<vtkIdType>, std::vector<size_t>> facets;
  for (size_t c = 0; c < numberOfCells; ++c)
  {
    for (int j = 0; j < size; ++j)
    {
      std::vector<vtkIdType> f;
      for (int k = 0; k < size; ++k)
      {
        if (k != j)
        {
          f.push_back(cells[c][k]);
        }
      }
      std::sort(f.begin(), f.end());
      facets[f].push_back(c);
    }
  }
  size_t interior = 0, hull = 0;
  for (const auto& f : facets)
  {
    PCS_CHECK(f.second.size() <= 2, label << ": a facet in more than two cells");
    (f.second.size() == 2 ? interior : hull) += 1;
  }

  // Line structure: Voronoi vertices have dim + 1 lines, far ends of rays one.
  vtkDataArray* unbounded = voronoi->GetCellData()->GetArray("Unbounded");
  vtkDataArray* radius = voronoi->GetPointData()->GetArray("Circumradius");
  PCS_CHECK(unbounded && radius, label << ": Unbounded and Circumradius arrays");
  const vtkIdType numberOfPoints = voronoi->GetNumberOfPoints();
  std::vector<int> degree(numberOfPoints, 0);
  std::vector<std::array<vtkIdType, 2>> lines;
  for (vtkIdType c = 0; c < voronoi->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    voronoi->GetCellPoints(c, npts, pts);
    PCS_CHECK(npts == 2, label << ": Voronoi cell " << c << " is not a segment");
    PCS_CHECK(unbounded->GetTuple1(c) == 0 || unbounded->GetTuple1(c) == 1,
      label << ": Unbounded is 0 or 1");
    lines.push_back({ pts[0], pts[1] });
    ++degree[pts[0]];
    ++degree[pts[1]];
  }
  size_t vertices = 0, farEnds = 0;
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    PCS_CHECK(degree[p] == size || degree[p] == 1,
      label << ": Voronoi point " << p << " is on " << degree[p] << " lines");
    (degree[p] == size ? vertices : farEnds) += 1;
  }
  PCS_CHECK(vertices == numberOfCells,
    label << ": " << vertices << " Voronoi vertices for " << numberOfCells << " cells");

  // Match every Voronoi vertex with the cell whose circumcentre it is.
  std::vector<std::array<LD, 3>> centres(numberOfCells);
  for (size_t c = 0; c < numberOfCells; ++c)
  {
    std::vector<const double*> p;
    for (vtkIdType id : cells[c])
    {
      p.push_back(X(id));
    }
    Circumcentre(p, dimension, centres[c].data());
  }
  // The cells' own Circumradius array (tetrahedra / triangles output) is the distance from
  // their vertices to the circumcentre.
  vtkDataArray* cellRadius =
    delaunay->GetTetrahedraOutput()->GetCellData()->GetArray("Circumradius");
  PCS_CHECK(cellRadius && cellRadius->GetNumberOfTuples() == static_cast<vtkIdType>(numberOfCells),
    label << ": Circumradius cell data, one value per cell");
  for (size_t c = 0; c < numberOfCells; ++c)
  {
    const LD r = Distance(X(cells[c][0]), centres[c].data(), dimension);
    PCS_CHECK(std::fabs(cellRadius->GetTuple1(static_cast<vtkIdType>(c)) - r) <= 1e-9 * r,
      label << ": Circumradius of cell " << c << " is " << cellRadius->GetTuple1(c)
            << ", its vertices are " << static_cast<double>(r) << " from its circumcentre");
  }
  std::vector<long long> cellOf(numberOfPoints, -1);
  std::vector<char> matched(numberOfCells, 0);
  double worstSpread = 0.0;
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    if (degree[p] != size)
    {
      continue;
    }
    double v[3];
    voronoi->GetPoint(p, v);
    const LD w[3] = { v[0], v[1], v[2] };
    size_t best = 0;
    LD bestDistance = -1;
    for (size_t c = 0; c < numberOfCells; ++c)
    {
      const LD d = Distance(v, centres[c].data(), dimension);
      if (bestDistance < 0 || d < bestDistance)
      {
        best = c;
        bestDistance = d;
      }
    }
    PCS_CHECK(!matched[best], label << ": two Voronoi vertices for cell " << best);
    matched[best] = 1;
    cellOf[p] = static_cast<long long>(best);
    // Equidistant from the cell's vertices (in the x-y plane in 2D), and that is Circumradius.
    const LD r0 = Distance(X(cells[best][0]), w, dimension);
    for (int j = 1; j < size; ++j)
    {
      const LD r = Distance(X(cells[best][j]), w, dimension);
      worstSpread = std::max(worstSpread, static_cast<double>(std::fabs(r - r0) / r0));
      PCS_CHECK(std::fabs(r - r0) <= 1e-9 * r0,
        label << ": vertex " << p << " is not equidistant from the vertices of cell " << best
              << " (" << static_cast<double>(r0) << ", " << static_cast<double>(r) << ")");
    }
    PCS_CHECK(std::fabs(radius->GetTuple1(p) - r0) <= 1e-9 * r0,
      label << ": Circumradius of vertex " << p);
  }

  // Bounded lines: dual of the interior facets, one each. Rays: one per hull facet.
  double bounds[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      bounds[2 * k] = std::min(bounds[2 * k], X(i)[k]);
      bounds[2 * k + 1] = std::max(bounds[2 * k + 1], X(i)[k]);
    }
  }
  double diagonal = 0.0;
  for (int k = 0; k < dimension; ++k)
  {
    diagonal += (bounds[2 * k + 1] - bounds[2 * k]) * (bounds[2 * k + 1] - bounds[2 * k]);
  }
  diagonal = std::sqrt(diagonal);
  std::set<std::vector<vtkIdType>> dualFacets, rayFacets;
  size_t rays = 0;
  for (size_t l = 0; l < lines.size(); ++l)
  {
    const vtkIdType a = lines[l][0], b = lines[l][1];
    if (unbounded->GetTuple1(static_cast<vtkIdType>(l)) == 0)
    {
      PCS_CHECK(degree[a] == size && degree[b] == size,
        label << ": a bounded line ends at the far end of a ray");
      std::vector<vtkIdType> common;
      std::vector<vtkIdType> ca = cells[cellOf[a]], cb = cells[cellOf[b]];
      std::sort(ca.begin(), ca.end());
      std::sort(cb.begin(), cb.end());
      std::set_intersection(ca.begin(), ca.end(), cb.begin(), cb.end(), std::back_inserter(common));
      PCS_CHECK(static_cast<int>(common.size()) == dimension,
        label << ": bounded line " << l << " joins cells that share no facet");
      PCS_CHECK(dualFacets.insert(common).second, label << ": two lines for one facet");
      continue;
    }
    ++rays;
    PCS_CHECK((degree[a] == size) != (degree[b] == size),
      label << ": a ray must join a Voronoi vertex to a far end");
    const vtkIdType start = degree[a] == size ? a : b, end = degree[a] == size ? b : a;
    double s[3], e[3];
    voronoi->GetPoint(start, s);
    voronoi->GetPoint(end, e);
    double direction[3] = { e[0] - s[0], e[1] - s[1], dimension == 3 ? e[2] - s[2] : 0.0 };
    const double length = vtkMath::Norm(direction);
    PCS_CHECK(std::fabs(length - diagonal) <= 1e-9 * diagonal,
      label << ": ray length " << length << " is not the bounding-box diagonal " << diagonal);
    // The hull facet of the start cell that the ray crosses: perpendicular to it and leaving
    // on the side opposite to the cell's remaining vertex.
    const auto& cell = cells[cellOf[start]];
    bool found = false;
    for (int j = 0; j < size && !found; ++j)
    {
      std::vector<vtkIdType> f;
      for (int k = 0; k < size; ++k)
      {
        if (k != j)
        {
          f.push_back(cell[k]);
        }
      }
      std::sort(f.begin(), f.end());
      if (facets[f].size() != 1)
      {
        continue;
      }
      bool perpendicular = true;
      for (size_t k = 1; k < f.size(); ++k)
      {
        double edge[3] = { X(f[k])[0] - X(f[0])[0], X(f[k])[1] - X(f[0])[1],
          dimension == 3 ? X(f[k])[2] - X(f[0])[2] : 0.0 };
        perpendicular = perpendicular &&
          std::fabs(vtkMath::Dot(edge, direction)) <= 1e-9 * vtkMath::Norm(edge) * length;
      }
      double inward[3] = { X(cell[j])[0] - X(f[0])[0], X(cell[j])[1] - X(f[0])[1],
        dimension == 3 ? X(cell[j])[2] - X(f[0])[2] : 0.0 };
      if (perpendicular && vtkMath::Dot(inward, direction) < 0)
      {
        found = true;
        PCS_CHECK(rayFacets.insert(f).second, label << ": two rays for one hull facet");
      }
    }
    PCS_CHECK(found, label << ": ray " << l << " is not the outward normal of a hull facet");
  }
  PCS_CHECK(dualFacets.size() == interior,
    label << ": " << dualFacets.size() << " bounded lines for " << interior << " interior facets");
  PCS_CHECK(rayFacets.size() == hull && rays == hull,
    label << ": " << rays << " rays for " << hull << " hull facets");
  PCS_CHECK(farEnds == rays, label << ": one far end per ray");
  if (dimension == 3)
  {
    PCS_CHECK(static_cast<size_t>(delaunay->GetSurfaceOutput()->GetNumberOfCells()) == hull,
      label << ": hull triangles");
  }
  std::cout << label << ": " << numberOfCells << " vertices, " << interior << " bounded edges, "
            << rays << " rays; largest relative spread of the distances to the cell vertices "
            << worstSpread << std::endl;
  return true;
}
} // namespace

int TestIncrementalDelaunay3DVoronoi(int, char*[])
{
  bool ok = CheckVoronoi(3, 500, 9);
  ok = CheckVoronoi(2, 500, 10) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
