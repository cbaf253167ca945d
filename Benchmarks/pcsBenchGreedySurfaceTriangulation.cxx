// vtkGreedySurfaceTriangulation against CGAL's Advancing Front Surface Reconstruction on the same
// clouds (issue 7), one run per process (so that the peak memory is the method's own):
//   pcsBenchGreedySurfaceTriangulation <ours|ours-step2|log|cgal> <input> [mesh.off]
// ours: the filter's defaults; ours-step2: BridgeIslands and FillHoles off (the well-sampled
// regions after the umbrella test); log: vtkLocalOptimumGrowth with its defaults (issue 7 asks
// the greedy filter to be at least as good on clean surfaces); cgal:
// CGAL::advancing_front_surface_reconstruction with its defaults. Inputs: see pcsBenchInput.h
// (sphere:N, torus:N, sample:mesh.off:N, mesh.off, cloud.xyz), optionally prefixed:
//   damaged:<input>   two regions removed and three thinned tenfold, as in the reconstruction
//                     benchmark (run_reconstruction_benchmark.py, after paper 001 section 4):
//                     five distinct random points of the cloud are the centres, R = 8 % of the
//                     bounding box diagonal; the points within R of the first two are removed,
//                     those within R of the other three are kept with probability 1/10
//                     (damaged=<seed>:<input> chooses the random seed, default 7);
//   noisy:<input>     Gaussian noise of standard deviation 1/4 of the mean spacing along each
//                     axis (may precede damaged:).
// Prints one JSON line: method, input, points, seconds (the reconstruction alone), points per
// second, triangles, peak_mb, unused points; then, measured by vtkReconstructionQuality for every
// method alike: boundary edges and loops, non-manifold edges and vertices, components, genus (-1
// when not closed), Hausdorff distance over the mean spacing, and the completeness: the fraction
// of the vertices of the reference surface (the undamaged mesh of mesh inputs, else the clean
// cloud) within 2 mean spacings (of those vertices) of the mesh; and input_bound_2s, the
// fraction of those vertices within 2 mean spacings of some input point (what the damaged cloud
// still covers; a mesh goes beyond it only by long triangles across gaps or by added points).
// With a third argument the mesh is written as OFF over all input points. CGAL is used here
// only: the library never links it.
#include "pcsBenchInput.h"
#include "pcsBenchTriangles.h"

#include "vtkGreedySurfaceTriangulation.h"
#include "vtkLocalOptimumGrowth.h"
#include "vtkReconstructionQuality.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> MakeMesh(const std::vector<double>& xyz,
                                      const std::vector<std::array<long, 3>>& triangles)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const long n = static_cast<long>(xyz.size() / 3);
  points->SetNumberOfPoints(n);
  for (long i = 0; i < n; ++i)
  {
    points->SetPoint(i, &xyz[3 * i]);
  }
  vtkNew<vtkCellArray> cells;
  for (const auto& t : triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    cells->InsertNextCell(3, ids);
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(cells);
  return mesh;
}

double FieldValue(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array && array->GetNumberOfTuples() > 0 ? array->GetTuple1(0) : -1.0;
}

// Mean distance of the points to their nearest neighbour.
double MeanSpacing(const std::vector<double>& xyz)
{
  vtkSmartPointer<vtkPolyData> cloud = MakeMesh(xyz, {});
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(cloud);
  locator->BuildLocator();
  vtkNew<vtkIdList> ids;
  double sum = 0.0;
  long count = 0;
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    locator->FindClosestNPoints(2, &xyz[3 * i], ids);
    if (ids->GetNumberOfIds() == 2)
    {
      const vtkIdType j = ids->GetId(0) == i ? ids->GetId(1) : ids->GetId(0);
      double q[3];
      cloud->GetPoint(j, q);
      sum += std::sqrt(vtkMath::Distance2BetweenPoints(&xyz[3 * i], q));
      ++count;
    }
  }
  return count > 0 ? sum / count : 0.0;
}

