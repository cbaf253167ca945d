#include "vtkIncrementalDelaunay3D.h"

#include "pcsCoordinateScaling.h"
#include "pcsDelaunay2D.h"
#include "pcsDelaunay3D.h"
#include "pcsDuplicatePoints.h"
#include "pcsFieldData.h"
#include "pcsGatherInput.h"
#include "pcsHoleFilling.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
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
#include "vtkSMPTools.h"
#include "vtkStaticPointLocator.h"
#include "vtkTypeInt32Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkIncrementalDelaunay3D);

namespace
{
// Cells are addressed with 32-bit links (4 * cell + mirror), which bounds the cell count by
// 2^30, about 150 million points for a 3D triangulation.
constexpr vtkIdType MaximumNumberOfPoints = 150000000;

// Finite vertex triple of the hull facet of an infinite cell, ordered so that its normal
// (right-hand rule) points out of the hull. The kernel's infinite cells, with the infinite
// vertex replaced by a point beyond the facet, have Orient3D > 0: the increasing-slot triple
// then faces outwards when the infinite slot is even, inwards when it is odd.
void OutwardHullTriangle(const int32_t* v, int32_t triangle[3])
{
  int k = 0;
  int infinite = 0;
  for (int j = 0; j < 4; ++j)
  {
    if (v[j] < 0)
    {
      infinite = j;
    }
    else
    {
      triangle[k++] = v[j];
    }
  }
  if (infinite % 2 == 1)
  {
    std::swap(triangle[1], triangle[2]);
  }
}

// Voronoi vertex of a flat tetrahedron (zero volume in floating point: four coplanar points,
// which in a Delaunay tetrahedralization lie on one circle, e.g. a ring of a scan): its
// circumsphere is not unique (the centres fill the circle's axis), so the vertex is the centre
// of the circle through its face of largest area, on that axis; the centroid when every face is
// collinear in floating point. Returns the distance from the vertex to the cell's first point.
double FlatCellCenter(const double* const p[4], double center[3])
{
  double best = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    center[i] = 0.25 * (p[0][i] + p[1][i] + p[2][i] + p[3][i]);
  }
  for (int skip = 0; skip < 4; ++skip)
  {
    const double* a = p[(skip + 1) & 3];
    const double* b = p[(skip + 2) & 3];
    const double* c = p[(skip + 3) & 3];
    double ab[3], ac[3], n[3];
    vtkMath::Subtract(b, a, ab);
    vtkMath::Subtract(c, a, ac);
    vtkMath::Cross(ab, ac, n);
    const double n2 = vtkMath::Dot(n, n);
    if (!(n2 > best) || !std::isfinite(n2))
    {
      continue;
    }
    // a + (|ac|^2 (n x ab) + |ab|^2 (ac x n)) / (2 |n|^2)
    double nab[3], acn[3];
    vtkMath::Cross(n, ab, nab);
    vtkMath::Cross(ac, n, acn);
    const double lab = vtkMath::Dot(ab, ab), lac = vtkMath::Dot(ac, ac);
    double candidate[3];
    for (int i = 0; i < 3; ++i)
    {
      candidate[i] = a[i] + (lac * nab[i] + lab * acn[i]) / (2.0 * n2);
    }
    if (std::isfinite(candidate[0]) && std::isfinite(candidate[1]) && std::isfinite(candidate[2]))
    {
      best = n2;
      std::copy(candidate, candidate + 3, center);
    }
  }
  return std::sqrt(vtkMath::Distance2BetweenPoints(center, p[0]));
}

// Circumcentre of a triangle in 2D coordinates.
bool TriangleCircumcenter2D(
  const double* a, const double* b, const double* c, double center[2], double& radius)
{
  const double bx = b[0] - a[0], by = b[1] - a[1];
  const double cx = c[0] - a[0], cy = c[1] - a[1];
  const double denominator = 2.0 * (bx * cy - by * cx);
  if (denominator == 0.0)
  {
    center[0] = center[1] = std::numeric_limits<double>::quiet_NaN();
    radius = std::numeric_limits<double>::infinity();
    return false;
  }
  const double lb = bx * bx + by * by, lc = cx * cx + cy * cy;
  const double ux = (cy * lb - by * lc) / denominator;
  const double uy = (bx * lc - cx * lb) / denominator;
  center[0] = a[0] + ux;
  center[1] = a[1] + uy;
  radius = std::sqrt(ux * ux + uy * uy);
  return true;
}

