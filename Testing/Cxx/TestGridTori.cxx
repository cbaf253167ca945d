// Tori sampled on a regular (u, v) parameter grid (issue 5): n x n points
// ((R + r cos v) cos u, (R + r cos v) sin u, r sin v), u and v in steps of 2 pi / n, R = 1, for
// n = 24, 40, 56 and tube radii r = 0.35, 0.45, 0.5, 0.65. Known by construction: a closed,
// manifold, oriented mesh over every point, one component of genus 1, hence 2 n^2 triangles
// (Euler: V - E + T = 0 with 3 T = 2 E), checked with vtkReconstructionQuality.
//
// Such grids are the most common way to make a torus, and they are hard for a growing front: every
// grid cell is an isosceles trapezoid (cocircular, its two diagonals equal), and the cells are
// anisotropic -- along u the spacing is 2 pi (R + r cos v) / n, along v 2 pi r / n, so the cells
// of the outer band are (R + r) / r times longer than wide (3 at r = 0.5) and those of the inner
// band (R - r) / r. With r = 0.45 to 0.54 a third to a half of the points lie on such lines next
// to lines; below the half, vtkLocalOptimumGrowth kept the paper's ratios, under which the
// diagonal of a cell 2.8 to 3 times longer than wide has no candidate to complete the cell (its
// short side is under a third of the diagonal), and the front made triangles skipping rows. Before
// the fix (5770d49) this test failed on 6 of its 12 tori: n = 24 at r = 0.45 and 0.5 gave 2 and 3
// components, n = 40 at r = 0.45 2 components and at r = 0.5 48 boundary edges, n = 56 at r =
// 0.45 and 0.5 left 4 and 5 points unused.
// Not checked (left, see Benchmarks/results/local_optimum.md, task gridlog): r = 0.2 with n <= 32,
// where the outer cells are 6 times longer than wide (the filter's largest ratio, 2 k2) and the
// tube's circle of 24 or 32 points is too curved for the scan-line stretch to see its lines.
#include "vtkLocalOptimumGrowth.h"

#include "pcsTestUtilities.h"

#include "vtkMath.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace
{
std::vector<double> GridTorus(int n, double ringRadius, double tubeRadius)
{
  std::vector<double> xyz;
  xyz.reserve(3 * static_cast<size_t>(n) * n);
  for (int j = 0; j < n; ++j)
  {
    const double v = 2.0 * vtkMath::Pi() * j / n;
    for (int i = 0; i < n; ++i)
    {
      const double u = 2.0 * vtkMath::Pi() * i / n;
      const double rho = ringRadius + tubeRadius * std::cos(v);
      xyz.insert(xyz.end(), { rho * std::cos(u), rho * std::sin(u), tubeRadius * std::sin(v) });
    }
  }
  return xyz;
}

bool CheckGridTorus(int n, double tubeRadius)
{
  std::ostringstream label;
  label << "LOG grid torus " << n << " x " << n << ", r = " << tubeRadius;
  const std::string what = label.str();
  vtkNew<vtkLocalOptimumGrowth> filter;
  filter->SetInputData(pcstest::MakeCloud(GridTorus(n, 1.0, tubeRadius)));
  filter->Update();
  vtkPolyData* mesh = filter->GetOutput();
  PCS_CHECK(mesh->GetNumberOfPoints() == static_cast<vtkIdType>(n) * n,
    what << ": " << mesh->GetNumberOfPoints() << " points, expected no added point");
  PCS_CHECK(filter->GetNumberOfUnusedPoints() == 0,
    what << ": " << filter->GetNumberOfUnusedPoints() << " unused points");
  return pcstest::CheckClosedSurface(mesh, static_cast<vtkIdType>(n) * n, 1, what);
}
} // namespace

int TestGridTori(int, char*[])
{
  bool ok = true;
  for (int n : { 24, 40, 56 })
  {
    for (double tubeRadius : { 0.35, 0.45, 0.5, 0.65 })
    {
      ok = CheckGridTorus(n, tubeRadius) && ok;
    }
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
