// Parallel runs (pvbatch / pvserver under MPI): the reconstruction filters need the whole cloud
// at once, so each one gathers its input on process 0 first; then the input check every filter
// shares (private helper, not wrapped).
#ifndef pcsGatherInput_h
#define pcsGatherInput_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

class vtkDataObject;
class vtkPoints;
class vtkPointSet;

namespace pcs
{
/// When VTK's global multi-process controller runs more than one process, collects the points,
/// point data and (for a vtkPolyData) the cells of `input` from every process on process 0, in
/// process order, and returns that on process 0 and nullptr on the others; the filter then
/// computes on process 0 only and leaves its outputs empty elsewhere, so the result is the same
/// surface as a serial run over the same points in the same order. With one process it returns
/// `input` itself (no copy). Pieces without points are skipped (their arrays may differ).
/// A mesh split in pieces (by a source or a reader) repeats its piece-border vertices in each
/// piece: when two or more pieces have lines, polygons or strips, a vertex of such a cell with
/// exactly the coordinates of such a vertex of an earlier piece is kept once (its first
/// occurrence; cells renumbered), so the gathered mesh has the serial mesh's topology. Points no
/// cell uses (cloud points) and coincident points within one piece are never merged.
/// Every process must call it (it communicates).
vtkSmartPointer<vtkPointSet> GatherInputOnFirstProcess(vtkPointSet* input);

/// Point data arrays of `input` whose number of tuples is not its number of points (a corrupt
/// data set: passed through, they would give the output arrays of the wrong length, and copying
/// their tuples reads out of bounds): `input` is replaced by a shallow copy without them (the
/// caller's data set is not modified). Returns the filter's warning naming them, empty when
/// there are none. `input` may be null.
std::string DropMismatchedPointArrays(vtkSmartPointer<vtkPointSet>& input);

/// The filter's error naming the parameters that are NaN (empty when none). VTK's
/// vtkSetClampMacro clamps infinities to the range but lets NaN through (every comparison is
/// false); the filters refuse a NaN parameter with this error and compute nothing (the points
/// pass through, unused).
std::string NaNParametersError(std::initializer_list<std::pair<const char*, double>> parameters);

/// The coordinates of every point of `points` as doubles (packed x, y, z; one copy when they are
/// a vtkDoubleArray) in `xyz`, and the ids of the points whose three coordinates are finite, in
/// increasing order, in `finite`: the points a filter meshes; it skips the others, with a
/// warning. Returns the number of points skipped. `points` may be null (no points).
vtkIdType ReadFiniteCoordinates(vtkPoints* points,
  std::vector<double>& xyz,
  std::vector<int32_t>& finite);
}

#endif