vtkSmartPointer<vtkCellArray> MakeCellArray(const std::vector<int32_t>& connectivity, int size)
{
  const vtkIdType cells = static_cast<vtkIdType>(connectivity.size()) / size;
  vtkNew<vtkTypeInt32Array> offsets;
  offsets->SetNumberOfValues(cells + 1);
  for (vtkIdType c = 0; c <= cells; ++c)
  {
    offsets->SetValue(c, static_cast<int32_t>(size * c));
  }
  vtkNew<vtkTypeInt32Array> ids;
  ids->SetNumberOfValues(static_cast<vtkIdType>(connectivity.size()));
  std::copy(connectivity.begin(), connectivity.end(), ids->GetPointer(0));
  auto array = vtkSmartPointer<vtkCellArray>::New();
  array->SetData(offsets, ids);
  return array;
}

// Cells of `size` points each over the connectivity array itself (no copy).
vtkSmartPointer<vtkCellArray> MakeCellArray(vtkTypeInt32Array* connectivity, int size)
{
  const vtkIdType cells = connectivity->GetNumberOfValues() / size;
  vtkNew<vtkTypeInt32Array> offsets;
  offsets->SetNumberOfValues(cells + 1);
  for (vtkIdType c = 0; c <= cells; ++c)
  {
    offsets->SetValue(c, static_cast<int32_t>(size * c));
  }
  auto array = vtkSmartPointer<vtkCellArray>::New();
  array->SetData(offsets, connectivity);
  return array;
}

// The projection plane of the 2.5D mode is a pcs::holes::Plane: the x-y plane by default, the
// least-squares plane of the points (centroid and the two principal axes of largest variance)
// with BEST_FIT_PLANE.
using ProjectionFrame = pcs::holes::Plane;

//------------------------------------------------------------------------------------------------
// Exact duplicates (dim = 2: of the projected coordinates), removed from `ids` (ascending) and
// mapped to the copy of smallest id (pcs::MergeExactDuplicates).
void MergeExactDuplicates(
  const double* coords, int dim, std::vector<int32_t>& ids, vtkIdTypeArray* representative)
{
  std::vector<std::pair<int32_t, int32_t>> merged;
  pcs::MergeExactDuplicates(coords, dim, ids, merged);
  for (const auto& copy : merged)
  {
    representative->SetValue(copy.first, copy.second);
  }
}

