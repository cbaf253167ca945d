// vtkPerimeterPeelSurface on clouds whose answers are known by construction (noise-free samples of
// closed smooth surfaces, checked with vtkReconstructionQuality):
// - a sphere (3,000 uniform random points, 2,000 Fibonacci points): closed, manifold, genus 0,
//   every point used (2V - 4 triangles), one orientation, facing outward;
// - a fixed Threshold above every facet keeps the whole convex hull and removes nothing;
// - a torus (5,000 uniform random points; 5,000 Fibonacci-lattice points): closed, manifold, genus
//   1 (the hole opens by a group removal), >= 99 % of the points used, 2V triangles, outward, every
//   triangle centroid within 3 (random) / 0.5 (lattice) mean spacings of the torus; with the area
//   and circumradius measures closed, manifold and outward;
// - a genus-2 surface (a thickened lemniscate of Gerono, blue-noise sample): genus 2, >= 99 %;
// - a torus sampled 25 times more densely on one side (5,000 points, 6 seeds): with the default
//   relative measure (LocalSpacingNeighbors 6) closed, manifold, >= 99 %, genus 1 on >= 4 seeds;
// - a goblet (paper Fig. 1; 8,000 random points, uniform by area): closed, manifold, genus 0,
//   >= 99 %, and its cup stays hollow (points on the axis inside the cup are outside the solid);
// - dense random samples (100,000 points): spheres genus 0 (no spurious handle), a torus genus 1;
// - noisy random samples (20,000 points of the sphere and the torus, Gaussian noise of 0.1 mean
//   spacing) and the same points without noise: closed, manifold, genus 0 / 1, >= 97 % of the
//   points, volume within 3 % of the true volume (not hollowed), every triangle centroid within
//   one mean spacing of the surface, at most 12 % (noisy) / 4 % (no noise) of the triangles facing
//   into the solid (flaps of flat tetrahedra; 17 % on the noisy sphere before the unfolding pass);
// - ManifoldOutput off (the paper's peeling): no point left in no tetrahedron;
// - an abort requested once the peel is done (progress 0.9) stops the unfolding pass: a valid
//   output with every point and no triangle (20,000 random sphere points, about 7,000 moves);
// - a strut (rule 8): a point 20 or 30 mean spacings above a random sphere (20,000 points, outlier
//   removal off), held at the end by one tetrahedron of facets over the group start, is reported
//   unused and the strut removed: the sphere alone, every triangle within one spacing of it;
// - separate objects (rule 9): two and three random spheres of different radii and densities, far
//   apart: one closed, manifold, genus-0 component per sphere over every point, every triangle
//   within one mean spacing of its sphere; a dumbbell whose neck is sampled (radius 4 spacings)
//   stays one genus-0 component;
// - the field data agree with the mesh (triangles, used points, Used array).
#include "vtkPerimeterPeelSurface.h"
#include "vtkReconstructionQuality.h"

#include "pcsPeelTestShapes.h"
#include "pcsTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkSelectEnclosedPoints.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <random>
#include <string>

