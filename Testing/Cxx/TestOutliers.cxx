// Far outliers (OutlierFactor, the shared rule of pcsOutliers) in vtkPerimeterPeelSurface,
// vtkLocalOptimumGrowth, vtkGreedySurfaceTriangulation and vtkCDTAdvancingFront, on clouds whose
// outliers are known by construction:
// - 3,000 random points of the unit sphere plus 3 % outliers uniform in the box [-3, 3]^3 (three
//   times the sphere's bounding box), none within 0.8 of the sphere (25 mean spacings; the rule
//   leaves points within about 8 reaches, some 20 spacings, alone):
//   each filter gives a closed, manifold, oriented, genus-0 surface over exactly the sphere
//   points (every one used, every outlier unused), every triangle within 2 mean spacings of the
//   sphere, and reports exactly the outliers (field data NumberOfOutliers, point data Used = 0);
//   with OutlierFactor 0 (off) the outliers are not reported; vtkLocalOptimumGrowth with 6
//   neighbours (the rule's own search instead of the growth's table) reports the same outliers;
// - clean clouds flag nothing: a torus sampled 25 times more densely on one side, and a sphere
//   with Gaussian noise of 0.4 mean spacings per coordinate;
// - a sparse part of a surface next to a dense patch holding most of the points is not flagged
//   (the flat-sample exemption of pcs::FindOutliersAndPiles);
// - piles of near-coincident points that outnumber the surface count once each
//   (pcs::FindPiles): 1,000 sphere points plus 4 piles of 600 distinct points within 3e-9
//   of 4 of them flag nothing; a fifth pile of 600 far from the sphere is flagged whole;
// - one stray point far from the sphere (10^4 and 10^12 radii away): each filter gives the sphere
//   and reports the stray. Before, at 10^12 the sphere itself was taken for a pile (its extent
//   under 1/10,000 of its distance to the stray) and merged into one point: no triangle at all;
//   at 10^4 vtkCDTAdvancingFront, which had no outlier rule, meshed the stray with the sphere.
#include "vtkCDTAdvancingFront.h"
#include "vtkGreedySurfaceTriangulation.h"
#include "vtkLocalOptimumGrowth.h"
#include "vtkPerimeterPeelSurface.h"
#include "vtkReconstructionQuality.h"

#include "pcsPeelTestShapes.h"
#include "pcsTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyDataAlgorithm.h"

#include <cmath>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>

namespace
{
using namespace pcstest;

constexpr int SpherePointCount = 3000;
// Mean nearest-neighbour distance of n uniform random points on the unit sphere: half the side
// of a square of area 4 pi / n.
const double SphereSpacing = 0.5 * std::sqrt(4.0 * M_PI / SpherePointCount);

// The sphere points first, then the outliers.
std::vector<double> SphereWithOutliers(int outliers, unsigned seed)
{
  std::vector<double> xyz = SpherePoints(SpherePointCount, seed);
  std::mt19937_64 rng(seed + 77);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  while (static_cast<int>(xyz.size()) < 3 * (SpherePointCount + outliers))
  {
    const double p[3] = { u(rng), u(rng), u(rng) };
    if (std::fabs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1.0) > 0.8)
    {
      xyz.insert(xyz.end(), p, p + 3);
    }
  }
  return xyz;
}

vtkSmartPointer<vtkPolyData> Run(vtkPolyDataAlgorithm* filter, const std::vector<double>& xyz)
{
  filter->SetInputData(MakeCloud(xyz));
  filter->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(filter->GetOutput());
  return out;
}

