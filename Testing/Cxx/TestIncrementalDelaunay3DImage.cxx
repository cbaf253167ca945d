// Image regression: left, the 2.5D triangulation of a jittered-grid terrain coloured by height;
// right, the convex hull (output 0) of a random cloud in 3D with its tetrahedra shrunk (output 1).
#include "vtkIncrementalDelaunay3D.h"

#include "pcsTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataSetMapper.h"
#include "vtkElevationFilter.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkShrinkFilter.h"

#include <cstdlib>

int TestIncrementalDelaunay3DImage(int argc, char* argv[])
{
  // Terrain: 40 x 40 jittered grid, z = smooth hills.
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<double> terrain;
  for (int i = 0; i < 40; ++i)
  {
    for (int j = 0; j < 40; ++j)
    {
      const double x = (i + jitter(rng)) / 39.0, y = (j + jitter(rng)) / 39.0;
      terrain.insert(terrain.end(),
        { x, y, 0.15 * std::sin(6.0 * x) * std::cos(4.0 * y) + 0.1 * x * y });
    }
  }
  vtkNew<vtkIncrementalDelaunay3D> surface;
  surface->SetInputData(pcstest::MakeCloud(terrain));
  surface->SetDimension(2);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(surface->GetOutputPort(0));
  elevation->SetLowPoint(0, 0, -0.2);
  elevation->SetHighPoint(0, 0, 0.25);
  vtkNew<vtkPolyDataMapper> terrainMapper;
  terrainMapper->SetInputConnection(elevation->GetOutputPort());
  vtkNew<vtkActor> terrainActor;
  terrainActor->SetMapper(terrainMapper);
  terrainActor->GetProperty()->EdgeVisibilityOn();
  terrainActor->GetProperty()->SetEdgeColor(0.1, 0.1, 0.1);

  // 3D: 60 random points, tetrahedra shrunk so each one is visible.
  vtkNew<vtkIncrementalDelaunay3D> tetrahedra;
  tetrahedra->SetInputData(pcstest::MakeCloud(pcstest::UniformCube(60, 5)));
  vtkNew<vtkShrinkFilter> shrink;
  shrink->SetInputConnection(tetrahedra->GetOutputPort(1));
  shrink->SetShrinkFactor(0.7);
  vtkNew<vtkDataSetMapper> tetraMapper;
  tetraMapper->SetInputConnection(shrink->GetOutputPort());
  tetraMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> tetraActor;
  tetraActor->SetMapper(tetraMapper);
  tetraActor->GetProperty()->SetColor(0.9, 0.6, 0.3);
  vtkNew<vtkPolyDataMapper> hullMapper;
  hullMapper->SetInputConnection(tetrahedra->GetOutputPort(0));
  vtkNew<vtkActor> hullActor;
  hullActor->SetMapper(hullMapper);
  hullActor->GetProperty()->SetRepresentationToWireframe();
  hullActor->GetProperty()->SetColor(0.2, 0.3, 0.8);

  vtkNew<vtkRenderer> left, right;
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  left->AddActor(terrainActor);
  right->AddActor(tetraActor);
  right->AddActor(hullActor);
  left->SetBackground(1, 1, 1);
  right->SetBackground(1, 1, 1);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(600, 300);
  window->AddRenderer(left);
  window->AddRenderer(right);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  for (vtkRenderer* renderer : { left.Get(), right.Get() })
  {
    renderer->ResetCamera();
    renderer->GetActiveCamera()->Elevation(-50);
    renderer->GetActiveCamera()->Azimuth(25);
    renderer->ResetCamera();
  }
  window->Render();

  const int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
