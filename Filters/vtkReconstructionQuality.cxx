#include "vtkReconstructionQuality.h"

#include "pcsFieldData.h"
#include "pcsGatherInput.h"

#include "pcsCoordinateScaling.h"
#include "pcsDisjointSets.h"
#include "pcsDuplicatePoints.h"
#include "pcsProjectedTests.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLine.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkSignedCharArray.h"
#include "vtkSmartPointer.h"
#include "vtkStaticPointLocator.h"
#include "vtkTriangle.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <memory>
#include <numeric>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkReconstructionQuality);

namespace
{
using Triangle = std::array<vtkIdType, 3>;
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

//------------------------------------------------------------------------------------------------
// The triangle cells of a point set: polygons with 3 point ids (VTK_TRIANGLE, or VTK_POLYGON of
// 3 points). Other 2D cells are counted and ignored, vertex / line / 3D cells skipped.
struct TriangleCells
{
  std::vector<Triangle> Triangles;
  std::vector<vtkIdType> CellIds; // cell id of each triangle in its data set
  vtkIdType OtherPolygons = 0;    // polygons of another size, strips, other 2D cells
  vtkIdType InvalidTriangles = 0; // triangles with a point id out of range
  vtkIdType NonFinitePoints = 0;  // points with a NaN or infinite coordinate
  vtkIdType NonFiniteTriangles = 0; // triangles on such a point (ignored)
};

TriangleCells ScanTriangles(vtkPointSet* data)
{
  TriangleCells cells;
  const vtkIdType numberOfPoints = data->GetNumberOfPoints();
  // Points with a NaN or infinite coordinate cannot be measured: triangles on them are ignored.
  std::vector<char> finite(numberOfPoints, 1);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double p[3];
    data->GetPoint(i, p);
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
    {
      finite[i] = 0;
      ++cells.NonFinitePoints;
    }
  }
  auto add = [&cells, &finite, numberOfPoints](
               vtkIdType cellId, vtkIdType npts, const vtkIdType* pts) {
    if (npts != 3)
    {
      ++cells.OtherPolygons;
      return;
    }
    for (int j = 0; j < 3; ++j)
    {
      if (pts[j] < 0 || pts[j] >= numberOfPoints)
      {
        ++cells.InvalidTriangles;
        return;
      }
    }
    for (int j = 0; j < 3; ++j)
    {
      if (!finite[pts[j]])
      {
        ++cells.NonFiniteTriangles;
        return;
      }
    }
    cells.Triangles.push_back({ { pts[0], pts[1], pts[2] } });
    cells.CellIds.push_back(cellId);
  };

  if (auto* polyData = vtkPolyData::SafeDownCast(data))
  {
    // Cell ids of a vtkPolyData: vertices, lines, polygons, strips.
    vtkIdType cellId = polyData->GetNumberOfVerts() + polyData->GetNumberOfLines();
    if (vtkCellArray* polys = polyData->GetPolys())
    {
      cells.Triangles.reserve(polys->GetNumberOfCells());
      cells.CellIds.reserve(polys->GetNumberOfCells());
      auto iter = vtk::TakeSmartPointer(polys->NewIterator());
      for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell(), ++cellId)
      {
        vtkIdType npts;
        const vtkIdType* pts;
        iter->GetCurrentCell(npts, pts);
        add(cellId, npts, pts);
      }
    }
    cells.OtherPolygons += polyData->GetNumberOfStrips();
    return cells;
  }

  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
  {
    const int type = data->GetCellType(c);
    if (vtkCellTypes::GetDimension(static_cast<unsigned char>(type)) != 2)
    {
      continue;
    }
    if (type == VTK_TRIANGLE || type == VTK_POLYGON)
    {
      data->GetCellPoints(c, ids);
      add(c, ids->GetNumberOfIds(), ids->GetPointer(0));
    }
    else
    {
      ++cells.OtherPolygons;
    }
  }
  return cells;
}

bool IsCollapsed(const Triangle& t)
{
  return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
}

// The points a, b, c times the power of two that brings their largest coordinate magnitude into
// [2^-60, 2^60] (pcs::PredicateSafeExponent): exact, so orientations and angles are unchanged,
// and the products of the predicates neither overflow nor underflow (coordinates of 1e300 or
// 1e-300).
std::array<std::array<double, 3>, 3> SafelyScaled(const double a[3],
  const double b[3],
  const double c[3])
{
  std::array<std::array<double, 3>, 3> scaled;
  const double* p[3] = { a, b, c };
  for (int k = 0; k < 3; ++k)
  {
    std::copy(p[k], p[k] + 3, scaled[k].begin());
  }
  double* coordinates = scaled[0].data(); // 9 contiguous values
  pcs::ScaleInPlace(
    coordinates, 9, pcs::PredicateSafeExponent(pcs::LargestFiniteMagnitude(coordinates, 9)));
  return scaled;
}

// Exact zero-area test: the three points are collinear (pcs::projected::Collinear), decided on
// the points scaled by a power of two (exact, SafelyScaled) when their coordinates are so small
// or large that the orientation products would underflow or overflow (a surface at 1e-300).
bool HasZeroArea(const double a[3], const double b[3], const double c[3])
{
  const auto scaled = SafelyScaled(a, b, c);
  return pcs::projected::Collinear(scaled[0].data(), scaled[1].data(), scaled[2].data());
}

// Smallest interior angle in degrees; atan2(|u x v|, u . v) is accurate for small and large
// angles alike and gives 0 for a zero-length edge.
double MinimumAngle(const double a[3], const double b[3], const double c[3])
{
  const auto scaled = SafelyScaled(a, b, c);
  const double* p[3] = { scaled[0].data(), scaled[1].data(), scaled[2].data() };
  double smallest = 180.0;
  for (int i = 0; i < 3; ++i)
  {
    double u[3], v[3], w[3];
    vtkMath::Subtract(p[(i + 1) % 3], p[i], u);
    vtkMath::Subtract(p[(i + 2) % 3], p[i], v);
    vtkMath::Cross(u, v, w);
    const double angle =
      vtkMath::DegreesFromRadians(std::atan2(vtkMath::Norm(w), vtkMath::Dot(u, v)));
    smallest = std::min(smallest, angle);
  }
  return smallest;
}

// Unit normal of the triangle a, b, c from the cross product of the two edges at the vertex
// opposite its longest edge (the shorter edges: the smallest rounding error on slivers), on the
// points scaled as SafelyScaled; false (normal untouched) when the product is zero or not finite.
bool UnitNormal(const double a[3], const double b[3], const double c[3], double normal[3])
{
  const auto scaled = SafelyScaled(a, b, c);
  const double* p[3] = { scaled[0].data(), scaled[1].data(), scaled[2].data() };
  int apex = 0;
  double longest = -1.0;
  for (int i = 0; i < 3; ++i)
  {
    const double opposite = vtkMath::Distance2BetweenPoints(p[(i + 1) % 3], p[(i + 2) % 3]);
    if (opposite > longest)
    {
      longest = opposite;
      apex = i;
    }
  }
  double u[3], v[3], w[3];
  vtkMath::Subtract(p[(apex + 1) % 3], p[apex], u);
  vtkMath::Subtract(p[(apex + 2) % 3], p[apex], v);
  vtkMath::Cross(u, v, w);
  const double length = vtkMath::Normalize(w);
  if (!(length > 0.0) || !std::isfinite(length))
  {
    return false;
  }
  std::copy(w, w + 3, normal);
  return true;
}

// Unoriented angle between two unit normals in degrees, in [0, 90]: atan2(|m x n|, |m . n|),
// accurate near 0 and 90 alike.
double AcuteAngle(const double m[3], const double n[3])
{
  double w[3];
  vtkMath::Cross(m, n, w);
  return vtkMath::DegreesFromRadians(std::atan2(vtkMath::Norm(w), std::abs(vtkMath::Dot(m, n))));
}

// Twice the area of the triangle a, b, c (on the points scaled as SafelyScaled, then unscaled in
// long double, whose range holds the squares of any double coordinates).
long double TwiceArea(const double a[3], const double b[3], const double c[3])
{
  double magnitude = pcs::LargestFiniteMagnitude(a, 3);
  magnitude = pcs::LargestFiniteMagnitude(b, 3, magnitude);
  magnitude = pcs::LargestFiniteMagnitude(c, 3, magnitude);
  const int exponent = pcs::PredicateSafeExponent(magnitude);
  const auto scaled = SafelyScaled(a, b, c);
  double u[3], v[3], w[3];
  vtkMath::Subtract(scaled[1].data(), scaled[0].data(), u);
  vtkMath::Subtract(scaled[2].data(), scaled[0].data(), v);
  vtkMath::Cross(u, v, w);
  return std::ldexp(static_cast<long double>(vtkMath::Norm(w)), -2 * exponent);
}

//------------------------------------------------------------------------------------------------
// Edge topology of the non-collapsed triangles.
struct HalfEdge
{
  vtkIdType Low;      // smaller end point id
  vtkIdType High;     // larger end point id
  vtkIdType Triangle; // index in the triangle list
  int8_t Slot;        // the edge (t[Slot], t[Slot + 1]) of the triangle
  bool Forward;       // the triangle traverses Low -> High
};

struct MeshTopology
{
  const std::vector<Triangle>& Triangles;
  const std::vector<char>& Collapsed;

  std::vector<HalfEdge> HalfEdges;      // sorted by edge, then triangle
  std::vector<vtkIdType> EdgeOffsets;   // edge e: HalfEdges[EdgeOffsets[e], EdgeOffsets[e + 1])
  std::vector<vtkIdType> TriangleEdges; // 3 per triangle, slot order; -1 for collapsed ones
  std::vector<vtkIdType> VertexOffsets; // triangles around each point (non-collapsed ones)
  std::vector<vtkIdType> VertexTriangles;

  MeshTopology(const std::vector<Triangle>& triangles, const std::vector<char>& collapsed)
    : Triangles(triangles)
    , Collapsed(collapsed)
  {}

  vtkIdType NumberOfEdges() const { return static_cast<vtkIdType>(this->EdgeOffsets.size()) - 1; }
  vtkIdType Valence(vtkIdType e) const { return this->EdgeOffsets[e + 1] - this->EdgeOffsets[e]; }

