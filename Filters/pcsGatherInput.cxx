#include "pcsGatherInput.h"

#include "vtkAbstractArray.h"
#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkMultiProcessController.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace
{
// The cells of `cells` with their point ids replaced through `newId`.
vtkSmartPointer<vtkCellArray> Renumber(vtkCellArray* cells, const std::vector<vtkIdType>& newId)
{
  auto renumbered = vtkSmartPointer<vtkCellArray>::New();
  if (!cells || cells->GetNumberOfCells() == 0)
  {
    return renumbered;
  }
  renumbered->AllocateExact(cells->GetNumberOfCells(), cells->GetNumberOfConnectivityIds());
  vtkNew<vtkIdList> ids;
  auto iterator = vtk::TakeSmartPointer(cells->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    iterator->GetCurrentCell(ids);
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
    {
      ids->SetId(i, newId[ids->GetId(i)]);
    }
    renumbered->InsertNextCell(ids);
  }
  return renumbered;
}

// A mesh split in pieces by a source or a reader repeats the vertices on the piece borders in
// each piece. Keeps each such vertex once: a point that is a vertex of a line, polygon or strip
// of its piece and has exactly the coordinates of such a vertex of an earlier piece becomes
// that point. Points that no cell uses (cloud points), and coincident points within one piece,
// are left alone, so a cloud gathered from pieces keeps every point. `pieceEnd[k]` is one past
// the last point of piece k in `mesh`.
void MergePieceSeams(vtkPolyData* mesh, const std::vector<vtkIdType>& pieceEnd)
{
  const vtkIdType numberOfPoints = mesh->GetNumberOfPoints();
  std::vector<char> used(numberOfPoints, 0);
  for (vtkCellArray* cells : { mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips() })
  {
    if (!cells)
    {
      continue;
    }
    vtkNew<vtkIdList> ids;
    auto iterator = vtk::TakeSmartPointer(cells->NewIterator());
    for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
    {
      iterator->GetCurrentCell(ids);
      for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
      {
        used[ids->GetId(i)] = 1;
      }
    }
  }
  // First used occurrence of each exact coordinate triple (finite points only: NaN has no
  // ordering), and the piece it came from.
  std::map<std::array<double, 3>, std::pair<vtkIdType, std::size_t>> first;
  std::vector<vtkIdType> newId(numberOfPoints);
  vtkIdType kept = 0;
  std::size_t piece = 0;
  for (vtkIdType id = 0; id < numberOfPoints; ++id)
  {
    while (piece + 1 < pieceEnd.size() && id >= pieceEnd[piece])
    {
      ++piece;
    }
    std::array<double, 3> x;
    mesh->GetPoint(id, x.data());
    const bool finite = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
    if (used[id] && finite)
    {
      auto found = first.find(x);
      if (found != first.end() && found->second.second < piece)
      {
        newId[id] = newId[found->second.first];
        continue;
      }
      if (found == first.end())
      {
        first.emplace(x, std::make_pair(id, piece));
      }
    }
    newId[id] = kept++;
  }
  if (kept == numberOfPoints)
  {
    return;
  }
  vtkNew<vtkPoints> points;
  points->SetDataType(mesh->GetPoints()->GetDataType());
  points->SetNumberOfPoints(kept);
  vtkNew<vtkPointData> pointData;
  pointData->CopyAllocate(mesh->GetPointData(), kept);
  vtkIdType next = 0;
  for (vtkIdType id = 0; id < numberOfPoints; ++id)
  {
    if (newId[id] == next) // a kept point (merged ones map to an earlier, smaller id)
    {
      points->SetPoint(next, mesh->GetPoint(id));
      pointData->CopyData(mesh->GetPointData(), id, next);
      ++next;
    }
  }
  mesh->SetVerts(Renumber(mesh->GetVerts(), newId));
  mesh->SetLines(Renumber(mesh->GetLines(), newId));
  mesh->SetPolys(Renumber(mesh->GetPolys(), newId));
  mesh->SetStrips(Renumber(mesh->GetStrips(), newId));
  mesh->SetPoints(points);
  mesh->GetPointData()->ShallowCopy(pointData);
}
} // namespace

