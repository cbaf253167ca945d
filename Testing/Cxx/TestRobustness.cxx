// Table-driven robustness test (issue 9): every filter of the module against every bad or
// degenerate input of the table. For each (filter, input):
// - Update() returns (no crash; a hang is caught by the ctest timeout, 300 s);
// - a warning or an error is reported where the input is unusable (no input, no points, one or
//   two points, all points identical, collinear points);
// - the output is valid: a vtkPolyData with all the input points (filters pass every point
//   through) and only the points it reports as added (NumberOfAddedPoints), every cell id in range,
//   no cell on a non-finite point, no triangle with a repeated vertex, and for the filters that
//   promise a manifold surface no non-manifold edge or vertex and no zero-area triangle (exactly
//   collinear vertices) (vtkReconstructionQuality);
// - point data arrays of every common type pass through unchanged; one of the wrong length (a
//   corrupt input) is dropped with a warning.
// Pairs of inputs that describe the same surface must give the same result: a 10^6 offset on
// every coordinate, float instead of double coordinates, a vtkUnstructuredGrid of vertices
// (double and float points) instead of a vtkPolyData (triangle count within 0.5 %, same
// closedness and genus, point data passed through); for vtkReconstructionQuality the same holds
// for the hulls of those clouds, and a reference cloud of int or short points, or with 20,000
// extra points with a NaN coordinate, gives the measures of the same (finite) cloud in doubles.
// Every parameter of every filter runs at its clamp limits (set beyond them, so the clamp is
// exercised too) on a regular input; OutlierFactor at 0, -1, huge and the default on a cloud with
// far outliers (excluded only at the default).
//
// The filters come from pcsTestFilters.h (a new filter of the module joins automatically); their
// parameter limits are listed in ExtremesOf below. Every double parameter set to NaN (which VTK's
// clamp macros let through) gives an error and no triangles (DoubleParametersOf).
#include "pcsTestFilters.h"
#include "pcsTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCharArray.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkLongLongArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkShortArray.h"
#include "vtkSignedCharArray.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedIntArray.h"
#include "vtkUnsignedShortArray.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace
{
using Algorithm = vtkSmartPointer<vtkPolyDataAlgorithm>;

//------------------------------------------------------------------------------------------------
// The filters.
vtkSmartPointer<vtkPolyData> HullOf(vtkPolyData* cloud);
vtkSmartPointer<vtkPolyData> Identity(vtkPolyData* cloud);

struct FilterEntry
{
  pcstest::FilterInfo Info;
  // Settings at the clamp limits of the filter's parameters (applied one at a time).
  std::vector<std::pair<std::string, std::function<void(vtkPolyDataAlgorithm*)>>> Extremes;
  // Turns a cloud into this filter's input.
  vtkSmartPointer<vtkPolyData> Prepare(vtkPolyData* cloud) const;
};

vtkSmartPointer<vtkPolyData> Identity(vtkPolyData* cloud)
{
  return cloud;
}

// The convex hull of the cloud (a triangle mesh over all its points): the input of
// vtkReconstructionQuality.
vtkSmartPointer<vtkPolyData> HullOf(vtkPolyData* cloud)
{
  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  delaunay->SetInputData(cloud);
  delaunay->GenerateTetrahedraOff();
  // Unusable clouds (no points...) give an empty hull; their warnings are not under test here.
  vtkNew<vtkCallbackCommand> silence;
  delaunay->AddObserver(vtkCommand::WarningEvent, silence);
  delaunay->AddObserver(vtkCommand::ErrorEvent, silence);
  delaunay->Update();
  auto hull = vtkSmartPointer<vtkPolyData>::New();
  hull->ShallowCopy(delaunay->GetOutput());
  return hull;
}

vtkSmartPointer<vtkPolyData> FilterEntry::Prepare(vtkPolyData* cloud) const
{
  return this->Info.ConsumesMesh ? HullOf(cloud) : Identity(cloud);
}

// The filters that read the input's point normals (the active normals): the inputs with
// zero-length or NaN normals must give them a warning, and every point must still be used (a
// missing normal is estimated).
bool TakesNormals(const std::string& name)
{
  return name == "vtkCDTAdvancingFront";
}

// Parameter limits of each filter, by class name.
std::vector<std::pair<std::string, std::function<void(vtkPolyDataAlgorithm*)>>> ExtremesOf(
  const std::string& name)
{
  if (name == "vtkIncrementalDelaunay3D")
  {
    return {
      { "Tolerance = max", [](vtkPolyDataAlgorithm* a)
        { static_cast<vtkIncrementalDelaunay3D*>(a)->SetTolerance(VTK_DOUBLE_MAX); } },
      { "Tolerance = -1 (clamped to 0)", [](vtkPolyDataAlgorithm* a)
        { static_cast<vtkIncrementalDelaunay3D*>(a)->SetTolerance(-1.0); } },
      { "Dimension = 2, best-fit plane", [](vtkPolyDataAlgorithm* a)
        {
          auto* d = static_cast<vtkIncrementalDelaunay3D*>(a);
          d->SetDimension(-7);       // clamped to 2
          d->SetProjectionPlane(99); // clamped to the best-fit plane
        } },
      { "Voronoi on", [](vtkPolyDataAlgorithm* a)
        { static_cast<vtkIncrementalDelaunay3D*>(a)->GenerateVoronoiOn(); } },
    };
  }
#ifdef PCS_HAVE_CDT
  if (name == "vtkCDTAdvancingFront")
  {
    auto cdt = [](vtkPolyDataAlgorithm* a) { return static_cast<vtkCDTAdvancingFront*>(a); };
    return {
      { "NeighborhoodRadius = max", [cdt](vtkPolyDataAlgorithm* a)
        { cdt(a)->SetNeighborhoodRadius(VTK_DOUBLE_MAX); } },
      { "NeighborhoodRadius = -1 (clamped to 0: automatic)", [cdt](vtkPolyDataAlgorithm* a)
        { cdt(a)->SetNeighborhoodRadius(-1.0); } },
      { "NeighborhoodRadiusFactor = 1", [cdt](vtkPolyDataAlgorithm* a)
        { cdt(a)->SetNeighborhoodRadiusFactor(0.0); } },
      { "NeighborhoodRadiusFactor = 100", [cdt](vtkPolyDataAlgorithm* a)
        { cdt(a)->SetNeighborhoodRadiusFactor(1e9); } },
      { "MinimumNormalDot = 0", [cdt](vtkPolyDataAlgorithm* a)
        { cdt(a)->SetMinimumNormalDot(-3.0); } },
      { "MinimumNormalDot = 1", [cdt](vtkPolyDataAlgorithm* a)
        { cdt(a)->SetMinimumNormalDot(7.0); } },
      { "MaximumRayDistance = max", [cdt](vtkPolyDataAlgorithm* a)
        { cdt(a)->SetMaximumRayDistance(VTK_DOUBLE_MAX); } },
      { "MinimumTriangleArea = max", [cdt](vtkPolyDataAlgorithm* a)
        { cdt(a)->SetMinimumTriangleArea(VTK_DOUBLE_MAX); } },
      { "HoleFilling off", [cdt](vtkPolyDataAlgorithm* a) { cdt(a)->HoleFillingOff(); } },
      { "HoleFillingRadiusFactor = 1, HoleFillingMinimumNormalDot = 0", [cdt](vtkPolyDataAlgorithm* a)
        {
          cdt(a)->SetHoleFillingRadiusFactor(5.0);
          cdt(a)->SetHoleFillingMinimumNormalDot(-1.0);
        } },
      { "HoleFillingRadiusFactor = 0.01, HoleFillingMinimumNormalDot = 1", [cdt](vtkPolyDataAlgorithm* a)
        {
          cdt(a)->SetHoleFillingRadiusFactor(0.0);
          cdt(a)->SetHoleFillingMinimumNormalDot(2.0);
        } },
      { "NormalSampleSize = 3", [cdt](vtkPolyDataAlgorithm* a)
        { cdt(a)->SetNormalSampleSize(0); } },
      { "NormalSampleSize = 100", [cdt](vtkPolyDataAlgorithm* a)
        { cdt(a)->SetNormalSampleSize(VTK_INT_MAX); } },
      { "UseInputNormals off", [cdt](vtkPolyDataAlgorithm* a) { cdt(a)->UseInputNormalsOff(); } },
      { "MaximumNumberOfCandidates = 1", [cdt](vtkPolyDataAlgorithm* a)
        { cdt(a)->SetMaximumNumberOfCandidates(-4); } },
      { "MaximumNumberOfCandidates = 100000", [cdt](vtkPolyDataAlgorithm* a)
        { cdt(a)->SetMaximumNumberOfCandidates(VTK_INT_MAX); } },
    };
  }
#endif
#ifdef PCS_HAVE_PEEL
  if (name == "vtkPerimeterPeelSurface")
  {
    auto peel = [](vtkPolyDataAlgorithm* a) { return static_cast<vtkPerimeterPeelSurface*>(a); };
    return {
      { "ThresholdFactor = 0.01", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetThresholdFactor(-1.0); } },
      { "ThresholdFactor = 1000", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetThresholdFactor(VTK_DOUBLE_MAX); } },
      { "Threshold = 0 (automatic)", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetThreshold(-1.0); } },
      { "Threshold = max", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetThreshold(VTK_DOUBLE_MAX); } },
      { "Threshold = tiny", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetThreshold(VTK_DOUBLE_MIN); } },
      { "ConvergenceTolerance = 0", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetConvergenceTolerance(-1.0); } },
      { "ConvergenceTolerance = 1", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetConvergenceTolerance(5.0); } },
      { "FacetMeasure = PERIMETER (clamped)", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetFacetMeasure(-3); } },
      { "FacetMeasure = AREA", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetFacetMeasure(vtkPerimeterPeelSurface::AREA); } },
      { "FacetMeasure = CIRCUMRADIUS (clamped)", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetFacetMeasure(99); } },
      { "MaximumIterations = 1", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetMaximumIterations(-5); } },
      { "MaximumIterations = 100000", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetMaximumIterations(VTK_INT_MAX); } },
      { "GroupFactor = 1", [peel](vtkPolyDataAlgorithm* a) { peel(a)->SetGroupFactor(0.0); } },
      { "GroupFactor = 1000", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetGroupFactor(VTK_DOUBLE_MAX); } },
      { "ManifoldOutput off", [peel](vtkPolyDataAlgorithm* a) { peel(a)->ManifoldOutputOff(); } },
      { "LocalSpacingNeighbors = 0", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetLocalSpacingNeighbors(-1); } },
      { "LocalSpacingNeighbors = 64", [peel](vtkPolyDataAlgorithm* a)
        { peel(a)->SetLocalSpacingNeighbors(VTK_INT_MAX); } },
    };
  }
