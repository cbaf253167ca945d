// Piles of near-coincident points (a scanner's repeated returns at one spot, jittered copies;
// pcs::FindPiles) are duplicates in vtkLocalOptimumGrowth, vtkGreedySurfaceTriangulation and
// vtkPerimeterPeelSurface, as in vtkCDTAdvancingFront: one point per pile is meshed, the others
// are unused and counted in NumberOfDuplicatePoints.
//
// The cloud: 400 Fibonacci points of the unit sphere (nearest-neighbour distances 0.155 to 0.17)
// and 9 piles at 9 of them, of 2, 8 and 600 points with extents (bounding-box diagonals) of
// 1e-7, 1e-6 and 1e-5 (each pile the sphere point and m - 1 points within that box; the largest
// extent is under 1e-4 of the gap to the rest, so each is a pile); then the same cloud with exact
// copies of pile points and of a sphere point. By construction the surface is the sphere over
// the 400 positions: every filter must give a closed, manifold, genus-0 mesh of 2 x 400 - 4
// triangles, no edge shorter than 1e-3 of the mean spacing, exactly one used point per pile, all
// other sphere points used, and NumberOfDuplicatePoints = all points - 400. Before (main
// 01a0170) the three filters meshed every pile point and the test failed for each: LOG 108
// boundary edges (143 with 6 neighbours), greedy added points to fill holes, the peel made 4,252
// triangles (3,000-3,600 of the filters' triangles had an edge under 1e-3 spacings).
// LOG with 6 neighbours and the peel with OutlierFactor 0 run the piles' own neighbour search
// (pcs::RemoveOutliersAndPiles) instead of the growth's table or the outlier rule's.
#include "vtkGreedySurfaceTriangulation.h"
#include "vtkLocalOptimumGrowth.h"
#include "vtkPerimeterPeelSurface.h"
#include "vtkReconstructionQuality.h"