//------------------------------------------------------------------------------------------------
// Greedy merge in input order: a point not yet merged is kept and absorbs every unmerged point
// within Tolerance of it (vtkStaticPointLocator radius queries).
void MergeWithinTolerance(double tolerance, const double* coords, int dim,
  std::vector<int32_t>& ids, vtkIdTypeArray* representative)
{
  vtkNew<vtkPoints> kept;
  kept->SetDataTypeToDouble();
  kept->SetNumberOfPoints(static_cast<vtkIdType>(ids.size()));
  for (size_t i = 0; i < ids.size(); ++i)
  {
    const double* p = coords + dim * static_cast<int64_t>(ids[i]);
    kept->SetPoint(static_cast<vtkIdType>(i), p[0], p[1], dim == 3 ? p[2] : 0.0);
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(kept);
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(cloud);
  locator->BuildLocator();

  std::vector<char> merged(ids.size(), 0);
  std::vector<int32_t> survivors;
  survivors.reserve(ids.size());
  vtkNew<vtkIdList> near;
  for (size_t i = 0; i < ids.size(); ++i)
  {
    if (merged[i])
    {
      continue;
    }
    survivors.push_back(ids[i]);
    double p[3];
    kept->GetPoint(static_cast<vtkIdType>(i), p);
    locator->FindPointsWithinRadius(tolerance, p, near);
    for (vtkIdType k = 0; k < near->GetNumberOfIds(); ++k)
    {
      const vtkIdType j = near->GetId(k);
      if (static_cast<size_t>(j) != i && !merged[j])
      {
        merged[j] = 1;
        representative->SetValue(ids[j], ids[i]);
      }
    }
  }
  ids.swap(survivors);
}

using pcs::PredicateSafeExponent;
using pcs::ScaledCopy;

// The edges of a Voronoi diagram whose vertices (the circumcentres) and their circumradii are
// `vertices` and `radii`: a segment between two vertices, or a ray from a vertex to a far end,
// added as a vertex of radius NaN. SetTo hands the vertices (point data Circumradius) and the
// edges (cell data Unbounded: 1 for a ray, 0 for a segment) to the output.
class VoronoiEdges
{
public:
  VoronoiEdges(vtkPoints* vertices, std::vector<double>& radii)
    : Vertices(vertices)
    , Radii(radii)
  {
    this->Unbounded->SetName("Unbounded");
  }

  void AddSegment(vtkIdType a, vtkIdType b)
  {
    const vtkIdType segment[2] = { a, b };
    this->Edges->InsertNextCell(2, segment);
    this->Unbounded->InsertNextValue(0);
  }

  void AddRay(vtkIdType from, const double end[3])
  {
    const vtkIdType ray[2] = { from, this->Vertices->InsertNextPoint(end) };
    this->Radii.push_back(std::numeric_limits<double>::quiet_NaN());
    this->Edges->InsertNextCell(2, ray);
    this->Unbounded->InsertNextValue(1);
  }

  void SetTo(vtkPolyData* voronoi)
  {
    vtkNew<vtkDoubleArray> radius;
    radius->SetName("Circumradius");
    radius->SetNumberOfValues(static_cast<vtkIdType>(this->Radii.size()));
    std::copy(this->Radii.begin(), this->Radii.end(), radius->GetPointer(0));
    voronoi->SetPoints(this->Vertices);
    voronoi->SetLines(this->Edges);
    voronoi->GetPointData()->AddArray(radius);
    voronoi->GetCellData()->AddArray(this->Unbounded);
  }

private:
  vtkPoints* Vertices;
  std::vector<double>& Radii;
  vtkNew<vtkCellArray> Edges;
  vtkNew<vtkUnsignedCharArray> Unbounded;
};

void BuildVoronoi3D(const double* xyz, const pcs::Delaunay3D& dt,
  const std::vector<int32_t>& finiteIndex, int32_t numberOfFinite, vtkPolyData* voronoi);

vtkIdType Triangulate3D(vtkIncrementalDelaunay3D* self, const double* xyz,
  const std::vector<int32_t>& ids, const pcs::Delaunay3D::ProgressFunction& progress,
  vtkIdTypeArray* representative, vtkPolyData* surface, vtkUnstructuredGrid* cells,
  vtkPolyData* voronoi)
{
  pcs::Delaunay3D dt;
  dt.SetComputeCircumradii(self->GetGenerateTetrahedra());
  const int exponent = PredicateSafeExponent(xyz, 3, ids);
  std::vector<double> scaled;
  if (exponent != 0)
  {
    scaled = ScaledCopy(xyz, 3 * static_cast<size_t>(representative->GetNumberOfValues()), exponent);
  }
  if (!dt.Triangulate(exponent != 0 ? scaled.data() : xyz, ids, progress))
  {
    if (!self->GetAbortExecute())
    {
      // The kernel reports duplicates only when it triangulates: count them here.
      std::vector<int32_t> remaining(ids);
      MergeExactDuplicates(xyz, 3, remaining, representative);
      vtkWarningWithObjectMacro(self, "Fewer than 4 distinct non-coplanar points among the "
          << ids.size() << " usable point(s): no tetrahedra are produced.");
    }
    return 0;
  }
  for (const auto& duplicate : dt.GetDuplicates())
  {
    representative->SetValue(duplicate.first, duplicate.second);
  }
  const std::string large = dt.DescribeLargeSize(ids.size());
  if (!large.empty())
  {
    vtkWarningWithObjectMacro(self, << large);
  }

  const int64_t numberOfKernelCells = dt.GetNumberOfCells();
  const int32_t numberOfFinite = static_cast<int32_t>(dt.GetNumberOfFiniteCells());
  const int64_t numberOfHull = numberOfKernelCells - numberOfFinite;

  // Hull triangles, oriented outwards (filled together with the tetrahedra when they are
  // generated: one pass over the cells).
  vtkNew<vtkTypeInt32Array> hullIds;
  hullIds->SetNumberOfValues(3 * numberOfHull);
  if (!self->GetGenerateTetrahedra())
  {
    int32_t* triangle = hullIds->GetPointer(0);
    for (int64_t c = 0; c < numberOfKernelCells; ++c)
    {
      if (dt.IsInfinite(c))
      {
        OutwardHullTriangle(dt.CellVertices(c), triangle);
        triangle += 3;
      }
    }
  }

  if (self->GetGenerateVoronoi())
  {
    // On the scaled coordinates (no overflow in the circumcentres), then back to input units.
    // Finite cells are numbered in kernel cell order, as in the tetrahedra output.
    std::vector<int32_t> finiteIndex(numberOfKernelCells, -1);
    for (int64_t c = 0, f = 0; c < numberOfKernelCells; ++c)
    {
      if (!dt.IsInfinite(c))
      {
        finiteIndex[c] = static_cast<int32_t>(f++);
      }
    }
    BuildVoronoi3D(exponent != 0 ? scaled.data() : xyz, dt, finiteIndex, numberOfFinite, voronoi);
    if (exponent != 0)
    {
      vtkPoints* vertices = voronoi->GetPoints();
      for (vtkIdType i = 0; i < vertices->GetNumberOfPoints(); ++i)
      {
        double p[3];
        vertices->GetPoint(i, p);
        vertices->SetPoint(i, std::ldexp(p[0], -exponent), std::ldexp(p[1], -exponent),
          std::ldexp(p[2], -exponent));
      }
      vtkDataArray* radius = voronoi->GetPointData()->GetArray("Circumradius");
      for (vtkIdType i = 0; i < radius->GetNumberOfTuples(); ++i)
      {
        radius->SetTuple1(i, std::ldexp(radius->GetTuple1(i), -exponent));
      }
    }
  }
  if (self->GetGenerateTetrahedra())
  {
    // VTK orders a tetrahedron so that (p1 - p0) x (p2 - p0) points towards p3, the opposite of
    // the kernel's Orient3D > 0 convention: swap the first two vertices.
    vtkNew<vtkTypeInt32Array> connectivity;
    connectivity->SetNumberOfValues(4 * static_cast<vtkIdType>(numberOfFinite));
    int32_t* ids = connectivity->GetPointer(0);
    vtkNew<vtkTypeInt32Array> offsets;
    offsets->SetNumberOfValues(static_cast<vtkIdType>(numberOfFinite) + 1);
    int32_t* offset = offsets->GetPointer(0);
    int32_t* triangle = hullIds->GetPointer(0);
    for (int64_t c = 0, f = 0; c < numberOfKernelCells; ++c)
    {
      const int32_t* v = dt.CellVertices(c);
      if (v[0] < 0 || v[1] < 0 || v[2] < 0 || v[3] < 0)
      {
        OutwardHullTriangle(v, triangle);
        triangle += 3;
      }
      else
      {
        int32_t* t = ids + 4 * f;
        t[0] = v[1];
        t[1] = v[0];
        t[2] = v[2];
        t[3] = v[3];
        offset[f] = static_cast<int32_t>(4 * f);
        ++f;
      }
    }
    offset[numberOfFinite] = 4 * numberOfFinite;
    // The kernel's radii are in the same (finite cell) order: adopt its buffer.
    vtkNew<vtkDoubleArray> radius;
    radius->SetName("Circumradius");
    double* radii = dt.ReleaseCircumradii();
    radius->SetArray(radii, numberOfFinite, 0, vtkAbstractArray::VTK_DATA_ARRAY_FREE);
    if (exponent != 0)
    {
      for (int32_t f = 0; f < numberOfFinite; ++f)
      {
        radii[f] = std::ldexp(radii[f], -exponent);
      }
    }
    dt.Clear();

    vtkNew<vtkCellArray> tetra;
    tetra->SetData(offsets, connectivity);
    cells->SetCells(VTK_TETRA, tetra);
    cells->GetCellData()->AddArray(radius);
  }
  surface->SetPolys(MakeCellArray(hullIds, 3));
  return numberOfFinite;
}

//------------------------------------------------------------------------------------------------
// Voronoi diagram (paper 002, section 2.1): vertices are the circumcentres of the finite
// tetrahedra; each facet shared by two finite tetrahedra gives a segment, each hull facet a ray
// along its outward normal, cut at one bounding-box diagonal.
void BuildVoronoi3D(const double* xyz, const pcs::Delaunay3D& dt,
  const std::vector<int32_t>& finiteIndex, int32_t numberOfFinite, vtkPolyData* voronoi)
{
  const int64_t numberOfKernelCells = dt.GetNumberOfCells();
  auto P = [xyz](int32_t id) { return xyz + 3 * static_cast<int64_t>(id); };
  vtkNew<vtkPoints> vertices;
  vertices->SetDataTypeToDouble();
  vertices->SetNumberOfPoints(numberOfFinite);
  std::vector<double> radii(numberOfFinite);
  double bounds[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int64_t c = 0; c < numberOfKernelCells; ++c)
  {
    const int32_t f = finiteIndex[c];
    if (f < 0)
    {
      continue;
    }
    double center[3];
    pcs::Delaunay3D::Circumsphere(P(dt.Vertex(c, 0)), P(dt.Vertex(c, 1)), P(dt.Vertex(c, 2)),
      P(dt.Vertex(c, 3)), center, radii[f]);
    if (!std::isfinite(center[0]) || !std::isfinite(center[1]) || !std::isfinite(center[2]))
    {
      const double* corners[4] = { P(dt.Vertex(c, 0)), P(dt.Vertex(c, 1)), P(dt.Vertex(c, 2)),
        P(dt.Vertex(c, 3)) };
      radii[f] = FlatCellCenter(corners, center);
    }
    vertices->SetPoint(f, center);
    for (int j = 0; j < 4; ++j)
    {
      const double* p = P(dt.Vertex(c, j));
      for (int i = 0; i < 3; ++i)
      {
        bounds[2 * i] = std::min(bounds[2 * i], p[i]);
        bounds[2 * i + 1] = std::max(bounds[2 * i + 1], p[i]);
      }
    }
  }
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));

  VoronoiEdges edges(vertices, radii);
  for (int64_t c = 0; c < numberOfKernelCells; ++c)
  {
    const int32_t f = finiteIndex[c];
    if (f < 0)
    {
      continue;
    }
    for (int j = 0; j < 4; ++j)
    {
      const int64_t n = dt.Neighbor(c, j);
      const int32_t g = finiteIndex[n];
      if (g >= 0)
      {
        if (f < g)
        {
          edges.AddSegment(f, g);
        }
        continue;
      }
      // Hull facet opposite vertex j: the ray leaves along the normal pointing away from it.
      const double* a = P(dt.Vertex(c, (j + 1) & 3));
      const double* b = P(dt.Vertex(c, (j + 2) & 3));
      const double* d = P(dt.Vertex(c, (j + 3) & 3));
      const double* opposite = P(dt.Vertex(c, j));
      double ab[3], ad[3], normal[3], ao[3];
      vtkMath::Subtract(b, a, ab);
      vtkMath::Subtract(d, a, ad);
      vtkMath::Cross(ab, ad, normal);
      vtkMath::Subtract(opposite, a, ao);
      if (vtkMath::Dot(normal, ao) > 0)
      {
        vtkMath::MultiplyScalar(normal, -1.0);
      }
      vtkMath::Normalize(normal);
      double start[3], end[3];
      vertices->GetPoint(f, start);
      for (int i = 0; i < 3; ++i)
      {
        end[i] = start[i] + diagonal * normal[i];
      }
      edges.AddRay(f, end);
    }
  }
  edges.SetTo(voronoi);
}