#endif
#ifdef PCS_HAVE_LOCAL_OPTIMUM
  if (name == "vtkLocalOptimumGrowth")
  {
    auto log = [](vtkPolyDataAlgorithm* a) { return static_cast<vtkLocalOptimumGrowth*>(a); };
    return {
      { "NumberOfNeighbors = 4", [log](vtkPolyDataAlgorithm* a)
        { log(a)->SetNumberOfNeighbors(0); } },
      { "NumberOfNeighbors = 200", [log](vtkPolyDataAlgorithm* a)
        { log(a)->SetNumberOfNeighbors(VTK_INT_MAX); } },
      { "MaximumNormalAngle = 1", [log](vtkPolyDataAlgorithm* a)
        { log(a)->SetMaximumNormalAngle(-10.0); } },
      { "MaximumNormalAngle = 179", [log](vtkPolyDataAlgorithm* a)
        { log(a)->SetMaximumNormalAngle(1000.0); } },
      { "MinimumEdgeRatio = 0, MaximumEdgeRatio = 1000", [log](vtkPolyDataAlgorithm* a)
        {
          log(a)->SetMinimumEdgeRatio(-1.0);
          log(a)->SetMaximumEdgeRatio(VTK_DOUBLE_MAX);
        } },
      { "MinimumEdgeRatio = 1, MaximumEdgeRatio = 1", [log](vtkPolyDataAlgorithm* a)
        {
          log(a)->SetMinimumEdgeRatio(2.0);
          log(a)->SetMaximumEdgeRatio(0.0);
        } },
      { "MaximumBaseAngle = 30", [log](vtkPolyDataAlgorithm* a)
        { log(a)->SetMaximumBaseAngle(0.0); } },
      { "MaximumBaseAngle = 179", [log](vtkPolyDataAlgorithm* a)
        { log(a)->SetMaximumBaseAngle(360.0); } },
      { "MaximumHoleEdges = 0", [log](vtkPolyDataAlgorithm* a)
        { log(a)->SetMaximumHoleEdges(-1); } },
      { "MaximumHoleEdges = 1000", [log](vtkPolyDataAlgorithm* a)
        { log(a)->SetMaximumHoleEdges(VTK_INT_MAX); } },
      { "RelaxConstraints off", [log](vtkPolyDataAlgorithm* a) { log(a)->RelaxConstraintsOff(); } },
    };
  }
#endif
#ifdef PCS_HAVE_GREEDY
  if (name == "vtkGreedySurfaceTriangulation")
  {
    auto gst = [](vtkPolyDataAlgorithm* a)
    { return static_cast<vtkGreedySurfaceTriangulation*>(a); };
    return {
      { "NumberOfNeighbors = 3", [gst](vtkPolyDataAlgorithm* a)
        { gst(a)->SetNumberOfNeighbors(0); } },
      { "NumberOfNeighbors = 64", [gst](vtkPolyDataAlgorithm* a)
        { gst(a)->SetNumberOfNeighbors(VTK_INT_MAX); } },
      { "CrossingTest = OFF (clamped)", [gst](vtkPolyDataAlgorithm* a)
        { gst(a)->SetCrossingTest(-1); } },
      { "CrossingTest = ON", [gst](vtkPolyDataAlgorithm* a)
        { gst(a)->SetCrossingTest(vtkGreedySurfaceTriangulation::CROSSING_TEST_ON); } },
      { "CrossingTest = AUTOMATIC (clamped), AutomaticCorrectFraction = 0",
        [gst](vtkPolyDataAlgorithm* a)
        {
          gst(a)->SetCrossingTest(99);
          gst(a)->SetAutomaticCorrectFraction(-1.0);
        } },
      { "AutomaticCorrectFraction = 1", [gst](vtkPolyDataAlgorithm* a)
        { gst(a)->SetAutomaticCorrectFraction(2.0); } },
      { "UniformityNeighbors = 2, UniformityAngle = 0", [gst](vtkPolyDataAlgorithm* a)
        {
          gst(a)->SetUniformityNeighbors(0);
          gst(a)->SetUniformityAngle(-1.0);
        } },
      { "UniformityNeighbors = 64, UniformityAngle = 90", [gst](vtkPolyDataAlgorithm* a)
        {
          gst(a)->SetUniformityNeighbors(VTK_INT_MAX);
          gst(a)->SetUniformityAngle(1000.0);
        } },
      { "MaximumNormalDeviation = 0", [gst](vtkPolyDataAlgorithm* a)
        { gst(a)->SetMaximumNormalDeviation(-1.0); } },
      { "MaximumNormalDeviation = 180", [gst](vtkPolyDataAlgorithm* a)
        { gst(a)->SetMaximumNormalDeviation(1000.0); } },
      { "MinimumIslandTriangles = 0", [gst](vtkPolyDataAlgorithm* a)
        { gst(a)->SetMinimumIslandTriangles(-1); } },
      { "MinimumIslandTriangles = max", [gst](vtkPolyDataAlgorithm* a)
        { gst(a)->SetMinimumIslandTriangles(VTK_INT_MAX); } },
      { "BoundaryVectorRadius = 0, StatusNeutralAngle = 0", [gst](vtkPolyDataAlgorithm* a)
        {
          gst(a)->SetBoundaryVectorRadius(-1.0);
          gst(a)->SetStatusNeutralAngle(-1.0);
        } },
      { "BoundaryVectorRadius = max, StatusNeutralAngle = 90", [gst](vtkPolyDataAlgorithm* a)
        {
          gst(a)->SetBoundaryVectorRadius(VTK_DOUBLE_MAX);
          gst(a)->SetStatusNeutralAngle(1000.0);
        } },
      { "BridgeIslands off, FillHoles off, SwapBridgeEdges off", [gst](vtkPolyDataAlgorithm* a)
        {
          gst(a)->BridgeIslandsOff();
          gst(a)->FillHolesOff();
          gst(a)->SwapBridgeEdgesOff();
        } },
      { "MaximumBridgeLength = 0, MinimumBridgeSeparation = 0", [gst](vtkPolyDataAlgorithm* a)
        {
          gst(a)->SetMaximumBridgeLength(-1.0);
          gst(a)->SetMinimumBridgeSeparation(-1.0);
        } },
      { "MaximumBridgeLength = max, MinimumBridgeSeparation = max", [gst](vtkPolyDataAlgorithm* a)
        {
          gst(a)->SetMaximumBridgeLength(VTK_DOUBLE_MAX);
          gst(a)->SetMinimumBridgeSeparation(VTK_DOUBLE_MAX);
        } },
      { "MaximumHoleDiameter = 0, AuxiliaryPointDistance = 0, MaximumHolePoints = 16",
        [gst](vtkPolyDataAlgorithm* a)
        {
          gst(a)->SetMaximumHoleDiameter(-1.0);
          gst(a)->SetAuxiliaryPointDistance(-1.0);
          gst(a)->SetMaximumHolePoints(0);
        } },
      { "MaximumHoleDiameter = max, AuxiliaryPointDistance = max, MaximumHolePoints = 100000",
        [gst](vtkPolyDataAlgorithm* a)
        {
          gst(a)->SetMaximumHoleDiameter(VTK_DOUBLE_MAX);
          gst(a)->SetAuxiliaryPointDistance(VTK_DOUBLE_MAX);
          gst(a)->SetMaximumHolePoints(VTK_INT_MAX);
        } },
    };
  }
