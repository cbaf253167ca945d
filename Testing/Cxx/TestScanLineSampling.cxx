// Scan-line sampling (issues 5, 7, 6): points 6 to 25 times denser along lines than across
// them, so that the K nearest neighbours of every point lie on its own line. The filters get the
// nearest points of the lines beside it and the sampling's anisotropy (its stretch) through
// pcs::AddOffLineNeighbors. Properties known by construction, measured with
// vtkReconstructionQuality:
// - a wavy sheet sampled on lines y = const: one manifold, oriented component with one boundary
//   loop (a disk: Euler characteristic 1), every point used, and every triangle between two
//   adjacent lines (none skips a line, none on one line: 2 (N - 1) triangles per strip of two
//   lines of N points). vtkLocalOptimumGrowth on z = 2 sin(x / 7) cos(y / 5), 10 lines y = 0..9,
//   a point every 0.08 along x (500 per line, 12.5 times closer); vtkGreedySurfaceTriangulation
//   and vtkCDTAdvancingFront on z = 0.1 sin(3 x), 16 lines 0.1 apart, 6 and 20 times closer along
//   them (150 and 500 per line);
// - a unit sphere sampled on 20 latitude circles (theta from 0.05 to pi - 0.05, 0.157 apart) of
//   800 sin(theta) + 3 points each (0.0079 apart, 20 times closer), and on 40 circles (0.078
//   apart) of 500 sin(theta) + 3 points (0.0126 apart, 6.2 times closer: the K nearest reach the
//   next circle, the K / 2 nearest do not): closed, manifold, oriented, genus 0, 2V - 4
//   triangles, every point used (vtkLocalOptimumGrowth, vtkGreedySurfaceTriangulation,
//   vtkCDTAdvancingFront); with CDT, every triangle between two adjacent circles but the caps
//   inside the first and the last circle (c - 2 triangles each). (The greedy filter fills the
//   caps in step 6, from the second circle where step 2 lost points of the first: a few more
//   triangles of one circle there.)
// Before pcs::AddOffLineNeighbors every triangle of LOG's sheet and of the first sphere was
// alone (three points of one line); the second sphere had 149 components. The greedy filter made
// 3 to 1,143 triangles of the sheets and the spheres, most of their points unused, before it
// measured its edges in the sampling's metric (issue 7); vtkCDTAdvancingFront made only
// triangles of three points of one line (its search radius came from the spacing along the
// lines), in hundreds of components (issue 6).
#include "vtkCDTAdvancingFront.h"
#include "vtkGreedySurfaceTriangulation.h"
#include "vtkLocalOptimumGrowth.h"
#include "vtkReconstructionQuality.h"

#include "pcsTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMath.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace
{
// The field data of vtkReconstructionQuality on a mesh, measured once.
class Measures
{
public:
  explicit Measures(vtkPolyData* mesh)
  {
    vtkNew<vtkReconstructionQuality> quality;
    quality->SetInputData(mesh);
    quality->Update();
    this->Fields->ShallowCopy(quality->GetOutput()->GetFieldData());
  }

  double operator()(const char* name) const
  {
    vtkDataArray* array = this->Fields->GetArray(name);
    return array ? array->GetTuple1(0) : std::numeric_limits<double>::quiet_NaN();
  }

private:
  vtkNew<vtkFieldData> Fields;
};

bool CheckManifold(const Measures& field, const std::string& what)
{
  PCS_CHECK(field("NumberOfNonManifoldEdges") == 0 && field("NumberOfNonManifoldVertices") == 0,
    what << ": not manifold");
  PCS_CHECK(field("OrientationConsistency") == 1.0, what << ": not oriented");
  PCS_CHECK(field("NumberOfConnectedComponents") == 1,
    what << ": " << field("NumberOfConnectedComponents") << " components, expected 1");
  PCS_CHECK(field("NumberOfDegenerateTriangles") == 0, what << ": degenerate triangles");
  return true;
}

// The samples of `lines` lines y = spacing * line, `perLine` points `along` apart on each,
// z = height(x, y); the points of line l are ids l * perLine .. (l + 1) * perLine - 1.
template<typename Height>
std::vector<double> LineSheet(int lines, int perLine, double spacing, double along, Height height)
{
  std::vector<double> xyz;
  for (int line = 0; line < lines; ++line)
  {
    for (int j = 0; j < perLine; ++j)
    {
      const double x = along * j, y = spacing * line;
      xyz.insert(xyz.end(), { x, y, height(x, y) });
    }
  }
  return xyz;
}

// A unit sphere on `circles` latitude circles of perCircle sin(theta) + 3 points; `circle` gets
// the circle of each point.
std::vector<double> LatitudeSphere(int circles, int perCircle, std::vector<int>& circle)
{
  std::vector<double> xyz;
  circle.clear();
  for (int i = 0; i < circles; ++i)
  {
    const double theta = 0.05 + (vtkMath::Pi() - 0.1) * i / (circles - 1);
    const int count = static_cast<int>(perCircle * std::sin(theta)) + 3;
    circle.insert(circle.end(), count, i);
    for (int j = 0; j < count; ++j)
    {
      const double phi = 2.0 * vtkMath::Pi() * j / count;
      xyz.insert(xyz.end(),
        { std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta) });
    }
  }
  return xyz;
}

