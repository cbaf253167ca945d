// vtkReconstructionQuality's angle between the mesh triangles and the reference surface
// (ReferenceNormalAngle, MeanReferenceNormalAngle, AreaWeightedMeanReferenceNormalAngle,
// NumberOfStandingTriangles), on meshes whose angles are known by construction:
// - a plane grid tilted by a known angle over a flat reference (with the reference's triangles
//   in either orientation): that angle in every cell, within 1e-9;
// - one flat and one vertical triangle of known areas: unweighted and area-weighted means, the
//   StandingAngle threshold at 0, 60 and 90;
// - a latitude-longitude sphere against itself (angles ~0) and against a finer one (angles
//   within a bound computed from the two tessellations): no standing triangle; the same sphere
//   with k slivers standing in planes through the centre: exactly k standing;
// - a reference cloud, a degenerate triangle, SamplesPerTriangle 0: NaN and -1, NaN for the
//   degenerate cell, the same angles and the vertex-only accuracy.
#include "vtkReconstructionQuality.h"

#include "pcsQualityTestUtilities.h"
#include "pcsTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkMath.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using pcsqtest::Field;
using pcsqtest::Mesh;

bool Near(double a, double b, double tolerance = 1e-9)
{
  return std::abs(a - b) <= tolerance;
}

vtkSmartPointer<vtkPolyData> Measure(
  const Mesh& mesh, vtkDataObject* reference, double standingAngle = 60.0, int samples = 3)
{
  return pcsqtest::Run(mesh.PolyData(), reference, samples, nullptr, standingAngle);
}

vtkDataArray* Angles(vtkPolyData* out)
{
  return out->GetCellData()->GetArray("ReferenceNormalAngle");
}

// An n x n grid of spacing h in the plane z = 0 centred on the origin, rotated about the x axis by
// `tilt` degrees and lifted by `lift` along z.
Mesh TiltedGrid(int n, double h, double tilt, double lift, bool flip = false)
{
  Mesh m;
  const double c = std::cos(vtkMath::RadiansFromDegrees(tilt));
  const double s = std::sin(vtkMath::RadiansFromDegrees(tilt));
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      const double x = (i - 0.5 * n) * h, y = (j - 0.5 * n) * h;
      m.AddPoint(x, c * y, s * y + lift);
    }
  }
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = j * (n + 1) + i, b = a + 1, d = a + n + 1, e = d + 1;
      if (flip)
      {
        m.Triangles.push_back({ { a, d, b } });
        m.Triangles.push_back({ { b, d, e } });
      }
      else
      {
        m.Triangles.push_back({ { a, b, d } });
        m.Triangles.push_back({ { b, e, d } });
      }
    }
  }
  return m;
}

bool TestTiltedPlane()
{
  // Reference: the plane z = 0, much wider than the mesh; mesh: a grid tilted by `tilt` about
  // the x axis, above it. Every mesh triangle makes the angle `tilt` with the reference.
  for (bool flip : { false, true })
  {
    auto reference = TiltedGrid(8, 1.0, 0.0, 0.0, flip).PolyData();
    for (double tilt : { 0.0, 7.5, 45.0, 59.0, 61.0, 89.0, 90.0 })
    {
      const Mesh mesh = TiltedGrid(6, 0.2, tilt, 1.0);
      auto out = Measure(mesh, reference);
      const std::string label = "tilt " + std::to_string(tilt) + (flip ? " (flipped)" : "");
      vtkDataArray* angles = Angles(out);
      PCS_CHECK(angles && angles->GetNumberOfTuples() == 72, label << ": no angle array");
      for (vtkIdType c = 0; c < angles->GetNumberOfTuples(); ++c)
      {
        PCS_CHECK(Near(angles->GetTuple1(c), tilt),
          label << ": cell " << c << " angle " << angles->GetTuple1(c));
      }
      PCS_CHECK(Near(Field(out, "MeanReferenceNormalAngle"), tilt),
        label << ": mean " << Field(out, "MeanReferenceNormalAngle"));
      PCS_CHECK(Near(Field(out, "AreaWeightedMeanReferenceNormalAngle"), tilt),
        label << ": area-weighted mean " << Field(out, "AreaWeightedMeanReferenceNormalAngle"));
      PCS_CHECK(Field(out, "NumberOfStandingTriangles") == (tilt > 60.0 ? 72 : 0),
        label << ": standing " << Field(out, "NumberOfStandingTriangles"));
    }
  }
  return true;
}