#endif
  if (name == "vtkReconstructionQuality")
  {
    return {
      { "SamplesPerTriangle = 0", [](vtkPolyDataAlgorithm* a)
        { static_cast<vtkReconstructionQuality*>(a)->SetSamplesPerTriangle(-5); } },
      { "SamplesPerTriangle = 100", [](vtkPolyDataAlgorithm* a)
        { static_cast<vtkReconstructionQuality*>(a)->SetSamplesPerTriangle(1000); } },
    };
  }
  return {};
}

std::vector<FilterEntry> Filters()
{
  std::vector<FilterEntry> filters;
  for (const pcstest::FilterInfo& info : pcstest::AllFilters())
  {
    filters.push_back({ info, ExtremesOf(info.Name) });
  }
  return filters;
}

//------------------------------------------------------------------------------------------------
// The inputs.
std::vector<double> Sphere(int n, unsigned seed, double radius = 1.0)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<double> xyz;
  for (int i = 0; i < n; ++i)
  {
    double p[3] = { g(rng), g(rng), g(rng) };
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    xyz.insert(xyz.end(), { radius * p[0] / r, radius * p[1] / r, radius * p[2] / r });
  }
  return xyz;
}

struct InputCase
{
  std::string Name;
  std::vector<double> XYZ;
  bool Unusable;               // a warning or an error is required
  std::vector<double> Normals; // the active point normals (none when empty)
  bool BadNormals = false;     // some normals are zero-length or not finite
};