// The mesh of a line sheet (LineSheet) is the strip triangulation of its lines: one disk, every
// point used, every triangle between two adjacent lines with one edge on a line.
bool CheckLineSheet(vtkPolyData* mesh,
  vtkIdType unused,
  int lines,
  int perLine,
  const std::string& what)
{
  const Measures field(mesh);
  if (!CheckManifold(field, what))
  {
    return false;
  }
  PCS_CHECK(field("NumberOfBoundaryLoops") == 1 && field("EulerCharacteristic") == 1,
    what << ": " << field("NumberOfBoundaryLoops") << " boundary loops, Euler characteristic "
         << field("EulerCharacteristic") << ", expected one disk");
  PCS_CHECK(unused == 0, what << ": " << unused << " unused points");
  PCS_CHECK(mesh->GetNumberOfPoints() == static_cast<vtkIdType>(lines) * perLine,
    what << ": " << mesh->GetNumberOfPoints() << " points, expected no added point");
  int skipping = 0, onOneLine = 0;
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
    onOneLine += highest == lowest ? 1 : 0;
  }
  PCS_CHECK(skipping == 0 && onOneLine == 0,
    what << ": " << skipping << " triangles span more than two lines, " << onOneLine
         << " lie on one line");
  // Every triangle between two adjacent lines, each with one edge on a line: 2 (N - 1) per
  // strip between two lines.
  PCS_CHECK(field("NumberOfTriangles") == 2 * (perLine - 1) * (lines - 1),
    what << ": " << field("NumberOfTriangles") << " triangles, expected "
         << 2 * (perLine - 1) * (lines - 1));
  return true;
}

// With `strips`, also: every triangle joins two adjacent circles, except the caps inside the
// first and the last circle (c points: c - 2 triangles of that circle each).
bool CheckLatitudeSphere(vtkPolyData* mesh,
  vtkIdType unused,
  const std::vector<int>& circle,
  bool strips,
  const std::string& what)
{
  const vtkIdType points = static_cast<vtkIdType>(circle.size());
  const Measures field(mesh);
  if (!CheckManifold(field, what))
  {
    return false;
  }
  PCS_CHECK(field("NumberOfBoundaryEdges") == 0 && field("Genus") == 0,
    what << ": " << field("NumberOfBoundaryEdges") << " boundary edges, genus " << field("Genus")
         << ", expected closed genus 0");
  PCS_CHECK(mesh->GetNumberOfPoints() == points,
    what << ": " << mesh->GetNumberOfPoints() << " points, expected no added point");
  PCS_CHECK(field("NumberOfTriangles") == 2 * points - 4,
    what << ": " << field("NumberOfTriangles") << " triangles, expected " << 2 * points - 4);
  PCS_CHECK(unused == 0, what << ": " << unused << " unused points");
  if (strips)
  {
    const int last = circle.back();
    const long caps = std::count(circle.begin(), circle.end(), 0) +
      std::count(circle.begin(), circle.end(), last) - 4;
    long skipping = 0, onOneCircle = 0;
    for (const auto& t : pcstest::CellTuples<3>(mesh))
    {
      const int a = circle[t[0]], b = circle[t[1]], c = circle[t[2]];
      const int lowest = std::min({ a, b, c }), highest = std::max({ a, b, c });
      skipping += highest - lowest > 1 ? 1 : 0;
      onOneCircle += highest == lowest ? 1 : 0;
    }
    PCS_CHECK(skipping == 0 && onOneCircle == caps,
      what << ": " << skipping << " triangles span more than two circles, " << onOneCircle
           << " lie on one circle, expected the two caps' " << caps);
  }
  return true;
}

