// vtkLocalOptimumGrowth on clouds whose surface is known by construction; every property is
// measured with vtkReconstructionQuality:
// - the paper's 441-point ball (MATLAB's sphere(20): 21 x 21 latitude-longitude grid whose poles
//   and seam repeat points, 382 distinct): 59 duplicates merged, a closed genus-0 mesh of
//   2 * 382 - 4 = 760 triangles (the paper's count), every distinct point used, outwards;
// - 3000 random points on the unit sphere: closed, manifold, oriented, genus 0, 2V - 4
//   triangles, every point used, Hausdorff distance to the sphere within 2 mean spacings;
// - 4000 random points on a torus: closed, manifold, oriented, genus 1, 2V triangles;
// - an open height-field patch (with a NaN point and exact duplicates): one boundary loop, Euler
//   characteristic 1, every finite distinct point used, the NaN point skipped and reported;
// - open tubes of 10- and 30-point rings: the ends of the thin one (radius 1.62 spacings) capped
//   by the narrow-loop fill (closed, genus 0, 2V - 4 triangles), those of the wide one (4.79
//   spacings) and of both with MaximumHoleEdges 0 left open (two loops, Euler characteristic 0);
// - a planar 20 x 20 grid (cocircular and collinear points everywhere): 722 triangles, one loop;
// - small flat patches (30-200 random points on a square): open, no edge with both triangles on
//   one side (the border loop was once filled back onto the patch: a closed flat double layer);
// - the surface of a box sampled on an integer grid (12 x 9 x 7 points, 406, points exactly on
//   its edges), holes not closed: every point used, six disks, every triangle in a face;
// - a tilted plane scanned in lines of an integer lattice: no zero-area triangle, manifold,
//   every point used;
// - a plane scanned in 40 lines 8.8 point spacings apart, tilted along the lines (z = x), where
//   the front once stalled tens of thousands of times (7,493 seeds at c90bb02; the quadratic
//   retry of the deferred edges took minutes here: the ctest timeout catches it): the strip
//   triangulation of its lines from one seed (2 (N - 1) (L - 1) triangles, each between two
//   adjacent lines, one disk over every point);
// - spheres sampled on latitude rings 3.5 and 4 times farther apart than their points (scan
//   lines; constraint 2 alone refuses every triangle between two rings), clean and with noise:
//   one component; clean, closed, genus 0 over every point;
// - two disjoint spheres: two closed components (the front dies, a second seed is planted);
// - random sphere and torus samples that once kept a sliver hole, gained a handle or left a
//   point unused: closed, genus 0 / 1, every point used; on the spheres (and the 3000-point
//   sphere above) no edge folded over between two triangles without a sliver angle (below 5
//   degrees);
// - open random hemispheres: one boundary loop, every point used, no edge longer than 6 h (no
//   chords across the rim);
// - noisy random spheres (noise a fifth of the mean spacing): closed, manifold, and at most 1.4 %
//   of the edges folded over (1.82 % when step 7 flipped to the shorter diagonal only);
// - degenerate inputs (no point, 2 points, collinear points): a warning and no triangle.
#include "vtkLocalOptimumGrowth.h"
#include "vtkReconstructionQuality.h"

#include "pcsTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <random>
#include <string>

namespace
{
struct Quality
{
  double Triangles, UsedPoints, BoundaryEdges, Loops, NonManifoldEdges, NonManifoldVertices, Genus,
    Orientation, Components, Euler, Degenerate, Duplicates, Hausdorff, Spacing;
};

Quality Measure(vtkPolyData* mesh, vtkPolyData* reference = nullptr)
{
  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputData(mesh);
  if (reference)
  {
    quality->SetReferenceData(reference);
  }
  quality->Update();
  vtkFieldData* fd = quality->GetOutput()->GetFieldData();
  auto get = [fd](const char* name) {
    vtkDataArray* array = fd->GetArray(name);
    return array ? array->GetTuple1(0) : std::numeric_limits<double>::quiet_NaN();
  };
  return { get("NumberOfTriangles"), get("NumberOfUsedPoints"), get("NumberOfBoundaryEdges"),
    get("NumberOfBoundaryLoops"), get("NumberOfNonManifoldEdges"),
    get("NumberOfNonManifoldVertices"), get("Genus"), get("OrientationConsistency"),
    get("NumberOfConnectedComponents"), get("EulerCharacteristic"),
    get("NumberOfDegenerateTriangles"), get("NumberOfDuplicateTriangles"), get("Hausdorff"),
    get("MeanSpacing") };
}

// Counts the warnings of the filter while it updates.
int UpdateCountingWarnings(vtkLocalOptimumGrowth* filter)
{
  int warnings = 0;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  callback->SetClientData(&warnings);
  filter->AddObserver(vtkCommand::WarningEvent, callback);
  filter->Update();
  filter->RemoveObservers(vtkCommand::WarningEvent);
  return warnings;
}

// Signed volume of the closed mesh (positive: outward orientation).
double SignedVolume(vtkPolyData* mesh)
{
  double volume = 0.0;
  for (const auto& t : pcstest::CellTuples<3>(mesh))
  {
    double a[3], b[3], c[3], cross[3];
    mesh->GetPoint(t[0], a);
    mesh->GetPoint(t[1], b);
    mesh->GetPoint(t[2], c);
    vtkMath::Cross(b, c, cross);
    volume += vtkMath::Dot(a, cross) / 6.0;
  }
  return volume;
}

// Edges whose two triangles fold over (normals with a negative dot product), counted only when
// both triangles have every angle of at least `sliverAngle` degrees (default 5): a closed smooth
// surface sampled densely has none (a sliver's normal says little about the surface).
int CountFolds(vtkPolyData* mesh, double sliverAngle = 5.0)
{
  std::map<std::pair<vtkIdType, vtkIdType>, std::array<double, 3>> owners;
  int folds = 0;
  for (const auto& t : pcstest::CellTuples<3>(mesh))
  {
    double p[3][3];
    for (int j = 0; j < 3; ++j)
    {
      mesh->GetPoint(t[j], p[j]);
    }
    double smallest = 180.0;
    for (int j = 0; j < 3; ++j)
    {
      double u[3], v[3];
      vtkMath::Subtract(p[(j + 1) % 3], p[j], u);
      vtkMath::Subtract(p[(j + 2) % 3], p[j], v);
      smallest =
        std::min(smallest, vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(u, v)));
    }
    if (smallest < sliverAngle)
    {
      continue;
    }
    double u[3], v[3], n[3];
    vtkMath::Subtract(p[1], p[0], u);
    vtkMath::Subtract(p[2], p[0], v);
    vtkMath::Cross(u, v, n);
    vtkMath::Normalize(n);
    for (int j = 0; j < 3; ++j)
    {
      const auto twin = owners.find({ t[(j + 1) % 3], t[j] });
      if (twin != owners.end() && vtkMath::Dot(twin->second.data(), n) < 0.0)
      {
        ++folds;
      }
      owners[{ t[j], t[(j + 1) % 3] }] = { n[0], n[1], n[2] };
    }
  }
  return folds;
}