std::vector<InputCase> Inputs()
{
  std::vector<InputCase> cases;
  cases.push_back({ "empty point set", {}, true });
  cases.push_back({ "1 point", { 0.5, 0.5, 0.5 }, true });
  cases.push_back({ "2 points", { 0, 0, 0, 1, 0, 0 }, true });
  cases.push_back({ "3 points", { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, false });
  {
    std::vector<double> same;
    for (int i = 0; i < 100; ++i)
    {
      same.insert(same.end(), { 0.25, -3.0, 7.0 });
    }
    cases.push_back({ "100 identical points", same, true });
  }
  {
    std::vector<double> xyz = Sphere(2000, 1);
    for (int i = 0; i < 200; ++i)
    {
      const size_t k = 3 * static_cast<size_t>((i * 7919) % 2000);
      xyz.insert(xyz.end(), { xyz[k], xyz[k + 1], xyz[k + 2] });
    }
    cases.push_back({ "sphere with 10 % exact duplicates", xyz, false });
  }
  {
    // 4 piles of 250 near-coincident points (a scanner's repeated returns at one spot; spread
    // 1e-9) on a 2,000-point sphere: the sphere is the sparse part of the cloud. (The shared
    // outlier rule queried the piles from every sphere point: with 10 piles of 1,000 points on a
    // 10^4-point sphere, 22x the time of the sphere alone for vtkLocalOptimumGrowth.)
    std::vector<double> xyz = Sphere(2000, 13);
    const std::vector<double> centres = Sphere(4, 14);
    const std::vector<double> jitter = Sphere(1000, 15, 1e-9);
    for (size_t i = 0; i < jitter.size(); i += 3)
    {
      const size_t c = 3 * ((i / 3) % 4);
      xyz.insert(xyz.end(),
        { centres[c] + jitter[i], centres[c + 1] + jitter[i + 1], centres[c + 2] + jitter[i + 2] });
    }
    cases.push_back({ "sphere and 4 piles of 250 near-coincident points", xyz, false });
  }
  {
    std::vector<double> xyz = Sphere(2000, 2);
    for (int i = 0; i < 200; ++i)
    {
      const size_t k = 3 * static_cast<size_t>((i * 7919) % 2000);
      xyz.insert(xyz.end(), { xyz[k] * (1 + 1e-12), xyz[k + 1], xyz[k + 2] * (1 - 1e-12) });
    }
    cases.push_back({ "sphere with near-duplicates at 1e-12", xyz, false });
  }
  {
    std::vector<double> xyz;
    for (int i = 0; i < 100; ++i)
    {
      xyz.insert(xyz.end(), { 0.1 * i, 0.2 * i, -0.05 * i });
    }
    cases.push_back({ "100 collinear points", xyz, true });
  }
  {
    std::vector<double> xyz;
    for (int i = 0; i < 30; ++i)
    {
      for (int j = 0; j < 30; ++j)
      {
        xyz.insert(xyz.end(), { 0.1 * i, 0.1 * j, 2.0 });
      }
    }
    cases.push_back({ "planar 30x30 grid", xyz, false });
  }
  {
    std::vector<double> xyz = Sphere(1000, 3);
    std::vector<double> far = Sphere(1000, 4);
    for (size_t k = 0; k < far.size(); k += 3)
    {
      far[k] += 1e6;
    }
    xyz.insert(xyz.end(), far.begin(), far.end());
    cases.push_back({ "two clusters 10^6 apart", xyz, false });
  }
  {
    std::vector<double> xyz = Sphere(2000, 5);
    const double bad[3] = { std::numeric_limits<double>::quiet_NaN(),
      std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() };
    for (int i = 0; i < 100; ++i)
    {
      xyz[3 * static_cast<size_t>(i * 19) + (i % 3)] = bad[i % 3];
    }
    cases.push_back({ "sphere with NaN and Inf coordinates", xyz, true });
  }
  cases.push_back({ "sphere", Sphere(2000, 6), false });
  {
    // A dense blob (3000 points, standard deviation 1e-4) on a 3000-point sphere: the blob's
    // points fall into one hole piece of the greedy filter and one neighbourhood ball of the
    // CDT front; both were unbounded (cubic in the blob size) before they were capped.
    std::vector<double> xyz = Sphere(3000, 41);
    std::mt19937_64 rng(42);
    std::normal_distribution<double> g(0.0, 1e-4);
    for (int i = 0; i < 3000; ++i)
    {
      xyz.insert(xyz.end(), { 1.0 + g(rng), g(rng), g(rng) });
    }
    cases.push_back({ "sphere with a dense cluster", xyz, false });
  }
  {
    // Two scales: a unit sphere around a sphere of radius 1e-6.
    std::vector<double> xyz = Sphere(2000, 43);
    const std::vector<double> inner = Sphere(400, 44, 1e-6);
    xyz.insert(xyz.end(), inner.begin(), inner.end());
    cases.push_back({ "sphere around a 1e-6 sphere", xyz, false });
  }
  {
    // A sphere scanned in 40 rings of 50 points (dense along a ring, sparse across): the points
    // of a ring are exactly coplanar, so the tetrahedralization has flat cells (4 cocircular
    // points) whose circumcentre is undefined; their Voronoi vertices were NaN.
    std::vector<double> xyz;
    const double pi = 3.14159265358979323846;
    for (int ring = 0; ring < 40; ++ring)
    {
      const double t = 0.05 + (pi - 0.1) * ring / 39.0;
      for (int k = 0; k < 50; ++k)
      {
        const double f = 2.0 * pi * k / 50.0;
        xyz.insert(
          xyz.end(), { std::sin(t) * std::cos(f), std::sin(t) * std::sin(f), std::cos(t) });
      }
    }
    cases.push_back({ "sphere scanned in rings", xyz, false });
  }
  {
    // 300,000 copies of one point and 3 other points: every copy's nearest-neighbour query met
    // the whole pile (quadratic: vtkCDTAdvancingFront's estimated normals took 46 s CPU for 10^5
    // copies, far more than the test's timeout for these).
    std::vector<double> xyz;
    xyz.reserve(3 * 300003);
    for (int i = 0; i < 300000; ++i)
    {
      xyz.insert(xyz.end(), { 0.3, 0.3, 0.3 });
    }
    xyz.insert(xyz.end(), { 1, 0, 0, 0, 1, 0, 0, 0, 1 });
    cases.push_back({ "300,000 identical points plus 3 others", xyz, false });
  }
  {
    // A plane scanned in 40 lines of 500 points, 12.5 times denser along a line than across:
    // the K nearest neighbours of a point all lie on its own line. vtkGreedySurfaceTriangulation
    // made 2 triangles and left 19,996 points unused without a warning.
    std::vector<double> xyz;
    for (int line = 0; line < 40; ++line)
    {
      for (int k = 0; k < 500; ++k)
      {
        const double x = k / 499.0;
        xyz.insert(xyz.end(), { x, line / 39.0, 0.01 * std::sin(7.0 * x) });
      }
    }
    cases.push_back({ "plane scanned in lines", xyz, false });
  }
  {
    // A sphere of radius 300 scanned in 40 rings of 100 points, coordinates rounded to integers
    // (an int16 scanner): rows of exactly collinear points. vtkLocalOptimumGrowth (a free point
    // inserted into a triangle beside an edge it lies on) made 17 zero-area triangles and
    // vtkGreedySurfaceTriangulation (a lost point on a hole's boundary edge) 8.
    std::vector<double> xyz;
    const double pi = 3.14159265358979323846;
    for (int ring = 0; ring < 40; ++ring)
    {
      const double t = pi * (ring + 0.5) / 40.0;
      for (int k = 0; k < 100; ++k)
      {
        const double f = 2.0 * pi * k / 100.0;
        xyz.insert(xyz.end(),
          { std::round(300.0 * std::sin(t) * std::cos(f)),
            std::round(300.0 * std::sin(t) * std::sin(f)),
            std::round(300.0 * std::cos(t)) });
      }
    }
    cases.push_back({ "sphere scanned in rings, integer coordinates", xyz, false });
  }
  {
    // A tilted plane scanned in 20 lines of 150 points on an integer lattice (1 apart along a
    // line, 7 across): vtkLocalOptimumGrowth made 584 zero-area triangles with points of a line.
    std::vector<double> xyz;
    for (int line = 0; line < 20; ++line)
    {
      for (int k = 0; k < 150; ++k)
      {
        const double x = k, y = 7.0 * line;
        xyz.insert(xyz.end(), { x, y, x + y });
      }
    }
    cases.push_back({ "tilted plane scanned in integer lines", xyz, false });
  }
  // Normals (exact, outward on the unit sphere) with zero-length or NaN ones.
  for (int kind = 0; kind < 4; ++kind)
  {
    const std::vector<double> xyz = Sphere(2000, 31 + kind);
    std::vector<double> normals(xyz);
    const char* names[4] = { "sphere with exact normals", "sphere with 10 % zero-length normals",
      "sphere with only zero-length normals", "sphere with 5 % NaN normals" };
    for (size_t i = 0; i < normals.size() / 3; ++i)
    {
      const bool zero = (kind == 1 && i % 10 == 0) || kind == 2;
      const bool nan = kind == 3 && i % 20 == 0;
      for (int c = 0; c < 3; ++c)
      {
        normals[3 * i + c] =
          zero ? 0.0 : (nan ? std::numeric_limits<double>::quiet_NaN() : normals[3 * i + c]);
      }
    }
    cases.push_back({ names[kind], xyz, false, normals, kind > 0 });
  }
  return cases;
}

// Adds a point data array of each common type (values derived from the point index).
void AddPointArrays(vtkPolyData* cloud)
{
  const vtkIdType n = cloud->GetNumberOfPoints();
  std::vector<vtkSmartPointer<vtkDataArray>> arrays = { vtkSmartPointer<vtkCharArray>::New(),
    vtkSmartPointer<vtkSignedCharArray>::New(), vtkSmartPointer<vtkUnsignedCharArray>::New(),
    vtkSmartPointer<vtkShortArray>::New(), vtkSmartPointer<vtkUnsignedShortArray>::New(),
    vtkSmartPointer<vtkIntArray>::New(), vtkSmartPointer<vtkUnsignedIntArray>::New(),
    vtkSmartPointer<vtkLongLongArray>::New(), vtkSmartPointer<vtkIdTypeArray>::New(),
    vtkSmartPointer<vtkFloatArray>::New(), vtkSmartPointer<vtkDoubleArray>::New() };
  for (auto& array : arrays)
  {
    array->SetName((std::string("Pass_") + array->GetDataTypeAsString()).c_str());
    array->SetNumberOfComponents(array->GetDataType() == VTK_DOUBLE ? 3 : 1);
    array->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        array->SetComponent(i, c, static_cast<double>((i * 31 + c) % 97));
      }
    }
    cloud->GetPointData()->AddArray(array);
  }
}

//------------------------------------------------------------------------------------------------
using Messages = pcstest::MessageCounter;

Messages Update(vtkPolyDataAlgorithm* algorithm)
{
  Messages messages;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(&Messages::Callback);
  callback->SetClientData(&messages);
  const unsigned long t1 = algorithm->AddObserver(vtkCommand::WarningEvent, callback);
  const unsigned long t2 = algorithm->AddObserver(vtkCommand::ErrorEvent, callback);
  const unsigned long t3 = algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, callback);
  algorithm->Update();
  algorithm->RemoveObserver(t1);
  algorithm->RemoveObserver(t2);
  algorithm->GetExecutive()->RemoveObserver(t3);
  return messages;
}

struct Topology
{
  vtkIdType Triangles = 0;
  vtkIdType BoundaryEdges = 0;
  vtkIdType Genus = -1;
};

Topology Measure(vtkPolyData* mesh)
{
  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputData(mesh);
  quality->ComputeDistancesOff();
  vtkNew<vtkCallbackCommand> silence;
  quality->AddObserver(vtkCommand::WarningEvent, silence);
  quality->Update();
  Topology t;
  t.Triangles = pcstest::FieldCount(quality->GetOutput(), "NumberOfTriangles");
  t.BoundaryEdges = pcstest::FieldCount(quality->GetOutput(), "NumberOfBoundaryEdges");
  t.Genus = pcstest::FieldCount(quality->GetOutput(), "Genus");
  return t;
}

