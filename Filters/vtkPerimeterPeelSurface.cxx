#include "vtkPerimeterPeelSurface.h"

#include "pcsCoordinateScaling.h"
#include "pcsDelaunay3D.h"
#include "pcsFieldData.h"
#include "pcsGatherInput.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkPerimeterPeelSurface);

namespace
{
// The solid being peeled: the finite tetrahedra of a Delaunay tetrahedralization, each inside or
// removed, with the number of inside tetrahedra at each vertex.
class PeelSolid
{
public:
  PeelSolid(const pcs::Delaunay3D& dt, const double* xyz, int measure, vtkIdType numberOfPoints)
    : DT(dt)
    , XYZ(xyz)
    , Measure(measure)
  {
    const int64_t cells = dt.GetNumberOfCells();
    this->Inside.assign(cells, 0);
    this->Count.assign(numberOfPoints, 0);
    for (int64_t c = 0; c < cells; ++c)
    {
      if (!dt.IsInfinite(c))
      {
        this->Inside[c] = 1;
        for (int k = 0; k < 4; ++k)
        {
          ++this->Count[dt.Vertex(c, k)];
        }
      }
    }
  }

  bool IsInside(int64_t c) const { return this->Inside[c] != 0; }

  // Facet j of c (opposite vertex j) is exterior: c inside, its neighbour across j not.
  bool IsExterior(int64_t c, int j) const
  {
    return this->Inside[c] && !this->Inside[this->DT.Neighbor(c, j)];
  }

  // The measure of facet j of c (perimeter, area or circumradius of its triangle).
  double FacetMeasure(int64_t c, int j) const
  {
    const double* p[3];
    for (int k = 0, m = 0; k < 4; ++k)
    {
      if (k != j)
      {
        p[m++] = this->XYZ + 3 * static_cast<int64_t>(this->DT.Vertex(c, k));
      }
    }
    double e[3][3];
    double length[3];
    for (int i = 0; i < 3; ++i)
    {
      const double* a = p[i];
      const double* b = p[(i + 1) % 3];
      e[i][0] = b[0] - a[0];
      e[i][1] = b[1] - a[1];
      e[i][2] = b[2] - a[2];
      length[i] = std::sqrt(e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2]);
    }
    if (this->Measure == vtkPerimeterPeelSurface::PERIMETER)
    {
      return length[0] + length[1] + length[2];
    }
    const double n[3] = { e[0][1] * e[1][2] - e[0][2] * e[1][1],
      e[0][2] * e[1][0] - e[0][0] * e[1][2], e[0][0] * e[1][1] - e[0][1] * e[1][0] };
    const double twiceArea = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (this->Measure == vtkPerimeterPeelSurface::AREA)
    {
      return 0.5 * twiceArea;
    }
    // R = abc / (4 area); a flat triangle has an infinite circumradius.
    return twiceArea > 0.0 ? length[0] * length[1] * length[2] / (2.0 * twiceArea)
                           : std::numeric_limits<double>::infinity();
  }

  // Whether removing c would leave one of its vertices in no inside tetrahedron.
  bool Orphans(int64_t c) const
  {
    for (int k = 0; k < 4; ++k)
    {
      if (this->Count[this->DT.Vertex(c, k)] <= 1)
      {
        return true;
      }
    }
    return false;
  }

  void SetInside(int64_t c, bool inside)
  {
    if (this->IsInside(c) == inside)
    {
      return;
    }
    this->Inside[c] = inside ? 1 : 0;
    for (int k = 0; k < 4; ++k)
    {
      this->Count[this->DT.Vertex(c, k)] += inside ? 1 : -1;
    }
  }

  const pcs::Delaunay3D& DT;
  const double* XYZ;
  int Measure;
  std::vector<uint8_t> Inside;
  std::vector<int32_t> Count;
};

// The exterior facets as oriented triangles (outward from the solid). In a positively oriented
// cell (v0, v1, v2, v3), the increasing-slot triple without vertex j faces away from v_j when j
// is odd and towards it when j is even.
std::vector<std::array<int32_t, 3>> ExteriorTriangles(const PeelSolid& solid)
{
  std::vector<std::array<int32_t, 3>> triangles;
  const int64_t cells = solid.DT.GetNumberOfCells();
  for (int64_t c = 0; c < cells; ++c)
  {
    if (!solid.IsInside(c))
    {
      continue;
    }
    for (int j = 0; j < 4; ++j)
    {
      if (!solid.IsExterior(c, j))
      {
        continue;
      }
      std::array<int32_t, 3> t;
      for (int k = 0, m = 0; k < 4; ++k)
      {
        if (k != j)
        {
          t[m++] = solid.DT.Vertex(c, k);
        }
      }
      if (j % 2 == 0)
      {
        std::swap(t[1], t[2]);
      }
      triangles.push_back(t);
    }
  }
  return triangles;
}

