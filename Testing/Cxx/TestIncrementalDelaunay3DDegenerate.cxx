// Degenerate inputs (cospherical grid, points on a sphere, duplicates, coplanar layers and
// collinear lines, a large offset): every distinct point is a vertex, every tetrahedron has
// positive volume, every interior facet is locally Delaunay, the boundary facets are the hull
// output (oriented outwards), V - E + F - T = 1, the volumes sum to the hull volume, and the
// result does not depend on the input order. Signs are checked with CGAL's exact predicates;
// the hull volume comes from CGAL::convex_hull_3.
#include "vtkIncrementalDelaunay3D.h"

#include "pcsCGALReference.h"
#include "pcsTestUtilities.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>

namespace
{
using pcstest::Kernel;
using pcstest::Point3;

double HullVolume(const std::vector<double>& xyz)
{
  std::vector<Point3> points;
  for (size_t i = 0; i < xyz.size() / 3; ++i)
  {
    points.push_back(pcstest::ToPoint(&xyz[3 * i]));
  }
  CGAL::Surface_mesh<Point3> hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  return CGAL::to_double(CGAL::Polygon_mesh_processing::volume(hull));
}

double SignedVolume(const double* a, const double* b, const double* c, const double* d)
{
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double w[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
           u[2] * (v[0] * w[1] - v[1] * w[0])) /
    6.0;
}

// expectedDuplicates: number of points that repeat an earlier point exactly.
bool CheckTriangulation(const std::vector<double>& xyz, vtkIdType expectedDuplicates,
  double expectedVolume, const char* label)
{
  const vtkIdType n = static_cast<vtkIdType>(xyz.size() / 3);
  auto cloud = pcstest::MakeCloud(xyz);
  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  delaunay->SetInputData(cloud);
  delaunay->Update();
  vtkUnstructuredGrid* grid = delaunay->GetTetrahedraOutput();
  vtkPolyData* surface = delaunay->GetSurfaceOutput();
  auto P = [&xyz](vtkIdType i) { return &xyz[3 * i]; };
  // Volumes relative to the first point: the subtraction is exact for clustered coordinates
  // (Sterbenz), so the volume check is not spoiled by a large offset.
  std::vector<double> shifted(xyz);
  for (size_t i = 0; i < shifted.size(); ++i)
  {
    shifted[i] -= xyz[i % 3];
  }
  auto S = [&shifted](vtkIdType i) { return &shifted[3 * i]; };

  PCS_CHECK(surface->GetNumberOfPoints() == n, label << ": all input points are passed");
  PCS_CHECK(delaunay->GetNumberOfDuplicatePoints() == expectedDuplicates,
    label << ": duplicates " << delaunay->GetNumberOfDuplicatePoints() << " expected "
          << expectedDuplicates);
  PCS_CHECK(pcstest::FieldCount(surface, "NumberOfDuplicatePoints") == expectedDuplicates,
    label << ": field data count");

  const auto tets = pcstest::CellTuples<4>(grid);
  std::vector<char> used(n, 0);
  std::map<std::array<vtkIdType, 3>, std::vector<std::pair<size_t, vtkIdType>>> facets;
  double volume = 0.0;
  for (size_t t = 0; t < tets.size(); ++t)
  {
    const auto& v = tets[t];
    for (vtkIdType id : v)
    {
      used[id] = 1;
    }
    PCS_CHECK(CGAL::orientation(pcstest::ToPoint(P(v[0])), pcstest::ToPoint(P(v[1])),
                pcstest::ToPoint(P(v[2])), pcstest::ToPoint(P(v[3]))) == CGAL::POSITIVE,
      label << ": tetrahedron " << t << " is not positively oriented");
    volume += SignedVolume(S(v[0]), S(v[1]), S(v[2]), S(v[3]));
    for (int j = 0; j < 4; ++j)
    {
      std::array<vtkIdType, 3> f;
      for (int k = 0, m = 0; k < 4; ++k)
      {
        if (k != j)
        {
          f[m++] = v[k];
        }
      }
      std::sort(f.begin(), f.end());
      facets[f].emplace_back(t, v[j]);
    }
  }

  // Every point is a vertex, or an exact duplicate of one.
  vtkDataArray* representative = surface->GetPointData()->GetArray("RepresentativeId");
  PCS_CHECK(representative, label << ": RepresentativeId array");
  vtkIdType duplicates = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const vtkIdType r = static_cast<vtkIdType>(representative->GetTuple1(i));
    PCS_CHECK(r >= 0 && r < n, label << ": representative of " << i);
    PCS_CHECK(P(r)[0] == P(i)[0] && P(r)[1] == P(i)[1] && P(r)[2] == P(i)[2],
      label << ": representative of " << i << " is not the same point");
    PCS_CHECK(used[r], label << ": point " << r << " is not a vertex");
    PCS_CHECK(r == i || !used[i], label << ": a duplicate is also a vertex");
    duplicates += r != i ? 1 : 0;
  }
  PCS_CHECK(duplicates == expectedDuplicates, label << ": duplicate count from the array");