// The validity checks of every output.
bool CheckOutput(const FilterEntry& filter, const std::string& label, vtkPolyData* input,
  vtkPolyData* output, bool checkArrays)
{
  PCS_CHECK(output != nullptr, label << ": no output");
  // The input points, then the points the filter reports as added (vtkGreedySurfaceTriangulation
  // refines its hole fills: NumberOfAddedPoints, Status 5).
  const vtkIdType added = output->GetFieldData()->GetArray("NumberOfAddedPoints")
    ? pcstest::FieldCount(output, "NumberOfAddedPoints")
    : 0;
  const vtkIdType n = input->GetNumberOfPoints() + added;
  PCS_CHECK(added >= 0 && output->GetNumberOfPoints() == n,
    label << ": " << output->GetNumberOfPoints() << " output points for "
          << input->GetNumberOfPoints() << " input points and " << added << " added");
  for (vtkIdType c = 0; c < output->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    output->GetCellPoints(c, npts, pts);
    for (vtkIdType k = 0; k < npts; ++k)
    {
      PCS_CHECK(pts[k] >= 0 && pts[k] < n, label << ": cell " << c << " has point id " << pts[k]);
      double p[3];
      output->GetPoint(pts[k], p);
      PCS_CHECK(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]),
        label << ": cell " << c << " uses the non-finite point " << pts[k]);
      for (vtkIdType j = 0; j < k; ++j)
      {
        PCS_CHECK(pts[j] != pts[k] || output->GetCellType(c) != VTK_TRIANGLE,
          label << ": triangle " << c << " repeats point " << pts[k]);
      }
    }
  }
  if (filter.Info.PromisesManifold && output->GetNumberOfPolys() > 0)
  {
    vtkNew<vtkReconstructionQuality> quality;
    quality->SetInputData(output);
    quality->ComputeDistancesOff();
    quality->Update();
    PCS_CHECK(pcstest::FieldCount(quality->GetOutput(), "NumberOfNonManifoldEdges") == 0,
      label << ": non-manifold edges");
    PCS_CHECK(pcstest::FieldCount(quality->GetOutput(), "NumberOfNonManifoldVertices") == 0,
      label << ": non-manifold vertices");
    const vtkIdType degenerate =
      pcstest::FieldCount(quality->GetOutput(), "NumberOfDegenerateTriangles");
    PCS_CHECK(degenerate == 0, label << ": " << degenerate << " zero-area triangles");
  }
  if (checkArrays)
  {
    vtkPointData* in = input->GetPointData();
    for (int a = 0; a < in->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* source = in->GetArray(a);
      if (!source || std::string(source->GetName()).rfind("Pass_", 0) != 0)
      {
        continue;
      }
      vtkDataArray* passed = output->GetPointData()->GetArray(source->GetName());
      PCS_CHECK(passed, label << ": point data " << source->GetName() << " not passed");
      // One tuple per output point: the input's, then those of the added points.
      PCS_CHECK(passed->GetDataType() == source->GetDataType() &&
          passed->GetNumberOfTuples() == source->GetNumberOfTuples() + added &&
          passed->GetNumberOfComponents() == source->GetNumberOfComponents(),
        label << ": point data " << source->GetName() << " changed type or size");
      for (vtkIdType i = 0; i < source->GetNumberOfTuples(); ++i)
      {
        PCS_CHECK(passed->GetComponent(i, 0) == source->GetComponent(i, 0),
          label << ": point data " << source->GetName() << " value " << i);
      }
    }
  }
  return true;
}

// vtkIncrementalDelaunay3D's Voronoi diagram (port 2): every vertex finite, every line's ids in
// range.
bool CheckVoronoi(const std::string& label, vtkPolyData* cloud)
{
  vtkNew<vtkIncrementalDelaunay3D> delaunay;
  delaunay->GenerateVoronoiOn();
  delaunay->SetInputData(cloud);
  Update(delaunay);
  vtkPolyData* voronoi = delaunay->GetVoronoiOutput();
  for (vtkIdType i = 0; i < voronoi->GetNumberOfPoints(); ++i)
  {
    double p[3];
    voronoi->GetPoint(i, p);
    PCS_CHECK(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]),
      label << ": Voronoi vertex " << i << " is not finite");
  }
  for (vtkIdType c = 0; c < voronoi->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    voronoi->GetCellPoints(c, npts, pts);
    for (vtkIdType k = 0; k < npts; ++k)
    {
      PCS_CHECK(pts[k] >= 0 && pts[k] < voronoi->GetNumberOfPoints(),
        label << ": Voronoi line " << c << " has point id " << pts[k]);
    }
  }
  return true;
}

bool RunCase(const FilterEntry& filter, const InputCase& input)
{
  const std::string label = filter.Info.Name + " / " + input.Name;
  auto cloud = pcstest::MakeCloud(input.XYZ);
  AddPointArrays(cloud);
  if (!input.Normals.empty())
  {
    vtkNew<vtkDoubleArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(cloud->GetNumberOfPoints());
    for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
    {
      normals->SetTuple(i, &input.Normals[3 * i]);
    }
    cloud->GetPointData()->SetNormals(normals);
  }
  auto prepared = filter.Prepare(cloud);
  Algorithm algorithm = filter.Info.Make();
  algorithm->SetInputData(prepared);
  const Messages messages = Update(algorithm);
  if (input.Unusable)
  {
    PCS_CHECK(messages.Warnings + messages.Errors > 0, label << ": no warning or error");
  }
  if (!input.Normals.empty() && TakesNormals(filter.Info.Name))
  {
    PCS_CHECK(!input.BadNormals || messages.Warnings > 0, label << ": no warning");
    vtkNew<vtkReconstructionQuality> quality;
    quality->SetInputData(algorithm->GetOutput());
    quality->ComputeDistancesOff();
    quality->Update();
    const vtkIdType used = pcstest::FieldCount(quality->GetOutput(), "NumberOfUsedPoints");
    PCS_CHECK(used == prepared->GetNumberOfPoints(),
      label << ": " << used << " of " << prepared->GetNumberOfPoints() << " points used");
  }
  // A reconstruction that leaves input points out of every triangle says so (the convex hull
  // of vtkIncrementalDelaunay3D leaves the inner points out by definition).
  if (filter.Info.Reconstructs && filter.Info.Name != "vtkIncrementalDelaunay3D" &&
    algorithm->GetOutput()->GetNumberOfPolys() > 0)
  {
    vtkNew<vtkReconstructionQuality> quality;
    quality->SetInputData(algorithm->GetOutput());
    quality->ComputeDistancesOff();
    vtkNew<vtkCallbackCommand> silence;
    quality->AddObserver(vtkCommand::WarningEvent, silence);
    quality->Update();
    const vtkIdType used = pcstest::FieldCount(quality->GetOutput(), "NumberOfUsedPoints");
    PCS_CHECK(used == algorithm->GetOutput()->GetNumberOfPoints() || messages.Warnings > 0,
      label << ": " << algorithm->GetOutput()->GetNumberOfPoints() - used
            << " point(s) unused without a warning");
  }
  if (filter.Info.Name == "vtkIncrementalDelaunay3D" && !CheckVoronoi(label, prepared))
  {
    return false;
  }
  return CheckOutput(filter, label, prepared, algorithm->GetOutput(), true);
}

bool SameSurface(const FilterEntry& filter, const std::string& label, vtkPolyData* a,
  vtkPolyData* b)
{
  const Topology ta = Measure(a), tb = Measure(b);
  PCS_CHECK(ta.Triangles > 0, label << ": no triangles on the reference input");
  PCS_CHECK(std::abs(ta.Triangles - tb.Triangles) <= 0.005 * ta.Triangles,
    label << ": " << tb.Triangles << " triangles instead of " << ta.Triangles);
  PCS_CHECK((ta.BoundaryEdges == 0) == (tb.BoundaryEdges == 0),
    label << ": closedness differs (" << ta.BoundaryEdges << " vs " << tb.BoundaryEdges
          << " boundary edges)");
  PCS_CHECK(ta.Genus == tb.Genus, label << ": genus " << tb.Genus << " instead of " << ta.Genus);
  (void)filter;
  return true;
}

// A cloud of the given coordinates with double or float points and the point data arrays of
// AddPointArrays.
vtkSmartPointer<vtkPolyData> CloudWithArrays(const std::vector<double>& xyz, bool floatPoints)
{
  auto cloud = pcstest::MakeCloud(xyz);
  if (floatPoints)
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    for (size_t i = 0; i < xyz.size(); i += 3)
    {
      points->InsertNextPoint(xyz[i], xyz[i + 1], xyz[i + 2]);
    }
    cloud->SetPoints(points);
  }
  AddPointArrays(cloud);
  return cloud;
}

