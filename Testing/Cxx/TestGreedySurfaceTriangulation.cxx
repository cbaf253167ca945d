// vtkGreedySurfaceTriangulation on clouds whose surface is known by construction; the meshes are
// measured with vtkReconstructionQuality and against the analytic surfaces:
// - 5000 random points on the unit sphere: closed, manifold, oriented outwards, genus 0, every
//   point used (coverage 1), hence 2V - 4 triangles;
// - 5000 random points on a torus: the same with genus 1 (2V triangles);
// - tori sampled on regular (u, v) grids, anisotropic and full of exact ties (issue 7): closed,
//   manifold, genus 1, every point used, 2 nu nv triangles;
// - a torus whose tube is cut across by an empty band 6 spacings wide (issue 7): the two rims run
//   alongside each other around the tube and the band is closed as a strip: closed, genus 1, no
//   end capped, every triangle vertex and centroid within 3 mean spacings of the torus (capped
//   like two tube ends, the caps crossed the tube 17 to 18 spacings from its surface, genus 0);
// - a damaged sphere (issue 7): two caps of 20 degrees removed, two other caps thinned tenfold:
//   closed, manifold, genus 0, every point used, every triangle vertex and centroid within 3 mean
//   spacings of the unit sphere; with BridgeIslands and FillHoles off (the step 2 result) the
//   well-sampled regions alone: open, with more boundary loops and the lost points unused;
// - two islands of a plane separated by an empty strip 6 spacings wide: bridged into one surface
//   (one connected component, one boundary loop); with BridgeIslands off two components;
// - a capsule cut in two by an empty slab wider than MaximumBridgeLength: two closed pieces (the
//   cut ends capped, the caps within the tube and on their side of the cut); with CapOpenEnds off
//   two open ends; an open disc and a hemisphere bowl keep their one boundary loop;
// - a washer sampled like a CAD part's mesh vertices (issue 7): a dense inner tube, an outer band
//   sampled in sparse rings, the two flat faces sampled only at their rims (gaps far wider than
//   MaximumBridgeLength): no fill across the through-hole or over the faces (a cap of the outer
//   rim would lie on the inner rim, the caps of the two rims of a face overlap): two open
//   components (four rims), every triangle on one of the two cylinders;
// - the point data Status, LocalUniformity and the cell data Stage agree with each other and with
//   the field data counts (the paper's Table 1 columns are recomputed from them);
// - degenerate inputs (no point, 2 points, collinear points, a NaN point): a warning and a valid
//   output without triangles.
#include "vtkGreedySurfaceTriangulation.h"
#include "vtkReconstructionQuality.h"

#include "pcsTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <random>
#include <string>

namespace
{
struct Quality
{
  double Triangles, UsedPoints, Coverage, BoundaryEdges, Loops, NonManifoldEdges,
    NonManifoldVertices, Genus, Orientation, Components, Degenerate, Duplicates;
};

Quality Measure(vtkPolyData* mesh)
{
  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputData(mesh);
  quality->Update();
  vtkFieldData* fd = quality->GetOutput()->GetFieldData();
  auto get = [fd](const char* name)
  {
    vtkDataArray* array = fd->GetArray(name);
    return array ? array->GetTuple1(0) : std::numeric_limits<double>::quiet_NaN();
  };
  return { get("NumberOfTriangles"),
           get("NumberOfUsedPoints"),
           get("Coverage"),
           get("NumberOfBoundaryEdges"),
           get("NumberOfBoundaryLoops"),
           get("NumberOfNonManifoldEdges"),
           get("NumberOfNonManifoldVertices"),
           get("Genus"),
           get("OrientationConsistency"),
           get("NumberOfConnectedComponents"),
           get("NumberOfDegenerateTriangles"),
           get("NumberOfDuplicateTriangles") };
}

double FieldValue(vtkDataObject* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? array->GetTuple1(0) : std::numeric_limits<double>::quiet_NaN();
}

int UpdateCountingWarnings(vtkGreedySurfaceTriangulation* filter)
{
  int warnings = 0;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback([](vtkObject*, unsigned long, void* data, void*)
                        { ++*static_cast<int*>(data); });
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

bool CheckClosed(const Quality& q, double genus, const std::string& what)
{
  PCS_CHECK(q.BoundaryEdges == 0, what << ": " << q.BoundaryEdges << " boundary edges");
  PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0,
            what << ": non-manifold " << q.NonManifoldEdges << " edges, " << q.NonManifoldVertices
                 << " vertices");
  PCS_CHECK(q.Orientation == 1.0, what << ": orientation consistency " << q.Orientation);
  PCS_CHECK(q.Genus == genus, what << ": genus " << q.Genus << ", expected " << genus);
  PCS_CHECK(q.Components == 1, what << ": " << q.Components << " connected components");
  PCS_CHECK(q.Degenerate == 0 && q.Duplicates == 0,
            what << ": " << q.Degenerate << " degenerate, " << q.Duplicates
                 << " duplicate triangles");
  return true;
}

std::vector<double> RandomSphere(int n, unsigned seed)
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
      xyz.insert(xyz.end(), { p[0] / length, p[1] / length, p[2] / length });
    }
  }
  return xyz;
}

// A random sphere with two caps removed and two caps thinned tenfold (caps of half-angle
// capDegrees around four fixed directions).
std::vector<double> DamagedSphere(int n, unsigned seed, double capDegrees)
{
  const std::vector<double> sphere = RandomSphere(n, seed);
  double directions[4][3] = { { 1, 0, 0 }, { -0.6, 0.8, 0 }, { 0, -0.6, 0.8 }, { 0, 0, -1 } };
  const double cosCap = std::cos(vtkMath::RadiansFromDegrees(capDegrees));
  std::mt19937_64 rng(seed + 1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xyz;
  for (size_t i = 0; i < sphere.size(); i += 3)
  {
    bool keep = true;
    const double draw = u(rng);
    for (int d = 0; d < 4; ++d)
    {
      if (vtkMath::Dot(&sphere[i], directions[d]) > cosCap)
      {
        keep = d >= 2 && draw < 0.1; // removed (d = 0, 1) or one point in ten kept (d = 2, 3)
      }
    }
    if (keep)
    {
      xyz.insert(xyz.end(), &sphere[i], &sphere[i] + 3);
    }
  }
  return xyz;
}

std::vector<double> RandomTorus(int n, unsigned seed, double big, double small)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 2.0 * vtkMath::Pi()), w(0.0, 1.0);
  std::vector<double> xyz;
  while (xyz.size() < 3 * static_cast<size_t>(n))
  {
    // Uniform on the surface: the tube angle accepted in proportion to the local circumference.
    const double a = u(rng), b = u(rng);
    if (w(rng) * (big + small) <= big + small * std::cos(b))
    {
      xyz.insert(xyz.end(),
                 { (big + small * std::cos(b)) * std::cos(a),
                   (big + small * std::cos(b)) * std::sin(a), small * std::sin(b) });
    }
  }
  return xyz;
}

