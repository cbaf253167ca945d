#include "vtkCDTAdvancingFront.h"

#include "pcsCoordinateScaling.h"
#include "pcsDisjointSets.h"
#include "pcsDuplicatePoints.h"
#include "pcsFieldData.h"
#include "pcsGatherInput.h"
#include "pcsHoleFilling.h"
#include "pcsNearestNeighbors.h"
#include "pcsNormalEstimation.h"
#include "pcsOutliers.h"
#include "pcsPiles.h"
#include "pcsPointInsertion.h"
#include "pcsProjectedTests.h"
#include "pcsSurfaceMesh.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkTypeInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkCDTAdvancingFront);

namespace
{
using Id = int32_t;
constexpr Id None = -1;

// Points are numbered with 32-bit ids in the kernel.
constexpr vtkIdType MaximumNumberOfPoints = std::numeric_limits<int32_t>::max() - 1;

// Why a point takes no part in the mesh.
enum PointStatus : uint8_t
{
  Usable = 0,
  NonFinite = 1, // NaN or infinite coordinates
  BadNormal = 2, // non-finite or zero-length normal
  Duplicate = 3  // same coordinates as a usable point of smaller id
};

// The `count` smallest (distance, point) pairs of `list`, sorted; the others dropped (the
// candidate budgets of Front::Seed and Front::BestThirdPoint: only what can be examined is sorted).
void SortNearest(std::vector<std::pair<double, Id>>& list, size_t count)
{
  if (list.size() > count)
  {
    std::nth_element(list.begin(), list.begin() + count, list.end());
    list.resize(count);
  }
  std::sort(list.begin(), list.end());
}

inline double Dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline double Distance2(const double* a, const double* b)
{
  const double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
  return Dot(d, d);
}

// Scan-line sampling is taken for the pattern of a region when at least this share of a point's
// nearest lie along their lines too (pcs::AddOffLineNeighbors' minimumShare). Higher than the
// greedy filter's 1/2: the line test reads the 4 nearest of the 9 of the normal estimation, which
// line up by chance far more often than 6 of 12 (at 1/2: 145 of 10^5 random samples of bunny00,
// 50 points of the noisy camel; at 0.9 none, and every point of the scan clouds still).
constexpr double ScanLineShare = 0.9;
// The neighbours of a point on its own sheet: normals within 60 degrees (the noise band's height
// fit), and on its own side (LocalPlaneProjection's planes and its decision with input normals:
// within 90 degrees, which leaves out the other side of a plate thinner than a neighbourhood).
constexpr double SameSheetNormalDot = 0.5;
constexpr double SameSideNormalDot = 0.0;
// The off-line points are searched within this many times a point's NormalSampleSize - 1-th
// neighbour distance (pcs::AddOffLineNeighbors' radiusFactor): with the default 10 points, lines
// up to about 36 spacings apart (4, its default, reaches 18: not the 20x scans).
constexpr double ScanLineRadiusFactor = 8.0;
// Rows of dense points with sparse gaps (pcs::EstimateNormals' rowLinearity, rowRadiusFactor
// and rowShare): a point whose 4 nearest (of the 9 of the normal estimation) spread along one
// curve, less than about 0.47 times as far across it as along it (linearity 0.15; the scan-line
// rule's 0.05, about 0.24, misses the rows of decimated meshes that bend with the surface), and
// so do at least half of its 9 nearest (a row, not a chance alignment of a random or noisy
// sample), has its plane fitted with its nearest points off that curve on each side (searched
// within twice the distance to its 9th nearest). Camel vertices: Hausdorff distance 2.80 ->
// 1.55 mean spacings (Benchmarks/results/cdt.md, "Rows of dense points").
constexpr double RowLinearity = 0.15;
constexpr double RowRadiusFactor = 2.0;
constexpr double RowShare = 0.5;
// The automatic NeighborhoodRadius follows the local spacing of a point (the median nearest-point
// distance over it and its 9 nearest) where that spacing is at least this many mean spacings: a
// sparser part of the cloud. The fluctuations of a uniform random sampling stay below it (on 10^5
// uniform points of a sphere the ratio exceeds 1 at 37 % of the points, 1.5 at 2 %, 2 at 0.01 %),
// so that a uniform sample keeps the radius of the mean spacing: below it, the enlarged radius
// only admitted farther candidates where nearer ones were refused (CGAL's elephant, 10^5 random
// samples, seed 2: Hausdorff 1.71 -> 2.43 mean spacings).
constexpr double SparseSpacingRatio = 1.5;
// It follows it as well where that spacing is at most 1 / DenseSpacingRatio mean spacings: a part
// of the cloud many times denser than the rest (a small object beside a large one, a close-up
// scan within a distant one), where the radius of the mean spacing puts thousands of points in
// every ring of candidates, all examined and sorted for each front edge until the examination
// budget runs out (two spheres of 10,000 points each, one 10^3 or 10^4 times smaller: 219-243
// boundary edges and 107-112 unused points on the small one, in 2.8-3.2 s). Not lower: the dense
// details of decimated meshes connect to sparse points beyond a reduced radius (with 16, the camel
// vertex set 56 -> 62 boundary edges, man 404 -> 420); with 64 only ALSTOM_TEST4 and mpi of the
// 137 CGAL vertex sets have points that dense.
constexpr double DenseSpacingRatio = 64.0;
// The automatic MaximumRayDistance of a triangle whose three vertices have local spacings (as
// above) of at least this many mean spacings also reaches the surface under it: the height over
// its plane of the vertices' tangent planes across it (its reach times the sine of the largest
// angle between a vertex normal and its normal; on a sphere about twice the sagitta of the
// triangle). With only twice the mean spacing, the large triangles of the sparse part of a cloud
// whose density varies by 10^3-10^4 (spacings 30-100 times apart) did not see the points and
// edges under them: overlapping triangles, holes and handles (a sphere closed with genus 1-3).
// At 2, above the fluctuations of a uniform random sampling (0.01 % of its points), a flat part
// keeps its bound (its normals are those of its triangles); at 1.5 more clean clouds changed
// (CGAL's spool vertex set: Hausdorff distance 8.05 -> 8.50 mean spacings).
constexpr double CurvedRaySpacingRatio = 2.0;
// Fans across a concave rim (ours; III.B only). Where the front runs along the rim of a real
// hole, the valid candidate nearest to a front edge's midpoint is the next point along the rim,
// across the hole: the triangle's new edge from the far end of the front edge is longer than the
// edge, it becomes a front edge itself, and the next triangle repeats it, so that one vertex fans
// out to a run of rim points with edges growing to the neighbourhood radius and beyond (a 60 x 60
// grid with a hole of radius 10: 14 slivers over the hole with edges up to 9 spacings, which the
// hole filling then extended into a lid with edges of 20 spacings). A front edge longer than this
// many local spacings (the median nearest-point distance over the point and its 9 nearest, the
// largest of the three vertices') takes no candidate that makes a longer new edge in a triangle
// with an angle below 15 degrees: the fan stops after its first triangle (RefuseRimFans, off by
// default: on clean random samples it left small holes, Benchmarks/results/cdt.md).
constexpr double FanEdgeSpacingRatio = 2.0;

// The squared distance between points a and b of `xyz` in the scan-line sampling's metric
// (pcs::StretchedLength2; `stretch` 3 values per point).
inline double StretchedDistance2(const std::vector<double>& stretch,
  const double* xyz,
  vtkIdType a,
  vtkIdType b)
{
  const double* pa = xyz + 3 * static_cast<size_t>(a);
  const double* pb = xyz + 3 * static_cast<size_t>(b);
  const double w[3] = { pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2] };
  return pcs::StretchedLength2(
    w, &stretch[3 * static_cast<size_t>(a)], &stretch[3 * static_cast<size_t>(b)]);
}

// Squared distance from x to the segment a b.
inline double SegmentDistance2(const double* a, const double* b, const double* x)
{
  const double ab[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double ax[3] = { x[0] - a[0], x[1] - a[1], x[2] - a[2] };
  const double length2 = Dot(ab, ab);
  double s = length2 > 0.0 ? Dot(ax, ab) / length2 : 0.0;
  // Clamped to [0, 1] without a branch (maxsd, minsd): with constant bounds GCC branches on the
  // lower one, and the projection tests' segments fall on either side at random. (zero and one
  // are 0 and 1 for a finite length2, as for the finite points and projections tested here.)
  const double zero = 0.0 * length2, one = zero + 1.0;
  s = s > zero ? s : zero;
  s = s < one ? s : one;
  const double d[3] = { ax[0] - s * ab[0], ax[1] - s * ab[1], ax[2] - s * ab[2] };
  return Dot(d, d);
}

//------------------------------------------------------------------------------------------------
// Queries on the shared front/edge topology (pcs::SurfaceMesh) used by the front.

// The vertices joined to v by an edge (appended).
void GetVertexNeighbors(
  const pcs::SurfaceMesh& mesh, Id v, std::vector<int64_t>& triangles, std::vector<Id>& neighbors)
{
  const int degree = mesh.GetVertexDegree(v);
  triangles.resize(static_cast<size_t>(degree));
  mesh.GetVertexTriangles(v, triangles.data(), degree);
  const size_t first = neighbors.size();
  for (int64_t t : triangles)
  {
    const int32_t* tri = mesh.GetTriangle(t);
    for (int i = 0; i < 3; ++i)
    {
      if (tri[i] != v &&
        std::find(neighbors.begin() + first, neighbors.end(), tri[i]) == neighbors.end())
      {
        neighbors.push_back(tri[i]);
      }
    }
  }
}

// The other end point of every edge at v, each edge once (replaces `ends`): the head of the
// half-edge leaving v in each triangle at v (a half-edge has one triangle), plus the tail of each
// front edge entering v (an edge whose only triangle does not leave v through it).
void GetEdgeEnds(
  const pcs::SurfaceMesh& mesh, Id v, std::vector<int64_t>& triangles, std::vector<Id>& ends)
{
  ends.clear();
  int32_t entering[32];
  const int count = mesh.GetBoundaryInVertices(v, entering, 32);
  if (count > 32)
  {
    GetVertexNeighbors(mesh, v, triangles, ends);
    return;
  }
  const int degree = mesh.GetVertexDegree(v);
  triangles.resize(static_cast<size_t>(degree));
  mesh.GetVertexTriangles(v, triangles.data(), degree);
  for (int64_t t : triangles)
  {
    const int32_t* tri = mesh.GetTriangle(t);
    ends.push_back(tri[0] == v ? tri[1] : tri[1] == v ? tri[2] : tri[0]);
  }
  ends.insert(ends.end(), entering, entering + count);
}

// The front (boundary) half-edges at v, leaving and entering it (appended).
void GetBoundaryHalfEdges(const pcs::SurfaceMesh& mesh, Id v, std::vector<std::pair<Id, Id>>& out)
{
  int32_t ends[16];
  const int leaving = std::min(mesh.GetBoundaryOutVertices(v, ends, 16), 16);
  for (int k = 0; k < leaving; ++k)
  {
    out.emplace_back(v, ends[k]);
  }
  const int entering = std::min(mesh.GetBoundaryInVertices(v, ends, 16), 16);
  for (int k = 0; k < entering; ++k)
  {
    out.emplace_back(ends[k], v);
  }
}

// Makes every vertex manifold again once the fronts have stopped: at each vertex with more than
// one fan (where two fronts touched without merging), the triangles of all its fans but the
// largest are removed, until no vertex has more than one fan. Returns the number removed; the
// vertices of the removed triangles are appended to `touched`.
vtkIdType RemovePinches(pcs::SurfaceMesh& mesh, std::vector<Id>& touched)
{
  vtkIdType removed = 0;
  std::vector<Id> work;
  for (Id v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    if (mesh.GetNumberOfFans(v) > 1)
    {
      work.push_back(v);
    }
  }
  std::vector<int64_t> triangles;
  std::vector<int> fan;
  while (!work.empty())
  {
    const Id v = work.back();
    work.pop_back();
    if (mesh.GetNumberOfFans(v) < 2)
    {
      continue;
    }
    // The fans: triangles (v, x, y) and (v, y, z) are linked through the edge v y.
    const int degree = mesh.GetVertexDegree(v);
    triangles.resize(static_cast<size_t>(degree));
    mesh.GetVertexTriangles(v, triangles.data(), degree);
    fan.assign(triangles.size(), -1);
    auto wedge = [&](int64_t t, Id& out, Id& in)
    {
      const int32_t* tri = mesh.GetTriangle(t);
      const int i = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
      out = tri[(i + 1) % 3];
      in = tri[(i + 2) % 3];
    };
    int fans = 0;
    for (size_t k = 0; k < triangles.size(); ++k)
    {
      if (fan[k] >= 0)
      {
        continue;
      }
      fan[k] = fans;
      for (bool grown = true; grown;)
      {
        grown = false;
        for (size_t i = 0; i < triangles.size(); ++i)
        {
          if (fan[i] != fans)
          {
            continue;
          }
          Id out, in;
          wedge(triangles[i], out, in);
          for (size_t j = 0; j < triangles.size(); ++j)
          {
            Id out2, in2;
            wedge(triangles[j], out2, in2);
            if (fan[j] < 0 && (out2 == in || in2 == out))
            {
              fan[j] = fans;
              grown = true;
            }
          }
        }
      }
      ++fans;
    }
    std::vector<int> size(static_cast<size_t>(fans), 0);
    for (int f : fan)
    {
      ++size[f];
    }
    const int largest = static_cast<int>(std::max_element(size.begin(), size.end()) - size.begin());
    for (size_t k = 0; k < triangles.size(); ++k)
    {
      if (fan[k] != largest)
      {
        const int32_t* tri = mesh.GetTriangle(triangles[k]);
        const Id vertices[3] = { tri[0], tri[1], tri[2] };
        mesh.RemoveTriangle(triangles[k]);
        ++removed;
        work.insert(work.end(), vertices, vertices + 3);
        touched.insert(touched.end(), vertices, vertices + 3);
      }
    }
  }
  return removed;
}

// The ids of the points within `radius` of x (in no particular order) filed in `bins`
// (pcs::PointBins; the front makes two such queries per candidate triangle, which made
// vtkStaticPointLocator::FindPointsWithinRadius more than 40 % of the filter's time).
void FindPointsWithinRadius(const pcs::PointBins& bins,
  double radius,
  const double* x,
  std::vector<Id>& result)
{
  result.clear();
  bins.ForEachPointWithinRadius(radius,
    x,
    [&result](Id id, double)
    {
      result.push_back(id);
      return true;
    });
}

// The bound on the work of the front (Front::Work: points gathered and mesh edges listed for the
// candidates and the projection tests, over seeds, III.B and III.C): MaximumWorkPerPoint per
// usable point, and at least MinimumWork (a small cloud's balls reach across much of it, so its
// work per point is larger). A sampled surface takes 160-3,300 per point at 5,000 points and
// more (the 10^5 sphere 162, CGAL's noisy sphere_20k 3,205), up to 10,054 on smaller clouds (CGAL's
// circles, 1,101 points: 11 million); a volume has several times as many points in each ball and
// took 22,558 per point on the 18^3 lattice, and its front ran away on the 30^3 lattice (310 s).
constexpr double MaximumWorkPerPoint = 10000.0;

// The nearest others of a point for its local spacing (the automatic NeighborhoodRadius and
// MaximumRayDistance) and its noise band; also the width of the table the outlier rule reads
// when the normals are given.
constexpr int LocalSpacingNeighbors = 9;
constexpr double MinimumWork = 5e7;

// Piles of near-coincident points (a scanner's repeated returns at one spot, points merged from
// overlapping scans) are copies of one sample point, like exact duplicates: pcs::FindPiles, the
// definition shared with the far-outlier rule (a group whose extent is under pcs::PileRatio times
// its distance to the rest of the cloud). A pile is a blob at a scale the sampling cannot
// resolve: its PCA normals are random, a triangle of its points has 1e-12 of a sample triangle's
// area, and a front inside it examines the whole pile for every edge (a cloud of piles of 1,000
// points took more than 100 times the clean surface's time; Benchmarks/results/cdt.md).
//
// Merges the groups of copies (`firstCopy`: the copy of smallest id of each point's group) that
// one pile holds. The piles are found among the `count` distinct positions `positionXYZ` (packed
// x, y, z) on their table `table` (`others` nearest per position, nearest first; searched again
// on `bins`, filed from exactly these positions, when narrower than pcs::PileNeighbors): position
// d is the group of first copy `positionIds[d]` (increasing), or point d itself when
// `positionIds` is empty (no exact duplicates). Returns whether some groups were merged.
bool MergePiles(const double* positionXYZ,
  Id count,
  const std::vector<Id>& positionIds,
  const pcs::PointBins& bins,
  const std::vector<int32_t>& table,
  int others,
  std::vector<Id>& firstCopy)
{
  std::vector<int32_t> widerTable;
  if (others < pcs::PileNeighbors)
  {
    if (count <= pcs::PileNeighbors ||
      !pcs::FindNearestNeighbors(
        bins, positionXYZ, static_cast<int32_t>(count), pcs::PileNeighbors, widerTable))
    {
      return false;
    }
  }
  const std::vector<int32_t>& piles = others < pcs::PileNeighbors ? widerTable : table;
  const int width = others < pcs::PileNeighbors ? pcs::PileNeighbors : others;
  std::vector<int32_t> groupOf, firstOf;
  if (pcs::FindPiles(positionXYZ, static_cast<int32_t>(count), piles, width, groupOf) == count ||
    pcs::FirstOfPiles(groupOf, firstOf) == 0)
  {
    return false;
  }
  // The first copy of each pile: its first position (positions in increasing id: its smallest
  // id), then each point's group replaced by its pile's.
  auto idOf = [&](Id d) { return positionIds.empty() ? d : positionIds[d]; };
  std::vector<Id> position(firstCopy.size(), None); // by first copy
  for (Id d = 0; d < count; ++d)
  {
    position[idOf(d)] = d;
  }
  for (size_t k = 0; k < firstCopy.size(); ++k)
  {
    firstCopy[k] = idOf(firstOf[position[firstCopy[k]]]);
  }
  return true;
}

//------------------------------------------------------------------------------------------------
// Where to look for the mesh edges that may cross a new triangle (rule II.D.2). An edge u w of
// length L passing within `reach` of a point x has its end point nearer to its closest point f to
// x within sqrt(reach^2 + L^2 / 4) of x (f is an end point, or x - f is perpendicular to the
// edge and the nearer end point is at most L / 2 from f along it); with one global longest
// edge that ball is large (a few long edges, typically made where the sampling is sparse, would
// make every query pay for them). This coarse grid keeps, per cell, the longest edge with an end
// point in it, so that the ball only grows where long edges are: the points themselves are then
// found by vtkStaticPointLocator. (Cells are hashed; two cells sharing a slot share the larger
// length, which only enlarges the ball.) Coarser levels of cells, each twice as wide as the one
// below and keeping the longest of its eight cells, answer the queries whose ball spans too many
// cells: a query walks down from the coarse cells only into those that may matter. (Before, such
// a query took the ball of the mesh's longest edge: on a cloud whose density varies by 10^4 the
// long edges of its sparse end put thousands of dense points in every projection test.)
class EdgeReachGrid
{
public:
  void Initialize(const double* bounds, double size)
  {
    this->Origin[0] = bounds[0];
    this->Origin[1] = bounds[2];
    this->Origin[2] = bounds[4];
    this->Size = size > 0.0 && std::isfinite(size) ? size : 1.0;
    this->Cells.clear();
    for (auto& level : this->Coarse)
    {
      level.clear();
    }
  }

  void Add(const double* p, double length)
  {
    const int64_t cell[3] = { this->Cell(p, 0), this->Cell(p, 1), this->Cell(p, 2) };
    double& longest = this->Cells[Key(cell[0], cell[1], cell[2])];
    if (!(length > longest))
    {
      return;
    }
    longest = length;
    // The coarser cells hold at least their finer cells' lengths: up until one already does.
    for (int level = 1; level <= CoarseLevels; ++level)
    {
      const int64_t key =
        Key(Coarser(cell[0], level), Coarser(cell[1], level), Coarser(cell[2], level));
      double& coarse = this->Coarse[level - 1][key];
      if (!(length > coarse))
      {
        return;
      }
      coarse = length;
    }
  }

  // The radius around x that holds at least one end point of every edge passing within `reach`
  // of x (the end point nearer to the edge's closest point to x: within sqrt(reach^2 + L^2 / 4)
  // for an edge of length L); `longest` is the longest edge of the mesh (no cell farther than
  // sqrt(reach^2 + longest^2 / 4) from x can matter; that bound itself when even the coarsest
  // level has too many cells in range).
  double Reach(const double* x, double reach, double longest) const
  {
    const double reach2 = reach * reach;
    const double extent = std::sqrt(reach2 + 0.25 * longest * longest);
    int64_t low[3], high[3];
    int64_t cells = 1;
    for (int k = 0; k < 3; ++k)
    {
      low[k] = this->Cell(x, k, -extent);
      high[k] = this->Cell(x, k, extent);
      // (Spans reach 2e15 on far-apart points: multiplied only while the product stays small.)
      const int64_t span = high[k] - low[k] + 1;
      cells = span <= 0 || span > 343 || cells > 343 ? 344 : cells * span;
    }
    // The cells within `extent`, or where they are too many, the cells of the first coarser
    // level of which it spans at most 4 per axis (then down through those that may matter).
    int level = 0;
    if (cells > 343 || cells <= 0)
    {
      for (level = 1; level <= CoarseLevels; ++level)
      {
        if (std::max({ Coarser(high[0], level) - Coarser(low[0], level),
              Coarser(high[1], level) - Coarser(low[1], level),
              Coarser(high[2], level) - Coarser(low[2], level) }) <= 3)
        {
          break;
        }
      }
      if (level > CoarseLevels)
      {
        return extent;
      }
    }
    double result = reach;
    for (int64_t i = Coarser(low[0], level); i <= Coarser(high[0], level); ++i)
    {
      for (int64_t j = Coarser(low[1], level); j <= Coarser(high[1], level); ++j)
      {
        for (int64_t k = Coarser(low[2], level); k <= Coarser(high[2], level); ++k)
        {
          this->Visit(x, reach2, level, i, j, k, result);
        }
      }
    }
    return result;
  }

private:
  // Levels above the cells (level l: cells 2^l cells wide); a query that would need a coarser
  // level than the last takes its whole ball.
  static constexpr int CoarseLevels = 40;

  // Raises `result` to the bound of the cell (i, j, k) of `level` (0: the cells), or for a coarser
  // cell to those of its cells (the same result as visiting every cell within the extent: a
  // coarse cell's length and distance bound its cells').
  void Visit(const double* x,
    double reach2,
    int level,
    int64_t i,
    int64_t j,
    int64_t k,
    double& result) const
  {
    const auto& cells = level == 0 ? this->Cells : this->Coarse[level - 1];
    const auto found = cells.find(Key(i, j, k));
    if (found == cells.end())
    {
      return;
    }
    const double bound2 = reach2 + 0.25 * found->second * found->second;
    if (bound2 <= result * result)
    {
      return;
    }
    // Distance from x to the cell's box.
    const double width = this->Size * static_cast<double>(int64_t(1) << level);
    const int64_t index[3] = { i, j, k };
    double d2 = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const double lo = this->Origin[c] + width * static_cast<double>(index[c]);
      const double gap = std::max(std::max(lo - x[c], x[c] - (lo + width)), 0.0);
      d2 += gap * gap;
    }
    if (d2 > bound2)
    {
      return;
    }
    if (level == 0)
    {
      result = std::sqrt(bound2);
      return;
    }
    for (int child = 0; child < 8; ++child)
    {
      this->Visit(x,
        reach2,
        level - 1,
        2 * i + (child & 1),
        2 * j + ((child >> 1) & 1),
        2 * k + (child >> 2),
        result);
    }
  }

  // The index of the cell of `level` holding the cell `index` (floor division by 2^level).
  static int64_t Coarser(int64_t index, int level)
  {
    return index >= 0 ? index >> level : -((-index - 1) >> level) - 1;
  }

  int64_t Cell(const double* p, int k, double shift = 0.0) const
  {
    const double c = std::floor((p[k] + shift - this->Origin[k]) / this->Size);
    return static_cast<int64_t>(std::max(-1e15, std::min(1e15, c)));
  }
  static int64_t Key(int64_t i, int64_t j, int64_t k)
  {
    // Unsigned products: the cell indices reach 1e15 (signed overflow would be undefined).
    return static_cast<int64_t>((static_cast<uint64_t>(i) * 73856093u) ^
      (static_cast<uint64_t>(j) * 19349663u) ^ (static_cast<uint64_t>(k) * 83492791u));
  }

  double Origin[3] = { 0, 0, 0 };
  double Size = 1.0;
  std::unordered_map<int64_t, double> Cells;
  std::array<std::unordered_map<int64_t, double>, CoarseLevels> Coarse;
};