#include "pcsPeelTestShapes.h"
#include "pcsTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPolyDataAlgorithm.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace
{
using namespace pcstest;

constexpr int SpherePointCount = 400;

struct PileCloud
{
  std::vector<double> XYZ;
  std::vector<std::vector<vtkIdType>> Piles; // each pile's points, its sphere point first
  std::vector<vtkIdType> ExactCopies;        // points that repeat an earlier point exactly
};

PileCloud MakePileCloud(bool exactCopies)
{
  PileCloud cloud;
  cloud.XYZ = FibonacciSphere(SpherePointCount);
  std::mt19937_64 rng(5);
  int center = 10;
  for (int m : { 2, 8, 600 })
  {
    for (double extent : { 1e-7, 1e-6, 1e-5 })
    {
      // The box [c, c + side]^3 has the diagonal `extent`.
      std::uniform_real_distribution<double> offset(0.0, extent / std::sqrt(3.0));
      std::vector<vtkIdType> pile{ center };
      for (int j = 1; j < m; ++j)
      {
        pile.push_back(static_cast<vtkIdType>(cloud.XYZ.size() / 3));
        for (int c = 0; c < 3; ++c)
        {
          cloud.XYZ.push_back(cloud.XYZ[3 * center + c] + offset(rng));
        }
      }
      cloud.Piles.push_back(pile);
      center += SpherePointCount / 10;
    }
  }
  if (exactCopies)
  {
    // A pile's sphere point, a pile's other point, a point of a 600-point pile, a sphere point in
    // no pile twice.
    for (vtkIdType original :
      { cloud.Piles[0][0], cloud.Piles[4][3], cloud.Piles[8][100], vtkIdType(5), vtkIdType(5) })
    {
      cloud.ExactCopies.push_back(static_cast<vtkIdType>(cloud.XYZ.size() / 3));
      for (int c = 0; c < 3; ++c)
      {
        cloud.XYZ.push_back(cloud.XYZ[3 * original + c]);
      }
    }
  }
  return cloud;
}

// The mean distance from a sphere point to its nearest other sphere point (brute force).
double MeanSpacing(const std::vector<double>& xyz)
{
  double sum = 0.0;
  for (int i = 0; i < SpherePointCount; ++i)
  {
    double nearest = std::numeric_limits<double>::infinity();
    for (int j = 0; j < SpherePointCount; ++j)
    {
      if (j != i)
      {
        const double dx = xyz[3 * i] - xyz[3 * j], dy = xyz[3 * i + 1] - xyz[3 * j + 1],
                     dz = xyz[3 * i + 2] - xyz[3 * j + 2];
        nearest = std::min(nearest, std::sqrt(dx * dx + dy * dy + dz * dz));
      }
    }
    sum += nearest;
  }
  return sum / SpherePointCount;
}

bool CheckPilesAreDuplicates(vtkPolyDataAlgorithm* filter,
  const std::string& label,
  const PileCloud& cloud,
  double spacing)
{
  filter->SetInputData(MakeCloud(cloud.XYZ));
  filter->Update();
  vtkPolyData* mesh = filter->GetOutput();
  const vtkIdType points = static_cast<vtkIdType>(cloud.XYZ.size() / 3);
  PCS_CHECK(mesh->GetNumberOfPoints() == points, label << ": points passed");
  PCS_CHECK(QualityValue(mesh, "NumberOfBoundaryEdges") == 0,
    label << ": " << QualityValue(mesh, "NumberOfBoundaryEdges") << " boundary edges");
  PCS_CHECK(QualityValue(mesh, "NumberOfNonManifoldEdges") == 0 &&
      QualityValue(mesh, "NumberOfNonManifoldVertices") == 0,
    label << ": manifold");
  PCS_CHECK(QualityValue(mesh, "Genus") == 0, label << ": genus 0");
  PCS_CHECK(mesh->GetNumberOfPolys() == 2 * SpherePointCount - 4,
    label << ": " << mesh->GetNumberOfPolys() << " triangles, 2V - 4 = " << 2 * SpherePointCount - 4
          << " expected");
  int shortEdges = 0;
  for (const auto& t : CellTuples<3>(mesh))
  {
    for (int k = 0; k < 3; ++k)
    {
      double p[3], q[3];
      mesh->GetPoint(t[k], p);
      mesh->GetPoint(t[(k + 1) % 3], q);
      shortEdges += std::sqrt(vtkMath::Distance2BetweenPoints(p, q)) < 1e-3 * spacing ? 1 : 0;
    }
  }
  PCS_CHECK(shortEdges == 0, label << ": " << shortEdges << " edges under 1e-3 mean spacings");
  vtkDataArray* used = mesh->GetPointData()->GetArray("Used");
  PCS_CHECK(used != nullptr, label << ": Used");
  std::vector<char> inPile(points, 0);
  for (size_t p = 0; p < cloud.Piles.size(); ++p)
  {
    int usedInPile = 0;
    for (vtkIdType id : cloud.Piles[p])
    {
      usedInPile += used->GetTuple1(id) != 0 ? 1 : 0;
      inPile[id] = 1;
    }
    PCS_CHECK(usedInPile == 1,
      label << ": " << usedInPile << " used points in pile " << p << " of " << cloud.Piles[p].size()
            << " points");
  }
  for (vtkIdType i = 0; i < SpherePointCount; ++i)
  {
    PCS_CHECK(inPile[i] || used->GetTuple1(i) != 0, label << ": sphere point " << i << " unused");
  }
  for (vtkIdType id : cloud.ExactCopies)
  {
    PCS_CHECK(used->GetTuple1(id) == 0, label << ": exact copy " << id << " used");
  }
  const vtkIdType duplicates = FieldCount(mesh, "NumberOfDuplicatePoints");
  PCS_CHECK(duplicates == points - SpherePointCount,
    label << ": " << duplicates << " duplicates reported, " << points - SpherePointCount
          << " by construction");
  PCS_CHECK(FieldCount(mesh, "NumberOfOutliers") == 0, label << ": outliers");
  std::cout << label << ": " << mesh->GetNumberOfPolys() << " triangles, " << duplicates
            << " duplicates" << std::endl;
  return true;
}
} // namespace

int TestPiles(int, char*[])
{
  bool ok = true;
  for (bool exactCopies : { false, true })
  {
    const PileCloud cloud = MakePileCloud(exactCopies);
    const double spacing = MeanSpacing(cloud.XYZ);
    const std::string suffix = exactCopies ? ", piles and exact copies" : ", piles";
    vtkNew<vtkLocalOptimumGrowth> growth;
    ok = CheckPilesAreDuplicates(growth, "LOG" + suffix, cloud, spacing) && ok;
    growth->SetNumberOfNeighbors(6);
    ok = CheckPilesAreDuplicates(growth, "LOG, 6 neighbours" + suffix, cloud, spacing) && ok;
    vtkNew<vtkGreedySurfaceTriangulation> greedy;
    ok = CheckPilesAreDuplicates(greedy, "greedy" + suffix, cloud, spacing) && ok;
    vtkNew<vtkPerimeterPeelSurface> peel;
    ok = CheckPilesAreDuplicates(peel, "peel" + suffix, cloud, spacing) && ok;
    peel->SetOutlierFactor(0.0);
    ok = CheckPilesAreDuplicates(peel, "peel, OutlierFactor 0" + suffix, cloud, spacing) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