bool CheckClosed(const Quality& q, double genus, const std::string& what)
{
  PCS_CHECK(q.BoundaryEdges == 0, what << ": " << q.BoundaryEdges << " boundary edges");
  PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0,
    what << ": non-manifold " << q.NonManifoldEdges << " edges, " << q.NonManifoldVertices
         << " vertices");
  PCS_CHECK(q.Orientation == 1.0, what << ": orientation consistency " << q.Orientation);
  PCS_CHECK(q.Genus == genus, what << ": genus " << q.Genus << ", expected " << genus);
  PCS_CHECK(q.Degenerate == 0 && q.Duplicates == 0,
    what << ": " << q.Degenerate << " degenerate, " << q.Duplicates << " duplicate triangles");
  return true;
}

std::vector<double> RandomSphere(int n, unsigned seed, const double center[3], double radius)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<double> xyz;
  while (xyz.size() < 3 * static_cast<size_t>(n))
  {
    double p[3] = { gauss(rng), gauss(rng), gauss(rng) };
    const double length = vtkMath::Norm(p);
    if (length > 0.0)
    {
      for (int i = 0; i < 3; ++i)
      {
        xyz.push_back(center[i] + radius * p[i] / length);
      }
    }
  }
  return xyz;
}

//------------------------------------------------------------------------------------------------
bool TestPaperBall()
{
  // MATLAB: [x, y, z] = sphere(20), the poles and the seam explicitly exact.
  const int n = 20;
  std::vector<double> xyz;
  for (int i = 0; i <= n; ++i)
  {
    const double phi = (-n + 2.0 * i) / n * vtkMath::Pi() / 2.0;
    const double cosphi = (i == 0 || i == n) ? 0.0 : std::cos(phi);
    for (int j = 0; j <= n; ++j)
    {
      const double theta = (-n + 2.0 * j) / n * vtkMath::Pi();
      const double sintheta = (j == 0 || j == n) ? 0.0 : std::sin(theta);
      xyz.insert(xyz.end(), { cosphi * std::cos(theta), cosphi * sintheta, std::sin(phi) });
    }
  }
  vtkNew<vtkLocalOptimumGrowth> growth;
  growth->SetInputData(pcstest::MakeCloud(xyz));
  UpdateCountingWarnings(growth); // warns about the 59 duplicates
  vtkPolyData* mesh = growth->GetOutput();
  const Quality q = Measure(mesh);
  PCS_CHECK(growth->GetNumberOfInputPoints() == 441, "441 input points");
  PCS_CHECK(growth->GetNumberOfDuplicatePoints() == 59,
    "duplicates " << growth->GetNumberOfDuplicatePoints());
  PCS_CHECK(growth->GetNumberOfUnusedPoints() == 0, "unused " << growth->GetNumberOfUnusedPoints());
  PCS_CHECK(q.UsedPoints == 382, "used points " << q.UsedPoints);
  PCS_CHECK(q.Triangles == 760, "paper ball: " << q.Triangles << " triangles, expected 760");
  PCS_CHECK(pcstest::FieldCount(mesh, "NumberOfTriangles") == 760, "field data triangles");
  PCS_CHECK(pcstest::FieldCount(mesh, "NumberOfDuplicatePoints") == 59, "field data duplicates");
  PCS_CHECK(CheckClosed(q, 0, "paper ball"), "");
  PCS_CHECK(SignedVolume(mesh) > 0.0, "outward orientation");
  // Every duplicate names a representative at the same place, which is used.
  vtkDataArray* representative = mesh->GetPointData()->GetArray("RepresentativeId");
  vtkDataArray* used = mesh->GetPointData()->GetArray("Used");
  PCS_CHECK(representative && used, "point data RepresentativeId and Used");
  for (vtkIdType i = 0; i < 441; ++i)
  {
    const vtkIdType r = static_cast<vtkIdType>(representative->GetTuple1(i));
    double p[3], pr[3];
    mesh->GetPoint(i, p);
    mesh->GetPoint(r, pr);
    PCS_CHECK(p[0] == pr[0] && p[1] == pr[1] && p[2] == pr[2], "representative elsewhere");
    PCS_CHECK(used->GetTuple1(i) == (r == i ? 1 : 0), "Used of point " << i);
  }
  return true;
}