  // Facets: interior ones locally Delaunay (exact), boundary ones exactly the hull output.
  std::set<std::array<vtkIdType, 3>> boundary;
  for (const auto& facet : facets)
  {
    const auto& sides = facet.second;
    PCS_CHECK(sides.size() == 1 || sides.size() == 2, label << ": facet in >2 tetrahedra");
    if (sides.size() == 1)
    {
      boundary.insert(facet.first);
      continue;
    }
    for (int s = 0; s < 2; ++s)
    {
      const auto& v = tets[sides[s].first];
      const vtkIdType opposite = sides[1 - s].second;
      const auto side = CGAL::side_of_oriented_sphere(pcstest::ToPoint(P(v[0])),
        pcstest::ToPoint(P(v[1])), pcstest::ToPoint(P(v[2])), pcstest::ToPoint(P(v[3])),
        pcstest::ToPoint(P(opposite)));
      PCS_CHECK(side != CGAL::ON_POSITIVE_SIDE,
        label << ": facet not locally Delaunay (tetrahedron " << sides[s].first << ")");
    }
  }
  std::set<std::array<vtkIdType, 3>> hull;
  for (const auto& t : pcstest::CellTuples<3>(surface))
  {
    std::array<vtkIdType, 3> s = t;
    std::sort(s.begin(), s.end());
    hull.insert(s);
    // Outward: the tetrahedron behind the hull triangle is on its negative side.
    auto it = facets.find(s);
    PCS_CHECK(it != facets.end() && it->second.size() == 1, label << ": hull facet");
    PCS_CHECK(CGAL::orientation(pcstest::ToPoint(P(t[0])), pcstest::ToPoint(P(t[1])),
                pcstest::ToPoint(P(t[2])), pcstest::ToPoint(P(it->second[0].second))) ==
        CGAL::NEGATIVE,
      label << ": hull triangle not oriented outwards");
  }
  PCS_CHECK(hull == boundary, label << ": boundary facets differ from the hull output");

  // Euler characteristic of a triangulated ball: V - E + F - T = 1.
  std::set<std::pair<vtkIdType, vtkIdType>> edges;
  for (const auto& v : tets)
  {
    for (int a = 0; a < 4; ++a)
    {
      for (int b = a + 1; b < 4; ++b)
      {
        edges.insert(std::minmax(v[a], v[b]));
      }
    }
  }
  vtkIdType vertices = 0;
  for (char u : used)
  {
    vertices += u;
  }
  const long long euler = static_cast<long long>(vertices) - static_cast<long long>(edges.size()) +
    static_cast<long long>(facets.size()) - static_cast<long long>(tets.size());
  PCS_CHECK(euler == 1, label << ": Euler characteristic " << euler);

  const double hullVolume = expectedVolume > 0 ? expectedVolume : HullVolume(shifted);
  PCS_CHECK(std::fabs(volume - hullVolume) <= 1e-9 * hullVolume,
    label << ": volume " << volume << " hull " << hullVolume);
  std::cout << label << ": " << n << " points, " << tets.size() << " tetrahedra, "
            << hull.size() << " hull triangles, volume " << volume << " (hull " << hullVolume
            << ")" << std::endl;
  return true;
}
// The header promises an output independent of the insertion order: cospherical ties are
// broken by a perturbation that depends on the points only. A permuted input (which changes the
// insertion order) must give the same tetrahedra and hull, up to the renumbering.
bool CheckOrderIndependence(const std::vector<double>& xyz, unsigned seed, const char* label)
{
  const size_t n = xyz.size() / 3;
  std::vector<vtkIdType> permutation(n);
  for (size_t i = 0; i < n; ++i)
  {
    permutation[i] = static_cast<vtkIdType>(i);
  }
  std::shuffle(permutation.begin(), permutation.end(), std::mt19937_64(seed));
  std::vector<double> permuted(xyz.size());
  for (size_t i = 0; i < n; ++i)
  {
    std::copy(&xyz[3 * permutation[i]], &xyz[3 * permutation[i]] + 3, &permuted[3 * i]);
  }
  auto Run = [](const std::vector<double>& points, const std::vector<vtkIdType>* map,
               std::set<std::array<vtkIdType, 4>>& tets, std::set<std::array<vtkIdType, 3>>& hull) {
    vtkNew<vtkIncrementalDelaunay3D> delaunay;
    delaunay->SetInputData(pcstest::MakeCloud(points));
    delaunay->Update();
    for (auto t : pcstest::CellTuples<4>(delaunay->GetTetrahedraOutput()))
    {
      for (vtkIdType& id : t)
      {
        id = map ? (*map)[id] : id;
      }
      std::sort(t.begin(), t.end());
      tets.insert(t);
    }
    for (auto t : pcstest::CellTuples<3>(delaunay->GetSurfaceOutput()))
    {
      for (vtkIdType& id : t)
      {
        id = map ? (*map)[id] : id;
      }
      std::sort(t.begin(), t.end());
      hull.insert(t);
    }
  };
  std::set<std::array<vtkIdType, 4>> tets, permutedTets;
  std::set<std::array<vtkIdType, 3>> hull, permutedHull;
  Run(xyz, nullptr, tets, hull);
  Run(permuted, &permutation, permutedTets, permutedHull);
  PCS_CHECK(!tets.empty(), label << ": tetrahedra");
  PCS_CHECK(tets == permutedTets, label << ": the tetrahedra depend on the input order");
  PCS_CHECK(hull == permutedHull, label << ": the hull depends on the input order");
  return true;
}
} // namespace