//------------------------------------------------------------------------------------------------
// II.C.2 within the noise band: the band of each point, NoiseBandFactor times its height noise
// (the residual of a quadric height field over its tangent plane fitted to the point and those
// of its nearest others, in the table `neighbors`, whose normals are within 60 degrees of its
// own, pcs::QuadricHeightNoise), at most `cap` (the mean spacing); 0 for a point that is not
// usable or has no fit, and for every point when `factor` is 0 or there is no table. (With all
// the neighbours, the points along the sharp rim of a lens, normals 100 degrees apart across
// it, got a band of a mean spacing and the front left 68 boundary edges along the rim.) A band
// is computed when first asked for: the front needs those of the vertices of the triangles that
// fail II.C.2 or close a hole, and of the points and edges near those that close a hole, a
// small share of the points of most clouds (the fit of every point was 7 % of the filter's time
// on the elephant vertices).
class NoiseBands
{
public:
  NoiseBands(const double* xyz,
    const double* normals,
    const std::vector<int32_t>& neighbors,
    int others,
    const std::vector<uint8_t>& status,
    double factor,
    double cap)
    : XYZ(xyz)
    , Normals(normals)
    , Neighbors(neighbors)
    , Others(others)
    , Status(status)
    , Factor(factor)
    , Cap(cap)
    , Values(status.size(), factor > 0.0 && others > 0 ? -1.0 : 0.0)
  {
  }

  double operator[](Id i) const
  {
    double& value = this->Values[i];
    if (value < 0.0)
    {
      const double noise = this->Status[i] != Usable
        ? 0.0
        : pcs::QuadricHeightNoise(this->XYZ,
            this->Normals,
            this->XYZ + 3 * static_cast<size_t>(i),
            this->Normals + 3 * static_cast<size_t>(i),
            &this->Neighbors[static_cast<size_t>(i) * this->Others],
            this->Others,
            SameSheetNormalDot);
      value = noise > 0.0 ? std::min(this->Factor * noise, this->Cap) : 0.0;
    }
    return value;
  }

private:
  const double* XYZ;
  const double* Normals;
  const std::vector<int32_t>& Neighbors;
  int Others;
  const std::vector<uint8_t>& Status;
  double Factor;
  double Cap;
  mutable std::vector<double> Values; // -1: not computed yet
};

//------------------------------------------------------------------------------------------------
// The rules of paper 003 in one place: which triangles are valid, and the front that grows them.
struct Parameters
{
  double Radius = 0;           // II.A neighbourhood of a front edge's midpoint
  // II.A: Radius (and LongEar) scaled at each front edge by the larger radius scale of its end
  // points (Front::RadiusScale, at least 1): the automatic radius follows the local spacing
  // where the sampling is sparser than the mean.
  bool LocalRadius = false;
  double MinimumNormalDot = 0; // II.C.2
  // II.C.2 within the noise band: a vertex whose normal fails the bound passes when the other
  // vertices lie within the triangle's noise band (Front::NoiseBand) of its tangent plane.
  bool NoiseBand = false;
  double MaximumRay = 0;       // II.D
  // II.D: MaximumRay scaled at each triangle by the largest local scale of its vertices
  // (Front::Scale, at most 1).
  bool LocalRay = false;
  double MinimumArea = 0;            // II.E, when positive
  double MinimumAreaRatio = 0;       // II.E otherwise: area / (longest edge)^2
  int MaximumCandidates = 0;         // candidates submitted to the II.D tests per edge
  bool CloseTriangularHoles = false; // III.C: a 3-edge hole closes without II.C.2
  // III.C: II.C.1 is not required of a triangle whose two edges at its third vertex are at most
  // LongEar long.
  bool ShortTrianglesSkipNormalAgreement = false;
  // III.C ears (a triangle with a front edge next to the edge expanded): an ear that adds an edge
  // longer than LongEar must have no angle whose cosine exceeds MaximumLongEarCos.
  double LongEar = 0;
  double MaximumLongEarCos = 1;
  // Scan lines: a triangle of three points of one line is refused (pcs::OnOneScanLine). Not in
  // hole filling, where the cap inside a closed line (a pole's circle) has only such ears.
  bool RefuseOneLineTriangles = true;
  // III.B: no fan across the rim of a hole (Front::ExtendsFan; RefuseRimFans).
  bool RefuseRimFans = false;
};

class Front
{
public:
  Front(vtkCDTAdvancingFront* self,
    const double* xyz,
    const double* normals,
    const double* scale,
    const double* radiusScale,
    const double* stretch,
    const NoiseBands& noiseBand,
    const std::vector<uint8_t>& status,
    const double bounds[6],
    const pcs::PointBins& bins,
    pcs::SurfaceMesh& mesh)
    : Self(self)
    , XYZ(xyz)
    , Normals(normals)
    , Scale(scale)
    , RadiusScale(radiusScale)
    , Stretch(stretch)
    , NoiseBand(noiseBand)
    , Status(status)
    , Bins(bins)
    , Mesh(mesh)
    , Stamp(status.size(), 0)
    , ProjectedStamp(status.size(), 0)
    , Projected(3 * status.size(), 0.0)
    , MaxIncident(status.size(), 0.0)
    , Adjacent(AdjacentCapacity * status.size(), None)
    , AdjacentCount(status.size(), 0)
    , FailedHead(status.size(), None)
    , FailedState(status.size(), 0)
    , Touched(status.size(), 0)
    , WatchStart(status.size(), -1)
    , WatchCount(status.size(), 0)
  {
    if (stretch)
    {
      this->Stretched.resize(status.size());
      for (size_t i = 0; i < status.size(); ++i)
      {
        const double* s = stretch + 3 * i;
        this->Stretched[i] = s[0] != 0.0 || s[1] != 0.0 || s[2] != 0.0 ? 1 : 0;
      }
    }
    std::copy_n(bounds, 6, this->Bounds);
    this->Diagonal = 1.01 *
        std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
          (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
          (bounds[5] - bounds[4]) * (bounds[5] - bounds[4])) +
      std::numeric_limits<double>::min();
  }

  // Cell size of the edge-reach grid (a few neighbourhood radii).
  void SetEdgeReachCellSize(double size)
  {
    this->EdgeReach.Initialize(this->Bounds, std::min(size, this->Diagonal));
  }

  // The triangles made, their origin (0 seed, 1 front, 2 hole filling).
  std::vector<uint8_t> Origin;
  vtkIdType NumberOfSeeds = 0;

  // III.A: a seed triangle from point p; false when none is valid.
  bool Seed(Id p, const Parameters& parameters);

  // III.B / III.C: expand the queued front edges until none is left.
  bool Advance(const Parameters& parameters, bool relaxed, uint8_t origin);

  // Queue the boundary half-edge a -> b (and nothing if it is not one when processed).
  void Queue(Id a, Id b) { this->Edges.emplace_back(a, b); }

  // Aborted by the user.
  bool Aborted = false;

  // Accept triangles that pinch a front vertex (see CanAdd).
  bool AllowPinches = true;

  // The mean spacing: loops shorter than 4 pi of it are holes (see KeepsGenus).
  double HoleSpacing = 0.0;
  // Per point: the median nearest-point distance over it and its 9 nearest, over HoleSpacing
  // (null: 1 everywhere). For ExtendsFan.
  const double* SpacingRatio = nullptr;

  // The work of the front: the points gathered for candidates and for the projection tests, and
  // the mesh edges listed for the projection tests. Seed and Advance stop (OutOfWork) once it
  // exceeds WorkBudget.
  uint64_t Work = 0;
  uint64_t WorkBudget = std::numeric_limits<uint64_t>::max();
  bool OutOfWork = false;

  // To call when triangles were removed (`vertices`: theirs): triangles found blocked may no
  // longer be, and the edges of the removed triangles may be gone. The edge lists (Adjacent) of
  // those vertices are listed again from the mesh; the other vertices kept all their edges (an
  // edge that is gone had both end points on a removed triangle), and a list holds more than
  // AdjacentCapacity ends (Overflow) exactly when the vertex has that many, since edges are
  // otherwise only added. (Relisting every vertex from every triangle was 1 % of the filter's
  // instructions on CGAL's elephant and camel vertex sets.)
  void TrianglesRemoved(const std::vector<Id>& vertices)
  {
    ++this->State;
    this->Blocked.Clear();
    this->ForgetWatches();
    this->PartsValid = false; // (rebuilt when next asked for)
    for (Id v : vertices)
    {
      this->AdjacentCount[v] = 0;
    }
    for (Id v : vertices)
    {
      if (this->AdjacentCount[v] != 0)
      {
        continue; // (listed already: a vertex of several removed triangles)
      }
      GetEdgeEnds(this->Mesh, v, this->VertexTriangles, this->Neighbors);
      for (Id w : this->Neighbors)
      {
        this->LinkOneWay(v, w);
      }
    }
  }

private:
  const double* P(Id i) const { return this->XYZ + 3 * static_cast<size_t>(i); }
  const double* N(Id i) const { return this->Normals + 3 * static_cast<size_t>(i); }

  // The squared distance from `centre` to point x that ranks candidates: Euclidean, and on scan
  // lines in the sampling's metric at the points a and b (pcs::StretchedLength2), in which the
  // next line's points come before the far points of the own line.
  double RankDistance2(const double* centre, Id x, Id a, Id b) const
  {
    if (!this->HasStretch(a) && !this->HasStretch(b))
    {
      return Distance2(this->P(x), centre);
    }
    const double* sa = this->Stretch + 3 * static_cast<size_t>(a);
    const double* sb = this->Stretch + 3 * static_cast<size_t>(b);
    const double* p = this->P(x);
    const double w[3] = { p[0] - centre[0], p[1] - centre[1], p[2] - centre[2] };
    return pcs::StretchedLength2(w, sa, sb);
  }

  // Is the oriented triangle (e0, e1, third) valid? (e0, e1) is the edge it is built on,
  // `opposite` the third vertex of the triangle already on that edge (None for a seed).
  bool IsValid(Id e0, Id e1, Id third, Id opposite, const Parameters& parameters);

  // The projection tests of section II.D on the triangle (e0, e1, third) with the plane `plane`:
  // true when no neighbouring point or mesh edge blocks it.
  // With `ignoreNoiseBand`, a point (or both end points of an edge) within the noise band of the
  // triangle's plane does not block it: its ray parameter t (along its normal) satisfies
  // t^2 <= b^2 + B^2, b its noise band and B the largest of the triangle's vertices'.
  bool PassesProjectionTests(Id e0,
    Id e1,
    Id third,
    const pcs::projected::TrianglePlane& plane,
    const Parameters& parameters,
    bool ignoreNoiseBand = false);

  // III.C: may the ear (e0, e1, x) be a candidate? Not when it adds an edge longer than
  // LongEar and has an angle below the minimum: a sliver along the hole. (The paper takes the
  // ears at any distance; on the 10^5-point camel samples a long slit left by the front was then
  // closed by a chain of slivers lengthwise, each ear's new edge the long side of the next one,
  // up to 115 mean spacings long and 11 mean spacings off the surface. A wide hole still closes
  // with long ears of reasonable shape: the bunny00 vertex set needs ears over 10 mean spacings
  // long, and left open its hole puts the Hausdorff distance at 6.3 mean spacings.)
  bool IsAcceptableEar(Id e0, Id e1, Id x, const Parameters& parameters) const
  {
    bool longEdge = false;
    for (Id end : { e0, e1 })
    {
      longEdge = longEdge ||
        (this->Mesh.GetEdgeValence(end, x) == 0 &&
          Distance2(this->P(end), this->P(x)) > parameters.LongEar * parameters.LongEar);
    }
    return !longEdge || this->HasNoAngleBelow(e0, e1, x, parameters.MaximumLongEarCos);
  }

  // Would the strict front's triangle (e0, e1, x) extend a fan across a concave rim: is the
  // front edge longer than FanEdgeSpacingRatio local spacings, and does the triangle add a longer
  // edge and have an angle below 15 degrees? (See FanEdgeSpacingRatio.)
  bool ExtendsFan(Id e0, Id e1, Id x, const Parameters& parameters) const
  {
    const double *a = this->P(e0), *b = this->P(e1), *c = this->P(x);
    const double edge2 = Distance2(a, b);
    const double spacing = FanEdgeSpacingRatio * this->HoleSpacing *
      (this->SpacingRatio
          ? std::max({ this->SpacingRatio[e0], this->SpacingRatio[e1], this->SpacingRatio[x] })
          : 1.0);
    return edge2 > spacing * spacing && std::max(Distance2(a, c), Distance2(b, c)) > edge2 &&
      !this->HasNoAngleBelow(e0, e1, x, parameters.MaximumLongEarCos);
  }

