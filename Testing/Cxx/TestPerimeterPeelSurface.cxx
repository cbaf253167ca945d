// vtkPerimeterPeelSurface on clouds whose answers are known by construction (noise-free samples of
// closed smooth surfaces, checked with vtkReconstructionQuality):
// - a sphere (3,000 uniform random points, 2,000 Fibonacci points): closed, manifold, genus 0,
//   every point used (2V - 4 triangles), one orientation, facing outward;
// - a fixed Threshold above every facet keeps the whole convex hull and removes nothing;
// - a torus (5,000 uniform random points; 5,000 Fibonacci-lattice points): closed, manifold, genus
//   1 (the hole opens by a group removal), >= 99 % of the points used, 2V triangles, outward, every
//   triangle centroid within 1.5 (random) / 0.5 (lattice) mean spacings of the torus; with the area
//   and circumradius measures closed, manifold and outward;
// - a genus-2 surface (a thickened lemniscate of Gerono, blue-noise sample): genus 2, >= 99 %;
// - ManifoldOutput off (the paper's peeling): no point left in no tetrahedron;
// - the field data agree with the mesh (triangles, used points, Used array).
#include "vtkPerimeterPeelSurface.h"
#include "vtkReconstructionQuality.h"

#include "pcsTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

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

// Fibonacci (golden spiral) points on the unit sphere.
std::vector<double> FibonacciSphere(int n)
{
  std::vector<double> xyz;
  for (int i = 0; i < n; ++i)
  {
    const double z = 1.0 - (2.0 * i + 1.0) / n, r = std::sqrt(1.0 - z * z);
    const double a = M_PI * (1.0 + std::sqrt(5.0)) * i;
    xyz.insert(xyz.end(), { r * std::cos(a), r * std::sin(a), z });
  }
  return xyz;
}

// A golden-ratio lattice on the torus of TorusPoints, area-uniform: the tube angle b solves (b +
// 0.35 sin b) / (2 pi) = u for evenly spaced u (Newton steps).
std::vector<double> FibonacciTorus(int n)
{
  const double golden = (std::sqrt(5.0) - 1.0) / 2.0;
  std::vector<double> xyz;
  for (int i = 0; i < n; ++i)
  {
    const double a = 2 * M_PI * std::fmod(i * golden, 1.0);
    const double u = 2 * M_PI * (i + 0.5) / n;
    double b = u;
    for (int k = 0; k < 50; ++k)
    {
      b -= (b + 0.35 * std::sin(b) - u) / (1.0 + 0.35 * std::cos(b));
    }
    const double r = 1.0 + 0.35 * std::cos(b);
    xyz.insert(xyz.end(), { r * std::cos(a), r * std::sin(a), 0.35 * std::sin(b) });
  }
  return xyz;
}