// The point data Status and LocalUniformity and the cell data Stage: present, consistent with
// each other, with the mesh and with the field data.
bool CheckArrays(vtkGreedySurfaceTriangulation* filter, const std::string& what)
{
  vtkPolyData* mesh = filter->GetOutput();
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkDataArray* status = mesh->GetPointData()->GetArray("Status");
  vtkDataArray* used = mesh->GetPointData()->GetArray("Used");
  vtkDataArray* uniformity = mesh->GetPointData()->GetArray("LocalUniformity");
  vtkDataArray* stage = mesh->GetCellData()->GetArray("Stage");
  PCS_CHECK(status && used && uniformity && stage,
            what << ": Status, Used, LocalUniformity, Stage");
  PCS_CHECK(status->GetNumberOfTuples() == n && used->GetNumberOfTuples() == n &&
              uniformity->GetNumberOfTuples() == n &&
              stage->GetNumberOfTuples() == mesh->GetNumberOfCells(),
            what << ": array sizes");

  // Used: exactly the triangle vertices.
  std::vector<int> inTriangle(n, 0);
  const auto triangles = pcstest::CellTuples<3>(mesh);
  for (const auto& t : triangles)
  {
    for (vtkIdType v : t)
    {
      inTriangle[v] = 1;
    }
  }
  // The points added by the hole fairing follow the input points, with Status 5.
  const vtkIdType added = pcstest::FieldCount(mesh, "NumberOfAddedPoints");
  PCS_CHECK(added >= 0 && added == filter->GetNumberOfAddedPoints() && added < n &&
      (added == 0 || (filter->GetFairHoleFills() && filter->GetFillHoles())),
    what << ": NumberOfAddedPoints " << added);
  const vtkIdType inputPoints = n - added;
  const vtkIdType loopsClosed = pcstest::FieldCount(mesh, "NumberOfSmallLoopsClosed");
  PCS_CHECK(loopsClosed >= 0 && (loopsClosed == 0 || filter->GetFillHoles()),
    what << ": NumberOfSmallLoopsClosed " << loopsClosed);
  const vtkIdType endsCapped = pcstest::FieldCount(mesh, "NumberOfEndsCapped");
  PCS_CHECK(endsCapped >= 0 &&
      (endsCapped == 0 || (filter->GetFillHoles() && filter->GetCapOpenEnds())),
    what << ": NumberOfEndsCapped " << endsCapped);
  // The loops closed by the least-dihedral fallback are among the small loops closed and the
  // ends capped.
  const vtkIdType byDihedral = pcstest::FieldCount(mesh, "NumberOfSmallLoopsFilledByDihedral");
  PCS_CHECK(byDihedral >= 0 && byDihedral <= loopsClosed + endsCapped,
    what << ": NumberOfSmallLoopsFilledByDihedral " << byDihedral << " of "
         << loopsClosed + endsCapped);
  vtkIdType count[6] = { 0, 0, 0, 0, 0, 0 }, unused = 0, ssrFinite = 0;
  double ssrUniformity = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const int s = static_cast<int>(status->GetTuple1(i));
    PCS_CHECK(s >= 0 && s <= 5, what << ": Status " << s << " of point " << i);
    PCS_CHECK((s == vtkGreedySurfaceTriangulation::ADDED_BY_HOLE_FILLING) == (i >= inputPoints),
      what << ": Status " << s << " of point " << i << " (" << inputPoints << " input points)");
    ++count[s];
    PCS_CHECK(used->GetTuple1(i) == inTriangle[i], what << ": Used of point " << i);
    unused += inTriangle[i] ? 0 : 1;
    // Correct, boundary and lost-but-used points are triangle vertices; the others are not.
    const bool expectUsed = s == vtkGreedySurfaceTriangulation::CORRECT ||
      s == vtkGreedySurfaceTriangulation::BOUNDARY ||
      s == vtkGreedySurfaceTriangulation::LOST_USED_BY_HOLE_FILLING ||
      s == vtkGreedySurfaceTriangulation::ADDED_BY_HOLE_FILLING;
    PCS_CHECK(inTriangle[i] == (expectUsed ? 1 : 0),
              what << ": point " << i << " of Status " << s
                   << (inTriangle[i] ? " used" : " unused"));
    const double m = uniformity->GetTuple1(i);
    PCS_CHECK(std::isnan(m) || m >= 1.0, what << ": LocalUniformity " << m << " < 1");
    if (s <= vtkGreedySurfaceTriangulation::BOUNDARY && std::isfinite(m))
    {
      ssrUniformity += m;
      ++ssrFinite;
    }
  }
  // Stage: 1 (step 1, kept by step 2), 2 (grown), 6 (hole filling), 7 (swap) or 8 (lost point
  // insertion);
  // every triangle around a correct point comes from step 1 unless lost points were inserted
  // (an insertion splits triangles at correct points; then never a hole filling triangle), and a
  // step 1 triangle has only correct or boundary vertices.
  const vtkIdType inserted = pcstest::FieldCount(mesh, "NumberOfInsertedPoints");
  PCS_CHECK(inserted >= 0 && inserted <= count[3] &&
              (inserted == 0 || filter->GetInsertLostPoints()),
            what << ": NumberOfInsertedPoints " << inserted);
  double ssrArea = 0.0, totalArea = 0.0;
  for (vtkIdType c = 0; c < static_cast<vtkIdType>(triangles.size()); ++c)
  {
    const auto& t = triangles[c];
    const int s = static_cast<int>(stage->GetTuple1(c));
    PCS_CHECK(s == 1 || (s == 2 && filter->GetGrowRegions()) || s == 6 || s == 7 || s == 8,
      what << ": Stage " << s << " of triangle " << c);
    bool correctVertex = false, lostVertex = false;
    for (vtkIdType v : t)
    {
      PCS_CHECK(v < inputPoints || s == 6 || s == 7,
        what << ": triangle " << c << " of stage " << s << " at an added point");
      correctVertex =
        correctVertex || status->GetTuple1(v) == vtkGreedySurfaceTriangulation::CORRECT;
      lostVertex = lostVertex || status->GetTuple1(v) > vtkGreedySurfaceTriangulation::BOUNDARY;
    }
    PCS_CHECK(!correctVertex || s == 1 || (inserted > 0 && s != 6),
              what << ": triangle " << c << " at a correct point, stage " << s);
    PCS_CHECK(!lostVertex || s != 1, what << ": step 1 triangle " << c << " at a lost point");
    double a[3], b[3], d[3], u[3], v[3], cross[3];
    mesh->GetPoint(t[0], a);
    mesh->GetPoint(t[1], b);
    mesh->GetPoint(t[2], d);
    vtkMath::Subtract(b, a, u);
    vtkMath::Subtract(d, a, v);
    vtkMath::Cross(u, v, cross);
    totalArea += 0.5 * vtkMath::Norm(cross);
    ssrArea += s == 1 ? 0.5 * vtkMath::Norm(cross) : 0.0;
  }

  // Field data: counts and the paper's Table 1 columns, recomputed.
  PCS_CHECK(pcstest::FieldCount(mesh, "NumberOfTriangles") == mesh->GetNumberOfCells() &&
              filter->GetNumberOfTriangles() == mesh->GetNumberOfCells(),
            what << ": NumberOfTriangles");
  PCS_CHECK(pcstest::FieldCount(mesh, "NumberOfUnusedPoints") == unused &&
              filter->GetNumberOfUnusedPoints() == unused,
            what << ": NumberOfUnusedPoints " << pcstest::FieldCount(mesh, "NumberOfUnusedPoints")
                 << ", counted " << unused);
  PCS_CHECK(pcstest::FieldCount(mesh, "NumberOfLostPoints") == count[2] + count[3] &&
              filter->GetNumberOfLostPoints() == count[2] + count[3],
            what << ": NumberOfLostPoints " << pcstest::FieldCount(mesh, "NumberOfLostPoints")
                 << ", Status 2 and 3: " << count[2] + count[3]);
  PCS_CHECK(pcstest::FieldCount(mesh, "NumberOfDuplicatePoints") +
                pcstest::FieldCount(mesh, "NumberOfSkippedPoints") ==
              count[4],
            what << ": Status 4 = duplicates + skipped");
  PCS_CHECK(pcstest::FieldCount(mesh, "NumberOfPoints") == inputPoints, what << ": NumberOfPoints");
  const double distinct = static_cast<double>(inputPoints - count[4]);
  PCS_CHECK(std::abs(FieldValue(mesh, "SSRPointsPercent") -
                     100.0 * (count[0] + count[1]) / distinct) < 1e-9,
            what << ": SSRPointsPercent " << FieldValue(mesh, "SSRPointsPercent"));
  PCS_CHECK(std::abs(FieldValue(mesh, "SSRAreaPercent") - 100.0 * ssrArea / totalArea) < 1e-6,
            what << ": SSRAreaPercent " << FieldValue(mesh, "SSRAreaPercent") << ", recomputed "
                 << 100.0 * ssrArea / totalArea);
  PCS_CHECK(std::abs(FieldValue(mesh, "AverageUniformityInSSR") - ssrUniformity / ssrFinite) <
              1e-9 * ssrUniformity / ssrFinite,
            what << ": AverageUniformityInSSR");
  PCS_CHECK(FieldValue(mesh, "MeanSpacing") > 0.0 &&
              FieldValue(mesh, "MeanSpacing") == filter->GetMeanSpacing(),
            what << ": MeanSpacing");
  const double seconds = FieldValue(mesh, "Seconds");
  PCS_CHECK(seconds > 0.0 &&
      std::abs(FieldValue(mesh, "PointsPerSecond") * seconds - inputPoints) < 1e-6 * inputPoints,
    what << ": Seconds and PointsPerSecond");
  vtkStringArray* steps =
    vtkStringArray::SafeDownCast(mesh->GetFieldData()->GetAbstractArray("StepsUsed"));
  PCS_CHECK(steps && steps->GetNumberOfValues() == 1 && steps->GetValue(0).rfind("1, 2", 0) == 0,
            what << ": StepsUsed starts with steps 1 and 2");
  const bool filled = pcstest::FieldCount(mesh, "NumberOfHolesFilled") > 0;
  PCS_CHECK(filled == (steps->GetValue(0).find('6') != std::string::npos),
            what << ": StepsUsed '" << steps->GetValue(0) << "' and holes filled");
  PCS_CHECK((filled || inserted > 0) == (count[3] > 0 || ssrArea < totalArea),
            what << ": hole filling or insertion triangles, and holes filled or points inserted");
  PCS_CHECK((inserted > 0) == (steps->GetValue(0).find('8') != std::string::npos),
            what << ": StepsUsed '" << steps->GetValue(0) << "' and points inserted");
  return true;
}