  void Build(vtkIdType numberOfPoints)
  {
    const vtkIdType n = static_cast<vtkIdType>(this->Triangles.size());
    // Half-edges ordered by (Low, High, Triangle): a counting sort on Low (linear, triangles in
    // increasing order within a bucket), then each bucket - the few edges at one vertex - by
    // High. Linear time, where a global sort of 3n half-edges took most of the topology time.
    std::vector<vtkIdType> bucket(numberOfPoints + 1, 0);
    for (vtkIdType t = 0; t < n; ++t)
    {
      if (!this->Collapsed[t])
      {
        const Triangle& tri = this->Triangles[t];
        for (int j = 0; j < 3; ++j)
        {
          ++bucket[std::min(tri[j], tri[(j + 1) % 3]) + 1];
        }
      }
    }
    for (vtkIdType p = 0; p < numberOfPoints; ++p)
    {
      bucket[p + 1] += bucket[p];
    }
    this->HalfEdges.resize(bucket[numberOfPoints]);
    {
      std::vector<vtkIdType> next(bucket.begin(), bucket.end() - 1);
      for (vtkIdType t = 0; t < n; ++t)
      {
        if (this->Collapsed[t])
        {
          continue;
        }
        const Triangle& tri = this->Triangles[t];
        for (int j = 0; j < 3; ++j)
        {
          const vtkIdType a = tri[j], b = tri[(j + 1) % 3];
          this->HalfEdges[next[std::min(a, b)]++] =
            HalfEdge{ std::min(a, b), std::max(a, b), t, static_cast<int8_t>(j), a < b };
        }
      }
    }
    for (vtkIdType p = 0; p < numberOfPoints; ++p)
    {
      // Stable: triangles stay in increasing order among equal edges.
      std::stable_sort(this->HalfEdges.begin() + bucket[p], this->HalfEdges.begin() + bucket[p + 1],
        [](const HalfEdge& x, const HalfEdge& y) { return x.High < y.High; });
    }

    this->TriangleEdges.assign(3 * n, -1);
    this->EdgeOffsets.clear();
    const vtkIdType h = static_cast<vtkIdType>(this->HalfEdges.size());
    for (vtkIdType i = 0; i < h; ++i)
    {
      const HalfEdge& he = this->HalfEdges[i];
      if (i == 0 || he.Low != this->HalfEdges[i - 1].Low || he.High != this->HalfEdges[i - 1].High)
      {
        this->EdgeOffsets.push_back(i);
      }
      this->TriangleEdges[3 * he.Triangle + he.Slot] =
        static_cast<vtkIdType>(this->EdgeOffsets.size()) - 1;
    }
    this->EdgeOffsets.push_back(h);

    // Triangles around each point (compressed rows).
    this->VertexOffsets.assign(numberOfPoints + 1, 0);
    for (vtkIdType t = 0; t < n; ++t)
    {
      if (!this->Collapsed[t])
      {
        for (vtkIdType p : this->Triangles[t])
        {
          ++this->VertexOffsets[p + 1];
        }
      }
    }
    std::partial_sum(
      this->VertexOffsets.begin(), this->VertexOffsets.end(), this->VertexOffsets.begin());
    this->VertexTriangles.resize(this->VertexOffsets[numberOfPoints]);
    std::vector<vtkIdType> fill(this->VertexOffsets.begin(), this->VertexOffsets.end() - 1);
    for (vtkIdType t = 0; t < n; ++t)
    {
      if (!this->Collapsed[t])
      {
        for (vtkIdType p : this->Triangles[t])
        {
          this->VertexTriangles[fill[p]++] = t;
        }
      }
    }
  }

  // The two edges of triangle t at its point v: slots m and m + 2 where t[m] == v.
  void EdgesAtVertex(vtkIdType t, vtkIdType v, vtkIdType edges[2]) const
  {
    const Triangle& tri = this->Triangles[t];
    const int m = tri[0] == v ? 0 : (tri[1] == v ? 1 : 2);
    edges[0] = this->TriangleEdges[3 * t + m];
    edges[1] = this->TriangleEdges[3 * t + (m + 2) % 3];
  }

  // The triangle across the valence-2 edge e from triangle t.
  vtkIdType OtherTriangle(vtkIdType e, vtkIdType t) const
  {
    const HalfEdge& first = this->HalfEdges[this->EdgeOffsets[e]];
    return first.Triangle == t ? this->HalfEdges[this->EdgeOffsets[e] + 1].Triangle
                               : first.Triangle;
  }

  // The boundary edge that follows boundary edge e at its end point v: turn around v from the
  // triangle of e through valence-2 edges until a boundary edge is reached. -1 when a
  // non-manifold edge is met first.
  vtkIdType NextBoundaryEdge(vtkIdType e, vtkIdType v) const
  {
    vtkIdType t = this->HalfEdges[this->EdgeOffsets[e]].Triangle;
    vtkIdType current = e;
    const vtkIdType steps = this->VertexOffsets[v + 1] - this->VertexOffsets[v];
    for (vtkIdType step = 0; step <= steps; ++step)
    {
      vtkIdType edges[2];
      this->EdgesAtVertex(t, v, edges);
      const vtkIdType next = edges[0] == current ? edges[1] : edges[0];
      const vtkIdType valence = this->Valence(next);
      if (valence == 1)
      {
        return next;
      }
      if (valence != 2)
      {
        return -1;
      }
      t = this->OtherTriangle(next, t);
      current = next;
    }
    return -1; // not reached: the triangles around v linked by valence-2 edges form chains
  }

  vtkIdType OtherEnd(vtkIdType e, vtkIdType v) const
  {
    const HalfEdge& he = this->HalfEdges[this->EdgeOffsets[e]];
    return he.Low == v ? he.High : he.Low;
  }

  vtkIdType CountBoundaryLoops() const
  {
    const vtkIdType edges = this->NumberOfEdges();
    std::vector<char> visited(edges, 0);
    vtkIdType loops = 0;
    for (vtkIdType e0 = 0; e0 < edges; ++e0)
    {
      if (this->Valence(e0) != 1 || visited[e0])
      {
        continue;
      }
      visited[e0] = 1;
      const HalfEdge& he = this->HalfEdges[this->EdgeOffsets[e0]];
      bool closed = false;
      // Walk forwards from the High end; if the chain is open, also backwards from the Low end
      // so that every edge of the chain is visited once.
      for (vtkIdType start : { he.High, he.Low })
      {
        vtkIdType e = e0, v = start;
        for (;;)
        {
          const vtkIdType next = this->NextBoundaryEdge(e, v);
          if (next == e0)
          {
            closed = true;
            break;
          }
          if (next < 0 || visited[next])
          {
            break;
          }
          visited[next] = 1;
          v = this->OtherEnd(next, v);
          e = next;
        }
        if (closed)
        {
          break;
        }
      }
      loops += closed ? 1 : 0;
    }
    return loops;
  }
};

// Flags the points whose triangles do not form one fan (or that are on a non-manifold edge).
struct FanFunctor
{
  const MeshTopology& Topology;
  unsigned char* Flags;

  struct Scratch
  {
    std::vector<std::pair<vtkIdType, vtkIdType>> EdgeTriangle; // (edge, local triangle)
    pcs::DisjointSets<vtkIdType> Sets;
  };
  vtkSMPThreadLocal<Scratch> Local;

  FanFunctor(const MeshTopology& topology, unsigned char* flags)
    : Topology(topology)
    , Flags(flags)
  {}

  void Initialize() {}

  void operator()(vtkIdType begin, vtkIdType end)
  {
    Scratch& scratch = this->Local.Local();
    const MeshTopology& topo = this->Topology;
    for (vtkIdType v = begin; v < end; ++v)
    {
      const vtkIdType first = topo.VertexOffsets[v];
      const vtkIdType k = topo.VertexOffsets[v + 1] - first;
      if (k == 0)
      {
        this->Flags[v] = 0;
        continue;
      }
      bool onNonManifoldEdge = false;
      scratch.EdgeTriangle.clear();
      for (vtkIdType i = 0; i < k; ++i)
      {
        vtkIdType edges[2];
        topo.EdgesAtVertex(topo.VertexTriangles[first + i], v, edges);
        for (vtkIdType e : edges)
        {
          onNonManifoldEdge = onNonManifoldEdge || topo.Valence(e) > 2;
          scratch.EdgeTriangle.emplace_back(e, i);
        }
      }
      std::sort(scratch.EdgeTriangle.begin(), scratch.EdgeTriangle.end());
      scratch.Sets.Reset(k);
      for (size_t i = 1; i < scratch.EdgeTriangle.size(); ++i)
      {
        if (scratch.EdgeTriangle[i].first == scratch.EdgeTriangle[i - 1].first)
        {
          scratch.Sets.Union(scratch.EdgeTriangle[i].second, scratch.EdgeTriangle[i - 1].second);
        }
      }
      vtkIdType fans = 0;
      for (vtkIdType i = 0; i < k && fans < 2; ++i)
      {
        fans += scratch.Sets.Find(i) == i ? 1 : 0;
      }
      this->Flags[v] = (fans > 1 || onNonManifoldEdge) ? 1 : 0;
    }
  }

  void Reduce() {}
};

//------------------------------------------------------------------------------------------------
// Deterministic barycentric samples: the centroid, then the R2 sequence (Roberts 2018, additive
// recurrence on the plastic number) folded into the triangle.
std::vector<std::pair<double, double>> BarycentricSamples(int count)
{
  constexpr double alpha1 = 0.7548776662466927; // 1 / g, g = 1.32471795724474602596...
  constexpr double alpha2 = 0.5698402909980532; // 1 / g^2
  std::vector<std::pair<double, double>> samples;
  for (int s = 0; s < count; ++s)
  {
    double u = std::fmod(1.0 / 3.0 + s * alpha1, 1.0);
    double v = std::fmod(1.0 / 3.0 + s * alpha2, 1.0);
    if (u + v > 1.0)
    {
      u = 1.0 - u;
      v = 1.0 - v;
    }
    samples.emplace_back(u, v);
  }
  return samples;
}

// The sample points of a surface: its vertices, then the barycentric samples of each triangle.
struct SurfaceSamples
{
  vtkPoints* Points = nullptr;
  std::vector<vtkIdType> Vertices;
  const std::vector<Triangle>* Triangles = nullptr;
  std::vector<std::pair<double, double>> PerTriangle;

  vtkIdType Size() const
  {
    const vtkIdType triangles =
      this->Triangles ? static_cast<vtkIdType>(this->Triangles->size()) : 0;
    return static_cast<vtkIdType>(this->Vertices.size()) +
      triangles * static_cast<vtkIdType>(this->PerTriangle.size());
  }

