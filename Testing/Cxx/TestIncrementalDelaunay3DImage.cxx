// Image regression, deterministic geometry only. Left: the 2.5D triangulation (Dimension 2,
// output 0) of 3000 points of a smooth two-hill terrain sampled on a jittered 60 x 50 grid,
// coloured by elevation, with its edges. Right: the convex hull (Dimension 3, output 0) of 150
// random points in a ball, with its edges, and the input points.
#include "vtkIncrementalDelaunay3D.h"

#include "pcsTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkElevationFilter.h"
#include "vtkLookupTable.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkVertexGlyphFilter.h"

#include <cstdlib>

namespace
{
double Hills(double x, double y)
{
  const double a = (x - 0.35) * (x - 0.35) + (y - 0.4) * (y - 0.4);
  const double b = (x - 0.72) * (x - 0.72) + (y - 0.68) * (y - 0.68);
  return 0.3 * std::exp(-a / 0.04) + 0.18 * std::exp(-b / 0.015) + 0.03 * std::sin(6.0 * x);
}
} // namespace

int TestIncrementalDelaunay3DImage(int argc, char* argv[])
{
  // Terrain: 60 x 50 jittered grid on [0, 1] x [0, 0.8].
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  std::vector<double> terrain;
  for (int i = 0; i < 60; ++i)
  {
    for (int j = 0; j < 50; ++j)
    {
      const double x = (i + jitter(rng)) / 59.0, y = 0.8 * (j + jitter(rng)) / 49.0;
      terrain.insert(terrain.end(), { x, y, Hills(x, y) });
    }
  }
  vtkNew<vtkIncrementalDelaunay3D> surface;
  surface->SetInputData(pcstest::MakeCloud(terrain));
  surface->SetDimension(2);
  surface->GenerateTetrahedraOff();
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(surface->GetOutputPort(0));
  elevation->SetLowPoint(0, 0, -0.03);
  elevation->SetHighPoint(0, 0, 0.33);
  vtkNew<vtkLookupTable> colors;
  colors->SetHueRange(0.66, 0.0);
  colors->Build();
  vtkNew<vtkPolyDataMapper> terrainMapper;
  terrainMapper->SetInputConnection(elevation->GetOutputPort());
  terrainMapper->SetLookupTable(colors);
  terrainMapper->SetScalarRange(0.0, 1.0);
  vtkNew<vtkActor> terrainActor;
  terrainActor->SetMapper(terrainMapper);
  terrainActor->GetProperty()->EdgeVisibilityOn();
  terrainActor->GetProperty()->SetEdgeColor(0.15, 0.15, 0.15);

  // 3D: the hull of 150 random points in the unit ball.
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> ball;
  while (ball.size() < 3 * 150)
  {
    const double p[3] = { u(rng), u(rng), u(rng) };
    if (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] <= 1.0)
    {
      ball.insert(ball.end(), p, p + 3);
    }
  }
  auto cloud = pcstest::MakeCloud(ball);
  vtkNew<vtkIncrementalDelaunay3D> hull;
  hull->SetInputData(cloud);
  hull->GenerateTetrahedraOff();
  vtkNew<vtkPolyDataMapper> hullMapper;
  hullMapper->SetInputConnection(hull->GetOutputPort(0));
  hullMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> hullActor;
  hullActor->SetMapper(hullMapper);
  hullActor->GetProperty()->SetColor(0.95, 0.7, 0.4);
  hullActor->GetProperty()->EdgeVisibilityOn();
  hullActor->GetProperty()->SetEdgeColor(0.3, 0.15, 0.05);
  vtkNew<vtkVertexGlyphFilter> vertices;
  vertices->SetInputData(cloud);
  vtkNew<vtkPolyDataMapper> pointMapper;
  pointMapper->SetInputConnection(vertices->GetOutputPort());
  vtkNew<vtkActor> pointActor;
  pointActor->SetMapper(pointMapper);
  pointActor->GetProperty()->SetColor(0.1, 0.2, 0.7);
  pointActor->GetProperty()->SetPointSize(4);

  vtkNew<vtkRenderer> left, right;
  left->SetViewport(0.0, 0.0, 0.55, 1.0);
  right->SetViewport(0.55, 0.0, 1.0, 1.0);
  left->AddActor(terrainActor);
  right->AddActor(hullActor);
  right->AddActor(pointActor);
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
  camera->SetFocalPoint(0.5, 0.4, 0.08);
  camera->SetPosition(0.5, -0.9, 1.0);
  camera->SetViewUp(0, 0, 1);
  left->ResetCamera();
  camera->Zoom(1.2);
  camera = right->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(2.0, -3.0, 2.0);
  camera->SetViewUp(0, 0, 1);
  right->ResetCamera();
  camera->Zoom(1.4);
  window->Render();

  const int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
