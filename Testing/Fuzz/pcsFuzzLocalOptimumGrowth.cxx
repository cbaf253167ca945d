// Fuzz target of vtkLocalOptimumGrowth: a small, often degenerate cloud from the bytes
// (pcsFuzzSurface.h), the parameters over their ranges (limits included), then the invariants
// of pcsFuzzSurface.h (the class promises an oriented 2-manifold with boundary) and its own:
// - RepresentativeId: -1 exactly for the points with a non-finite coordinate; otherwise a point
//   that represents itself, with the same coordinates or, for a point of a pile of
//   near-coincident points (pcs::FindPiles), within pcs::PileRatio x the diagonal of the finite
//   points' bounding box (a pile's extent is under that); a used point represents itself;
// - NumberOfSkippedPoints = the points with RepresentativeId -1, NumberOfDuplicatePoints = the
//   finite points represented by another, and used + NumberOfUnusedPoints + duplicates +
//   skipped = NumberOfInputPoints = the input points;
// - NumberOfBoundaryEdges = the edges of a single triangle (vtkReconstructionQuality).
// A violated invariant aborts.
#include "pcsFuzzSurface.h"
#include "pcsPiles.h"
#include "vtkLocalOptimumGrowth.h"

#include <algorithm>
#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  pcsfuzz::Quiet();
  const char* name = "vtkLocalOptimumGrowth";
  const pcsfuzz::SurfaceInput input = pcsfuzz::MakeSurfaceInput(data, size);
  const uint8_t* p = input.Parameters;

  vtkNew<vtkLocalOptimumGrowth> growth;
  growth->SetInputData(input.Data);
  // K in [4, 200] (0 and 255 beyond the limits), the angles, the edge ratios, the hole size.
  growth->SetNumberOfNeighbors(p[0] == 0 ? 0 : (p[0] == 255 ? 1000 : 3 + p[0] % 40));
  growth->SetMaximumNormalAngle(p[1] * 180.0 / 255.0);
  growth->SetMaximumBaseAngle(p[1] & 1 ? 20.0 + (p[1] >> 1) * 160.0 / 127.0 : 120.0);
  growth->SetMinimumEdgeRatio((p[2] & 0x0f) / 14.0);
  growth->SetMaximumEdgeRatio((p[2] >> 4) == 15 ? 1e9 : 0.5 + (p[2] >> 4) / 2.0);
  growth->SetMaximumHoleEdges((p[3] & 0x7f) == 0x7f ? 5000 : (p[3] & 0x7f) - 1);
  growth->SetRelaxConstraints((p[3] & 0x80) == 0);
  growth->Update();
  vtkPolyData* out = growth->GetOutput();
  vtkSmartPointer<vtkPolyData> measures = pcsfuzz::CheckSurface(name, input, out, true);

  const vtkIdType n = input.N;
  if (pcsfuzz::Field(name, out, "NumberOfInputPoints") != n)
  {
    pcsfuzz::Fail(name, "NumberOfInputPoints differs from the input");
  }
  vtkDataArray* used = pcsfuzz::PointArray(name, out, "Used");
  vtkDataArray* representative = pcsfuzz::PointArray(name, out, "RepresentativeId");
  vtkIdType usedCount = 0, skipped = 0, duplicates = 0;
  // The diagonal of the finite points' bounding box.
  double low[3] = { INFINITY, INFINITY, INFINITY }, high[3] = { -INFINITY, -INFINITY, -INFINITY };
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double* x = &input.XYZ[3 * i];
    for (int c = 0; c < 3 && pcsfuzz::Finite(x); ++c)
    {
      low[c] = std::min(low[c], x[c]);
      high[c] = std::max(high[c], x[c]);
    }
  }
  const double diagonal = std::hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const vtkIdType r = static_cast<vtkIdType>(representative->GetTuple1(i));
    const double* x = &input.XYZ[3 * i];
    if (!pcsfuzz::Finite(x))
    {
      if (r != -1)
      {
        pcsfuzz::Fail(name, "a non-finite point has a representative");
      }
      ++skipped;
      continue;
    }
    if (r < 0 || r >= n || static_cast<vtkIdType>(representative->GetTuple1(r)) != r)
    {
      pcsfuzz::Fail(name, "RepresentativeId out of range or not a representative");
    }
    const double* y = &input.XYZ[3 * r];
    if ((x[0] != y[0] || x[1] != y[1] || x[2] != y[2]) &&
      !(std::hypot(x[0] - y[0], x[1] - y[1], x[2] - y[2]) < pcs::PileRatio * diagonal))
    {
      pcsfuzz::Fail(name, "a point represented by a point at other coordinates, not in a pile");
    }
    duplicates += r != i ? 1 : 0;
    if (used->GetTuple1(i) != 0)
    {
      ++usedCount;
      if (r != i)
      {
        pcsfuzz::Fail(name, "a duplicate point is used");
      }
    }
  }
  const double unused = pcsfuzz::Field(name, out, "NumberOfUnusedPoints");
  if (n > 0 &&
    (pcsfuzz::Field(name, out, "NumberOfSkippedPoints") != skipped ||
      pcsfuzz::Field(name, out, "NumberOfDuplicatePoints") != duplicates ||
      usedCount + unused + duplicates + skipped != n))
  {
    pcsfuzz::Fail(name, "point counts inconsistent");
  }
  if (out->GetNumberOfPolys() > 0 &&
    pcsfuzz::Field(name, out, "NumberOfBoundaryEdges") !=
      pcsfuzz::Field(name, measures, "NumberOfBoundaryEdges"))
  {
    pcsfuzz::Fail(name, "NumberOfBoundaryEdges differs from the edges of one triangle");
  }
  return 0;
}
