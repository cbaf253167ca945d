// Fuzz target of vtkPerimeterPeelSurface: a small, often degenerate cloud from the bytes
// (pcsFuzzSurface.h), the parameters over their ranges (limits included), then the invariants
// of pcsFuzzSurface.h and the class's own:
// - with ManifoldOutput (the default) no non-manifold edge or vertex, consistent orientation,
//   and a closed surface (the boundary of a solid of tetrahedra has no boundary edge);
// - NumberOfUsedPoints + NumberOfUnusedPoints = the input points, NumberOfUsedPoints = the
//   points with Used = 1; the tetrahedra removed by peeling are at most the tetrahedra.
// A violated invariant aborts.
#include "pcsFuzzSurface.h"
#include "vtkPerimeterPeelSurface.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  pcsfuzz::Quiet();
  const char* name = "vtkPerimeterPeelSurface";
  const pcsfuzz::SurfaceInput input = pcsfuzz::MakeSurfaceInput(data, size);
  const uint8_t* p = input.Parameters;

  vtkNew<vtkPerimeterPeelSurface> peel;
  peel->SetInputData(input.Data);
  // ThresholdFactor over [0.01, 1000] (log scale; the ends reached), the measure, a fixed
  // threshold sometimes, the convergence tolerance and the iteration limit, ManifoldOutput.
  peel->SetThresholdFactor(p[0] == 0 ? 0.0 : (p[0] == 255 ? 1e9 : std::pow(10.0, p[0] / 51.0 - 2)));
  peel->SetFacetMeasure(p[1] % 4 == 3 ? -1 : p[1] % 4); // -1: clamped to PERIMETER
  if (p[1] & 0x04)
  {
    peel->SetThreshold(p[1] & 0x08 ? VTK_DOUBLE_MAX : std::ldexp(1.0, (p[1] >> 4) - 8));
  }
  peel->SetConvergenceTolerance(p[2] / 250.0);
  peel->SetMaximumIterations((p[3] & 0x7f) == 0 ? 0 : (p[3] & 0x7f));
  const bool manifold = (p[3] & 0x80) == 0;
  peel->SetManifoldOutput(manifold);
  peel->Update();
  vtkPolyData* out = peel->GetOutput();
  vtkSmartPointer<vtkPolyData> measures = pcsfuzz::CheckSurface(name, input, out, manifold);

  const vtkIdType triangles = out->GetNumberOfPolys();
  if (input.N == 0)
  {
    return 0;
  }
  const double used = pcsfuzz::Field(name, out, "NumberOfUsedPoints");
  const double unused = pcsfuzz::Field(name, out, "NumberOfUnusedPoints");
  if (used + unused != input.N || used != pcsfuzz::Field(name, measures, "NumberOfUsedPoints"))
  {
    pcsfuzz::Fail(name, "NumberOfUsedPoints / NumberOfUnusedPoints inconsistent");
  }
  const double tetrahedra = pcsfuzz::Field(name, out, "NumberOfTetrahedra");
  const double removed = pcsfuzz::Field(name, out, "NumberOfRemovedTetrahedra");
  const double groups = pcsfuzz::Field(name, out, "NumberOfGroupRemovals");
  if (removed < 0 || groups < 0 || groups > removed || removed > tetrahedra)
  {
    pcsfuzz::Fail(name, "tetrahedra counts inconsistent");
  }
  if (manifold && triangles > 0 && pcsfuzz::Field(name, measures, "NumberOfBoundaryEdges") != 0)
  {
    pcsfuzz::Fail(name, "the surface of the solid has a boundary edge");
  }
  return 0;
}