  void Get(vtkIdType i, double x[3]) const
  {
    const vtkIdType vertices = static_cast<vtkIdType>(this->Vertices.size());
    if (i < vertices)
    {
      this->Points->GetPoint(this->Vertices[i], x);
      return;
    }
    i -= vertices;
    const vtkIdType k = static_cast<vtkIdType>(this->PerTriangle.size());
    const Triangle& t = (*this->Triangles)[i / k];
    const std::pair<double, double>& uv = this->PerTriangle[i % k];
    double a[3], b[3], c[3];
    this->Points->GetPoint(t[0], a);
    this->Points->GetPoint(t[1], b);
    this->Points->GetPoint(t[2], c);
    for (int j = 0; j < 3; ++j)
    {
      x[j] = a[j] + uv.first * (b[j] - a[j]) + uv.second * (c[j] - a[j]);
    }
  }
};

// A vtkPolyData holding the points `ids` of `points` as doubles, no cells. (Sharing the points
// instead crashed vtkStaticPointLocator's FindClosestNPoints (VTK 9.2) on a reference cloud of
// int or short points.)
vtkSmartPointer<vtkPolyData> PointCloud(vtkPoints* points, const std::vector<vtkIdType>& ids)
{
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  if (!points)
  {
    return cloud;
  }
  vtkNew<vtkPoints> subset;
  subset->SetDataTypeToDouble();
  subset->SetNumberOfPoints(static_cast<vtkIdType>(ids.size()));
  for (size_t i = 0; i < ids.size(); ++i)
  {
    double x[3];
    points->GetPoint(ids[i], x);
    subset->SetPoint(static_cast<vtkIdType>(i), x);
  }
  cloud->SetPoints(subset);
  return cloud;
}

// Squared distance from x to the triangle (a, b, c), for pruning only: the closest point is found
// by the Voronoi region of x (vertex, edge or face), from dot products with the edge vectors.
// NaN or infinite when the computation overflows or the triangle is numerically flat. Accurate
// to rounding on well-shaped triangles only (SeparatingAxes::WellShaped): on a sliver the region
// tests cancel (twice its area is a difference of products much larger than it), and the point
// taken can be far from the closest one, beyond the distance (0.063 instead of 0.0082 for a
// sliver of quality 3e-14 in TestReconstructionQualityBruteForce).
double PruningDistance2(const double x[3], const double* a, const double* b, const double* c)
{
  double ab[3], ac[3], ax[3], bx[3], cx[3];
  vtkMath::Subtract(b, a, ab);
  vtkMath::Subtract(c, a, ac);
  vtkMath::Subtract(x, a, ax);
  vtkMath::Subtract(x, b, bx);
  vtkMath::Subtract(x, c, cx);
  const double abAx = vtkMath::Dot(ab, ax), acAx = vtkMath::Dot(ac, ax);
  const double abBx = vtkMath::Dot(ab, bx), acBx = vtkMath::Dot(ac, bx);
  const double abCx = vtkMath::Dot(ab, cx), acCx = vtkMath::Dot(ac, cx);
  if (abAx <= 0.0 && acAx <= 0.0)
  {
    return vtkMath::Dot(ax, ax); // vertex a
  }
  if (abBx >= 0.0 && acBx <= abBx)
  {
    return vtkMath::Dot(bx, bx); // vertex b
  }
  if (acCx >= 0.0 && abCx <= acCx)
  {
    return vtkMath::Dot(cx, cx); // vertex c
  }
  double closest[3];
  auto along = [&closest](const double* p, const double* d, double t)
  {
    for (int i = 0; i < 3; ++i)
    {
      closest[i] = p[i] + t * d[i];
    }
  };
  // Signed areas (times |ab x ac|) of the sub-triangles opposite a, b and c.
  const double areaC = abAx * acBx - abBx * acAx;
  const double areaB = abCx * acAx - abAx * acCx;
  const double areaA = abBx * acCx - abCx * acBx;
  if (areaC <= 0.0 && abAx >= 0.0 && abBx <= 0.0)
  {
    along(a, ab, abAx / (abAx - abBx)); // edge ab
  }
  else if (areaB <= 0.0 && acAx >= 0.0 && acCx <= 0.0)
  {
    along(a, ac, acAx / (acAx - acCx)); // edge ac
  }
  else if (areaA <= 0.0 && acBx - abBx >= 0.0 && abCx - acCx >= 0.0)
  {
    double bc[3];
    vtkMath::Subtract(c, b, bc);
    along(b, bc, (acBx - abBx) / ((acBx - abBx) + (abCx - acCx))); // edge bc
  }
  else
  {
    const double sum = areaA + areaB + areaC; // inside: barycentric coordinates
    for (int i = 0; i < 3; ++i)
    {
      closest[i] = a[i] + (areaB / sum) * ab[i] + (areaC / sum) * ac[i];
    }
  }
  return vtkMath::Distance2BetweenPoints(x, closest);
}

// Squared distance from x to the box {xmin, xmax, ymin, ymax, zmin, zmax} (0 inside), computed as
// vtkStaticCellLocator does.
double Distance2ToBox(const double x[3], const double* box)
{
  double d2 = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double gap =
      x[i] < box[2 * i] ? box[2 * i] - x[i] : (x[i] > box[2 * i + 1] ? x[i] - box[2 * i + 1] : 0.0);
    d2 += gap * gap;
  }
  return d2;
}

// Squared gap between two boxes (0 when they overlap).
double BoxGap2(const double* p, const double* q)
{
  double d2 = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double gap = std::max({ p[2 * i] - q[2 * i + 1], q[2 * i] - p[2 * i + 1], 0.0 });
    d2 += gap * gap;
  }
  return d2;
}

double BoxDiagonal2(const double* box)
{
  double d2 = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    d2 += (box[2 * i + 1] - box[2 * i]) * (box[2 * i + 1] - box[2 * i]);
  }
  return d2;
}

// Makes box {xmin, xmax, ymin, ymax, zmin, zmax} empty: any point given to GrowBox enlarges it.
void EmptyBox(double box[6])
{
  for (int i = 0; i < 3; ++i)
  {
    box[2 * i] = VTK_DOUBLE_MAX;
    box[2 * i + 1] = -VTK_DOUBLE_MAX;
  }
}

void GrowBox(double box[6], const double x[3])
{
  for (int i = 0; i < 3; ++i)
  {
    box[2 * i] = std::min(box[2 * i], x[i]);
    box[2 * i + 1] = std::max(box[2 * i + 1], x[i]);
  }
}

// Separating axes of a triangle: its unit normal n and the unit in-plane normals m_i of its
// edges, pointing out of the triangle, with the triangle's extent along each m_i, all relative to
// its first point a (differences first: no cancellation far from the origin). A point y is at
// least the distance from n.(y - a) to the triangle's extent along n (the slab of its points: a
// computed normal is not exactly normal to a sliver) and at least max(m_i.(y - a) - offset_i, 0)
// along m_i; as n and m_i are orthogonal, the sum of the squares of the two gaps bounds the
// squared distance from below, for any unit n. WellShaped: twice the area is at least
// WellShapedQuality times the longest edge squared, where PruningDistance2's relative error
// (about 1e-16 / quality) stays far below the search's 1e-9 widening.
struct SeparatingAxes
{
  double Normal[3];
  double EdgeNormals[3][3];
  double EdgeOffsets[3];
  double PlaneLow, PlaneHigh; // the triangle's extent along Normal, relative to its first point
  bool Valid;
  bool WellShaped = true;

  static constexpr double WellShapedQuality = 1e-5;

  void Set(const double* corner)
  {
    double edges[3][3];
    for (int i = 0; i < 3; ++i)
    {
      vtkMath::Subtract(corner + 3 * ((i + 1) % 3), corner + 3 * i, edges[i]);
    }
    vtkMath::Cross(edges[0], edges[1], this->Normal);
    const double twiceArea = vtkMath::Normalize(this->Normal);
    this->Valid = twiceArea > 0.0;
    const double longest2 = std::max({ vtkMath::Dot(edges[0], edges[0]),
      vtkMath::Dot(edges[1], edges[1]),
      vtkMath::Dot(edges[2], edges[2]) });
    this->WellShaped = twiceArea >= WellShapedQuality * longest2; // false for NaN
    const double zero[3] = { 0.0, 0.0, 0.0 };
    const double* relative[3] = { zero, edges[0], nullptr }; // the points minus a
    double third[3];
    vtkMath::Subtract(corner + 6, corner, third);
    relative[2] = third;
    this->PlaneLow = std::min(
      { 0.0, vtkMath::Dot(this->Normal, relative[1]), vtkMath::Dot(this->Normal, relative[2]) });
    this->PlaneHigh = std::max(
      { 0.0, vtkMath::Dot(this->Normal, relative[1]), vtkMath::Dot(this->Normal, relative[2]) });
    for (int i = 0; i < 3 && this->Valid; ++i)
    {
      vtkMath::Cross(edges[i], this->Normal, this->EdgeNormals[i]); // outwards
      this->Valid = vtkMath::Normalize(this->EdgeNormals[i]) > 0.0;
      this->EdgeOffsets[i] = std::max({ vtkMath::Dot(this->EdgeNormals[i], relative[0]),
        vtkMath::Dot(this->EdgeNormals[i], relative[1]),
        vtkMath::Dot(this->EdgeNormals[i], relative[2]) });
    }
    this->Valid = this->Valid &&
      std::isfinite(this->EdgeOffsets[0] + this->EdgeOffsets[1] + this->EdgeOffsets[2]) &&
      std::isfinite(this->PlaneLow + this->PlaneHigh);
  }

  // Lower bound of the squared distance from any point within `half` (half-widths along x, y, z)
  // of `centre` to the triangle whose first point is a; 0 when not valid.
  double Gap2(const double centre[3], const double half[3], const double* a) const
  {
    if (!this->Valid)
    {
      return 0.0;
    }
    auto radius = [half](const double* axis) {
      return std::abs(axis[0]) * half[0] + std::abs(axis[1]) * half[1] +
        std::abs(axis[2]) * half[2];
    };
    double y[3];
    vtkMath::Subtract(centre, a, y);
    const double along = vtkMath::Dot(this->Normal, y), reach = radius(this->Normal);
    const double plane =
      std::max({ along - reach - this->PlaneHigh, this->PlaneLow - along - reach, 0.0 });
    double edge = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      edge = std::max(edge,
        vtkMath::Dot(this->EdgeNormals[i], y) - this->EdgeOffsets[i] -
          radius(this->EdgeNormals[i]));
    }
    const double gap2 = plane * plane + edge * edge;
    return std::isfinite(gap2) ? gap2 : 0.0;
  }
};

