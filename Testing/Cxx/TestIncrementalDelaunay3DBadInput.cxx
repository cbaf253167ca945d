// Bad input gives a warning (or an error) and a valid output, never a crash: empty input, too
// few points, coplanar / collinear / identical points, NaN and Inf coordinates, inputs with
// cells, a non point-set input. Every output keeps all the input points and their point data.
// Abort at the first progress event stops the filter early with a valid, cell-less output;
// progress is reported in [0, 1] in increasing order.
#include "vtkIncrementalDelaunay3D.h"

#include "pcsTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <limits>
#include <set>

namespace
{
using MessageCounter = pcstest::MessageCounter;

// Updates the filter on `input`; counts the warnings and errors of the filter and its executive.
MessageCounter Run(vtkDataObject* input, int dimension, vtkIncrementalDelaunay3D* delaunay)
{
  MessageCounter counter;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(MessageCounter::Callback);
  callback->SetClientData(&counter);
  vtkObject* emitters[2] = { delaunay, delaunay->GetExecutive() };
  for (vtkObject* emitter : emitters)
  {
    emitter->AddObserver(vtkCommand::WarningEvent, callback);
    emitter->AddObserver(vtkCommand::ErrorEvent, callback);
  }
  delaunay->SetInputData(input);
  delaunay->SetDimension(dimension);
  delaunay->Update();
  for (vtkObject* emitter : emitters)
  {
    emitter->RemoveObservers(vtkCommand::WarningEvent);
    emitter->RemoveObservers(vtkCommand::ErrorEvent);
  }
  return counter;
}

// Sorted cell tuples of the tetrahedra (or triangles) output, with ids mapped through `map`.
std::set<std::vector<vtkIdType>> CellSet(
  vtkIncrementalDelaunay3D* delaunay, const std::vector<vtkIdType>* map = nullptr)
{
  std::set<std::vector<vtkIdType>> set;
  vtkUnstructuredGrid* grid = delaunay->GetTetrahedraOutput();
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    grid->GetCellPoints(c, npts, pts);
    std::vector<vtkIdType> t(pts, pts + npts);
    if (map)
    {
      for (vtkIdType& id : t)
      {
        id = (*map)[id];
      }
    }
    std::sort(t.begin(), t.end());
    set.insert(t);
  }
  return set;
}

// What every output must satisfy: all points passed through with RepresentativeId, field data
// counts equal to the getters.
bool CheckValidOutput(vtkIncrementalDelaunay3D* delaunay, vtkIdType n, const char* label)
{
  vtkPolyData* surface = delaunay->GetSurfaceOutput();
  PCS_CHECK(surface->GetNumberOfPoints() == n, label << ": points are passed through");
  PCS_CHECK(delaunay->GetNumberOfInputPoints() == n, label << ": NumberOfInputPoints");
  PCS_CHECK(delaunay->GetNumberOfCells() == delaunay->GetTetrahedraOutput()->GetNumberOfCells(),
    label << ": NumberOfCells");
  vtkDataArray* representative = surface->GetPointData()->GetArray("RepresentativeId");
  PCS_CHECK(n == 0 || representative, label << ": RepresentativeId");
  if (n > 0)
  {
    PCS_CHECK(representative->GetNumberOfTuples() == n, label << ": RepresentativeId size");
    PCS_CHECK(pcstest::FieldCount(surface, "NumberOfInputPoints") == n, label << ": field data");
    PCS_CHECK(pcstest::FieldCount(surface, "NumberOfDuplicatePoints") ==
        delaunay->GetNumberOfDuplicatePoints(),
      label << ": field data duplicates");
    PCS_CHECK(pcstest::FieldCount(surface, "NumberOfSkippedPoints") ==
        delaunay->GetNumberOfSkippedPoints(),
      label << ": field data skipped");
  }
  for (vtkIdType c = 0; c < delaunay->GetTetrahedraOutput()->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    delaunay->GetTetrahedraOutput()->GetCellPoints(c, npts, pts);
    for (vtkIdType j = 0; j < npts; ++j)
    {
      PCS_CHECK(pts[j] >= 0 && pts[j] < n, label << ": cell point id out of range");
    }
  }
  return true;
}

bool ExpectNoCells(const std::vector<double>& xyz, int dimension, const char* label)
{
  const vtkIdType n = static_cast<vtkIdType>(xyz.size() / 3);
  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  delaunay->GenerateVoronoiOn();
  const MessageCounter messages = Run(pcstest::MakeCloud(xyz), dimension, delaunay);
  PCS_CHECK(messages.Warnings + messages.Errors > 0, label << ": no warning");
  PCS_CHECK(delaunay->GetTetrahedraOutput()->GetNumberOfCells() == 0, label << ": cells");
  PCS_CHECK(delaunay->GetSurfaceOutput()->GetNumberOfPolys() == 0, label << ": surface cells");
  PCS_CHECK(delaunay->GetVoronoiOutput()->GetNumberOfCells() == 0, label << ": Voronoi cells");
  return CheckValidOutput(delaunay, n, label);
}

