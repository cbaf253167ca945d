// placeholder implementation (being written): compiles, produces empty outputs.
#include "vtkIncrementalDelaunay3D.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

vtkStandardNewMacro(vtkIncrementalDelaunay3D);

vtkIncrementalDelaunay3D::vtkIncrementalDelaunay3D()
{
  this->SetNumberOfOutputPorts(3);
}
vtkIncrementalDelaunay3D::~vtkIncrementalDelaunay3D() = default;

vtkPolyData* vtkIncrementalDelaunay3D::GetSurfaceOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(0));
}
vtkUnstructuredGrid* vtkIncrementalDelaunay3D::GetTetrahedraOutput()
{
  return vtkUnstructuredGrid::SafeDownCast(this->GetOutputDataObject(1));
}
vtkPolyData* vtkIncrementalDelaunay3D::GetVoronoiOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(2));
}

int vtkIncrementalDelaunay3D::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkIncrementalDelaunay3D::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

int vtkIncrementalDelaunay3D::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector*)
{
  return 1;
}

void vtkIncrementalDelaunay3D::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
