// The triangles of a filter's output as point id triples, for the reconstruction benchmarks
// (pcsBench*.cxx) that write them as OFF or compare them with a peer's.
#ifndef pcsBenchTriangles_h
#define pcsBenchTriangles_h

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <vector>

namespace pcsbench
{
// Appends the polygons of `output` (triangles: the first three ids of each) to `triangles`.
inline void AppendTriangles(vtkPolyData* output, std::vector<std::array<long, 3>>& triangles)
{
  auto iter = vtk::TakeSmartPointer(output->GetPolys()->NewIterator());
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    iter->GetCurrentCell(npts, pts);
    triangles.push_back(
      { static_cast<long>(pts[0]), static_cast<long>(pts[1]), static_cast<long>(pts[2]) });
  }
}
} // namespace pcsbench

#endif
