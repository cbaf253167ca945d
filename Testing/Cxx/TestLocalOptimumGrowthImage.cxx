// Image regression of vtkLocalOptimumGrowth. Left: the mesh grown on 1500 random points of the
// unit sphere, with its edges. Right: the mesh grown on the 37,706 vertices of the Stanford bunny
// of CGAL's demo data (Debian package libcgal-demo, data/meshes/bunny00.off, extracted at
// configure time; the path comes in the environment variable PCS_CGAL_BUNNY). Both must be
// closed, manifold, genus 0 and use every point before anything is rendered.
#include "vtkLocalOptimumGrowth.h"
#include "vtkReconstructionQuality.h"

#include "pcsTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace
{
// The vertices of an OFF file (the faces are ignored: the test meshes the points).
bool ReadOffVertices(const std::string& path, std::vector<double>& xyz)
{
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line) || line.compare(0, 3, "OFF") != 0)
  {
    return false;
  }
  long vertices = -1, faces, edges;
  while (vertices < 0 && std::getline(in, line))
  {
    std::istringstream header(line);
    if (line.empty() || line[0] == '#' || !(header >> vertices >> faces >> edges))
    {
      vertices = -1;
    }
  }
  for (long i = 0; i < vertices && std::getline(in, line);)
  {
    std::istringstream s(line);
    double p[3];
    if (s >> p[0] >> p[1] >> p[2])
    {
      xyz.insert(xyz.end(), p, p + 3);
      ++i;
    }
  }
  return vertices > 0 && static_cast<long>(xyz.size()) == 3 * vertices;
}

bool ClosedGenusZero(vtkLocalOptimumGrowth* growth, const char* what)
{
  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputConnection(growth->GetOutputPort());
  quality->Update();
  vtkPolyData* q = quality->GetOutput();
  auto get = [q](const char* name) { return q->GetFieldData()->GetArray(name)->GetTuple1(0); };
  PCS_CHECK(get("NumberOfBoundaryEdges") == 0 && get("NumberOfNonManifoldEdges") == 0 &&
      get("NumberOfNonManifoldVertices") == 0 && get("Genus") == 0 &&
      get("OrientationConsistency") == 1.0,
    what << ": boundary edges " << get("NumberOfBoundaryEdges") << ", non-manifold "
         << get("NumberOfNonManifoldEdges") << "/" << get("NumberOfNonManifoldVertices")
         << ", genus " << get("Genus"));
  PCS_CHECK(growth->GetNumberOfUnusedPoints() == 0,
    what << ": " << growth->GetNumberOfUnusedPoints() << " unused points");
  PCS_CHECK(get("NumberOfTriangles") == 2 * get("NumberOfUsedPoints") - 4, what << ": 2V - 4");
  return true;
}

vtkSmartPointer<vtkActor> MeshActor(vtkAlgorithmOutput* mesh, bool edges)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(mesh);
  normals->SplittingOff();
  normals->ConsistencyOff(); // the mesh is consistently oriented already
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(normals->GetOutputPort());
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.78, 0.62);
  if (edges)
  {
    actor->GetProperty()->EdgeVisibilityOn();
    actor->GetProperty()->SetEdgeColor(0.25, 0.2, 0.1);
  }
  return actor;
}
} // namespace

int TestLocalOptimumGrowthImage(int argc, char* argv[])
{
  const char* bunnyPath = std::getenv("PCS_CGAL_BUNNY");
  std::vector<double> bunny;
  if (!bunnyPath || !ReadOffVertices(bunnyPath, bunny))
  {
    std::cerr << "CGAL's bunny00.off is not available (apt-get install libcgal-demo, then "
                 "reconfigure): test skipped."
              << std::endl;
    return 125;
  }

  // Sphere: 1500 random points.
  std::mt19937_64 rng(2013);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<double> sphere;
  while (sphere.size() < 3 * 1500)
  {
    double p[3] = { gauss(rng), gauss(rng), gauss(rng) };
    const double length = vtkMath::Norm(p);
    if (length > 0.0)
    {
      sphere.insert(sphere.end(), { p[0] / length, p[1] / length, p[2] / length });
    }
  }
  vtkNew<vtkLocalOptimumGrowth> sphereGrowth;
  sphereGrowth->SetInputData(pcstest::MakeCloud(sphere));
  sphereGrowth->Update();
  vtkNew<vtkLocalOptimumGrowth> bunnyGrowth;
  bunnyGrowth->SetInputData(pcstest::MakeCloud(bunny));
  bunnyGrowth->Update();
  if (!ClosedGenusZero(sphereGrowth, "sphere") || !ClosedGenusZero(bunnyGrowth, "bunny"))
  {
    return EXIT_FAILURE;
  }

  vtkNew<vtkRenderer> left, right;
  left->SetViewport(0.0, 0.0, 0.45, 1.0);
  right->SetViewport(0.45, 0.0, 1.0, 1.0);
  left->AddActor(MeshActor(sphereGrowth->GetOutputPort(), true));
  right->AddActor(MeshActor(bunnyGrowth->GetOutputPort(), false));
  left->SetBackground(1, 1, 1);
  right->SetBackground(0.92, 0.93, 0.96);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(720, 360);
  window->SetMultiSamples(0);
  window->AddRenderer(left);
  window->AddRenderer(right);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);

  vtkCamera* camera = left->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(2.0, -3.0, 1.5);
  camera->SetViewUp(0, 0, 1);
  left->ResetCamera();
  camera->Zoom(1.3);
  camera = right->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(0.0, 0.0, 1.0); // the bunny looks along +z in its own frame
  camera->SetViewUp(0, 1, 0);
  right->ResetCamera();
  camera->Zoom(1.35);
  window->Render();

  const int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