bool TestSphere()
{
  const double center[3] = { 0, 0, 0 };
  const int n = 3000;
  vtkNew<vtkLocalOptimumGrowth> growth;
  growth->SetInputData(pcstest::MakeCloud(RandomSphere(n, 11, center, 1.0)));
  PCS_CHECK(UpdateCountingWarnings(growth) == 0, "no warning on a clean sphere");
  vtkNew<vtkSphereSource> exact;
  exact->SetRadius(1.0);
  exact->SetThetaResolution(400);
  exact->SetPhiResolution(200);
  exact->Update();
  const Quality q = Measure(growth->GetOutput(), exact->GetOutput());
  PCS_CHECK(CheckClosed(q, 0, "sphere"), "");
  PCS_CHECK(q.UsedPoints == n && growth->GetNumberOfUnusedPoints() == 0, "every point used");
  PCS_CHECK(
    q.Triangles == 2 * n - 4, "sphere: " << q.Triangles << " triangles, 2V-4 = " << 2 * n - 4);
  PCS_CHECK(q.Hausdorff <= 2.0 * q.Spacing,
    "Hausdorff " << q.Hausdorff << " > 2 x mean spacing " << q.Spacing);
  PCS_CHECK(SignedVolume(growth->GetOutput()) > 0.0, "outward orientation");
  PCS_CHECK(growth->GetNumberOfSeeds() == 1, "one seed: " << growth->GetNumberOfSeeds());
  PCS_CHECK(CountFolds(growth->GetOutput()) == 0, "sphere: folded edges");
  return true;
}

bool TestTorus()
{
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0.0, 2.0 * vtkMath::Pi()), w(0.0, 1.0);
  const double big = 1.0, small = 0.35;
  std::vector<double> xyz;
  const int n = 4000;
  while (xyz.size() < 3 * static_cast<size_t>(n))
  {
    // Uniform on the surface: accept the tube angle with probability proportional to the
    // local circumference.
    const double a = u(rng), b = u(rng);
    if (w(rng) * (big + small) <= big + small * std::cos(b))
    {
      xyz.insert(xyz.end(),
        { (big + small * std::cos(b)) * std::cos(a), (big + small * std::cos(b)) * std::sin(a),
          small * std::sin(b) });
    }
  }
  vtkNew<vtkLocalOptimumGrowth> growth;
  growth->SetInputData(pcstest::MakeCloud(xyz));
  growth->Update();
  const Quality q = Measure(growth->GetOutput());
  PCS_CHECK(CheckClosed(q, 1, "torus"), "");
  PCS_CHECK(q.UsedPoints == n && growth->GetNumberOfUnusedPoints() == 0, "every point used");
  PCS_CHECK(q.Triangles == 2 * n, "torus: " << q.Triangles << " triangles, 2V = " << 2 * n);
  PCS_CHECK(SignedVolume(growth->GetOutput()) > 0.0, "outward orientation");
  return true;
}

bool TestOpenPatch()
{
  // A smooth height field over a disk, random points, plus a NaN point and 5 exact duplicates.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> xyz;
  while (xyz.size() < 3 * 2000)
  {
    const double x = u(rng), y = u(rng);
    if (x * x + y * y <= 1.0)
    {
      xyz.insert(xyz.end(), { x, y, 0.2 * std::sin(2.0 * x) * std::cos(1.5 * y) });
    }
  }
  for (int i = 0; i < 5; ++i)
  {
    xyz.insert(xyz.end(), { xyz[30 * i], xyz[30 * i + 1], xyz[30 * i + 2] });
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  xyz.insert(xyz.end(), { nan, 0.0, 0.0 });
  vtkNew<vtkLocalOptimumGrowth> growth;
  growth->SetInputData(pcstest::MakeCloud(xyz));
  PCS_CHECK(UpdateCountingWarnings(growth) >= 2, "warnings about the NaN point and duplicates");
  const Quality q = Measure(growth->GetOutput());
  PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0, "patch manifold");
  PCS_CHECK(q.Orientation == 1.0, "patch oriented");
  PCS_CHECK(q.Loops == 1, "patch: " << q.Loops << " boundary loops, expected 1");
  PCS_CHECK(q.Components == 1 && q.Euler == 1,
    "patch is one disk: components " << q.Components << ", Euler characteristic " << q.Euler);
  PCS_CHECK(growth->GetNumberOfSkippedPoints() == 1, "NaN point skipped");
  PCS_CHECK(growth->GetNumberOfDuplicatePoints() == 5, "5 duplicates");
  PCS_CHECK(growth->GetNumberOfUnusedPoints() == 0, "unused " << growth->GetNumberOfUnusedPoints());
  PCS_CHECK(q.UsedPoints == 2000, "used " << q.UsedPoints);
  vtkDataArray* representative = growth->GetOutput()->GetPointData()->GetArray("RepresentativeId");
  PCS_CHECK(representative->GetTuple1(2005) == -1, "NaN point has RepresentativeId -1");
  PCS_CHECK(growth->GetNumberOfBoundaryEdges() == q.BoundaryEdges, "boundary edges reported");
  return true;
}

// An open tube of unit radius: `rows` rings of n points, every other ring turned by half a step,
// the rings sqrt(3)/2 chords apart (every point's nearest neighbours one chord away).
std::vector<double> Tube(int n, int rows)
{
  const double chord = 2.0 * std::sin(vtkMath::Pi() / n);
  std::vector<double> xyz;
  for (int i = 0; i < rows; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      const double a = 2.0 * vtkMath::Pi() * (j + 0.5 * (i % 2)) / n;
      xyz.insert(xyz.end(), { std::cos(a), std::sin(a), i * chord * std::sqrt(3.0) / 2.0 });
    }
  }
  return xyz;
}