  // Has the triangle (e0, e1, x) no angle whose cosine exceeds maximumCos?
  bool HasNoAngleBelow(Id e0, Id e1, Id x, double maximumCos) const
  {
    const Id v[3] = { e0, e1, x };
    for (int i = 0; i < 3; ++i)
    {
      const double *a = this->P(v[i]), *b = this->P(v[(i + 1) % 3]), *c = this->P(v[(i + 2) % 3]);
      const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
      const double w[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
      const double lengths = std::sqrt(Dot(u, u) * Dot(w, w));
      if (!(Dot(u, w) <= maximumCos * lengths))
      {
        return false;
      }
    }
    return true;
  }

  // Best valid third point for the oriented edge (e0, e1) (new triangle e0, e1, x), None if none.
  Id BestThirdPoint(Id e0, Id e1, Id opposite, const Parameters& parameters, bool relaxed);

  // The points within `radius` of x. Every query centre lies in the bounding box of the points,
  // so a ball larger than its diagonal holds them all: the radius is capped there (a huge radius
  // would overflow the squared distances).
  void FindPoints(double radius, const double* x, std::vector<Id>& result)
  {
    FindPointsWithinRadius(this->Bins, std::min(radius, this->Diagonal), x, result);
  }

  // Point x projected along its normal onto the plane through `origin` with normal `normal`
  // (II.D.2), or x itself for a vertex of the triangle; null when the ray parameter exceeds
  // `maximumRay` or the line is parallel to the plane. Cached for the current triangle
  // (CurrentStamp).
  const double* Project(
    Id x, bool isVertex, const double* normal, const double* origin, double maximumRay)
  {
    if (isVertex)
    {
      return this->P(x);
    }
    double* out = &this->Projected[3 * static_cast<size_t>(x)];
    if (this->ProjectedStamp[x] != this->CurrentStamp)
    {
      this->ProjectedStamp[x] = this->CurrentStamp;
      double t;
      const double *px = this->P(x), *nx = this->N(x);
      if (!pcs::projected::RayParameter(px, nx, origin, normal, t) || std::fabs(t) > maximumRay)
      {
        out[0] = std::numeric_limits<double>::quiet_NaN();
      }
      else
      {
        for (int c = 0; c < 3; ++c)
        {
          out[c] = px[c] + t * nx[c];
        }
      }
    }
    return std::isnan(out[0]) ? nullptr : out;
  }

  // II.C.2 within the noise band: does each other vertex of the triangle v lie within the noise
  // band of the tangent plane of v[i]? The height of q over that plane is a difference of two
  // noisy heights: its band is the root sum of squares of the two points' bands.
  bool WithinNoiseBand(const Id v[3], int i) const
  {
    const double *p = this->P(v[i]), *n = this->N(v[i]);
    const double band2 = this->NoiseBand[v[i]] * this->NoiseBand[v[i]];
    for (int j = 1; j < 3; ++j)
    {
      const Id other = v[(i + j) % 3];
      const double* q = this->P(other);
      const double d[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
      const double height = Dot(n, d);
      if (!(height * height <= band2 + this->NoiseBand[other] * this->NoiseBand[other]))
      {
        return false;
      }
    }
    return true;
  }

  // PassesProjectionTests: is the end point x of an edge (a vertex of the triangle tested, or
  // a point whose ray parameter t onto its plane passes `within`) in the noise band?
  template<typename Within>
  bool EndWithinNoiseBand(Id x, bool isVertex, const double* normal, const Within& within) const
  {
    double t;
    return isVertex ||
      (pcs::projected::RayParameter(this->P(x), this->N(x), this->Projected0, normal, t) &&
        within(x, t));
  }
  const double* Projected0 = nullptr; // a point of the plane of the triangle tested

  bool CanAdd(Id a, Id b, Id c) const;
  // Add the triangle (a, b, c); `across`: the triangle across the front edge it is built on.
  int64_t Add(Id a, Id b, Id c, uint8_t origin, int64_t across = -1);

  // Handles (ours). A triangle that puts two different front loops of one edge-connected part on
  // one loop -- at a front vertex it pinches, or at a vertex where it merges two fans -- adds a
  // handle to the surface. That is how the front closes around the tube of a torus (a loop around
  // the tube meets the other one), but on genus-0 samples the front also made such triangles
  // where it met itself across a layer of noise, a second sampling of the surface or a fold of
  // wrong normals. When one of the two loops is a hole (short, as vtkLocalOptimumGrowth's step 4
  // defines it) such a triangle does not close around a tube, it jumps across the surface: it is
  // refused (KeepsGenus), and the hole is closed on its own -- unless both loops go around a tube
  // (pcs::holes::JoinsLoopsAroundTube: a loop around a thin tube is as short as a hole, and
  // refusing the join capped the tube twice). A triangle between two longer loops
  // is made: a loop around a tube shrinks as the front goes on (the caps of a tube sampled by a
  // few points around), so deferring it lost the true handles of coarse samplings.
  //
  // The edge-connected parts: a union-find over the triangle ids. A new triangle joins the part
  // across the front edge it is built on, and the parts at its joints (FindJoints); an ear's other
  // edge lies on the same loop, hence in the same part. Rebuilt when triangles are removed.
  pcs::DisjointSets<int64_t> Parts;
  bool PartsValid = true;
  void RebuildParts();
  int64_t PartOf(Id tail, Id head)
  {
    if (!this->PartsValid)
    {
      this->RebuildParts();
    }
    return this->Parts.Find(this->Mesh.FindTriangle(tail, head));
  }
  // The pairs of front half-edges that the triangle v would put on one loop: at a vertex whose two
  // edges of v are glued to two different fans of the vertex (a merge), and at a front vertex
  // that v only touches (a pinch: each fan of the vertex against a front edge v is glued to).
  struct Joint
  {
    Id Tail0, Head0, Tail1, Head1;
    bool Pinch;
  };
  std::vector<Joint> Joints;
  Id JointsOf[3] = { None, None, None }; // the triangle of Joints (State JointsState)
  uint64_t JointsState = 0;
  void FindJoints(const Id v[3]);
  // Are the front half-edges a->b and c->d on two loops (the walk NextBoundaryVertex, which
  // turns around a vertex through one fan), one of them short: at most HoleEdges edges, or
  // shorter than 4 pi HoleSpacing (the loop around a tube of radius below 2 spacings, which no
  // rule tells from a hole; vtkLocalOptimumGrowth's bound, its step 4, with its default
  // MaximumHoleEdges)? pcs::holes::IsShortLoop walks each loop, avoiding the other half-edge,
  // at most a short loop's length.
  static constexpr int64_t HoleEdges = 8;
  bool JoinsHole(Id a, Id b, Id c, Id d) const;
  // May the triangle (v0, v1, v2) be added: it joins no hole to another loop of its part?
  bool KeepsGenus(Id v0, Id v1, Id v2);
  void Progress();

  vtkCDTAdvancingFront* Self;
  const double* XYZ;
  const double* Normals;
  const double* Scale; // per point: its local spacing over the mean spacing, at most 1
  // Per point: its local spacing (median) over the mean where at least SparseSpacingRatio, else 1.
  const double* RadiusScale;

  // The parameters at the edge (a, b): with LocalRadius, Radius and LongEar scaled by the larger
  // radius scale of a and b.
  Parameters AtEdge(const Parameters& parameters, Id a, Id b) const
  {
    Parameters local = parameters;
    if (parameters.LocalRadius)
    {
      const double scale = std::max(this->RadiusScale[a], this->RadiusScale[b]);
      local.Radius *= scale;
      local.LongEar *= scale;
    }
    return local;
  }
  const double* Stretch; // per point: its scan-line stretch (3 values), null when none has one
  std::vector<uint8_t> Stretched; // per point: a non-zero stretch (empty when Stretch is null)
  bool HasStretch(Id i) const { return this->Stretch && this->Stretched[i]; }
  const NoiseBands& NoiseBand; // per point: the height band of its sampling noise (II.C.2)
  const std::vector<uint8_t>& Status;
  double Bounds[6]; // of the points
  const pcs::PointBins& Bins;
  double Diagonal = 0.0; // of the bounding box of the points, slightly enlarged
  pcs::SurfaceMesh& Mesh;
  std::deque<std::pair<Id, Id>> Edges;

  // Scratch.
  std::vector<Id> Near;
  // PassesProjectionTests' buffers (they only grow; each test uses a prefix): the points stamped
  // as edge end points with their squared distances to the centroid of the triangle tested, the
  // ball of that triangle, its II.D.1 candidates and the edges left for II.D.2's projections.
  std::vector<std::pair<Id, double>> StampedEnds;
  std::vector<std::pair<Id, double>> Ball;
  std::vector<Id> PointCandidates;
  std::vector<std::pair<Id, Id>> EdgeCandidates;
  std::vector<std::pair<double, Id>> Candidates;
  std::vector<std::pair<double, Id>> Pending; // BestThirdPoint on scan lines: for the next ring
  std::vector<Id> Ears;                       // BestThirdPoint in III.C: the ears of the edge
  std::vector<Id> Neighbors;
  std::vector<int64_t> VertexTriangles;
  std::vector<std::pair<Id, Id>> HalfEdges;
  std::vector<unsigned> Stamp;
  unsigned CurrentStamp = 0;
  std::vector<unsigned> ProjectedStamp; // Project's cache: its triangle's stamp, per point
  std::vector<double> Projected;        // and the projected point (NaN: none)
  double LongestEdge = 0;          // of the mesh: bounds the reach of an edge crossing a triangle
  std::vector<double> MaxIncident; // per point: its longest edge

  // The other end points of the edges at each vertex, AdjacentCapacity per vertex (AdjacentCount
  // of them used; Overflow: more, ask the mesh): read once per end point in every II.D.2 test,
  // where asking the mesh (three walks around the vertex) was a tenth of the time.
  static constexpr int AdjacentCapacity = 10;
  static constexpr uint8_t Overflow = 255;
  std::vector<Id> Adjacent;
  std::vector<uint8_t> AdjacentCount;
  void LinkOneWay(Id a, Id b)
  {
    uint8_t& count = this->AdjacentCount[a];
    if (count == Overflow)
    {
      return;
    }
    Id* list = &this->Adjacent[AdjacentCapacity * static_cast<size_t>(a)];
    bool listed = false; // (all the slots compared: no branch on where b is)
    for (int k = 0; k < AdjacentCapacity; ++k)
    {
      listed = listed | ((k < count) & (list[k] == b));
    }
    if (listed)
    {
      return;
    }
    if (count == AdjacentCapacity)
    {
      count = Overflow;
      return;
    }
    list[count++] = b;
  }
  void Link(Id a, Id b)
  {
    this->LinkOneWay(a, b);
    this->LinkOneWay(b, a);
  }
  EdgeReachGrid EdgeReach;

  // The triangles (vertex sets, sorted) found blocked by the projection tests (II.D). While the
  // mesh only gains triangles a blocked triangle stays blocked (the points, their normals and
  // MaximumRay do not change; every mesh edge that blocked it is still there, and the decision
  // does not depend on the orientation or on the edge it is built on), so a front edge tried
  // again, or a seed from another point, does not repeat the tests. Cleared when triangles are
  // removed (TrianglesRemoved).
  // (An open-addressing hash set of sorted vertex triples: one probe sequence in a flat array,
  // where std::unordered_set's node lists made the lookups a quarter of the time on noisy
  // clouds.)
  class TripleSet
  {
  public:
    bool Contains(const std::array<Id, 3>& key) const
    {
      if (this->Slots.empty())
      {
        return false;
      }
      for (size_t i = this->Slot(key);; i = (i + 1) & this->Mask)
      {
        if (Same(this->Slots[i], key))
        {
          return true;
        }
        if (this->Slots[i][0] == None)
        {
          return false;
        }
      }
    }
    void Insert(const std::array<Id, 3>& key)
    {
      if (2 * (this->Count + 1) > this->Slots.size())
      {
        this->Grow();
      }
      size_t i = this->Slot(key);
      for (; this->Slots[i][0] != None; i = (i + 1) & this->Mask)
      {
        if (Same(this->Slots[i], key))
        {
          return;
        }
      }
      this->Slots[i] = key;
      ++this->Count;
    }
    void Clear()
    {
      this->Slots.clear();
      this->Count = 0;
      this->Shift = 64;
      this->Mask = 0;
    }

  private:
    // (std::array's == compiles to a memcmp call here.)
    static bool Same(const std::array<Id, 3>& a, const std::array<Id, 3>& b)
    {
      return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
    }
    size_t Slot(const std::array<Id, 3>& t) const
    {
      const uint64_t h = (static_cast<uint64_t>(static_cast<uint32_t>(t[0])) << 32 ^
                           static_cast<uint64_t>(static_cast<uint32_t>(t[1]))) *
          0x9E3779B97F4A7C15u ^
        static_cast<uint64_t>(static_cast<uint32_t>(t[2])) * 0xC2B2AE3D27D4EB4Fu;
      return static_cast<size_t>((h * 0x9E3779B97F4A7C15u) >> this->Shift);
    }
    void Grow()
    {
      std::vector<std::array<Id, 3>> old;
      old.swap(this->Slots);
      const size_t size = std::max<size_t>(1024, 2 * old.size());
      this->Slots.assign(size, { None, None, None });
      this->Mask = size - 1;
      this->Shift = 64;
      for (size_t s = size; s > 1; s >>= 1)
      {
        --this->Shift;
      }
      this->Count = 0;
      for (const auto& key : old)
      {
        if (key[0] != None)
        {
          this->Insert(key);
        }
      }
    }
    std::vector<std::array<Id, 3>> Slots; // a power of two, at most half full
    size_t Count = 0;
    size_t Mask = 0;
    int Shift = 64;
  };
  TripleSet Blocked;
  vtkIdType Steps = 0;
  int ProjectionTests = 0; // of the current edge

  // Advance: a front edge is not examined again while nothing has changed since it found no
  // third point (BestThirdPoint is a function of the mesh, the points and the parameters: it
  // would find none again). Its last such edge per tail vertex (FailedHead) and the State then;
  // State changes with every triangle added or removed and with every Advance (parameters).
  std::vector<Id> FailedHead;
  std::vector<uint64_t> FailedState;
  uint64_t State = 1;

  // Advance, more locally: nor is a failed front edge examined again while no triangle was added
  // at the points it watches (Watched; Touched: per point, the State when a triangle was last
  // added at it): BestThirdPoint would find none again. While triangles are only added, a
  // candidate refused by a test on its own points (Status, scan lines, II.C.1, II.E, orientation,
  // II.C.3, and II.C.2 outside III.C) or by the projection tests (which only refuse more as edges
  // are added: the argument of Blocked) stays refused; a point only leaves the candidates by
  // becoming interior, which changes nothing while no budget ran out; what else may change is
  // read at the edge's ends and at the candidate: CanAdd and the pinch rule, and in III.C the
  // ears and whether the triangle closes a hole (which waives II.C.2 and may take the noise-band
  // path). So an edge watches its ends (in III.C, or once a candidate was refused otherwise) and
  // each candidate refused otherwise (IsValid's RefusedForGood false). Nothing is watched (the
  // global State rule only) when a budget ran out, a candidate took the noise-band path (its
  // exemption of meshed points is not monotone) or the list is long; the watches are forgotten
  // when triangles are removed, the parameters change or they hold more than 4 ids per point
  // (about 1 on the clean benchmark clouds at most, 16 on a noisy one).
  std::vector<uint64_t> Touched;
  std::vector<int64_t> WatchStart; // per tail vertex: its failed edge's points in Watched, or -1
  std::vector<uint16_t> WatchCount;
  std::vector<Id> Watched;
  std::vector<Id> Watch; // of the current BestThirdPoint
  bool WatchValid = false;
  bool RefusedForGood = false; // IsValid's last refusal holds while triangles are only added
  const Parameters* WatchParameters = nullptr;
  static constexpr size_t MaximumWatch = 256;
  void ForgetWatches()
  {
    this->Watched.clear();
    std::fill(this->WatchStart.begin(), this->WatchStart.end(), -1);
  }
  void WatchPoint(Id x)
  {
    if (this->WatchValid && this->Watch.size() < MaximumWatch)
    {
      this->Watch.push_back(x);
    }
    else
    {
      this->WatchValid = false;
    }
  }
  // Records the watch of the failed edge a -> b (after FailedState[a] is set).
  void RecordWatch(Id a)
  {
    this->WatchStart[a] = -1;
    if (!this->WatchValid)
    {
      return;
    }
    if (this->Watched.size() + this->Watch.size() > 4 * this->Touched.size() + 4096)
    {
      this->ForgetWatches();
    }
    this->WatchStart[a] = static_cast<int64_t>(this->Watched.size());
    this->WatchCount[a] = static_cast<uint16_t>(this->Watch.size());
    this->Watched.insert(this->Watched.end(), this->Watch.begin(), this->Watch.end());
  }
  // No triangle added at the watched points of a's failed edge since it failed.
  bool Unchanged(Id a) const
  {
    if (this->WatchStart[a] < 0)
    {
      return false;
    }
    const Id* watched = this->Watched.data() + this->WatchStart[a];
    for (int k = 0; k < this->WatchCount[a]; ++k)
    {
      if (this->Touched[watched[k]] > this->FailedState[a])
      {
        return false;
      }
    }
    return true;
  }
};

bool Front::IsValid(Id e0, Id e1, Id third, Id opposite, const Parameters& parameters)
{
  this->RefusedForGood = true;
  if (this->Status[third] != Usable ||
    // (pcs::OnOneScanLine: its first test on the flags, at least two of the points have a
    // stretch, then its edge tests.)
    (this->Stretch && parameters.RefuseOneLineTriangles &&
      this->Stretched[e0] + this->Stretched[e1] + this->Stretched[third] >= 2 &&
      pcs::EdgesAlongOneScanLine(this->XYZ, this->Stretch, e0, e1, third)))
  {
    return false;
  }
  const double *n0 = this->N(e0), *n1 = this->N(e1), *n2 = this->N(third);
  // II.C.1: the edge's end-point normals agree with the third point's.
  // (Waived in the hole-filling step when both edges at the third point are short.)
  const bool agreementWaived = parameters.ShortTrianglesSkipNormalAgreement &&
    Distance2(this->P(e0), this->P(third)) <= parameters.LongEar * parameters.LongEar &&
    Distance2(this->P(e1), this->P(third)) <= parameters.LongEar * parameters.LongEar;
  if (!agreementWaived && (Dot(n0, n2) <= 0.0 || Dot(n1, n2) <= 0.0))
  {
    return false;
  }
  // The tests on the triangle's floating-point normal come first (they reject the most
  // candidates, for a few products each), then those on the mesh and the exact ones: all must
  // pass, so their order does not change the answer.
  // II.E: area large enough.
  double normal[3];
  pcs::projected::TriangleNormal(this->P(e0), this->P(e1), this->P(third), normal);
  const double length = std::sqrt(Dot(normal, normal));
  if (!(0.5 * length >= parameters.MinimumArea) || !(length > 0.0))
  {
    return false;
  }
  if (parameters.MinimumAreaRatio > 0.0)
  {
    const double longest2 = std::max({ Distance2(this->P(e0), this->P(e1)),
      Distance2(this->P(e1), this->P(third)), Distance2(this->P(third), this->P(e0)) });
    if (!(0.5 * length >= parameters.MinimumAreaRatio * longest2))
    {
      return false;
    }
  }
  // Orientation agrees with the vertex normals (the mesh is oriented like the normals).
  const double sum[3] = { n0[0] + n1[0] + n2[0], n0[1] + n1[1] + n2[1], n0[2] + n1[2] + n2[2] };
  if (Dot(normal, sum) <= 0.0)
  {
    return false;
  }
  // II.C.2: no dangling triangle (a weaker bound in the hole-filling step, none for the last
  // triangle of a hole: its three edges are already on the front and it is the only way to close
  // the hole, however thin).
  const bool closesHole = parameters.CloseTriangularHoles &&
    this->Mesh.IsBoundaryHalfEdge(third, e1) && this->Mesh.IsBoundaryHalfEdge(e0, third);
  if (!closesHole)
  {
    const double bound = parameters.MinimumNormalDot * length;
    const Id v[3] = { e0, e1, third };
    const double* n[3] = { n0, n1, n2 };
    for (int i = 0; i < 3; ++i)
    {
      if (std::fabs(Dot(n[i], normal)) < bound &&
        !(parameters.NoiseBand && this->WithinNoiseBand(v, i)))
      {
        this->RefusedForGood = !parameters.CloseTriangularHoles; // (closesHole may change)
        return false;
      }
    }
  }
  // The mesh (topology), and II.E: not collinear (exact).
  if (!this->CanAdd(e0, e1, third))
  {
    this->RefusedForGood = false;
    return false;
  }
  pcs::projected::TrianglePlane plane;
  if (!plane.Set(this->P(e0), this->P(e1), this->P(third)))
  {
    return false;
  }
  // II.C.3: the third vertices of the two triangles of the edge lie on different sides of the
  // edge plane, unless their normals are opposite (Fig. 2b).
  if (opposite != None && Dot(this->N(opposite), n2) >= 0.0)
  {
    const double* a = this->P(e0);
    const double* b = this->P(e1);
    const double* c = this->P(opposite);
    // Normal of the existing triangle (e1, e0, opposite).
    const double u[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
    const double v[3] = { c[0] - b[0], c[1] - b[1], c[2] - b[2] };
    const double existing[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
      u[0] * v[1] - u[1] * v[0] };
    const int sideOpposite = pcs::projected::EdgePlaneSide(a, b, existing, c);
    const int sideThird = pcs::projected::EdgePlaneSide(a, b, existing, this->P(third));
    if (sideOpposite * sideThird >= 0)
    {
      return false;
    }
  }

  // The projection tests are the costly part: at most MaximumCandidates candidates of a front
  // edge (or of a seed edge) get that far.
  if (this->ProjectionTests >= parameters.MaximumCandidates)
  {
    this->RefusedForGood = false;
    return false;
  }
  ++this->ProjectionTests;
  // (Refused by the projection tests: for good while edges are only added, unless a hole may
  // close at this triangle, which then takes the noise-band path below.)
  this->RefusedForGood = !parameters.CloseTriangularHoles;
  // III.C within the noise band: the last triangle of a hole is not blocked by points and edges
  // within the noise band of its plane (see PassesProjectionTests). That decision depends on the
  // mesh (the hole), so it is not remembered in Blocked. Where the three vertices have no band
  // (an exact plane, or no fit) nothing is exempt: the usual, cached tests.
  if (closesHole && parameters.NoiseBand &&
    std::max({ this->NoiseBand[e0], this->NoiseBand[e1], this->NoiseBand[third] }) > 0.0)
  {
    this->WatchValid = false;
    return this->PassesProjectionTests(e0, e1, third, plane, parameters, true);
  }
  std::array<Id, 3> key = { e0, e1, third };
  std::sort(key.begin(), key.end());
  if (this->Blocked.Contains(key))
  {
    return false;
  }
  if (!this->PassesProjectionTests(e0, e1, third, plane, parameters))
  {
    this->Blocked.Insert(key);
    return false;
  }
  return true;
}

bool Front::PassesProjectionTests(Id e0,
  Id e1,
  Id third,
  const pcs::projected::TrianglePlane& plane,
  const Parameters& parameters,
  bool ignoreNoiseBand)
{
  const double *n0 = this->N(e0), *n1 = this->N(e1), *n2 = this->N(third);
  const double* normal = plane.GetNormal();
  const double length = std::sqrt(Dot(normal, normal));
  const double sum[3] = { n0[0] + n1[0] + n2[0], n0[1] + n1[1] + n2[1], n0[2] + n1[2] + n2[2] };
  // II.D: the neighbourhood of the triangle (centroid g, vertices within `reach` of g). A point
  // blocks it only when its normal line meets the triangle within MaximumRay: the point is
  // within reach + MaximumRay of g. An edge u w crosses it only if a point of the projected
  // segment, (1 - s) u' + s w' with u' = u + t_u n_u, |t_u| <= MaximumRay (the same for w), is in
  // the triangle: the segment u w passes within s = reach + MaximumRay of g, and one of u and w
  // is within sqrt(s^2 + |u w|^2 / 4) of g (see EdgeReachGrid, which bounds |u w| locally): the
  // edges are found from their end points in that ball. These bounds only select what the exact
  // tests then decide (1 % of margin against rounding).
  const Id v[3] = { e0, e1, third };
  double centroid[3];
  for (int k = 0; k < 3; ++k)
  {
    centroid[k] = (this->P(e0)[k] + this->P(e1)[k] + this->P(third)[k]) / 3.0;
  }
  double reach = 0.0;
  for (Id i : v)
  {
    reach = std::max(reach, std::sqrt(Distance2(this->P(i), centroid)));
  }
  // The ray bound of this triangle: a function of its three vertices only (whatever edge it is
  // built on), so that a triangle found blocked stays blocked (Blocked).
  double maximumRay = parameters.LocalRay ? parameters.MaximumRay *
      std::max(this->Scale[e0], std::max(this->Scale[e1], this->Scale[third]))
                                          : parameters.MaximumRay;
  if (parameters.LocalRay &&
    std::min({ this->RadiusScale[e0], this->RadiusScale[e1], this->RadiusScale[third] }) >=
      CurvedRaySpacingRatio)
  {
    // A large triangle of a sparse part: the surface under it may lie farther from its plane
    // than the bound of the mean spacing, as far as a vertex's tangent plane rises over it across
    // the triangle (reach times the sine of the angle between the vertex's normal and the
    // triangle's).
    double tilt2 = 0.0;
    for (const double* n : { n0, n1, n2 })
    {
      const double c = Dot(n, normal) / length;
      tilt2 = std::max(tilt2, 1.0 - c * c);
    }
    maximumRay = std::max(maximumRay, reach * std::sqrt(tilt2));
  }
  const double triangleBand2 = ignoreNoiseBand
    ? std::pow(std::max({ this->NoiseBand[e0], this->NoiseBand[e1], this->NoiseBand[third] }), 2)
    : 0.0;
  this->Projected0 = this->P(e0);
  auto withinNoiseBand = [&](Id x, double t)
  { return ignoreNoiseBand && t * t <= this->NoiseBand[x] * this->NoiseBand[x] + triangleBand2; };
  const double pointReach = reach + maximumRay;
  const double edgeReach =
    this->EdgeReach.Reach(centroid, 1.01 * pointReach, this->LongestEdge) * 1.000001;
  const double segmentReach2 = 1.0201 * pointReach * pointReach;
  const double pointReach2 = pointReach * pointReach;
  const double triangleReach2 = 1.0201 * reach * reach; // the triangle's ball, 1 % of margin
  if (++this->CurrentStamp == 0)                        // wrapped around: no stale stamp may match
  {
    std::fill(this->Stamp.begin(), this->Stamp.end(), 0u);
    std::fill(this->ProjectedStamp.begin(), this->ProjectedStamp.end(), 0u);
    this->CurrentStamp = 1;
  }

  // The ball, gathered in pieces of 16 points (a dense cluster is not walked whole when
  // one of its first points blocks), each filtered in passes that write their survivors without
  // a branch on each test (the tests on neighbouring points and edges pass or fail at random:
  // the branches were mispredicted about a third of the time). The answer, blocked by some point
  // or some edge, does not depend on the order of the tests.
  // Each point of the ball is stamped as an end point of the edges II.D.2 tests below when it may
  // be the nearer end of an edge passing within the segment reach s (within sqrt(s^2 + L^2 / 4) of
  // g for its longest edge L; every edge that may cross has at least one stamped end point, and
  // is tested from its stamped end point of smaller id). It is a II.D.1 candidate (Fig. 3) when
  // it is within the point reach, not a vertex of the triangle, usable, and its normal is on the
  // triangle's side of the vertex normals (Fig. 3b: not the other side of a thin sheet).
  const unsigned stamp = this->CurrentStamp;
  size_t stampedEnds = 0;
  auto testPiece = [&](size_t inPiece)
  {
    if (this->StampedEnds.size() < stampedEnds + inPiece)
    {
      this->StampedEnds.resize(2 * (stampedEnds + inPiece));
    }
    if (this->PointCandidates.size() < inPiece)
    {
      this->PointCandidates.resize(2 * inPiece);
    }
    size_t pointCandidates = 0;
    this->Work += inPiece;
    for (size_t i = 0; i < inPiece; ++i)
    {
      const Id p = this->Ball[i].first;
      const double distance2 = this->Ball[i].second;
      const double incident = this->MaxIncident[p];
      const bool end =
        (distance2 <= segmentReach2 + 0.25 * incident * incident) & !this->Mesh.IsFree(p);
      const unsigned old = this->Stamp[p]; // (end ? stamp : old, without a branch)
      this->Stamp[p] = old ^ ((old ^ stamp) & (0u - static_cast<unsigned>(end)));
      this->StampedEnds[stampedEnds] = { p, distance2 };
      stampedEnds += end ? 1 : 0;
      const double* np = this->N(p);
      const bool candidate = (distance2 <= pointReach2) & (p != e0) & (p != e1) & (p != third) &
        (this->Status[p] == Usable) & !(Dot(np, n0) <= 0.0) & !(Dot(np, n1) <= 0.0) &
        !(Dot(np, n2) <= 0.0);
      this->PointCandidates[pointCandidates] = p;
      pointCandidates += candidate ? 1 : 0;
    }
    // II.D.1: a candidate blocks when its normal line crosses the open triangle (exact) at a ray
    // parameter of at most MaximumRay. The parameter is tested first, and when the line is not
    // nearly parallel to the plane (|np . N| >= 0.1: t and its point are then accurate to a few
    // ulps), a crossing point farther than the vertices from the centroid (with 1 % of margin)
    // cannot be in the triangle: the exact test is skipped. Same decisions, fewer exact tests.
    for (size_t i = 0; i < pointCandidates; ++i)
    {
      const Id p = this->PointCandidates[i];
      const double *x = this->P(p), *np = this->N(p);
      double t = 0.0; // (left at 0 when there is no parameter)
      bool reached = pcs::projected::RayParameter(x, np, this->P(e0), normal, t);
      reached = reached & (std::fabs(t) <= maximumRay);
      if (ignoreNoiseBand && reached && !this->Mesh.IsFree(p) && withinNoiseBand(p, t))
      {
        reached = false;
      }
      const bool steep = std::fabs(Dot(np, normal)) >= 0.1 * length;
      const double hit[3] = { x[0] + t * np[0], x[1] + t * np[1], x[2] + t * np[2] };
      const bool outside = steep & (Distance2(hit, centroid) > triangleReach2);
      if (reached && !outside &&
        pcs::projected::LineCrossesTriangle(x, np, this->P(e0), this->P(e1), this->P(third)))
      {
        return false;
      }
    }
    return true;
  };
  if (!this->Bins.GatherWithinRadius(
        std::min(edgeReach, this->Diagonal), centroid, this->Ball, 16, testPiece))
  {
    return false;
  }

  // II.D.2: projected neighbouring edges (Fig. 4), each edge once: the edges that pass the tests
  // on their end points (not tested from the other end, not an edge of the triangle, within the
  // segment reach, Fig. 4b) are gathered without a branch on each test, then projected, those of
  // each end point in turn (an end point's edges are only listed when no edge listed before
  // crosses: a vertex of a dense cluster has hundreds, which GetEdgeEnds lists from the mesh).
  size_t edges = 0;
  auto testEdges = [&]()
  {
    for (size_t i = 0; i < edges; ++i)
    {
      const Id u = this->EdgeCandidates[i].first;
      const Id w = this->EdgeCandidates[i].second;
      const bool uIsVertex = (u == e0) | (u == e1) | (u == third);
      const bool wIsVertex = (w == e0) | (w == e1) | (w == third);
      // Projected end points (each computed once per triangle tested, most points end several
      // edges); a vertex of the triangle projects onto itself.
      const double* pu = this->Project(u, uIsVertex, normal, this->P(e0), maximumRay);
      const double* pw =
        pu ? this->Project(w, wIsVertex, normal, this->P(e0), maximumRay) : nullptr;
      // A projected segment that stays out of the triangle's ball (1 % of margin) cannot cross.
      if (pw && SegmentDistance2(pu, pw, centroid) <= triangleReach2 &&
        plane.SegmentCrosses(pu, pw) &&
        !(ignoreNoiseBand && this->EndWithinNoiseBand(u, uIsVertex, normal, withinNoiseBand) &&
          this->EndWithinNoiseBand(w, wIsVertex, normal, withinNoiseBand)))
      {
        return false;
      }
    }
    edges = 0;
    return true;
  };
  for (size_t s = 0; s < stampedEnds; ++s)
  {
    const Id u = this->StampedEnds[s].first;
    const double uDistance2 = this->StampedEnds[s].second; // (within s: every edge of u passes)
    const Id* ends = &this->Adjacent[AdjacentCapacity * static_cast<size_t>(u)];
    int numberOfEnds = this->AdjacentCount[u];
    if (numberOfEnds == Overflow)
    {
      GetEdgeEnds(this->Mesh, u, this->VertexTriangles, this->Neighbors);
      ends = this->Neighbors.data();
      numberOfEnds = static_cast<int>(this->Neighbors.size());
    }
    this->Work += static_cast<uint64_t>(numberOfEnds);
    if (this->EdgeCandidates.size() < edges + static_cast<size_t>(numberOfEnds))
    {
      this->EdgeCandidates.resize(2 * (edges + static_cast<size_t>(numberOfEnds)));
    }
    const bool uIsVertex = u == e0 || u == e1 || u == third;
    const bool uBeyond = uDistance2 > segmentReach2;
    const double* nu = this->N(u);
    for (int j = 0; j < numberOfEnds; ++j)
    {
      const Id w = ends[j];
      const bool wIsVertex = (w == e0) | (w == e1) | (w == third);
      const double* nw = this->N(w);
      const double edgeNormal[3] = { nu[0] + nw[0], nu[1] + nw[1], nu[2] + nw[2] };
      bool keep = !((this->Stamp[w] == stamp) & (w < u)) & !(uIsVertex & wIsVertex) &
        !(Dot(edgeNormal, sum) <= 0.0);
      if (uBeyond) // (the same for all the edges of u)
      {
        keep = keep & !(SegmentDistance2(this->P(u), this->P(w), centroid) > segmentReach2);
      }
      this->EdgeCandidates[edges] = { u, w };
      edges += keep ? 1 : 0;
    }
    if (!testEdges())
    {
      return false;
    }
  }
  return true;
}

Id Front::BestThirdPoint(Id e0, Id e1, Id opposite, const Parameters& global, bool relaxed)
{
  const Parameters parameters = this->AtEdge(global, e0, e1);
  const double *a = this->P(e0), *b = this->P(e1);
  const double midpoint[3] = { 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]) };
  // The candidates in order of distance to the midpoint, in rings: those within a quarter of
  // the radius first, then those within half of it, then the others (the first candidate is
  // accepted for most front edges, and the inner ball holds a sixteenth of the points). The
  // order, hence the result, is the one of a single sorted list: a ring holds the points of its
  // query ball (squared distance at most the squared query radius, as the query computes it)
  // that are not in the previous one; the last ring has no outer bound (III.C ears).
  // On scan lines the candidates are ranked in the sampling's metric (RankDistance2), which is
  // never shorter than the Euclidean distance: a candidate of a ring ranked beyond the ring's
  // radius waits for the next ring (Pending), so the order is still that of one sorted list.
  // Where the radius is enlarged (a sparser sampling, see AtEdge), the rings are those of the
  // radius at the mean spacing and one more out to the enlarged radius: the same order, and the
  // inner rings cost what they do at the mean spacing.
  // Where the radius is reduced (a denser part), the three rings are those of the reduced radius.
  const double base = std::min(global.Radius, parameters.Radius);
  const int rings = parameters.Radius > global.Radius ? 4 : 3;
  const double radii[4] = { 0.25 * base, 0.5 * base, base, parameters.Radius };
  this->Pending.clear();
  this->ProjectionTests = 0;
  // Besides the projection tests, a bound on the candidates examined (the cheap tests reject
  // without counting one): a dense cluster puts thousands of points in every ring, and sorting
  // and examining them all for each front edge made it quadratic. Only the nearest candidates
  // within the bound are sorted.
  const size_t examinedBudget = 50 * static_cast<size_t>(parameters.MaximumCandidates);
  size_t examined = 0;
  // Ranked in the sampling's metric only where an end of the edge has a stretch.
  const bool stretchedEdge = this->HasStretch(e0) || this->HasStretch(e1);
  this->Watch.clear();
  this->WatchValid = true;
  bool endsWatched = false;
  auto watchEnds = [&]()
  {
    if (!endsWatched)
    {
      this->WatchPoint(e0);
      this->WatchPoint(e1);
      endsWatched = true;
    }
  };
  if (relaxed)
  {
    watchEnds(); // (the ears, and the holes that may close)
  }
  this->Ears.clear();
  if (relaxed)
  {
    // III.C: the triangles with the adjacent boundary edges at a common vertex (ears),
    // whatever their distance, except slivers with a long new edge (IsAcceptableEar); each is a
    // candidate of the ring its distance falls in. (The mesh does not change here: listed once.)
    this->HalfEdges.clear();
    GetBoundaryHalfEdges(this->Mesh, e0, this->HalfEdges);
    GetBoundaryHalfEdges(this->Mesh, e1, this->HalfEdges);
    for (const auto& halfEdge : this->HalfEdges)
    {
      for (Id x : { halfEdge.first, halfEdge.second })
      {
        if (x != e0 && x != e1 && x != opposite && this->IsAcceptableEar(e0, e1, x, parameters))
        {
          this->Ears.push_back(x);
        }
      }
    }
  }
  for (int ring = 0; ring < rings; ++ring)
  {
    this->Candidates.clear();
    const double outer2 =
      ring + 1 < rings ? radii[ring] * radii[ring] : std::numeric_limits<double>::infinity();
    const double inner2 = ring > 0 ? radii[ring - 1] * radii[ring - 1] : -1.0;
    auto consider = [&](Id x, double d2)
    {
      if (d2 > inner2 && d2 <= outer2)
      {
        this->Candidates.emplace_back(
          stretchedEdge ? this->RankDistance2(midpoint, x, e0, e1) : d2, x);
      }
    };
    // The points of the ring's ball (FindPoints' query, gathered here: its squared distances are
    // Distance2(P(x), midpoint)), those of the inner rings left out; the candidates are written
    // without a branch on each test (see PassesProjectionTests).
    const size_t inBall =
      this->Bins.GatherWithinRadius(std::min(radii[ring], this->Diagonal), midpoint, this->Ball);
    this->Work += inBall;
    this->Candidates.resize(inBall); // (empty before: cleared above)
    size_t kept = 0;
    for (size_t i = 0; i < inBall; ++i)
    {
      const Id x = this->Ball[i].first;
      const double d2 = this->Ball[i].second;
      const bool candidate = (d2 > inner2) & (d2 <= outer2) & (x != e0) & (x != e1) &
        (x != opposite) & (this->Status[x] == Usable) & !this->Mesh.IsInterior(x);
      this->Candidates[kept] = { stretchedEdge ? this->RankDistance2(midpoint, x, e0, e1) : d2, x };
      kept += candidate ? 1 : 0;
    }
    this->Candidates.resize(kept);
    for (Id x : this->Ears) // (empty unless relaxed)
    {
      consider(x, Distance2(this->P(x), midpoint));
    }
    this->Candidates.insert(this->Candidates.end(), this->Pending.begin(), this->Pending.end());
    this->Pending.clear();
    if (this->Candidates.size() > examinedBudget - examined)
    {
      this->WatchValid = false; // (candidates left out by the budget)
    }
    SortNearest(this->Candidates, examinedBudget - examined);
    this->Candidates.erase(
      std::unique(this->Candidates.begin(), this->Candidates.end()), this->Candidates.end());
    for (auto candidate = this->Candidates.begin(); candidate != this->Candidates.end();
         ++candidate)
    {
      if (candidate->first > outer2)
      {
        this->Pending.assign(candidate, this->Candidates.end()); // scan lines only
        break;
      }
      if (++examined > examinedBudget)
      {
        this->WatchValid = false;
        return None;
      }
      // A candidate beyond the neighbourhood radius of the mean spacing (found because the
      // edge's sampling is sparser) must make a well-shaped triangle: no angle below 15 degrees.
      if (!relaxed && parameters.Radius > global.Radius &&
        Distance2(this->P(candidate->second), midpoint) > global.Radius * global.Radius &&
        !this->HasNoAngleBelow(e0, e1, candidate->second, parameters.MaximumLongEarCos))
      {
        continue;
      }
      // Nor may it extend a fan across the rim of a hole (see FanEdgeSpacingRatio).
      if (!relaxed && parameters.RefuseRimFans &&
        this->ExtendsFan(e0, e1, candidate->second, parameters))
      {
        continue;
      }
      if (this->IsValid(e0, e1, candidate->second, opposite, parameters) &&
        this->KeepsGenus(e0, e1, candidate->second))
      {
        return candidate->second;
      }
      if (!this->RefusedForGood)
      {
        this->WatchPoint(candidate->second);
        watchEnds(); // (CanAdd reads the mesh at the ends too)
      }
      if (this->ProjectionTests >= parameters.MaximumCandidates)
      {
        this->WatchValid = false;
        return None; // the budget is spent: no further candidate can be accepted
      }
    }
  }
  return None;
}

bool Front::CanAdd(Id a, Id b, Id c) const
{
  // A pinch (a triangle touching a front vertex without sharing an edge with it) is allowed:
  // two fronts, or two parts of one, meet that way, and the next triangles usually merge the two
  // fans; RemovePinches undoes the pinches left at the end.
  const pcs::SurfaceMesh::Check check = this->Mesh.CanAddTriangle(a, b, c);
  return check == pcs::SurfaceMesh::Check::Ok ||
    (this->AllowPinches && check == pcs::SurfaceMesh::Check::NonManifoldVertex &&
      !this->Mesh.IsInterior(a) && !this->Mesh.IsInterior(b) && !this->Mesh.IsInterior(c));
}

void Front::RebuildParts()
{
  this->PartsValid = true;
  this->Parts.Reset(this->Mesh.GetNumberOfTriangleIds());
  this->Mesh.JoinAcrossEdges(this->Parts);
}

void Front::FindJoints(const Id v[3])
{
  if (this->JointsState == this->State && std::equal(v, v + 3, this->JointsOf))
  {
    return; // (KeepsGenus found them for this triangle, and the mesh has not changed since)
  }
  std::copy_n(v, 3, this->JointsOf);
  this->JointsState = this->State;
  this->Joints.clear();
  // A front half-edge the triangle is glued to (for the pinches).
  Id glueTail = None, glueHead = None;
  for (int i = 0; i < 3 && glueTail == None; ++i)
  {
    if (this->Mesh.IsBoundaryHalfEdge(v[(i + 1) % 3], v[i]))
    {
      glueTail = v[(i + 1) % 3];
      glueHead = v[i];
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    // The triangle owns x->next and previous->x: it is glued at x along next->x and x->previous
    // where those are front half-edges.
    const Id x = v[i], next = v[(i + 1) % 3], previous = v[(i + 2) % 3];
    if (this->Mesh.IsFree(x))
    {
      continue;
    }
    const bool in = this->Mesh.IsBoundaryHalfEdge(next, x);
    const bool out = this->Mesh.IsBoundaryHalfEdge(x, previous);
    if (in && out)
    {
      if (this->Mesh.NextBoundaryVertex(next, x) != previous) // two fans of x merged
      {
        this->Joints.push_back({ next, x, x, previous, false });
      }
    }
    else if (!in && !out && glueTail != None)
    {
      Id fans[4];
      const int count = std::min(this->Mesh.GetBoundaryOutVertices(x, fans, 4), 4);
      for (int k = 0; k < count; ++k)
      {
        this->Joints.push_back({ glueTail, glueHead, x, fans[k], true });
      }
    }
  }
}

bool Front::JoinsHole(Id a, Id b, Id c, Id d) const
{
  // (Two loops, one short: a loop that closes short without passing the other half-edge.)
  const double limit = 4.0 * vtkMath::Pi() * this->HoleSpacing;
  return (pcs::holes::IsShortLoop(this->Mesh, this->XYZ, a, b, HoleEdges, limit, c, d) ||
           pcs::holes::IsShortLoop(this->Mesh, this->XYZ, c, d, HoleEdges, limit, a, b)) &&
    !pcs::holes::JoinsLoopsAroundTube(this->Mesh, this->XYZ, a, b, c, d);
}

bool Front::KeepsGenus(Id v0, Id v1, Id v2)
{
  if (this->Mesh.IsFree(v2))
  {
    return true; // (each edge but v1 v0 has a free end point: no joint)
  }
  const Id v[3] = { v0, v1, v2 };
  this->FindJoints(v);
  for (const Joint& joint : this->Joints)
  {
    if (this->PartOf(joint.Tail0, joint.Head0) != this->PartOf(joint.Tail1, joint.Head1))
    {
      continue; // two parts joined
    }
    if (this->JoinsHole(joint.Tail0, joint.Head0, joint.Tail1, joint.Head1))
    {
      this->RefusedForGood = false;
      return false;
    }
  }
  return true;
}

int64_t Front::Add(Id a, Id b, Id c, uint8_t origin, int64_t across)
{
  // The parts the triangle joins: across its front edge (for a seed, across every edge it is
  // glued to) and at its joints other than pinches (a pinch joins no part: two fans at a vertex).
  int64_t joined[8];
  int count = 0;
  if (across >= 0)
  {
    joined[count++] = across;
  }
  if (!this->Mesh.IsFree(c) || across < 0)
  {
    const Id v[3] = { a, b, c };
    for (int i = 0; i < 3 && across < 0; ++i)
    {
      const int64_t twin = this->Mesh.FindTriangle(v[(i + 1) % 3], v[i]);
      if (twin >= 0)
      {
        joined[count++] = twin;
      }
    }
    this->FindJoints(v);
    for (const Joint& joint : this->Joints)
    {
      if (!joint.Pinch && count + 2 <= 8)
      {
        joined[count++] = this->Mesh.FindTriangle(joint.Tail0, joint.Head0);
        joined[count++] = this->Mesh.FindTriangle(joint.Tail1, joint.Head1);
      }
    }
  }
  const int64_t t = this->Mesh.AddTriangle(a, b, c);
  if (t < 0)
  {
    return t;
  }
  if (this->PartsValid && this->Parts.GetNumberOfIds() == t)
  {
    this->Parts.Add();
    for (int k = 0; k < count; ++k)
    {
      this->Parts.Union(t, joined[k]);
    }
  }
  else
  {
    this->PartsValid = false; // (triangles made or removed outside the front)
  }
  ++this->State;
  this->Origin.push_back(origin);
  const Id v[3] = { a, b, c };
  for (Id x : v)
  {
    this->Touched[x] = this->State;
  }
  double lengths[3]; // of the edge v[i] v[i + 1]
  for (int i = 0; i < 3; ++i)
  {
    const Id from = v[i], to = v[(i + 1) % 3];
    const double length = std::sqrt(Distance2(this->P(from), this->P(to)));
    lengths[i] = length;
    this->LongestEdge = std::max(this->LongestEdge, length);
    this->MaxIncident[from] = std::max(this->MaxIncident[from], length);
    this->MaxIncident[to] = std::max(this->MaxIncident[to], length);
    this->Link(from, to);
  }
  // Each vertex's cell keeps the longer of its two new edges (one lookup per vertex).
  for (int i = 0; i < 3; ++i)
  {
    this->EdgeReach.Add(this->P(v[i]), std::max(lengths[i], lengths[(i + 2) % 3]));
  }
  // Its edges, and the front edges next to its vertices (which may now close as ears).
  for (int i = 0; i < 3; ++i)
  {
    this->Queue(v[i], v[(i + 1) % 3]);
  }
  this->HalfEdges.clear();
  for (Id x : v)
  {
    GetBoundaryHalfEdges(this->Mesh, x, this->HalfEdges);
  }
  for (const auto& halfEdge : this->HalfEdges)
  {
    this->Queue(halfEdge.first, halfEdge.second);
  }
  return t;
}

void Front::Progress()
{
  if (++this->Steps % 1024 == 0)
  {
    const double fraction = std::min(1.0,
      static_cast<double>(this->Mesh.GetNumberOfTriangles()) /
        (2.0 * static_cast<double>(this->Mesh.GetNumberOfVertices()) + 1.0));
    this->Self->UpdateProgress(0.2 + 0.7 * fraction);
    this->Aborted = this->Self->GetAbortExecute() != 0;
  }
}

bool Front::Advance(const Parameters& parameters, bool relaxed, uint8_t origin)
{
  ++this->State;
  if (this->WatchParameters != &parameters)
  {
    this->ForgetWatches();
    this->WatchParameters = &parameters;
  }
  while (!this->Edges.empty() && !this->Aborted && !this->OutOfWork)
  {
    const Id a = this->Edges.front().first;
    const Id b = this->Edges.front().second;
    this->Edges.pop_front();
    if (!this->Mesh.IsBoundaryHalfEdge(a, b))
    {
      continue; // not a front edge (any more)
    }
    this->Progress();
    if (this->FailedHead[a] == b && (this->FailedState[a] == this->State || this->Unchanged(a)))
    {
      continue; // tried since the last change (near it), in vain
    }
    // The new triangle traverses the edge the other way: (b, a, x).
    const int64_t across = this->Mesh.FindTriangle(a, b);
    const int32_t* triangle = this->Mesh.GetTriangle(across);
    const Id opposite = triangle[0] != a && triangle[0] != b
      ? triangle[0]
      : (triangle[1] != a && triangle[1] != b ? triangle[1] : triangle[2]);
    const Id x = this->BestThirdPoint(b, a, opposite, parameters, relaxed);
    this->OutOfWork = this->Work > this->WorkBudget;
    if (x != None)
    {
      this->Add(b, a, x, origin, across);
    }
    else
    {
      this->FailedHead[a] = b;
      this->FailedState[a] = this->State;
      this->RecordWatch(a);
    }
  }
  return !this->Aborted;
}

bool Front::Seed(Id p, const Parameters& parameters)
{
  // The nearest points first (the paper's rule), then the next ones if no triangle is valid.
  this->FindPoints(this->AtEdge(parameters, p, p).Radius, this->P(p), this->Near);
  std::vector<std::pair<double, Id>> firsts;
  for (vtkIdType k = 0; k < static_cast<vtkIdType>(this->Near.size()); ++k)
  {
    const Id q = static_cast<Id>(this->Near[k]);
    if (q != p && this->Status[q] == Usable && Dot(this->N(p), this->N(q)) > 0.0 &&
      !this->Mesh.IsInterior(q))
    {
      firsts.emplace_back(this->RankDistance2(this->P(p), q, p, q), q);
    }
  }
  // One budget of projection tests for the seed point (over all its first edges), and one of
  // examined triangles (the cheap tests reject without counting a projection test: without it a
  // dense cluster in a large ball costs the cube of its size). Only the nearest points within
  // the budgets are sorted.
  const size_t examinedBudget = 10 * static_cast<size_t>(parameters.MaximumCandidates);
  size_t examined = 0;
  SortNearest(firsts, examinedBudget);
  this->ProjectionTests = 0;
  for (const auto& first : firsts)
  {
    if (this->ProjectionTests >= parameters.MaximumCandidates || examined >= examinedBudget)
    {
      break;
    }
    this->OutOfWork = this->Work > this->WorkBudget; // (the seeds' work counts too)
    if (this->OutOfWork)
    {
      return false;
    }
    const Id q = first.second;
    const Parameters atEdge = this->AtEdge(parameters, p, q);
    // Orientation from the normals: try (p, q, x); IsValid rejects the reversed orientation, so
    // the other one is tried with the same third point.
    const double *a = this->P(p), *b = this->P(q);
    const double midpoint[3] = { 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]) };
    this->FindPoints(atEdge.Radius, midpoint, this->Near);
    this->Work += this->Near.size();
    this->Candidates.clear();
    for (vtkIdType k = 0; k < static_cast<vtkIdType>(this->Near.size()); ++k)
    {
      const Id x = static_cast<Id>(this->Near[k]);
      if (x != p && x != q && this->Status[x] == Usable && !this->Mesh.IsInterior(x))
      {
        this->Candidates.emplace_back(this->RankDistance2(midpoint, x, p, q), x);
      }
    }
    SortNearest(this->Candidates, examinedBudget - examined);
    for (const auto& candidate : this->Candidates)
    {
      if (this->ProjectionTests >= parameters.MaximumCandidates || examined >= examinedBudget)
      {
        break;
      }
      ++examined;
      const Id x = candidate.second;
      if (this->IsValid(p, q, x, None, atEdge) && this->KeepsGenus(p, q, x))
      {
        this->Add(p, q, x, 0);
        ++this->NumberOfSeeds;
        return true;
      }
      if (this->IsValid(q, p, x, None, atEdge) && this->KeepsGenus(q, p, x))
      {
        this->Add(q, p, x, 0);
        ++this->NumberOfSeeds;
        return true;
      }
    }
  }
  return false;
}

