#include "pcsGatherInput.h"

#include "vtkAppendPolyData.h"
#include "vtkMultiProcessController.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"

#include <vector>

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
  int inputs = 0;
  for (const auto& received : pieces)
  {
    auto* polyData = vtkPolyData::SafeDownCast(received);
    if (polyData && polyData->GetNumberOfPoints() > 0)
    {
      append->AddInputData(polyData);
      ++inputs;
    }
  }
  auto gathered = vtkSmartPointer<vtkPolyData>::New();
  if (inputs > 0)
  {
    append->Update();
    gathered->ShallowCopy(append->GetOutput());
  }
  return gathered;
}
} // namespace pcs
