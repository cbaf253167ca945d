// Bad input gives a warning and a valid output, never a crash: empty input, too few points,
// coplanar / collinear / identical points, NaN and Inf coordinates. Abort stops the filter with
// a valid output; progress is reported in [0, 1].
#include "vtkIncrementalDelaunay3D.h"

#include "pcsTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"

#include <cstdlib>
#include <limits>

namespace
{
struct WarningCounter
{
  int Warnings = 0;
  static void Callback(vtkObject*, unsigned long, void* data, void*)
  {
    static_cast<WarningCounter*>(data)->Warnings++;
  }
};

// Runs the filter; returns the number of warnings and errors it emitted.
int Run(const std::vector<double>& xyz, int dimension, vtkIncrementalDelaunay3D* delaunay)
{
  WarningCounter counter;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(WarningCounter::Callback);
  callback->SetClientData(&counter);
  delaunay->AddObserver(vtkCommand::WarningEvent, callback);
  delaunay->AddObserver(vtkCommand::ErrorEvent, callback);
  delaunay->SetInputData(pcstest::MakeCloud(xyz));
  delaunay->SetDimension(dimension);
  delaunay->Update();
  delaunay->RemoveAllObservers();
  return counter.Warnings;
}

bool ExpectNoCells(const std::vector<double>& xyz, int dimension, const char* label)
{
  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  const int warnings = Run(xyz, dimension, delaunay);
  PCS_CHECK(warnings > 0, label << ": no warning");
  PCS_CHECK(delaunay->GetTetrahedraOutput()->GetNumberOfCells() == 0, label << ": cells");
  PCS_CHECK(delaunay->GetSurfaceOutput()->GetNumberOfPoints() ==
      static_cast<vtkIdType>(xyz.size() / 3),
    label << ": points are passed through");
  PCS_CHECK(delaunay->GetNumberOfInputPoints() == static_cast<vtkIdType>(xyz.size() / 3),
    label << ": input count");
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
  ok = ExpectNoCells({ 0, 0, 0, 1, 0, 0, 0, 1, 0 }, 3, "three points") && ok;
  ok = ExpectNoCells({ 0, 0, 0, 1, 0, 0 }, 2, "two points 2D") && ok;
  std::vector<double> coplanar, collinear, identical;
  for (int i = 0; i < 10; ++i)
  {
    coplanar.insert(coplanar.end(), { double(i % 4), double(i / 4), 2.0 });
    collinear.insert(collinear.end(), { double(i), 2.0 * i, -1.0 * i });
    identical.insert(identical.end(), { 0.5, 0.5, 0.5 });
  }
  ok = ExpectNoCells(coplanar, 3, "coplanar") && ok;
  ok = ExpectNoCells(collinear, 3, "collinear") && ok;
  ok = ExpectNoCells(collinear, 2, "collinear 2D") && ok;
  ok = ExpectNoCells(identical, 3, "identical") && ok;
  ok = ExpectNoCells({ nan, 0, 0, inf, 1, 1, 0, -inf, 0, nan, nan, nan, 0, 0, 1 }, 3,
         "non-finite") && ok;

  { // Non-finite points among valid ones: skipped, counted, the rest triangulated.
    std::vector<double> xyz = pcstest::UniformCube(1000, 1);
    xyz.insert(xyz.end(), { nan, 0.5, 0.5, 0.5, inf, 0.5, 0.5, 0.5, -inf });
    vtkNew<vtkIncrementalDelaunay3D> delaunay;
    const int warnings = Run(xyz, 3, delaunay);
    PCS_CHECK(warnings > 0, "non-finite among valid: warning");
    PCS_CHECK(delaunay->GetNumberOfSkippedPoints() == 3, "skipped count");
    vtkDataArray* representative =
      delaunay->GetSurfaceOutput()->GetPointData()->GetArray("RepresentativeId");
    for (vtkIdType i = 1000; i < 1003; ++i)
    {
      PCS_CHECK(representative->GetTuple1(i) == -1, "RepresentativeId of a skipped point");
    }
    std::vector<char> used(1003, 0);
    for (const auto& t : pcstest::CellTuples<4>(delaunay->GetTetrahedraOutput()))
    {
      for (vtkIdType id : t)
      {
        used[id] = 1;
      }
    }
    for (int i = 0; i < 1003; ++i)
    {
      PCS_CHECK(used[i] == (i < 1000 ? 1 : 0), "point " << i << " use");
    }
  }

  { // Abort at the first progress event: quick return with a valid, cell-less output.
    std::vector<double> xyz = pcstest::UniformCube(200000, 2);
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
      const double value = *static_cast<double*>(call);
      p->Values.push_back(value);
      if (value > 0.2)
      {
        p->Filter->SetAbortExecute(1);
      }
    });
    delaunay->AddObserver(vtkCommand::ProgressEvent, callback);
    delaunay->SetInputData(pcstest::MakeCloud(xyz));
    delaunay->Update();
    PCS_CHECK(!progress.Values.empty(), "progress events");
    for (size_t i = 0; i < progress.Values.size(); ++i)
    {
      PCS_CHECK(progress.Values[i] >= 0.0 && progress.Values[i] <= 1.0, "progress range");
      PCS_CHECK(i == 0 || progress.Values[i] >= progress.Values[i - 1], "progress increases");
    }
    PCS_CHECK(delaunay->GetTetrahedraOutput()->GetNumberOfCells() == 0, "aborted: no cells");
    PCS_CHECK(delaunay->GetSurfaceOutput()->GetNumberOfPoints() == 200000, "aborted: points");
    std::cout << "abort after " << progress.Values.size() << " progress events, last "
              << progress.Values.back() << std::endl;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
