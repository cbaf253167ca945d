// 2.5D mode (Dimension = 2): the triangles equal vtkDelaunay2D's and CGAL's
// Delaunay_triangulation_2 on points in general position; on a cocircular grid every point is
// used, triangles are counter-clockwise and locally Delaunay (exact), their area is the hull area
// and their count is 2n - 2 - h; the best-fit plane of a tilted terrain gives the same
// triangulation as the x-y projection of the untilted one.
#include "vtkIncrementalDelaunay3D.h"

#include "pcsTestUtilities.h"

#include "vtkDelaunay2D.h"
#include "vtkTransform.h"
#include "vtkTransformFilter.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Kernel::Point_2;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<long long, Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase>;
using CGALDelaunay2 = CGAL::Delaunay_triangulation_2<Kernel, DataStructure>;
using TriangleSet = std::set<std::array<vtkIdType, 3>>;

TriangleSet Sorted(const std::vector<std::array<vtkIdType, 3>>& triangles)
{
  TriangleSet set;
  for (auto t : triangles)
  {
    std::sort(t.begin(), t.end());
    set.insert(t);
  }
  return set;
}

std::vector<double> Terrain(int n, unsigned seed, double amplitude = 0.3)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> xyz;
  for (int i = 0; i < n; ++i)
  {
    const double x = u(rng), y = u(rng);
    xyz.insert(xyz.end(), { x, y, amplitude * std::sin(3 * x) * std::cos(2 * y) });
  }
  return xyz;
}

vtkSmartPointer<vtkPolyData> Run2D(vtkPolyData* cloud, int plane = vtkIncrementalDelaunay3D::XY_PLANE)
{
  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  delaunay->SetInputData(cloud);
  delaunay->SetDimension(2);
  delaunay->SetProjectionPlane(plane);
  delaunay->Update();
  return delaunay->GetSurfaceOutput();
}

bool CompareWithPeers()
{
  const std::vector<double> xyz = Terrain(20000, 11);
  auto cloud = pcstest::MakeCloud(xyz);
  const TriangleSet ours = Sorted(pcstest::CellTuples<3>(Run2D(cloud).Get()));

  vtkNew<vtkDelaunay2D> vtk;
  vtk->SetInputData(cloud);
  vtk->Update();
  const TriangleSet theirs = Sorted(pcstest::CellTuples<3>(vtk->GetOutput()));

  std::vector<std::pair<Point2, long long>> points;
  for (size_t i = 0; i < xyz.size() / 3; ++i)
  {
    points.emplace_back(Point2(xyz[3 * i], xyz[3 * i + 1]), static_cast<long long>(i));
  }
  CGALDelaunay2 cgal(points.begin(), points.end());
  TriangleSet reference;
  for (auto f = cgal.finite_faces_begin(); f != cgal.finite_faces_end(); ++f)
  {
    std::array<vtkIdType, 3> t = { f->vertex(0)->info(), f->vertex(1)->info(),
      f->vertex(2)->info() };
    std::sort(t.begin(), t.end());
    reference.insert(t);
  }
  std::cout << "terrain 2e4: ours " << ours.size() << ", vtkDelaunay2D " << theirs.size()
            << ", CGAL " << reference.size() << std::endl;
  PCS_CHECK(ours == reference, "2.5D triangles differ from CGAL");
  // vtkDelaunay2D is not an exact Delaunay triangulation: it starts from a finite bounding
  // triangulation (so it misses thin triangles along the convex hull) and decides in floating
  // point. So its triangles cannot all equal ours; instead every one of its triangles that is not
  // ours must be wrong, i.e. have an input point strictly inside its circumcircle (exact
  // predicate), and it must agree with ours on almost everything.
  auto Q = [&xyz](vtkIdType i) { return Point2(xyz[3 * i], xyz[3 * i + 1]); };
  size_t missing = 0, common = 0;
  for (const auto& t : theirs)
  {
    if (ours.count(t))
    {
      ++common;
      continue;
    }
    ++missing;
    Point2 a = Q(t[0]), b = Q(t[1]), c = Q(t[2]);
    if (CGAL::orientation(a, b, c) == CGAL::RIGHT_TURN)
    {
      std::swap(b, c);
    }
    bool witness = false;
    for (size_t i = 0; i < xyz.size() / 3 && !witness; ++i)
    {
      witness = CGAL::side_of_oriented_circle(a, b, c, Q(static_cast<vtkIdType>(i))) ==
        CGAL::ON_POSITIVE_SIDE;
    }
    PCS_CHECK(witness,
      "vtkDelaunay2D triangle (" << t[0] << ", " << t[1] << ", " << t[2]
                                 << ") is Delaunay but not in the 2.5D triangulation");
  }
  std::cout << "vtkDelaunay2D: " << common << " triangles in common, " << missing
            << " not Delaunay (a point strictly inside the circumcircle), "
            << ours.size() - common << " of ours missing" << std::endl;
  PCS_CHECK(common >= 0.99 * ours.size(), "vtkDelaunay2D agrees on less than 99 %");
  return true;
}

