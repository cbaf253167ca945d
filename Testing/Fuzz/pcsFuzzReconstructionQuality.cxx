// Fuzz target of vtkReconstructionQuality: a small triangle mesh from the bytes (coordinates of a
// degenerate-prone family as in pcsFuzzInput.h, then triangles whose ids may repeat, go out of
// range, duplicate or flip other triangles, share an edge three times or pinch a vertex), an
// optional reference (the same points as a cloud), then the invariants of the measures:
// - counts are consistent: used points <= points, coverage = used / points in [0, 1],
//   triangles <= the triangles given, non-manifold, boundary edges <= 3 x triangles;
// - closed manifold meshes (no boundary, no non-manifold edge or vertex) have an integer genus
//   >= -1 and an even Euler characteristic when orientable;
// - orientation consistency in [0, 1]; distances, when defined, >= 0;
// - every per-cell and per-point array has one value per cell / point.
// A violated invariant aborts.
#include "pcsFuzzInput.h"
#include "vtkReconstructionQuality.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace
{
void Fail(const char* what)
{
  std::fprintf(stderr, "pcsFuzzReconstructionQuality: invariant violated: %s\n", what);
  std::abort();
}

double Field(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  if (!array || array->GetNumberOfTuples() != 1)
  {
    Fail(name);
  }
  return array->GetTuple1(0);
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  static bool quiet = [] {
    vtkObject::GlobalWarningDisplayOff();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    return true;
  }();
  (void)quiet;
  if (size < 4)
  {
    return 0;
  }
  // Header: byte 0 = number of triangles (0..63), byte 1 = whether a reference is given; the
  // rest: first the cloud (pcsFuzzInput.h), then 3 bytes per triangle from the end.
  const int triangles = data[0] % 64;
  const bool withReference = (data[1] & 1) != 0;
  const size_t tail = std::min(size - 2, static_cast<size_t>(3 * triangles));
  const std::vector<double> xyz = pcsfuzz::Cloud(data + 2, size - 2 - tail, 3);
  const vtkIdType n = static_cast<vtkIdType>(xyz.size() / 3);

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->InsertNextPoint(&xyz[3 * i]);
  }
  vtkNew<vtkCellArray> polys;
  const uint8_t* t = data + size - tail;
  for (size_t k = 0; k + 2 < tail; k += 3)
  {
    // Ids a little beyond n test the out-of-range handling.
    const vtkIdType ids[3] = { t[k] % (n + 2), t[k + 1] % (n + 2), t[k + 2] % (n + 2) };
    polys->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(polys);

  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputData(0, mesh);
  vtkNew<vtkPolyData> cloud;
  if (withReference)
  {
    cloud->SetPoints(points);
    quality->SetInputData(1, cloud);
  }
  quality->SetSamplesPerTriangle(data[1] % 5);
  quality->Update();
  vtkPolyData* out = quality->GetOutput();
  if (out->GetNumberOfPoints() != n || out->GetNumberOfCells() != mesh->GetNumberOfCells())
  {
    Fail("output is not the input mesh");
  }
  if (n == 0 || polys->GetNumberOfCells() == 0)
  {
    return 0; // warned; counts are zero
  }
  const double used = Field(out, "NumberOfUsedPoints");
  const double coverage = Field(out, "Coverage");
  const double tris = Field(out, "NumberOfTriangles");
  const double boundary = Field(out, "NumberOfBoundaryEdges");
  const double nonManifoldEdges = Field(out, "NumberOfNonManifoldEdges");
  const double nonManifoldVertices = Field(out, "NumberOfNonManifoldVertices");
  const double genus = Field(out, "Genus");
  const double euler = Field(out, "EulerCharacteristic");
  const double orientation = Field(out, "OrientationConsistency");
  if (used < 0 || used > n || std::fabs(coverage - used / n) > 1e-12 || tris < 0 ||
    tris > polys->GetNumberOfCells() || boundary < 0 || boundary > 3 * tris ||
    nonManifoldEdges < 0 || nonManifoldEdges > 3 * tris || nonManifoldVertices < 0 ||
    nonManifoldVertices > used)
  {
    Fail("inconsistent counts");
  }
  if (!(orientation >= 0.0 && orientation <= 1.0))
  {
    Fail("orientation consistency outside [0, 1]");
  }
  if (genus != -1)
  {
    if (boundary != 0 || nonManifoldEdges != 0 || nonManifoldVertices != 0 || genus < 0 ||
      static_cast<long long>(euler) % 2 != 0)
    {
      Fail("genus given for a mesh that is not closed, manifold and orientable");
    }
  }
  const char* cellArrays[] = { "NonManifoldEdge", "BoundaryEdge", "MinAngle" };
  for (const char* name : cellArrays)
  {
    vtkDataArray* a = out->GetCellData()->GetArray(name);
    if (!a || a->GetNumberOfTuples() != out->GetNumberOfCells())
    {
      Fail(name);
    }
  }
  const char* pointArrays[] = { "Used", "NonManifoldVertex" };
  for (const char* name : pointArrays)
  {
    vtkDataArray* a = out->GetPointData()->GetArray(name);
    if (!a || a->GetNumberOfTuples() != n)
    {
      Fail(name);
    }
  }
  if (withReference)
  {
    const char* distances[] = { "AccuracyMean", "AccuracyMax", "CompletenessMean",
      "CompletenessMax", "Hausdorff" };
    for (const char* name : distances)
    {
      const double d = Field(out, name);
      if (!std::isnan(d) && d < 0)
      {
        Fail(name);
      }
    }
  }
  return 0;
}