// Largest distance of the triangle vertices and centroids of `mesh` from a surface (`distance`
// of a point), in units of `spacing`.
double DistanceToSurface(vtkPolyData* mesh,
  double spacing,
  const std::function<double(const double*)>& distance)
{
  double worst = 0.0;
  for (const auto& t : pcstest::CellTuples<3>(mesh))
  {
    double centroid[3] = { 0, 0, 0 };
    for (vtkIdType v : t)
    {
      double p[3];
      mesh->GetPoint(v, p);
      worst = std::max(worst, distance(p));
      for (int i = 0; i < 3; ++i)
      {
        centroid[i] += p[i] / 3.0;
      }
    }
    worst = std::max(worst, distance(centroid));
  }
  return worst / spacing;
}

// Largest distance to the unit sphere of the triangle vertices and centroids, in mean spacings.
double DistanceToUnitSphere(vtkPolyData* mesh, double spacing)
{
  return DistanceToSurface(
    mesh, spacing, [](const double* p) { return std::abs(vtkMath::Norm(p) - 1.0); });
}

// The same from the torus of radii `big` and `small` about the z axis.
double DistanceToTorus(vtkPolyData* mesh, double big, double small, double spacing)
{
  return DistanceToSurface(mesh,
    spacing,
    [&](const double* p)
    { return std::abs(std::hypot(std::hypot(p[0], p[1]) - big, p[2]) - small); });
}