int TestIncrementalDelaunay3DDegenerate(int, char*[])
{
  bool ok = true;
  std::mt19937_64 rng(42);

  { // 12 x 12 x 12 integer grid: every cube has 8 cospherical corners.
    std::vector<double> xyz;
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j)
        for (int k = 0; k < 12; ++k)
        {
          xyz.insert(xyz.end(), { double(i), double(j), double(k) });
        }
    ok = CheckTriangulation(xyz, 0, 11.0 * 11.0 * 11.0, "grid 12^3") && ok;
    ok = CheckOrderIndependence(xyz, 1, "grid 12^3 permuted") && ok;
  }
  { // 2000 points on the unit sphere (cospherical up to rounding) and its centre.
    std::normal_distribution<double> g;
    std::vector<double> xyz;
    for (int i = 0; i < 2000; ++i)
    {
      double p[3] = { g(rng), g(rng), g(rng) };
      const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      xyz.insert(xyz.end(), { p[0] / r, p[1] / r, p[2] / r });
    }
    xyz.insert(xyz.end(), { 0.0, 0.0, 0.0 });
    ok = CheckTriangulation(xyz, 0, 0, "sphere 2000") && ok;
    ok = CheckOrderIndependence(xyz, 2, "sphere 2000 permuted") && ok;
  }
  { // 5000 random points and 500 exact duplicates of some of them, shuffled.
    std::vector<double> base = pcstest::UniformCube(5000, 3);
    std::vector<std::array<double, 3>> points;
    for (int i = 0; i < 5000; ++i)
    {
      points.push_back({ base[3 * i], base[3 * i + 1], base[3 * i + 2] });
    }
    std::uniform_int_distribution<int> pick(0, 4999);
    std::set<int> chosen;
    while (chosen.size() < 500)
    {
      chosen.insert(pick(rng));
    }
    for (int i : chosen)
    {
      points.push_back(points[i]);
    }
    std::shuffle(points.begin(), points.end(), rng);
    std::vector<double> xyz;
    for (const auto& p : points)
    {
      xyz.insert(xyz.end(), p.begin(), p.end());
    }
    ok = CheckTriangulation(xyz, 500, 0, "duplicates 10%") && ok;
  }
  { // Five coplanar layers of random points, plus collinear points along an edge.
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> xyz;
    for (int layer = 0; layer < 5; ++layer)
    {
      for (int i = 0; i < 300; ++i)
      {
        xyz.insert(xyz.end(), { u(rng), u(rng), 0.25 * layer });
      }
    }
    for (int i = 0; i <= 20; ++i)
    {
      xyz.insert(xyz.end(), { 0.05 * i, 0.0, 0.0 });          // on an edge of the hull
      xyz.insert(xyz.end(), { 0.25, 0.025 * i + 0.25, 0.5 }); // inside a layer
      xyz.insert(xyz.end(), { 0.5, 0.5, 0.05 * i });          // across all layers
    }
    ok = CheckTriangulation(xyz, 0, 0, "coplanar layers and lines") && ok;
    ok = CheckOrderIndependence(xyz, 3, "coplanar layers and lines permuted") && ok;
  }
  { // Large offset, tiny extent: the floating-point filter fails often, exact arithmetic decides.
    std::uniform_real_distribution<double> u(0.0, 1e-3);
    std::vector<double> xyz;
    for (int i = 0; i < 2000; ++i)
    {
      xyz.insert(xyz.end(), { 1e6 + u(rng), -1e6 + u(rng), 1e6 + u(rng) });
    }
    ok = CheckTriangulation(xyz, 0, 0, "offset 1e6") && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