bool TestNarrowLoops()
{
  // The end rings (loops longer than MaximumHoleEdges) are closed only when narrow: every fill
  // point within 2 local spacings (here the chord) of a point. Every point of a flat disc lies
  // within its radius of the nearest rim vertex: the radius of a 10-point ring is 1.62 chords,
  // so its end is capped. In a 30-point ring (radius 4.79 chords) any triangulation has a
  // triangle containing the centre, whose centroid lies within a third of the radius from the
  // centre and so at least 3.19 chords from every point: both ends stay open.
  for (int n : { 10, 30 })
  {
    for (int holes : { 8, 0 })
    {
      const std::vector<double> xyz = Tube(n, 12);
      vtkNew<vtkLocalOptimumGrowth> growth;
      growth->SetMaximumHoleEdges(holes);
      growth->SetInputData(pcstest::MakeCloud(xyz));
      growth->Update();
      const Quality q = Measure(growth->GetOutput());
      const std::string what =
        "tube of " + std::to_string(n) + "-point rings, MaximumHoleEdges " + std::to_string(holes);
      PCS_CHECK(growth->GetNumberOfUnusedPoints() == 0,
        what << ": unused " << growth->GetNumberOfUnusedPoints());
      if (n == 10 && holes > 0)
      {
        if (!CheckClosed(q, 0, what))
        {
          return false;
        }
        PCS_CHECK(q.Triangles == 2 * 12 * n - 4, what << ": " << q.Triangles << " triangles");
        PCS_CHECK(growth->GetNumberOfHolesClosed() == 2,
          what << ": " << growth->GetNumberOfHolesClosed() << " holes closed");
      }
      else
      {
        PCS_CHECK(q.Loops == 2 && q.BoundaryEdges == 2 * n,
          what << ": " << q.Loops << " loops, " << q.BoundaryEdges << " boundary edges");
        PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0 && q.Orientation == 1.0,
          what << ": not a manifold oriented mesh");
        PCS_CHECK(q.Components == 1 && q.Euler == 0,
          what << ": components " << q.Components << ", Euler characteristic " << q.Euler);
      }
    }
  }
  return true;
}

bool TestPlanarGrid()
{
  // 20 x 20 unit grid: every quad has 4 cocircular corners, the border is collinear.
  std::vector<double> xyz;
  for (int i = 0; i < 20; ++i)
  {
    for (int j = 0; j < 20; ++j)
    {
      xyz.insert(xyz.end(), { static_cast<double>(i), static_cast<double>(j), 0.0 });
    }
  }
  vtkNew<vtkLocalOptimumGrowth> growth;
  growth->SetInputData(pcstest::MakeCloud(xyz));
  growth->Update();
  const Quality q = Measure(growth->GetOutput());
  PCS_CHECK(q.Triangles == 2 * 19 * 19, "grid: " << q.Triangles << " triangles, expected 722");
  PCS_CHECK(q.Loops == 1 && q.BoundaryEdges == 4 * 19,
    "grid: one loop of 76 edges, got " << q.Loops << " loops, " << q.BoundaryEdges << " edges");
  PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0 && q.Orientation == 1.0,
    "grid manifold and oriented");
  PCS_CHECK(q.Degenerate == 0, "no degenerate triangle");
  return true;
}

// Small flat patches (random points on the unit square, z = 0): the border loop is not a hole.
// A fill of it lay in the patch's plane, folded back onto the patch, and closed the patch into
// a component enclosing no volume (two layers back to back). An open patch keeps at least one
// boundary loop, and no edge has its two triangles on the same side of it.
bool TestSmallFlatPatches()
{
  for (int n : { 30, 60, 100, 200 })
  {
    for (unsigned seed = 1; seed <= 5; ++seed)
    {
      std::mt19937_64 rng(seed);
      std::uniform_real_distribution<double> unit(0.0, 1.0);
      std::vector<double> xyz;
      for (int i = 0; i < n; ++i)
      {
        const double x = unit(rng);
        xyz.insert(xyz.end(), { x, unit(rng), 0.0 });
      }
      vtkNew<vtkLocalOptimumGrowth> growth;
      growth->SetInputData(pcstest::MakeCloud(xyz));
      growth->Update();
      vtkPolyData* mesh = growth->GetOutput();
      const Quality q = Measure(mesh);
      const std::string what = "flat patch n " + std::to_string(n) + " seed " + std::to_string(seed);
      PCS_CHECK(q.Triangles > 0 && q.BoundaryEdges > 0 && q.Loops >= 1,
        what << ": open, got " << q.BoundaryEdges << " boundary edges, " << q.Loops << " loops");
      // Both triangles of an edge on the same side of it (z = 0: the sign of a 2D cross product).
      std::map<std::pair<vtkIdType, vtkIdType>, std::vector<vtkIdType>> across;
      vtkNew<vtkIdList> cell;
      for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
      {
        mesh->GetCellPoints(c, cell);
        for (int k = 0; k < 3; ++k)
        {
          const vtkIdType a = cell->GetId(k), b = cell->GetId((k + 1) % 3);
          across[std::minmax(a, b)].push_back(cell->GetId((k + 2) % 3));
        }
      }
      int sameSide = 0;
      for (const auto& entry : across)
      {
        if (entry.second.size() != 2)
        {
          continue;
        }
        double a[3], b[3], c[3], d[3];
        mesh->GetPoint(entry.first.first, a);
        mesh->GetPoint(entry.first.second, b);
        mesh->GetPoint(entry.second[0], c);
        mesh->GetPoint(entry.second[1], d);
        const double sc = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        const double sd = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
        sameSide += sc * sd > 0.0 ? 1 : 0;
      }
      PCS_CHECK(sameSide == 0, what << ": " << sameSide << " edges with both triangles on one side");
    }
  }
  return true;
}