// Two regions removed, three thinned tenfold (see the header comment).
void Damage(std::vector<double>& xyz, unsigned seed)
{
  const long n = static_cast<long>(xyz.size() / 3);
  double lo[3] = { xyz[0], xyz[1], xyz[2] }, hi[3] = { xyz[0], xyz[1], xyz[2] };
  for (long i = 0; i < n; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      lo[j] = std::min(lo[j], xyz[3 * i + j]);
      hi[j] = std::max(hi[j], xyz[3 * i + j]);
    }
  }
  const double radius = 0.08 * std::sqrt(vtkMath::Distance2BetweenPoints(lo, hi));
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> pick(0, n - 1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<long> centers;
  while (centers.size() < std::min<size_t>(5, n))
  {
    const long c = pick(rng);
    if (std::find(centers.begin(), centers.end(), c) == centers.end())
    {
      centers.push_back(c);
    }
  }
  std::vector<double> center(3 * centers.size());
  for (size_t k = 0; k < centers.size(); ++k)
  {
    std::copy_n(&xyz[3 * centers[k]], 3, &center[3 * k]);
  }
  std::vector<double> kept;
  for (long i = 0; i < n; ++i)
  {
    bool keep = true;
    for (size_t k = 0; k < centers.size(); ++k)
    {
      const double draw = u(rng);
      if (vtkMath::Distance2BetweenPoints(&xyz[3 * i], &center[3 * k]) < radius * radius)
      {
        keep = keep && k >= 2 && draw < 0.1;
      }
    }
    if (keep)
    {
      kept.insert(kept.end(), &xyz[3 * i], &xyz[3 * i] + 3);
    }
  }
  xyz.swap(kept);
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: pcsBenchGreedySurfaceTriangulation <ours|ours-step2|log|cgal> "
                 "[noisy:][damaged:]<sphere:N|torus:N|sample:mesh.off:N|mesh.off|cloud.xyz> "
                 "[mesh.off]"
              << std::endl;
    return 2;
  }
  // ours[:Name=value,...] sets numeric parameters of the filter (e.g. ours:MaximumBridgeLength=30).
  std::string method = argv[1];
  std::vector<std::pair<std::string, double>> settings;
  if (method.rfind("ours:", 0) == 0)
  {
    std::istringstream list(method.substr(5));
    std::string item;
    while (std::getline(list, item, ','))
    {
      const size_t equal = item.find('=');
      if (equal != std::string::npos)
      {
        settings.emplace_back(item.substr(0, equal), std::stod(item.substr(equal + 1)));
      }
    }
    method = "ours";
  }
  const std::string spec = argv[2];
  std::string base = spec;
  bool noisy = false, damaged = false;
  if (base.rfind("noisy:", 0) == 0)
  {
    noisy = true;
    base = base.substr(6);
  }
  unsigned seed = 7;
  if (base.rfind("damaged", 0) == 0 && base.find(':') != std::string::npos)
  {
    // damaged:<input> or damaged=<seed>:<input>
    const size_t colon = base.find(':');
    damaged = true;
    seed = base[7] == '=' ? static_cast<unsigned>(std::stoul(base.substr(8, colon - 8))) : seed;
    base = base.substr(colon + 1);
  }
  const pcsbench::Input input = pcsbench::LoadInput(base);
  // The reference: the undamaged surface of mesh inputs, else the clean cloud.
  vtkSmartPointer<vtkPolyData> reference = input.Reference.empty()
    ? MakeMesh(input.XYZ, {})
    : MakeMesh(input.ReferenceXYZ, input.Reference);
  std::vector<double> xyz = input.XYZ;
  if (noisy)
  {
    const double sigma = 0.25 * MeanSpacing(xyz);
    std::mt19937_64 rng(11);
    std::normal_distribution<double> g(0.0, sigma);
    for (double& c : xyz)
    {
      c += g(rng);
    }
  }
  if (damaged)
  {
    Damage(xyz, seed);
  }
  const long n = static_cast<long>(xyz.size() / 3);
  std::vector<std::array<long, 3>> triangles;
  // The mesh's points: the input points, then the points the method added (hole fairing).
  std::vector<double> meshXYZ = xyz;
  double seconds = 0.0;
  using Clock = std::chrono::steady_clock;
  if (method == "cgal")
  {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<Kernel::Point_3> points;
    points.reserve(n);
    for (long i = 0; i < n; ++i)
    {
      points.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    }
    std::vector<std::array<std::size_t, 3>> facets;
    const auto start = Clock::now();
    CGAL::advancing_front_surface_reconstruction(points.begin(), points.end(),
                                                 std::back_inserter(facets));
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
    for (const auto& f : facets)
    {
      triangles.push_back(
        { static_cast<long>(f[0]), static_cast<long>(f[1]), static_cast<long>(f[2]) });
    }
  }
  else if (method == "ours" || method == "ours-step2")
  {
    vtkSmartPointer<vtkPolyData> cloud = MakeMesh(xyz, {});
    vtkNew<vtkGreedySurfaceTriangulation> greedy;
    greedy->SetInputData(cloud);
    for (const auto& setting : settings)
    {
      const std::string& name = setting.first;
      const double value = setting.second;
      if (name == "MaximumBridgeLength")
        greedy->SetMaximumBridgeLength(value);
      else if (name == "MaximumNormalDeviation")
        greedy->SetMaximumNormalDeviation(value);
      else if (name == "NumberOfNeighbors")
        greedy->SetNumberOfNeighbors(static_cast<int>(value));
      else if (name == "CrossingTest")
        greedy->SetCrossingTest(static_cast<int>(value));
      else if (name == "MinimumIslandTriangles")
        greedy->SetMinimumIslandTriangles(static_cast<int>(value));
      else if (name == "BoundaryVectorRadius")
        greedy->SetBoundaryVectorRadius(value);
      else if (name == "MaximumHoleDiameter")
        greedy->SetMaximumHoleDiameter(value);
      else if (name == "InsertLostPoints")
        greedy->SetInsertLostPoints(value != 0.0);
      else if (name == "FairHoleFills")
        greedy->SetFairHoleFills(value != 0.0);
      else if (name == "CapOpenEnds")
        greedy->SetCapOpenEnds(value != 0.0);
      else if (name == "GrowRegions")
        greedy->SetGrowRegions(value != 0.0);
      else
      {
        std::cerr << "unknown parameter " << name << std::endl;
        return 2;
      }
    }
    if (method == "ours-step2")
    {
      greedy->BridgeIslandsOff();
      greedy->FillHolesOff();
    }
    const auto start = Clock::now();
    greedy->Update();
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
    vtkPoints* outPoints = greedy->GetOutput()->GetPoints();
    for (vtkIdType i = n; outPoints && i < outPoints->GetNumberOfPoints(); ++i)
    {
      double p[3];
      outPoints->GetPoint(i, p);
      meshXYZ.insert(meshXYZ.end(), p, p + 3);
    }
    pcsbench::AppendTriangles(greedy->GetOutput(), triangles);
  }
  else if (method == "log")
  {
    vtkSmartPointer<vtkPolyData> cloud = MakeMesh(xyz, {});
    vtkNew<vtkLocalOptimumGrowth> growth;
    growth->SetInputData(cloud);
    const auto start = Clock::now();
    growth->Update();
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
    pcsbench::AppendTriangles(growth->GetOutput(), triangles);
  }
  else
  {
    std::cerr << "unknown method " << method << std::endl;
    return 2;
  }
  const double peak = pcsbench::StatusMegabytes("VmHWM");

  // The same quality measures for every method: the mesh itself, then the reference's vertices
  // measured against it (their distance to the mesh's triangles).
  vtkSmartPointer<vtkPolyData> mesh = MakeMesh(meshXYZ, triangles);
  const long meshPoints = static_cast<long>(meshXYZ.size() / 3);
  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputData(mesh);
  quality->SetReferenceData(reference);
  quality->Update();
  vtkPolyData* measured = quality->GetOutput();
  // The reference's spacing: of its vertices (its used points when it is a surface).
  const double spacing =
    input.Reference.empty() ? MeanSpacing(input.XYZ) : MeanSpacing(input.ReferenceXYZ);
  // The input bound: the fraction of the reference vertices within 2 spacings of some point of
  // the (damaged, noisy) input cloud, what the cloud itself still covers. A method that adds no
  // points goes beyond it only through long triangles spanning gaps of the cloud.
  double inputBound = 0.0;
  {
    vtkSmartPointer<vtkPolyData> cloud = MakeMesh(xyz, {});
    vtkNew<vtkStaticPointLocator> locator;
    locator->SetDataSet(cloud);
    locator->BuildLocator();
    vtkPoints* refPoints = reference->GetPoints();
    long within = 0;
    const vtkIdType m = refPoints ? refPoints->GetNumberOfPoints() : 0;
    for (vtkIdType i = 0; i < m && n > 0; ++i)
    {
      double p[3], q[3];
      refPoints->GetPoint(i, p);
      cloud->GetPoint(locator->FindClosestPoint(p), q);
      within += vtkMath::Distance2BetweenPoints(p, q) <= 4.0 * spacing * spacing ? 1 : 0;
    }
    inputBound = m > 0 ? static_cast<double>(within) / m : 0.0;
  }
  double completeness = 0.0;
  if (!triangles.empty())
  {
    vtkNew<vtkReconstructionQuality> back;
    back->SetInputData(reference);
    back->SetReferenceData(mesh);
    back->Update();
    vtkPolyData* out = back->GetOutput();
    vtkDataArray* distance = out->GetPointData()->GetArray("DistanceToReference");
    long within = 0, counted = 0;
    for (vtkIdType i = 0; i < distance->GetNumberOfTuples(); ++i)
    {
      const double d = distance->GetTuple1(i);
      if (!std::isnan(d))
      {
        ++counted;
        within += d <= 2.0 * spacing ? 1 : 0;
      }
    }
    completeness = counted > 0 ? static_cast<double>(within) / counted : 0.0;
  }
  if (argc > 3)
  {
    std::ofstream out(argv[3]);
    out.precision(17);
    out << "OFF\n" << meshPoints << " " << triangles.size() << " 0\n";
    for (long i = 0; i < meshPoints; ++i)
    {
      out << meshXYZ[3 * i] << " " << meshXYZ[3 * i + 1] << " " << meshXYZ[3 * i + 2] << "\n";
    }
    for (const auto& t : triangles)
    {
      out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
    }
  }
  const long used = static_cast<long>(FieldValue(measured, "NumberOfUsedPoints"));
  std::printf("{\"method\": \"%s\", \"input\": \"%s\", \"points\": %ld, \"seconds\": %.4f, "
              "\"points_per_second\": %.0f, \"triangles\": %zu, \"peak_mb\": %.1f, "
              "\"unused\": %ld, \"added\": %ld, \"boundary_edges\": %ld, \"boundary_loops\": %ld, "
              "\"non_manifold_edges\": %ld, \"non_manifold_vertices\": %ld, \"components\": %ld, "
              "\"genus\": %ld, \"hausdorff_over_spacing\": %.3f, \"completeness_2s\": %.5f, "
              "\"input_bound_2s\": %.5f}\n",
    method.c_str(), spec.c_str(), n, seconds, seconds > 0 ? n / seconds : 0.0, triangles.size(),
    peak, meshPoints - used, meshPoints - n,
    static_cast<long>(FieldValue(measured, "NumberOfBoundaryEdges")),
    static_cast<long>(FieldValue(measured, "NumberOfBoundaryLoops")),
    static_cast<long>(FieldValue(measured, "NumberOfNonManifoldEdges")),
    static_cast<long>(FieldValue(measured, "NumberOfNonManifoldVertices")),
    static_cast<long>(FieldValue(measured, "NumberOfConnectedComponents")),
    static_cast<long>(FieldValue(measured, "Genus")), FieldValue(measured, "HausdorffOverSpacing"),
    completeness, inputBound);
  return 0;
}