// n identical points: n - 1 duplicates of one representative, whatever the dimension.
bool CheckIdentical(int dimension)
{
  const char* label = dimension == 3 ? "identical 3D" : "identical 2D";
  std::vector<double> xyz;
  for (int i = 0; i < 10; ++i)
  {
    xyz.insert(xyz.end(), { 0.5, 0.5, 0.5 });
  }
  if (!ExpectNoCells(xyz, dimension, label))
  {
    return false;
  }
  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  Run(pcstest::MakeCloud(xyz), dimension, delaunay);
  PCS_CHECK(delaunay->GetNumberOfDuplicatePoints() == 9,
    label << ": " << delaunay->GetNumberOfDuplicatePoints() << " duplicates, expected 9");
  vtkDataArray* representative =
    delaunay->GetSurfaceOutput()->GetPointData()->GetArray("RepresentativeId");
  const double r = representative->GetTuple1(0);
  for (vtkIdType i = 0; i < 10; ++i)
  {
    PCS_CHECK(representative->GetTuple1(i) == r, label << ": one representative for all");
  }
  return true;
}

// Non-finite points interleaved with valid ones: skipped and counted (RepresentativeId -1); the
// triangulation is the one of the finite points alone.
bool CheckNonFinite()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> valid = pcstest::UniformCube(1000, 1);
  std::vector<double> xyz;
  std::vector<vtkIdType> finiteId; // input id -> id among the finite points, or -1
  const double bad[4][3] = { { nan, 0.5, 0.5 }, { 0.5, inf, 0.5 }, { 0.5, 0.5, -inf },
    { nan, nan, nan } };
  int numberOfBad = 0;
  for (int i = 0; i < 1000; ++i)
  {
    if (i % 97 == 13)
    {
      xyz.insert(xyz.end(), bad[numberOfBad % 4], bad[numberOfBad % 4] + 3);
      finiteId.push_back(-1);
      ++numberOfBad;
    }
    xyz.insert(xyz.end(), &valid[3 * i], &valid[3 * i] + 3);
    finiteId.push_back(i);
  }
  const vtkIdType n = static_cast<vtkIdType>(finiteId.size());
  for (int dimension = 2; dimension <= 3; ++dimension)
  {
    const char* label = dimension == 3 ? "non-finite among valid 3D" : "non-finite among valid 2D";
    vtkNew<vtkIncrementalDelaunay3D> delaunay;
    const MessageCounter messages = Run(pcstest::MakeCloud(xyz), dimension, delaunay);
    PCS_CHECK(messages.Warnings > 0, label << ": warning");
    PCS_CHECK(delaunay->GetNumberOfSkippedPoints() == numberOfBad,
      label << ": skipped " << delaunay->GetNumberOfSkippedPoints() << " expected "
            << numberOfBad);
    if (!CheckValidOutput(delaunay, n, label))
    {
      return false;
    }
    vtkDataArray* representative =
      delaunay->GetSurfaceOutput()->GetPointData()->GetArray("RepresentativeId");
    for (vtkIdType i = 0; i < n; ++i)
    {
      PCS_CHECK(representative->GetTuple1(i) == (finiteId[i] < 0 ? -1 : i),
        label << ": RepresentativeId of " << i);
    }
    vtkNew<vtkIncrementalDelaunay3D> reference;
    Run(pcstest::MakeCloud(valid), dimension, reference);
    PCS_CHECK(reference->GetNumberOfCells() > 0, label << ": reference cells");
    PCS_CHECK(CellSet(delaunay, &finiteId) == CellSet(reference),
      label << ": the cells differ from those of the finite points alone");
  }
  return true;
}

