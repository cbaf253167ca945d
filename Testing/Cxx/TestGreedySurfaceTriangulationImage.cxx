// Image regression of vtkGreedySurfaceTriangulation on the damaged sphere of issue 7: 4000 random
// points of the unit sphere, two caps of 20 degrees removed (around +x and (-0.6, 0.8, 0)), two
// caps thinned tenfold (around (0, -0.6, 0.8) and -z). Left: the step 2 result (BridgeIslands and
// FillHoles off): the well-sampled regions, open, with the lost points in red. Right: the
// repaired mesh, the triangles coloured by the step that made them (Stage: step 1 sand, hole
// filling blue, step 7 swaps green; the fill of the removed cap in view is refined and faired by
// FairHoleFills). The repaired mesh must be closed, manifold, genus 0 and use every point, the
// step 2 result manifold, before anything is rendered.
#include "vtkGreedySurfaceTriangulation.h"
#include "vtkReconstructionQuality.h"

#include "pcsTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkMath.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>

namespace
{
std::vector<double> DamagedSphere(int n, unsigned seed, double capDegrees)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double directions[4][3] = { { 1, 0, 0 }, { -0.6, 0.8, 0 }, { 0, -0.6, 0.8 }, { 0, 0, -1 } };
  const double cosCap = std::cos(vtkMath::RadiansFromDegrees(capDegrees));
  std::vector<double> xyz;
  for (int i = 0; i < n; ++i)
  {
    double p[3] = { gauss(rng), gauss(rng), gauss(rng) };
    const double length = vtkMath::Norm(p);
    const double draw = u(rng);
    if (!(length > 0.0))
    {
      continue;
    }
    vtkMath::MultiplyScalar(p, 1.0 / length);
    bool keep = true;
    for (int d = 0; d < 4; ++d)
    {
      if (vtkMath::Dot(p, directions[d]) > cosCap)
      {
        keep = d >= 2 && draw < 0.1; // removed (d = 0, 1) or one point in ten kept (d = 2, 3)
      }
    }
    if (keep)
    {
      xyz.insert(xyz.end(), p, p + 3);
    }
  }
  return xyz;
}

double Field(vtkPolyData* data, const char* name)
{
  return data->GetFieldData()->GetArray(name)->GetTuple1(0);
}

bool Check(vtkGreedySurfaceTriangulation* greedy, bool closed, const char* what)
{
  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputConnection(greedy->GetOutputPort());
  quality->Update();
  vtkPolyData* q = quality->GetOutput();
  PCS_CHECK(Field(q, "NumberOfNonManifoldEdges") == 0 &&
              Field(q, "NumberOfNonManifoldVertices") == 0 &&
              Field(q, "OrientationConsistency") == 1.0,
            what << ": not an oriented manifold");
  if (closed)
  {
    PCS_CHECK(Field(q, "NumberOfBoundaryEdges") == 0 && Field(q, "Genus") == 0 &&
                greedy->GetNumberOfUnusedPoints() == 0,
              what << ": boundary edges " << Field(q, "NumberOfBoundaryEdges") << ", genus "
                   << Field(q, "Genus") << ", unused points " << greedy->GetNumberOfUnusedPoints());
  }
  else
  {
    PCS_CHECK(Field(q, "NumberOfBoundaryEdges") > 0 && greedy->GetNumberOfLostPoints() > 0,
              what << ": expected holes and lost points");
  }
  return true;
}

vtkSmartPointer<vtkActor> MeshActor(vtkPolyData* mesh, bool byStage)
{
  vtkNew<vtkPolyData> colored;
  colored->ShallowCopy(mesh);
  if (byStage)
  {
    vtkDataArray* stage = mesh->GetCellData()->GetArray("Stage");
    vtkNew<vtkUnsignedCharArray> colors;
    colors->SetName("StageColors");
    colors->SetNumberOfComponents(3);
    for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
    {
      const int s = static_cast<int>(stage->GetTuple1(c));
      const unsigned char sand[3] = { 217, 199, 158 }, blue[3] = { 70, 130, 220 },
                          green[3] = { 60, 170, 80 };
      colors->InsertNextTypedTuple(s == 1 ? sand : (s == 6 ? blue : green));
    }
    colored->GetCellData()->SetScalars(colors);
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(colored);
  normals->SplittingOff();
  normals->ConsistencyOff(); // the mesh is consistently oriented already
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(normals->GetOutputPort());
  if (byStage)
  {
    mapper->SetScalarModeToUseCellData();
    mapper->SetColorModeToDirectScalars();
  }
  else
  {
    mapper->ScalarVisibilityOff();
  }
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.78, 0.62);
  actor->GetProperty()->EdgeVisibilityOn();
  actor->GetProperty()->SetEdgeColor(0.45, 0.38, 0.25);
  actor->GetProperty()->BackfaceCullingOn(); // holes show the background, not the far side
  return actor;
}

// The points of the given Status, as vertices.
vtkSmartPointer<vtkActor> PointsActor(vtkPolyData* mesh, int status)
{
  vtkDataArray* statusArray = mesh->GetPointData()->GetArray("Status");
  vtkNew<vtkCellArray> vertices;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    if (statusArray->GetTuple1(i) == status)
    {
      vertices->InsertNextCell(1, &i);
    }
  }
  vtkNew<vtkPolyData> points;
  points->SetPoints(mesh->GetPoints());
  points->SetVerts(vertices);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(points);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.1, 0.1);
  actor->GetProperty()->SetPointSize(5);
  return actor;
}
} // namespace

int TestGreedySurfaceTriangulationImage(int argc, char* argv[])
{
  const auto cloud = pcstest::MakeCloud(DamagedSphere(4000, 7, 20.0));
  vtkNew<vtkGreedySurfaceTriangulation> step2;
  step2->SetInputData(cloud);
  step2->BridgeIslandsOff();
  step2->FillHolesOff();
  step2->Update();
  vtkNew<vtkGreedySurfaceTriangulation> repaired;
  repaired->SetInputData(cloud);
  repaired->Update();
  if (!Check(step2, false, "step 2 result") || !Check(repaired, true, "repaired"))
  {
    return EXIT_FAILURE;
  }

  vtkNew<vtkRenderer> left, right;
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  left->AddActor(MeshActor(step2->GetOutput(), false));
  left->AddActor(PointsActor(step2->GetOutput(), vtkGreedySurfaceTriangulation::LOST));
  right->AddActor(MeshActor(repaired->GetOutput(), true));
  left->SetBackground(1, 1, 1);
  right->SetBackground(0.92, 0.93, 0.96);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(720, 360);
  window->SetMultiSamples(0);
  window->AddRenderer(left);
  window->AddRenderer(right);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);

  // Both views look at the removed cap around +x and the thinned cap around (0, -0.6, 0.8).
  for (vtkRenderer* renderer : { left.Get(), right.Get() })
  {
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0, 0, 0);
    camera->SetPosition(3.0, -2.2, 2.0);
    camera->SetViewUp(0, 0, 1);
    renderer->ResetCamera();
    camera->Zoom(1.3);
  }
  window->Render();

  const int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