namespace
{
using namespace pcstest;

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

vtkSmartPointer<vtkPolyData> Peel(
  const std::vector<double>& xyz, int measure = 0, int spacingNeighbors = 6)
{
  vtkNew<vtkPerimeterPeelSurface> peel;
  peel->SetInputData(pcstest::MakeCloud(xyz));
  peel->SetFacetMeasure(measure);
  peel->SetLocalSpacingNeighbors(spacingNeighbors);
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
  return pcstest::FarthestCentroid(mesh,
           [](const double* c)
           {
             const double ring = std::hypot(c[0], c[1]) - 1.0;
             return std::fabs(std::hypot(ring, c[2]) - 0.35);
           }) /
    spacing;
}

bool CheckTorus()
{
  const int n = 5000;
  auto random = Peel(TorusPoints(n, 9));
  if (!CheckClosedSurface("random torus", random, 1))
  {
    return false;
  }
  PCS_CHECK(TorusDistance(random, n) <= 3.0, "random torus: distance " << TorusDistance(random, n));
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

// The goblet of the paper's Fig. 1 (a surface of revolution with a cavity): closed, manifold,
// genus 0, >= 99 % of the points, and the cup stays hollow: the axis point at mid-height inside
// the cup and the point just above its inner bottom are outside the solid, while a point in the
// stem is inside, and one in the cup's wall at ThresholdFactor 1.5 (vtkSelectEnclosedPoints).
// (The shallow top of the foot comes out pitted on random samples: no point inside the foot is
// asserted.)
bool CheckGoblet()
{
  for (unsigned seed : { 1u, 2u })
  {
    auto mesh = Peel(GobletPoints(8000, seed));
    const std::string label = "goblet (seed " + std::to_string(seed) + ")";
    if (!CheckClosedSurface(label, mesh, 0))
    {
      return false;
    }
    vtkNew<vtkSelectEnclosedPoints> enclosed;
    enclosed->Initialize(mesh);
    PCS_CHECK(!enclosed->IsInsideSurface(0.0, 0.0, 1.2), label << ": cup axis at mid-height");
    PCS_CHECK(!enclosed->IsInsideSurface(0.0, 0.0, 0.95), label << ": above the cup's bottom");
    PCS_CHECK(enclosed->IsInsideSurface(0.0, 0.0, 0.45), label << ": in the stem");
    enclosed->Complete();
    // The cup's wall (0.1, about two spacings) is thinner than the relative measure resolves at
    // ThresholdFactor 1.0: the surface zigzags through it (class docs), so a point in the wall is
    // inside on some samples only (measured on 8 other seeds: 3 of 8, 6 of 8 with the cave
    // limit). From 1.5 on the wall is clean: there the point must be inside.
    vtkNew<vtkPerimeterPeelSurface> wider;
    wider->SetInputData(pcstest::MakeCloud(GobletPoints(8000, seed)));
    wider->SetThresholdFactor(1.5);
    wider->Update();
    vtkNew<vtkSelectEnclosedPoints> wall;
    wall->Initialize(wider->GetOutput());
    PCS_CHECK(!wall->IsInsideSurface(0.0, 0.0, 1.2), label << ", factor 1.5: cup axis");
    PCS_CHECK(wall->IsInsideSurface(0.5, 0.0, 1.2), label << ", factor 1.5: in the cup's wall");
    wall->Complete();
  }
  return true;
}

bool CheckGenus2()
{
  return CheckClosedSurface("genus-2 surface", Peel(Genus2Points(12000, 3)), 2);
}

// A torus sampled 25 times more densely on one side than on the other (6 seeds): with the
// relative measure (LocalSpacingNeighbors, default 6) one threshold fits both sides: every surface
// is closed, manifold, over >= 99 % of the points, and the hole opens (genus 1) on at least 4 of
// the 6 seeds and on more seeds than with the absolute measure (0: the paper's global threshold,
// its caveat on non-uniform density). Measured: 6 of 6 relative, 2 of 6 absolute (4 and 1 before
// groups stopped at their first manifold state). Opening a handle stays fragile (a known limit, see
// the class docs).
bool CheckGradedTorus()
{
  bool ok = true;
  int handles = 0, absoluteHandles = 0;
  for (unsigned seed = 1; seed <= 6; ++seed)
  {
    const std::vector<double> xyz = GradedTorusPoints(5000, seed, 1.2);
    const std::string label = "graded torus (seed " + std::to_string(seed) + ")";
    auto mesh = Peel(xyz);
    auto q = Measure(mesh);
    PCS_CHECK(FieldValue(q, "NumberOfBoundaryEdges") == 0 &&
        FieldValue(q, "NumberOfNonManifoldEdges") == 0 &&
        FieldValue(q, "NumberOfNonManifoldVertices") == 0 && FieldValue(q, "Coverage") >= 0.99,
      label << ": closed, manifold, coverage " << FieldValue(q, "Coverage"));
    handles += FieldValue(q, "Genus") == 1 ? 1 : 0;
    auto absolute = Measure(Peel(xyz, 0, 0));
    absoluteHandles += FieldValue(absolute, "Genus") == 1 ? 1 : 0;
    std::cout << label << ": genus " << FieldValue(q, "Genus") << ", coverage "
              << FieldValue(q, "Coverage") << "; absolute measure: genus "
              << FieldValue(absolute, "Genus") << ", coverage " << FieldValue(absolute, "Coverage")
              << std::endl;
  }
  PCS_CHECK(handles >= 4 && handles > absoluteHandles,
    "graded torus: genus 1 on " << handles << " of 6 seeds (absolute measure " << absoluteHandles
                                << ")");
  std::cout << "graded torus: genus 1 on " << handles << " of 6 seeds (absolute measure: "
            << absoluteHandles << ")" << std::endl;
  return ok;
}

// Random samples of the unit sphere and of the torus (20,000 points) with Gaussian noise of 0.1
// mean spacing in each coordinate, as scans have. Before the peel compared the facets it shows
// with the smallest facet on its way in (not only with the facet it came through), it dug under
// the noisy surface layer in steps of less than 1.5 times (hull facets over the noise are 9-10
// local spacings, above the cave limit) and hollowed both shapes: a double layer, closed,
// manifold, genus 0 or 1 and over 95 % of the points, enclosing 0.7 % of the sphere's volume and
// 4 % of the torus's. Now: within 3 % of the true volume, every triangle within one spacing of the
// surface, most points used (a few lie under the noisy layer, inside the solid). The same shapes
// without noise, too. Triangles facing into the solid (normal against the surface's, thin flaps of
// flat tetrahedra): about 17 % before the unfolding pass (rule 6 of the class docs); after it, on
// these samples (printed below, 2026-11-24), 4,020 of 39,470 (10.2 %) on the noisy sphere, 923 of
// 39,996 (2.3 %) without noise, 3,889 of 39,452 (9.9 %) on the noisy torus, none on the exact
// one (the class docs' figures are from other samples, Benchmarks/results/peel.md).
bool CheckNoisy()
{
  const int n = 20000;
  struct Shape
  {
    const char* Label;
    std::vector<double> Points;
    double Spacing, Volume;
    int Genus;
    std::function<double(const double*)> Distance;
    std::function<void(const double*, double*)> Outward; // the surface's normal near a point
  };
  const Shape shapes[] = {
    { "noisy sphere",
      SpherePoints(n, 7),
      std::sqrt(4 * M_PI / n),
      4 * M_PI / 3,
      0,
      [](const double* p) { return std::fabs(std::sqrt(vtkMath::Dot(p, p)) - 1.0); },
      [](const double* p, double* n) { vtkMath::Assign(p, n); } },
    { "noisy torus",
      TorusPoints(n, 7),
      std::sqrt(4 * M_PI * M_PI * 0.35 / n),
      2 * M_PI * M_PI * 0.35 * 0.35,
      1,
      [](const double* p)
      { return std::fabs(std::hypot(std::hypot(p[0], p[1]) - 1.0, p[2]) - 0.35); },
      [](const double* p, double* n)
      {
        const double r = std::hypot(p[0], p[1]);
        n[0] = p[0] - p[0] / r;
        n[1] = p[1] - p[1] / r;
        n[2] = p[2];
      } },
  };
  bool ok = true;
  for (const Shape& shape : shapes)
  {
    for (const double sigma : { 0.1, 0.0 })
    {
      std::vector<double> xyz = shape.Points;
      std::mt19937_64 rng(11);
      std::normal_distribution<double> noise(0.0, sigma * shape.Spacing);
      for (double& x : xyz)
      {
        x += sigma > 0.0 ? noise(rng) : 0.0;
      }
      auto mesh = Peel(xyz);
      auto q = Measure(mesh);
      const std::string label = std::string(shape.Label) + (sigma > 0.0 ? "" : " (no noise)");
      PCS_CHECK(FieldValue(q, "NumberOfBoundaryEdges") == 0, label << ": closed");
      PCS_CHECK(FieldValue(q, "NumberOfNonManifoldEdges") == 0 &&
          FieldValue(q, "NumberOfNonManifoldVertices") == 0,
        label << ": manifold");
      PCS_CHECK(FieldValue(q, "NumberOfConnectedComponents") == 1, label << ": one component");
      PCS_CHECK(
        FieldValue(q, "Genus") == shape.Genus, label << ": genus " << FieldValue(q, "Genus"));
      PCS_CHECK(FieldValue(q, "OrientationConsistency") == 1.0, label << ": orientation");
      PCS_CHECK(
        FieldValue(q, "Coverage") >= 0.97, label << ": coverage " << FieldValue(q, "Coverage"));
      const double volume = SignedVolume6(mesh) / 6.0 / shape.Volume;
      double farthest = 0.0;
      int inward = 0, triangles = 0;
      for (const auto& t : pcstest::CellTuples<3>(mesh.GetPointer()))
      {
        double c[3] = { 0, 0, 0 }, p[3][3];
        for (int k = 0; k < 3; ++k)
        {
          mesh->GetPoint(t[k], p[k]);
          vtkMath::Add(c, p[k], c);
        }
        vtkMath::MultiplyScalar(c, 1.0 / 3.0);
        farthest = std::max(farthest, shape.Distance(c) / shape.Spacing);
        double u[3], v[3], normal[3], outward[3];
        vtkMath::Subtract(p[1], p[0], u);
        vtkMath::Subtract(p[2], p[0], v);
        vtkMath::Cross(u, v, normal);
        shape.Outward(c, outward);
        inward += vtkMath::Dot(normal, outward) < 0.0 ? 1 : 0;
        ++triangles;
      }
      const double inwardFraction = triangles > 0 ? double(inward) / triangles : 1.0;
      std::cout << label << ": volume / true volume " << volume << ", farthest triangle "
                << farthest << " spacings, coverage " << FieldValue(q, "Coverage") << ", genus "
                << FieldValue(q, "Genus") << ", facing inwards " << inward << " of " << triangles
                << std::endl;
      PCS_CHECK(std::fabs(volume - 1.0) <= 0.03, label << ": volume ratio " << volume);
      PCS_CHECK(farthest <= 1.0, label << ": farthest triangle " << farthest << " spacings");
      PCS_CHECK(inwardFraction <= (sigma > 0.0 ? 0.12 : 0.04),
        label << ": " << inward << " of " << triangles << " triangles face inwards");
      ok = CheckConsistentFields(label.c_str(), mesh) && ok;
    }
  }
  return ok;
}

// Dense random samples of a sphere (100,000 points): the surface is the convex hull, genus 0; no
// group removal may open a handle. Before a handle needed a start facet over 2 x GroupFactor x
// threshold, these two seeds got small spurious tunnels between two dents (genus 1 and 2; seeds
// 1-8: 2 failures; at 40,000 points none).
bool CheckDenseSpheres()
{
  bool ok = true;
  for (unsigned seed : { 5u, 6u })
  {
    const std::string label = "dense random sphere (seed " + std::to_string(seed) + ")";
    ok = CheckClosedSurface(label, Peel(SpherePoints(100000, seed)), 0) && ok;
  }
  return ok;
}

// A dense random sample of the torus (100,000 points): closed, manifold, genus 1. Before a group
// stopped at the first cell after which the boundary is a manifold again (its links were checked
// only when it doubled), the groups started over the hole went on along the tube to the size bound
// and the hole stayed closed at this density: genus 0 on seeds 2-6 and 8 of 1-8 (this one: seed 2).
bool CheckDenseTorus()
{
  return CheckClosedSurface("dense random torus (seed 2)", Peel(TorusPoints(100000, 2)), 1);
}
// A strut (rule 8): a point held by one tetrahedron whose facets through it all measure over the
// group start. A point 20 or 30 mean spacings above a random sphere (20,000 points; far outlier
// removal off, so that the point is tetrahedralized): the peel removes every cell of the point but
// the last (no point lost), a spike whose facets through the point are over the group start. The
// rule removes it and reports the point unused: the sphere's surface alone (closed, manifold,
// genus 0), every triangle centroid within one mean spacing of the sphere, the point's Used 0 and
// NumberOfStrutPoints 1. Without the rule the spike stays: triangles 6.6 (20) and 9.9 (30)
// spacings out on both seeds (2026-11-24).
bool CheckStrutAt(unsigned seed, double height)
{
  const int n = 20000;
  const double spacing = 0.5 * std::sqrt(4 * M_PI / n);
  const std::string label = "strut of " + std::to_string(static_cast<int>(height)) +
    " spacings (seed " + std::to_string(seed) + ")";
  std::vector<double> xyz = SpherePoints(n, seed);
  xyz.insert(xyz.end(), { 0.0, 0.0, 1.0 + height * spacing });
  vtkNew<vtkPerimeterPeelSurface> peel;
  peel->SetInputData(pcstest::MakeCloud(xyz));
  peel->SetOutlierFactor(0.0);
  peel->Update();
  vtkPolyData* mesh = peel->GetOutput();
  const double farthest = pcstest::FarthestCentroid(
    mesh, [spacing](const double* c) { return std::fabs(vtkMath::Norm(c) - 1.0) / spacing; });
  std::cout << label << ": farthest triangle centroid " << farthest << " spacings, "
            << FieldValue(mesh, "NumberOfStrutPoints") << " strut point(s)" << std::endl;
  PCS_CHECK(farthest <= 1.0, label << ": a triangle " << farthest << " spacings out");
  PCS_CHECK(mesh->GetPointData()->GetArray("Used")->GetTuple1(n) == 0, label << ": point used");
  PCS_CHECK(FieldValue(mesh, "NumberOfStrutPoints") == 1, label << ": NumberOfStrutPoints");
  return CheckClosedSurface(label, mesh, 0);
}

bool CheckStrut()
{
  bool ok = true;
  for (unsigned seed : { 1u, 2u })
  {
    for (double height : { 20.0, 30.0 })
    {
      ok = CheckStrutAt(seed, height) && ok;
    }
  }
  return ok;
}

// Separate objects (rule 9): random samples of spheres of different radii and densities, far
// apart. Each sphere comes out as its own closed, manifold, genus-0 component over every point
// (2V - 4 triangles per component), every triangle centroid within one mean spacing of its
// sphere. Before the rule the peel joined them by a neck of long triangles that no group could
// remove (its removal splits the solid): one component, triangles 8-20 spacings out (2026-11-24).
struct Ball
{
  std::array<double, 3> Centre;
  double Radius;
  int Points;
  double Spacing() const { return Radius * std::sqrt(4 * M_PI / Points); }
};

bool CheckSeparateBalls(const std::string& label, const std::vector<Ball>& balls, unsigned seed)
{
  std::vector<double> xyz;
  for (const Ball& b : balls)
  {
    const std::vector<double> unit = SpherePoints(b.Points, seed++);
    for (size_t i = 0; i < unit.size(); ++i)
    {
      xyz.push_back(b.Centre[i % 3] + b.Radius * unit[i]);
    }
  }
  vtkSmartPointer<vtkPolyData> mesh = Peel(xyz);
  auto q = Measure(mesh);
  const double farthest = pcstest::FarthestCentroid(mesh,
    [&balls](const double* c)
    {
      double nearest = VTK_DOUBLE_MAX;
      for (const Ball& b : balls)
      {
        const double d = std::sqrt(vtkMath::Distance2BetweenPoints(c, b.Centre.data()));
        nearest = std::min(nearest, std::fabs(d - b.Radius) / b.Spacing());
      }
      return nearest;
    });
  const double components = FieldValue(q, "NumberOfConnectedComponents");
  std::cout << label << ": " << mesh->GetNumberOfPolys() << " triangles, " << components
            << " components, farthest triangle centroid " << farthest << " spacings, "
            << FieldValue(mesh, "NumberOfGroupRemovals") << " groups" << std::endl;
  const double count = static_cast<double>(balls.size());
  PCS_CHECK(components == count, label << ": " << components << " components");
  PCS_CHECK(FieldValue(q, "NumberOfBoundaryEdges") == 0, label << ": closed");
  PCS_CHECK(FieldValue(q, "NumberOfNonManifoldEdges") == 0 &&
      FieldValue(q, "NumberOfNonManifoldVertices") == 0,
    label << ": manifold");
  PCS_CHECK(FieldValue(q, "Genus") == 0, label << ": genus " << FieldValue(q, "Genus"));
  PCS_CHECK(FieldValue(mesh, "NumberOfUnusedPoints") == 0, label << ": unused points");
  PCS_CHECK(mesh->GetNumberOfPolys() == 2 * FieldValue(q, "NumberOfUsedPoints") - 4 * count,
    label << ": 2V - 4 triangles per component");
  PCS_CHECK(FieldValue(q, "OrientationConsistency") == 1.0, label << ": consistent orientation");
  PCS_CHECK(SignedVolume6(mesh) > 0.0, label << ": triangles face outward");
  PCS_CHECK(farthest <= 1.0, label << ": a triangle " << farthest << " spacings out");
  return CheckConsistentFields(label.c_str(), mesh);
}

// Random points of a dumbbell: two unit spheres, centres 3 apart on the x axis, joined by a
// cylinder of radius `neck` along the axis; uniform by area (each point of a part inside another
// part is drawn again).
std::vector<double> DumbbellPoints(int n, double neck, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 1.0);
  const double length = 3.0, sphereArea = 4 * M_PI, neckArea = 2 * M_PI * neck * length;
  auto inSphere = [](const double* p, double cx)
  { return (p[0] - cx) * (p[0] - cx) + p[1] * p[1] + p[2] * p[2] < 1.0 - 1e-12; };
  std::vector<double> xyz;
  while (static_cast<int>(xyz.size() / 3) < n)
  {
    const double pick = u(rng) * (2 * sphereArea + neckArea);
    double p[3];
    bool keep = true;
    if (pick < 2 * sphereArea)
    {
      const double cx = pick < sphereArea ? 0.0 : length;
      double d[3] = { g(rng), g(rng), g(rng) };
      const double r = vtkMath::Norm(d);
      p[0] = cx + d[0] / r;
      p[1] = d[1] / r;
      p[2] = d[2] / r;
      keep = !inSphere(p, length - cx) &&
        !(p[0] > 0.0 && p[0] < length && p[1] * p[1] + p[2] * p[2] < neck * neck * (1 - 1e-12));
    }
    else
    {
      const double a = 2 * M_PI * u(rng);
      p[0] = length * u(rng);
      p[1] = neck * std::cos(a);
      p[2] = neck * std::sin(a);
      keep = !inSphere(p, 0.0) && !inSphere(p, length);
    }
    if (keep)
    {
      xyz.insert(xyz.end(), { p[0], p[1], p[2] });
    }
  }
  return xyz;
}

bool CheckSeparateObjects()
{
  bool ok = CheckSeparateBalls("two spheres, radii 1 and 0.5",
    { { { 0.0, 0.0, 0.0 }, 1.0, 4000 }, { { 3.0, 0.0, 0.0 }, 0.5, 1000 } },
    11);
  ok = CheckSeparateBalls("three spheres, radii 1, 0.5 and 0.3, three densities",
         { { { 0.0, 0.0, 0.0 }, 1.0, 4000 },
           { { 2.5, 0.0, 0.0 }, 0.5, 3000 },
           { { 0.0, 2.0, 0.5 }, 0.3, 2000 } },
         21) &&
    ok;
  // A dumbbell whose neck is sampled (radius 4 mean spacings) is one object: the neck's surface
  // triangles are of the sampling's size, never over the group start, so it stays.
  const int n = 12000;
  const double spacing = std::sqrt((8 * M_PI) / n);
  ok = CheckClosedSurface(
         "dumbbell, neck of 4 spacings", Peel(DumbbellPoints(n, 4 * spacing, 3)), 0) &&
    ok;
  return ok;
}

// Abort during the unfolding pass (rule 6): requested at the progress 0.9 reported when the peel
// is done, it must stop the pass (which reports progress and reads the flag) and leave an output
// with every point and no triangle, as an abort during the peel does.
bool CheckAbortInUnfolding()
{
  const int n = 20000;
  vtkNew<vtkPerimeterPeelSurface> peel;
  peel->SetInputData(pcstest::MakeCloud(SpherePoints(n, 5)));
  struct State
  {
    vtkPerimeterPeelSurface* Filter;
    bool Requested;
  } state{ peel, false };
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(&state);
  callback->SetCallback(
    [](vtkObject*, unsigned long, void* client, void* call)
    {
      auto* s = static_cast<State*>(client);
      const double progress = *static_cast<double*>(call);
      if (!s->Requested && progress >= 0.9 && progress < 1.0)
      {
        s->Requested = true;
        s->Filter->SetAbortExecute(1);
      }
    });
  peel->AddObserver(vtkCommand::ProgressEvent, callback);
  peel->Update();
  vtkPolyData* out = peel->GetOutput();
  PCS_CHECK(state.Requested, "abort in unfolding: no progress event at 0.9");
  PCS_CHECK(out->GetNumberOfPoints() == n,
    "abort in unfolding: " << out->GetNumberOfPoints() << " points, expected " << n);
  PCS_CHECK(out->GetNumberOfPolys() == 0,
    "abort in unfolding: " << out->GetNumberOfPolys() << " triangles: the pass did not stop");
  return true;
}
} // namespace

int TestPerimeterPeelSurface(int, char*[])
{
  bool ok = CheckSphere();
  ok = CheckTorus() && ok;
  ok = CheckGenus2() && ok;
  ok = CheckGradedTorus() && ok;
  ok = CheckGoblet() && ok;
  ok = CheckDenseSpheres() && ok;
  ok = CheckDenseTorus() && ok;
  ok = CheckNoisy() && ok;
  ok = CheckAbortInUnfolding() && ok;
  ok = CheckStrut() && ok;
  ok = CheckSeparateObjects() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