// Small open patches (issue 5): random points on a bowl and on a tilted disc (20 to 200 points,
// seeds 1-5) are one open surface: one component with exactly one boundary loop (so no closed
// component). The border of such a patch used to be "closed" by a fill as large as the patch: a
// lid over the bowl, a second layer back to back with the disc (on 9819af6 the bowl and the
// tilted disc of 20 points, seed 1, came back closed; the exactly coplanar square of
// TestSmallFlatPatches was caught by the fold rule, the tilted disc was not).
bool TestSmallOpenPatches()
{
  for (bool bowl : { true, false })
  {
    for (int n : { 20, 30, 60, 100, 200 })
    {
      for (unsigned seed = 1; seed <= 5; ++seed)
      {
        std::vector<double> xyz, normals;
        pcstest::SmallOpenPatch(bowl, n, seed, xyz, normals);
        vtkNew<vtkLocalOptimumGrowth> growth;
        growth->SetInputData(pcstest::MakeCloud(xyz));
        growth->Update();
        const Quality q = Measure(growth->GetOutput());
        PCS_CHECK(q.Components == 1 && q.Loops == 1,
          (bowl ? "bowl" : "tilted disc")
            << " n " << n << " seed " << seed << ": " << q.Components << " components, " << q.Loops
            << " boundary loops (one open patch expected)");
      }
    }
  }
  return true;
}

bool TestGridBox()
{
  // The surface of a box sampled on an integer grid: 12 x 9 x 7 points, 406 on the surface, 96
  // exactly on its edges (corners included). In the frame of a face triangle the points of the
  // face beyond an edge project exactly onto that edge's points, and blocked every triangle with
  // a vertex on the edge (35 points were left unused, 10 components). Constraint 1 (60 degrees)
  // keeps the faces, which meet at 90 degrees, apart: every point is used and the growth makes
  // the six faces as six disks (Euler characteristic 6), every triangle in a face (its three
  // vertices share the coordinate of that face). The holes are not closed (MaximumHoleEdges 0):
  // the narrow-loop fill caps such a flat face's loop with a second layer of triangles on the
  // face, back to back with the first (a closed flat component).
  const int size[3] = { 12, 9, 7 };
  std::vector<double> xyz;
  for (int i = 0; i < size[0]; ++i)
  {
    for (int j = 0; j < size[1]; ++j)
    {
      for (int k = 0; k < size[2]; ++k)
      {
        if (i == 0 || j == 0 || k == 0 || i == size[0] - 1 || j == size[1] - 1 || k == size[2] - 1)
        {
          xyz.insert(xyz.end(), { double(i), double(j), double(k) });
        }
      }
    }
  }
  const double points = static_cast<double>(xyz.size() / 3);
  PCS_CHECK(points == 406, "grid box: 406 points, got " << points);
  vtkNew<vtkLocalOptimumGrowth> growth;
  growth->SetInputData(pcstest::MakeCloud(xyz));
  growth->SetMaximumHoleEdges(0);
  growth->Update();
  vtkPolyData* mesh = growth->GetOutput();
  const Quality q = Measure(mesh);
  PCS_CHECK(q.UsedPoints == points,
    "grid box: every point used, " << points - q.UsedPoints << " left unused");
  PCS_CHECK(q.Components == 6 && q.Loops == 6 && q.Euler == 6,
    "grid box: six disks, got " << q.Components << " components, " << q.Loops
                                << " loops, Euler characteristic " << q.Euler);
  PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0 && q.Orientation == 1.0,
    "grid box manifold and oriented");
  PCS_CHECK(q.Degenerate == 0, "grid box: no degenerate triangle");
  vtkNew<vtkIdList> cell;
  vtkIdType offFace = 0;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, cell);
    bool inFace = false;
    for (int axis = 0; axis < 3 && !inFace; ++axis)
    {
      for (const double side : { 0.0, size[axis] - 1.0 })
      {
        bool all = true;
        for (vtkIdType v = 0; v < cell->GetNumberOfIds(); ++v)
        {
          all = all && mesh->GetPoint(cell->GetId(v))[axis] == side;
        }
        inFace = inFace || all;
      }
    }
    offFace += inFace ? 0 : 1;
  }
  PCS_CHECK(offFace == 0, "grid box: " << offFace << " triangles across an edge");
  return true;
}

bool TestLatticeLines()
{
  // A tilted plane scanned in 20 lines of 150 points on an integer lattice (2 apart along a
  // line, 7 across): many exactly collinear triples. A free point lying on a triangle's edge was
  // inserted by splitting the triangle in three, one of them of zero area (17 such triangles, 127
  // points unused before).
  std::vector<double> xyz;
  for (int line = 0; line < 20; ++line)
  {
    for (int k = 0; k < 150; ++k)
    {
      const double x = 2.0 * k, y = 7.0 * line;
      xyz.insert(xyz.end(), { x, y, x + y });
    }
  }
  vtkNew<vtkLocalOptimumGrowth> growth;
  growth->SetInputData(pcstest::MakeCloud(xyz));
  growth->Update();
  const Quality q = Measure(growth->GetOutput());
  PCS_CHECK(q.Degenerate == 0 && q.Duplicates == 0,
    "lattice lines: " << q.Degenerate << " zero-area, " << q.Duplicates << " duplicate triangles");
  PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0 && q.Orientation == 1.0,
    "lattice lines: manifold and oriented");
  PCS_CHECK(q.UsedPoints == 3000 && growth->GetNumberOfUnusedPoints() == 0,
    "lattice lines: " << q.UsedPoints << " of 3000 points used");
  return true;
}