// Vertices where the triangle set is not a 2-manifold: an edge with more than two triangles, or
// triangles around the vertex forming more than one fan (connected through shared edges).
std::vector<int32_t> SingularVertices(
  const std::vector<std::array<int32_t, 3>>& triangles, vtkIdType numberOfPoints)
{
  // Per vertex: the (other vertex of the edge, triangle) pairs of its corners, two per corner.
  std::vector<int64_t> offsets(numberOfPoints + 1, 0);
  for (const auto& t : triangles)
  {
    for (int32_t v : t)
    {
      offsets[v + 1] += 2;
    }
  }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<std::pair<int32_t, int32_t>> corners(offsets[numberOfPoints]);
  {
    std::vector<int64_t> next(offsets.begin(), offsets.end() - 1);
    for (size_t i = 0; i < triangles.size(); ++i)
    {
      const auto& t = triangles[i];
      for (int k = 0; k < 3; ++k)
      {
        const int32_t v = t[k];
        corners[next[v]++] = { t[(k + 1) % 3], static_cast<int32_t>(i) };
        corners[next[v]++] = { t[(k + 2) % 3], static_cast<int32_t>(i) };
      }
    }
  }
  std::vector<int32_t> singular;
  std::vector<int32_t> parent;
  for (vtkIdType v = 0; v < numberOfPoints; ++v)
  {
    auto first = corners.begin() + offsets[v], last = corners.begin() + offsets[v + 1];
    if (first == last)
    {
      continue;
    }
    std::sort(first, last);
    // Fans: union the two triangles of each edge (v, w); more than two on an edge: singular.
    const int64_t size = last - first;
    parent.resize(size);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&parent](int64_t i) {
      while (parent[i] != i)
      {
        parent[i] = parent[parent[i]];
        i = parent[i];
      }
      return i;
    };
    bool bad = false;
    // Map triangle -> first local index, to join the two corners of one triangle at v.
    for (int64_t i = 0; i < size && !bad; ++i)
    {
      int64_t j = i;
      while (j + 1 < size && first[j + 1].first == first[i].first)
      {
        ++j;
      }
      if (j - i + 1 > 2)
      {
        bad = true; // edge (v, w) with more than two triangles
      }
      else if (j == i + 1)
      {
        parent[find(i)] = find(j);
      }
      i = j;
    }
    if (!bad)
    {
      // Corners of the same triangle belong together.
      std::vector<std::pair<int32_t, int64_t>> byTriangle;
      byTriangle.reserve(size);
      for (int64_t i = 0; i < size; ++i)
      {
        byTriangle.emplace_back(first[i].second, i);
      }
      std::sort(byTriangle.begin(), byTriangle.end());
      for (int64_t i = 0; i + 1 < size; ++i)
      {
        if (byTriangle[i].first == byTriangle[i + 1].first)
        {
          parent[find(byTriangle[i].second)] = find(byTriangle[i + 1].second);
        }
      }
      int64_t roots = 0;
      for (int64_t i = 0; i < size; ++i)
      {
        roots += find(i) == i ? 1 : 0;
      }
      bad = roots > 1;
    }
    if (bad)
    {
      singular.push_back(static_cast<int32_t>(v));
    }
  }
  return singular;
}

// The cells (finite and infinite) that have vertex v, starting from cell `start` which has it.
void StarOf(const pcs::Delaunay3D& dt, int32_t v, int64_t start, std::vector<int64_t>& star)
{
  star.clear();
  star.push_back(start);
  for (size_t i = 0; i < star.size(); ++i)
  {
    const int64_t c = star[i];
    for (int j = 0; j < 4; ++j)
    {
      if (dt.Vertex(c, j) == v)
      {
        continue; // the facet opposite v does not contain it
      }
      const int64_t n = dt.Neighbor(c, j);
      if (std::find(star.begin(), star.end(), n) == star.end())
      {
        star.push_back(n);
      }
    }
  }
}
} // namespace

//------------------------------------------------------------------------------------------------
vtkPerimeterPeelSurface::vtkPerimeterPeelSurface() = default;

int vtkPerimeterPeelSurface::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