//------------------------------------------------------------------------------------------------
// After III.C (ours): the boundary loops that the relaxed front could not close. They are left
// where the estimated normals of an irregular sampling are far off the surface (on CGAL's cow
// vertex set 40 of the 41 loops have a vertex whose normal is more than 30 degrees off or
// reversed): the normal rules refuse every triangle across such a hole, and the front triangles
// made around it are tilted or folded. A loop is closed by the triangulation of its own vertices
// of least largest dihedral angle (the shared kernel pcs::holes::LeastDihedralFill, Liepa 2003,
// which reads no point normal), kept only when it stays on the sampled surface (the rules of
// pcs::holes::FillLoopNearSamples, shared with vtkLocalOptimumGrowth; the parameters here):
// - the centroid and the midpoints of the new edges of every fill triangle lie within 1.5 local
//   spacings of an input point, the local spacing being the largest of the mean spacing, the mean
//   nearest-point distance of the loop's vertices and the mean length of the interior mesh edges
//   at them (the scale at which the surface around the hole is triangulated: on a vertex set with
//   edges of 10 to 20 mean spacings in its flat parts, the nearest-point distances alone refused
//   holes of a few such edges). A fill across empty space is refused: the paper's cylinder rims
//   (the middle of a rim's fill is 2.9 spacings from every point) stay open, and so does a slit
//   6 spacings wide in a sphere (with 2 local spacings it was closed by fill triangles along it,
//   1.1 mean spacings off the sphere);
// - no fill triangle is exactly degenerate or a mesh triangle reversed, and none folds onto its
//   neighbour (largest dihedral angle at most MaximumDihedral: 170 degrees, where a fill
//   triangle and the triangle across its edge would overlap within 10 degrees).
// The triangles around such a hole are often steep against it (90 to 180 degrees against the
// fill on 33 of the cow's 37 loops): a smaller bound left most holes open, and removing every
// steep triangle to fill the larger loop did not help (Benchmarks/results/cdt.md, "Holes left
// with estimated normals"). Removing only the triangles folded over the hole (facing against its
// fill) when no fill closes the loop does: CloseAfterPeel; and, when that does not close it, all
// the triangles across the loop's edges (a crack between the fans on either side of a dense row
// of points, whose own points are nearly collinear: cdt.md, "Cracks along dense rows").
class LoopCloser
{
public:
  LoopCloser(pcs::SurfaceMesh& mesh,
    const double* xyz,
    const std::vector<double>& nearest,
    double meanSpacing,
    const std::vector<uint8_t>& status,
    const pcs::PointBins& bins,
    std::vector<uint8_t>& origin)
    : Mesh(mesh)
    , XYZ(xyz)
    , Nearest(nearest)
    , MeanSpacing(meanSpacing)
    , Status(status)
    , Bins(bins)
    , Origin(origin)
  {
  }

