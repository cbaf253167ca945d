// The filters of the module, as a table for the tests that run every filter (robustness, abort).
// A surface filter joins the table as soon as its header exists (__has_include): the tests
// pick it up without further edits; add its specifics (parameter limits...) in the tests.
#ifndef pcsTestFilters_h
#define pcsTestFilters_h

#include "vtkIncrementalDelaunay3D.h"
#include "vtkReconstructionQuality.h"
#if __has_include("vtkPerimeterPeelSurface.h")
#include "vtkPerimeterPeelSurface.h"
#define PCS_HAVE_PEEL
#endif
#if __has_include("vtkLocalOptimumGrowth.h")
#include "vtkLocalOptimumGrowth.h"
#define PCS_HAVE_LOCAL_OPTIMUM
#endif
#if __has_include("vtkCDTAdvancingFront.h")
#include "vtkCDTAdvancingFront.h"
#define PCS_HAVE_CDT
#endif
#if __has_include("vtkGreedySurfaceTriangulation.h")
#include "vtkGreedySurfaceTriangulation.h"
#define PCS_HAVE_GREEDY
#endif

#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"

#include <functional>
#include <string>
#include <vector>

namespace pcstest
{
struct FilterInfo
{
  std::string Name;
  std::function<vtkSmartPointer<vtkPolyDataAlgorithm>()> Make;
  bool ConsumesMesh;     // input: a triangle mesh (vtkReconstructionQuality), else a cloud
  bool PromisesManifold; // output: no non-manifold edge or vertex
  bool Reconstructs;     // makes a surface from a cloud
};

template <typename T>
vtkSmartPointer<vtkPolyDataAlgorithm> NewFilter()
{
  return vtkSmartPointer<T>::New();
}

inline std::vector<FilterInfo> AllFilters()
{
  std::vector<FilterInfo> filters;
  // The convex hull (port 0) is a closed 2-manifold.
  filters.push_back(
    { "vtkIncrementalDelaunay3D", NewFilter<vtkIncrementalDelaunay3D>, false, true, true });
  filters.push_back(
    { "vtkReconstructionQuality", NewFilter<vtkReconstructionQuality>, true, false, false });
#ifdef PCS_HAVE_PEEL
  filters.push_back(
    { "vtkPerimeterPeelSurface", NewFilter<vtkPerimeterPeelSurface>, false, true, true });
#endif
#ifdef PCS_HAVE_LOCAL_OPTIMUM
  filters.push_back(
    { "vtkLocalOptimumGrowth", NewFilter<vtkLocalOptimumGrowth>, false, true, true });
#endif
#ifdef PCS_HAVE_CDT
  filters.push_back(
    { "vtkCDTAdvancingFront", NewFilter<vtkCDTAdvancingFront>, false, true, true });
#endif
#ifdef PCS_HAVE_GREEDY
  // An oriented 2-manifold with boundary (its class documentation).
  filters.push_back({ "vtkGreedySurfaceTriangulation",
    NewFilter<vtkGreedySurfaceTriangulation>, false, true, true });
#endif
  return filters;
}
} // namespace pcstest

#endif