// Exact closest distances from many query points to a set of triangles, whatever their shapes.
//
// The queries are split recursively into halves (a k-d tree on the queries, median on the longest
// axis of their box) and every node keeps only the triangles that can be the closest one to one of
// its queries. The node's bound is an upper bound of the distance of each of its queries: the
// distance from each query to the triangle closest to the node's centre (at most the parent's
// bound). A triangle stays when three lower bounds of its distance to the node's box are within
// the bound: the gap between the boxes, the distance from the centre minus the half-diagonal, and
// the gaps along the triangle's separating axes (SeparatingAxes). A long triangle thus drops out
// near the root wherever it passes, where a grid or a tree of triangle boxes keeps it in every bin
// its box touches and tests it for every query near any part of that box (a fan of slivers or a
// triangle soup across an object made those searches quadratic). At the leaves each query
// evaluates its node's triangles with vtkTriangle::EvaluatePosition, skipping those whose box is
// farther than the best distance so far, as vtkStaticCellLocator::FindClosestPointWithinRadius
// does: the minimum, hence the result, is the same. The pruning tests are widened by a relative
// 1e-9 and 1e-9 of the triangles' box diagonal so that rounding never drops the closest triangle.
struct TriangleSearch
{
  std::vector<double> Corners; // 9 per triangle: the points in cell order
  std::vector<double> Boxes;   // 6 per triangle
  std::vector<double> Sizes;   // 1 per triangle: its box diagonal
  std::vector<SeparatingAxes> Axes;
  double Slack = 0.0;
  bool PointsOnly = false; // a cloud: each "triangle" is one point, at its plain distance

  vtkIdType Size() const { return static_cast<vtkIdType>(this->Axes.size()); }

  // The triangles, times 2^exponent, that vtkTriangle::EvaluatePosition can evaluate (the cell
  // locators skip the others, numerically flat: status -1 whatever the point); exact copies (same
  // ids in the same order) are kept once, as they have the same distances. Returns the number of
  // distinct triangles left out as numerically flat.
  vtkIdType Build(vtkPoints* points, std::vector<Triangle> triangles, int exponent)
  {
    std::sort(triangles.begin(), triangles.end());
    triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
    vtkNew<vtkTriangle> cell;
    double all[6];
    EmptyBox(all);
    for (const Triangle& triangle : triangles)
    {
      const size_t t = this->Axes.size();
      this->Corners.resize(9 * (t + 1));
      double* corner = &this->Corners[9 * t];
      double centroid[3] = { 0.0, 0.0, 0.0 };
      for (int j = 0; j < 3; ++j)
      {
        points->GetPoint(triangle[j], corner + 3 * j);
      }
      pcs::ScaleInPlace(corner, 9, exponent);
      for (int j = 0; j < 3; ++j)
      {
        for (int i = 0; i < 3; ++i)
        {
          centroid[i] += corner[3 * j + i] / 3.0;
        }
      }
      double dist2;
      if (!Evaluate(cell, centroid, corner, dist2))
      {
        this->Corners.resize(9 * t);
        continue;
      }
      this->Boxes.resize(6 * (t + 1));
      double* box = &this->Boxes[6 * t];
      EmptyBox(box);
      for (int j = 0; j < 3; ++j)
      {
        GrowBox(box, corner + 3 * j);
        GrowBox(all, corner + 3 * j);
      }
      this->Sizes.push_back(std::sqrt(BoxDiagonal2(box)));
      this->Axes.emplace_back();
      this->Axes.back().Set(corner);
    }
    this->Slack = this->Axes.empty() ? 0.0 : 1e-9 * std::sqrt(BoxDiagonal2(all));
    return static_cast<vtkIdType>(triangles.size()) - this->Size();
  }

  // The points `ids`, times 2^exponent, as degenerate triangles (the pruning tests hold for them;
  // the distance is the plain distance between points, as with vtkStaticPointLocator). Points
  // with a NaN or infinite coordinate are left out; returns 0.
  vtkIdType BuildPoints(vtkPoints* points, const std::vector<vtkIdType>& ids, int exponent)
  {
    this->PointsOnly = true;
    double all[6];
    EmptyBox(all);
    for (vtkIdType id : ids)
    {
      double x[3];
      points->GetPoint(id, x);
      if (!(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2])))
      {
        continue;
      }
      pcs::ScaleInPlace(x, 3, exponent);
      GrowBox(all, x);
      for (int j = 0; j < 3; ++j)
      {
        this->Corners.insert(this->Corners.end(), x, x + 3);
      }
      const double box[6] = { x[0], x[0], x[1], x[1], x[2], x[2] };
      this->Boxes.insert(this->Boxes.end(), box, box + 6);
      this->Sizes.push_back(0.0);
      this->Axes.emplace_back();
      this->Axes.back().Valid = false;
    }
    this->Slack = this->Axes.empty() ? 0.0 : 1e-9 * std::sqrt(BoxDiagonal2(all));
    return 0;
  }

  // The squared distance from x to a triangle by vtkTriangle::EvaluatePosition (as the cell
  // locators compute it); false when the triangle is numerically flat (status -1).
  static bool Evaluate(vtkTriangle* cell, const double x[3], const double* corner, double& dist2)
  {
    vtkPoints* pts = cell->GetPoints();
    for (int j = 0; j < 3; ++j)
    {
      pts->SetPoint(j, corner + 3 * j);
    }
    double closest[3], pcoords[3], weights[3];
    int subId = 0;
    return cell->EvaluatePosition(x, closest, subId, pcoords, dist2, weights) != -1;
  }

  // The smallest squared distance from x to the candidate triangles (all when null) if one is
  // below best2, else false (as FindClosestPointWithinRadius: a box test, then EvaluatePosition).
  // EvaluatePosition is skipped when the pruning distance is clearly beyond the best so far.
  bool Nearest(vtkTriangle* cell,
    const double x[3],
    const vtkIdType* candidates,
    size_t count,
    double& best2,
    vtkIdType& which) const
  {
    bool found = false;
    double reach = this->Widen(std::sqrt(best2));
    for (size_t k = 0; k < count; ++k)
    {
      const vtkIdType t = candidates ? candidates[k] : static_cast<vtkIdType>(k);
      if (this->PointsOnly)
      {
        const double dist2 = vtkMath::Distance2BetweenPoints(x, &this->Corners[9 * t]);
        if (dist2 < best2)
        {
          best2 = dist2;
          which = t;
          found = true;
        }
        continue;
      }
      if (!(Distance2ToBox(x, &this->Boxes[6 * t]) < best2))
      {
        continue;
      }
      const double* c = &this->Corners[9 * t];
      if (this->Axes[t].WellShaped &&
        PruningDistance2(x, c, c + 3, c + 6) > reach * reach) // false for NaN
      {
        continue;
      }
      double dist2;
      if (Evaluate(cell, x, c, dist2) && dist2 < best2)
      {
        best2 = dist2;
        which = t;
        reach = this->Widen(std::sqrt(best2));
        found = true;
      }
    }
    return found;
  }

  double Widen(double d) const { return d * (1.0 + 1e-9) + this->Slack; }

  // An upper bound of the squared distance from x to triangle t: PruningDistance2 where it is
  // accurate (a well-shaped triangle, a point), else the distance to the nearest point of its
  // edges (vtkLine::DistanceToLine gives a point of the segment: never below the distance).
  double UpperDistance2(const double x[3], vtkIdType t) const
  {
    const double* c = &this->Corners[9 * t];
    if (this->PointsOnly || this->Axes[t].WellShaped)
    {
      return PruningDistance2(x, c, c + 3, c + 6);
    }
    double parameter, closest[3];
    return std::min({ vtkLine::DistanceToLine(x, c, c + 3, parameter, closest),
      vtkLine::DistanceToLine(x, c + 3, c + 6, parameter, closest),
      vtkLine::DistanceToLine(x, c + 6, c, parameter, closest) });
  }
};

// The queries of a TriangleSearch (coordinates, results) and their k-d order.
struct TriangleQueries
{
  const TriangleSearch& Search;
  const double* Points; // 3 per query
  double* Distances;    // result: the distance, NaN when no triangle can be evaluated
  vtkIdType* Closest;   // optional result: the index of the closest triangle, -1 when none
  std::vector<vtkIdType> Order;

  static constexpr vtkIdType LeafQueries = 8;
  static constexpr size_t LeafCandidates = 8;

  struct Node
  {
    double Box[6];
    double Center[3];
    double Half[3]; // half-widths of the box
    double HalfDiagonal;
    double Bound; // upper bound of the distance of every query of the node
  };

  struct Scratch
  {
    std::deque<std::vector<vtkIdType>> Candidates; // one list per depth (growing keeps references)
  };