//------------------------------------------------------------------------------------------------
vtkIdType Triangulate2D(vtkIncrementalDelaunay3D* self, const double* uv,
  const ProjectionFrame& frame, const std::vector<int32_t>& ids,
  const pcs::Delaunay2D::ProgressFunction& progress, vtkPolyData* surface,
  vtkUnstructuredGrid* cells, vtkPolyData* voronoi)
{
  pcs::Delaunay2D dt;
  const int exponent = PredicateSafeExponent(uv, 2, ids);
  std::vector<double> scaled;
  if (exponent != 0)
  {
    size_t count = 0;
    for (int32_t id : ids)
    {
      count = std::max(count, 2 * static_cast<size_t>(id) + 2);
    }
    scaled = ScaledCopy(uv, count, exponent);
  }
  if (!dt.Triangulate(exponent != 0 ? scaled.data() : uv, ids, progress))
  {
    if (!self->GetAbortExecute())
    {
      vtkWarningWithObjectMacro(self, "Fewer than 3 distinct non-collinear projected points among the "
          << ids.size() << " usable point(s): no triangles are produced.");
    }
    return 0;
  }
  const std::vector<int32_t>& triangles = dt.GetTriangles();
  const vtkIdType numberOfTriangles = static_cast<vtkIdType>(triangles.size() / 3);

  vtkSmartPointer<vtkCellArray> polys = MakeCellArray(triangles, 3);
  surface->SetPolys(polys);

  std::vector<double> centers(2 * static_cast<size_t>(numberOfTriangles));
  std::vector<double> radii(numberOfTriangles);
  auto Q = [uv](int32_t id) { return uv + 2 * static_cast<int64_t>(id); };
  vtkSMPTools::For(0, numberOfTriangles, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType t = begin; t < end; ++t)
    {
      TriangleCircumcenter2D(Q(triangles[3 * t]), Q(triangles[3 * t + 1]),
        Q(triangles[3 * t + 2]), &centers[2 * t], radii[t]);
    }
  });

  if (self->GetGenerateTetrahedra())
  {
    vtkNew<vtkDoubleArray> radius;
    radius->SetName("Circumradius");
    radius->SetNumberOfValues(numberOfTriangles);
    std::copy(radii.begin(), radii.end(), radius->GetPointer(0));
    cells->SetCells(VTK_TRIANGLE, polys);
    cells->GetCellData()->AddArray(radius);
  }

  if (self->GetGenerateVoronoi())
  {
    // The 2D Voronoi diagram, in the projection plane.
    const std::vector<int32_t>& neighbors = dt.GetNeighbors();
    double bounds[4] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    for (int32_t id : ids)
    {
      bounds[0] = std::min(bounds[0], Q(id)[0]);
      bounds[1] = std::max(bounds[1], Q(id)[0]);
      bounds[2] = std::min(bounds[2], Q(id)[1]);
      bounds[3] = std::max(bounds[3], Q(id)[1]);
    }
    const double diagonal =
      std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
        (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]));
    vtkNew<vtkPoints> vertices;
    vertices->SetDataTypeToDouble();
    vertices->SetNumberOfPoints(numberOfTriangles);
    for (vtkIdType t = 0; t < numberOfTriangles; ++t)
    {
      double p[3];
      frame.Lift(&centers[2 * t], p);
      vertices->SetPoint(t, p);
    }
    VoronoiEdges edges(vertices, radii);
    for (vtkIdType t = 0; t < numberOfTriangles; ++t)
    {
      for (int i = 0; i < 3; ++i)
      {
        const int32_t n = neighbors[3 * t + i];
        if (n >= 0)
        {
          if (t < n)
          {
            edges.AddSegment(t, n);
          }
          continue;
        }
        // Hull edge opposite vertex i: the ray leaves along the outward normal of the edge.
        const double* a = Q(triangles[3 * t + (i + 1) % 3]);
        const double* b = Q(triangles[3 * t + (i + 2) % 3]);
        double normal[2] = { b[1] - a[1], a[0] - b[0] }; // right of a->b: outside for CCW
        const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1]);
        double endUV[2] = { centers[2 * t] + diagonal * normal[0] / length,
          centers[2 * t + 1] + diagonal * normal[1] / length };
        double end[3];
        frame.Lift(endUV, end);
        edges.AddRay(t, end);
      }
    }
    edges.SetTo(voronoi);
  }
  return numberOfTriangles;
}
} // namespace