// Cells of the input are ignored: a mesh or an unstructured grid gives the triangulation of its
// points; point data is passed through.
bool CheckInputsWithCells()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  sphere->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  sphere->Update();
  vtkPolyData* mesh = sphere->GetOutput();
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  for (vtkIdType i = 0; i < n; ++i)
  {
    height->InsertNextValue(mesh->GetPoint(i)[2]);
  }
  mesh->GetPointData()->AddArray(height);

  std::vector<double> xyz(3 * n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    mesh->GetPoint(i, &xyz[3 * i]);
  }
  vtkNew<vtkIncrementalDelaunay3D> cloud;
  Run(pcstest::MakeCloud(xyz), 3, cloud);
  vtkNew<vtkIncrementalDelaunay3D> fromMesh;
  Run(mesh, 3, fromMesh);
  PCS_CHECK(cloud->GetNumberOfCells() > 0, "sphere cloud cells");
  PCS_CHECK(CellSet(fromMesh) == CellSet(cloud), "the cells of a mesh input are not ignored");
  if (!CheckValidOutput(fromMesh, n, "mesh input"))
  {
    return false;
  }
  vtkDataArray* passed = fromMesh->GetSurfaceOutput()->GetPointData()->GetArray("Height");
  PCS_CHECK(passed && passed->GetNumberOfTuples() == n, "point data is passed through");
  for (vtkIdType i = 0; i < n; ++i)
  {
    PCS_CHECK(passed->GetTuple1(i) == mesh->GetPoint(i)[2], "point data value " << i);
  }
  // Every point of a sphere is a hull vertex.
  std::set<vtkIdType> used;
  for (const auto& t : pcstest::CellTuples<3>(fromMesh->GetSurfaceOutput()))
  {
    used.insert(t.begin(), t.end());
  }
  PCS_CHECK(static_cast<vtkIdType>(used.size()) == n, "sphere points on the hull");

  // An unstructured grid (the filter's own tetrahedra) as input.
  vtkNew<vtkUnstructuredGrid> grid;
  grid->DeepCopy(fromMesh->GetTetrahedraOutput());
  vtkNew<vtkIncrementalDelaunay3D> fromGrid;
  Run(grid, 3, fromGrid);
  PCS_CHECK(CellSet(fromGrid) == CellSet(cloud), "unstructured grid input");
  return CheckValidOutput(fromGrid, n, "unstructured grid input");
}

// vtkImageData is not a vtkPointSet: the pipeline refuses it with an error, without a crash.
bool CheckImageInput()
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 4);
  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  const MessageCounter messages = Run(image, 3, delaunay);
  PCS_CHECK(messages.Errors > 0, "image data input: no error reported");
  PCS_CHECK(delaunay->GetTetrahedraOutput()->GetNumberOfCells() == 0, "image data: cells");
  // The filter still works on valid input afterwards.
  Run(pcstest::MakeCloud(pcstest::UniformCube(100, 4)), 3, delaunay);
  PCS_CHECK(delaunay->GetNumberOfCells() > 0, "a valid input after an invalid one");
  return CheckValidOutput(delaunay, 100, "valid input after image data");
}

// Counts are reset between executions.
bool CheckReexecution()
{
  std::vector<double> xyz = pcstest::UniformCube(200, 6);
  std::vector<double> withDuplicates = xyz;
  withDuplicates.insert(withDuplicates.end(), xyz.begin(), xyz.begin() + 30); // 10 duplicates
  withDuplicates.insert(withDuplicates.end(), { std::numeric_limits<double>::quiet_NaN(), 0, 0 });
  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  Run(pcstest::MakeCloud(withDuplicates), 3, delaunay);
  PCS_CHECK(delaunay->GetNumberOfDuplicatePoints() == 10, "10 duplicates");
  PCS_CHECK(delaunay->GetNumberOfSkippedPoints() == 1, "1 skipped");
  Run(pcstest::MakeCloud(xyz), 3, delaunay);
  PCS_CHECK(delaunay->GetNumberOfDuplicatePoints() == 0, "duplicates reset");
  PCS_CHECK(delaunay->GetNumberOfSkippedPoints() == 0, "skipped reset");
  return CheckValidOutput(delaunay, 200, "re-execution");
}