  TriangleQueries(const TriangleSearch& search,
    const double* points,
    double* distances,
    vtkIdType count,
    vtkIdType* closest = nullptr)
    : Search(search)
    , Points(points)
    , Distances(distances)
    , Closest(closest)
  {
    // Queries with a NaN or infinite coordinate have no distance (and no place in the tree).
    for (vtkIdType q = 0; q < count; ++q)
    {
      const double* x = points + 3 * q;
      if (std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]))
      {
        this->Order.push_back(q);
      }
      else
      {
        distances[q] = NaN;
      }
    }
  }

  Node Describe(vtkIdType begin, vtkIdType end, double bound) const
  {
    Node node;
    EmptyBox(node.Box);
    for (vtkIdType k = begin; k < end; ++k)
    {
      GrowBox(node.Box, this->Points + 3 * this->Order[k]);
    }
    for (int i = 0; i < 3; ++i)
    {
      node.Center[i] = 0.5 * (node.Box[2 * i] + node.Box[2 * i + 1]);
      node.Half[i] = 0.5 * (node.Box[2 * i + 1] - node.Box[2 * i]);
    }
    node.HalfDiagonal = 0.5 * std::sqrt(BoxDiagonal2(node.Box));
    node.Bound = bound;
    return node;
  }

  // The triangles of `from` that can be the closest one to a query of the node [begin, end);
  // tightens node.Bound. The distance from the centre and the separating axes are only tested for
  // the triangles larger than the node: for the others the gap between the boxes is as tight.
  void Filter(Node& node,
    vtkIdType begin,
    vtkIdType end,
    const std::vector<vtkIdType>& from,
    std::vector<vtkIdType>& to) const
  {
    const TriangleSearch& s = this->Search;
    to.clear();
    double reach = s.Widen(node.Bound);
    vtkIdType nearest = -1;
    double nearest2 = std::numeric_limits<double>::infinity();
    for (vtkIdType t : from)
    {
      const double* box = &s.Boxes[6 * t];
      if (BoxGap2(box, node.Box) > reach * reach)
      {
        continue;
      }
      to.push_back(t);
      if (Distance2ToBox(node.Center, box) < nearest2)
      {
        const double d2 = s.UpperDistance2(node.Center, t);
        if (d2 < nearest2) // false for NaN
        {
          nearest2 = d2;
          nearest = t;
        }
      }
    }
    if (nearest >= 0)
    {
      // Every query is within its distance to the triangle closest to the centre.
      double farthest2 = 0.0;
      for (vtkIdType k = begin; k < end; ++k)
      {
        const double d2 = s.UpperDistance2(this->Points + 3 * this->Order[k], nearest);
        farthest2 =
          std::isfinite(d2) ? std::max(farthest2, d2) : std::numeric_limits<double>::infinity();
      }
      node.Bound = std::min(node.Bound, s.Widen(std::sqrt(farthest2)));
      reach = s.Widen(node.Bound);
    }
    if (!std::isfinite(reach))
    {
      return;
    }
    const double reach2 = reach * reach;
    const double far = s.Widen(node.Bound + node.HalfDiagonal);
    size_t kept = 0;
    for (vtkIdType t : to)
    {
      if (BoxGap2(&s.Boxes[6 * t], node.Box) > reach2)
      {
        continue;
      }
      if (s.Sizes[t] > 2.0 * node.HalfDiagonal)
      {
        const double* c = &s.Corners[9 * t];
        const double d2 =
          s.Axes[t].WellShaped ? PruningDistance2(node.Center, c, c + 3, c + 6) : 0.0;
        if ((std::isfinite(d2) && std::sqrt(d2) > far) ||
          s.Axes[t].Gap2(node.Center, node.Half, c) > reach2)
        {
          continue;
        }
      }
      to[kept++] = t;
    }
    to.resize(kept);
  }

  // Splits the queries [begin, end) at the median of the longest axis of the node's box.
  vtkIdType Split(const Node& node, vtkIdType begin, vtkIdType end)
  {
    int axis = 0;
    for (int i = 1; i < 3; ++i)
    {
      axis = node.Half[i] > node.Half[axis] ? i : axis;
    }
    const vtkIdType middle = begin + (end - begin) / 2;
    const double* pts = this->Points;
    std::nth_element(this->Order.begin() + begin,
      this->Order.begin() + middle,
      this->Order.begin() + end,
      [pts, axis](vtkIdType a, vtkIdType b) { return pts[3 * a + axis] < pts[3 * b + axis]; });
    return middle;
  }

  // Each query of the leaf against the leaf's triangles within the node's bound, then against
  // every triangle if none was within it (rounding beyond the slack).
  void Leaf(vtkTriangle* cell,
    const Node& node,
    vtkIdType begin,
    vtkIdType end,
    const std::vector<vtkIdType>& candidates) const
  {
    const double reach = this->Search.Widen(node.Bound);
    for (vtkIdType k = begin; k < end; ++k)
    {
      const vtkIdType q = this->Order[k];
      const double* x = this->Points + 3 * q;
      double best2 = std::isnan(reach) ? std::numeric_limits<double>::infinity() : reach * reach;
      vtkIdType which = -1;
      bool found =
        this->Search.Nearest(cell, x, candidates.data(), candidates.size(), best2, which);
      if (!found && !std::isinf(reach))
      {
        best2 = std::numeric_limits<double>::infinity();
        found = this->Search.Nearest(
          cell, x, nullptr, static_cast<size_t>(this->Search.Size()), best2, which);
      }
      this->Distances[q] = found ? std::sqrt(best2) : NaN;
      if (this->Closest)
      {
        this->Closest[q] = found ? which : -1;
      }
    }
  }

  // Solves the queries [begin, end), whose closest triangles are among `candidates` and whose
  // distances are at most `bound`.
  void Descend(vtkTriangle* cell,
    vtkIdType begin,
    vtkIdType end,
    const std::vector<vtkIdType>& candidates,
    double bound,
    Scratch& scratch,
    size_t depth)
  {
    if (scratch.Candidates.size() <= depth)
    {
      scratch.Candidates.resize(depth + 1);
    }
    std::vector<vtkIdType>& kept = scratch.Candidates[depth];
    Node node = this->Describe(begin, end, bound);
    this->Filter(node, begin, end, candidates, kept);
    if (end - begin <= LeafQueries || kept.size() <= LeafCandidates)
    {
      this->Leaf(cell, node, begin, end, kept);
      return;
    }
    const vtkIdType middle = this->Split(node, begin, end);
    this->Descend(cell, begin, middle, kept, node.Bound, scratch, depth + 1);
    this->Descend(cell, middle, end, kept, node.Bound, scratch, depth + 1);
  }
};

// Runs TriangleQueries in parallel: the top of the tree is split serially into tasks (up to 64
// subtrees with their triangles), each task then descends in one thread. The results do not
// depend on the thread count: each query's distance is the minimum over the same triangles.
struct TriangleQueryFunctor
{
  TriangleQueries& Queries;
  struct Task
  {
    vtkIdType Begin, End;
    std::vector<vtkIdType> Candidates;
    double Bound;
  };
  std::vector<Task> Tasks;
  vtkSMPThreadLocalObject<vtkTriangle> Cell;
  vtkSMPThreadLocal<TriangleQueries::Scratch> Local;

  explicit TriangleQueryFunctor(TriangleQueries& queries)
    : Queries(queries)
  {
    std::vector<vtkIdType> all(static_cast<size_t>(queries.Search.Size()));
    std::iota(all.begin(), all.end(), vtkIdType(0));
    this->Plan(0,
      static_cast<vtkIdType>(queries.Order.size()),
      all,
      std::numeric_limits<double>::infinity(),
      0);
  }

  void Plan(vtkIdType begin,
    vtkIdType end,
    const std::vector<vtkIdType>& candidates,
    double bound,
    int depth)
  {
    if (depth == 6 || end - begin <= 4 * TriangleQueries::LeafQueries)
    {
      this->Tasks.push_back(Task{ begin, end, candidates, bound });
      return;
    }
    std::vector<vtkIdType> kept;
    auto node = this->Queries.Describe(begin, end, bound);
    this->Queries.Filter(node, begin, end, candidates, kept);
    const vtkIdType middle = this->Queries.Split(node, begin, end);
    this->Plan(begin, middle, kept, node.Bound, depth + 1);
    this->Plan(middle, end, kept, node.Bound, depth + 1);
  }

  void Initialize() {}

  void operator()(vtkIdType begin, vtkIdType end)
  {
    vtkTriangle* cell = this->Cell.Local();
    for (vtkIdType k = begin; k < end; ++k)
    {
      const Task& task = this->Tasks[k];
      if (task.End > task.Begin)
      {
        this->Queries.Descend(
          cell, task.Begin, task.End, task.Candidates, task.Bound, this->Local.Local(), 0);
      }
    }
  }

  void Reduce() {}
};

// Scales the points of `cloud` (double coordinates, its own copy: PointCloud) by the power of two
// that brings their largest finite coordinate magnitude into [2^-60, 2^60]
// (pcs::PredicateSafeExponent), when they are outside it: nearest-neighbour distances then
// neither overflow nor underflow. Returns the exponent.
int ScaleSafely(vtkPolyData* cloud)
{
  auto* coordinates = vtkDoubleArray::SafeDownCast(cloud->GetPoints()->GetData());
  double* xyz = coordinates->GetPointer(0);
  const size_t count = 3 * static_cast<size_t>(cloud->GetNumberOfPoints());
  const int exponent = pcs::PredicateSafeExponent(pcs::LargestFiniteMagnitude(xyz, count));
  if (exponent != 0)
  {
    pcs::ScaleInPlace(xyz, count, exponent);
    coordinates->Modified();
    cloud->GetPoints()->Modified();
  }
  return exponent;
}

// What the distances are measured to: the triangles of non-zero area when there are any, else
// points (a TriangleSearch of either is built for the samples, MeasureDistances).
struct DistanceTarget
{
  vtkPoints* Points = nullptr;
  std::vector<Triangle> Triangles;
  std::vector<vtkIdType> Cloud; // without triangles: the point ids

  bool IsEmpty() const { return this->Triangles.empty() && this->Cloud.empty(); }

  // Triangles of non-zero area when there are any, else the points `cloud` (all points of
  // `points` when cloud is null).
  void Build(vtkPoints* points,
    const std::vector<Triangle>& triangles,
    const std::vector<vtkIdType>* cloud)
  {
    this->Points = points;
    if (!triangles.empty())
    {
      this->Triangles = triangles;
    }
    else if (cloud)
    {
      this->Cloud = *cloud;
    }
    else
    {
      this->Cloud.resize(points ? points->GetNumberOfPoints() : 0);
      std::iota(this->Cloud.begin(), this->Cloud.end(), vtkIdType(0));
    }
  }
};

// The coordinates of the samples.
struct SampleFunctor
{
  const SurfaceSamples& Samples;
  double* Points;

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    for (vtkIdType i = begin; i < end; ++i)
    {
      this->Samples.Get(i, this->Points + 3 * i);
    }
  }
};

// Distance from every sample to the target, one value per sample (NaN if none is found). The
// samples and the target are scaled by the power of two that brings their
// largest coordinate magnitude into [2^-60, 2^60] (pcs::PredicateSafeExponent; none for most
// data): EvaluatePosition's products then neither overflow nor underflow, and as the scaling is
// exact the distances are those of the unscaled computation, where it does not overflow.
// With `normalSamples`, `normals` receives for each of these samples the unit normal of the
// target triangle closest to it (3 values; NaN when the target is a cloud or none was found).
// Returns the number of triangles of the target left out as numerically flat.
vtkIdType MeasureDistances(const SurfaceSamples& samples,
  const DistanceTarget& target,
  double* out,
  const std::vector<vtkIdType>* normalSamples = nullptr,
  double* normals = nullptr)
{
  const vtkIdType n = samples.Size();
  std::vector<double> xyz(3 * static_cast<size_t>(n));
  SampleFunctor prepare{ samples, xyz.data() };
  vtkSMPTools::For(0, n, prepare);
  double largest = pcs::LargestFiniteMagnitude(xyz.data(), xyz.size());
  for (const Triangle& t : target.Triangles)
  {
    for (vtkIdType p : t)
    {
      largest = pcs::LargestFiniteMagnitude(target.Points->GetPoint(p), 3, largest);
    }
  }
  for (vtkIdType p : target.Cloud)
  {
    largest = pcs::LargestFiniteMagnitude(target.Points->GetPoint(p), 3, largest);
  }
  const int exponent = pcs::PredicateSafeExponent(largest);
  pcs::ScaleInPlace(xyz.data(), xyz.size(), exponent);
  TriangleSearch search;
  const vtkIdType flat = target.Triangles.empty()
    ? search.BuildPoints(target.Points, target.Cloud, exponent)
    : search.Build(target.Points, target.Triangles, exponent);
  std::vector<vtkIdType> closest(normalSamples ? static_cast<size_t>(n) : 0, -1);
  if (search.Size() > 0)
  {
    TriangleQueries queries(search, xyz.data(), out, n, normalSamples ? closest.data() : nullptr);
    TriangleQueryFunctor run(queries);
    vtkSMPTools::For(0, static_cast<vtkIdType>(run.Tasks.size()), 1, run);
  }
  pcs::ScaleInPlace(out, static_cast<size_t>(n), -exponent);
  if (normalSamples)
  {
    // The normal's direction does not depend on the scaling by 2^exponent.
    for (size_t i = 0; i < normalSamples->size(); ++i)
    {
      const vtkIdType t = closest[(*normalSamples)[i]];
      const double* c = t >= 0 ? &search.Corners[9 * t] : nullptr;
      if (!(c && !search.PointsOnly && UnitNormal(c, c + 3, c + 6, normals + 3 * i)))
      {
        std::fill(normals + 3 * i, normals + 3 * i + 3, NaN);
      }
    }
  }
  return flat;
}

