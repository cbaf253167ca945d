#include "vtkReconstructionQuality.h"

#include "pcsFieldData.h"
#include "pcsGatherInput.h"

#include "pcsCoordinateScaling.h"
#include "pcsProjectedTests.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
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
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkSignedCharArray.h"
#include "vtkSmartPointer.h"
#include "vtkStaticCellLocator.h"
#include "vtkStaticPointLocator.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <tuple>
#include <utility>
#include <string>
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

// Exact zero-area test: the three points are collinear (pcs::projected::Collinear), decided on
// the points scaled by a power of two (exact) when their coordinates are so small or large that
// the orientation products would underflow or overflow (a surface at 1e-300).
bool HasZeroArea(const double a[3], const double b[3], const double c[3])
{
  const double points[9] = { a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2] };
  static const std::vector<int32_t> ids = { 0, 1, 2 };
  const int exponent = pcs::PredicateSafeExponent(points, 3, ids);
  if (exponent == 0)
  {
    return pcs::projected::Collinear(a, b, c);
  }
  const std::vector<double> scaled = pcs::ScaledCopy(points, 9, exponent);
  return pcs::projected::Collinear(&scaled[0], &scaled[3], &scaled[6]);
}

// Smallest interior angle in degrees; atan2(|u x v|, u . v) is accurate for small and large
// angles alike and gives 0 for a zero-length edge.
double MinimumAngle(const double a[3], const double b[3], const double c[3])
{
  const double* p[3] = { a, b, c };
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

struct DisjointSets
{
  std::vector<vtkIdType> Parent;

  void Reset(vtkIdType n)
  {
    this->Parent.resize(n);
    std::iota(this->Parent.begin(), this->Parent.end(), vtkIdType(0));
  }
  vtkIdType Find(vtkIdType i)
  {
    while (this->Parent[i] != i)
    {
      this->Parent[i] = this->Parent[this->Parent[i]]; // path halving
      i = this->Parent[i];
    }
    return i;
  }
  void Union(vtkIdType a, vtkIdType b)
  {
    a = this->Find(a);
    b = this->Find(b);
    if (a != b)
    {
      this->Parent[std::max(a, b)] = std::min(a, b);
    }
  }
};

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
    DisjointSets Sets;
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

// A vtkPolyData holding the points `ids` of `points` (all of them when ids is null), no cells.
vtkSmartPointer<vtkPolyData> PointCloud(vtkPoints* points, const std::vector<vtkIdType>* ids)
{
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  if (!points)
  {
    return cloud;
  }
  if (!ids)
  {
    cloud->SetPoints(points);
    return cloud;
  }
  vtkNew<vtkPoints> subset;
  subset->SetDataTypeToDouble();
  subset->SetNumberOfPoints(static_cast<vtkIdType>(ids->size()));
  for (size_t i = 0; i < ids->size(); ++i)
  {
    double x[3];
    points->GetPoint((*ids)[i], x);
    subset->SetPoint(static_cast<vtkIdType>(i), x);
  }
  cloud->SetPoints(subset);
  return cloud;
}

// What the distances are measured to: triangles (cell locator) or points (point locator).
struct DistanceTarget
{
  vtkSmartPointer<vtkPolyData> Data;
  vtkSmartPointer<vtkStaticCellLocator> CellLocator;
  vtkSmartPointer<vtkStaticPointLocator> PointLocator;
  // With triangles: their vertices, whose nearest one bounds the search radius of a query.
  vtkSmartPointer<vtkPolyData> Vertices;
  vtkSmartPointer<vtkStaticPointLocator> VertexLocator;
  double Slack = 0.0;

  bool IsEmpty() const { return !this->CellLocator && !this->PointLocator; }

  // Triangles of non-zero area when there are any, else the points `cloud` (all points of
  // `points` when cloud is null).
  void Build(
    vtkPoints* points, const std::vector<Triangle>& triangles, const std::vector<vtkIdType>* cloud)
  {
    this->Data = vtkSmartPointer<vtkPolyData>::New();
    if (!triangles.empty())
    {
      vtkNew<vtkIdTypeArray> offsets, connectivity;
      offsets->SetNumberOfValues(static_cast<vtkIdType>(triangles.size()) + 1);
      connectivity->SetNumberOfValues(3 * static_cast<vtkIdType>(triangles.size()));
      for (size_t t = 0; t < triangles.size(); ++t)
      {
        offsets->SetValue(static_cast<vtkIdType>(t), 3 * static_cast<vtkIdType>(t));
        for (int j = 0; j < 3; ++j)
        {
          connectivity->SetValue(3 * static_cast<vtkIdType>(t) + j, triangles[t][j]);
        }
      }
      offsets->SetValue(
        static_cast<vtkIdType>(triangles.size()), connectivity->GetNumberOfValues());
      vtkNew<vtkCellArray> polys;
      polys->SetData(offsets, connectivity);
      this->Data->SetPoints(points);
      this->Data->SetPolys(polys);
      this->Data->BuildCells(); // GetCell(id, vtkGenericCell*) is then safe from any thread
      this->CellLocator = vtkSmartPointer<vtkStaticCellLocator>::New();
      this->CellLocator->SetDataSet(this->Data);
      this->CellLocator->BuildLocator();
      std::vector<char> flag(points->GetNumberOfPoints(), 0);
      std::vector<vtkIdType> ids;
      for (const Triangle& t : triangles)
      {
        for (vtkIdType p : t)
        {
          if (!flag[p])
          {
            flag[p] = 1;
            ids.push_back(p);
          }
        }
      }
      this->Vertices = PointCloud(points, &ids);
      this->VertexLocator = vtkSmartPointer<vtkStaticPointLocator>::New();
      this->VertexLocator->SetDataSet(this->Vertices);
      this->VertexLocator->BuildLocator();
      this->Slack = 1e-9 * this->Data->GetLength();
      return;
    }
    this->Data = PointCloud(points, cloud);
    if (this->Data->GetNumberOfPoints() == 0)
    {
      return;
    }
    this->PointLocator = vtkSmartPointer<vtkStaticPointLocator>::New();
    this->PointLocator->SetDataSet(this->Data);
    this->PointLocator->BuildLocator();
  }
};

// Distance from every sample to the target, one value per sample (NaN if none is found).
struct DistanceFunctor
{
  const SurfaceSamples& Samples;
  const DistanceTarget& Target;
  double* Distances;
  vtkSMPThreadLocalObject<vtkGenericCell> Cell;

  DistanceFunctor(const SurfaceSamples& samples, const DistanceTarget& target, double* distances)
    : Samples(samples)
    , Target(target)
    , Distances(distances)
  {}

  void Initialize() {}

  void operator()(vtkIdType begin, vtkIdType end)
  {
    vtkGenericCell* cell = this->Cell.Local();
    double x[3], closest[3];
    for (vtkIdType i = begin; i < end; ++i)
    {
      this->Samples.Get(i, x);
      if (this->Target.CellLocator)
      {
        vtkIdType cellId = -1;
        int subId = 0;
        double dist2 = NaN;
        // The overloads with a caller-owned vtkGenericCell are the thread-safe ones (VTK 9.2).
        // The nearest triangle vertex bounds the distance: searching within that radius first
        // prunes the locator's bins and cells (about 15 % faster); the unbounded search is the
        // fallback, so the result is the same.
        vtkIdType found = 0;
        if (this->Target.VertexLocator)
        {
          double v[3];
          this->Target.Vertices->GetPoint(this->Target.VertexLocator->FindClosestPoint(x), v);
          const double radius =
            std::sqrt(vtkMath::Distance2BetweenPoints(x, v)) * (1.0 + 1e-9) + this->Target.Slack;
          found = this->Target.CellLocator->FindClosestPointWithinRadius(
            x, radius, closest, cell, cellId, subId, dist2);
        }
        if (!found)
        {
          this->Target.CellLocator->FindClosestPoint(x, closest, cell, cellId, subId, dist2);
        }
        this->Distances[i] = cellId >= 0 ? std::sqrt(dist2) : NaN;
      }
      else
      {
        const vtkIdType id = this->Target.PointLocator->FindClosestPoint(x);
        if (id < 0)
        {
          this->Distances[i] = NaN;
          continue;
        }
        this->Target.Data->GetPoint(id, closest);
        this->Distances[i] = std::sqrt(vtkMath::Distance2BetweenPoints(x, closest));
      }
    }
  }

  void Reduce() {}
};

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
  DisjointSets components;
  components.Reset(numberOfTriangles);
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
    referenceSamples.Vertices.resize(numberOfReferencePoints);
    std::iota(referenceSamples.Vertices.begin(), referenceSamples.Vertices.end(), vtkIdType(0));
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
  if (!referenceTarget.IsEmpty())
  {
    DistanceFunctor query(meshSamples, referenceTarget, accuracy.data());
    vtkSMPTools::For(0, meshSamples.Size(), query);
  }
  this->UpdateProgress(0.7);
  // Completeness: reference samples -> mesh.
  std::vector<double> completeness(referenceSamples.Size(), NaN);
  if (!meshTarget.IsEmpty() && !referenceTarget.IsEmpty())
  {
    DistanceFunctor query(referenceSamples, meshTarget, completeness.data());
    vtkSMPTools::For(0, referenceSamples.Size(), query);
  }
  this->UpdateProgress(0.9);

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
  MeanAndMax(accuracy.data(), accuracy.data() + accuracy.size(), accuracyMean, accuracyMax);
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
      ? PointCloud(points, &meshSamples.Vertices)
      : PointCloud(referencePoints, nullptr);
    if (cloud->GetNumberOfPoints() > 1)
    {
      vtkNew<vtkStaticPointLocator> locator;
      locator->SetDataSet(cloud);
      locator->BuildLocator();
      std::vector<double> spacing(cloud->GetNumberOfPoints(), NaN);
      // Exact duplicates grouped by sorting on the coordinates (non-finite points stay single).
      const vtkIdType n = cloud->GetNumberOfPoints();
      std::vector<double> xyz(3 * static_cast<size_t>(n));
      for (vtkIdType i = 0; i < n; ++i)
      {
        cloud->GetPoint(i, &xyz[3 * i]);
      }
      auto finite = [&xyz](vtkIdType i)
      {
        return std::isfinite(xyz[3 * i]) && std::isfinite(xyz[3 * i + 1]) &&
          std::isfinite(xyz[3 * i + 2]);
      };
      std::vector<vtkIdType> order(n);
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(),
        [&xyz, &finite](vtkIdType a, vtkIdType b)
        {
          const bool fa = finite(a), fb = finite(b);
          if (fa != fb || !fa)
          {
            return fa != fb ? fa : a < b;
          }
          for (int c = 0; c < 3; ++c)
          {
            if (xyz[3 * a + c] != xyz[3 * b + c])
            {
              return xyz[3 * a + c] < xyz[3 * b + c];
            }
          }
          return a < b;
        });
      std::vector<vtkIdType> queries, copies, groupStart;
      for (vtkIdType j = 0; j < n; ++j)
      {
        const vtkIdType a = order[j];
        const bool same = j > 0 && finite(a) && finite(order[j - 1]) &&
          std::equal(&xyz[3 * a], &xyz[3 * a] + 3, &xyz[3 * order[j - 1]]);
        if (!same)
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
      meanSpacing = MeanOfDefined(spacing);
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
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------------------------
void vtkReconstructionQuality::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SamplesPerTriangle: " << this->SamplesPerTriangle << "\n";
  os << indent << "ComputeDistances: " << (this->ComputeDistances ? "On" : "Off") << "\n";
}
