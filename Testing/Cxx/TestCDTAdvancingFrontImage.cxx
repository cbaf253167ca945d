// Image regression of vtkCDTAdvancingFront, deterministic geometry only. Left: the paper's
// cylinder (12 circles x 36 points, radius 1.223, stacked 0.2 apart, radial normals), its hole
// triangles (cell data HoleTriangle: the two rims) in orange, the others in blue, with edges.
// Right: a torus (radii 1 and 0.4) sampled by 2500 random points with normals, with edges.
#include "vtkCDTAdvancingFront.h"

#include "pcsTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkLookupTable.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

#include <cmath>
#include <cstdlib>

namespace
{
vtkSmartPointer<vtkPolyData> WithNormals(
  const std::vector<double>& xyz, const std::vector<double>& normals)
{
  auto cloud = pcstest::MakeCloud(xyz);
  vtkNew<vtkDoubleArray> array;
  array->SetName("Normals");
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(static_cast<vtkIdType>(normals.size() / 3));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    array->SetTuple(i, &normals[3 * i]);
  }
  cloud->GetPointData()->SetNormals(array);
  return cloud;
}
} // namespace

int TestCDTAdvancingFrontImage(int argc, char* argv[])
{
  const double pi = 3.14159265358979323846;
  std::vector<double> xyz, normals;
  for (int k = 0; k < 12; ++k)
  {
    for (int j = 0; j < 36; ++j)
    {
      const double a = 2.0 * pi * j / 36;
      xyz.insert(xyz.end(), { 1.223 * std::cos(a), 1.223 * std::sin(a), 0.2 * k });
      normals.insert(normals.end(), { std::cos(a), std::sin(a), 0.0 });
    }
  }
  vtkNew<vtkCDTAdvancingFront> cylinder;
  cylinder->SetInputData(WithNormals(xyz, normals));
  cylinder->Update();

  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  xyz.clear();
  normals.clear();
  while (xyz.size() < 3 * 2500)
  {
    const double a = 2 * pi * u(rng), b = 2 * pi * u(rng);
    if (u(rng) > (1.0 + 0.4 * std::cos(b)) / 1.4)
    {
      continue;
    }
    xyz.insert(xyz.end(),
      { (1.0 + 0.4 * std::cos(b)) * std::cos(a), (1.0 + 0.4 * std::cos(b)) * std::sin(a),
        0.4 * std::sin(b) });
    normals.insert(
      normals.end(), { std::cos(b) * std::cos(a), std::cos(b) * std::sin(a), std::sin(b) });
  }
  vtkNew<vtkCDTAdvancingFront> torus;
  torus->SetInputData(WithNormals(xyz, normals));
  torus->Update();
  if (cylinder->GetNumberOfTriangles() != 792 || torus->GetNumberOfTriangles() != 5000)
  {
    std::cerr << "unexpected triangle counts " << cylinder->GetNumberOfTriangles() << ", "
              << torus->GetNumberOfTriangles() << std::endl;
    return EXIT_FAILURE;
  }

  vtkNew<vtkLookupTable> holeColors;
  holeColors->SetNumberOfTableValues(2);
  holeColors->SetTableValue(0, 0.45, 0.6, 0.85);
  holeColors->SetTableValue(1, 0.95, 0.55, 0.2);
  holeColors->Build();
  vtkNew<vtkPolyDataMapper> cylinderMapper;
  cylinderMapper->SetInputConnection(cylinder->GetOutputPort());
  cylinderMapper->SetScalarModeToUseCellFieldData();
  cylinderMapper->SetColorModeToMapScalars(); // HoleTriangle is unsigned char: not colours
  cylinderMapper->SelectColorArray("HoleTriangle");
  cylinderMapper->SetLookupTable(holeColors);
  cylinderMapper->SetScalarRange(0, 1);
  vtkNew<vtkActor> cylinderActor;
  cylinderActor->SetMapper(cylinderMapper);
  cylinderActor->GetProperty()->EdgeVisibilityOn();
  cylinderActor->GetProperty()->SetEdgeColor(0.1, 0.1, 0.2);

  vtkNew<vtkPolyDataMapper> torusMapper;
  torusMapper->SetInputConnection(torus->GetOutputPort());
  torusMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> torusActor;
  torusActor->SetMapper(torusMapper);
  torusActor->GetProperty()->SetColor(0.95, 0.75, 0.45);
  torusActor->GetProperty()->EdgeVisibilityOn();
  torusActor->GetProperty()->SetEdgeColor(0.35, 0.2, 0.05);

  vtkNew<vtkRenderer> left, right;
  left->SetViewport(0.0, 0.0, 0.45, 1.0);
  right->SetViewport(0.45, 0.0, 1.0, 1.0);
  left->AddActor(cylinderActor);
  right->AddActor(torusActor);
  left->SetBackground(1, 1, 1);
  right->SetBackground(0.92, 0.92, 0.95);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(660, 320);
  window->SetMultiSamples(0);
  window->AddRenderer(left);
  window->AddRenderer(right);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);

  vtkCamera* camera = left->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 1.1);
  camera->SetPosition(3.5, -5.0, 4.0);
  camera->SetViewUp(0, 0, 1);
  left->ResetCamera();
  camera->Zoom(1.3);
  camera = right->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(1.5, -3.0, 2.5);
  camera->SetViewUp(0, 0, 1);
  right->ResetCamera();
  camera->Zoom(1.5);
  window->Render();

  const int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