//------------------------------------------------------------------------------------------------
bool TestSphere()
{
  const int n = 5000;
  vtkNew<vtkGreedySurfaceTriangulation> greedy;
  greedy->SetInputData(pcstest::MakeCloud(RandomSphere(n, 11)));
  PCS_CHECK(UpdateCountingWarnings(greedy) == 0, "no warning on a clean sphere");
  vtkPolyData* mesh = greedy->GetOutput();
  const Quality q = Measure(mesh);
  PCS_CHECK(CheckClosed(q, 0, "sphere"), "");
  const vtkIdType added = greedy->GetNumberOfAddedPoints();
  PCS_CHECK(
    q.Coverage == 1.0 && q.UsedPoints == n + added && greedy->GetNumberOfUnusedPoints() == 0,
    "sphere: coverage " << q.Coverage);
  PCS_CHECK(q.Triangles == 2 * (n + added) - 4, "sphere: " << q.Triangles << " triangles, 2V-4");
  PCS_CHECK(SignedVolume(mesh) > 0.0, "sphere: outward orientation");
  PCS_CHECK(CheckArrays(greedy, "sphere"), "");
  return true;
}

// Progress never runs backwards: a sphere with far points, whose outlier rule reads the
// neighbour table and runs the search a second time (both searches had the range 0.02-0.25).
void OnProgressRecordDrop(vtkObject*, unsigned long, void* client, void* call)
{
  auto* last = static_cast<double*>(client);
  const double progress = *static_cast<double*>(call);
  last[1] = std::max(last[1], last[0] - progress);
  last[0] = progress;
}

bool TestMonotoneProgress()
{
  auto xyz = RandomSphere(2000, 13);
  for (int i = 0; i < 5; ++i)
  {
    xyz.insert(xyz.end(), { 20.0 + 3.0 * i, -15.0, 10.0 * i });
  }
  vtkNew<vtkGreedySurfaceTriangulation> greedy;
  greedy->SetInputData(pcstest::MakeCloud(xyz));
  double last[2] = { 0.0, 0.0 }; // last progress, largest drop
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(&OnProgressRecordDrop);
  callback->SetClientData(last);
  greedy->AddObserver(vtkCommand::ProgressEvent, callback);
  UpdateCountingWarnings(greedy);
  const double outliers = FieldValue(greedy->GetOutput(), "NumberOfOutliers");
  PCS_CHECK(outliers == 5, "progress: " << outliers << " outliers, not 5");
  PCS_CHECK(last[1] == 0.0, "progress went back by " << last[1]);
  return true;
}

bool TestTorus()
{
  const int n = 5000;
  vtkNew<vtkGreedySurfaceTriangulation> greedy;
  greedy->SetInputData(pcstest::MakeCloud(RandomTorus(n, 23, 1.0, 0.35)));
  greedy->Update();
  vtkPolyData* mesh = greedy->GetOutput();
  const Quality q = Measure(mesh);
  PCS_CHECK(CheckClosed(q, 1, "torus"), "");
  const vtkIdType added = greedy->GetNumberOfAddedPoints();
  PCS_CHECK(q.Coverage == 1.0 && q.UsedPoints == n + added, "torus: coverage " << q.Coverage);
  PCS_CHECK(q.Triangles == 2 * (n + added), "torus: " << q.Triangles << " triangles, 2V");
  PCS_CHECK(SignedVolume(mesh) > 0.0, "torus: outward orientation");
  PCS_CHECK(CheckArrays(greedy, "torus"), "");
  return true;
}

// A torus sampled on a regular (u, v) parameter grid of nu x nv points (u around the axis, v
// around the tube), turned by a fixed rotation so that no grid line is axis-aligned.
std::vector<double> GridTorus(int nu, int nv, double big, double small)
{
  const double c = std::cos(0.3), s = std::sin(0.3), c2 = std::cos(0.7), s2 = std::sin(0.7);
  std::vector<double> xyz;
  for (int j = 0; j < nv; ++j)
  {
    for (int i = 0; i < nu; ++i)
    {
      const double u = 2.0 * vtkMath::Pi() * i / nu, v = 2.0 * vtkMath::Pi() * j / nv;
      const double p[3] = { (big + small * std::cos(v)) * std::cos(u),
        (big + small * std::cos(v)) * std::sin(u), small * std::sin(v) };
      // About x by 0.3 rad, then about z by 0.7 rad.
      const double q[3] = { p[0], c * p[1] - s * p[2], s * p[1] + c * p[2] };
      xyz.insert(xyz.end(), { c2 * q[0] - s2 * q[1], s2 * q[0] + c2 * q[1], q[2] });
    }
  }
  return xyz;
}

// Issue 7: tori sampled on a regular parameter grid, the most common way to make one. The grid
// is anisotropic (spacing 2 pi (R + r cos v) / nu along u, 2 pi r / nv along v) and full of exact
// ties (every cell an isosceles trapezoid, its two diagonals of equal length). Where the spacing
// along v is under half that along u, three consecutive points of a circle around the tube
// are nearer to each other than to the next circle, and step 1 closed triangles across the tube
// (standing across the surface); around the inner equator of a fat tube the circles around the
// axis did the same across the torus's hole. The result was open (up to 797 boundary edges) or
// closed with the wrong genus (0: the hole filled; 34 of 200 grids). Each grid must give a closed,
// manifold torus over every point, with no point added: genus 1 and 2 nu nv triangles.
bool TestGridTori()
{
  auto check = [](int nu, int nv, double small)
  {
    vtkNew<vtkGreedySurfaceTriangulation> greedy;
    greedy->SetInputData(pcstest::MakeCloud(GridTorus(nu, nv, 1.0, small)));
    greedy->Update();
    const std::string what = "grid torus " + std::to_string(nu) + " x " + std::to_string(nv) +
      ", r " + std::to_string(small);
    const Quality q = Measure(greedy->GetOutput());
    PCS_CHECK(CheckClosed(q, 1, what), "");
    PCS_CHECK(q.UsedPoints == nu * nv && q.Coverage == 1.0,
      what << ": " << q.UsedPoints << " points used of " << nu * nv);
    PCS_CHECK(q.Triangles == 2 * nu * nv, what << ": " << q.Triangles << " triangles");
    return true;
  };
  const int grids[][2] = { { 24, 24 }, { 32, 32 }, { 40, 40 }, { 56, 56 }, { 48, 36 }, { 36, 48 },
    { 24, 16 } };
  bool ok = true;
  for (const auto& grid : grids)
  {
    for (double small : { 0.2, 0.35, 0.5, 0.65 })
    {
      ok = check(grid[0], grid[1], small) && ok;
    }
  }
  return ok;
}

