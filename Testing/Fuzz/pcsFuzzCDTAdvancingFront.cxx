// Fuzz target of vtkCDTAdvancingFront: a small, often degenerate cloud from the bytes
// (pcsFuzzSurface.h) without normals (estimated by PCA), with radial or arbitrary normals, or
// with zero-length and NaN normals mixed in, the parameters over their ranges (limits
// included), then the invariants of pcsFuzzSurface.h (the class promises no non-manifold edge
// or vertex and consistently oriented triangles) and its own:
// - NumberOfPoints = the input points, NumberOfUnusedPoints = the points with Used = 0;
// - every used point has a finite, non-zero normal among the normals used (passed to the output
//   as EstimatedNormals or Normals when some were estimated: zero-length and NaN input normals
//   are estimated);
// - cell data HoleFilled and HoleTriangle: their sums are NumberOfHoleFillingTriangles and
//   NumberOfHoleTriangles, HoleTriangle = 1 exactly for the triangles with an edge of a single
//   triangle (vtkReconstructionQuality's BoundaryEdge), NumberOfFrontTriangles = triangles -
//   hole-filling triangles >= NumberOfSeedTriangles;
// - NumberOfSkippedPoints counts at least the points with a non-finite coordinate.
// A violated invariant aborts.
#include "pcsFuzzSurface.h"
#include "vtkCDTAdvancingFront.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  pcsfuzz::Quiet();
  const char* name = "vtkCDTAdvancingFront";
  const pcsfuzz::SurfaceInput input = pcsfuzz::MakeSurfaceInput(data, size);
  const uint8_t* p = input.Parameters;

  vtkNew<vtkCDTAdvancingFront> cdt;
  cdt->SetInputData(input.Data);
  cdt->SetUseInputNormals((p[0] & 0x80) == 0);
  cdt->SetNormalSampleSize((p[0] & 0x07) == 7 ? 1000 : 2 + (p[0] & 0x07) * 3);
  // Radius: automatic (factor in [1, 100], limits beyond), or fixed (tiny to VTK_DOUBLE_MAX).
  const int radius = (p[0] >> 3) & 0x0f;
  if (radius < 8)
  {
    cdt->SetNeighborhoodRadiusFactor(radius == 0 ? 0.0 : (radius == 7 ? 1e9 : 1.0 + radius));
  }
  else
  {
    cdt->SetNeighborhoodRadius(radius == 15 ? VTK_DOUBLE_MAX : std::ldexp(1.0, 2 * (radius - 12)));
  }
  cdt->SetMinimumNormalDot((p[1] & 0x0f) / 14.0 - 0.03);
  cdt->SetHoleFillingMinimumNormalDot((p[1] >> 4) / 14.0 - 0.03);
  cdt->SetMaximumNumberOfCandidates((p[2] & 0x0f) == 15 ? VTK_INT_MAX : (p[2] & 0x0f) * 3);
  const int ray = (p[2] >> 4) & 0x03;
  cdt->SetMaximumRayDistance(ray == 3 ? VTK_DOUBLE_MAX : (ray == 2 ? 1e-3 : 0.0));
  const int area = (p[2] >> 6) & 0x03;
  cdt->SetMinimumTriangleArea(area == 3 ? VTK_DOUBLE_MAX : (area == 2 ? 1e-3 : 0.0));
  cdt->SetHoleFilling((p[3] & 0x80) == 0);
  cdt->SetHoleFillingRadiusFactor((p[3] & 0x7f) / 100.0);
  cdt->Update();
  vtkPolyData* out = cdt->GetOutput();
  vtkSmartPointer<vtkPolyData> measures = pcsfuzz::CheckSurface(name, input, out, true);

  const vtkIdType n = input.N;
  if (n == 0)
  {
    return 0;
  }
  vtkDataArray* used = pcsfuzz::PointArray(name, out, "Used");
  vtkDataArray* normals = out->GetPointData()->GetArray("EstimatedNormals");
  normals = normals ? normals : out->GetPointData()->GetArray("Normals");
  if (normals && (normals->GetNumberOfComponents() != 3 || normals->GetNumberOfTuples() != n))
  {
    pcsfuzz::Fail(name, "the normals used do not have 3 components per point");
  }
  vtkIdType unused = 0, nonFinite = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    nonFinite += pcsfuzz::Finite(&input.XYZ[3 * i]) ? 0 : 1;
    if (used->GetTuple1(i) == 0)
    {
      ++unused;
    }
    else if (normals)
    {
      const double* v = normals->GetTuple3(i);
      if (!pcsfuzz::Finite(v) || (v[0] == 0 && v[1] == 0 && v[2] == 0))
      {
        pcsfuzz::Fail(name, "a used point has a zero-length or non-finite normal");
      }
    }
  }
  if (pcsfuzz::Field(name, out, "NumberOfPoints") != n ||
    pcsfuzz::Field(name, out, "NumberOfUnusedPoints") != unused ||
    pcsfuzz::Field(name, out, "NumberOfSkippedPoints") < nonFinite)
  {
    pcsfuzz::Fail(name, "point counts inconsistent");
  }
  const vtkIdType triangles = out->GetNumberOfPolys();
  vtkDataArray* holeFilled = pcsfuzz::CellArray(name, out, "HoleFilled");
  vtkDataArray* holeTriangle = pcsfuzz::CellArray(name, out, "HoleTriangle");
  vtkDataArray* boundary = measures->GetCellData()->GetArray("BoundaryEdge");
  double filledSum = 0, holeSum = 0;
  for (vtkIdType t = 0; t < triangles; ++t)
  {
    filledSum += holeFilled->GetTuple1(t);
    holeSum += holeTriangle->GetTuple1(t);
    if ((holeTriangle->GetTuple1(t) != 0) != (boundary->GetTuple1(t) > 0))
    {
      pcsfuzz::Fail(name, "HoleTriangle differs from the triangles with a boundary edge");
    }
  }
  const double filling = pcsfuzz::Field(name, out, "NumberOfHoleFillingTriangles");
  const double front = pcsfuzz::Field(name, out, "NumberOfFrontTriangles");
  if (filledSum != filling || holeSum != pcsfuzz::Field(name, out, "NumberOfHoleTriangles") ||
    front != triangles - filling || pcsfuzz::Field(name, out, "NumberOfSeedTriangles") > front)
  {
    pcsfuzz::Fail(name, "triangle counts inconsistent");
  }
  return 0;
}