bool TestAreaWeighting()
{
  // Reference z = 0. A flat triangle of area 1/2 (angle 0) and a vertical one of area 1 (angle
  // 90), whose centroids are nearest to the interior of reference triangles: mean 45,
  // area-weighted mean 90 x 1 / 1.5 = 60.
  auto reference = TiltedGrid(8, 1.0, 0.0, 0.0).PolyData();
  Mesh mesh;
  mesh.AddPoint(0.1, 0.1, 0.5);
  mesh.AddPoint(1.1, 0.1, 0.5);
  mesh.AddPoint(0.1, 1.1, 0.5);
  mesh.AddPoint(0.3, -0.9, 0.1);
  mesh.AddPoint(0.3, 1.1, 0.1);
  mesh.AddPoint(0.3, -0.9, 1.1);
  mesh.Triangles = { { { 0, 1, 2 } }, { { 3, 4, 5 } } };
  for (double standing : { 0.0, 60.0, 90.0 })
  {
    auto out = Measure(mesh, reference, standing);
    PCS_CHECK(Near(Angles(out)->GetTuple1(0), 0.0) && Near(Angles(out)->GetTuple1(1), 90.0),
      "area: angles " << Angles(out)->GetTuple1(0) << ", " << Angles(out)->GetTuple1(1));
    PCS_CHECK(Near(Field(out, "MeanReferenceNormalAngle"), 45.0), "area: unweighted mean");
    PCS_CHECK(Near(Field(out, "AreaWeightedMeanReferenceNormalAngle"), 60.0),
      "area: weighted mean " << Field(out, "AreaWeightedMeanReferenceNormalAngle"));
    PCS_CHECK(Field(out, "NumberOfStandingTriangles") == (standing < 90.0 ? 1 : 0),
      "area: standing above " << standing << ": " << Field(out, "NumberOfStandingTriangles"));
  }
  return true;
}