  // Closes what it can of the current boundary loops; returns the number of triangles added
  // (their origin is 2, hole filling).
  vtkIdType CloseAll()
  {
    std::vector<std::vector<Id>> loops;
    this->Mesh.GetBoundaryLoops(loops);
    const int64_t before = this->Mesh.GetNumberOfTriangles();
    std::vector<Id> fill;
    for (const std::vector<Id>& loop : loops)
    {
      if (!this->IsLoop(loop))
      {
        continue; // opened further by the peel around an earlier loop
      }
      if (this->Fill(loop, fill))
      {
        this->AddFill(fill);
      }
      else if (IsFillable(loop))
      {
        this->CloseAfterPeel(loop); // refused by its fills, not by its shape
      }
    }
    return static_cast<vtkIdType>(this->Mesh.GetNumberOfTriangles() - before);
  }

private:
  // Are the loop's edges all boundary half-edges (loop[i] -> loop[i + 1])?
  bool IsLoop(const std::vector<Id>& loop) const
  {
    for (size_t i = 0; i < loop.size(); ++i)
    {
      if (!this->Mesh.IsBoundaryHalfEdge(loop[i], loop[(i + 1) % loop.size()]))
      {
        return false;
      }
    }
    return true;
  }

  // The fill's triangles added to the mesh (origin 2, hole filling); false when the mesh
  // refuses them (it is then unchanged).
  bool AddFill(const std::vector<Id>& fill)
  {
    if (!this->Mesh.AddTriangles(fill.data(), fill.size() / 3, this->Added))
    {
      return false;
    }
    this->Origin.resize(static_cast<size_t>(this->Mesh.GetNumberOfTriangleIds()), 2);
    return true;
  }

  // A loop that no fill closes below MaximumDihedral: where the front folded triangles over a
  // small hole (wrong normals), the fill of the loop would fold onto them. The folded triangles
  // across its edges are removed (PeelAcross) and the larger loop they leave is filled; this is
  // kept only when it closes the loop's edges exactly (no more boundary than before), otherwise
  // the mesh is put back as it was. Then the same with every triangle across the loop's edges:
  // a loop along a dense row of points (a scan line, a ring of a vertex set) whose points are
  // nearly collinear has only slivers as fills, standing across the surface; the larger loop
  // through the apexes of the fans on either side has fills along it.
  void CloseAfterPeel(const std::vector<Id>& loop)
  {
    const int64_t open = this->Mesh.GetNumberOfBoundaryHalfEdges();
    std::vector<Id> peeled, larger, fill;
    bool unfolded = true; // a triangle across the loop that the fold peel left
    for (bool onlyFolded : { true, false })
    {
      if (!unfolded)
      {
        return; // the second peel would repeat the first
      }
      peeled.clear();
      const bool closed = this->PeelAcross(loop, onlyFolded, peeled, unfolded) &&
        this->LoopAround(peeled, larger) && this->Fill(larger, fill) && this->AddFill(fill);
      if (closed &&
        this->Mesh.GetNumberOfBoundaryHalfEdges() == open - static_cast<int64_t>(loop.size()))
      {
        return;
      }
      if (closed)
      {
        for (int64_t t : this->Added)
        {
          this->Mesh.RemoveTriangle(t);
        }
      }
      this->Restore(peeled);
    }
  }

  // The mesh triangles across the loop's edges (onlyFolded: those folded over the hole, their
  // normal against the loop's vector area, oriented like its fill) are removed, except one whose
  // removal would leave a vertex with no triangle: no point leaves the mesh. Each removed triangle
  // is appended to `peeled` (its 3 vertices and its origin); false when none is removed.
  bool PeelAcross(
    const std::vector<Id>& loop, bool onlyFolded, std::vector<Id>& peeled, bool& unfolded)
  {
    unfolded = false;
    const size_t m = loop.size();
    double area[3]; // the vector area of the fill's loop (walked backwards)
    pcs::holes::LoopVectorArea(this->XYZ, std::vector<Id>(loop.rbegin(), loop.rend()), area);
    std::vector<int64_t> across; // the triangles to remove
    for (size_t i = 0; i < m; ++i)
    {
      const int64_t t = this->Mesh.FindTriangle(loop[i], loop[(i + 1) % m]);
      if (t < 0)
      {
        return false;
      }
      const int32_t* v = this->Mesh.GetTriangle(t);
      double normal[3];
      pcs::projected::TriangleNormal(this->P(v[0]), this->P(v[1]), this->P(v[2]), normal);
      const bool folded = Dot(normal, area) < 0.0;
      unfolded = unfolded || !folded;
      if ((!onlyFolded || folded) && std::find(across.begin(), across.end(), t) == across.end())
      {
        across.push_back(t);
      }
    }
    std::vector<int64_t> removable;
    for (int64_t t : across)
    {
      const int32_t* v = this->Mesh.GetTriangle(t);
      if (this->KeepsATriangle(v[0], across) && this->KeepsATriangle(v[1], across) &&
        this->KeepsATriangle(v[2], across))
      {
        removable.push_back(t);
      }
    }
    for (int64_t t : removable)
    {
      const int32_t* v = this->Mesh.GetTriangle(t);
      peeled.insert(peeled.end(), v, v + 3);
      peeled.push_back(this->Origin[static_cast<size_t>(t)]);
      this->Mesh.RemoveTriangle(t);
    }
    return !removable.empty();
  }

  // Has v a triangle that is not one of `removed`?
  bool KeepsATriangle(Id v, const std::vector<int64_t>& removed) const
  {
    constexpr int Capacity = 64;
    int64_t around[Capacity];
    const int n = this->Mesh.GetVertexTriangles(v, around, Capacity);
    return n > Capacity ||
      std::any_of(around,
        around + n,
        [&](int64_t t) { return std::find(removed.begin(), removed.end(), t) == removed.end(); });
  }

