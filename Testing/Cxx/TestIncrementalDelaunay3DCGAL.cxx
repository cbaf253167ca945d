// The tetrahedra and hull of vtkIncrementalDelaunay3D equal CGAL's Delaunay_triangulation_3 on
// points in general position (where the Delaunay tetrahedralization is unique).
#include "vtkIncrementalDelaunay3D.h"

#include "pcsCGALReference.h"
#include "pcsTestUtilities.h"

#include <cstdlib>

namespace
{
bool CompareWithCGAL(const std::vector<double>& xyz, const char* label)
{
  auto cloud = pcstest::MakeCloud(xyz);
  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  delaunay->SetInputData(cloud);
  delaunay->Update();

  std::set<std::array<long long, 4>> reference;
  std::set<std::array<long long, 3>> referenceHull;
  pcstest::CGALDelaunay(xyz, reference, referenceHull);

  std::set<std::array<long long, 4>> ours;
  for (const auto& t : pcstest::CellTuples<4>(delaunay->GetTetrahedraOutput()))
  {
    std::array<long long, 4> s = { t[0], t[1], t[2], t[3] };
    std::sort(s.begin(), s.end());
    ours.insert(s);
  }
  std::set<std::array<long long, 3>> oursHull;
  for (const auto& t : pcstest::CellTuples<3>(delaunay->GetSurfaceOutput()))
  {
    std::array<long long, 3> s = { t[0], t[1], t[2] };
    std::sort(s.begin(), s.end());
    oursHull.insert(s);
  }
  std::cout << label << ": " << xyz.size() / 3 << " points, ours " << ours.size()
            << " tetrahedra / " << oursHull.size() << " hull triangles, CGAL " << reference.size()
            << " / " << referenceHull.size() << std::endl;
  PCS_CHECK(delaunay->GetTetrahedraOutput()->GetNumberOfCells() ==
      static_cast<vtkIdType>(ours.size()),
    label << ": a tetrahedron is repeated");
  PCS_CHECK(ours == reference, label << ": tetrahedra differ from CGAL");
  PCS_CHECK(oursHull == referenceHull, label << ": hull differs from CGAL");
  PCS_CHECK(delaunay->GetNumberOfCells() == static_cast<vtkIdType>(reference.size()),
    label << ": NumberOfCells");
  return true;
}

// Noisy samples of a torus: a surface-like cloud, as a scan gives.
std::vector<double> TorusCloud(int n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI);
  std::normal_distribution<double> noise(0.0, 0.002);
  std::vector<double> xyz;
  for (int i = 0; i < n; ++i)
  {
    const double u = angle(rng), v = angle(rng);
    const double r = 0.3 + noise(rng);
    xyz.push_back((1.0 + r * std::cos(v)) * std::cos(u));
    xyz.push_back((1.0 + r * std::cos(v)) * std::sin(u));
    xyz.push_back(r * std::sin(v));
  }
  return xyz;
}
} // namespace

int TestIncrementalDelaunay3DCGAL(int, char*[])
{
  bool ok = CompareWithCGAL(pcstest::UniformCube(100000, 20261122), "uniform 1e5");
  ok = CompareWithCGAL(TorusCloud(20000, 7), "torus 2e4") && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