// Abort at the first progress event.
bool CheckAbort()
{
  const int n = 200000;
  auto cloud = pcstest::MakeCloud(pcstest::UniformCube(n, 2));
  using Clock = std::chrono::steady_clock;

  vtkNew<vtkIncrementalDelaunay3D> full;
  full->SetInputData(cloud);
  auto start = Clock::now();
  full->Update();
  const double fullSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  PCS_CHECK(full->GetNumberOfCells() > 0, "full run");

  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  struct Progress
  {
    vtkIncrementalDelaunay3D* Filter;
    std::vector<double> Values;
  } progress{ delaunay, {} };
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(&progress);
  callback->SetCallback([](vtkObject*, unsigned long, void* client, void* call) {
    auto* p = static_cast<Progress*>(client);
    p->Values.push_back(*static_cast<double*>(call));
    p->Filter->SetAbortExecute(1);
  });
  delaunay->AddObserver(vtkCommand::ProgressEvent, callback);
  delaunay->GenerateVoronoiOn();
  delaunay->SetInputData(cloud);
  start = Clock::now();
  delaunay->Update();
  const double abortedSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::cout << "abort: " << progress.Values.size() << " progress events, aborted run "
            << abortedSeconds << " s, full run " << fullSeconds << " s" << std::endl;
  PCS_CHECK(!progress.Values.empty(), "progress events");
  for (size_t i = 0; i < progress.Values.size(); ++i)
  {
    PCS_CHECK(progress.Values[i] >= 0.0 && progress.Values[i] <= 1.0, "progress range");
    PCS_CHECK(i == 0 || progress.Values[i] >= progress.Values[i - 1], "progress increases");
  }
  PCS_CHECK(abortedSeconds < 0.5 * fullSeconds,
    "the aborted run took " << abortedSeconds << " s, the full run " << fullSeconds << " s");
  PCS_CHECK(delaunay->GetTetrahedraOutput()->GetNumberOfCells() == 0, "aborted: no cells");
  PCS_CHECK(delaunay->GetSurfaceOutput()->GetNumberOfPolys() == 0, "aborted: no hull");
  PCS_CHECK(delaunay->GetVoronoiOutput()->GetNumberOfCells() == 0, "aborted: no Voronoi");
  PCS_CHECK(delaunay->GetSurfaceOutput()->GetNumberOfPoints() == n, "aborted: points");
  PCS_CHECK(delaunay->GetNumberOfInputPoints() == n, "aborted: input count");

  // A full run is observed with increasing progress that ends at 1.
  progress.Values.clear();
  delaunay->RemoveAllObservers();
  vtkNew<vtkCallbackCommand> recorder;
  recorder->SetClientData(&progress);
  recorder->SetCallback([](vtkObject*, unsigned long, void* client, void* call) {
    static_cast<Progress*>(client)->Values.push_back(*static_cast<double*>(call));
  });
  delaunay->AddObserver(vtkCommand::ProgressEvent, recorder);
  delaunay->SetAbortExecute(0);
  delaunay->GenerateVoronoiOff();
  delaunay->Modified();
  delaunay->Update();
  PCS_CHECK(delaunay->GetNumberOfCells() == full->GetNumberOfCells(), "run after an abort");
  PCS_CHECK(progress.Values.size() >= 3, "several progress events in a full run");
  for (size_t i = 0; i < progress.Values.size(); ++i)
  {
    PCS_CHECK(progress.Values[i] >= 0.0 && progress.Values[i] <= 1.0, "progress range");
    PCS_CHECK(i == 0 || progress.Values[i] >= progress.Values[i - 1], "progress increases");
  }
  PCS_CHECK(progress.Values.back() == 1.0, "progress ends at 1");
  return true;
}
} // namespace

int TestIncrementalDelaunay3DBadInput(int, char*[])
{
  bool ok = true;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  ok = ExpectNoCells({}, 3, "empty") && ok;
  ok = ExpectNoCells({}, 2, "empty 2D") && ok;
  ok = ExpectNoCells({ 0, 0, 0 }, 3, "one point") && ok;
  ok = ExpectNoCells({ 0, 0, 0 }, 2, "one point 2D") && ok;
  ok = ExpectNoCells({ 0, 0, 0, 1, 0, 0, 0, 1, 0 }, 3, "three points") && ok;
  ok = ExpectNoCells({ 0, 0, 0, 1, 0, 0 }, 2, "two points 2D") && ok;
  std::vector<double> coplanar, collinear, vertical;
  for (int i = 0; i < 10; ++i)
  {
    coplanar.insert(coplanar.end(), { double(i % 4), double(i / 4), 2.0 });
    collinear.insert(collinear.end(), { double(i), 2.0 * i, -1.0 * i });
    vertical.insert(vertical.end(), { double(i % 2), 0.0, double(i) }); // a plane seen edge-on
  }
  ok = ExpectNoCells(coplanar, 3, "coplanar") && ok;
  ok = ExpectNoCells(collinear, 3, "collinear") && ok;
  ok = ExpectNoCells(collinear, 2, "collinear 2D") && ok;
  ok = ExpectNoCells(vertical, 2, "projection on a line 2D") && ok;
  ok = CheckIdentical(3) && ok;
  ok = CheckIdentical(2) && ok;
  ok = ExpectNoCells({ nan, 0, 0, inf, 1, 1, 0, -inf, 0, nan, nan, nan, 0, 0, 1 }, 3,
         "non-finite") && ok;
  { // Coplanar points are a valid 2.5D input: 10 points of a 4 x 3 grid (2 missing).
    vtkNew<vtkIncrementalDelaunay3D> delaunay;
    Run(pcstest::MakeCloud(coplanar), 2, delaunay);
    // n = 10 points, h = 8 on the hull boundary: 2n - 2 - h = 10 triangles.
    if (delaunay->GetNumberOfCells() != 10)
    {
      std::cerr << "coplanar 2D: " << delaunay->GetNumberOfCells() << " triangles, expected 10"
                << std::endl;
      ok = false;
    }
    ok = CheckValidOutput(delaunay, 10, "coplanar 2D") && ok;
  }
  ok = CheckNonFinite() && ok;
  ok = CheckInputsWithCells() && ok;
  ok = CheckImageInput() && ok;
  ok = CheckReexecution() && ok;
  ok = CheckAbort() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