// Issue 7: a band of missing surface around a thin part (on random samples of CGAL's camel, a band
// of lost points around a leg) has two rims that each go once around the part: step 3 calls them
// islands, one connected piece holds both, so no bridge may join them, and each was capped like
// the cut end of a tube, the caps crossing the tube. The tube of a torus (radius 0.4, about 18
// spacings) cut across by an empty band 6 spacings wide at x = 0: the rims are closed as a strip.
bool TestTorusBand()
{
  const int n = 8000;
  const double big = 1.0, small = 0.4;
  // The mean spacing of n random points: about half the square root of the area per point.
  const double spacing = 0.5 * std::sqrt(4.0 * vtkMath::Pi() * vtkMath::Pi() * big * small / n);
  for (unsigned seed : { 31u, 32u, 33u })
  {
    const std::vector<double> torus = RandomTorus(n, seed, big, small);
    std::vector<double> xyz;
    for (size_t i = 0; i < torus.size(); i += 3)
    {
      if (!(std::abs(torus[i]) < 3.0 * spacing && torus[i + 1] > 0.0))
      {
        xyz.insert(xyz.end(), { torus[i], torus[i + 1], torus[i + 2] });
      }
    }
    vtkNew<vtkGreedySurfaceTriangulation> greedy;
    greedy->SetInputData(pcstest::MakeCloud(xyz));
    greedy->Update();
    vtkPolyData* mesh = greedy->GetOutput();
    const std::string what = "torus band, seed " + std::to_string(seed);
    PCS_CHECK(CheckClosed(Measure(mesh), 1, what), "");
    const double capped = FieldValue(mesh, "NumberOfEndsCapped");
    PCS_CHECK(capped == 0, what << ": " << capped << " ends capped");
    const double far = DistanceToTorus(mesh, big, small, greedy->GetMeanSpacing());
    PCS_CHECK(far <= 3.0, what << ": a triangle " << far << " spacings from the torus");
  }
  return true;
}

bool TestDamagedSphere()
{
  const auto xyz = DamagedSphere(4000, 3, 20.0);
  const vtkIdType n = static_cast<vtkIdType>(xyz.size() / 3);
  vtkNew<vtkGreedySurfaceTriangulation> greedy;
  greedy->SetInputData(pcstest::MakeCloud(xyz));
  greedy->Update();
  vtkPolyData* mesh = greedy->GetOutput();
  const Quality q = Measure(mesh);
  PCS_CHECK(CheckClosed(q, 0, "damaged sphere"), "");
  PCS_CHECK(q.Coverage == 1.0 && q.UsedPoints == n + greedy->GetNumberOfAddedPoints(),
    "damaged sphere: coverage " << q.Coverage);
  PCS_CHECK(SignedVolume(mesh) > 0.0, "damaged sphere: outward orientation");
  const double spacing = greedy->GetMeanSpacing();
  const double distance = DistanceToUnitSphere(mesh, spacing);
  PCS_CHECK(distance <= 3.0,
            "damaged sphere: a triangle " << distance << " mean spacings from the sphere");
  PCS_CHECK(CheckArrays(greedy, "damaged sphere"), "");
  PCS_CHECK(greedy->GetNumberOfHolesFilled() > 0, "damaged sphere: holes filled");

  // The flat fill of the removed caps (FairHoleFills off) lies up to the cap's sagitta, 1 -
  // cos(20 deg) = 0.06 or about 2 mean spacings, inside the sphere; the refined and faired fill
  // continues the sphere: new points on the caps, closer to the sphere than the flat fill.
  vtkNew<vtkGreedySurfaceTriangulation> flat;
  flat->SetInputData(pcstest::MakeCloud(xyz));
  flat->FairHoleFillsOff();
  flat->Update();
  const Quality qFlat = Measure(flat->GetOutput());
  PCS_CHECK(CheckClosed(qFlat, 0, "damaged sphere, flat fill"), "");
  PCS_CHECK(flat->GetNumberOfAddedPoints() == 0 && qFlat.UsedPoints == n,
    "damaged sphere, flat fill: no point added");
  const double flatDistance = DistanceToUnitSphere(flat->GetOutput(), spacing);
  PCS_CHECK(greedy->GetNumberOfAddedPoints() > 0, "damaged sphere: points added on the caps");
  PCS_CHECK(distance < 0.5 * flatDistance,
    "damaged sphere: faired fill " << distance << " mean spacings from the sphere, flat fill "
                                   << flatDistance);
  std::cout << "damaged sphere: " << greedy->GetNumberOfAddedPoints()
            << " points added; farthest vertex or centroid " << distance
            << " mean spacings from the sphere (flat fill " << flatDistance << ")" << std::endl;

  // The step 2 result: the well-sampled regions only, open, the lost points unused.
  vtkNew<vtkGreedySurfaceTriangulation> step2;
  step2->SetInputData(pcstest::MakeCloud(xyz));
  step2->BridgeIslandsOff();
  step2->FillHolesOff();
  step2->Update();
  vtkPolyData* open = step2->GetOutput();
  const Quality q2 = Measure(open);
  PCS_CHECK(q2.NonManifoldEdges == 0 && q2.NonManifoldVertices == 0 && q2.Orientation == 1.0,
            "step 2 result: manifold and oriented");
  PCS_CHECK(q2.Loops > q.Loops && q2.BoundaryEdges > 0,
            "step 2 result: " << q2.Loops << " boundary loops (after repair " << q.Loops << ")");
  PCS_CHECK(q2.Triangles < q.Triangles, "step 2 result: fewer triangles");
  PCS_CHECK(step2->GetNumberOfHolesFilled() == 0 && step2->GetNumberOfBridges() == 0,
            "step 2 result: no bridge, no hole filled");
  PCS_CHECK(step2->GetNumberOfUnusedPoints() == step2->GetNumberOfLostPoints() &&
              step2->GetNumberOfLostPoints() == greedy->GetNumberOfLostPoints(),
            "step 2 result: the lost points, and only them, unused");
  vtkDataArray* stage = open->GetCellData()->GetArray("Stage");
  for (vtkIdType c = 0; c < open->GetNumberOfCells(); ++c)
  {
    PCS_CHECK(stage->GetTuple1(c) == 1, "step 2 result: every triangle from step 1");
  }
  PCS_CHECK(FieldValue(open, "SSRAreaPercent") == 100.0, "step 2 result: SSR area 100 %");
  PCS_CHECK(CheckArrays(step2, "step 2 result"), "");
  return true;
}