// The same surface through different inputs: a 10^6 offset on every coordinate, float points, a
// vtkUnstructuredGrid of vertices (the cloud filters; vtkReconstructionQuality measures a
// vtkPolyData mesh, its inputs are the hulls of the offset and float clouds). Each output has
// the triangle count of the reference within 0.5 %, its closedness and genus, and passes the
// point data through.
bool RunEquivalences(const FilterEntry& filter)
{
  const std::vector<double> xyz = Sphere(3000, 11);
  auto reference = filter.Info.Make();
  reference->SetInputData(filter.Prepare(pcstest::MakeCloud(xyz)));
  reference->Update();

  auto run = [&filter, &reference](const std::string& what, vtkDataSet* input) -> bool
  {
    const std::string label = filter.Info.Name + " / " + what;
    auto algorithm = filter.Info.Make();
    algorithm->SetInputData(input);
    Update(algorithm);
    vtkNew<vtkPolyData> asPolyData; // the points and point data of a non-polydata input
    asPolyData->SetPoints(vtkPointSet::SafeDownCast(input)->GetPoints());
    asPolyData->GetPointData()->ShallowCopy(input->GetPointData());
    return CheckOutput(filter, label, asPolyData, algorithm->GetOutput(), true) &&
      SameSurface(filter, label, reference->GetOutput(), algorithm->GetOutput());
  };

  // 10^6 offset on every coordinate.
  std::vector<double> shifted(xyz);
  for (double& c : shifted)
  {
    c += 1e6;
  }
  if (!run("10^6 offset", filter.Prepare(CloudWithArrays(shifted, false))))
  {
    return false;
  }
  // Float coordinates.
  if (!run("float points", filter.Prepare(CloudWithArrays(xyz, true))))
  {
    return false;
  }
  // Extreme scales: the squares of the coordinates overflow or underflow a double.
  for (double scale : { 1e300, 1e-300 })
  {
    std::vector<double> scaled(xyz);
    for (double& c : scaled)
    {
      c *= scale;
    }
    if (!run(scale > 1 ? "coordinates x 1e300" : "coordinates x 1e-300",
          filter.Prepare(CloudWithArrays(scaled, false))))
    {
      return false;
    }
  }
  // Every point 8 times (exact duplicates): the neighbourhoods of the normal estimation, the
  // spacing and the growing filters' neighbour lists must look through the copies.
  if (!filter.Info.ConsumesMesh)
  {
    std::vector<double> repeated;
    for (int copy = 0; copy < 8; ++copy)
    {
      repeated.insert(repeated.end(), xyz.begin(), xyz.end());
    }
    if (!run("every point 8 times", filter.Prepare(CloudWithArrays(repeated, false))))
    {
      return false;
    }
  }
  // A vtkUnstructuredGrid of vertices, float and double points.
  if (!filter.Info.ConsumesMesh)
  {
    for (bool floatPoints : { false, true })
    {
      auto cloud = CloudWithArrays(xyz, floatPoints);
      vtkNew<vtkUnstructuredGrid> grid;
      grid->SetPoints(cloud->GetPoints());
      grid->GetPointData()->ShallowCopy(cloud->GetPointData());
      grid->Allocate(cloud->GetNumberOfPoints());
      for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
      {
        grid->InsertNextCell(VTK_VERTEX, 1, &i);
      }
      if (!run(floatPoints ? "unstructured grid input, float points" : "unstructured grid input",
            grid))
      {
        return false;
      }
    }
  }
  return true;
}

bool RunExtremes(const FilterEntry& filter)
{
  auto cloud = pcstest::MakeCloud(Sphere(1500, 21));
  auto prepared = filter.Prepare(cloud);
  for (const auto& extreme : filter.Extremes)
  {
    Algorithm algorithm = filter.Info.Make();
    extreme.second(algorithm);
    algorithm->SetInputData(prepared);
    Update(algorithm);
    // vtkPerimeterPeelSurface's paper mode (ManifoldOutput off) may leave non-manifold edges
    // (its class documentation); everything else is checked as usual.
    FilterEntry checked = filter;
    checked.Info.PromisesManifold &= extreme.first.find("ManifoldOutput off") == std::string::npos;
    if (!CheckOutput(checked, filter.Info.Name + " / " + extreme.first, prepared,
          algorithm->GetOutput(), false))
    {
      return false;
    }
  }
  return true;
}

// The double parameters of each filter (NaN passes VTK's clamp macros: every comparison is
// false).
// Get: only where a test reads the parameter back (OutlierFactor, RunOutlierFactorLimits).
struct DoubleSetter
{
  std::string Name;
  std::function<void(vtkPolyDataAlgorithm*, double)> Set;
  std::function<double(vtkPolyDataAlgorithm*)> Get;
};
template<typename T>
DoubleSetter Setter(const char* name, void (T::*set)(double))
{
  return {
    name, [set](vtkPolyDataAlgorithm* a, double v) { (static_cast<T*>(a)->*set)(v); }, nullptr
  };
}
template<typename T, typename Getter>
DoubleSetter Setter(const char* name, void (T::*set)(double), Getter get)
{
  DoubleSetter setter = Setter(name, set);
  setter.Get = [get](vtkPolyDataAlgorithm* a) { return (static_cast<T*>(a)->*get)(); };
  return setter;
}

std::vector<DoubleSetter> DoubleParametersOf(const std::string& name)
{
  if (name == "vtkIncrementalDelaunay3D")
  {
    return { Setter("Tolerance", &vtkIncrementalDelaunay3D::SetTolerance) };
  }
#ifdef PCS_HAVE_PEEL
  if (name == "vtkPerimeterPeelSurface")
  {
    using F = vtkPerimeterPeelSurface;
    return { Setter("ThresholdFactor", &F::SetThresholdFactor),
      Setter("ConvergenceTolerance", &F::SetConvergenceTolerance),
      Setter("Threshold", &F::SetThreshold),
      Setter("GroupFactor", &F::SetGroupFactor),
      Setter("HandleFactor", &F::SetHandleFactor),
      Setter("CaveLimit", &F::SetCaveLimit),
      Setter("GroupStartLimit", &F::SetGroupStartLimit),
      Setter("OutlierFactor", &F::SetOutlierFactor, &F::GetOutlierFactor) };
  }
#endif
#ifdef PCS_HAVE_CDT
  if (name == "vtkCDTAdvancingFront")
  {
    using F = vtkCDTAdvancingFront;
    return { Setter("NeighborhoodRadius", &F::SetNeighborhoodRadius),
      Setter("NeighborhoodRadiusFactor", &F::SetNeighborhoodRadiusFactor),
      Setter("MinimumNormalDot", &F::SetMinimumNormalDot),
      Setter("MaximumRayDistance", &F::SetMaximumRayDistance),
      Setter("MinimumTriangleArea", &F::SetMinimumTriangleArea),
      Setter("HoleFillingRadiusFactor", &F::SetHoleFillingRadiusFactor),
      Setter("HoleFillingMinimumNormalDot", &F::SetHoleFillingMinimumNormalDot),
      Setter("NoiseBandFactor", &F::SetNoiseBandFactor) };
  }
#endif
#ifdef PCS_HAVE_LOCAL_OPTIMUM
  if (name == "vtkLocalOptimumGrowth")
  {
    using F = vtkLocalOptimumGrowth;
    return { Setter("MaximumNormalAngle", &F::SetMaximumNormalAngle),
      Setter("MinimumEdgeRatio", &F::SetMinimumEdgeRatio),
      Setter("MaximumEdgeRatio", &F::SetMaximumEdgeRatio),
      Setter("MaximumBaseAngle", &F::SetMaximumBaseAngle),
      Setter("OutlierFactor", &F::SetOutlierFactor, &F::GetOutlierFactor) };
  }
#endif
#ifdef PCS_HAVE_GREEDY
  if (name == "vtkGreedySurfaceTriangulation")
  {
    using F = vtkGreedySurfaceTriangulation;
    return { Setter("OutlierFactor", &F::SetOutlierFactor, &F::GetOutlierFactor),
      Setter("AutomaticCorrectFraction", &F::SetAutomaticCorrectFraction),
      Setter("UniformityAngle", &F::SetUniformityAngle),
      Setter("MaximumNormalDeviation", &F::SetMaximumNormalDeviation),
      Setter("BoundaryVectorRadius", &F::SetBoundaryVectorRadius),
      Setter("StatusNeutralAngle", &F::SetStatusNeutralAngle),
      Setter("MaximumBridgeLength", &F::SetMaximumBridgeLength),
      Setter("MinimumBridgeSeparation", &F::SetMinimumBridgeSeparation),
      Setter("MaximumHoleDiameter", &F::SetMaximumHoleDiameter),
      Setter("AuxiliaryPointDistance", &F::SetAuxiliaryPointDistance) };
  }
#endif
  return {};
}

