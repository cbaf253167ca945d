// Standalone test of pcs::Delaunay3D::RenumberByInsertion (Filters/Kernel/pcsDelaunay3D.h), the
// renumbering vtkPerimeterPeelSurface peels on. Every expectation is known by construction: the
// renumbered triangulation is the same one (the same cells, each with its vertices in the same
// order once mapped back to point ids, the same neighbours across the same facets), its vertex
// ids are 0..n-1 and map to distinct point ids, and its cells are sorted by their newest vertex.
// Clouds: random points in a cube (some ids left out, some exact duplicates) and points on a
// sphere (all on the hull: many near-cospherical cells).
#include "pcsDelaunay3D.h"
#include "pcsKernelTest.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <vector>

namespace
{
using Cell = std::array<int32_t, 4>;

// Cell c's vertices as point ids (Infinite kept), through pointOfVertex when given.
Cell PointsOf(const pcs::Delaunay3D& dt, int64_t c, const std::vector<int32_t>* pointOfVertex)
{
  Cell cell;
  for (int k = 0; k < 4; ++k)
  {
    const int32_t v = dt.Vertex(c, k);
    cell[k] = v >= 0 && pointOfVertex ? (*pointOfVertex)[v] : v;
  }
  return cell;
}

// Each cell (point ids, slot order kept) with its four neighbours (point ids).
std::map<Cell, std::array<Cell, 4>> Cells(const pcs::Delaunay3D& dt,
  const std::vector<int32_t>* pointOfVertex)
{
  std::map<Cell, std::array<Cell, 4>> cells;
  for (int64_t c = 0; c < dt.GetNumberOfCells(); ++c)
  {
    std::array<Cell, 4> neighbors;
    for (int j = 0; j < 4; ++j)
    {
      neighbors[j] = PointsOf(dt, dt.Neighbor(c, j), pointOfVertex);
    }
    cells[PointsOf(dt, c, pointOfVertex)] = neighbors;
  }
  return cells;
}

void Check(const char* name, const std::vector<double>& xyz, const std::vector<int32_t>& ids)
{
  pcs::Delaunay3D dt;
  dt.SetKeepInsertionOrder(true);
  EXPECT(dt.Triangulate(xyz.data(), ids), name);
  const auto before = Cells(dt, nullptr);
  const int64_t finite = dt.GetNumberOfFiniteCells();
  const std::vector<int32_t> pointOfVertex = dt.RenumberByInsertion();

  // The insertion order: a permutation of `ids` (duplicates included; no cell has them).
  std::vector<int32_t> points = pointOfVertex;
  std::sort(points.begin(), points.end());
  std::vector<int32_t> sortedIds = ids;
  std::sort(sortedIds.begin(), sortedIds.end());
  EXPECT(points == sortedIds, name);

  // The same cells and neighbours; vertex ids in range; cells sorted by their newest vertex;
  // each neighbour link mirrored.
  EXPECT(Cells(dt, &pointOfVertex) == before, name);
  EXPECT(dt.GetNumberOfFiniteCells() == finite, name);
  int32_t newest = 0;
  bool sorted = true, inRange = true, mirrored = true;
  for (int64_t c = 0; c < dt.GetNumberOfCells(); ++c)
  {
    int32_t cellNewest = 0;
    for (int k = 0; k < 4; ++k)
    {
      const int32_t v = dt.Vertex(c, k);
      inRange =
        inRange && v >= pcs::Delaunay3D::Infinite && v < static_cast<int32_t>(pointOfVertex.size());
      cellNewest = std::max(cellNewest, v);
      const int64_t n = dt.Neighbor(c, k);
      mirrored = mirrored && dt.Neighbor(n, dt.MirrorIndex(c, k)) == c;
    }
    sorted = sorted && cellNewest >= newest;
    newest = cellNewest;
  }
  EXPECT(inRange, name);
  EXPECT(sorted, name);
  EXPECT(mirrored, name);

  // Without SetKeepInsertionOrder nothing is kept: an empty order, cells untouched.
  pcs::Delaunay3D plain;
  plain.Triangulate(xyz.data(), ids);
  const auto plainCells = Cells(plain, nullptr);
  EXPECT(plain.RenumberByInsertion().empty(), name);
  EXPECT(Cells(plain, nullptr) == plainCells, name);
}
} // namespace

int main()
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::normal_distribution<double> normal;

  // 5,000 points in a cube, 200 of them exact copies of others, every tenth id left out.
  std::vector<double> cube;
  for (int i = 0; i < 5000; ++i)
  {
    if (i % 25 == 24)
    {
      const size_t copied = 3 * static_cast<size_t>(random() % (cube.size() / 3));
      cube.insert(cube.end(), { cube[copied], cube[copied + 1], cube[copied + 2] });
      continue;
    }
    cube.insert(cube.end(), { uniform(random), uniform(random), uniform(random) });
  }
  std::vector<int32_t> ids;
  for (int32_t i = 0; i < 5000; ++i)
  {
    if (i % 10 != 3)
    {
      ids.push_back(i);
    }
  }
  Check("cube", cube, ids);

  // 3,000 points on the unit sphere.
  std::vector<double> sphere;
  for (int i = 0; i < 3000; ++i)
  {
    double p[3] = { normal(random), normal(random), normal(random) };
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    sphere.insert(sphere.end(), { p[0] / r, p[1] / r, p[2] / r });
  }
  std::vector<int32_t> all(3000);
  for (int32_t i = 0; i < 3000; ++i)
  {
    all[i] = i;
  }
  Check("sphere", sphere, all);

  if (pcstest::Failures > 0)
  {
    std::cerr << pcstest::Failures << " failure(s)" << std::endl;
    return 1;
  }
  std::cout << "TestDelaunay3DRenumber: all passed (" << pcstest::Checks << " checks)" << std::endl;
  return 0;
}