// Lines of one point id range each (line l: ids l * perLine .. (l + 1) * perLine - 1): the
// triangles on one line and those across more than two lines.
void CountLineSpans(vtkPolyData* mesh, int perLine, int& onOneLine, int& skipping)
{
  onOneLine = skipping = 0;
  for (const auto& t : pcstest::CellTuples<3>(mesh))
  {
    const vtkIdType lowest = std::min({ t[0], t[1], t[2] }) / perLine;
    const vtkIdType highest = std::max({ t[0], t[1], t[2] }) / perLine;
    onOneLine += highest == lowest ? 1 : 0;
    skipping += highest - lowest > 1 ? 1 : 0;
  }
}

// The plane z = x scanned in 40 lines y = 0 .. 39 of 1000 points 0.08 apart in x (0.113 along
// the line, 8.8 times closer than across): the off-line neighbours and the sampling's metric make
// it the strip triangulation of its lines, known by construction: 2 (N - 1) (L - 1) = 77,922
// triangles, each between two adjacent lines, one disk (one boundary loop of 2 (N - 1) + 2 (L - 1)
// = 2,076 edges, Euler characteristic 1) over every point, from one seed. (Before the off-line
// neighbours the front stalled tens of thousands of times: 7,493 seeds at c90bb02.)
bool TestStallingScanLines()
{
  const int lines = 40, perLine = 1000;
  std::vector<double> xyz;
  for (int line = 0; line < lines; ++line)
  {
    for (int k = 0; k < perLine; ++k)
    {
      const double x = 0.08 * k;
      xyz.insert(xyz.end(), { x, static_cast<double>(line), x });
    }
  }
  vtkNew<vtkLocalOptimumGrowth> growth;
  growth->SetInputData(pcstest::MakeCloud(xyz));
  growth->Update();
  const Quality q = Measure(growth->GetOutput());
  PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0 && q.Orientation == 1.0,
    "stalling scan lines: manifold and oriented");
  PCS_CHECK(q.Degenerate == 0 && q.Duplicates == 0,
    "stalling scan lines: " << q.Degenerate << " zero-area, " << q.Duplicates << " duplicates");
  PCS_CHECK(q.UsedPoints == lines * perLine && growth->GetNumberOfUnusedPoints() == 0,
    "stalling scan lines: " << q.UsedPoints << " used, " << growth->GetNumberOfUnusedPoints()
                            << " reported unused");
  PCS_CHECK(q.Triangles == 2 * (perLine - 1) * (lines - 1),
    "stalling scan lines: " << q.Triangles << " triangles, expected "
                            << 2 * (perLine - 1) * (lines - 1));
  PCS_CHECK(q.Components == 1 && q.Loops == 1 && q.Euler == 1 &&
      q.BoundaryEdges == 2 * (perLine - 1) + 2 * (lines - 1),
    "stalling scan lines: " << q.Components << " components, " << q.Loops << " loops of "
                            << q.BoundaryEdges << " edges, Euler characteristic " << q.Euler
                            << ", expected one disk");
  int onOneLine = 0, skipping = 0;
  CountLineSpans(growth->GetOutput(), perLine, onOneLine, skipping);
  PCS_CHECK(onOneLine == 0 && skipping == 0,
    "stalling scan lines: " << onOneLine << " triangles on one line, " << skipping
                            << " across more than two lines");
  PCS_CHECK(growth->GetNumberOfSeeds() == 1,
    "stalling scan lines: " << growth->GetNumberOfSeeds() << " seeds, expected 1");
  return true;
}

// The unit sphere sampled on latitude rings `ratio` times farther apart than the points along a
// ring (a scan in lines), about n points, each ring turned by a random phase, every point moved by
// Gaussian noise of `jitter` in-ring spacings.
std::vector<double> RingSphere(int n, double ratio, double jitter, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * vtkMath::Pi());
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double across = std::sqrt(4.0 * vtkMath::Pi() * ratio / n), along = across / ratio;
  std::vector<double> xyz;
  for (double latitude = -vtkMath::Pi() / 2 + across / 2; latitude < vtkMath::Pi() / 2;
       latitude += across)
  {
    const double r = std::cos(latitude);
    const int count = std::max(3, static_cast<int>(std::lround(2.0 * vtkMath::Pi() * r / along)));
    const double start = phase(rng);
    for (int k = 0; k < count; ++k)
    {
      const double a = start + 2.0 * vtkMath::Pi() * k / count;
      const double p[3] = { r * std::cos(a), r * std::sin(a), std::sin(latitude) };
      for (double c : p)
      {
        xyz.push_back(c + (jitter > 0.0 ? jitter * along * gauss(rng) : 0.0));
      }
    }
  }
  return xyz;
}

bool TestRingSpheres()
{
  // Rings 3.5 and 4 times farther apart than their points: every triangle between two rings has
  // an edge along a ring 3.5 to 4 times shorter than its others, beyond constraint 2's [1/3, 3].
  // The growth broke into thousands of pieces there (a seed skipping a ring's point left it to a
  // sliver along the ring, standing across the sphere, whose edges no front could expand): 4,000
  // points at ratio 4 gave hundreds of components. Clean rings: closed, genus 0, every point used;
  // with noise of a tenth of the spacing: one component, boundary edges under 0.5 % of the edges
  // (issue 5's bound for closed surfaces).
  for (double ratio : { 3.5, 4.0 })
  {
    for (double jitter : { 0.0, 0.1 })
    {
      const std::vector<double> xyz = RingSphere(4000, ratio, jitter, 7);
      vtkNew<vtkLocalOptimumGrowth> growth;
      growth->SetInputData(pcstest::MakeCloud(xyz));
      growth->Update();
      const Quality q = Measure(growth->GetOutput());
      const std::string what =
        "ring sphere, ratio " + std::to_string(ratio) + ", jitter " + std::to_string(jitter);
      PCS_CHECK(q.Components == 1, what << ": " << q.Components << " components");
      PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0 && q.Orientation == 1.0,
        what << ": not a manifold oriented mesh");
      PCS_CHECK(q.BoundaryEdges <= 0.005 * 1.5 * q.Triangles,
        what << ": " << q.BoundaryEdges << " boundary edges of " << 1.5 * q.Triangles);
      if (jitter == 0.0)
      {
        const int n = static_cast<int>(xyz.size() / 3);
        if (!CheckClosed(q, 0, what))
        {
          return false;
        }
        PCS_CHECK(q.UsedPoints == n && q.Triangles == 2 * n - 4,
          what << ": " << q.UsedPoints << " of " << n << " points used, " << q.Triangles
               << " triangles");
      }
    }
  }
  return true;
}