// OutlierFactor at its limits, on a sphere sample with 3 far outliers (4 radii from the centre,
// 30 to 40 sphere spacings from any point): 0 turns the rule off (and -1 is clamped to 0), so
// nothing is excluded; a huge value is clamped to 1000, above these outliers' ratio (about 35):
// nothing is excluded either; the default 8 excludes exactly the 3 with a warning, reported in
// NumberOfOutliers with Used 0. No error, and a valid output, in every case. (NaN: an error,
// RunNaNParameters.)
bool RunOutlierFactorLimits(const FilterEntry& filter)
{
  // The filters with an OutlierFactor: those whose double parameters list it, with its getter.
  DoubleSetter access;
  for (const DoubleSetter& parameter : DoubleParametersOf(filter.Info.Name))
  {
    access = parameter.Name == "OutlierFactor" ? parameter : access;
  }
  if (!access.Get)
  {
    return true;
  }
  std::vector<double> xyz = Sphere(1500, 21);
  const vtkIdType firstOutlier = static_cast<vtkIdType>(xyz.size() / 3);
  xyz.insert(xyz.end(), { 4.0, 0.0, 0.0, 0.0, -4.0, 0.0, 0.0, 0.0, 4.0 });
  auto prepared = filter.Prepare(pcstest::MakeCloud(xyz));
  struct Limit
  {
    const char* Label;
    double Value, Clamped;
    vtkIdType Outliers;
  };
  const Limit limits[] = {
    { "OutlierFactor = -1 (clamped to 0: off)", -1.0, 0.0, 0 },
    { "OutlierFactor = 0 (off)", 0.0, 0.0, 0 },
    { "OutlierFactor = huge (clamped to 1000)", VTK_DOUBLE_MAX, 1000.0, 0 },
    { "OutlierFactor = 8 (default)", 8.0, 8.0, 3 },
  };
  for (const Limit& limit : limits)
  {
    const std::string label = filter.Info.Name + " / " + limit.Label;
    Algorithm algorithm = filter.Info.Make();
    access.Set(algorithm, limit.Value);
    PCS_CHECK(access.Get(algorithm) == limit.Clamped,
      label << ": OutlierFactor reads " << access.Get(algorithm));
    algorithm->SetInputData(prepared);
    const Messages messages = Update(algorithm);
    vtkPolyData* output = algorithm->GetOutput();
    PCS_CHECK(messages.Errors == 0, label << ": " << messages.Errors << " error(s)");
    PCS_CHECK(pcstest::FieldCount(output, "NumberOfOutliers") == limit.Outliers,
      label << ": " << pcstest::FieldCount(output, "NumberOfOutliers") << " outliers, expected "
            << limit.Outliers);
    if (limit.Outliers > 0)
    {
      PCS_CHECK(messages.Warnings > 0, label << ": outliers excluded without a warning");
      vtkDataArray* used = output->GetPointData()->GetArray("Used");
      PCS_CHECK(used, label << ": no Used array");
      for (vtkIdType p = firstOutlier; p < firstOutlier + 3; ++p)
      {
        PCS_CHECK(used->GetTuple1(p) == 0, label << ": outlier " << p << " used");
      }
    }
    if (!CheckOutput(filter, label, prepared, output, false))
    {
      return false;
    }
  }
  return true;
}

// vtkReconstructionQuality against a reference cloud holding a pile of 20,000 copies of one
// point: its MeanSpacing looked for each copy's nearest distinct point with queries doubling past
// the whole pile (82 s CPU for 10,000 copies, beyond the test's timeout for these). The pile's
// copies are 0.5 from the unit sphere, so the mean spacing lies between the sphere's and 0.5.
bool RunQualityReferencePile()
{
  std::vector<double> xyz = Sphere(2000, 51);
  auto hull = HullOf(pcstest::MakeCloud(xyz));
  for (int i = 0; i < 20000; ++i)
  {
    xyz.insert(xyz.end(), { 0.5, 0.0, 0.0 });
  }
  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputData(hull);
  quality->SetInputData(1, pcstest::MakeCloud(xyz));
  Update(quality);
  const double spacing =
    quality->GetOutput()->GetFieldData()->GetArray("MeanSpacing")->GetTuple1(0);
  PCS_CHECK(spacing > 0.04 && spacing < 0.5,
    "vtkReconstructionQuality / reference with a pile of 20,000 copies: MeanSpacing " << spacing);
  return true;
}

// vtkReconstructionQuality against a reference cloud of integer points (int, short: a scanner's
// raw coordinates): the measures of the same cloud in double points. The spacing search read
// such points through vtkStaticPointLocator, which crashed (VTK 9.2) on int and short points.
bool RunQualityIntegerReference()
{
  std::vector<double> xyz = Sphere(2000, 61, 300.0);
  for (double& c : xyz)
  {
    c = std::round(c);
  }
  auto hull = HullOf(pcstest::MakeCloud(xyz));
  auto measure = [&hull](vtkPolyData* reference)
  {
    vtkNew<vtkReconstructionQuality> quality;
    quality->SetInputData(hull);
    quality->SetInputData(1, reference);
    Update(quality);
    vtkFieldData* fd = quality->GetOutput()->GetFieldData();
    return std::vector<double>{ fd->GetArray("MeanSpacing")->GetTuple1(0),
      fd->GetArray("CompletenessMean")->GetTuple1(0),
      fd->GetArray("Hausdorff")->GetTuple1(0) };
  };
  const std::vector<double> expected = measure(pcstest::MakeCloud(xyz));
  PCS_CHECK(expected[0] > 0.0, "vtkReconstructionQuality / integer reference: no spacing");
  for (int type : { VTK_INT, VTK_SHORT })
  {
    vtkNew<vtkPoints> points;
    points->SetDataType(type);
    for (size_t i = 0; i < xyz.size(); i += 3)
    {
      points->InsertNextPoint(xyz[i], xyz[i + 1], xyz[i + 2]);
    }
    vtkNew<vtkPolyData> reference;
    reference->SetPoints(points);
    PCS_CHECK(measure(reference) == expected,
      "vtkReconstructionQuality / reference of " << (type == VTK_INT ? "int" : "short")
                                                 << " points: other measures");
  }
  return true;
}

// vtkReconstructionQuality against a reference cloud of 2,000 sphere points and 20,000 points
// with a NaN coordinate: the measures of the sphere points alone. Each NaN point used to search
// for its nearest distinct point with queries doubling up to the whole cloud (the mean spacing),
// about 19 s CPU for 600 such points among 3,000, quadratic beyond the test's timeout for these.
bool RunQualityReferenceNaNPoints()
{
  const std::vector<double> xyz = Sphere(2000, 62);
  auto hull = HullOf(pcstest::MakeCloud(xyz));
  std::vector<double> withNaN = xyz;
  for (int i = 0; i < 20000; ++i)
  {
    withNaN.insert(withNaN.end(), { std::numeric_limits<double>::quiet_NaN(), 0.001 * i, 0.5 });
  }
  vtkNew<vtkReconstructionQuality> clean, hostile;
  clean->SetInputData(hull);
  clean->SetInputData(1, pcstest::MakeCloud(xyz));
  Update(clean);
  hostile->SetInputData(hull);
  hostile->SetInputData(1, pcstest::MakeCloud(withNaN));
  const Messages messages = Update(hostile);
  PCS_CHECK(messages.Warnings > 0, "vtkReconstructionQuality / NaN reference points: no warning");
  for (const char* name : { "MeanSpacing", "CompletenessMean", "Hausdorff" })
  {
    const double expected = clean->GetOutput()->GetFieldData()->GetArray(name)->GetTuple1(0);
    const double value = hostile->GetOutput()->GetFieldData()->GetArray(name)->GetTuple1(0);
    PCS_CHECK(value == expected,
      "vtkReconstructionQuality / NaN reference points: " << name << " " << value << " instead of "
                                                          << expected);
  }
  return true;
}

