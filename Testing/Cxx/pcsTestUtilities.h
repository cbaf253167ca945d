// Helpers shared by the C++ tests of PointCloudSurface (not part of the library).
#ifndef pcsTestUtilities_h
#define pcsTestUtilities_h

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkReconstructionQuality.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace pcstest
{
// Counts the warnings and errors a filter (or its executive) emits: register Callback with a
// vtkCallbackCommand whose client data is the counter.
struct MessageCounter
{
  int Warnings = 0;
  int Errors = 0;
  static void Callback(vtkObject*, unsigned long event, void* data, void*)
  {
    auto* self = static_cast<MessageCounter*>(data);
    (event == vtkCommand::ErrorEvent ? self->Errors : self->Warnings)++;
  }
};

#define PCS_CHECK(condition, message)                                                              \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #condition " -- " << message  \
                << std::endl;                                                                      \
      return false;                                                                                \
    }                                                                                              \
  } while (false)

/// A point cloud (vertices only) from packed x, y, z coordinates.
inline vtkSmartPointer<vtkPolyData> MakeCloud(const std::vector<double>& xyz)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(xyz.size() / 3));
  for (size_t i = 0; i < xyz.size() / 3; ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), &xyz[3 * i]);
  }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  return cloud;
}

/// Uniform random points in the unit cube.
inline std::vector<double> UniformCube(int n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xyz(3 * static_cast<size_t>(n));
  for (double& c : xyz)
  {
    c = u(rng);
  }
  return xyz;
}

/// `n` uniform random points on a small open patch over the unit disc, with the exact unit
/// normals (upwards): the bowl z = 0.2 (x^2 + y^2) or the tilted plane z = 0.3 x + 0.2 y (a disc
/// whose points are not exactly coplanar in floating point). Packed x, y, z.
inline void SmallOpenPatch(
  bool bowl, int n, unsigned seed, std::vector<double>& xyz, std::vector<double>& normals)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  xyz.clear();
  normals.clear();
  while (static_cast<int>(xyz.size() / 3) < n)
  {
    const double x = u(rng), y = u(rng);
    if (x * x + y * y > 1.0)
    {
      continue;
    }
    const double gx = bowl ? 0.4 * x : 0.3, gy = bowl ? 0.4 * y : 0.2;
    const double z = bowl ? 0.2 * (x * x + y * y) : 0.3 * x + 0.2 * y;
    const double length = std::sqrt(gx * gx + gy * gy + 1.0);
    xyz.insert(xyz.end(), { x, y, z });
    normals.insert(normals.end(), { -gx / length, -gy / length, 1.0 / length });
  }
}

/// Cells of a data set as fixed-size id tuples (N = 3 or 4).
template <int N, typename DataSetT>
std::vector<std::array<vtkIdType, N>> CellTuples(DataSetT* data)
{
  std::vector<std::array<vtkIdType, N>> cells;
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    data->GetCellPoints(c, npts, pts);
    std::array<vtkIdType, N> t;
    for (int i = 0; i < N; ++i)
    {
      t[i] = i < npts ? pts[i] : -1;
    }
    cells.push_back(t);
  }
  return cells;
}

inline vtkIdType FieldCount(vtkDataObject* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? static_cast<vtkIdType>(array->GetTuple1(0)) : -1;
}

/// A topology field of vtkReconstructionQuality on `mesh` (no distances), -1 when missing.
inline double QualityValue(vtkPolyData* mesh, const char* name)
{
  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputData(mesh);
  quality->ComputeDistancesOff();
  quality->Update();
  vtkDataArray* array = quality->GetOutput()->GetFieldData()->GetArray(name);
  return array ? array->GetTuple1(0) : -1.0;
}

/// `mesh` is one closed, manifold, consistently oriented surface of the given genus over `points`
/// vertices, hence with 2 points - 4 + 4 genus triangles (Euler: V - E + T = 2 - 2 genus, 3 T = 2
/// E), all checked with vtkReconstructionQuality (no distances); `what` names the case in the
/// message.
inline bool CheckClosedSurface(
  vtkPolyData* mesh, vtkIdType points, int genus, const std::string& what)
{
  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputData(mesh);
  quality->ComputeDistancesOff();
  quality->Update();
  vtkFieldData* field = quality->GetOutput()->GetFieldData();
  auto value = [field](const char* name)
  {
    vtkDataArray* array = field->GetArray(name);
    return array ? array->GetTuple1(0) : -1.0;
  };
  PCS_CHECK(value("NumberOfNonManifoldEdges") == 0 && value("NumberOfNonManifoldVertices") == 0,
    what << ": not manifold");
  PCS_CHECK(value("OrientationConsistency") == 1.0, what << ": not oriented");
  PCS_CHECK(value("NumberOfConnectedComponents") == 1,
    what << ": " << value("NumberOfConnectedComponents") << " components, expected 1");
  PCS_CHECK(value("NumberOfBoundaryEdges") == 0 && value("Genus") == genus,
    what << ": " << value("NumberOfBoundaryEdges") << " boundary edges, genus " << value("Genus")
         << ", expected closed genus " << genus);
  const double triangles = 2.0 * static_cast<double>(points) - 4.0 + 4.0 * genus;
  PCS_CHECK(value("NumberOfTriangles") == triangles,
    what << ": " << value("NumberOfTriangles") << " triangles, expected " << triangles);
  return true;
}

/// The largest `distance` (a function of a point, e.g. to a known surface) over the centroids of
/// the triangles of `mesh`.
template<typename Distance>
double FarthestCentroid(vtkPolyData* mesh, Distance&& distance)
{
  double farthest = 0.0;
  for (const auto& t : CellTuples<3>(mesh))
  {
    double centroid[3] = { 0.0, 0.0, 0.0 };
    for (vtkIdType v : t)
    {
      double p[3];
      mesh->GetPoint(v, p);
      for (int i = 0; i < 3; ++i)
      {
        centroid[i] += p[i] / 3.0;
      }
    }
    farthest = std::max(farthest, distance(centroid));
  }
  return farthest;
}
} // namespace pcstest

#endif