// The filter's mesh of the cloud and its count of unused points.
template<typename Filter>
vtkSmartPointer<vtkPolyData> Reconstruct(const std::vector<double>& xyz, vtkIdType& unused)
{
  vtkNew<Filter> filter;
  filter->SetInputData(pcstest::MakeCloud(xyz));
  filter->Update();
  unused = filter->GetNumberOfUnusedPoints();
  return filter->GetOutput();
}

template<typename Filter>
bool TestSheet(const std::string& what,
  int lines,
  int perLine,
  double spacing,
  double along,
  double (*height)(double, double))
{
  const std::vector<double> xyz = LineSheet(lines, perLine, spacing, along, height);
  vtkIdType unused = -1;
  vtkSmartPointer<vtkPolyData> mesh = Reconstruct<Filter>(xyz, unused);
  return CheckLineSheet(mesh, unused, lines, perLine, what);
}

template<typename Filter>
bool TestSphere(const std::string& what, int circles, int perCircle, bool strips)
{
  std::vector<int> circle;
  const std::vector<double> xyz = LatitudeSphere(circles, perCircle, circle);
  vtkIdType unused = -1;
  vtkSmartPointer<vtkPolyData> mesh = Reconstruct<Filter>(xyz, unused);
  return CheckLatitudeSphere(
    mesh, unused, circle, strips, what + " on " + std::to_string(circles) + " circles");
}

double LongWave(double x, double y)
{
  return 2.0 * std::sin(x / 7.0) * std::cos(y / 5.0);
}

double ShortWave(double x, double)
{
  return 0.1 * std::sin(3.0 * x);
}
}

int TestScanLineSampling(int, char*[])
{
  bool ok = TestSheet<vtkLocalOptimumGrowth>("LOG sheet", 10, 500, 1.0, 0.08, LongWave);
  ok = TestSphere<vtkLocalOptimumGrowth>("LOG sphere", 20, 800, false) && ok;
  ok = TestSphere<vtkLocalOptimumGrowth>("LOG sphere", 40, 500, false) && ok;
  ok =
    TestSheet<vtkGreedySurfaceTriangulation>("greedy sheet 6x", 16, 150, 0.1, 0.1 / 6, ShortWave) &&
    ok;
  ok = TestSheet<vtkGreedySurfaceTriangulation>(
         "greedy sheet 20x", 16, 500, 0.1, 0.1 / 20, ShortWave) &&
    ok;
  ok = TestSphere<vtkGreedySurfaceTriangulation>("greedy sphere", 20, 800, false) && ok;
  ok = TestSphere<vtkGreedySurfaceTriangulation>("greedy sphere", 40, 500, false) && ok;
  ok = TestSheet<vtkCDTAdvancingFront>("CDT sheet 6x", 16, 150, 0.1, 0.1 / 6, ShortWave) && ok;
  ok = TestSheet<vtkCDTAdvancingFront>("CDT sheet 20x", 16, 500, 0.1, 0.1 / 20, ShortWave) && ok;
  ok = TestSphere<vtkCDTAdvancingFront>("CDT sphere", 20, 800, true) && ok;
  ok = TestSphere<vtkCDTAdvancingFront>("CDT sphere", 40, 500, true) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