// A point data array with half as many tuples as points (a corrupt input) is dropped with a
// warning: every output point data array has one tuple per output point, the sound arrays pass
// through. (The filters passed it on, an output array of the wrong length.)
bool RunMismatchedPointData(const FilterEntry& filter)
{
  auto prepared = filter.Prepare(pcstest::MakeCloud(Sphere(1000, 71)));
  AddPointArrays(prepared);
  vtkNew<vtkFloatArray> half;
  half->SetName("Half");
  half->SetNumberOfTuples(prepared->GetNumberOfPoints() / 2);
  half->FillValue(1.0f);
  prepared->GetPointData()->AddArray(half);
  Algorithm algorithm = filter.Info.Make();
  algorithm->SetInputData(prepared);
  const Messages messages = Update(algorithm);
  const std::string label = filter.Info.Name + " / point data array of half length";
  PCS_CHECK(messages.Warnings > 0, label << ": no warning");
  vtkPolyData* output = algorithm->GetOutput();
  vtkPointData* pd = output->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    PCS_CHECK(pd->GetAbstractArray(a)->GetNumberOfTuples() == output->GetNumberOfPoints(),
      label << ": output array " << pd->GetAbstractArray(a)->GetName() << " has "
            << pd->GetAbstractArray(a)->GetNumberOfTuples() << " tuples for "
            << output->GetNumberOfPoints() << " points");
  }
  PCS_CHECK(half->GetNumberOfTuples() == prepared->GetNumberOfPoints() / 2 &&
      prepared->GetPointData()->GetArray("Half") == half,
    label << ": the input was modified");
  return CheckOutput(filter, label, prepared, output, true);
}

// Each double parameter set to NaN, one at a time: an error and a valid output without
// triangles. (NaN went through the clamp: most parameters then acted as some limit, silently;
// a NaN NeighborhoodRadiusFactor left vtkCDTAdvancingFront without any triangle, a NaN
// MinimumEdgeRatio changed vtkLocalOptimumGrowth's mesh, without an error.)
bool RunNaNParameters(const FilterEntry& filter)
{
  auto prepared = filter.Prepare(pcstest::MakeCloud(Sphere(500, 81)));
  for (const DoubleSetter& parameter : DoubleParametersOf(filter.Info.Name))
  {
    const std::string label = filter.Info.Name + " / " + parameter.Name + " = NaN";
    Algorithm algorithm = filter.Info.Make();
    parameter.Set(algorithm, std::numeric_limits<double>::quiet_NaN());
    algorithm->SetInputData(prepared);
    const Messages messages = Update(algorithm);
    PCS_CHECK(messages.Errors > 0, label << ": no error");
    PCS_CHECK(algorithm->GetOutput()->GetNumberOfPolys() == 0, label << ": triangles made");
    if (!CheckOutput(filter, label, prepared, algorithm->GetOutput(), false))
    {
      return false;
    }
  }
  return true;
}

// A sphere with a cap cut off (a 20-degree hole that vtkGreedySurfaceTriangulation fills with
// new points): the output starts with the input points, unchanged (same data type, same values),
// the points a filter adds come after them. (Greedy's output points were a float copy when it
// added points: every double input coordinate was rounded.)
bool RunAddedPointsKeepInput(const FilterEntry& filter)
{
  const std::vector<double> sphere = Sphere(3000, 91);
  std::vector<double> xyz;
  for (size_t i = 0; i < sphere.size(); i += 3)
  {
    if (sphere[i + 2] < std::cos(vtkMath::RadiansFromDegrees(20.0)))
    {
      xyz.insert(xyz.end(), &sphere[i], &sphere[i] + 3);
    }
  }
  auto prepared = filter.Prepare(pcstest::MakeCloud(xyz));
  Algorithm algorithm = filter.Info.Make();
  algorithm->SetInputData(prepared);
  Update(algorithm);
  const std::string label = filter.Info.Name + " / sphere with a hole";
  vtkPoints* in = prepared->GetPoints();
  vtkPoints* out = algorithm->GetOutput()->GetPoints();
  const vtkIdType n = in->GetNumberOfPoints();
  PCS_CHECK(out && out->GetNumberOfPoints() >= n, label << ": fewer output points than input");
  // The hole is what makes greedy add points: without them the case would test nothing.
  PCS_CHECK(filter.Info.Name != "vtkGreedySurfaceTriangulation" || out->GetNumberOfPoints() > n,
    label << ": no point added, the case no longer tests the copy of the input points");
  PCS_CHECK(out->GetDataType() == in->GetDataType(),
    label << ": " << out->GetData()->GetDataTypeAsString() << " output points for "
          << in->GetData()->GetDataTypeAsString() << " input points ("
          << out->GetNumberOfPoints() - n << " added)");
  for (vtkIdType i = 0; i < n; ++i)
  {
    double a[3], b[3];
    in->GetPoint(i, a);
    out->GetPoint(i, b);
    PCS_CHECK(
      a[0] == b[0] && a[1] == b[1] && a[2] == b[2], label << ": input point " << i << " changed");
  }
  vtkPolyData* output = algorithm->GetOutput();
  for (vtkIdType c = 0; c < output->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    output->GetCellPoints(c, npts, pts);
    for (vtkIdType k = 0; k < npts; ++k)
    {
      PCS_CHECK(pts[k] >= 0 && pts[k] < out->GetNumberOfPoints(),
        label << ": cell " << c << " has point id " << pts[k]);
    }
  }
  return true;
}

// 300 points on the moment curve (t, t^2, t^3): nearly every pair of points is a Delaunay edge,
// and the tetrahedralization has n^2 / 2 tetrahedra, not about 7n. The filters that build it
// (vtkIncrementalDelaunay3D, vtkPerimeterPeelSurface) say so in a warning (they said nothing;
// at 10^4 points such a cloud runs for minutes); every filter gives a valid output.
bool RunLargeTetrahedralization(const FilterEntry& filter)
{
  std::vector<double> xyz;
  for (int i = 0; i < 300; ++i)
  {
    const double t = -1.0 + 2.0 * i / 299.0;
    xyz.insert(xyz.end(), { t, t * t, t * t * t });
  }
  auto prepared = filter.Prepare(pcstest::MakeCloud(xyz));
  Algorithm algorithm = filter.Info.Make();
  algorithm->SetInputData(prepared);
  std::string warnings;
  vtkNew<vtkCallbackCommand> capture;
  capture->SetClientData(&warnings);
  capture->SetCallback([](vtkObject*, unsigned long, void* client, void* text)
    { *static_cast<std::string*>(client) += static_cast<const char*>(text); });
  algorithm->AddObserver(vtkCommand::WarningEvent, capture);
  algorithm->Update();
  const std::string label = filter.Info.Name + " / 300 points on the moment curve";
  const bool tetrahedralizes =
    filter.Info.Name == "vtkIncrementalDelaunay3D" || filter.Info.Name == "vtkPerimeterPeelSurface";
  PCS_CHECK(
    !tetrahedralizes || warnings.find("The Delaunay tetrahedralization has") != std::string::npos,
    label << ": no warning on the size of the tetrahedralization");
  return CheckOutput(filter, label, prepared, algorithm->GetOutput(), false);
}

bool RunWithoutInput(const FilterEntry& filter)
{
  Algorithm algorithm = filter.Info.Make();
  const Messages messages = Update(algorithm);
  PCS_CHECK(messages.Errors + messages.Warnings > 0, filter.Info.Name << ": no input, no error");
  return true;
}
} // namespace

int TestRobustness(int, char*[])
{
  int failures = 0;
  const std::vector<InputCase> inputs = Inputs();
  for (const FilterEntry& filter : Filters())
  {
    int cases = 0;
    failures += RunWithoutInput(filter) ? 0 : 1;
    for (const InputCase& input : inputs)
    {
      failures += RunCase(filter, input) ? 0 : 1;
      ++cases;
    }
    failures += RunEquivalences(filter) ? 0 : 1;
    failures += RunMismatchedPointData(filter) ? 0 : 1;
    failures += RunNaNParameters(filter) ? 0 : 1;
    failures += RunExtremes(filter) ? 0 : 1;
    failures += RunOutlierFactorLimits(filter) ? 0 : 1;
    failures += RunAddedPointsKeepInput(filter) ? 0 : 1;
    failures += RunLargeTetrahedralization(filter) ? 0 : 1;
    std::cout << filter.Info.Name << ": " << cases << " inputs, " << filter.Extremes.size()
              << " parameter limits" << std::endl;
  }
  failures += RunQualityReferencePile() ? 0 : 1;
  failures += RunQualityIntegerReference() ? 0 : 1;
  failures += RunQualityReferenceNaNPoints() ? 0 : 1;
  std::cout << failures << " failure(s)" << std::endl;
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