// A sphere with one cap removed (half-angle 20 degrees, about 17 mean spacings across, no point
// left in it): every vertex and centroid of the faired fill lies within 0.8 mean spacings of the
// sphere (the flat fill lies up to the cap's sagitta, 1 - cos(20 deg) = 0.06, about 3 mean
// spacings, inside it). Over 10 random samples the area-weighted fairing measured 0.3 to 1.0
// spacings; with the umbrellas unweighted by the local area, the coarser fill was flattened
// against the finer mesh around it: 0.8 to 1.5 (seed 5: 1.12, which fails the bound).
bool TestRemovedCap()
{
  for (unsigned seed : { 5u, 6u })
  {
    const std::vector<double> sphere = RandomSphere(8000, seed);
    double axis[3] = { 0.3, 0.5, 0.8 };
    vtkMath::Normalize(axis);
    const double cosCap = std::cos(vtkMath::RadiansFromDegrees(20.0));
    std::vector<double> xyz;
    for (size_t i = 0; i < sphere.size(); i += 3)
    {
      if (vtkMath::Dot(&sphere[i], axis) <= cosCap)
      {
        xyz.insert(xyz.end(), &sphere[i], &sphere[i] + 3);
      }
    }
    vtkNew<vtkGreedySurfaceTriangulation> greedy;
    greedy->SetInputData(pcstest::MakeCloud(xyz));
    greedy->Update();
    vtkPolyData* mesh = greedy->GetOutput();
    const Quality q = Measure(mesh);
    PCS_CHECK(CheckClosed(q, 0, "removed cap"), "");
    PCS_CHECK(greedy->GetNumberOfAddedPoints() > 0, "removed cap: points added on the cap");
    const double distance = DistanceToUnitSphere(mesh, greedy->GetMeanSpacing());
    std::cout << "removed cap, seed " << seed << ": " << greedy->GetNumberOfAddedPoints()
              << " points added; farthest vertex or centroid " << distance
              << " mean spacings from the sphere" << std::endl;
    PCS_CHECK(distance <= 0.8,
      "removed cap: a vertex or centroid " << distance << " mean spacings from the sphere");
  }
  return true;
}

// A tube of radius 1 and length 2 open at both ends, sampled in 41 rings of 125 points 0.05
// apart (a scan's natural border, not a hole): its ends stay open, two boundary loops, one
// manifold piece, every point used, no point added (no faired cap). Exact rings (step 6 capped
// both ends before the natural border rule) and rings turned by half a step with noise of 0.1
// spacings (CapOpenEnds capped them).
bool TestOpenTube()
{
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 0.005);
  for (bool jittered : { false, true })
  {
    std::vector<double> xyz;
    for (int ring = 0; ring <= 40; ++ring)
    {
      const double turn = jittered ? 0.5 * (ring % 2) : 0.0;
      for (int k = 0; k < 125; ++k)
      {
        const double angle = 2.0 * vtkMath::Pi() * (k + turn) / 125.0;
        const double p[3] = { std::cos(angle), std::sin(angle), -1.0 + 0.05 * ring };
        for (double c : p)
        {
          xyz.push_back(c + (jittered ? noise(rng) : 0.0));
        }
      }
    }
    const std::string what = jittered ? "open tube, jittered rings" : "open tube, exact rings";
    vtkNew<vtkGreedySurfaceTriangulation> greedy;
    greedy->SetInputData(pcstest::MakeCloud(xyz));
    greedy->Update();
    const Quality q = Measure(greedy->GetOutput());
    PCS_CHECK(q.Loops == 2, what << ": " << q.Loops << " boundary loops, expected 2");
    PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0 && q.Components == 1,
      what << ": non-manifold " << q.NonManifoldEdges << " edges, " << q.Components
           << " components");
    PCS_CHECK(greedy->GetNumberOfUnusedPoints() == 0 && greedy->GetNumberOfAddedPoints() == 0,
      what << ": " << greedy->GetNumberOfUnusedPoints() << " unused, "
           << greedy->GetNumberOfAddedPoints() << " added points");
  }
  return true;
}

bool TestBridgedIslands()
{
  // Two halves of the unit square (z = 0) separated by an empty strip of width 0.06, about 6
  // mean spacings (below the default MaximumBridgeLength of 10).
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xyz;
  for (int i = 0; i < 3000; ++i)
  {
    const double x = u(rng), y = u(rng);
    if (std::abs(x - 0.5) > 0.03)
    {
      xyz.insert(xyz.end(), { x, y, 0.0 });
    }
  }
  const vtkIdType n = static_cast<vtkIdType>(xyz.size() / 3);
  vtkNew<vtkGreedySurfaceTriangulation> greedy;
  greedy->SetInputData(pcstest::MakeCloud(xyz));
  greedy->Update();
  PCS_CHECK(0.06 / greedy->GetMeanSpacing() < 10.0, "the strip is narrower than the bridges");
  const Quality q = Measure(greedy->GetOutput());
  PCS_CHECK(q.Components == 1, "islands: " << q.Components << " connected components");
  PCS_CHECK(q.Loops == 1, "islands: " << q.Loops << " boundary loops");
  PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0 && q.Orientation == 1.0,
            "islands: manifold and oriented");
  PCS_CHECK(q.Degenerate == 0 && q.Duplicates == 0, "islands: no degenerate triangle");
  // Lost points at the outer border of the open surface are in no hole: they stay unused
  // (Status 2), at most 0.5 % of the points, and only there (within 3 mean spacings of the
  // square's sides).
  vtkPolyData* mesh = greedy->GetOutput();
  vtkDataArray* status = mesh->GetPointData()->GetArray("Status");
  const double border = 3.0 * greedy->GetMeanSpacing();
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (status->GetTuple1(i) == vtkGreedySurfaceTriangulation::LOST)
    {
      double p[3];
      mesh->GetPoint(i, p);
      PCS_CHECK(std::min({ p[0], 1.0 - p[0], p[1], 1.0 - p[1] }) <= border,
                "islands: lost point " << i << " left unused away from the border");
    }
  }
  PCS_CHECK(
    q.UsedPoints + greedy->GetNumberOfUnusedPoints() == n + greedy->GetNumberOfAddedPoints() &&
      greedy->GetNumberOfUnusedPoints() <= n / 200,
    "islands: " << greedy->GetNumberOfUnusedPoints() << " unused points");
  PCS_CHECK(greedy->GetNumberOfIslands() == 2, "islands: " << greedy->GetNumberOfIslands());
  PCS_CHECK(greedy->GetNumberOfBridges() > 0, "islands: bridges");
  vtkStringArray* steps = vtkStringArray::SafeDownCast(
    greedy->GetOutput()->GetFieldData()->GetAbstractArray("StepsUsed"));
  PCS_CHECK(steps && steps->GetValue(0).find('4') != std::string::npos,
            "islands: step 4 in StepsUsed");
  PCS_CHECK(CheckArrays(greedy, "islands"), "");

  // Without bridges: the two halves stay apart; without hole filling as well: the step 2 result.
  vtkNew<vtkGreedySurfaceTriangulation> unbridged;
  unbridged->SetInputData(pcstest::MakeCloud(xyz));
  unbridged->BridgeIslandsOff();
  unbridged->Update();
  const Quality qu = Measure(unbridged->GetOutput());
  PCS_CHECK(qu.Components == 2 && qu.Loops == 2,
            "unbridged islands: " << qu.Components << " components, " << qu.Loops << " loops");
  PCS_CHECK(unbridged->GetNumberOfBridges() == 0, "unbridged islands: no bridge");
  vtkNew<vtkGreedySurfaceTriangulation> step2;
  step2->SetInputData(pcstest::MakeCloud(xyz));
  step2->BridgeIslandsOff();
  step2->FillHolesOff();
  step2->Update();
  const Quality q2 = Measure(step2->GetOutput());
  PCS_CHECK(q2.Components == 2 && q2.Loops > qu.Loops,
            "islands step 2: " << q2.Components << " components, " << q2.Loops << " loops");
  PCS_CHECK(CheckArrays(step2, "islands step 2"), "");
  return true;
}