namespace pcs
{
vtkSmartPointer<vtkPointSet> GatherInputOnFirstProcess(vtkPointSet* input)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() <= 1)
  {
    return input;
  }
  // What travels: a vtkPolyData with the points, the point data and, for polydata input, the
  // cells (vtkReconstructionQuality measures meshes); other point sets send their points only.
  vtkNew<vtkPolyData> piece;
  if (auto* polyData = vtkPolyData::SafeDownCast(input))
  {
    piece->ShallowCopy(polyData);
  }
  else if (input)
  {
    piece->SetPoints(input->GetPoints());
    piece->GetPointData()->ShallowCopy(input->GetPointData());
  }
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->Gather(piece, pieces, 0);
  if (controller->GetLocalProcessId() != 0)
  {
    return nullptr;
  }
  vtkNew<vtkAppendPolyData> append;
  std::vector<vtkIdType> pieceEnd;
  vtkIdType points = 0;
  int piecesWithCells = 0;
  for (const auto& received : pieces)
  {
    auto* polyData = vtkPolyData::SafeDownCast(received);
    if (polyData && polyData->GetNumberOfPoints() > 0)
    {
      append->AddInputData(polyData);
      points += polyData->GetNumberOfPoints();
      pieceEnd.push_back(points);
      piecesWithCells += polyData->GetNumberOfCells() > polyData->GetNumberOfVerts() ? 1 : 0;
    }
  }
  auto gathered = vtkSmartPointer<vtkPolyData>::New();
  if (!pieceEnd.empty())
  {
    append->Update();
    gathered->ShallowCopy(append->GetOutput());
    if (piecesWithCells > 1)
    {
      MergePieceSeams(gathered, pieceEnd);
    }
  }
  return gathered;
}

std::string DropMismatchedPointArrays(vtkSmartPointer<vtkPointSet>& input)
{
  std::string names;
  if (!input)
  {
    return names;
  }
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  vtkPointData* pointData = input->GetPointData();
  std::vector<int> mismatched;
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = pointData->GetAbstractArray(a);
    if (array && array->GetNumberOfTuples() != numberOfPoints)
    {
      mismatched.push_back(a);
      const char* name = array->GetName();
      names += (names.empty() ? "" : ", ") + std::string(name ? name : "(unnamed)");
    }
  }
  if (mismatched.empty())
  {
    return names;
  }
  auto copy = vtk::TakeSmartPointer(input->NewInstance());
  copy->ShallowCopy(input);
  for (auto a = mismatched.rbegin(); a != mismatched.rend(); ++a)
  {
    copy->GetPointData()->RemoveArray(*a);
  }
  input = copy;
  return "Ignored " + std::to_string(mismatched.size()) + " point data array(s) whose number " +
    "of tuples is not the number of points (" + std::to_string(numberOfPoints) + "): " + names +
    ".";
}

std::string NaNParametersError(std::initializer_list<std::pair<const char*, double>> parameters)
{
  std::string names;
  for (const auto& parameter : parameters)
  {
    if (std::isnan(parameter.second))
    {
      names += (names.empty() ? "" : ", ") + std::string(parameter.first);
    }
  }
  return names.empty() ? names : "NaN parameter(s): " + names + ". Nothing is computed.";
}

vtkIdType ReadFiniteCoordinates(vtkPoints* points,
  std::vector<double>& xyz,
  std::vector<int32_t>& finite)
{
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  xyz.resize(3 * static_cast<size_t>(n));
  auto* doubles = points ? vtkDoubleArray::SafeDownCast(points->GetData()) : nullptr;
  if (doubles && doubles->GetNumberOfComponents() == 3)
  {
    std::copy_n(doubles->GetPointer(0), xyz.size(), xyz.data());
  }
  else if (n > 0)
  {
    vtkSMPTools::For(0,
      n,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          points->GetPoint(i, &xyz[3 * static_cast<size_t>(i)]);
        }
      });
  }
  finite.clear();
  finite.reserve(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double* p = &xyz[3 * static_cast<size_t>(i)];
    if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))
    {
      finite.push_back(static_cast<int32_t>(i));
    }
  }
  return n - static_cast<vtkIdType>(finite.size());
}
} // namespace pcs
