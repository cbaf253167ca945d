// Voronoi output: one vertex per tetrahedron at its circumcentre (equidistant from its four
// vertices), one segment per facet shared by two tetrahedra, one ray per hull facet.
#include "vtkIncrementalDelaunay3D.h"

#include "pcsTestUtilities.h"

#include "vtkCellData.h"
#include "vtkMath.h"

#include <cstdlib>
#include <map>

namespace
{
bool CheckVoronoi(int dimension)
{
  std::vector<double> xyz = pcstest::UniformCube(500, 9);
  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  delaunay->SetInputData(pcstest::MakeCloud(xyz));
  delaunay->SetDimension(dimension);
  delaunay->GenerateVoronoiOn();
  delaunay->Update();
  vtkPolyData* voronoi = delaunay->GetVoronoiOutput();
  const int size = dimension + 1;
  std::vector<std::array<vtkIdType, 4>> cells;
  for (vtkIdType c = 0; c < delaunay->GetTetrahedraOutput()->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    delaunay->GetTetrahedraOutput()->GetCellPoints(c, npts, pts);
    std::array<vtkIdType, 4> t = { -1, -1, -1, -1 };
    std::copy(pts, pts + npts, t.begin());
    cells.push_back(t);
  }
  const vtkIdType numberOfCells = static_cast<vtkIdType>(cells.size());
  PCS_CHECK(numberOfCells > 0, "cells");
  // Facets (edges in 2D) shared by two cells, and boundary ones.
  std::map<std::vector<vtkIdType>, int> facets;
  for (const auto& t : cells)
  {
    for (int j = 0; j < size; ++j)
    {
      std::vector<vtkIdType> f;
      for (int k = 0; k < size; ++k)
      {
        if (k != j)
        {
          f.push_back(t[k]);
        }
      }
      std::sort(f.begin(), f.end());
      ++facets[f];
    }
  }
  vtkIdType interior = 0, boundary = 0;
  for (const auto& f : facets)
  {
    (f.second == 2 ? interior : boundary) += 1;
  }
  vtkDataArray* unbounded = voronoi->GetCellData()->GetArray("Unbounded");
  PCS_CHECK(unbounded, "Unbounded array");
  vtkIdType rays = 0;
  for (vtkIdType c = 0; c < voronoi->GetNumberOfCells(); ++c)
  {
    rays += unbounded->GetTuple1(c) != 0 ? 1 : 0;
  }
  PCS_CHECK(voronoi->GetNumberOfCells() == interior + boundary,
    "Voronoi edges " << voronoi->GetNumberOfCells() << " expected " << interior + boundary);
  PCS_CHECK(rays == boundary, "rays " << rays << " expected " << boundary);
  PCS_CHECK(voronoi->GetNumberOfPoints() == numberOfCells + rays, "Voronoi vertices");
  if (dimension == 3)
  {
    for (vtkIdType c = 0; c < numberOfCells; ++c)
    {
      double center[3];
      voronoi->GetPoint(c, center);
      const double r0 = std::sqrt(vtkMath::Distance2BetweenPoints(center, &xyz[3 * cells[c][0]]));
      for (int j = 1; j < 4; ++j)
      {
        const double r = std::sqrt(vtkMath::Distance2BetweenPoints(center, &xyz[3 * cells[c][j]]));
        PCS_CHECK(std::fabs(r - r0) <= 1e-7 * std::max(1.0, r0), "circumcentre of " << c);
      }
    }
  }
  std::cout << "Voronoi " << dimension << "D: " << numberOfCells << " vertices, " << interior
            << " segments, " << rays << " rays" << std::endl;
  return true;
}
} // namespace

int TestIncrementalDelaunay3DVoronoi(int, char*[])
{
  bool ok = CheckVoronoi(3);
  ok = CheckVoronoi(2) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