//------------------------------------------------------------------------------------------------
int vtkPerimeterPeelSurface::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  vtkSmartPointer<vtkPointSet> input =
    pcs::GatherInputOnFirstProcess(vtkPointSet::GetData(inputVector[0]));
  if (!input && output)
  {
    return 1; // another MPI process: process 0 computes the surface
  }
  if (!input || !output)
  {
    vtkErrorMacro("Missing input or output data object.");
    return 0;
  }

  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
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

  vtkIdType iterations = 0, removedCount = 0, restoredCount = 0, tetrahedra = 0;
  double finalThreshold = 0.0;
  vtkNew<vtkCellArray> polys;
  auto finish = [&]() {
    output->SetPolys(polys);
    vtkIdType usedPoints = 0;
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      usedPoints += used->GetValue(i);
    }
    vtkFieldData* fd = output->GetFieldData();
    pcs::AddFieldCount(fd, "NumberOfIterations", iterations);
    pcs::AddFieldValue(fd, "FinalThreshold", finalThreshold);
    pcs::AddFieldCount(fd, "NumberOfTetrahedra", tetrahedra);
    pcs::AddFieldCount(fd, "NumberOfRemovedTetrahedra", removedCount);
    pcs::AddFieldCount(fd, "NumberOfRestoredTetrahedra", restoredCount);
    pcs::AddFieldCount(fd, "NumberOfTriangles", polys->GetNumberOfCells());
    pcs::AddFieldCount(fd, "NumberOfUsedPoints", usedPoints);
    pcs::AddFieldCount(fd, "NumberOfUnusedPoints", numberOfPoints - usedPoints);
    if (numberOfPoints > usedPoints && polys->GetNumberOfCells() > 0)
    {
      vtkWarningMacro(<< numberOfPoints - usedPoints << " of " << numberOfPoints
                      << " point(s) are not on the surface (duplicates, non-finite points or "
                         "points inside the solid): see the point data array Used.");
    }
    return 1;
  };

  if (numberOfPoints == 0)
  {
    vtkWarningMacro("The input has no points: the output is empty.");
    return finish();
  }
  if (numberOfPoints > 150000000)
  {
    vtkErrorMacro("The input has " << numberOfPoints << " points; at most 150000000 are supported.");
    return finish();
  }

  // Finite coordinates, scaled by a power of two into the predicates' range when needed.
  std::vector<double> xyz(3 * static_cast<size_t>(numberOfPoints));
  std::vector<int32_t> ids;
  ids.reserve(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    input->GetPoint(i, &xyz[3 * i]);
    if (std::isfinite(xyz[3 * i]) && std::isfinite(xyz[3 * i + 1]) &&
      std::isfinite(xyz[3 * i + 2]))
    {
      ids.push_back(static_cast<int32_t>(i));
    }
  }
  if (static_cast<vtkIdType>(ids.size()) < numberOfPoints)
  {
    vtkWarningMacro("Skipped " << numberOfPoints - static_cast<vtkIdType>(ids.size())
                               << " point(s) with NaN or infinite coordinates.");
  }
  const int exponent = pcs::PredicateSafeExponent(xyz.data(), 3, ids);
  if (exponent != 0)
  {
    xyz = pcs::ScaledCopy(xyz.data(), xyz.size(), exponent);
  }

  pcs::Delaunay3D dt;
  auto progress = [this](double fraction) {
    this->UpdateProgress(0.6 * fraction);
    return !this->GetAbortExecute();
  };
  if (!dt.Triangulate(xyz.data(), ids, progress))
  {
    if (!this->GetAbortExecute())
    {
      vtkWarningMacro("Fewer than 4 distinct non-coplanar points among the "
        << ids.size() << " usable point(s): no surface is produced.");
    }
    return finish();
  }
  tetrahedra = dt.GetNumberOfFiniteCells();
  this->UpdateProgress(0.6);

  // Peeling (paper section 3, steps 3-7).
  PeelSolid solid(dt, xyz.data(), this->FacetMeasure, numberOfPoints);
  const int64_t cells = dt.GetNumberOfCells();
  double sum = 0.0;
  int64_t exterior = 0;
  for (int64_t c = 0; c < cells; ++c)
  {
    for (int j = 0; j < 4 && solid.IsInside(c); ++j)
    {
      if (solid.IsExterior(c, j))
      {
        sum += solid.FacetMeasure(c, j);
        ++exterior;
      }
    }
  }
  const bool fixed = this->Threshold > 0.0;
  double mean = exterior > 0 ? sum / exterior : 0.0;
  double threshold = fixed ? std::ldexp(this->Threshold, exponent) : mean * this->ThresholdFactor;
  using Entry = std::pair<double, int64_t>; // measure, 4 * cell + facet
  std::priority_queue<Entry> queue;
  bool aborted = false;
  while (!aborted)
  {
    for (int64_t c = 0; c < cells; ++c)
    {
      for (int j = 0; j < 4 && solid.IsInside(c); ++j)
      {
        if (solid.IsExterior(c, j))
        {
          const double m = solid.FacetMeasure(c, j);
          if (m > threshold)
          {
            queue.emplace(m, 4 * c + j);
          }
        }
      }
    }
    while (!queue.empty())
    {
      const int64_t facet = queue.top().second;
      queue.pop();
      const int64_t c = facet >> 2;
      if (!solid.IsExterior(c, static_cast<int>(facet & 3)) || solid.Orphans(c))
      {
        continue;
      }
      // Remove c: its exterior facets leave the surface, the others join it.
      for (int k = 0; k < 4; ++k)
      {
        const double m = solid.FacetMeasure(c, k);
        if (solid.IsExterior(c, k))
        {
          sum -= m;
          --exterior;
        }
        else
        {
          sum += m;
          ++exterior;
          if (m > threshold)
          {
            queue.emplace(m, 4 * dt.Neighbor(c, k) + dt.MirrorIndex(c, k));
          }
        }
      }
      solid.SetInside(c, false);
      ++removedCount;
      if (removedCount % 65536 == 0)
      {
        this->UpdateProgress(std::min(0.9, 0.6 + 0.3 * removedCount / double(tetrahedra)));
        if (this->GetAbortExecute())
        {
          aborted = true;
          break;
        }
      }
    }
    ++iterations;
    if (aborted || fixed || exterior == 0 || iterations >= this->MaximumIterations)
    {
      break;
    }
    const double updated = sum / exterior;
    if (std::fabs(updated - mean) <= this->ConvergenceTolerance * mean)
    {
      break;
    }
    mean = updated;
    threshold = mean * this->ThresholdFactor;
  }
  finalThreshold = std::ldexp(threshold, -exponent);
  if (aborted)
  {
    return finish();
  }
  this->UpdateProgress(0.9);

  std::vector<std::array<int32_t, 3>> triangles = ExteriorTriangles(solid);
  if (this->ManifoldOutput)
  {
    // Restore the removed tetrahedra around every singular vertex until there is none left.
    std::vector<int64_t> star;
    for (int round = 0; round < 10000; ++round)
    {
      const std::vector<int32_t> singular = SingularVertices(triangles, numberOfPoints);
      if (singular.empty() || this->GetAbortExecute())
      {
        break;
      }
      // A cell of each singular vertex: any inside cell that has it.
      std::vector<int64_t> startCell(numberOfPoints, -1);
      for (int32_t v : singular)
      {
        startCell[v] = -2; // wanted
      }
      for (int64_t c = 0; c < cells; ++c)
      {
        if (!solid.IsInside(c))
        {
          continue;
        }
        for (int k = 0; k < 4; ++k)
        {
          const int32_t v = dt.Vertex(c, k);
          if (startCell[v] == -2)
          {
            startCell[v] = c;
          }
        }
      }
      for (int32_t v : singular)
      {
        StarOf(dt, v, startCell[v], star);
        for (int64_t c : star)
        {
          if (!dt.IsInfinite(c) && !solid.IsInside(c))
          {
            solid.SetInside(c, true);
            ++restoredCount;
          }
        }
      }
      triangles = ExteriorTriangles(solid);
    }
  }

  vtkNew<vtkTypeInt32Array> connectivity;
  connectivity->SetNumberOfValues(3 * static_cast<vtkIdType>(triangles.size()));
  vtkNew<vtkTypeInt32Array> offsets;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(triangles.size()) + 1);
  for (size_t t = 0; t < triangles.size(); ++t)
  {
    offsets->SetValue(static_cast<vtkIdType>(t), static_cast<int32_t>(3 * t));
    for (int k = 0; k < 3; ++k)
    {
      connectivity->SetValue(static_cast<vtkIdType>(3 * t + k), triangles[t][k]);
      used->SetValue(triangles[t][k], 1);
    }
  }
  offsets->SetValue(
    static_cast<vtkIdType>(triangles.size()), static_cast<int32_t>(3 * triangles.size()));
  polys->SetData(offsets, connectivity);
  this->UpdateProgress(1.0);
  return finish();
}

//------------------------------------------------------------------------------------------------
void vtkPerimeterPeelSurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ThresholdFactor: " << this->ThresholdFactor << "\n";
  os << indent << "ConvergenceTolerance: " << this->ConvergenceTolerance << "\n";
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "FacetMeasure: " << this->FacetMeasure << "\n";
  os << indent << "MaximumIterations: " << this->MaximumIterations << "\n";
  os << indent << "ManifoldOutput: " << this->ManifoldOutput << "\n";
}