// Distance from every point of `cloud` to its nearest other point at a non-zero distance (NaN
// when all the points coincide with it). One query per distinct position (Queries[q], with
// Copies[q] points at that position): its copies share the result, and the first query asks for
// the copies plus one, so a pile of d copies costs one query of d + 1 points instead of d
// queries of about d points each.
struct SpacingFunctor
{
  vtkPolyData* Cloud;
  vtkStaticPointLocator* Locator;
  const vtkIdType* Queries;
  const vtkIdType* Copies;
  double* Spacing;
  vtkSMPThreadLocalObject<vtkIdList> Ids;

  SpacingFunctor(vtkPolyData* cloud, vtkStaticPointLocator* locator, const vtkIdType* queries,
    const vtkIdType* copies, double* spacing)
    : Cloud(cloud)
    , Locator(locator)
    , Queries(queries)
    , Copies(copies)
    , Spacing(spacing)
  {}

  void Initialize() {}

  void operator()(vtkIdType begin, vtkIdType end)
  {
    vtkIdList* ids = this->Ids.Local();
    const vtkIdType n = this->Cloud->GetNumberOfPoints();
    double x[3], y[3];
    for (vtkIdType q = begin; q < end; ++q)
    {
      const vtkIdType i = this->Queries[q];
      this->Cloud->GetPoint(i, x);
      double best = NaN;
      // Exact duplicates (distance 0) come first: widen the query until a distinct point shows.
      for (vtkIdType k = std::max<vtkIdType>(2, this->Copies[q] + 1);; k *= 2)
      {
        const vtkIdType count = std::min(k, n);
        this->Locator->FindClosestNPoints(static_cast<int>(count), x, ids);
        for (vtkIdType j = 0; j < ids->GetNumberOfIds(); ++j)
        {
          this->Cloud->GetPoint(ids->GetId(j), y);
          const double d2 = vtkMath::Distance2BetweenPoints(x, y);
          if (d2 > 0.0 && !(d2 >= best * best))
          {
            best = std::sqrt(d2);
          }
        }
        if (!std::isnan(best) || count == n)
        {
          break;
        }
      }
      this->Spacing[i] = best;
    }
  }

  void Reduce() {}
};

// Mean of the non-NaN values, NaN when there are none.
double MeanOfDefined(const std::vector<double>& values)
{
  double sum = 0.0;
  vtkIdType count = 0;
  for (double v : values)
  {
    if (!std::isnan(v))
    {
      sum += v;
      ++count;
    }
  }
  return count > 0 ? sum / count : NaN;
}

// Mean and maximum of a range of distances; NaN for an empty range or if any value is NaN.
void MeanAndMax(const double* begin, const double* end, double& mean, double& maximum)
{
  if (begin == end)
  {
    mean = maximum = NaN;
    return;
  }
  double sum = 0.0;
  maximum = 0.0;
  for (const double* d = begin; d != end; ++d)
  {
    sum += *d;
    maximum = (std::isnan(*d) || *d > maximum) ? *d : maximum;
    if (std::isnan(maximum))
    {
      break;
    }
  }
  mean = std::isnan(maximum) ? NaN : sum / static_cast<double>(end - begin);
}

// Cell data ReferenceNormalAngle and field data MeanReferenceNormalAngle,
// AreaWeightedMeanReferenceNormalAngle, NumberOfStandingTriangles (angle above standingAngle) from
// the unit normals of the reference triangles closest to the mesh triangles' centroids (3 per
// triangle, NaN where none); without them (no reference surface) NaN and -1.
void AddReferenceNormalAngles(vtkPolyData* output,
  vtkPoints* points,
  const std::vector<Triangle>& triangles,
  const std::vector<vtkIdType>& cellIds,
  const std::vector<char>& zeroArea,
  const double* referenceNormals,
  double standingAngle)
{
  vtkNew<vtkDoubleArray> angles;
  angles->SetName("ReferenceNormalAngle");
  angles->SetNumberOfValues(output->GetNumberOfCells());
  angles->FillValue(NaN);
  double mean = NaN, areaWeightedMean = NaN;
  vtkIdType standing = -1;
  if (referenceNormals)
  {
    double sum = 0.0;
    long double weightedSum = 0.0L, totalWeight = 0.0L;
    vtkIdType measured = 0;
    standing = 0;
    for (size_t t = 0; t < triangles.size(); ++t)
    {
      const double* reference = referenceNormals + 3 * t;
      double a[3], b[3], c[3], normal[3];
      points->GetPoint(triangles[t][0], a);
      points->GetPoint(triangles[t][1], b);
      points->GetPoint(triangles[t][2], c);
      if (zeroArea[t] || std::isnan(reference[0]) || !UnitNormal(a, b, c, normal))
      {
        continue;
      }
      const double angle = AcuteAngle(normal, reference);
      angles->SetValue(cellIds[t], angle);
      sum += angle;
      ++measured;
      standing += angle > standingAngle ? 1 : 0;
      const long double weight = TwiceArea(a, b, c);
      weightedSum += weight * angle;
      totalWeight += weight;
    }
    mean = measured > 0 ? sum / measured : NaN;
    areaWeightedMean = totalWeight > 0.0L ? static_cast<double>(weightedSum / totalWeight) : NaN;
  }
  output->GetCellData()->AddArray(angles);
  vtkFieldData* fd = output->GetFieldData();
  pcs::AddFieldValue(fd, "MeanReferenceNormalAngle", mean);
  pcs::AddFieldValue(fd, "AreaWeightedMeanReferenceNormalAngle", areaWeightedMean);
  pcs::AddFieldCount(fd, "NumberOfStandingTriangles", standing);
}

} // namespace

//------------------------------------------------------------------------------------------------
vtkReconstructionQuality::vtkReconstructionQuality()
{
  this->SetNumberOfInputPorts(2);
}

vtkReconstructionQuality::~vtkReconstructionQuality() = default;

void vtkReconstructionQuality::SetReferenceConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkReconstructionQuality::SetReferenceData(vtkDataObject* data)
{
  this->SetInputData(1, data);
}

