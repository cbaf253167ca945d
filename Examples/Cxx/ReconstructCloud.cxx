// C++ example: a VTK pipeline with the PointCloudSurface filters. Reads a point cloud (any file
// VTK's XML readers take: .vtp, .vtu; or x y z lines in a .xyz/.txt file), builds its exact
// Delaunay hull with vtkIncrementalDelaunay3D, measures it with vtkReconstructionQuality and
// writes the mesh to a .vtp file.
//
//   ReconstructCloud <cloud.(vtp|vtu|xyz|txt)> <mesh.vtp>
//   ReconstructCloud --sphere <mesh.vtp>      (a generated cloud: 2,000 points on a sphere)
#include "vtkIncrementalDelaunay3D.h"
#include "vtkReconstructionQuality.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLGenericDataObjectReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace
{
vtkSmartPointer<vtkPointSet> ReadCloud(const std::string& path)
{
  const std::string extension = path.substr(path.find_last_of('.') + 1);
  if (extension == "xyz" || extension == "txt")
  {
    std::ifstream in(path);
    if (!in)
    {
      return nullptr;
    }
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    std::string line;
    while (std::getline(in, line))
    {
      std::istringstream fields(line);
      double p[3];
      if (fields >> p[0] >> p[1] >> p[2])
      {
        points->InsertNextPoint(p);
      }
    }
    auto cloud = vtkSmartPointer<vtkPolyData>::New();
    cloud->SetPoints(points);
    return cloud;
  }
  vtkNew<vtkXMLGenericDataObjectReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return vtkPointSet::SafeDownCast(reader->GetOutputDataObject(0));
}

vtkSmartPointer<vtkPointSet> SphereCloud(int n)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  vtkNew<vtkPoints> points;
  for (int i = 0; i < n; ++i)
  {
    // Uniform on the sphere: z uniform in [-1, 1], longitude uniform.
    const double z = 2.0 * random->GetNextValue() - 1.0;
    const double phi = 2.0 * vtkMath::Pi() * random->GetNextValue();
    const double r = std::sqrt(1.0 - z * z);
    points->InsertNextPoint(r * std::cos(phi), r * std::sin(phi), z);
  }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  return cloud;
}

double Field(vtkDataObject* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? array->GetTuple1(0) : -1.0;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cerr << "usage: ReconstructCloud <cloud.(vtp|vtu|xyz|txt)> <mesh.vtp>\n"
                 "       ReconstructCloud --sphere <mesh.vtp>"
              << std::endl;
    return EXIT_FAILURE;
  }
  const std::string input = argv[1];
  vtkSmartPointer<vtkPointSet> cloud = input == "--sphere" ? SphereCloud(2000) : ReadCloud(input);
  if (!cloud || cloud->GetNumberOfPoints() == 0)
  {
    std::cerr << "cannot read a point cloud from " << input << std::endl;
    return EXIT_FAILURE;
  }

  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  delaunay->SetInputData(cloud);
  delaunay->GenerateTetrahedraOff();

  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputConnection(delaunay->GetOutputPort());
  quality->Update();

  vtkPolyData* mesh = quality->GetOutput();
  std::cout << cloud->GetNumberOfPoints() << " points -> " << mesh->GetNumberOfPolys()
            << " triangles; genus " << Field(mesh, "Genus") << ", boundary edges "
            << Field(mesh, "NumberOfBoundaryEdges") << ", coverage " << Field(mesh, "Coverage")
            << std::endl;

  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(argv[2]);
  return writer->Write() == 1 ? EXIT_SUCCESS : EXIT_FAILURE;
}