bool TestTwoSpheres()
{
  const double c1[3] = { 0, 0, 0 }, c2[3] = { 3, 0.5, 0 };
  std::vector<double> xyz = RandomSphere(1500, 3, c1, 1.0);
  const std::vector<double> other = RandomSphere(1000, 4, c2, 0.8);
  xyz.insert(xyz.end(), other.begin(), other.end());
  vtkNew<vtkLocalOptimumGrowth> growth;
  growth->SetInputData(pcstest::MakeCloud(xyz));
  growth->Update();
  const Quality q = Measure(growth->GetOutput());
  PCS_CHECK(CheckClosed(q, 0, "two spheres"), "");
  PCS_CHECK(q.Components == 2, "two components, got " << q.Components);
  PCS_CHECK(growth->GetNumberOfSeeds() == 2, "two seeds, got " << growth->GetNumberOfSeeds());
  PCS_CHECK(q.Triangles == 2 * 2500 - 8, "2V - 4 per sphere: " << q.Triangles);
  PCS_CHECK(growth->GetNumberOfUnusedPoints() == 0, "every point used");
  return true;
}

// Random samples whose growth, before the level-2 ear rule and the handle rule of relaxed
// bridges (see the class documentation), left a sliver hole of 9 to 19 edges (spheres of 3000
// points, seeds 4, 16 and 84; 5000 points, seed 65; tori of 2000 points, seeds 1, 4 and 12) or a
// handle (sphere of 12000 points, seed 84: closed with genus 1; torus of 5000 points, seed 19:
// genus 3), or, before orphans beside a boundary edge were attached to it, one unused point
// (spheres of 2000 points, seed 42, and 3000 points, seed 28; torus of 5000 points, seed 9).
// Each must be closed, manifold, oriented, of the right genus, with every point used.
bool TestRandomSamples()
{
  const double center[3] = { 0, 0, 0 };
  const std::pair<int, unsigned> spheres[] = { { 2000, 42 }, { 3000, 4 }, { 3000, 16 },
    { 3000, 28 }, { 3000, 84 }, { 5000, 65 }, { 12000, 84 } };
  for (const auto& sample : spheres)
  {
    vtkNew<vtkLocalOptimumGrowth> growth;
    growth->SetInputData(
      pcstest::MakeCloud(RandomSphere(sample.first, sample.second, center, 1.0)));
    growth->Update();
    const std::string what =
      "sphere " + std::to_string(sample.first) + "/" + std::to_string(sample.second);
    const Quality q = Measure(growth->GetOutput());
    PCS_CHECK(CheckClosed(q, 0, what), "");
    PCS_CHECK(q.Triangles == 2 * sample.first - 4, what << ": " << q.Triangles << " triangles");
    PCS_CHECK(growth->GetNumberOfUnusedPoints() == 0 && q.UsedPoints == sample.first,
      what << ": every point used");
    PCS_CHECK(CountFolds(growth->GetOutput()) == 0, what << ": folded edges");
  }
  const std::pair<int, unsigned> tori[] = { { 2000, 1 }, { 2000, 4 }, { 2000, 12 }, { 5000, 9 },
    { 5000, 19 } };
  for (const auto& sample : tori)
  {
    // Uniform by area on the torus of radii 1 and 0.35 (rejection on the tube angle).
    std::mt19937_64 rng(sample.second);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> xyz;
    while (xyz.size() < 3 * static_cast<size_t>(sample.first))
    {
      const double a = 2.0 * vtkMath::Pi() * u(rng), b = 2.0 * vtkMath::Pi() * u(rng);
      if (u(rng) * 1.35 <= 1.0 + 0.35 * std::cos(b))
      {
        const double r = 1.0 + 0.35 * std::cos(b);
        xyz.insert(xyz.end(), { r * std::cos(a), r * std::sin(a), 0.35 * std::sin(b) });
      }
    }
    vtkNew<vtkLocalOptimumGrowth> growth;
    growth->SetInputData(pcstest::MakeCloud(xyz));
    growth->Update();
    const std::string what =
      "torus " + std::to_string(sample.first) + "/" + std::to_string(sample.second);
    const Quality q = Measure(growth->GetOutput());
    PCS_CHECK(CheckClosed(q, 1, what), "");
    PCS_CHECK(q.Triangles == 2 * sample.first, what << ": " << q.Triangles << " triangles");
    PCS_CHECK(growth->GetNumberOfUnusedPoints() == 0 && q.UsedPoints == sample.first,
      what << ": every point used");
    // Not checked here: 2000/4 and 2000/12 keep a folded triangle (see the class @warning).
  }
  return true;
}

