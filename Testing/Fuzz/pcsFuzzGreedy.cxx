// Fuzz target of vtkGreedySurfaceTriangulation: a small, often degenerate cloud from the bytes
// (pcsFuzzSurface.h), the parameters over their ranges (limits included), then the invariants
// of pcsFuzzSurface.h (the class promises an oriented 2-manifold with boundary) and its own:
// - Status in 0..4; lost and unused (2), not triangulated (4) points are unused, lost points
//   used by hole filling (3) are used; the points with Status 4 are at least
//   NumberOfDuplicatePoints + NumberOfSkippedPoints (all points when fewer than 3 are distinct
//   and finite), exactly these when there are triangles; non-finite points have Status 4;
// - NumberOfPoints = the input points, NumberOfUnusedPoints = the points with Used = 0;
// - cell data Stage in {1, 2, 6, 7, 8}; LocalUniformity has one value per point.
// A violated invariant aborts.
#include "pcsFuzzSurface.h"
#include "vtkGreedySurfaceTriangulation.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  pcsfuzz::Quiet();
  const char* name = "vtkGreedySurfaceTriangulation";
  const pcsfuzz::SurfaceInput input = pcsfuzz::MakeSurfaceInput(data, size);
  const uint8_t* p = input.Parameters;

  vtkNew<vtkGreedySurfaceTriangulation> greedy;
  greedy->SetInputData(input.Data);
  greedy->SetNumberOfNeighbors(p[0] == 0 ? 0 : (p[0] == 255 ? 1000 : 2 + p[0] % 24));
  greedy->SetCrossingTest(p[1] % 4 == 3 ? 7 : p[1] % 4); // 7: clamped to automatic
  greedy->SetAutomaticCorrectFraction(((p[1] >> 2) & 0x03) / 3.0);
  greedy->SetMaximumNormalDeviation(((p[1] >> 4) & 0x0f) * 12.0);
  greedy->SetUniformityNeighbors(1 + (p[2] & 0x07));
  greedy->SetMinimumIslandTriangles((p[2] >> 3) & 0x01 ? 0 : 20);
  greedy->SetBridgeIslands((p[2] & 0x10) == 0);
  greedy->SetFillHoles((p[2] & 0x20) == 0);
  greedy->SetSwapBridgeEdges((p[2] & 0x40) == 0);
  greedy->SetMaximumHolePoints((p[2] & 0x80) ? 0 : 256);
  const int lengths = p[3] & 0x03; // the lengths in units of the mean spacing
  if (lengths == 1)
  {
    greedy->SetMaximumBridgeLength(0.0);
    greedy->SetMaximumHoleDiameter(0.0);
    greedy->SetBoundaryVectorRadius(0.0);
    greedy->SetAuxiliaryPointDistance(0.0);
  }
  else if (lengths == 2)
  {
    greedy->SetMaximumBridgeLength(VTK_DOUBLE_MAX);
    greedy->SetMinimumBridgeSeparation(VTK_DOUBLE_MAX);
    greedy->SetBoundaryVectorRadius(VTK_DOUBLE_MAX);
    greedy->SetAuxiliaryPointDistance(VTK_DOUBLE_MAX);
  }
  else if (lengths == 3)
  {
    greedy->SetMinimumBridgeSeparation(0.0);
    greedy->SetMaximumHoleDiameter(1.0 + (p[3] >> 2));
  }
  greedy->SetInsertLostPoints(((p[0] ^ p[2]) & 0x01) == 0);
  greedy->SetCapOpenEnds(((p[1] ^ p[2]) & 0x02) == 0);
  greedy->SetStatusNeutralAngle((p[3] >> 2) * 90.0 / 63.0);
  greedy->SetUniformityAngle((p[3] >> 2) * 95.0 / 63.0);
  greedy->Update();
  vtkPolyData* out = greedy->GetOutput();
  pcsfuzz::CheckSurface(name, input, out, true);

  const vtkIdType n = input.N;
  if (n == 0)
  {
    return 0;
  }
  vtkDataArray* used = pcsfuzz::PointArray(name, out, "Used");
  vtkDataArray* status = pcsfuzz::PointArray(name, out, "Status");
  pcsfuzz::PointArray(name, out, "LocalUniformity");
  vtkIdType unused = 0, notTriangulated = 0, nonFinite = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double s = status->GetTuple1(i);
    const bool u = used->GetTuple1(i) != 0;
    unused += u ? 0 : 1;
    nonFinite += pcsfuzz::Finite(&input.XYZ[3 * i]) ? 0 : 1;
    notTriangulated += s == 4 ? 1 : 0;
    if (s < 0 || s > 4 || ((s == 2 || s == 4) && u) || (s == 3 && !u))
    {
      pcsfuzz::Fail(name, "Status inconsistent with Used");
    }
    if (!pcsfuzz::Finite(&input.XYZ[3 * i]) && s != 4)
    {
      pcsfuzz::Fail(name, "a non-finite point without Status 4");
    }
  }
  if (pcsfuzz::Field(name, out, "NumberOfPoints") != n ||
    pcsfuzz::Field(name, out, "NumberOfUnusedPoints") != unused ||
    pcsfuzz::Field(name, out, "NumberOfDuplicatePoints") +
        pcsfuzz::Field(name, out, "NumberOfSkippedPoints") >
      notTriangulated ||
    (out->GetNumberOfPolys() > 0 &&
      pcsfuzz::Field(name, out, "NumberOfDuplicatePoints") +
          pcsfuzz::Field(name, out, "NumberOfSkippedPoints") +
          pcsfuzz::Field(name, out, "NumberOfOutliers") !=
        notTriangulated) ||
    pcsfuzz::Field(name, out, "NumberOfSkippedPoints") < nonFinite)
  {
    pcsfuzz::Fail(name, "point counts inconsistent");
  }
  vtkDataArray* stage = pcsfuzz::CellArray(name, out, "Stage");
  for (vtkIdType t = 0; t < out->GetNumberOfPolys(); ++t)
  {
    const double s = stage->GetTuple1(t);
    if (s != 1 && s != 2 && s != 6 && s != 7 && s != 8)
    {
      pcsfuzz::Fail(name, "cell data Stage outside {1, 2, 6, 7, 8}");
    }
  }
  return 0;
}