// Random points on a capsule along x, uniform by area: a cylinder of radius r over |x| <= h with
// hemispherical ends; the points with |x| < gap / 2 are left out.
std::vector<double> CutCapsule(int n, unsigned seed, double r, double h, double gap)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double cylinder = 4.0 * vtkMath::Pi() * r * h, sphere = 4.0 * vtkMath::Pi() * r * r;
  std::vector<double> xyz;
  for (int i = 0; i < n; ++i)
  {
    double p[3];
    if (u(rng) * (cylinder + sphere) < cylinder)
    {
      const double angle = 2.0 * vtkMath::Pi() * u(rng);
      p[0] = h * (2.0 * u(rng) - 1.0);
      p[1] = r * std::cos(angle);
      p[2] = r * std::sin(angle);
    }
    else
    {
      double d[3] = { gauss(rng), gauss(rng), gauss(rng) };
      if (vtkMath::Normalize(d) == 0.0)
      {
        continue;
      }
      p[0] = r * d[0] + (d[0] > 0 ? h : -h);
      p[1] = r * d[1];
      p[2] = r * d[2];
    }
    if (std::abs(p[0]) >= 0.5 * gap)
    {
      xyz.insert(xyz.end(), { p[0], p[1], p[2] });
    }
  }
  return xyz;
}

bool TestOpenEnds()
{
  // A capsule (radius 0.5, cylinder |x| <= 1.5) cut in two by an empty slab |x| < 0.2, wider
  // than MaximumBridgeLength spacings: two separate halves, each a tube closed at one end. Their
  // cut ends are holes of a closed object (each half's area is about 7 times the area its rim
  // spans): both capped, two closed pieces.
  const double r = 0.5, h = 1.5, gap = 0.4;
  const auto xyz = CutCapsule(6000, 11, r, h, gap);
  vtkNew<vtkGreedySurfaceTriangulation> greedy;
  greedy->SetInputData(pcstest::MakeCloud(xyz));
  greedy->Update();
  vtkPolyData* mesh = greedy->GetOutput();
  const double spacing = greedy->GetMeanSpacing();
  PCS_CHECK(gap / spacing > greedy->GetMaximumBridgeLength(),
    "cut capsule: the slab (" << gap / spacing << " spacings) is narrower than a bridge");
  const Quality q = Measure(mesh);
  PCS_CHECK(q.BoundaryEdges == 0 && q.Components == 2,
    "cut capsule: " << q.BoundaryEdges << " boundary edges, " << q.Components << " components");
  PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0 && q.Orientation == 1.0,
    "cut capsule: manifold and oriented");
  PCS_CHECK(q.Degenerate == 0 && q.Duplicates == 0, "cut capsule: no degenerate triangle");
  PCS_CHECK(pcstest::FieldCount(mesh, "NumberOfEndsCapped") == 2,
    "cut capsule: " << pcstest::FieldCount(mesh, "NumberOfEndsCapped") << " ends capped");
  // The caps stay inside the tube (no vertex farther than 3 spacings from its axis) and on their
  // side of the cut, each between the flat disc of its rim and a hemisphere on it: the volume is
  // at least the two halves' (5 % less for the inscribed mesh) and less than that plus a ball of
  // radius r.
  double nearestToCut = VTK_DOUBLE_MAX, farthestFromAxis = 0.0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    nearestToCut = std::min(nearestToCut, std::abs(p[0]));
    farthestFromAxis = std::max(farthestFromAxis, std::hypot(p[1], p[2]));
  }
  PCS_CHECK(farthestFromAxis <= r + 3.0 * spacing,
    "cut capsule: a vertex " << farthestFromAxis << " from the axis");
  PCS_CHECK(nearestToCut > 0.0, "cut capsule: a cap crosses the middle of the cut");
  const double ball = 4.0 / 3.0 * vtkMath::Pi() * r * r * r;
  const double halves = 0.5 * ball + vtkMath::Pi() * r * r * (2.0 * h - gap);
  const double volume = SignedVolume(mesh);
  PCS_CHECK(volume >= 0.95 * halves && volume <= halves + ball,
    "cut capsule: volume " << volume << ", " << halves << " with flat caps");
  PCS_CHECK(CheckArrays(greedy, "cut capsule"), "");

  // Without CapOpenEnds the cut ends stay open.
  vtkNew<vtkGreedySurfaceTriangulation> open;
  open->SetInputData(pcstest::MakeCloud(xyz));
  open->CapOpenEndsOff();
  open->Update();
  const Quality qo = Measure(open->GetOutput());
  PCS_CHECK(qo.Loops == 2 && qo.Components == 2,
    "cut capsule, CapOpenEnds off: " << qo.Loops << " loops, " << qo.Components << " components");
  PCS_CHECK(CheckArrays(open, "cut capsule, CapOpenEnds off"), "");

  // Open surfaces keep their border: a flat disc and a hemisphere bowl (whose area is twice the
  // area its rim spans), one boundary loop each.
  for (int bowl = 0; bowl < 2; ++bowl)
  {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> sheet;
    for (int i = 0; i < 3000; ++i)
    {
      const double angle = 2.0 * vtkMath::Pi() * u(rng);
      // Uniform by area: on the lower unit hemisphere z is uniform, on the unit disc rho^2.
      const double z = bowl ? -u(rng) : 0.0;
      const double rho = bowl ? std::sqrt(1.0 - z * z) : std::sqrt(u(rng));
      sheet.insert(sheet.end(), { rho * std::cos(angle), rho * std::sin(angle), z });
    }
    const std::string what = bowl ? "hemisphere bowl" : "open disc";
    vtkNew<vtkGreedySurfaceTriangulation> patch;
    patch->SetInputData(pcstest::MakeCloud(sheet));
    patch->Update();
    const Quality qp = Measure(patch->GetOutput());
    PCS_CHECK(qp.Loops == 1 && qp.Components == 1,
      what << ": " << qp.Loops << " loops, " << qp.Components << " components");
    PCS_CHECK(qp.NonManifoldEdges == 0 && qp.NonManifoldVertices == 0 && qp.Orientation == 1.0,
      what << ": manifold and oriented");
    PCS_CHECK(pcstest::FieldCount(patch->GetOutput(), "NumberOfEndsCapped") == 0,
      what << ": an end capped");
    PCS_CHECK(CheckArrays(patch, what), "");
  }
  return true;
}