// A latitude-longitude unit sphere: `rings` rings of `sectors` points between the poles.
Mesh Sphere(int rings, int sectors)
{
  Mesh m;
  const vtkIdType north = m.AddPoint(0, 0, 1);
  for (int r = 1; r <= rings; ++r)
  {
    const double theta = vtkMath::Pi() * r / (rings + 1);
    for (int s = 0; s < sectors; ++s)
    {
      const double phi = 2.0 * vtkMath::Pi() * (s + 0.5 * (r % 2)) / sectors;
      m.AddPoint(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    }
  }
  const vtkIdType south = m.AddPoint(0, 0, -1);
  auto ring = [sectors](int r, int s) { return 1 + (r - 1) * sectors + (s % sectors); };
  for (int s = 0; s < sectors; ++s)
  {
    m.Triangles.push_back({ { north, ring(1, s), ring(1, s + 1) } });
    m.Triangles.push_back({ { south, ring(rings, s + 1), ring(rings, s) } });
  }
  for (int r = 1; r < rings; ++r)
  {
    for (int s = 0; s < sectors; ++s)
    {
      m.Triangles.push_back({ { ring(r, s), ring(r + 1, s), ring(r, s + 1) } });
      m.Triangles.push_back({ { ring(r, s + 1), ring(r + 1, s), ring(r + 1, s + 1) } });
    }
  }
  return m;
}

// Facet angle of a sphere tessellation: the largest angle between a triangle's normal and the
// radial direction at any of its vertices and its centroid. Also the sagitta: 1 - the smallest
// distance from the centre to a triangle's plane.
double FacetAngle(const Mesh& m, double& sagitta)
{
  double largest = 0.0;
  sagitta = 0.0;
  for (const pcsqtest::Tri& t : m.Triangles)
  {
    const double* p[3] = { &m.Points[3 * t[0]], &m.Points[3 * t[1]], &m.Points[3 * t[2]] };
    double u[3], v[3], n[3], centroid[3];
    vtkMath::Subtract(p[1], p[0], u);
    vtkMath::Subtract(p[2], p[0], v);
    vtkMath::Cross(u, v, n);
    vtkMath::Normalize(n);
    for (int i = 0; i < 3; ++i)
    {
      centroid[i] = (p[0][i] + p[1][i] + p[2][i]) / 3.0;
    }
    sagitta = std::max(sagitta, 1.0 - std::abs(vtkMath::Dot(n, p[0])));
    for (const double* x : { p[0], p[1], p[2], static_cast<const double*>(centroid) })
    {
      double radial[3] = { x[0], x[1], x[2] };
      vtkMath::Normalize(radial);
      largest = std::max(largest,
        vtkMath::DegreesFromRadians(std::acos(std::min(1.0, std::abs(vtkMath::Dot(n, radial))))));
    }
  }
  return largest;
}

bool TestSphere()
{
  const Mesh coarse = Sphere(12, 24), fine = Sphere(30, 60);
  double coarseSagitta, fineSagitta;
  const double coarseFacet = FacetAngle(coarse, coarseSagitta);
  const double fineFacet = FacetAngle(fine, fineSagitta);
  auto coarseData = coarse.PolyData();
  auto fineData = fine.PolyData();
  const auto triangles = static_cast<vtkIdType>(coarse.Triangles.size());

  // Against itself: each centroid lies on its own triangle.
  auto self = Measure(coarse, coarseData);
  PCS_CHECK(Field(self, "NumberOfStandingTriangles") == 0, "sphere itself: standing");
  PCS_CHECK(Field(self, "MeanReferenceNormalAngle") < 1e-6,
    "sphere itself: mean " << Field(self, "MeanReferenceNormalAngle"));

  // Against the finer sphere. The closest point p of the fine mesh to a centroid c (|c| = r) is
  // within D = 1 - r + fineSagitta of it: the radial directions at c and p differ by at most
  // asin(D / r), the coarse normal from the radial at c and the fine normal from the radial at
  // p by at most their facet angles.
  auto out = Measure(coarse, fineData);
  double bound = 0.0;
  {
    double minRadius = 1.0;
    for (const pcsqtest::Tri& t : coarse.Triangles)
    {
      double c[3] = { 0, 0, 0 };
      for (vtkIdType id : t)
      {
        for (int i = 0; i < 3; ++i)
        {
          c[i] += coarse.Points[3 * id + i] / 3.0;
        }
      }
      minRadius = std::min(minRadius, vtkMath::Norm(c));
    }
    bound = coarseFacet + fineFacet +
      vtkMath::DegreesFromRadians(std::asin((1.0 - minRadius + fineSagitta) / minRadius));
  }
  std::cout << "sphere: facet angles " << coarseFacet << ", " << fineFacet << "; bound " << bound
            << std::endl;
  PCS_CHECK(bound < 30.0, "sphere: the tessellations are too coarse for the test");
  vtkDataArray* angles = Angles(out);
  double largest = 0.0;
  for (vtkIdType c = 0; c < triangles; ++c)
  {
    largest = std::max(largest, angles->GetTuple1(c));
  }
  PCS_CHECK(largest <= bound, "sphere vs fine sphere: angle " << largest << " > " << bound);
  PCS_CHECK(Field(out, "NumberOfStandingTriangles") == 0, "sphere vs fine sphere: standing");
  PCS_CHECK(Field(out, "MeanReferenceNormalAngle") <= bound, "sphere vs fine sphere: mean");

  // k slivers (a, b, 0.8 (a + b) / 2) on edges a-b of the coarse sphere: in the plane through
  // a, b and the centre, so normal to the radial direction at their centroid c (|c| >= rs). The
  // reference normal nearest to c is within facet + asin((1 - rs + sagitta) / rs) of that
  // radial direction (as above): the sliver's angle is above 90 minus that.
  Mesh withSlivers = coarse;
  const int k = 7;
  double rs = 1.0;
  for (int i = 0; i < k; ++i)
  {
    const pcsqtest::Tri& t = coarse.Triangles[13 * i + 5];
    const double* a = &coarse.Points[3 * t[0]];
    const double* b = &coarse.Points[3 * t[1]];
    const double m[3] = { 0.4 * (a[0] + b[0]), 0.4 * (a[1] + b[1]), 0.4 * (a[2] + b[2]) };
    const double c[3] = {
      (a[0] + b[0] + m[0]) / 3.0, (a[1] + b[1] + m[1]) / 3.0, (a[2] + b[2] + m[2]) / 3.0
    };
    rs = std::min(rs, vtkMath::Norm(c));
    const vtkIdType id = withSlivers.AddPoint(m[0], m[1], m[2]);
    withSlivers.Triangles.push_back({ { t[0], t[1], id } });
  }
  const double coarseSlack =
    coarseFacet + vtkMath::DegreesFromRadians(std::asin((1.0 - rs + coarseSagitta) / rs));
  const double fineSlack =
    fineFacet + vtkMath::DegreesFromRadians(std::asin((1.0 - rs + fineSagitta) / rs));
  std::cout << "slivers: slack " << coarseSlack << ", " << fineSlack << std::endl;
  PCS_CHECK(coarseSlack < 30.0 && fineSlack < 30.0, "slivers: the slack does not separate them");
  for (bool fineReference : { false, true })
  {
    vtkPolyData* reference = fineReference ? fineData.Get() : coarseData.Get();
    const double slack = fineReference ? fineSlack : coarseSlack;
    auto slivers = Measure(withSlivers, reference);
    PCS_CHECK(Field(slivers, "NumberOfStandingTriangles") == k,
      "slivers: standing " << Field(slivers, "NumberOfStandingTriangles") << ", expected " << k);
    for (vtkIdType c = triangles; c < triangles + k; ++c)
    {
      PCS_CHECK(Angles(slivers)->GetTuple1(c) >= 90.0 - slack,
        "sliver " << c << ": angle " << Angles(slivers)->GetTuple1(c));
    }
  }
  return true;
}

bool TestUndefined()
{
  auto reference = TiltedGrid(8, 1.0, 0.0, 0.0).PolyData();
  Mesh mesh = TiltedGrid(4, 0.2, 30.0, 1.0);
  // A degenerate (collinear) triangle: NaN, not counted.
  const vtkIdType p = mesh.AddPoint(0.0, 0.0, 2.0), q = mesh.AddPoint(0.1, 0.0, 2.0),
                  r = mesh.AddPoint(0.3, 0.0, 2.0);
  mesh.Triangles.push_back({ { p, q, r } });
  auto out = Measure(mesh, reference);
  PCS_CHECK(std::isnan(Angles(out)->GetTuple1(32)), "degenerate triangle: angle not NaN");
  PCS_CHECK(Near(Field(out, "MeanReferenceNormalAngle"), 30.0), "degenerate: mean");
  PCS_CHECK(Field(out, "NumberOfStandingTriangles") == 0, "degenerate: standing");

  // No samples: the centroids are still queried (same angles); the accuracy is the vertices'.
  auto vertices = Measure(mesh, reference, 60.0, 0);
  for (vtkIdType c = 0; c < 33; ++c)
  {
    const double a = Angles(out)->GetTuple1(c), b = Angles(vertices)->GetTuple1(c);
    PCS_CHECK((std::isnan(a) && std::isnan(b)) || a == b, "no samples: angle " << c);
  }
  double largestZ = 0.0, sumZ = 0.0;
  vtkIdType used = 0;
  for (vtkIdType i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    largestZ = std::max(largestZ, mesh.Points[3 * i + 2]);
    sumZ += mesh.Points[3 * i + 2];
    ++used;
  }
  PCS_CHECK(Near(Field(vertices, "AccuracyMax"), largestZ), "no samples: AccuracyMax");
  PCS_CHECK(Near(Field(vertices, "AccuracyMean"), sumZ / used), "no samples: AccuracyMean");

  // A reference cloud: no reference normal.
  auto cloud = pcstest::MakeCloud(TiltedGrid(8, 1.0, 0.0, 0.0).Points);
  auto fromCloud = Measure(mesh, cloud);
  PCS_CHECK(std::isnan(Field(fromCloud, "MeanReferenceNormalAngle")) &&
      std::isnan(Field(fromCloud, "AreaWeightedMeanReferenceNormalAngle")) &&
      Field(fromCloud, "NumberOfStandingTriangles") == -1,
    "cloud reference: defined values");
  for (vtkIdType c = 0; c < 33; ++c)
  {
    PCS_CHECK(std::isnan(Angles(fromCloud)->GetTuple1(c)), "cloud reference: cell angle");
  }
  return true;
}
} // namespace

int TestReconstructionQualityNormals(int, char*[])
{
  const std::vector<pcsqtest::NamedTest> tests = {
    { "tilted plane", TestTiltedPlane },
    { "area weighting", TestAreaWeighting },
    { "sphere and slivers", TestSphere },
    { "undefined angles", TestUndefined },
  };
  return pcsqtest::RunTests(tests);
}