  // The boundary loop through a vertex of the last triangle of `peeled` that has one open fan,
  // into `loop`; false when there is none or the loop is longer than MaximumLoopEdges.
  bool LoopAround(const std::vector<Id>& peeled, std::vector<Id>& loop) const
  {
    Id start = None, out[2];
    for (size_t k = peeled.size() - 4; k + 1 < peeled.size() && start == None; ++k)
    {
      if (this->Mesh.GetBoundaryOutVertices(peeled[k], out, 2) == 1)
      {
        start = peeled[k];
      }
    }
    if (start == None)
    {
      return false;
    }
    loop.assign(1, start);
    for (Id previous = start, current = out[0]; current != start;)
    {
      if (current < 0 || loop.size() > MaximumLoopEdges)
      {
        return false;
      }
      loop.push_back(current);
      const Id next = this->Mesh.NextBoundaryVertex(previous, current);
      previous = current;
      current = next;
    }
    return true;
  }

  // The triangles of `peeled` put back (see PeelAcross).
  void Restore(const std::vector<Id>& peeled)
  {
    for (size_t k = peeled.size(); k >= 4; k -= 4)
    {
      this->Mesh.AddTriangle(peeled[k - 4], peeled[k - 3], peeled[k - 2]);
      this->Origin.resize(static_cast<size_t>(this->Mesh.GetNumberOfTriangleIds()),
        static_cast<uint8_t>(peeled[k - 1]));
    }
  }

  // The least-dihedral triangulation is cubic in the loop's length. Loops up to the kernel's
  // limit (400 edges) are tried (100 before; FillLoopNearSamples refuses a wide loop by its area
  // before the programme): the noisy clouds, with many long loops, took 0 to 5 % more CPU than
  // with 100 (Benchmarks/results/cdt.md, "Loops of up to 400 edges").
  static constexpr size_t MaximumLoopEdges = pcs::holes::MaximumFillLoopEdges;
  static constexpr double MaximumDihedral = 170.0 * 3.14159265358979323846 / 180.0;

  const double* P(Id i) const { return this->XYZ + 3 * static_cast<size_t>(i); }

  // The mean length of the interior mesh edges (two triangles) at the loop's vertices.
  double MeshEdgeLength(const std::vector<Id>& loop) const
  {
    double sum = 0.0;
    int count = 0;
    constexpr int Capacity = 64;
    int64_t triangles[Capacity];
    for (Id v : loop)
    {
      const int n = std::min(Capacity, this->Mesh.GetVertexTriangles(v, triangles, Capacity));
      for (int k = 0; k < n; ++k)
      {
        const int32_t* t = this->Mesh.GetTriangle(triangles[k]);
        for (int j = 0; j < 3; ++j)
        {
          // Each interior edge at v once: the one leaving v in its triangle.
          const Id w = t[(j + 1) % 3];
          if (t[j] == v && this->Mesh.GetEdgeValence(v, w) == 2)
          {
            sum += std::sqrt(Distance2(this->P(v), this->P(w)));
            ++count;
          }
        }
      }
    }
    return count > 0 ? sum / count : 0.0;
  }

  // Is there a usable input point within `reach` of x?
  bool NearSomePoint(const double* x, double reach) const
  {
    bool found = false;
    this->Bins.ForEachPointWithinRadius(reach,
      x,
      [&](Id p, double)
      {
        found = this->Status[p] == Usable;
        return !found;
      });
    return found;
  }

  // Can the loop have a fill at all: 3 to MaximumLoopEdges edges, through no vertex twice?
  static bool IsFillable(const std::vector<Id>& boundary)
  {
    const size_t m = boundary.size();
    if (m < 3 || m > MaximumLoopEdges)
    {
      return false;
    }
    std::vector<Id> sorted(boundary);
    std::sort(sorted.begin(), sorted.end());
    return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
  }

  // The fill of `boundary` (a loop of boundary half-edges) into `fill`; true when it passes the
  // rules above.
  bool Fill(const std::vector<Id>& boundary, std::vector<Id>& fill) const
  {
    fill.clear();
    if (!IsFillable(boundary))
    {
      return false;
    }
    const size_t m = boundary.size();
    // The loop as the fill walks it (backwards), the order of the sums below.
    const std::vector<Id> loop(boundary.rbegin(), boundary.rend());
    double spacing = 0.0;
    for (Id v : loop)
    {
      spacing += std::max(this->Nearest[v], 0.0);
    }
    spacing =
      std::max({ spacing / static_cast<double>(m), this->MeanSpacing, this->MeshEdgeLength(loop) });
    return pcs::holes::FillLoopNearSamples(
      this->XYZ,
      boundary,
      this->Mesh,
      1.5 * spacing,
      MaximumDihedral,
      [this](const double* x, double reach) { return this->NearSomePoint(x, reach); },
      fill);
  }

  pcs::SurfaceMesh& Mesh;
  const double* XYZ;
  const std::vector<double>& Nearest;
  double MeanSpacing;
  const std::vector<uint8_t>& Status;
  const pcs::PointBins& Bins;
  std::vector<uint8_t>& Origin;
  std::vector<int64_t> Added; // the triangles of the last AddFill
};

//------------------------------------------------------------------------------------------------
// After the loops are closed (ours): a usable point that no triangle uses (left under a fill
// triangle, or beside the mesh where every candidate triangle at it was refused) is connected by
// the shared kernel pcs::InsertFreePoint at its nearest neighbours (`knn`, `others` per point):
// the nearest triangle is split at it, or the edge it lies beyond. A point farther from those
// triangles than their longest edge is not on that part of the surface and stays unused
// (counted). Passes are repeated while points are inserted (a point may become reachable once
// its neighbours are). The new triangles count as hole filling (origin 2). Returns the number of
// points inserted.
vtkIdType InsertUnusedPoints(pcs::SurfaceMesh& mesh,
  const double* xyz,
  const std::vector<int32_t>& knn,
  int others,
  const std::vector<uint8_t>& status,
  std::vector<uint8_t>& origin)
{
  vtkIdType inserted = 0;
  for (bool progress = others > 0; progress;)
  {
    progress = false;
    for (Id q = 0; q < mesh.GetNumberOfVertices(); ++q)
    {
      if (status[q] != Usable || !mesh.IsFree(q))
      {
        continue;
      }
      pcs::PointInsertionResult result;
      const bool done = pcs::InsertFreePoint(
        mesh, xyz, q, &knn[static_cast<size_t>(q) * others], others, true, result);
      origin.resize(static_cast<size_t>(mesh.GetNumberOfTriangleIds()), 2);
      for (const auto& restored : result.Restored)
      {
        origin[static_cast<size_t>(restored.second)] = origin[static_cast<size_t>(restored.first)];
      }
      if (done)
      {
        ++inserted;
        progress = true;
      }
    }
  }
  return inserted;
}
} // namespace

//------------------------------------------------------------------------------------------------
vtkCDTAdvancingFront::vtkCDTAdvancingFront()
{
  // Input array 0: the point normals (the active normals attribute unless set otherwise).
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::NORMALS);
}

vtkCDTAdvancingFront::~vtkCDTAdvancingFront() = default;

int vtkCDTAdvancingFront::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

