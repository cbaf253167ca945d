// Scan-line sampling (issues 5, 7, 6): points 12.5 to 25 times denser along lines than across
// them, so that the K = 20 nearest neighbours of every point lie on its own line. The filters
// get the nearest points of the lines beside it through pcs::AddOffLineNeighbors. Properties
// known by construction, measured with vtkReconstructionQuality:
// - vtkLocalOptimumGrowth on a wavy sheet z = 2 sin(x / 7) cos(y / 5) sampled on 10 lines
//   y = 0..9, a point every 0.08 along x (500 per line): one manifold, oriented component with one
//   boundary loop (a disk: Euler characteristic 1), every point used, and every triangle between
//   two adjacent lines (none skips a line, none on one line: 2 x 499 triangles per strip);
// - vtkLocalOptimumGrowth on a unit sphere sampled on 20 latitude circles (theta from 0.05 to
//   pi - 0.05, 0.157 apart) of 800 sin(theta) + 3 points each (0.0079 apart, 20 times closer),
//   and on 40 circles (0.078 apart) of 500 sin(theta) + 3 points (0.0126 apart, 6.2 times closer:
//   the K nearest reach the next circle, the K / 2 nearest do not): closed, manifold, oriented,
//   genus 0, 2V - 4 triangles, every point used.
// Before pcs::AddOffLineNeighbors every triangle of the sheet and of the first sphere was alone
// (three points of one line); the second sphere had 149 components.
#include "vtkLocalOptimumGrowth.h"
#include "vtkReconstructionQuality.h"

#include "pcsTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkMath.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace
{
double Field(vtkPolyData* mesh, const char* name)
{
  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputData(mesh);
  quality->Update();
  vtkDataArray* array = quality->GetOutput()->GetFieldData()->GetArray(name);
  return array ? array->GetTuple1(0) : std::numeric_limits<double>::quiet_NaN();
}

bool CheckManifold(vtkPolyData* mesh, const std::string& what)
{
  PCS_CHECK(
    Field(mesh, "NumberOfNonManifoldEdges") == 0 && Field(mesh, "NumberOfNonManifoldVertices") == 0,
    what << ": not manifold");
  PCS_CHECK(Field(mesh, "OrientationConsistency") == 1.0, what << ": not oriented");
  PCS_CHECK(Field(mesh, "NumberOfConnectedComponents") == 1,
    what << ": " << Field(mesh, "NumberOfConnectedComponents") << " components, expected 1");
  PCS_CHECK(Field(mesh, "NumberOfDegenerateTriangles") == 0, what << ": degenerate triangles");
  return true;
}

bool TestWavySheet()
{
  const int lines = 10, perLine = 500;
  std::vector<double> xyz;
  for (int line = 0; line < lines; ++line)
  {
    for (int j = 0; j < perLine; ++j)
    {
      const double x = 0.08 * j, y = line;
      xyz.insert(xyz.end(), { x, y, 2.0 * std::sin(x / 7.0) * std::cos(y / 5.0) });
    }
  }
  vtkNew<vtkLocalOptimumGrowth> growth;
  growth->SetInputData(pcstest::MakeCloud(xyz));
  growth->Update();
  vtkPolyData* mesh = growth->GetOutput();
  if (!CheckManifold(mesh, "sheet"))
  {
    return false;
  }
  PCS_CHECK(Field(mesh, "NumberOfBoundaryLoops") == 1 && Field(mesh, "EulerCharacteristic") == 1,
    "sheet: " << Field(mesh, "NumberOfBoundaryLoops") << " boundary loops, Euler characteristic "
              << Field(mesh, "EulerCharacteristic") << ", expected one disk");
  PCS_CHECK(growth->GetNumberOfUnusedPoints() == 0,
    "sheet: " << growth->GetNumberOfUnusedPoints() << " unused points");
  int skipping = 0;
  for (const auto& t : pcstest::CellTuples<3>(mesh))
  {
    int lowest = lines, highest = -1;
    for (vtkIdType v : t)
    {
      const int line = static_cast<int>(v / perLine);
      lowest = std::min(lowest, line);
      highest = std::max(highest, line);
    }
    skipping += highest - lowest > 1 ? 1 : 0;
  }
  PCS_CHECK(skipping == 0, "sheet: " << skipping << " triangles span more than two lines");
  // Every triangle between two adjacent lines, each with one edge on a line: 2 (500 - 1) per
  // strip between two lines (a triangle of three points of one line would add one).
  PCS_CHECK(Field(mesh, "NumberOfTriangles") == 2 * (perLine - 1) * (lines - 1),
    "sheet: " << Field(mesh, "NumberOfTriangles") << " triangles, expected "
              << 2 * (perLine - 1) * (lines - 1));
  return true;
}

bool TestLatitudeSphere(int circles, int perCircle)
{
  std::vector<double> xyz;
  for (int i = 0; i < circles; ++i)
  {
    const double theta = 0.05 + (vtkMath::Pi() - 0.1) * i / (circles - 1);
    const int count = static_cast<int>(perCircle * std::sin(theta)) + 3;
    for (int j = 0; j < count; ++j)
    {
      const double phi = 2.0 * vtkMath::Pi() * j / count;
      xyz.insert(xyz.end(),
        { std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta) });
    }
  }
  const double n = static_cast<double>(xyz.size() / 3);
  vtkNew<vtkLocalOptimumGrowth> growth;
  growth->SetInputData(pcstest::MakeCloud(xyz));
  growth->Update();
  vtkPolyData* mesh = growth->GetOutput();
  if (!CheckManifold(mesh, "latitude sphere"))
  {
    return false;
  }
  PCS_CHECK(Field(mesh, "NumberOfBoundaryEdges") == 0 && Field(mesh, "Genus") == 0,
    "latitude sphere " << circles << ": " << Field(mesh, "NumberOfBoundaryEdges")
                       << " boundary edges, genus " << Field(mesh, "Genus")
                       << ", expected closed genus 0");
  PCS_CHECK(Field(mesh, "NumberOfTriangles") == 2 * n - 4,
    "latitude sphere: " << Field(mesh, "NumberOfTriangles") << " triangles, expected "
                        << 2 * n - 4);
  PCS_CHECK(growth->GetNumberOfUnusedPoints() == 0,
    "latitude sphere: " << growth->GetNumberOfUnusedPoints() << " unused points");
  return true;
}
}

int TestScanLineSampling(int, char*[])
{
  bool ok = TestWavySheet();
  ok = TestLatitudeSphere(20, 800) && ok;
  ok = TestLatitudeSphere(40, 500) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