// The sphere of SphereWithOutliers without its outliers: closed, manifold, oriented, genus 0,
// every sphere point used and no outlier, all triangles near the sphere, the outliers reported.
bool CheckSphereSurface(const std::string& label, vtkPolyData* mesh, int outliers)
{
  PCS_CHECK(mesh->GetNumberOfPoints() == SpherePointCount + outliers, label << ": points passed");
  PCS_CHECK(FieldCount(mesh, "NumberOfOutliers") == outliers,
    label << ": " << FieldCount(mesh, "NumberOfOutliers") << " outliers reported, " << outliers
          << " added");
  vtkDataArray* used = mesh->GetPointData()->GetArray("Used");
  PCS_CHECK(used != nullptr, label << ": Used");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    PCS_CHECK((used->GetTuple1(i) != 0) == (i < SpherePointCount),
      label << ": point " << i << (i < SpherePointCount ? " (sphere) unused" : " (outlier) used"));
  }
  PCS_CHECK(mesh->GetNumberOfPolys() == 2 * SpherePointCount - 4, label << ": 2V - 4 triangles");
  PCS_CHECK(QualityValue(mesh, "NumberOfBoundaryEdges") == 0, label << ": closed");
  PCS_CHECK(QualityValue(mesh, "NumberOfNonManifoldEdges") == 0 &&
      QualityValue(mesh, "NumberOfNonManifoldVertices") == 0,
    label << ": manifold");
  PCS_CHECK(QualityValue(mesh, "Genus") == 0, label << ": genus 0");
  PCS_CHECK(QualityValue(mesh, "OrientationConsistency") == 1.0, label << ": oriented");
  for (const auto& t : CellTuples<3>(mesh))
  {
    double c[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      double p[3];
      mesh->GetPoint(t[k], p);
      for (int j = 0; j < 3; ++j)
      {
        c[j] += p[j] / 3.0;
      }
    }
    const double offset = 1.0 - std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    PCS_CHECK(offset <= 2.0 * SphereSpacing, label << ": a triangle " << offset / SphereSpacing
                                                   << " mean spacings inside the sphere");
  }
  std::cout << label << ": " << mesh->GetNumberOfPolys() << " triangles, "
            << FieldCount(mesh, "NumberOfOutliers") << " outliers reported" << std::endl;
  return true;
}

// `Filter` on the sphere with 3 % outliers: the sphere, the outliers reported; none reported with
// OutlierFactor 0.
template <typename Filter>
bool CheckExcluded(const std::string& name, unsigned seed)
{
  const int outliers = SpherePointCount * 3 / 100;
  const std::vector<double> xyz = SphereWithOutliers(outliers, seed);
  vtkNew<Filter> filter;
  if (!CheckSphereSurface(name + ", 3 % box outliers", Run(filter, xyz), outliers))
  {
    return false;
  }
  filter->SetOutlierFactor(0.0);
  PCS_CHECK(FieldCount(Run(filter, xyz), "NumberOfOutliers") == 0, name << ", OutlierFactor 0");
  return true;
}

// One stray point `distance` radii from the sphere: the sphere, the stray reported.
template <typename Filter>
bool CheckFarStray(const std::string& name, double distance)
{
  std::vector<double> xyz = SpherePoints(SpherePointCount, 11);
  xyz.insert(xyz.end(), { 0.6 * distance, -0.8 * distance, 0.0 });
  vtkNew<Filter> filter;
  std::ostringstream label;
  label << name << ", one stray point " << distance << " radii away";
  return CheckSphereSurface(label.str(), Run(filter, xyz), 1);
}

template <typename Filter>
bool CheckFarStrays(const std::string& name)
{
  const bool near = CheckFarStray<Filter>(name, 1e4);
  return CheckFarStray<Filter>(name, 1e12) && near;
}

// vtkLocalOptimumGrowth takes the rule's neighbours from its own table when NumberOfNeighbors >= 8,
// else searches them apart: the same outliers either way.
bool CheckFewNeighbors()
{
  const int outliers = SpherePointCount * 3 / 100;
  const std::vector<double> xyz = SphereWithOutliers(outliers, 4);
  vtkNew<vtkLocalOptimumGrowth> growth;
  growth->SetNumberOfNeighbors(6);
  auto mesh = Run(growth, xyz);
  PCS_CHECK(FieldCount(mesh, "NumberOfOutliers") == outliers, "LOG, 6 neighbours: outliers");
  vtkDataArray* used = mesh->GetPointData()->GetArray("Used");
  for (vtkIdType i = SpherePointCount; i < mesh->GetNumberOfPoints(); ++i)
  {
    PCS_CHECK(used->GetTuple1(i) == 0, "LOG, 6 neighbours: outlier " << i << " used");
  }
  return true;
}

