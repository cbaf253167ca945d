// Helpers of the vtkReconstructionQuality tests (not part of the library): triangle meshes given
// by coordinates and id triples, and the filter run with its warnings and errors counted.
#ifndef pcsQualityTestUtilities_h
#define pcsQualityTestUtilities_h

#include "vtkReconstructionQuality.h"

#include "pcsTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"

#include <array>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <limits>
#include <utility>
#include <vector>

namespace pcsqtest
{
using Tri = std::array<vtkIdType, 3>;

struct Mesh
{
  std::vector<double> Points; // x, y, z
  std::vector<Tri> Triangles;

  vtkIdType AddPoint(double x, double y, double z)
  {
    for (double c : { x, y, z })
    {
      this->Points.push_back(c);
    }
    return static_cast<vtkIdType>(this->Points.size() / 3) - 1;
  }
  vtkIdType NumberOfPoints() const { return static_cast<vtkIdType>(this->Points.size() / 3); }
  // Appends `other` with its point ids shifted.
  void Append(const Mesh& other)
  {
    const vtkIdType shift = this->NumberOfPoints();
    this->Points.insert(this->Points.end(), other.Points.begin(), other.Points.end());
    for (Tri t : other.Triangles)
    {
      this->Triangles.push_back({ { t[0] + shift, t[1] + shift, t[2] + shift } });
    }
  }
  vtkSmartPointer<vtkPolyData> PolyData() const
  {
    auto data = pcstest::MakeCloud(this->Points);
    vtkNew<vtkCellArray> polys;
    for (const Tri& t : this->Triangles)
    {
      polys->InsertNextCell(3, t.data());
    }
    data->SetPolys(polys);
    return data;
  }
};

using Counter = pcstest::MessageCounter;

// Runs the filter; counts its warnings and errors (and its executive's).
inline vtkSmartPointer<vtkPolyData> Run(vtkPolyData* mesh,
  vtkDataObject* reference = nullptr,
  int samples = 3,
  Counter* counter = nullptr,
  double standingAngle = 60.0)
{
  vtkNew<vtkReconstructionQuality> quality;
  Counter local;
  Counter* c = counter ? counter : &local;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(Counter::Callback);
  callback->SetClientData(c);
  for (vtkObject* emitter :
    { static_cast<vtkObject*>(quality.Get()), static_cast<vtkObject*>(quality->GetExecutive()) })
  {
    emitter->AddObserver(vtkCommand::WarningEvent, callback);
    emitter->AddObserver(vtkCommand::ErrorEvent, callback);
  }
  quality->SetInputData(mesh);
  quality->SetReferenceData(reference);
  quality->SetSamplesPerTriangle(samples);
  quality->SetStandingAngle(standingAngle);
  quality->Update();
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->ShallowCopy(quality->GetOutput());
  return output;
}

inline double Field(vtkDataObject* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? array->GetTuple1(0) : std::numeric_limits<double>::quiet_NaN();
}

using NamedTest = std::pair<const char*, std::function<bool()>>;

// Runs every test (all of them, whatever fails), prints each result; EXIT_SUCCESS when all pass.
inline int RunTests(const std::vector<NamedTest>& tests)
{
  int failures = 0;
  for (const NamedTest& test : tests)
  {
    const bool ok = test.second();
    std::cout << (ok ? "passed: " : "FAILED: ") << test.first << std::endl;
    failures += ok ? 0 : 1;
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
} // namespace pcsqtest

#endif