// The vertices of a washer's mesh: inner cylinder of radius 1 sampled every 0.05 (125 points
// per ring, a ring every 0.05), outer cylinder of radius 2 sampled in rings of 48 points every
// 0.25, both over |z| <= 1; the flat faces z = +-1 between them have no sample but their rims.
std::vector<double> SparseWasher()
{
  std::vector<double> xyz;
  auto ring = [&xyz](double r, double z, int n)
  {
    for (int i = 0; i < n; ++i)
    {
      const double angle = 2.0 * vtkMath::Pi() * i / n;
      xyz.insert(xyz.end(), { r * std::cos(angle), r * std::sin(angle), z });
    }
  };
  for (int k = 0; k <= 40; ++k)
  {
    ring(1.0, -1.0 + 0.05 * k, 125);
  }
  for (int k = 0; k <= 8; ++k)
  {
    ring(2.0, -1.0 + 0.25 * k, 48);
  }
  return xyz;
}

bool TestWasher()
{
  const auto xyz = SparseWasher();
  vtkNew<vtkGreedySurfaceTriangulation> greedy;
  greedy->SetInputData(pcstest::MakeCloud(xyz));
  greedy->Update();
  vtkPolyData* mesh = greedy->GetOutput();
  const double spacing = greedy->GetMeanSpacing();
  PCS_CHECK(1.0 / spacing > greedy->GetMaximumBridgeLength(),
    "washer: the faces (" << 1.0 / spacing << " spacings) are narrower than a bridge");
  const Quality q = Measure(mesh);
  PCS_CHECK(q.Components == 2 && q.Loops == 4,
    "washer: " << q.Components << " components, " << q.Loops << " boundary loops");
  PCS_CHECK(q.NonManifoldEdges == 0 && q.NonManifoldVertices == 0,
    "washer: non-manifold " << q.NonManifoldEdges << " edges");
  PCS_CHECK(q.UsedPoints == static_cast<double>(xyz.size() / 3), "washer: every point used");
  // Every triangle lies on one of the two cylinders (its vertices on one radius, its centroid
  // within a spacing of it): none across the through-hole, over a face or through the other
  // part of the mesh.
  int inside = 0, across = 0;
  for (const auto& t : pcstest::CellTuples<3>(mesh))
  {
    double r[3], centroid[3] = { 0, 0, 0 };
    for (int j = 0; j < 3; ++j)
    {
      double p[3];
      mesh->GetPoint(t[j], p);
      r[j] = std::hypot(p[0], p[1]);
      vtkMath::Add(centroid, p, centroid);
    }
    vtkMath::MultiplyScalar(centroid, 1.0 / 3.0);
    const double rc = std::hypot(centroid[0], centroid[1]);
    inside += rc < 1.0 - spacing ? 1 : 0;
    const bool onInner =
      std::max({ std::abs(r[0] - 1), std::abs(r[1] - 1), std::abs(r[2] - 1) }) < 1e-9 &&
      std::abs(rc - 1.0) < spacing;
    const bool onOuter =
      std::max({ std::abs(r[0] - 2), std::abs(r[1] - 2), std::abs(r[2] - 2) }) < 1e-9 &&
      std::abs(rc - 2.0) < spacing;
    across += onInner || onOuter ? 0 : 1;
  }
  PCS_CHECK(inside == 0, "washer: " << inside << " triangles inside the through-hole");
  PCS_CHECK(across == 0, "washer: " << across << " triangles off the two cylinders");
  PCS_CHECK(CheckArrays(greedy, "washer"), "");
  return true;
}

bool TestDegenerate()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::vector<double>> inputs = {
    {},                                              // no point
    { 0, 0, 0, 1, 0, 0 },                            // 2 points
    { 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 5, 5, 5 }, // collinear
    { 0, 0, 0, 0, 0, 0, 0, 0, 0 },                   // one point three times
    { 0, 0, 0, 1, 0, 0, nan, 0, 0 },                 // two finite points and a NaN
  };
  for (size_t k = 0; k < inputs.size(); ++k)
  {
    vtkNew<vtkGreedySurfaceTriangulation> greedy;
    greedy->SetInputData(pcstest::MakeCloud(inputs[k]));
    PCS_CHECK(UpdateCountingWarnings(greedy) >= 1, "degenerate input " << k << ": a warning");
    vtkPolyData* out = greedy->GetOutput();
    PCS_CHECK(out->GetNumberOfPolys() == 0, "degenerate input " << k << ": no triangle");
    PCS_CHECK(out->GetNumberOfPoints() == static_cast<vtkIdType>(inputs[k].size() / 3),
              "degenerate input " << k << ": every point passed through");
    PCS_CHECK(pcstest::FieldCount(out, "NumberOfTriangles") == 0, "field data on " << k);
    PCS_CHECK(pcstest::FieldCount(out, "NumberOfUnusedPoints") == out->GetNumberOfPoints(),
              "degenerate input " << k << ": every point reported unused");
  }
  return true;
}
} // namespace

int TestGreedySurfaceTriangulation(int, char*[])
{
  bool ok = true;
  ok = TestSphere() && ok;
  ok = TestMonotoneProgress() && ok;
  ok = TestTorus() && ok;
  ok = TestTorusBand() && ok;
  ok = TestGridTori() && ok;
  ok = TestDamagedSphere() && ok;
  ok = TestRemovedCap() && ok;
  ok = TestOpenTube() && ok;
  ok = TestBridgedIslands() && ok;
  ok = TestOpenEnds() && ok;
  ok = TestWasher() && ok;
  ok = TestDegenerate() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