int vtkReconstructionQuality::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  }
  else
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------------------------
int vtkReconstructionQuality::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  // Under MPI the mesh and the reference are measured whole on process 0; the other processes'
  // outputs stay empty.
  const bool hasReference = vtkPointSet::GetData(inputVector[1]) != nullptr;
  vtkSmartPointer<vtkPointSet> gathered =
    pcs::GatherInputOnFirstProcess(vtkPolyData::GetData(inputVector[0]));
  vtkSmartPointer<vtkPointSet> gatheredReference = hasReference
    ? pcs::GatherInputOnFirstProcess(vtkPointSet::GetData(inputVector[1]))
    : nullptr;
  if (!gathered && output)
  {
    return 1;
  }
  const std::string mismatched = pcs::DropMismatchedPointArrays(gathered);
  if (!mismatched.empty())
  {
    vtkWarningMacro(<< mismatched);
  }
  vtkPolyData* input = vtkPolyData::SafeDownCast(gathered);
  vtkPointSet* reference = gatheredReference;
  if (!input || !output)
  {
    vtkErrorMacro("Missing input or output data object.");
    return 0;
  }
  output->ShallowCopy(input);
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  const vtkIdType numberOfCells = input->GetNumberOfCells();
  vtkPoints* points = input->GetPoints();

  // Triangles.
  TriangleCells cells = ScanTriangles(input);
  const std::vector<Triangle>& triangles = cells.Triangles;
  const vtkIdType numberOfTriangles = static_cast<vtkIdType>(triangles.size());
  if (numberOfPoints == 0)
  {
    vtkWarningMacro("The input mesh has no points: every count is zero.");
  }
  else if (numberOfTriangles == 0)
  {
    vtkWarningMacro("The input mesh has no triangles: every count is zero.");
  }
  if (cells.OtherPolygons > 0)
  {
    vtkWarningMacro("Ignored " << cells.OtherPolygons
                               << " polygon(s) or strip(s) that are not triangles (they are not "
                                  "triangulated).");
  }
  if (cells.NonFinitePoints > 0)
  {
    vtkWarningMacro(<< cells.NonFinitePoints
                    << " point(s) have NaN or infinite coordinates; they are counted as unused"
                    << (cells.NonFiniteTriangles > 0 ? " and the " : "")
                    << (cells.NonFiniteTriangles > 0 ? std::to_string(cells.NonFiniteTriangles)
                                                     : std::string())
                    << (cells.NonFiniteTriangles > 0 ? " triangle(s) on them are ignored." : "."));
  }
  if (cells.InvalidTriangles > 0)
  {
    vtkWarningMacro(
      "Ignored " << cells.InvalidTriangles << " triangle(s) with a point id out of range.");
  }

  std::vector<char> collapsed(numberOfTriangles, 0);
  std::vector<char> zeroArea(numberOfTriangles, 0);
  std::vector<double> minAngles(numberOfTriangles, 0.0);
  vtkIdType degenerate = 0;
  for (vtkIdType t = 0; t < numberOfTriangles; ++t)
  {
    double a[3], b[3], c[3];
    points->GetPoint(triangles[t][0], a);
    points->GetPoint(triangles[t][1], b);
    points->GetPoint(triangles[t][2], c);
    collapsed[t] = IsCollapsed(triangles[t]) ? 1 : 0;
    zeroArea[t] = (collapsed[t] || HasZeroArea(a, b, c)) ? 1 : 0;
    minAngles[t] = zeroArea[t] ? 0.0 : MinimumAngle(a, b, c);
    degenerate += zeroArea[t];
  }

  // Duplicates: same sorted id triple as an earlier triangle.
  vtkIdType duplicates = 0;
  {
    std::vector<Triangle> sorted(triangles);
    for (Triangle& t : sorted)
    {
      std::sort(t.begin(), t.end());
    }
    vtkSMPTools::Sort(sorted.begin(), sorted.end());
    for (size_t i = 1; i < sorted.size(); ++i)
    {
      duplicates += sorted[i] == sorted[i - 1] ? 1 : 0;
    }
  }
  this->UpdateProgress(0.1);
  if (this->GetAbortExecute())
  {
    return 1; // aborted: the output is the input mesh, without measures
  }

  // Edges, fans, components, loops, orientation.
  MeshTopology topology(triangles, collapsed);
  topology.Build(numberOfPoints);
  if (this->GetAbortExecute())
  {
    return 1; // aborted: the output is the input mesh, without measures
  }
  const vtkIdType numberOfEdges = topology.NumberOfEdges();
  vtkIdType boundaryEdges = 0, nonManifoldEdges = 0, interiorEdges = 0, consistentEdges = 0;
  for (vtkIdType e = 0; e < numberOfEdges; ++e)
  {
    const vtkIdType valence = topology.Valence(e);
    boundaryEdges += valence == 1 ? 1 : 0;
    nonManifoldEdges += valence > 2 ? 1 : 0;
    if (valence == 2)
    {
      ++interiorEdges;
      const HalfEdge* he = &topology.HalfEdges[topology.EdgeOffsets[e]];
      consistentEdges += he[0].Forward != he[1].Forward ? 1 : 0;
    }
  }

  vtkNew<vtkUnsignedCharArray> used;
  used->SetName("Used");
  used->SetNumberOfValues(numberOfPoints);
  used->FillValue(0);
  for (const Triangle& t : triangles)
  {
    for (vtkIdType p : t)
    {
      used->SetValue(p, 1);
    }
  }
  vtkIdType numberOfUsedPoints = 0, topologicalVertices = 0;
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    numberOfUsedPoints += used->GetValue(p);
    topologicalVertices += topology.VertexOffsets[p + 1] > topology.VertexOffsets[p] ? 1 : 0;
  }

  vtkNew<vtkUnsignedCharArray> nonManifoldVertex;
  nonManifoldVertex->SetName("NonManifoldVertex");
  nonManifoldVertex->SetNumberOfValues(numberOfPoints);
  {
    FanFunctor fans(topology, nonManifoldVertex->GetPointer(0));
    vtkSMPTools::For(0, numberOfPoints, fans);
  }
  if (this->GetAbortExecute())
  {
    return 1; // aborted: the output is the input mesh, without measures
  }
  vtkIdType nonManifoldVertices = 0;
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    nonManifoldVertices += nonManifoldVertex->GetValue(p);
  }

  // Connected components through shared edges.
  pcs::DisjointSets<vtkIdType> components(numberOfTriangles);
  for (vtkIdType e = 0; e < numberOfEdges; ++e)
  {
    for (vtkIdType h = topology.EdgeOffsets[e] + 1; h < topology.EdgeOffsets[e + 1]; ++h)
    {
      components.Union(topology.HalfEdges[h - 1].Triangle, topology.HalfEdges[h].Triangle);
    }
  }
  vtkIdType numberOfComponents = 0;
  for (vtkIdType t = 0; t < numberOfTriangles; ++t)
  {
    numberOfComponents += (!collapsed[t] && components.Find(t) == t) ? 1 : 0;
  }

  const vtkIdType boundaryLoops = topology.CountBoundaryLoops();
  if (this->GetAbortExecute())
  {
    return 1; // aborted: the output is the input mesh, without measures
  }
  const vtkIdType faces = numberOfTriangles -
    static_cast<vtkIdType>(std::count(collapsed.begin(), collapsed.end(), char(1)));
  const vtkIdType euler = topologicalVertices - numberOfEdges + faces;

  // Genus of a closed, manifold, orientable mesh: orient every component by propagation across
  // its edges; a contradiction means a non-orientable component.
  vtkIdType genus = -1;
  if (faces > 0 && boundaryEdges == 0 && nonManifoldEdges == 0 && nonManifoldVertices == 0)
  {
    std::vector<signed char> flip(numberOfTriangles, -1);
    bool orientable = true;
    std::vector<vtkIdType> stack;
    for (vtkIdType seed = 0; seed < numberOfTriangles && orientable; ++seed)
    {
      if (collapsed[seed] || flip[seed] >= 0)
      {
        continue;
      }
      flip[seed] = 0;
      stack.push_back(seed);
      while (!stack.empty() && orientable)
      {
        const vtkIdType t = stack.back();
        stack.pop_back();
        for (int j = 0; j < 3; ++j)
        {
          const vtkIdType e = topology.TriangleEdges[3 * t + j];
          const HalfEdge* he = &topology.HalfEdges[topology.EdgeOffsets[e]];
          const HalfEdge& mine = he[0].Triangle == t ? he[0] : he[1];
          const HalfEdge& theirs = he[0].Triangle == t ? he[1] : he[0];
          // Consistent after flipping iff the two traversal directions differ.
          const signed char required =
            static_cast<signed char>(flip[t] ^ (mine.Forward == theirs.Forward ? 1 : 0));
          if (flip[theirs.Triangle] < 0)
          {
            flip[theirs.Triangle] = required;
            stack.push_back(theirs.Triangle);
          }
          else if (flip[theirs.Triangle] != required)
          {
            orientable = false;
            break;
          }
        }
      }
    }
    if (orientable)
    {
      genus = (2 * numberOfComponents - euler) / 2;
    }
  }

  // 1st percentile (nearest rank) of the per-triangle minimum angle.
  double minAngleP1 = NaN;
  if (numberOfTriangles > 0)
  {
    std::vector<double> angles(minAngles);
    const vtkIdType rank = (numberOfTriangles + 99) / 100; // ceil(0.01 n), 1-based
    std::nth_element(angles.begin(), angles.begin() + (rank - 1), angles.end());
    minAngleP1 = angles[rank - 1];
  }

  // Cell data.
  vtkNew<vtkSignedCharArray> nonManifoldEdgeCells, boundaryEdgeCells;
  nonManifoldEdgeCells->SetName("NonManifoldEdge");
  boundaryEdgeCells->SetName("BoundaryEdge");
  nonManifoldEdgeCells->SetNumberOfValues(numberOfCells);
  boundaryEdgeCells->SetNumberOfValues(numberOfCells);
  nonManifoldEdgeCells->FillValue(-1);
  boundaryEdgeCells->FillValue(-1);
  vtkNew<vtkDoubleArray> minAngleCells;
  minAngleCells->SetName("MinAngle");
  minAngleCells->SetNumberOfValues(numberOfCells);
  minAngleCells->FillValue(NaN);
  for (vtkIdType t = 0; t < numberOfTriangles; ++t)
  {
    const vtkIdType cellId = cells.CellIds[t];
    minAngleCells->SetValue(cellId, minAngles[t]);
    if (collapsed[t])
    {
      continue;
    }
    signed char nonManifold = 0, boundary = 0;
    for (int j = 0; j < 3; ++j)
    {
      const vtkIdType valence = topology.Valence(topology.TriangleEdges[3 * t + j]);
      nonManifold += valence > 2 ? 1 : 0;
      boundary += valence == 1 ? 1 : 0;
    }
    nonManifoldEdgeCells->SetValue(cellId, nonManifold);
    boundaryEdgeCells->SetValue(cellId, boundary);
  }
  output->GetCellData()->AddArray(nonManifoldEdgeCells);
  output->GetCellData()->AddArray(boundaryEdgeCells);
  output->GetCellData()->AddArray(minAngleCells);
  output->GetPointData()->AddArray(used);
  output->GetPointData()->AddArray(nonManifoldVertex);

  vtkFieldData* fd = output->GetFieldData();
  pcs::AddFieldCount(fd, "NumberOfTriangles", numberOfTriangles);
  pcs::AddFieldCount(fd, "NumberOfUsedPoints", numberOfUsedPoints);
  pcs::AddFieldValue(fd, "Coverage",
    numberOfPoints > 0 ? static_cast<double>(numberOfUsedPoints) / numberOfPoints : 0.0);
  pcs::AddFieldCount(fd, "NumberOfNonManifoldEdges", nonManifoldEdges);
  pcs::AddFieldCount(fd, "NumberOfNonManifoldVertices", nonManifoldVertices);
  pcs::AddFieldCount(fd, "NumberOfBoundaryEdges", boundaryEdges);
  pcs::AddFieldCount(fd, "NumberOfBoundaryLoops", boundaryLoops);
  pcs::AddFieldCount(fd, "NumberOfConnectedComponents", numberOfComponents);
  pcs::AddFieldCount(fd, "EulerCharacteristic", euler);
  pcs::AddFieldCount(fd, "Genus", genus);
  pcs::AddFieldValue(fd, "OrientationConsistency",
    interiorEdges > 0 ? static_cast<double>(consistentEdges) / interiorEdges : 1.0);
  pcs::AddFieldCount(fd, "NumberOfDegenerateTriangles", degenerate);
  pcs::AddFieldCount(fd, "NumberOfDuplicateTriangles", duplicates);
  pcs::AddFieldValue(fd, "MinAngleP1", minAngleP1);
  this->UpdateProgress(0.4);

  if (!reference || !this->ComputeDistances || this->GetAbortExecute())
  {
    this->UpdateProgress(1.0);
    return 1;
  }

  //----------------------------------------------------------------------------------------------
  // Distances to the reference.
  const auto perTriangle = BarycentricSamples(this->SamplesPerTriangle);
  TriangleCells referenceCells = ScanTriangles(reference);
  if (referenceCells.OtherPolygons > 0 || referenceCells.InvalidTriangles > 0)
  {
    vtkWarningMacro("Ignored " << referenceCells.OtherPolygons + referenceCells.InvalidTriangles
                               << " non-triangle 2D cell(s) or invalid triangle(s) of the "
                                  "reference.");
  }
  const bool referenceIsSurface = !referenceCells.Triangles.empty();
  if (referenceCells.NonFinitePoints > 0)
  {
    // As on the mesh side: such points are neither samples nor targets.
    vtkWarningMacro(<< referenceCells.NonFinitePoints
                    << " reference point(s) have NaN or infinite coordinates: they are left out "
                       "of the distances"
                    << (referenceCells.NonFiniteTriangles > 0 ? ", with the " : ".")
                    << (referenceCells.NonFiniteTriangles > 0
                           ? std::to_string(referenceCells.NonFiniteTriangles) +
                             " reference triangle(s) on them."
                           : std::string()));
  }
  vtkPoints* referencePoints = reference->GetPoints();
  const vtkIdType numberOfReferencePoints = reference->GetNumberOfPoints();

  // Triangles of non-zero area (the distance targets) and the vertex lists of both sides.
  auto positiveArea = [](vtkPoints* pts, const std::vector<Triangle>& all) {
    std::vector<Triangle> kept;
    for (const Triangle& t : all)
    {
      double a[3], b[3], c[3];
      pts->GetPoint(t[0], a);
      pts->GetPoint(t[1], b);
      pts->GetPoint(t[2], c);
      if (!IsCollapsed(t) && !HasZeroArea(a, b, c))
      {
        kept.push_back(t);
      }
    }
    return kept;
  };
  auto usedVertices = [](vtkIdType n, const std::vector<Triangle>& all) {
    std::vector<char> flag(n, 0);
    for (const Triangle& t : all)
    {
      flag[t[0]] = flag[t[1]] = flag[t[2]] = 1;
    }
    std::vector<vtkIdType> ids;
    for (vtkIdType p = 0; p < n; ++p)
    {
      if (flag[p])
      {
        ids.push_back(p);
      }
    }
    return ids;
  };

  SurfaceSamples meshSamples;
  meshSamples.Points = points;
  meshSamples.Vertices = usedVertices(numberOfPoints, triangles);
  meshSamples.Triangles = &triangles;
  meshSamples.PerTriangle = perTriangle;
  // The reference normal angles query the mesh triangles' centroids, the first sample of each
  // triangle: without samples (SamplesPerTriangle 0) the centroids are added as queries, left out
  // of the accuracy (which then stays on the vertices, the first `accuracySamples` samples).
  const vtkIdType accuracySamples = meshSamples.Size();
  if (referenceIsSurface && meshSamples.PerTriangle.empty())
  {
    meshSamples.PerTriangle = BarycentricSamples(1);
  }
  std::vector<vtkIdType> centroidSamples;
  if (referenceIsSurface)
  {
    const vtkIdType first = static_cast<vtkIdType>(meshSamples.Vertices.size());
    const vtkIdType stride = static_cast<vtkIdType>(meshSamples.PerTriangle.size());
    centroidSamples.resize(triangles.size());
    for (vtkIdType t = 0; t < numberOfTriangles; ++t)
    {
      centroidSamples[t] = first + t * stride;
    }
  }
  std::vector<double> referenceNormals(3 * centroidSamples.size(), NaN);

  SurfaceSamples referenceSamples;
  referenceSamples.Points = referencePoints;
  referenceSamples.PerTriangle = perTriangle;
  if (referenceIsSurface)
  {
    referenceSamples.Vertices = usedVertices(numberOfReferencePoints, referenceCells.Triangles);
    referenceSamples.Triangles = &referenceCells.Triangles;
  }
  else
  {
    referenceSamples.Vertices.reserve(numberOfReferencePoints);
    for (vtkIdType p = 0; p < numberOfReferencePoints; ++p)
    {
      double x[3];
      referencePoints->GetPoint(p, x);
      if (std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]))
      {
        referenceSamples.Vertices.push_back(p);
      }
    }
  }

  DistanceTarget referenceTarget, meshTarget;
  if (numberOfReferencePoints > 0)
  {
    const std::vector<Triangle> referenceArea = referenceIsSurface
      ? positiveArea(referencePoints, referenceCells.Triangles)
      : std::vector<Triangle>();
    referenceTarget.Build(
      referencePoints, referenceArea, referenceIsSurface ? &referenceSamples.Vertices : nullptr);
  }
  if (numberOfTriangles > 0)
  {
    meshTarget.Build(points, positiveArea(points, triangles), &meshSamples.Vertices);
  }
  if (referenceTarget.IsEmpty() || meshTarget.IsEmpty())
  {
    vtkWarningMacro(<< (referenceTarget.IsEmpty() ? "The reference has no points"
                                                  : "The mesh has no triangles")
                    << ": the distances are undefined (NaN).");
  }

  // Accuracy: mesh samples -> reference. The first samples are the used points.
  std::vector<double> accuracy(meshSamples.Size(), NaN);
  vtkIdType flat = 0;
  if (!referenceTarget.IsEmpty())
  {
    flat += MeasureDistances(meshSamples,
      referenceTarget,
      accuracy.data(),
      referenceIsSurface ? &centroidSamples : nullptr,
      referenceNormals.data());
  }
  this->UpdateProgress(0.7);
  // Completeness: reference samples -> mesh.
  std::vector<double> completeness(referenceSamples.Size(), NaN);
  if (!meshTarget.IsEmpty() && !referenceTarget.IsEmpty())
  {
    flat += MeasureDistances(referenceSamples, meshTarget, completeness.data());
  }
  this->UpdateProgress(0.9);
  if (flat > 0)
  {
    vtkWarningMacro(<< flat
                    << " triangle(s) of non-zero area are too thin for their coordinate range "
                       "(vtkTriangle::EvaluatePosition fails on them): the distances ignore them.");
  }
  if (!referenceTarget.IsEmpty() && !meshTarget.IsEmpty())
  {
    const auto unmeasured = std::count_if(accuracy.begin(),
                              accuracy.begin() + accuracySamples,
                              [](double d) { return std::isnan(d); }) +
      std::count_if(
        completeness.begin(), completeness.end(), [](double d) { return std::isnan(d); });
    if (unmeasured > 0)
    {
      vtkWarningMacro(<< unmeasured
                      << " distance sample(s) could not be measured (coordinates that overflow, "
                         "or no triangle of measurable area): their distances are NaN, and so "
                         "are the means and maxima that include them.");
    }
  }

  vtkNew<vtkDoubleArray> distanceToReference;
  distanceToReference->SetName("DistanceToReference");
  distanceToReference->SetNumberOfValues(numberOfPoints);
  distanceToReference->FillValue(NaN);
  for (size_t i = 0; i < meshSamples.Vertices.size(); ++i)
  {
    distanceToReference->SetValue(meshSamples.Vertices[i], accuracy[i]);
  }
  output->GetPointData()->AddArray(distanceToReference);

  double accuracyMean, accuracyMax, completenessMean, completenessMax;
  MeanAndMax(accuracy.data(), accuracy.data() + accuracySamples, accuracyMean, accuracyMax);
  MeanAndMax(completeness.data(), completeness.data() + completeness.size(), completenessMean,
    completenessMax);
  const double hausdorff = (std::isnan(accuracyMax) || std::isnan(completenessMax))
    ? NaN
    : std::max(accuracyMax, completenessMax);

  // Mean nearest-neighbour spacing of the cloud: the reference points when the reference is a
  // cloud, else the used points of the mesh.
  double meanSpacing = NaN;
  {
    vtkSmartPointer<vtkPolyData> cloud = referenceIsSurface
      ? PointCloud(points, meshSamples.Vertices)
      : PointCloud(referencePoints, referenceSamples.Vertices);
    // (pcs::FindExactDuplicates numbers points with 32-bit ids: larger clouds get no spacing.)
    if (cloud->GetNumberOfPoints() > 1 &&
      cloud->GetNumberOfPoints() <= std::numeric_limits<int32_t>::max())
    {
      const int exponent = ScaleSafely(cloud);
      vtkNew<vtkStaticPointLocator> locator;
      locator->SetDataSet(cloud);
      locator->BuildLocator();
      std::vector<double> spacing(cloud->GetNumberOfPoints(), NaN);
      // Exact duplicates grouped by sorting on the coordinates (non-finite points stay single):
      // one query per group, its first copy.
      const vtkIdType n = cloud->GetNumberOfPoints();
      std::vector<double> xyz(3 * static_cast<size_t>(n));
      for (vtkIdType i = 0; i < n; ++i)
      {
        cloud->GetPoint(i, &xyz[3 * i]);
      }
      std::vector<int32_t> firstCopy, order;
      pcs::FindExactDuplicates(xyz.data(), 3, nullptr, static_cast<int32_t>(n), firstCopy, &order);
      std::vector<vtkIdType> queries, copies, groupStart;
      for (vtkIdType j = 0; j < n; ++j)
      {
        const int32_t a = order[j];
        if (firstCopy[a] == a)
        {
          queries.push_back(a);
          copies.push_back(0);
          groupStart.push_back(j);
        }
        ++copies.back();
      }
      groupStart.push_back(n);
      SpacingFunctor nearest(cloud, locator, queries.data(), copies.data(), spacing.data());
      vtkSMPTools::For(0, static_cast<vtkIdType>(queries.size()), nearest);
      for (size_t g = 0; g < queries.size(); ++g)
      {
        for (vtkIdType j = groupStart[g]; j < groupStart[g + 1]; ++j)
        {
          spacing[order[j]] = spacing[queries[g]];
        }
      }
      meanSpacing = std::ldexp(MeanOfDefined(spacing), -exponent);
    }
  }
  auto overSpacing = [meanSpacing](double d) { return meanSpacing > 0.0 ? d / meanSpacing : NaN; };

  pcs::AddFieldValue(fd, "AccuracyMean", accuracyMean);
  pcs::AddFieldValue(fd, "AccuracyMax", accuracyMax);
  pcs::AddFieldValue(fd, "CompletenessMean", completenessMean);
  pcs::AddFieldValue(fd, "CompletenessMax", completenessMax);
  pcs::AddFieldValue(fd, "Hausdorff", hausdorff);
  pcs::AddFieldValue(fd, "MeanSpacing", meanSpacing);
  pcs::AddFieldValue(fd, "AccuracyMeanOverSpacing", overSpacing(accuracyMean));
  pcs::AddFieldValue(fd, "AccuracyMaxOverSpacing", overSpacing(accuracyMax));
  pcs::AddFieldValue(fd, "CompletenessMeanOverSpacing", overSpacing(completenessMean));
  pcs::AddFieldValue(fd, "CompletenessMaxOverSpacing", overSpacing(completenessMax));
  pcs::AddFieldValue(fd, "HausdorffOverSpacing", overSpacing(hausdorff));
  AddReferenceNormalAngles(output,
    points,
    triangles,
    cells.CellIds,
    zeroArea,
    referenceIsSurface ? referenceNormals.data() : nullptr,
    this->StandingAngle);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------------------------
void vtkReconstructionQuality::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "StandingAngle: " << this->StandingAngle << "\n";
  os << indent << "SamplesPerTriangle: " << this->SamplesPerTriangle << "\n";
  os << indent << "ComputeDistances: " << (this->ComputeDistances ? "On" : "Off") << "\n";
}