//------------------------------------------------------------------------------------------------
int vtkCDTAdvancingFront::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  // Under MPI the whole cloud is meshed on process 0; the other processes' outputs stay empty.
  vtkSmartPointer<vtkPointSet> input =
    pcs::GatherInputOnFirstProcess(vtkPointSet::GetData(inputVector[0]));
  if (!input && output)
  {
    return 1;
  }
  if (!input || !output)
  {
    vtkErrorMacro("Missing input or output data object.");
    return 0;
  }
  const std::string mismatched = pcs::DropMismatchedPointArrays(input);
  if (!mismatched.empty())
  {
    vtkWarningMacro(<< mismatched);
  }
  this->NumberOfTriangles = 0;
  this->NumberOfFrontTriangles = 0;
  this->NumberOfSeedTriangles = 0;
  this->NumberOfHoleFillingTriangles = 0;
  this->NumberOfHoleTriangles = 0;
  this->NumberOfUnusedPoints = 0;
  this->NumberOfDuplicatePoints = 0;
  this->NumberOfSkippedPoints = 0;
  this->NumberOfOutliers = 0;
  this->NumberOfRemovedTriangles = 0;
  this->MeanSpacing = 0.0;
  this->NeighborhoodRadiusUsed = 0.0;
  this->ProjectedOntoLocalPlanes = false;
  this->NoiseLevel = this->NoiseShare = 0.0;

  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  this->UpdateProgress(0.01);

  // Every input point and its data pass through; triangles are added at the end.
  if (input->GetPoints())
  {
    output->SetPoints(input->GetPoints());
  }
  output->GetPointData()->PassData(input->GetPointData());
  vtkNew<vtkUnsignedCharArray> used;
  used->SetName("Used");
  used->SetNumberOfValues(numberOfPoints);
  used->FillValue(0);
  output->GetPointData()->AddArray(used);
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkUnsignedCharArray> holeFilled;
  holeFilled->SetName("HoleFilled");
  vtkNew<vtkUnsignedCharArray> holeTriangle;
  holeTriangle->SetName("HoleTriangle");
  std::vector<double> angles; // Table 2: per used point

  auto finish = [&]()
  {
    output->SetPolys(polys);
    holeFilled->SetNumberOfValues(polys->GetNumberOfCells());
    holeTriangle->SetNumberOfValues(polys->GetNumberOfCells());
    output->GetCellData()->AddArray(holeFilled);
    output->GetCellData()->AddArray(holeTriangle);
    this->NumberOfUnusedPoints = 0;
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      this->NumberOfUnusedPoints += used->GetValue(i) ? 0 : 1;
    }
    vtkFieldData* fd = output->GetFieldData();
    pcs::AddFieldCount(fd, "NumberOfPoints", numberOfPoints);
    pcs::AddFieldCount(fd, "NumberOfTriangles", this->NumberOfTriangles);
    pcs::AddFieldCount(fd, "NumberOfHoleFillingTriangles", this->NumberOfHoleFillingTriangles);
    pcs::AddFieldCount(fd, "NumberOfHoleTriangles", this->NumberOfHoleTriangles);
    pcs::AddFieldCount(fd, "NumberOfFrontTriangles", this->NumberOfFrontTriangles);
    pcs::AddFieldCount(fd, "NumberOfSeedTriangles", this->NumberOfSeedTriangles);
    pcs::AddFieldCount(fd, "NumberOfUnusedPoints", this->NumberOfUnusedPoints);
    pcs::AddFieldCount(fd, "NumberOfDuplicatePoints", this->NumberOfDuplicatePoints);
    pcs::AddFieldCount(fd, "NumberOfSkippedPoints", this->NumberOfSkippedPoints);
    pcs::AddFieldCount(fd, "NumberOfOutliers", this->NumberOfOutliers);
    pcs::AddFieldCount(fd, "NumberOfRemovedTriangles", this->NumberOfRemovedTriangles);
    double mean = std::numeric_limits<double>::quiet_NaN(), deviation = mean, low = mean,
           high = mean;
    if (!angles.empty())
    {
      double sum = 0.0;
      low = angles.front();
      high = angles.front();
      for (double a : angles)
      {
        sum += a;
        low = std::min(low, a);
        high = std::max(high, a);
      }
      mean = sum / static_cast<double>(angles.size());
      double squares = 0.0;
      for (double a : angles)
      {
        squares += (a - mean) * (a - mean);
      }
      deviation = std::sqrt(squares / static_cast<double>(angles.size()));
    }
    pcs::AddFieldValue(fd, "NormalAngleMean", mean);
    pcs::AddFieldValue(fd, "NormalAngleDeviation", deviation);
    pcs::AddFieldValue(fd, "NormalAngleMin", low);
    pcs::AddFieldValue(fd, "NormalAngleMax", high);
    pcs::AddFieldValue(fd, "MeanSpacing", this->MeanSpacing);
    pcs::AddFieldValue(fd, "NeighborhoodRadiusUsed", this->NeighborhoodRadiusUsed);
    pcs::AddFieldCount(fd, "ProjectedOntoLocalPlanes", this->ProjectedOntoLocalPlanes ? 1 : 0);
    pcs::AddFieldValue(fd, "NoiseLevel", this->NoiseLevel);
    pcs::AddFieldValue(fd, "NoiseShare", this->NoiseShare);
    if (this->NumberOfUnusedPoints > 0 && !this->GetAbortExecute())
    {
      vtkWarningMacro(<< this->NumberOfUnusedPoints << " of " << numberOfPoints
                      << " point(s) are not used by any triangle (point data Used = 0).");
    }
    this->UpdateProgress(1.0);
    return 1;
  };

  if (numberOfPoints == 0)
  {
    vtkWarningMacro("The input has no points: the output is empty.");
    return finish();
  }
  if (numberOfPoints > MaximumNumberOfPoints)
  {
    vtkErrorMacro("The input has " << numberOfPoints << " points; at most " << MaximumNumberOfPoints
                                   << " are supported.");
    return finish();
  }
  const std::string nanParameters =
    pcs::NaNParametersError({ { "NeighborhoodRadius", this->NeighborhoodRadius },
      { "NeighborhoodRadiusFactor", this->NeighborhoodRadiusFactor },
      { "MinimumNormalDot", this->MinimumNormalDot },
      { "MaximumRayDistance", this->MaximumRayDistance },
      { "MinimumTriangleArea", this->MinimumTriangleArea },
      { "HoleFillingRadiusFactor", this->HoleFillingRadiusFactor },
      { "HoleFillingMinimumNormalDot", this->HoleFillingMinimumNormalDot },
      { "NoiseBandFactor", this->NoiseBandFactor }, { "OutlierFactor", this->OutlierFactor } });
  if (!nanParameters.empty())
  {
    vtkErrorMacro(<< nanParameters);
    return finish();
  }

  // Coordinates as doubles; the finite points form the cloud the bins and the normal
  // estimation see (local ids), mapped back to input ids at the end.
  std::vector<double> all;
  std::vector<Id> inputId; // local id -> input id
  this->NumberOfSkippedPoints = pcs::ReadFiniteCoordinates(input->GetPoints(), all, inputId);
  Id local = static_cast<Id>(inputId.size());
  std::vector<double> xyz;
  if (this->NumberOfSkippedPoints == 0)
  {
    xyz.swap(all); // every point is finite: local ids are input ids
  }
  else
  {
    xyz.resize(3 * static_cast<size_t>(local));
    for (Id k = 0; k < local; ++k)
    {
      std::copy_n(&all[3 * static_cast<size_t>(inputId[k])], 3, &xyz[3 * static_cast<size_t>(k)]);
    }
    all.clear();
    all.shrink_to_fit();
  }
  // Coordinates far from 1 in magnitude are scaled by a power of two (exact) so that the exact
  // predicates and the cross products neither overflow nor underflow; lengths are converted
  // back for the counts and the parameters are converted to the scaled units.
  int exponent = 0;
  {
    std::vector<int32_t> everyPoint(static_cast<size_t>(local));
    for (Id k = 0; k < local; ++k)
    {
      everyPoint[k] = k;
    }
    exponent = pcs::PredicateSafeExponent(xyz.data(), 3, everyPoint);
    pcs::ScaleInPlace(xyz.data(), xyz.size(), exponent);
  }
  if (this->NumberOfSkippedPoints > 0)
  {
    vtkWarningMacro(
      "Skipped " << this->NumberOfSkippedPoints << " point(s) with NaN or infinite coordinates.");
  }
  if (local < 3)
  {
    vtkWarningMacro(
      "Fewer than 3 points with finite coordinates (" << local << "): no triangle is made.");
    return finish();
  }
  if (this->GetAbortExecute())
  {
    return finish();
  }
  pcs::PointBins bins;
  double bounds[6]; // of the points
  pcs::BuildSurfaceSampleBins(bins, xyz.data(), local, /*withCoordinates=*/true, bounds);
  this->UpdateProgress(0.02);
  if (this->GetAbortExecute())
  {
    return finish();
  }

  // Groups of copies of a point (firstCopy[k]: the copy of smallest id of point k's group): for
  // the estimated normals and the duplicates below. Exactly equal points
  // (pcs::FindExactDuplicates), and piles of near-coincident points (MergePiles, on the table of
  // the normal estimation, else on the table for the local spacing below).
  auto boxDiagonal = [&bounds]()
  {
    return std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
      (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
      (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  };
  double diagonal = boxDiagonal();
  std::vector<Id> firstCopy;
  pcs::FindExactDuplicates(xyz.data(), 3, nullptr, local, firstCopy);
  bool pilesChecked = false;

  // Far outliers (ours; OutlierFactor, the rule and parameter of the other surface filters):
  // left out like non-finite points, so that no front edge reaches them (clutter around a sphere
  // was meshed into pieces of long triangles, and one point 10^4 radii away gave the front a ball
  // holding every point). On a cloud without exact copies the rule reads the first table the
  // filter searches anyway (of the normal estimation, or of the local spacing when the normals
  // are given), searched here on the same bins and handed on (the same rows); otherwise, or when
  // that table is narrower than the rule's 8 neighbours, a search of its own over the distinct
  // positions (pcs::FindOutliersAndPiles). With outliers, the bins and copies are made again
  // without them (the table too).
  const bool givenNormals = this->UseInputNormals && this->GetInputArrayToProcess(0, input);
  // The table of the `others` nearest of every point on the current bins (stopped by an abort).
  auto searchNeighbors = [&](int others, std::vector<int32_t>& table)
  {
    return pcs::FindNearestNeighbors(bins, xyz.data(), static_cast<int32_t>(local), others, table,
      [this](double) { return !this->GetAbortExecute(); });
  };
  std::vector<int32_t> firstTable; // the table handed on (empty: none)
  int firstTableOthers = 0;
  if (this->OutlierFactor > 0.0 && local > pcs::PileNeighbors)
  {
    bool distinct = true;
    for (Id k = 0; k < local && distinct; ++k)
    {
      distinct = firstCopy[k] == k;
    }
    const int others = givenNormals ? std::min<int>(LocalSpacingNeighbors, local - 1)
                                    : std::max(0, std::min<int>(this->NormalSampleSize, local) - 1);
    std::vector<uint8_t> outlier;
    if (distinct && others >= pcs::OutlierNeighbors)
    {
      std::vector<int32_t> table;
      if (!searchNeighbors(others, table))
      {
        return finish();
      }
      std::vector<int32_t> firstOfPile;
      int64_t pileCopies = 0;
      this->NumberOfOutliers = pcs::FlagOutliersAndPiles(xyz.data(),
        static_cast<int32_t>(local),
        table,
        others,
        this->OutlierFactor,
        outlier,
        firstOfPile,
        pileCopies);
      if (this->NumberOfOutliers == 0)
      {
        firstTable.swap(table);
        firstTableOthers = others;
      }
    }
    else
    {
      std::vector<int32_t> ids(static_cast<size_t>(local));
      std::iota(ids.begin(), ids.end(), 0);
      std::vector<int32_t> firstOfPile; // (the piles are merged below, on the normals' table)
      int64_t pileCopies = 0;
      this->NumberOfOutliers = pcs::FindOutliersAndPiles(
        xyz.data(), ids, this->OutlierFactor, outlier, firstOfPile, pileCopies);
    }
    if (this->NumberOfOutliers > 0)
    {
      Id kept = 0;
      for (Id k = 0; k < local; ++k)
      {
        if (!outlier[k])
        {
          std::copy_n(&xyz[3 * static_cast<size_t>(k)], 3, &xyz[3 * static_cast<size_t>(kept)]);
          inputId[kept++] = inputId[k];
        }
      }
      local = kept;
      xyz.resize(3 * static_cast<size_t>(local));
      inputId.resize(static_cast<size_t>(local));
      vtkWarningMacro("Excluded " << this->NumberOfOutliers << " far outlier(s) (OutlierFactor "
                                  << this->OutlierFactor
                                  << "): point data Used = 0, field data NumberOfOutliers.");
      if (local < 3)
      {
        vtkWarningMacro("Fewer than 3 points left (" << local << "): no triangle is made.");
        return finish();
      }
      pcs::BuildSurfaceSampleBins(bins, xyz.data(), local, /*withCoordinates=*/true, bounds);
      diagonal = boxDiagonal();
      pcs::FindExactDuplicates(xyz.data(), 3, nullptr, local, firstCopy);
    }
  }

  // Normals: the input's, else estimated (vtkPCANormalEstimation, consistently oriented). Input
  // normals that are zero-length or not finite count as missing: those are estimated too.
  std::vector<double> normals(3 * static_cast<size_t>(local), 0.0);
  vtkDataArray* inputNormals =
    this->UseInputNormals ? this->GetInputArrayToProcess(0, input) : nullptr;
  if (inputNormals &&
    (inputNormals->GetNumberOfComponents() != 3 ||
      inputNormals->GetNumberOfTuples() != numberOfPoints))
  {
    vtkWarningMacro("The normals array " << (inputNormals->GetName() ? inputNormals->GetName() : "")
                                         << " is not a 3-component point array: the normals "
                                            "are estimated instead.");
    inputNormals = nullptr;
  }
  auto isBadNormal = [](const double* n)
  {
    const double length2 = Dot(n, n);
    return !std::isfinite(length2) || !(length2 > 0.0);
  };
  // The estimated normals, for every point: PCA planes oriented along a minimum spanning tree,
  // each connected part of the neighbour graph then turned outwards by its extreme points
  // (pcs::EstimateNormals), both from one table of nearest neighbours.
  // The table of nearest neighbours (knnOthers per point), kept for the local spacing when it is
  // the table of all the points.
  std::vector<int32_t> knn;
  int knnOthers = 0;
  // Scan-line sampling (pcs::AddOffLineNeighbors): the points' stretch, 3 per point (empty when
  // none has one), and whether it was looked for on a table of all the points.
  std::vector<double> stretch;
  bool scanLinesChecked = false;
  // With copies and estimated normals: the estimation's table of the distinct positions (extended
  // by the scan-line pass, positionRowsOthers per position) and their stretch, which give the
  // points their rows below instead of a search over all the points.
  std::vector<int32_t> positionRows;
  int positionRowsOthers = 0;
  std::vector<double> positionRowsStretch;
  auto estimateNormalsOn = [&](const double* pts,
                             Id count,
                             pcs::PointBins& grid,
                             std::vector<double>& estimatedNormals,
                             std::vector<int32_t>& table,
                             int& tableOthers,
                             std::vector<double>* tableStretch,
                             bool tableGiven = false)
  {
    // The neighbourhood of a point: itself and its NormalSampleSize - 1 nearest other points (the
    // NormalSampleSize nearest points of vtkPCANormalEstimation, which include the point), for
    // its plane and its edges in the orientation graph.
    std::vector<double> variation;
    pcs::EstimateNormals(
      grid,
      pts,
      count,
      this->NormalSampleSize,
      /*orient=*/true,
      estimatedNormals,
      variation,
      table,
      tableOthers,
      [this](double fraction)
      {
        this->UpdateProgress(0.02 + 0.08 * fraction);
        return !this->GetAbortExecute();
      },
      tableStretch,
      ScanLineShare,
      ScanLineRadiusFactor,
      RowLinearity,
      RowRadiusFactor,
      RowShare,
      tableGiven);
  };
  // The distinct positions (one per group of copies, firstCopy), their coordinates and (withBins)
  // bins.
  struct Positions
  {
    std::vector<Id> Ids;  // the first copy of each group, increasing
    std::vector<Id> Slot; // per point: its group's position (None for none yet)
    std::vector<double> XYZ;
    pcs::PointBins Bins;
  };
  auto distinctPositions = [&](Positions& positions, bool withBins)
  {
    positions.Ids.clear();
    positions.Slot.assign(static_cast<size_t>(local), None);
    for (Id k = 0; k < local; ++k)
    {
      if (firstCopy[k] == k)
      {
        positions.Slot[k] = static_cast<Id>(positions.Ids.size());
        positions.Ids.push_back(k);
      }
    }
    if (static_cast<Id>(positions.Ids.size()) == local)
    {
      return;
    }
    positions.XYZ.resize(3 * positions.Ids.size());
    for (size_t d = 0; d < positions.Ids.size(); ++d)
    {
      std::copy_n(&xyz[3 * static_cast<size_t>(positions.Ids[d])], 3, &positions.XYZ[3 * d]);
    }
    if (!withBins)
    {
      return;
    }
    double positionBounds[6];
    pcs::BuildSurfaceSampleBins(positions.Bins,
      positions.XYZ.data(),
      static_cast<Id>(positions.Ids.size()),
      /*withCoordinates=*/false,
      positionBounds);
  };
  // The table of the distinct positions (`width` nearest other positions each), taken from the
  // table of all the points, `knn`, on their bins (pcs::DistinctNeighbors; positions numbered as in
  // distinctPositions).
  auto positionNeighbors = [&](const Positions& positions, int width, std::vector<int32_t>& table)
  {
    std::vector<int32_t> positionOf(static_cast<size_t>(local));
    for (Id k = 0; k < local; ++k)
    {
      positionOf[k] = positions.Slot[firstCopy[k]];
    }
    pcs::DistinctNeighbors(bins,
      xyz.data(),
      static_cast<int32_t>(local),
      knn,
      knnOthers,
      positionOf,
      positions.Ids,
      width,
      table);
  };
  // Exact duplicates would fill a neighbourhood with copies of one point (a zero covariance):
  // with duplicates, the normals are estimated on the distinct points and copied to the others.
  // Piles are looked for on the estimation's table; when there are some, the normals are
  // estimated again on one point per pile.
  auto estimateNormals = [&](std::vector<double>& estimatedNormals)
  {
    for (;;)
    {
      Positions positions;
      distinctPositions(positions, /*withBins=*/true);
      if (static_cast<Id>(positions.Ids.size()) == local)
      {
        // The front's grid (the same bins): one grid for both. The table searched for the
        // outlier rule when it has the estimation's width (the same rows).
        const bool given = !firstTable.empty() &&
          firstTableOthers == std::max(0, std::min<int>(this->NormalSampleSize, local) - 1);
        if (given)
        {
          knn.swap(firstTable);
          firstTable.clear();
        }
        estimateNormalsOn(
          xyz.data(), local, bins, estimatedNormals, knn, knnOthers, &stretch, given);
        scanLinesChecked = knnOthers > 0;
        if (pilesChecked || knnOthers == 0)
        {
          return;
        }
        pilesChecked = true;
        if (!MergePiles(xyz.data(), local, {}, bins, knn, knnOthers, firstCopy))
        {
          return;
        }
        knn.clear(); // (not the table of the points to mesh)
        knnOthers = 0;
        stretch.clear();
        scanLinesChecked = false;
        continue;
      }
      const Id distinctCount = static_cast<Id>(positions.Ids.size());
      std::vector<double> distinctNormals;
      std::vector<int32_t> distinctTable; // not the table of all the points
      int distinctOthers = 0;
      std::vector<double> distinctStretch; // planes across scan lines; the stretch is found later
      estimateNormalsOn(positions.XYZ.data(),
        distinctCount,
        positions.Bins,
        distinctNormals,
        distinctTable,
        distinctOthers,
        &distinctStretch);
      estimatedNormals.assign(3 * static_cast<size_t>(local), 0.0);
      if (distinctNormals.size() != 3 * positions.Ids.size())
      {
        return; // aborted
      }
      if (!pilesChecked)
      {
        pilesChecked = true;
        if (MergePiles(positions.XYZ.data(),
              distinctCount,
              positions.Ids,
              positions.Bins,
              distinctTable,
              distinctOthers,
              firstCopy))
        {
          continue;
        }
      }
      for (Id k = 0; k < local; ++k)
      {
        const Id d = positions.Slot[firstCopy[k]];
        std::copy_n(&distinctNormals[3 * static_cast<size_t>(d)],
          3,
          &estimatedNormals[3 * static_cast<size_t>(k)]);
      }
      positionRows = std::move(distinctTable);
      positionRowsOthers = distinctOthers;
      positionRowsStretch = std::move(distinctStretch);
      return;
    }
  };
  // The normals used, passed to the output when some were estimated ("Normals", or
  // "EstimatedNormals" if the input has a "Normals" array).
  vtkSmartPointer<vtkDoubleArray> outputNormals;
  auto passNormals = [&]()
  {
    outputNormals = vtkSmartPointer<vtkDoubleArray>::New();
    const bool clash = output->GetPointData()->GetArray("Normals") != nullptr;
    outputNormals->SetName(clash ? "EstimatedNormals" : "Normals");
    outputNormals->SetNumberOfComponents(3);
    outputNormals->SetNumberOfTuples(numberOfPoints);
    outputNormals->Fill(0.0);
    for (Id k = 0; k < local; ++k)
    {
      outputNormals->SetTuple(inputId[k], &normals[3 * static_cast<size_t>(k)]);
    }
    output->GetPointData()->AddArray(outputNormals);
    if (!output->GetPointData()->GetNormals())
    {
      output->GetPointData()->SetNormals(outputNormals);
    }
  };
  if (inputNormals)
  {
    vtkIdType missing = 0;
    for (Id k = 0; k < local; ++k)
    {
      double* n = &normals[3 * static_cast<size_t>(k)];
      inputNormals->GetTuple(inputId[k], n);
      missing += isBadNormal(n) ? 1 : 0;
    }
    if (missing > 0)
    {
      // The estimated normals take the orientation of the input normals (the sign of the sum of
      // their dot products with the valid input normals; outwards if none is valid).
      vtkWarningMacro(<< missing << " of " << local << " input normal(s) (array "
                      << (inputNormals->GetName() ? inputNormals->GetName() : "")
                      << ") are zero-length or not finite: those normals are estimated "
                         "(vtkPCANormalEstimation).");
      std::vector<double> estimated;
      estimateNormals(estimated);
      double agreement = 0.0;
      for (Id k = 0; k < local; ++k)
      {
        const double* n = &normals[3 * static_cast<size_t>(k)];
        if (!isBadNormal(n))
        {
          const double length = std::sqrt(Dot(n, n));
          agreement += Dot(n, &estimated[3 * static_cast<size_t>(k)]) / length;
        }
      }
      const double sign = agreement < 0.0 ? -1.0 : 1.0;
      for (Id k = 0; k < local; ++k)
      {
        double* n = &normals[3 * static_cast<size_t>(k)];
        if (isBadNormal(n))
        {
          for (int c = 0; c < 3; ++c)
          {
            n[c] = sign * estimated[3 * static_cast<size_t>(k) + c];
          }
        }
      }
      passNormals();
    }
  }
  else
  {
    estimateNormals(normals);
    passNormals();
  }
  this->UpdateProgress(0.1);
  if (this->GetAbortExecute())
  {
    return finish();
  }

  // Unit normals; zero-length or non-finite ones exclude their point.
  std::vector<uint8_t> status(local, Usable);
  vtkIdType badNormals = 0;
  for (Id k = 0; k < local; ++k)
  {
    double* n = &normals[3 * static_cast<size_t>(k)];
    const double length = std::sqrt(Dot(n, n));
    if (!std::isfinite(length) || length == 0.0)
    {
      status[k] = BadNormal;
      ++badNormals;
      continue;
    }
    n[0] /= length;
    n[1] /= length;
    n[2] /= length;
  }
  this->NumberOfSkippedPoints += badNormals;
  if (badNormals > 0)
  {
    vtkWarningMacro("Skipped " << badNormals
                               << " point(s) whose normal is zero-length or not finite (also "
                                  "when estimated: too few distinct neighbours).");
  }

  // The table of nearest neighbours for the local spacing (the automatic NeighborhoodRadius and
  // MaximumRayDistance) and the noise band: LocalSpacingNeighbors per point (that of the normal
  // estimation when it has that size). It is also the table on which scan-line sampling is looked
  // for when the normals were not estimated on all the points (given, or estimated on the distinct
  // points).
  const bool localRay = this->MaximumRayDistance <= 0.0;
  const bool localRadius = this->NeighborhoodRadius <= 0.0;
  const bool noiseBand = this->NoiseBandFactor > 0.0;
  const int localOthers = std::min<int>(LocalSpacingNeighbors, local - 1);
  // Each point gets its position's row of `table` (knnOthers positions per row, mapped to their
  // first copies) and its position's stretch (none when `positionStretch` is empty).
  auto giveRowsOfPositions = [&](const Positions& positions,
                               const std::vector<int32_t>& table,
                               const std::vector<double>& positionStretch)
  {
    knn.resize(static_cast<size_t>(local) * knnOthers);
    stretch.clear();
    if (!positionStretch.empty())
    {
      stretch.resize(3 * static_cast<size_t>(local));
    }
    for (Id k = 0; k < local; ++k)
    {
      const Id position = positions.Slot[firstCopy[k]];
      const int32_t* row = &table[static_cast<size_t>(position) * knnOthers];
      for (int j = 0; j < knnOthers; ++j)
      {
        knn[static_cast<size_t>(k) * knnOthers + j] = row[j] >= 0 ? positions.Ids[row[j]] : -1;
      }
      if (!positionStretch.empty())
      {
        std::copy_n(&positionStretch[3 * static_cast<size_t>(position)],
          3,
          &stretch[3 * static_cast<size_t>(k)]);
      }
    }
  };
  // Each point gets its position's row from the estimation's table of the positions (see
  // positionRows), when it has the width of the table below: the same rows as the path below
  // (a search over all the points, the positions' rows taken from it, their scan-line pass).
  bool rowsOnPositions = false;
  if (!positionRows.empty() && positionRowsOthers == localOthers && knnOthers != localOthers)
  {
    Positions positions;
    distinctPositions(positions, /*withBins=*/false);
    if (positionRows.size() == positions.Ids.size() * static_cast<size_t>(localOthers) &&
      (positionRowsStretch.empty() || positionRowsStretch.size() == 3 * positions.Ids.size()))
    {
      knnOthers = localOthers;
      giveRowsOfPositions(positions, positionRows, positionRowsStretch);
      scanLinesChecked = true;
      rowsOnPositions = true;
    }
  }
  positionRows = std::vector<int32_t>();
  positionRowsStretch = std::vector<double>();
  if ((localRay || localRadius || noiseBand || !scanLinesChecked) && knnOthers != localOthers &&
    !firstTable.empty() && firstTableOthers == localOthers)
  {
    knn.swap(firstTable); // (searched for the outlier rule: the same rows)
    firstTable.clear();
    knnOthers = localOthers;
  }
  if ((localRay || localRadius || noiseBand || !scanLinesChecked) && knnOthers != localOthers)
  {
    knnOthers = 0;
    if (!searchNeighbors(localOthers, knn))
    {
      return finish();
    }
    knnOthers = localOthers;
  }
  // Piles when the normals were given (none estimated): on this table when the points are
  // distinct (before its off-line neighbours), else on the table of the distinct positions taken
  // from it (the same as a search on the positions).
  if (!pilesChecked)
  {
    pilesChecked = true;
    Positions positions;
    distinctPositions(positions, /*withBins=*/false); // (the table comes from knn)
    const Id count = static_cast<Id>(positions.Ids.size());
    if (count == local)
    {
      MergePiles(xyz.data(), local, {}, bins, knn, knnOthers, firstCopy);
    }
    else
    {
      std::vector<int32_t> positionTable;
      if (knnOthers > 0 && count > pcs::PileNeighbors)
      {
        positionNeighbors(positions, pcs::PileNeighbors, positionTable);
      }
      else
      {
        distinctPositions(positions, /*withBins=*/true); // (MergePiles searches them)
      }
      MergePiles(positions.XYZ.data(),
        count,
        positions.Ids,
        positions.Bins,
        positionTable,
        positionTable.empty() ? 0 : pcs::PileNeighbors,
        firstCopy);
    }
  }
  // Duplicates (firstCopy): in each group of copies the usable point of smallest id is kept. Then
  // the mean spacing: the mean distance from a point to its nearest point that is not a copy.
  {
    std::vector<Id> kept(local, None); // per group (indexed by its first copy): the kept point
    for (Id k = 0; k < local; ++k)
    {
      if (status[k] != Usable)
      {
        continue;
      }
      if (kept[firstCopy[k]] == None)
      {
        kept[firstCopy[k]] = k;
      }
      else
      {
        status[k] = Duplicate;
      }
    }
  }
  for (Id k = 0; k < local; ++k)
  {
    this->NumberOfDuplicatePoints += status[k] == Duplicate ? 1 : 0;
  }
  if (this->NumberOfDuplicatePoints > 0)
  {
    vtkWarningMacro(<< pcs::DuplicatesWarning(
                      this->NumberOfDuplicatePoints, "the copy of smallest id is meshed"));
  }
  // With copies (exact, or a pile's points), the table is read on the distinct positions: a row
  // is its point's position's row (pcs::DistinctNeighbors: each other position once, by its first
  // copy), and the scan-line pass below sees the same rows and bins as on the cloud without the
  // copies. Otherwise a row holding copies of a point or of a neighbour looks like a line, and the
  // local spacing and the noise band weigh copied neighbours several times: the triangles
  // depended on how many copies a point has. A pile's points count as copies of its first here
  // (DistinctNeighbors reads the first copy's row: the pile's extent is under 1e-4 of its gap to
  // the rest, so only distances that tie within that may rank differently from a search).
  if (knnOthers > 0 && !rowsOnPositions)
  {
    Positions positions;
    distinctPositions(positions, /*withBins=*/true);
    const Id count = static_cast<Id>(positions.Ids.size());
    if (count < local && count > knnOthers)
    {
      std::vector<int32_t> positionTable;
      positionNeighbors(positions, knnOthers, positionTable);
      std::vector<double> positionStretch;
      if (!scanLinesChecked &&
        pcs::AddOffLineNeighbors(positions.Bins,
          positions.XYZ.data(),
          static_cast<int32_t>(count),
          knnOthers,
          positionTable,
          &positionStretch,
          0.05,
          ScanLineRadiusFactor,
          ScanLineShare) <= 0)
      {
        positionStretch.clear();
      }
      scanLinesChecked = true;
      giveRowsOfPositions(positions, positionTable, positionStretch);
    }
  }
  if (!scanLinesChecked && knnOthers > 0 &&
    pcs::AddOffLineNeighbors(bins,
      xyz.data(),
      static_cast<int32_t>(local),
      knnOthers,
      knn,
      &stretch,
      0.05,
      ScanLineRadiusFactor,
      ScanLineShare) <= 0)
  {
    stretch.clear();
  }
  // Noisy clouds: from here on the geometry is that of the points projected onto their local
  // planes (LocalPlaneProjection; the normals and the neighbour table stay those of the input
  // points, copies of a position share its row and so its projection), filed into new bins.
  if (knnOthers > 0 && this->LocalPlaneProjection != pcs::ProjectionOff)
  {
    // With input normals only the neighbours on the point's side make its plane (a thin plate's
    // two sides stay apart). Not with estimated ones: on a noisy cloud their orientation has
    // wrong patches, and leaving those neighbours out spoilt the planes (TestNoisyClouds'
    // spheres: 5 of 32 with handles or holes, 1 without the rule).
    const double* sides = inputNormals ? normals.data() : nullptr;
    bool project = this->LocalPlaneProjection == pcs::ProjectionOn;
    if (this->LocalPlaneProjection == pcs::ProjectionAutomatic)
    {
      const pcs::SamplingNoiseMeasure noise = pcs::MeasureSamplingNoise(xyz.data(),
        static_cast<int32_t>(local), knn, knnOthers, pcs::NoiseNeighbors, sides, SameSideNormalDot);
      this->NoiseLevel = noise.Level;
      this->NoiseShare = noise.Share;
      project = noise.Noisy;
    }
    if (project)
    {
      // The planes of ProjectionNeighbors nearest (a table of its own: knn has 9 columns), one
      // projection per position (copies and piles take their first copy's).
      std::vector<int32_t> table;
      const int others = std::min<int>(pcs::ProjectionNeighbors, local - 1);
      if (!searchNeighbors(others, table))
      {
        return finish();
      }
      // Scan lines: a point whose nearest lie on its own line gets those of the lines beside it
      // (as the normal estimation's table), so that its plane is the surface's.
      pcs::AddOffLineNeighbors(bins, xyz.data(), static_cast<int32_t>(local), others, table,
        nullptr, 0.05, ScanLineRadiusFactor, ScanLineShare);
      std::vector<double> projected;
      pcs::ProjectOntoLocalPlanes(xyz.data(), static_cast<int32_t>(local), table, others, others,
        projected, sides, SameSideNormalDot);
      table = std::vector<int32_t>();
      for (Id k = 0; k < local; ++k)
      {
        std::copy_n(
          &projected[3 * static_cast<size_t>(firstCopy[k])], 3, &xyz[3 * static_cast<size_t>(k)]);
      }
      bins = pcs::PointBins();
      pcs::BuildSurfaceSampleBins(bins, xyz.data(), local, /*withCoordinates=*/true, bounds);
      this->ProjectedOntoLocalPlanes = true;
      if (!inputNormals)
      {
        // Estimated normals: the planes again, on the projected points, and their orientation
        // (on the noisy points some parts of the propagation went the wrong way).
        std::vector<double> planes, variation;
        pcs::EstimatePlaneNormals(
          xyz.data(), static_cast<int32_t>(local), knn, knnOthers, planes, variation);
        pcs::OrientNormals(
          xyz.data(), static_cast<int32_t>(local), knn, knnOthers, variation, planes);
        for (Id k = 0; k < local; ++k)
        {
          const double* m = &planes[3 * static_cast<size_t>(k)];
          if (status[k] == Usable && std::isfinite(Dot(m, m)) && Dot(m, m) > 0.0)
          {
            std::copy_n(m, 3, &normals[3 * static_cast<size_t>(k)]);
            if (outputNormals)
            {
              outputNormals->SetTuple(inputId[k], m);
            }
          }
        }
      }
    }
  }
  std::vector<double> nearest(local, -1.0);
  {
    // The smallest distance to a point that is not a copy (firstCopy): from the table of nearest
    // neighbours (nearest first) when one of them is not, else among the points within a radius,
    // the radius doubled from the width of a bin until one is found or the ball holds the whole
    // cloud.
    const double widest =
      std::max({ bins.GetBucketWidth(0), bins.GetBucketWidth(1), bins.GetBucketWidth(2) });
    const double first = widest > 0.0 ? widest : diagonal;
    vtkSMPThreadLocal<std::vector<Id>> balls;
    vtkSMPTools::For(0, local,
      [&](vtkIdType begin, vtkIdType end)
      {
        std::vector<Id>& ball = balls.Local();
        for (vtkIdType k = begin; k < end; ++k)
        {
          if (status[k] != Usable)
          {
            continue;
          }
          for (int j = 0; j < knnOthers; ++j)
          {
            const Id w = knn[static_cast<size_t>(k) * knnOthers + j];
            const bool other = w >= 0 && firstCopy[w] != firstCopy[k]; // (not a copy of k)
            const double d2 =
              other ? Distance2(&xyz[3 * static_cast<size_t>(w)], &xyz[3 * k]) : 0.0;
            if (other && !stretch.empty())
            {
              // Scan lines: the nearest in the sampling's metric, about the spacing across
              // the lines.
              const double stretched = std::sqrt(StretchedDistance2(stretch, xyz.data(), k, w));
              nearest[k] = nearest[k] < 0.0 ? stretched : std::min(nearest[k], stretched);
            }
            else if (other)
            {
              nearest[k] = std::sqrt(d2);
              break;
            }
          }
          for (double radius = first; nearest[k] < 0.0; radius *= 2.0)
          {
            FindPointsWithinRadius(bins, radius, &xyz[3 * k], ball);
            double best = -1.0;
            for (Id j : ball)
            {
              const double d2 = Distance2(&xyz[3 * static_cast<size_t>(j)], &xyz[3 * k]);
              if (firstCopy[j] != firstCopy[k] && (best < 0.0 || d2 < best))
              {
                best = d2;
              }
            }
            if (best > 0.0)
            {
              nearest[k] = std::sqrt(best);
              break;
            }
            if (!(radius > 0.0) || !(radius <= 2.0 * diagonal))
            {
              break; // no other distinct point
            }
          }
        }
      });
  }
  vtkIdType usable = 0;
  double spacing = 0.0;
  vtkIdType spaced = 0;
  for (Id k = 0; k < local; ++k)
  {
    if (status[k] == Usable)
    {
      ++usable;
      if (nearest[k] > 0.0)
      {
        spacing += nearest[k];
        ++spaced;
      }
    }
  }
  const double meanSpacing = spaced > 0 ? spacing / static_cast<double>(spaced) : 0.0;
  this->MeanSpacing = std::ldexp(meanSpacing, -exponent);
  if (usable < 3 || meanSpacing <= 0.0)
  {
    vtkWarningMacro("Fewer than 3 distinct usable points (" << usable << "): no triangle is made.");
    return finish();
  }
  this->UpdateProgress(0.2);
  if (this->GetAbortExecute())
  {
    return finish();
  }

  // The local scales of each point, from the nearest-point distances of the point and its
  // LocalSpacingNeighbors nearest others, over the mean spacing:
  // - `scale`, for the automatic MaximumRayDistance: their mean, at most 1;
  // - `radiusScale`, for the automatic NeighborhoodRadius: their median where it is at least
  //   SparseSpacingRatio, else 1 (the median, so that an isolated outlier, whose own nearest
  //   distance is large, does not get a radius reaching across the cloud; its neighbours are not
  //   affected by it either).
  std::vector<double> scale(static_cast<size_t>(local), 1.0);
  std::vector<double> radiusScale(static_cast<size_t>(local), 1.0);
  std::vector<double> spacingRatio; // the median over the mean, for Front::ExtendsFan
  if (localRay || localRadius)
  {
    spacingRatio.assign(static_cast<size_t>(local), 1.0);
    const int others = knnOthers;
    vtkSMPTools::For(0, local,
      [&](Id begin, Id end)
      {
        for (Id i = begin; i < end; ++i)
        {
          double sum = nearest[i] > 0.0 ? nearest[i] : 0.0;
          int count = nearest[i] > 0.0 ? 1 : 0;
          std::array<double, LocalSpacingNeighbors + 1> values;
          values[0] = nearest[i];
          for (int j = 0; j < others && count < static_cast<int>(values.size()); ++j)
          {
            const Id w = knn[static_cast<size_t>(i) * others + j];
            if (w >= 0 && nearest[w] > 0.0)
            {
              sum += nearest[w];
              values[count] = nearest[w];
              ++count;
            }
          }
          scale[i] = count > 0 ? std::min(1.0, sum / count / meanSpacing) : 1.0;
          if (count > 0)
          {
            std::nth_element(values.begin(), values.begin() + count / 2, values.begin() + count);
            const double ratio = values[count / 2] / meanSpacing;
            radiusScale[i] =
              ratio >= SparseSpacingRatio || ratio * DenseSpacingRatio <= 1.0 ? ratio : 1.0;
            spacingRatio[i] = ratio;
          }
        }
      });
  }

  // II.C.2 within the noise band (computed on demand).
  const NoiseBands band(xyz.data(),
    normals.data(),
    knn,
    knnOthers,
    status,
    noiseBand ? this->NoiseBandFactor : 0.0,
    meanSpacing);

  // The parameters in the (scaled) units of xyz.
  Parameters strict;
  strict.Radius = this->NeighborhoodRadius > 0.0 ? std::ldexp(this->NeighborhoodRadius, exponent)
                                                 : this->NeighborhoodRadiusFactor * meanSpacing;
  strict.LocalRadius = localRadius;
  strict.LocalRay = localRay;
  strict.MinimumNormalDot = this->MinimumNormalDot;
  strict.NoiseBand = noiseBand;
  strict.MaximumRay = this->MaximumRayDistance > 0.0
    ? std::ldexp(this->MaximumRayDistance, exponent)
    : 2.0 * meanSpacing;
  strict.MaximumCandidates = this->MaximumNumberOfCandidates;
  strict.MaximumLongEarCos = std::cos(vtkMath::RadiansFromDegrees(15.0));
  strict.RefuseRimFans = this->RefuseRimFans;
  // II.E: an explicit smallest area, or by default a shape bound that holds at every scale of a
  // cloud of mixed density (area at least 1e-6 times the squared longest edge: a height of at
  // least 2e-6 times that edge).
  strict.MinimumArea =
    this->MinimumTriangleArea > 0.0 ? std::ldexp(this->MinimumTriangleArea, 2 * exponent) : 0.0;
  strict.MinimumAreaRatio = this->MinimumTriangleArea > 0.0 ? 0.0 : 1e-6;
  this->NeighborhoodRadiusUsed = std::ldexp(strict.Radius, -exponent);

  // III.A and III.B: seeds in input order, each grown by the advancing front.
  pcs::SurfaceMesh mesh(local);
  Front front(this,
    xyz.data(),
    normals.data(),
    scale.data(),
    radiusScale.data(),
    stretch.empty() ? nullptr : stretch.data(),
    band,
    status,
    bounds,
    bins,
    mesh);
  front.SetEdgeReachCellSize(2.0 * strict.Radius);
  front.HoleSpacing = meanSpacing;
  front.SpacingRatio = spacingRatio.empty() ? nullptr : spacingRatio.data();
  front.WorkBudget =
    static_cast<uint64_t>(std::max(MinimumWork, MaximumWorkPerPoint * static_cast<double>(usable)));
  for (Id p = 0; p < local && !front.Aborted && !front.OutOfWork; ++p)
  {
    if (status[p] != Usable || !mesh.IsFree(p))
    {
      continue;
    }
    if (front.Seed(p, strict))
    {
      front.Advance(strict, false, 1);
    }
  }
  // III.C: the front edges left, with the relaxed rules. Then the pinches left (two fronts that
  // touched at a vertex and never merged) are undone, and the holes this opens are filled again,
  // this time without pinches, so that the result is a manifold.
  Parameters relaxed = strict;
  relaxed.Radius = this->HoleFillingRadiusFactor * strict.Radius;
  relaxed.MinimumNormalDot = this->HoleFillingMinimumNormalDot;
  relaxed.CloseTriangularHoles = true;
  relaxed.RefuseOneLineTriangles = false;
  relaxed.ShortTrianglesSkipNormalAgreement = true;
  // An ear that adds an edge longer than the neighbourhood radius must have no angle below 15
  // degrees (see IsAcceptableEar).
  relaxed.LongEar = strict.Radius;
  relaxed.MaximumLongEarCos = std::cos(vtkMath::RadiansFromDegrees(15.0));
  auto fillHoles = [&]()
  {
    std::vector<std::vector<Id>> loops;
    mesh.GetBoundaryLoops(loops);
    for (const std::vector<Id>& loop : loops)
    {
      for (size_t k = 0; k < loop.size(); ++k)
      {
        front.Queue(loop[k], loop[(k + 1) % loop.size()]);
      }
    }
    front.Advance(relaxed, true, 2);
  };
  if (this->HoleFilling && !front.Aborted)
  {
    fillHoles();
  }
  if (!front.Aborted)
  {
    std::vector<Id> touched;
    this->NumberOfRemovedTriangles = RemovePinches(mesh, touched);
    if (this->NumberOfRemovedTriangles > 0 && this->HoleFilling)
    {
      front.TrianglesRemoved(touched);
      front.AllowPinches = false;
      fillHoles();
    }
  }
  if (front.OutOfWork && !front.Aborted)
  {
    vtkWarningMacro("The advancing front was stopped: its work (points and mesh edges examined) "
                    "exceeded "
      << front.WorkBudget
      << ", the bound for a sampled surface of this size: the cloud does not look like a "
         "surface (a volume, or clutter around one?). The triangles made so far are kept, "
         "without pinches; the loops left are not closed.");
  }
  if (this->HoleFilling && !front.Aborted && !front.OutOfWork)
  {
    // The loops left, by the least-dihedral triangulation of their vertices (see LoopCloser).
    LoopCloser closer(mesh, xyz.data(), nearest, meanSpacing, status, bins, front.Origin);
    InsertUnusedPoints(mesh, xyz.data(), knn, knnOthers, status, front.Origin);
    closer.CloseAll();
    // The parts without an interior vertex (lone triangles, strips one triangle wide), which no
    // fill closes, are taken out while the unused points are inserted, so that their points join
    // the surface under or beside them; what could not be is put back (pcs::TakeOutStrips,
    // pcs::PutBackStrips) and its remaining points tried again.
    pcs::TakenStrips strips;
    pcs::TakeOutStrips(mesh, strips);
    InsertUnusedPoints(mesh, xyz.data(), knn, knnOthers, status, front.Origin);
    std::vector<std::pair<int64_t, int64_t>> restored;
    pcs::PutBackStrips(mesh, strips, restored);
    front.Origin.resize(static_cast<size_t>(mesh.GetNumberOfTriangleIds()), 2);
    for (const auto& pair : restored)
    {
      front.Origin[static_cast<size_t>(pair.second)] =
        front.Origin[static_cast<size_t>(pair.first)];
    }
    InsertUnusedPoints(mesh, xyz.data(), knn, knnOthers, status, front.Origin);
  }
  if (front.Aborted)
  {
    return finish(); // no triangles on abort
  }

  // Output: triangles over input ids, cell data, Used, Table 2.
  const Id triangles = static_cast<Id>(mesh.GetNumberOfTriangles());
  vtkNew<vtkTypeInt32Array> offsets;
  offsets->SetNumberOfValues(triangles + 1);
  vtkNew<vtkTypeInt32Array> connectivity;
  connectivity->SetNumberOfValues(3 * static_cast<vtkIdType>(triangles));
  holeFilled->SetNumberOfValues(triangles);
  holeTriangle->SetNumberOfValues(triangles);
  std::vector<double> angleSum(local, 0.0);
  std::vector<int> angleCount(local, 0);
  for (int64_t slot = 0, t = 0; slot < mesh.GetNumberOfTriangleIds(); ++slot)
  {
    if (mesh.IsTriangleRemoved(slot))
    {
      continue;
    }
    const int32_t* v = mesh.GetTriangle(slot);
    offsets->SetValue(t, 3 * t);
    bool hole = false;
    for (int i = 0; i < 3; ++i)
    {
      connectivity->SetValue(3 * t + i, inputId[v[i]]);
      used->SetValue(inputId[v[i]], 1);
      // (Its edge v[i] -> v[i + 1] has one triangle when the twin half-edge is unused.)
      hole = hole || mesh.IsBoundaryHalfEdge(v[i], v[(i + 1) % 3]);
    }
    holeFilled->SetValue(t, front.Origin[slot] == 2 ? 1 : 0);
    holeTriangle->SetValue(t, hole ? 1 : 0);
    this->NumberOfHoleTriangles += hole ? 1 : 0;
    this->NumberOfHoleFillingTriangles += front.Origin[slot] == 2 ? 1 : 0;
    this->NumberOfSeedTriangles += front.Origin[slot] == 0 ? 1 : 0;
    // Table 2: angle between each vertex normal and the triangle's plane.
    const double* a = &xyz[3 * static_cast<size_t>(v[0])];
    const double* b = &xyz[3 * static_cast<size_t>(v[1])];
    const double* c = &xyz[3 * static_cast<size_t>(v[2])];
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double w[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    double normal[3] = { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
      u[0] * w[1] - u[1] * w[0] };
    const double length = std::sqrt(Dot(normal, normal));
    for (int i = 0; i < 3; ++i)
    {
      const double cosine =
        std::min(1.0, std::fabs(Dot(normal, &normals[3 * static_cast<size_t>(v[i])])) / length);
      angleSum[v[i]] += std::asin(cosine) * 180.0 / 3.14159265358979323846;
      ++angleCount[v[i]];
    }
    ++t;
  }
  offsets->SetValue(triangles, 3 * triangles);
  polys->SetData(offsets, connectivity);
  for (Id k = 0; k < local; ++k)
  {
    if (angleCount[k] > 0)
    {
      angles.push_back(angleSum[k] / angleCount[k]);
    }
  }
  this->NumberOfTriangles = triangles;
  this->NumberOfFrontTriangles = triangles - this->NumberOfHoleFillingTriangles;
  if (triangles == 0)
  {
    vtkWarningMacro("No valid triangle was found among the "
      << usable
      << " usable point(s) (collinear points, inconsistent normals, or a "
         "NeighborhoodRadius too small?).");
  }
  return finish();
}

//------------------------------------------------------------------------------------------------
void vtkCDTAdvancingFront::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UseInputNormals: " << (this->UseInputNormals ? "On" : "Off") << "\n";
  os << indent << "NormalSampleSize: " << this->NormalSampleSize << "\n";
  os << indent << "NeighborhoodRadius: " << this->NeighborhoodRadius << "\n";
  os << indent << "NeighborhoodRadiusFactor: " << this->NeighborhoodRadiusFactor << "\n";
  os << indent << "MinimumNormalDot: " << this->MinimumNormalDot << "\n";
  os << indent << "MaximumRayDistance: " << this->MaximumRayDistance << "\n";
  os << indent << "MinimumTriangleArea: " << this->MinimumTriangleArea << "\n";
  os << indent << "MaximumNumberOfCandidates: " << this->MaximumNumberOfCandidates << "\n";
  os << indent << "NoiseBandFactor: " << this->NoiseBandFactor << "\n";
  os << indent << "OutlierFactor: " << this->OutlierFactor << "\n";
  os << indent << "RefuseRimFans: " << (this->RefuseRimFans ? "On" : "Off") << "\n";
  os << indent << "HoleFilling: " << (this->HoleFilling ? "On" : "Off") << "\n";
  os << indent << "HoleFillingRadiusFactor: " << this->HoleFillingRadiusFactor << "\n";
  os << indent << "HoleFillingMinimumNormalDot: " << this->HoleFillingMinimumNormalDot << "\n";
  os << indent << "LocalPlaneProjection: " << this->LocalPlaneProjection << "\n";
  os << indent << "NumberOfTriangles: " << this->NumberOfTriangles << "\n";
  os << indent << "NumberOfFrontTriangles: " << this->NumberOfFrontTriangles << "\n";
  os << indent << "NumberOfSeedTriangles: " << this->NumberOfSeedTriangles << "\n";
  os << indent << "NumberOfHoleFillingTriangles: " << this->NumberOfHoleFillingTriangles << "\n";
  os << indent << "NumberOfHoleTriangles: " << this->NumberOfHoleTriangles << "\n";
  os << indent << "NumberOfUnusedPoints: " << this->NumberOfUnusedPoints << "\n";
  os << indent << "NumberOfDuplicatePoints: " << this->NumberOfDuplicatePoints << "\n";
  os << indent << "NumberOfSkippedPoints: " << this->NumberOfSkippedPoints << "\n";
  os << indent << "NumberOfOutliers: " << this->NumberOfOutliers << "\n";
  os << indent << "NumberOfRemovedTriangles: " << this->NumberOfRemovedTriangles << "\n";
  os << indent << "MeanSpacing: " << this->MeanSpacing << "\n";
  os << indent << "NeighborhoodRadiusUsed: " << this->NeighborhoodRadiusUsed << "\n";
  os << indent << "ProjectedOntoLocalPlanes: " << this->ProjectedOntoLocalPlanes << "\n";
  os << indent << "NoiseLevel: " << this->NoiseLevel << "\n";
  os << indent << "NoiseShare: " << this->NoiseShare << "\n";
}