// Open hemispheres of random points (uniform by area, h = sqrt(area / N)): the front reaches the
// rim, where nothing lies beyond it. One disk, every point used, manifold, and no edge longer than
// 6 h (4.6-4.8 h now). Before the new edge of an ear exceeding constraint 3 was bounded by 3 local
// spacings, such ears cut ever longer chords across the rim at the last relaxation level (a
// partial lid over the opening): 16.0 h on the first seed.
bool TestOpenHemispheres()
{
  const double center[3] = { 0, 0, 0 };
  const int n = 3000;
  const double h = std::sqrt(2.0 * vtkMath::Pi() / n);
  for (unsigned seed = 1; seed <= 3; ++seed)
  {
    std::vector<double> xyz = RandomSphere(n, seed, center, 1.0);
    for (size_t i = 2; i < xyz.size(); i += 3)
    {
      xyz[i] = std::fabs(xyz[i]);
    }
    vtkNew<vtkLocalOptimumGrowth> growth;
    growth->SetInputData(pcstest::MakeCloud(xyz));
    growth->Update();
    const std::string what = "hemisphere " + std::to_string(n) + "/" + std::to_string(seed);
    vtkPolyData* mesh = growth->GetOutput();
    const Quality q = Measure(mesh);
    PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0, what << ": manifold");
    PCS_CHECK(q.Loops == 1 && q.Components == 1 && q.Euler == 1,
      what << ": one disk, loops " << q.Loops << ", Euler characteristic " << q.Euler);
    PCS_CHECK(
      growth->GetNumberOfUnusedPoints() == 0 && q.UsedPoints == n, what << ": every point used");
    double longest = 0.0;
    for (const auto& t : pcstest::CellTuples<3>(mesh))
    {
      for (int j = 0; j < 3; ++j)
      {
        double a[3], b[3];
        mesh->GetPoint(t[j], a);
        mesh->GetPoint(t[(j + 1) % 3], b);
        longest = std::max(longest, std::sqrt(vtkMath::Distance2BetweenPoints(a, b)));
      }
    }
    PCS_CHECK(longest <= 6.0 * h, what << ": longest edge " << longest / h << " h");
  }
  return true;
}

// Noisy random spheres (Gaussian noise of 0.1 sqrt(area / N) per coordinate, about a fifth of
// the mean spacing): the noise leaves folds (small standing triangles), which step 7 flips, to
// the longer diagonal too when it joins two K nearest neighbours. Over five seeds of 5000 points
// at most 1.4 % of the edges fold over (normals more than 90 degrees apart, slivers included):
// 1.82 % when only flips to the shorter diagonal were allowed, 1.14 % now (CGAL's advancing
// front: 0.44 % at 20,000 points). Still closed and manifold.
bool TestNoisySpheres()
{
  const double center[3] = { 0, 0, 0 };
  const int n = 5000;
  const double sigma = 0.1 * std::sqrt(4.0 * vtkMath::Pi() / n);
  double folds = 0.0, edges = 0.0;
  for (unsigned seed = 1; seed <= 5; ++seed)
  {
    std::vector<double> xyz = RandomSphere(n, seed, center, 1.0);
    std::mt19937_64 rng(100 + seed);
    std::normal_distribution<double> noise(0.0, sigma);
    for (double& x : xyz)
    {
      x += noise(rng);
    }
    vtkNew<vtkLocalOptimumGrowth> growth;
    growth->SetInputData(pcstest::MakeCloud(xyz));
    growth->Update();
    const Quality q = Measure(growth->GetOutput());
    const std::string what = "noisy sphere " + std::to_string(seed);
    PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0 && q.Orientation == 1.0,
      what << ": not a manifold oriented mesh");
    PCS_CHECK(q.BoundaryEdges == 0, what << ": " << q.BoundaryEdges << " boundary edges");
    folds += CountFolds(growth->GetOutput(), 0.0);
    edges += 1.5 * q.Triangles;
  }
  PCS_CHECK(folds <= 0.014 * edges,
    "noisy spheres: " << folds << " folded edges of " << edges << " (more than 1.4 %)");
  return true;
}

bool TestDegenerate()
{
  const std::vector<std::vector<double>> inputs = {
    {},                                              // no point
    { 0, 0, 0, 1, 0, 0 },                            // 2 points
    { 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 5, 5, 5 }, // collinear
    { 0, 0, 0, 0, 0, 0, 0, 0, 0 },                   // one point three times
  };
  for (size_t k = 0; k < inputs.size(); ++k)
  {
    vtkNew<vtkLocalOptimumGrowth> growth;
    growth->SetInputData(pcstest::MakeCloud(inputs[k]));
    PCS_CHECK(UpdateCountingWarnings(growth) >= 1, "degenerate input " << k << ": a warning");
    vtkPolyData* out = growth->GetOutput();
    PCS_CHECK(out->GetNumberOfPolys() == 0, "degenerate input " << k << ": no triangle");
    PCS_CHECK(out->GetNumberOfPoints() == static_cast<vtkIdType>(inputs[k].size() / 3),
      "degenerate input " << k << ": every point passed through");
    PCS_CHECK(pcstest::FieldCount(out, "NumberOfTriangles") == 0, "field data on " << k);
  }
  return true;
}
} // namespace

int TestLocalOptimumGrowth(int, char*[])
{
  bool ok = true;
  ok = TestPaperBall() && ok;
  ok = TestSphere() && ok;
  ok = TestTorus() && ok;
  ok = TestOpenPatch() && ok;
  ok = TestNarrowLoops() && ok;
  ok = TestPlanarGrid() && ok;
  ok = TestSmallFlatPatches() && ok;
  ok = TestSmallOpenPatches() && ok;
  ok = TestGridBox() && ok;
  ok = TestLatticeLines() && ok;
  ok = TestStallingScanLines() && ok;
  ok = TestRingSpheres() && ok;
  ok = TestTwoSpheres() && ok;
  ok = TestRandomSamples() && ok;
  ok = TestOpenHemispheres() && ok;
  ok = TestNoisySpheres() && ok;
  ok = TestDegenerate() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