// A genus-2 surface: f = g^2 + z^2 - 0.1^2 = 0 with g = x^2 (1 - x^2) - y^2 (a tube around the
// figure-eight lemniscate of Gerono, smooth since 0.1 is no critical value of g). Random points of
// a box are projected onto it by Newton steps, then thinned to a blue-noise sample (no two points
// closer than `radius`, chosen for about n points): roughly uniform by area.
std::vector<double> Genus2Points(int n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(-1.2, 1.2), uy(-0.6, 0.6), uz(-0.15, 0.15);
  const double radius = 0.5 * std::sqrt(4.6 / n);
  std::map<std::array<long, 3>, std::vector<std::array<double, 3>>> grid;
  std::vector<double> xyz;
  for (int trial = 0; trial < 40 * n; ++trial)
  {
    double p[3] = { ux(rng), uy(rng), uz(rng) };
    double f = 1.0;
    for (int k = 0; k < 30; ++k)
    {
      const double g = p[0] * p[0] * (1 - p[0] * p[0]) - p[1] * p[1];
      f = g * g + p[2] * p[2] - 0.01;
      const double d[3] = { 2 * g * (2 * p[0] - 4 * p[0] * p[0] * p[0]), -4 * g * p[1], 2 * p[2] };
      const double d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      if (d2 < 1e-30)
      {
        break;
      }
      for (int j = 0; j < 3; ++j)
      {
        p[j] -= f / d2 * d[j];
      }
    }
    if (!(std::fabs(f) < 1e-12))
    {
      continue;
    }
    const std::array<long, 3> cell = { std::lround(std::floor(p[0] / radius)),
      std::lround(std::floor(p[1] / radius)), std::lround(std::floor(p[2] / radius)) };
    bool free = true;
    for (long dx = -1; dx <= 1 && free; ++dx)
    {
      for (long dy = -1; dy <= 1 && free; ++dy)
      {
        for (long dz = -1; dz <= 1 && free; ++dz)
        {
          auto it = grid.find({ cell[0] + dx, cell[1] + dy, cell[2] + dz });
          for (size_t k = 0; it != grid.end() && k < it->second.size() && free; ++k)
          {
            const auto& q = it->second[k];
            free = std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) >= radius;
          }
        }
      }
    }
    if (free)
    {
      grid[cell].push_back({ p[0], p[1], p[2] });
      xyz.insert(xyz.end(), { p[0], p[1], p[2] });
    }
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

// A closed, manifold, consistently oriented, outward surface of the given genus over >= 99 % of the
// points, with V - E + F = 2 - 2 genus (2V - 4 + 4 genus triangles over its V points).
bool CheckClosedSurface(const std::string& label, vtkPolyData* mesh, int genus)
{
  auto q = Measure(mesh);
  PCS_CHECK(mesh->GetNumberOfPolys() > 0, label << ": triangles");
  PCS_CHECK(FieldValue(q, "NumberOfBoundaryEdges") == 0, label << ": closed");
  PCS_CHECK(FieldValue(q, "NumberOfNonManifoldEdges") == 0 &&
      FieldValue(q, "NumberOfNonManifoldVertices") == 0,
    label << ": manifold");
  PCS_CHECK(FieldValue(q, "NumberOfConnectedComponents") == 1, label << ": one component");
  PCS_CHECK(FieldValue(q, "Genus") == genus,
    label << ": genus " << FieldValue(q, "Genus") << ", expected " << genus);
  PCS_CHECK(FieldValue(q, "Coverage") >= 0.99, label << ": coverage " << FieldValue(q, "Coverage"));
  PCS_CHECK(mesh->GetNumberOfPolys() == 2 * FieldValue(q, "NumberOfUsedPoints") - 4 + 4 * genus,
    label << ": 2V - 4 + 4g triangles");
  PCS_CHECK(FieldValue(q, "OrientationConsistency") == 1.0, label << ": consistent orientation");
  PCS_CHECK(SignedVolume6(mesh) > 0.0, label << ": triangles face outward");
  std::cout << label << ": " << mesh->GetNumberOfPolys() << " triangles, genus "
            << FieldValue(q, "Genus") << ", coverage " << FieldValue(q, "Coverage") << ", "
            << FieldValue(mesh, "NumberOfIterations") << " iterations, "
            << FieldValue(mesh, "NumberOfRemovedTetrahedra") << " removed, "
            << FieldValue(mesh, "NumberOfGroupRemovals") << " groups" << std::endl;
  return CheckConsistentFields(label.c_str(), mesh);
}

vtkSmartPointer<vtkPolyData> Peel(const std::vector<double>& xyz, int measure = 0)
{
  vtkNew<vtkPerimeterPeelSurface> peel;
  peel->SetInputData(pcstest::MakeCloud(xyz));
  peel->SetFacetMeasure(measure);
  peel->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(peel->GetOutput());
  return out;
}

bool CheckSphere()
{
  const int n = 3000;
  auto mesh = Peel(SpherePoints(n, 5));
  PCS_CHECK(mesh->GetNumberOfPoints() == n, "sphere: all points passed through");
  if (!CheckClosedSurface("random sphere", mesh, 0) ||
    !CheckClosedSurface("Fibonacci sphere", Peel(FibonacciSphere(2000)), 0))
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

// The largest distance from a triangle's centroid to the torus, in mean sample spacings.
double TorusDistance(vtkPolyData* mesh, int n)
{
  const double spacing = std::sqrt(4 * M_PI * M_PI * 0.35 / n);
  double largest = 0.0;
  for (const auto& t : pcstest::CellTuples<3>(mesh))
  {
    double c[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      double p[3];
      mesh->GetPoint(t[k], p);
      c[0] += p[0] / 3;
      c[1] += p[1] / 3;
      c[2] += p[2] / 3;
    }
    const double ring = std::hypot(c[0], c[1]) - 1.0;
    largest = std::max(largest, std::fabs(std::hypot(ring, c[2]) - 0.35));
  }
  return largest / spacing;
}

bool CheckTorus()
{
  const int n = 5000;
  auto random = Peel(TorusPoints(n, 9));
  if (!CheckClosedSurface("random torus", random, 1))
  {
    return false;
  }
  PCS_CHECK(TorusDistance(random, n) <= 1.5, "random torus: distance " << TorusDistance(random, n));
  // The paper's alternative measures (it found them weaker, and so do we: the area and the
  // circumradius of the triangles of a random sample spread much more than their perimeter, so the
  // hole may stay closed or extra handles open): closed, manifold, outward, all points.
  for (int measure : { vtkPerimeterPeelSurface::AREA, vtkPerimeterPeelSurface::CIRCUMRADIUS })
  {
    auto mesh = Peel(TorusPoints(n, 9), measure);
    auto q = Measure(mesh);
    const std::string label = "random torus (measure " + std::to_string(measure) + ")";
    PCS_CHECK(FieldValue(q, "NumberOfBoundaryEdges") == 0, label << ": closed");
    PCS_CHECK(FieldValue(q, "NumberOfNonManifoldEdges") == 0 &&
        FieldValue(q, "NumberOfNonManifoldVertices") == 0,
      label << ": manifold");
    PCS_CHECK(FieldValue(q, "OrientationConsistency") == 1.0, label << ": orientation");
    PCS_CHECK(SignedVolume6(mesh) > 0.0, label << ": outward");
    PCS_CHECK(FieldValue(q, "Coverage") >= 0.99, label << ": coverage");
    std::cout << label << ": genus " << FieldValue(q, "Genus") << std::endl;
  }
  auto mesh = Peel(FibonacciTorus(n));
  if (!CheckClosedSurface("Fibonacci torus", mesh, 1))
  {
    return false;
  }
  PCS_CHECK(TorusDistance(mesh, n) <= 0.5, "Fibonacci torus: distance " << TorusDistance(mesh, n));

  // The paper's peeling (ManifoldOutput off) never leaves a point in no tetrahedron.
  vtkNew<vtkPerimeterPeelSurface> paper;
  paper->SetInputData(pcstest::MakeCloud(TorusPoints(n, 9)));
  paper->ManifoldOutputOff();
  paper->Update();
  PCS_CHECK(FieldValue(paper->GetOutput(), "NumberOfUsedPoints") == n, "paper: every point used");
  PCS_CHECK(FieldValue(paper->GetOutput(), "NumberOfGroupRemovals") == 0, "paper: no group");
  return CheckConsistentFields("paper", paper->GetOutput());
}

bool CheckGenus2()
{
  return CheckClosedSurface("genus-2 surface", Peel(Genus2Points(12000, 3)), 2);
}
} // namespace

int TestPerimeterPeelSurface(int, char*[])
{
  bool ok = CheckSphere();
  ok = CheckTorus() && ok;
  ok = CheckGenus2() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