//------------------------------------------------------------------------------------------------
vtkIncrementalDelaunay3D::vtkIncrementalDelaunay3D()
{
  this->SetNumberOfOutputPorts(3);
}

vtkIncrementalDelaunay3D::~vtkIncrementalDelaunay3D() = default;

vtkPolyData* vtkIncrementalDelaunay3D::GetSurfaceOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(0));
}

vtkUnstructuredGrid* vtkIncrementalDelaunay3D::GetTetrahedraOutput()
{
  return vtkUnstructuredGrid::SafeDownCast(this->GetOutputDataObject(1));
}

vtkPolyData* vtkIncrementalDelaunay3D::GetVoronoiOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(2));
}

int vtkIncrementalDelaunay3D::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkIncrementalDelaunay3D::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------------------------
int vtkIncrementalDelaunay3D::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* surface = vtkPolyData::GetData(outputVector, 0);
  vtkUnstructuredGrid* cells = vtkUnstructuredGrid::GetData(outputVector, 1);
  vtkPolyData* voronoi = vtkPolyData::GetData(outputVector, 2);
  // Under MPI the whole cloud is triangulated on process 0; the other processes' outputs stay
  // empty.
  vtkSmartPointer<vtkPointSet> input =
    pcs::GatherInputOnFirstProcess(vtkPointSet::GetData(inputVector[0]));
  if (!input && surface && cells && voronoi)
  {
    return 1;
  }
  if (!input || !surface || !cells || !voronoi)
  {
    vtkErrorMacro("Missing input or output data object.");
    return 0;
  }
  const std::string mismatched = pcs::DropMismatchedPointArrays(input);
  if (!mismatched.empty())
  {
    vtkWarningMacro(<< mismatched);
  }
  this->NumberOfInputPoints = 0;
  this->NumberOfDuplicatePoints = 0;
  this->NumberOfSkippedPoints = 0;
  this->NumberOfCells = 0;

  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  this->NumberOfInputPoints = numberOfPoints;

  // Every output keeps all input points (and their data) so point ids refer to the input.
  vtkNew<vtkIdTypeArray> representative;
  representative->SetName("RepresentativeId");
  representative->SetNumberOfValues(numberOfPoints);
  // (Also with no points: the output then has the input's arrays, empty.)
  if (input->GetPoints())
  {
    surface->SetPoints(input->GetPoints());
  }
  surface->GetPointData()->PassData(input->GetPointData());
  surface->GetPointData()->AddArray(representative);
  auto finish = [&]() {
    vtkFieldData* fd = surface->GetFieldData();
    pcs::AddFieldCount(fd, "NumberOfInputPoints", this->NumberOfInputPoints);
    pcs::AddFieldCount(fd, "NumberOfDuplicatePoints", this->NumberOfDuplicatePoints);
    pcs::AddFieldCount(fd, "NumberOfSkippedPoints", this->NumberOfSkippedPoints);
    pcs::AddFieldCount(fd, this->Dimension == 3 ? "NumberOfTetrahedra" : "NumberOfTriangles",
      this->NumberOfCells);
    if (this->GenerateTetrahedra)
    {
      if (surface->GetPoints())
      {
        cells->SetPoints(surface->GetPoints());
      }
      cells->GetPointData()->ShallowCopy(surface->GetPointData());
      cells->GetFieldData()->ShallowCopy(fd);
    }
    return 1;
  };

  if (numberOfPoints == 0)
  {
    vtkWarningMacro("The input has no points: the outputs are empty.");
    return finish();
  }
  if (numberOfPoints > MaximumNumberOfPoints)
  {
    vtkErrorMacro("The input has " << numberOfPoints << " points; at most "
                                   << MaximumNumberOfPoints << " are supported.");
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      representative->SetValue(i, -1);
    }
    return finish();
  }
  const std::string nanParameters = pcs::NaNParametersError({ { "Tolerance", this->Tolerance } });
  if (!nanParameters.empty())
  {
    vtkErrorMacro(<< nanParameters);
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      representative->SetValue(i, -1);
    }
    return finish();
  }

  // Coordinates as doubles; non-finite points are skipped (RepresentativeId -1).
  std::vector<double> xyz;
  std::vector<int32_t> ids;
  this->NumberOfSkippedPoints = pcs::ReadFiniteCoordinates(input->GetPoints(), xyz, ids);
  representative->FillValue(-1);
  for (const int32_t id : ids)
  {
    representative->SetValue(id, id);
  }
  if (this->NumberOfSkippedPoints > 0)
  {
    vtkWarningMacro("Skipped " << this->NumberOfSkippedPoints
                               << " point(s) with NaN or infinite coordinates.");
  }
  this->UpdateProgress(0.05);

  // The triangulated coordinates: the points themselves in 3D, their projection in 2.5D.
  ProjectionFrame frame;
  std::vector<double> uv;
  if (this->Dimension == 2)
  {
    if (this->ProjectionPlane == BEST_FIT_PLANE)
    {
      frame.Fit(xyz.data(), ids.data(), ids.size());
    }
    uv.resize(2 * static_cast<size_t>(numberOfPoints), 0.0);
    for (int32_t id : ids)
    {
      frame.Project(&xyz[3 * static_cast<size_t>(id)], &uv[2 * static_cast<size_t>(id)]);
    }
    MergeExactDuplicates(uv.data(), 2, ids, representative);
  }
  if (this->Tolerance > 0.0)
  {
    MergeWithinTolerance(this->Tolerance, this->Dimension == 2 ? uv.data() : xyz.data(),
      this->Dimension, ids, representative);
  }

  const double progressBegin = 0.1, progressEnd = 0.85;
  auto progress = [this, progressBegin, progressEnd](double fraction) {
    this->UpdateProgress(progressBegin + (progressEnd - progressBegin) * fraction);
    return !this->GetAbortExecute();
  };

  if (this->Dimension == 3)
  {
    this->NumberOfCells =
      Triangulate3D(this, xyz.data(), ids, progress, representative, surface, cells, voronoi);
  }
  else
  {
    this->NumberOfCells =
      Triangulate2D(this, uv.data(), frame, ids, progress, surface, cells, voronoi);
  }

  // Chains of merges (an exact duplicate of a point merged within Tolerance) end at the point
  // kept in the triangulation.
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    vtkIdType r = representative->GetValue(i);
    while (r >= 0 && representative->GetValue(r) != r)
    {
      r = representative->GetValue(r);
    }
    representative->SetValue(i, r);
    if (r >= 0 && r != i)
    {
      ++this->NumberOfDuplicatePoints;
    }
  }
  if (this->NumberOfDuplicatePoints > 0)
  {
    vtkWarningMacro("Merged " << this->NumberOfDuplicatePoints
                              << " duplicate point(s) into the point they coincide with"
                              << (this->Tolerance > 0 ? " (within Tolerance)." : ".")
                              << " See the point data array RepresentativeId.");
  }
  this->UpdateProgress(1.0);
  return finish();
}

//------------------------------------------------------------------------------------------------
void vtkIncrementalDelaunay3D::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Dimension: " << this->Dimension << "\n";
  os << indent << "ProjectionPlane: "
     << (this->ProjectionPlane == XY_PLANE ? "XY_PLANE" : "BEST_FIT_PLANE") << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "GenerateTetrahedra: " << this->GenerateTetrahedra << "\n";
  os << indent << "GenerateVoronoi: " << this->GenerateVoronoi << "\n";
  os << indent << "NumberOfInputPoints: " << this->NumberOfInputPoints << "\n";
  os << indent << "NumberOfDuplicatePoints: " << this->NumberOfDuplicatePoints << "\n";
  os << indent << "NumberOfSkippedPoints: " << this->NumberOfSkippedPoints << "\n";
  os << indent << "NumberOfCells: " << this->NumberOfCells << "\n";
}