// Clean clouds, graded or noisy: nothing is an outlier.
bool CheckCleanClouds()
{
  std::vector<double> noisy = SpherePoints(SpherePointCount, 6);
  std::mt19937_64 rng(6);
  std::normal_distribution<double> g(0.0, 0.4 * SphereSpacing);
  for (double& c : noisy)
  {
    c += g(rng);
  }
  const std::vector<double> graded = GradedTorusPoints(5000, 1, 1.2);
  vtkNew<vtkPerimeterPeelSurface> peel;
  vtkNew<vtkLocalOptimumGrowth> growth;
  PCS_CHECK(FieldCount(Run(peel, graded), "NumberOfOutliers") == 0, "peel, graded torus");
  PCS_CHECK(FieldCount(Run(growth, graded), "NumberOfOutliers") == 0, "LOG, graded torus");
  PCS_CHECK(FieldCount(Run(peel, noisy), "NumberOfOutliers") == 0, "peel, noisy sphere");
  PCS_CHECK(FieldCount(Run(growth, noisy), "NumberOfOutliers") == 0, "LOG, noisy sphere");
  return true;
}
// A sparse part of a sampled surface is not an outlier, however much denser the rest: 2,000
// random points of the unit sphere plus 5,000 in the cap within 0.3 rad of +z (about 110 times
// denser, a reach about 10 times smaller, so the whole sparse part is past the sparse limit and
// past OutlierFactor 8 against the cap's points). Before the flat-sample exemption 871 of the
// sparse points were flagged, all over the sphere; now only points at the cap's rim may be (their
// nearest points are partly cap points): at most 40 outliers, and at most 1 % of the sparse points
// more than 40 degrees from +z unused (the peel may leave a few inside its solid).
bool CheckDensePatch()
{
  std::vector<double> xyz = SpherePoints(2000, 8);
  const std::vector<double> many = SpherePoints(300000, 9);
  for (size_t i = 0; i < many.size() && xyz.size() < 3 * 7000; i += 3)
  {
    if (many[i + 2] > std::cos(0.3))
    {
      xyz.insert(xyz.end(), &many[i], &many[i] + 3);
    }
  }
  PCS_CHECK(xyz.size() == 3 * 7000, "dense patch: 5,000 cap points");
  vtkNew<vtkPerimeterPeelSurface> peel;
  vtkNew<vtkLocalOptimumGrowth> growth;
  vtkNew<vtkGreedySurfaceTriangulation> greedy;
  for (vtkPolyDataAlgorithm* filter :
    { static_cast<vtkPolyDataAlgorithm*>(peel), static_cast<vtkPolyDataAlgorithm*>(growth),
      static_cast<vtkPolyDataAlgorithm*>(greedy) })
  {
    auto mesh = Run(filter, xyz);
    const std::string name = filter->GetClassName();
    PCS_CHECK(FieldCount(mesh, "NumberOfOutliers") <= 40, name << ", dense patch: outliers");
    vtkDataArray* used = mesh->GetPointData()->GetArray("Used");
    int unusedFar = 0;
    for (vtkIdType i = 0; i < 2000; ++i)
    {
      unusedFar += used->GetTuple1(i) == 0 && xyz[3 * i + 2] < std::cos(40.0 * M_PI / 180.0);
    }
    PCS_CHECK(unusedFar <= 20, name << ", dense patch: " << unusedFar << " sparse points unused");
  }
  return true;
}

// Piles of near-coincident points count once each: 1,000 random points of the unit sphere and
// 4 piles of 600 distinct points within 3e-9 of the sphere points 0, 250, 500 and 750 (most of
// the cloud): every point lies on the sampled sphere, so none is an outlier (before, the median
// reach was a pile's and 80 sphere points were flagged). With a fifth pile of 600 points within
// 1e-9 of (3, 0, 0), two radii off the sphere, exactly those 600 are outliers (before, none:
// each pile point's reach was tiny).
bool CheckPiles()
{
  std::vector<double> xyz = SpherePoints(1000, 10);
  for (int i = 0; i < 2400; ++i)
  {
    const double* center = &xyz[3 * 250 * (i % 4)];
    const double step = 1e-12 * (i + 1);
    const double p[3] = { center[0] + step, center[1] + 2 * step, center[2] + 3 * step };
    xyz.insert(xyz.end(), p, p + 3);
  }
  std::vector<double> withFarPile = xyz;
  for (int i = 0; i < 600; ++i)
  {
    const double step = 1e-12 * (i + 1);
    const double p[3] = { 3.0 + step, -step, 2 * step };
    withFarPile.insert(withFarPile.end(), p, p + 3);
  }
  vtkNew<vtkPerimeterPeelSurface> peel;
  vtkNew<vtkLocalOptimumGrowth> growth;
  vtkNew<vtkGreedySurfaceTriangulation> greedy;
  for (vtkPolyDataAlgorithm* filter : { static_cast<vtkPolyDataAlgorithm*>(peel),
         static_cast<vtkPolyDataAlgorithm*>(growth),
         static_cast<vtkPolyDataAlgorithm*>(greedy) })
  {
    const std::string name = filter->GetClassName();
    const vtkIdType onSphere = FieldCount(Run(filter, xyz), "NumberOfOutliers");
    PCS_CHECK(onSphere == 0, name << ", piles on the sphere: " << onSphere << " outliers");
    auto mesh = Run(filter, withFarPile);
    const vtkIdType far = FieldCount(mesh, "NumberOfOutliers");
    PCS_CHECK(far == 600, name << ", a far pile: " << far << " outliers, 600 added");
    vtkDataArray* used = mesh->GetPointData()->GetArray("Used");
    for (vtkIdType i = 3400; i < 4000; ++i)
    {
      PCS_CHECK(used->GetTuple1(i) == 0, name << ", a far pile: point " << i << " used");
    }
  }
  return true;
}