bool CheckGrid()
{
  const int g = 40;
  std::vector<double> xyz;
  for (int i = 0; i < g; ++i)
  {
    for (int j = 0; j < g; ++j)
    {
      xyz.insert(xyz.end(), { double(i), double(j), 0.01 * i * j });
    }
  }
  // Same (x, y) with another z: merged as a duplicate of the projection.
  xyz.insert(xyz.end(), { 5.0, 7.0, 100.0 });
  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  delaunay->SetInputData(pcstest::MakeCloud(xyz));
  delaunay->SetDimension(2);
  delaunay->Update();
  PCS_CHECK(delaunay->GetNumberOfDuplicatePoints() == 1, "projected duplicate merged");
  {
    vtkDataArray* representative =
      delaunay->GetSurfaceOutput()->GetPointData()->GetArray("RepresentativeId");
    const vtkIdType last = static_cast<vtkIdType>(xyz.size() / 3) - 1;
    PCS_CHECK(representative->GetTuple1(last) == 5 * g + 7,
      "the projected duplicate is represented by the grid point (5, 7)");
    for (vtkIdType i = 0; i < last; ++i)
    {
      PCS_CHECK(representative->GetTuple1(i) == i, "grid point " << i << " represents itself");
    }
    PCS_CHECK(pcstest::FieldCount(delaunay->GetSurfaceOutput(), "NumberOfDuplicatePoints") == 1,
      "field data duplicate count");
  }
  const auto triangles = pcstest::CellTuples<3>(delaunay->GetSurfaceOutput());
  const int n = g * g, h = 4 * (g - 1);
  PCS_CHECK(static_cast<int>(triangles.size()) == 2 * n - 2 - h,
    "grid triangle count " << triangles.size() << " expected " << 2 * n - 2 - h);
  std::vector<char> used(xyz.size() / 3, 0);
  double area = 0.0;
  std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> opposite; // directed edge -> vertex
  auto Q = [&xyz](vtkIdType i) { return Point2(xyz[3 * i], xyz[3 * i + 1]); };
  for (const auto& t : triangles)
  {
    PCS_CHECK(CGAL::orientation(Q(t[0]), Q(t[1]), Q(t[2])) == CGAL::LEFT_TURN,
      "grid triangle not counter-clockwise");
    area += CGAL::to_double(CGAL::area(Q(t[0]), Q(t[1]), Q(t[2])));
    for (int i = 0; i < 3; ++i)
    {
      used[t[i]] = 1;
      opposite[{ t[(i + 1) % 3], t[(i + 2) % 3] }] = t[i];
    }
  }
  for (const auto& t : triangles)
  {
    for (int i = 0; i < 3; ++i)
    {
      auto it = opposite.find({ t[(i + 2) % 3], t[(i + 1) % 3] });
      if (it != opposite.end())
      {
        PCS_CHECK(CGAL::side_of_oriented_circle(Q(t[0]), Q(t[1]), Q(t[2]), Q(it->second)) !=
            CGAL::ON_POSITIVE_SIDE,
          "grid edge not locally Delaunay");
      }
    }
  }
  for (int i = 0; i < n; ++i)
  {
    PCS_CHECK(used[i], "grid point " << i << " unused");
  }
  PCS_CHECK(std::fabs(area - (g - 1) * (g - 1)) < 1e-9, "grid area " << area);

  // The grid is massively cocircular: the triangulation is fixed by the symbolic perturbation,
  // which depends on the points only, so a permuted input gives the same triangles.
  std::vector<vtkIdType> permutation(n);
  for (int i = 0; i < n; ++i)
  {
    permutation[i] = i;
  }
  std::shuffle(permutation.begin(), permutation.end(), std::mt19937_64(99));
  std::vector<double> permuted(3 * static_cast<size_t>(n));
  for (int i = 0; i < n; ++i)
  {
    std::copy(&xyz[3 * permutation[i]], &xyz[3 * permutation[i]] + 3, &permuted[3 * i]);
  }
  vtkNew<vtkIncrementalDelaunay3D> shuffled;
  shuffled->SetInputData(pcstest::MakeCloud(permuted));
  shuffled->SetDimension(2);
  shuffled->Update();
  TriangleSet mapped;
  for (auto t : pcstest::CellTuples<3>(shuffled->GetSurfaceOutput()))
  {
    for (vtkIdType& id : t)
    {
      id = permutation[id];
    }
    std::sort(t.begin(), t.end());
    mapped.insert(t);
  }
  PCS_CHECK(mapped == Sorted(triangles), "the grid triangulation depends on the input order");
  return true;
}

bool CheckBestFitPlane()
{
  const std::vector<double> xyz = Terrain(3000, 5, 0.0); // planar
  auto flat = pcstest::MakeCloud(xyz);
  vtkNew<vtkTransform> tilt;
  tilt->RotateX(35.0);
  tilt->RotateY(-20.0);
  tilt->Translate(3.0, -2.0, 1.0);
  vtkNew<vtkTransformFilter> transform;
  transform->SetInputData(flat);
  transform->SetTransform(tilt);
  transform->Update();
  auto tilted = vtkPolyData::SafeDownCast(transform->GetOutput());
  const TriangleSet reference = Sorted(pcstest::CellTuples<3>(Run2D(flat).Get()));
  const TriangleSet ours =
    Sorted(pcstest::CellTuples<3>(Run2D(tilted, vtkIncrementalDelaunay3D::BEST_FIT_PLANE).Get()));
  size_t common = 0;
  for (const auto& t : ours)
  {
    common += reference.count(t);
  }
  std::cout << "best-fit plane: " << common << " of " << reference.size()
            << " triangles in common" << std::endl;
  PCS_CHECK(ours == reference, "best-fit plane triangulation differs from the x-y one");
  return true;
}
} // namespace

int TestIncrementalDelaunay2D(int, char*[])
{
  bool ok = CompareWithPeers();
  ok = CheckGrid() && ok;
  ok = CheckBestFitPlane() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
