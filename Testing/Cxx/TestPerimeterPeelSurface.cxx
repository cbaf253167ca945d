// vtkPerimeterPeelSurface on clouds whose answers are known by construction:
// - 3,000 uniform points on a sphere: a closed, manifold, genus-0 surface over every point
//   (2V - 4 triangles), consistently oriented and facing outward (positive enclosed volume);
// - a fixed Threshold above every facet keeps the whole convex hull (2V - 4 triangles too) and
//   removes nothing;
// - 5,000 points on a torus: with ManifoldOutput (default) no non-manifold edge or vertex, closed,
//   oriented outward; the field data agree with the mesh (triangles, used points, Used array).
#include "vtkPerimeterPeelSurface.h"
#include "vtkReconstructionQuality.h"

#include "pcsTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"

#include <cmath>
#include <cstdlib>

namespace
{
std::vector<double> SpherePoints(int n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<double> xyz;
  for (int i = 0; i < n; ++i)
  {
    const double p[3] = { g(rng), g(rng), g(rng) };
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    xyz.insert(xyz.end(), { p[0] / r, p[1] / r, p[2] / r });
  }
  return xyz;
}

// Area-uniform points on a torus (ring radius 1, tube radius 0.35) by rejection.
std::vector<double> TorusPoints(int n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xyz;
  while (static_cast<int>(xyz.size()) < 3 * n)
  {
    const double a = 2 * M_PI * u(rng), b = 2 * M_PI * u(rng);
    if (u(rng) > (1.0 + 0.35 * std::cos(b)) / 1.35)
    {
      continue;
    }
    const double r = 1.0 + 0.35 * std::cos(b);
    xyz.insert(xyz.end(), { r * std::cos(a), r * std::sin(a), 0.35 * std::sin(b) });
  }
  return xyz;
}

// Six times the volume enclosed by the triangles (positive when they face outward).
double SignedVolume6(vtkPolyData* mesh)
{
  double volume = 0.0;
  for (const auto& t : pcstest::CellTuples<3>(mesh))
  {
    double a[3], b[3], c[3];
    mesh->GetPoint(t[0], a);
    mesh->GetPoint(t[1], b);
    mesh->GetPoint(t[2], c);
    volume += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
      a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return volume;
}

vtkSmartPointer<vtkPolyData> Measure(vtkPolyData* mesh)
{
  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputData(mesh);
  quality->ComputeDistancesOff();
  quality->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(quality->GetOutput());
  return out;
}

double FieldValue(vtkDataObject* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? array->GetTuple1(0) : -1.0;
}

bool CheckConsistentFields(const char* label, vtkPolyData* mesh)
{
  vtkDataArray* used = mesh->GetPointData()->GetArray("Used");
  PCS_CHECK(used && used->GetNumberOfTuples() == mesh->GetNumberOfPoints(), label << ": Used");
  vtkIdType usedCount = 0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    usedCount += used->GetTuple1(i) != 0 ? 1 : 0;
  }
  PCS_CHECK(FieldValue(mesh, "NumberOfUsedPoints") == usedCount, label << ": NumberOfUsedPoints");
  PCS_CHECK(FieldValue(mesh, "NumberOfUnusedPoints") == mesh->GetNumberOfPoints() - usedCount,
    label << ": NumberOfUnusedPoints");
  PCS_CHECK(FieldValue(mesh, "NumberOfTriangles") == mesh->GetNumberOfPolys(),
    label << ": NumberOfTriangles");
  return true;
}

bool CheckSphere()
{
  const int n = 3000;
  vtkNew<vtkPerimeterPeelSurface> peel;
  peel->SetInputData(pcstest::MakeCloud(SpherePoints(n, 5)));
  peel->Update();
  vtkPolyData* mesh = peel->GetOutput();
  auto q = Measure(mesh);
  PCS_CHECK(mesh->GetNumberOfPoints() == n, "sphere: all points passed through");
  PCS_CHECK(FieldValue(q, "NumberOfBoundaryEdges") == 0, "sphere: closed");
  PCS_CHECK(FieldValue(q, "NumberOfNonManifoldEdges") == 0 &&
      FieldValue(q, "NumberOfNonManifoldVertices") == 0,
    "sphere: manifold");
  PCS_CHECK(FieldValue(q, "Genus") == 0, "sphere: genus 0");
  PCS_CHECK(FieldValue(q, "Coverage") >= 0.99, "sphere: coverage " << FieldValue(q, "Coverage"));
  PCS_CHECK(mesh->GetNumberOfPolys() == 2 * FieldValue(q, "NumberOfUsedPoints") - 4,
    "sphere: 2V - 4 triangles");
  PCS_CHECK(FieldValue(q, "OrientationConsistency") == 1.0, "sphere: consistent orientation");
  PCS_CHECK(SignedVolume6(mesh) > 0.0, "sphere: triangles face outward");
  std::cout << "sphere: " << mesh->GetNumberOfPolys() << " triangles, "
            << FieldValue(mesh, "NumberOfIterations") << " iterations, "
            << FieldValue(mesh, "NumberOfRemovedTetrahedra") << " removed, "
            << FieldValue(mesh, "NumberOfRestoredTetrahedra") << " restored" << std::endl;
  if (!CheckConsistentFields("sphere", mesh))
  {
    return false;
  }

  // A fixed threshold above every facet: the convex hull, nothing removed.
  vtkNew<vtkPerimeterPeelSurface> hull;
  hull->SetInputData(pcstest::MakeCloud(SpherePoints(n, 5)));
  hull->SetThreshold(100.0);
  hull->Update();
  PCS_CHECK(hull->GetOutput()->GetNumberOfPolys() == 2 * n - 4, "hull: 2V - 4 triangles");
  PCS_CHECK(FieldValue(hull->GetOutput(), "NumberOfRemovedTetrahedra") == 0, "hull: no removal");
  PCS_CHECK(FieldValue(hull->GetOutput(), "NumberOfIterations") == 1, "hull: one pass");
  return true;
}

bool CheckTorus()
{
  const int n = 5000;
  for (int measure : { vtkPerimeterPeelSurface::PERIMETER, vtkPerimeterPeelSurface::AREA,
         vtkPerimeterPeelSurface::CIRCUMRADIUS })
  {
    vtkNew<vtkPerimeterPeelSurface> peel;
    peel->SetInputData(pcstest::MakeCloud(TorusPoints(n, 9)));
    peel->SetFacetMeasure(measure);
    peel->Update();
    vtkPolyData* mesh = peel->GetOutput();
    auto q = Measure(mesh);
    PCS_CHECK(mesh->GetNumberOfPolys() > 0, "torus: triangles");
    PCS_CHECK(FieldValue(q, "NumberOfNonManifoldEdges") == 0 &&
        FieldValue(q, "NumberOfNonManifoldVertices") == 0,
      "torus (measure " << measure << "): manifold");
    PCS_CHECK(FieldValue(q, "NumberOfBoundaryEdges") == 0, "torus: closed");
    PCS_CHECK(FieldValue(q, "OrientationConsistency") == 1.0, "torus: consistent orientation");
    PCS_CHECK(SignedVolume6(mesh) > 0.0, "torus: triangles face outward");
    std::cout << "torus (measure " << measure << "): " << mesh->GetNumberOfPolys()
              << " triangles, genus " << FieldValue(q, "Genus") << ", coverage "
              << FieldValue(q, "Coverage") << std::endl;
    if (!CheckConsistentFields("torus", mesh))
    {
      return false;
    }
  }
  return true;
}
} // namespace

int TestPerimeterPeelSurface(int, char*[])
{
  bool ok = CheckSphere();
  ok = CheckTorus() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