// Small piles (2 to 8 near-coincident points, as repeated returns of a scanner give): every third
// point of a 1,000-point sphere repeated m - 1 more times within 1e-8 gives no outlier, and a
// pile of m points far off the sphere is flagged whole (m outliers; before the piles counted
// once, a far pile's reach was its own 1e-9 and it was never flagged).
bool CheckSmallPiles()
{
  const std::vector<double> sphere = SpherePoints(1000, 10);
  vtkNew<vtkPerimeterPeelSurface> peel;
  vtkNew<vtkLocalOptimumGrowth> growth;
  vtkNew<vtkGreedySurfaceTriangulation> greedy;
  for (int m : { 2, 8 })
  {
    std::vector<double> xyz = sphere;
    for (int i = 0; i < 1000; i += 3)
    {
      for (int j = 1; j < m; ++j)
      {
        const double step = 1e-9 * j;
        const double p[3] = { sphere[3 * i] + step, sphere[3 * i + 1] + 2 * step,
          sphere[3 * i + 2] - step };
        xyz.insert(xyz.end(), p, p + 3);
      }
    }
    std::vector<double> withFarPile = xyz;
    for (int j = 0; j < m; ++j)
    {
      const double p[3] = { 3.0 + 1e-9 * j, -1e-9 * j, 2e-9 * j };
      withFarPile.insert(withFarPile.end(), p, p + 3);
    }
    for (vtkPolyDataAlgorithm* filter : { static_cast<vtkPolyDataAlgorithm*>(peel),
           static_cast<vtkPolyDataAlgorithm*>(growth),
           static_cast<vtkPolyDataAlgorithm*>(greedy) })
    {
      const std::string name = filter->GetClassName();
      const vtkIdType onSphere = FieldCount(Run(filter, xyz), "NumberOfOutliers");
      PCS_CHECK(onSphere == 0,
        name << ", piles of " << m << " on the sphere: " << onSphere << " outliers");
      const vtkIdType far = FieldCount(Run(filter, withFarPile), "NumberOfOutliers");
      PCS_CHECK(far == m, name << ", a far pile of " << m << ": " << far << " outliers");
    }
  }
  return true;
}
} // namespace

int TestOutliers(int, char*[])
{
  bool ok = CheckExcluded<vtkPerimeterPeelSurface>("peel", 3);
  ok = CheckExcluded<vtkLocalOptimumGrowth>("local optimum growth", 4) && ok;
  ok = CheckExcluded<vtkGreedySurfaceTriangulation>("greedy", 5) && ok;
  ok = CheckExcluded<vtkCDTAdvancingFront>("CDT", 6) && ok;
  ok = CheckFarStrays<vtkPerimeterPeelSurface>("peel") && ok;
  ok = CheckFarStrays<vtkLocalOptimumGrowth>("local optimum growth") && ok;
  ok = CheckFarStrays<vtkGreedySurfaceTriangulation>("greedy") && ok;
  ok = CheckFarStrays<vtkCDTAdvancingFront>("CDT") && ok;
  ok = CheckFewNeighbors() && ok;
  ok = CheckCleanClouds() && ok;
  ok = CheckDensePatch() && ok;
  ok = CheckPiles() && ok;
  ok = CheckSmallPiles() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
