// vtkCDTAdvancingFront against CGAL's Advancing Front Surface Reconstruction, one run per process
// (so that the peak memory is the method's own):
//   pcsBenchCDTAdvancingFront <ours|ours-normals|cgal> <input> [mesh.off]
// ours: normals estimated by the filter (vtkPCANormalEstimation); ours-normals: the input's
// normals (the mesh's vertex normals, the exact normals of the sphere and torus, see
// pcsBenchInput.h); cgal: CGAL::advancing_front_surface_reconstruction with its defaults (it
// takes no normals). Inputs: see pcsBenchInput.h (sphere:N, torus:N, sample:mesh.off:N, mesh.off,
// cloud.xyz), and noise:F:<input>: that input with Gaussian noise of standard deviation F mean
// spacings added to every coordinate (fixed seed; the normals and the reference surface stay the
// noise-free ones, as in run_reconstruction_benchmark.py's noisy variants).
// Prints one JSON line: method, input, points, seconds (the reconstruction alone, wall clock),
// cpu_seconds (the CPU time of the process, all threads, over the same span: steadier than the
// wall clock on a loaded machine), triangles,
// peak_mb and baseline_mb (VmHWM after the reconstruction, and VmRSS before it, from
// /proc/self/status), unused points and boundary edges; then, measured after the peak by
// vtkReconstructionQuality for every method alike, non-manifold edges and vertices, coverage,
// components, genus (-1 when not closed) and the Hausdorff distance in units of the mean spacing
// (to the reference surface of mesh inputs, else to the cloud). With a third argument the mesh is
// written as OFF over all input points. With PCS_BENCH_NO_QUALITY=1 in the environment only the
// reconstruction runs (for profiling and for comparing outputs): the JSON line stops at the
// triangle count and the third argument, if any, receives the triangles, one "i j k" per line.
// With PCS_BENCH_WRITE_INPUT=<file.xyz> the input cloud is also written there, one point per
// line, "x y z nx ny nz" (the normals of ours-normals; an input for this benchmark and others).
// CGAL is used here only: the library never links it.
#include "pcsBenchInput.h"
#include "pcsBenchTriangles.h"

#include "vtkCDTAdvancingFront.h"
#include "vtkReconstructionQuality.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> MakeMesh(
  const std::vector<double>& xyz, const std::vector<std::array<long, 3>>& triangles)
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

// Gaussian noise of `fraction` mean spacings (mean distance to the nearest other point).
void AddNoise(std::vector<double>& xyz, double fraction)
{
  const long n = static_cast<long>(xyz.size() / 3);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (long i = 0; i < n; ++i)
  {
    points->SetPoint(i, &xyz[3 * i]);
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(cloud);
  locator->BuildLocator();
  vtkNew<vtkIdList> closest;
  double sum = 0.0;
  long count = 0;
  for (long i = 0; i < n; ++i)
  {
    locator->FindClosestNPoints(2, &xyz[3 * i], closest);
    for (vtkIdType k = 0; k < closest->GetNumberOfIds(); ++k)
    {
      const vtkIdType j = closest->GetId(k);
      if (j != i)
      {
        const double d[3] = { xyz[3 * j] - xyz[3 * i], xyz[3 * j + 1] - xyz[3 * i + 1],
          xyz[3 * j + 2] - xyz[3 * i + 2] };
        sum += std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        ++count;
        break;
      }
    }
  }
  const double spacing = count > 0 ? sum / static_cast<double>(count) : 0.0;
  std::mt19937_64 rng(8);
  std::normal_distribution<double> g(0.0, fraction * spacing);
  for (double& c : xyz)
  {
    c += g(rng);
  }
}

double FieldValue(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array && array->GetNumberOfTuples() > 0 ? array->GetTuple1(0) : -1.0;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: pcsBenchCDTAdvancingFront <ours|ours-normals|cgal> <sphere:N|torus:N|"
                 "sample:mesh.off:N|mesh.off|cloud.xyz> [mesh.off]"
              << std::endl;
    return 2;
  }
  const std::string method = argv[1], spec = argv[2];
  // PCS_BENCH_NO_QUALITY=1: the reconstruction alone, no quality measures.
  const char* noQuality = std::getenv("PCS_BENCH_NO_QUALITY");
  double noise = 0.0;
  std::string source = spec;
  if (spec.rfind("noise:", 0) == 0 && spec.find(':', 6) != std::string::npos)
  {
    const size_t colon = spec.find(':', 6);
    noise = std::stod(spec.substr(6, colon - 6));
    source = spec.substr(colon + 1);
  }
  pcsbench::Input input = pcsbench::LoadInput(source);
  if (noise > 0.0)
  {
    AddNoise(input.XYZ, noise);
  }
  const std::vector<double>& xyz = input.XYZ;
  const long n = input.Size();
  if (const char* inputPath = std::getenv("PCS_BENCH_WRITE_INPUT"))
  {
    std::ofstream out(inputPath);
    out.precision(17);
    for (long i = 0; i < n; ++i)
    {
      out << xyz[3 * i] << " " << xyz[3 * i + 1] << " " << xyz[3 * i + 2] << " "
          << input.Normals[3 * i] << " " << input.Normals[3 * i + 1] << " "
          << input.Normals[3 * i + 2] << "\n";
    }
  }
  std::vector<std::array<long, 3>> triangles;
  double seconds = 0.0, cpuSeconds = 0.0, baseline = 0.0;
  auto cpuNow = []()
  {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  };
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
    baseline = pcsbench::StatusMegabytes("VmRSS");
    const double cpuStart = cpuNow();
    const auto start = Clock::now();
    CGAL::advancing_front_surface_reconstruction(
      points.begin(), points.end(), std::back_inserter(facets));
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
    cpuSeconds = cpuNow() - cpuStart;
    for (const auto& f : facets)
    {
      triangles.push_back(
        { static_cast<long>(f[0]), static_cast<long>(f[1]), static_cast<long>(f[2]) });
    }
  }
  else if (method == "ours" || method == "ours-normals")
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(n);
    for (long i = 0; i < n; ++i)
    {
      points->SetPoint(i, &xyz[3 * i]);
    }
    vtkNew<vtkPolyData> cloud;
    cloud->SetPoints(points);
    if (method == "ours-normals")
    {
      vtkNew<vtkDoubleArray> normals;
      normals->SetName("Normals");
      normals->SetNumberOfComponents(3);
      normals->SetNumberOfTuples(n);
      for (long i = 0; i < n; ++i)
      {
        normals->SetTuple(i, &input.Normals[3 * i]);
      }
      cloud->GetPointData()->SetNormals(normals);
    }
    vtkNew<vtkCDTAdvancingFront> front;
    front->SetInputData(cloud);
    baseline = pcsbench::StatusMegabytes("VmRSS");
    const double cpuStart = cpuNow();
    const auto start = Clock::now();
    front->Update();
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
    cpuSeconds = cpuNow() - cpuStart;
    pcsbench::AppendTriangles(front->GetOutput(), triangles);
  }
  else
  {
    std::cerr << "unknown method " << method << std::endl;
    return 2;
  }
  const double peak = pcsbench::StatusMegabytes("VmHWM");
  if (noQuality && std::string(noQuality) == "1")
  {
    std::printf("{\"method\": \"%s\", \"input\": \"%s\", \"points\": %ld, \"seconds\": %.4f, "
                "\"cpu_seconds\": %.4f, \"triangles\": %zu}\n",
      method.c_str(), spec.c_str(), n, seconds, cpuSeconds, triangles.size());
    if (argc > 3)
    {
      std::ofstream out(argv[3]);
      for (const auto& t : triangles)
      {
        out << t[0] << " " << t[1] << " " << t[2] << "\n";
      }
    }
    return 0;
  }

  // The same quality measures for every method.
  vtkSmartPointer<vtkPolyData> mesh = MakeMesh(xyz, triangles);
  vtkSmartPointer<vtkPolyData> reference = input.Reference.empty()
    ? MakeMesh(xyz, {})
    : MakeMesh(input.ReferenceXYZ, input.Reference);
  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputData(mesh);
  quality->SetReferenceData(reference);
  quality->Update();
  vtkPolyData* measured = quality->GetOutput();
  if (argc > 3)
  {
    std::ofstream out(argv[3]);
    out.precision(17);
    out << "OFF\n" << n << " " << triangles.size() << " 0\n";
    for (long i = 0; i < n; ++i)
    {
      out << xyz[3 * i] << " " << xyz[3 * i + 1] << " " << xyz[3 * i + 2] << "\n";
    }
    for (const auto& t : triangles)
    {
      out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
    }
  }
  const long used = static_cast<long>(FieldValue(measured, "NumberOfUsedPoints"));
  std::printf("{\"method\": \"%s\", \"input\": \"%s\", \"points\": %ld, \"seconds\": %.4f, "
              "\"cpu_seconds\": %.4f, \"triangles\": %zu, \"peak_mb\": %.1f, "
              "\"baseline_mb\": %.1f, \"unused\": %ld, "
              "\"boundary_edges\": %ld, \"non_manifold_edges\": %ld, "
              "\"non_manifold_vertices\": %ld, \"coverage\": %.5f, \"components\": %ld, "
              "\"genus\": %ld, \"hausdorff_over_spacing\": %.3f, \"reference\": \"%s\"}\n",
    method.c_str(), spec.c_str(), n, seconds, cpuSeconds, triangles.size(), peak, baseline,
    n - used,
    static_cast<long>(FieldValue(measured, "NumberOfBoundaryEdges")),
    static_cast<long>(FieldValue(measured, "NumberOfNonManifoldEdges")),
    static_cast<long>(FieldValue(measured, "NumberOfNonManifoldVertices")),
    FieldValue(measured, "Coverage"),
    static_cast<long>(FieldValue(measured, "NumberOfConnectedComponents")),
    static_cast<long>(FieldValue(measured, "Genus")),
    FieldValue(measured, "HausdorffOverSpacing"), input.Reference.empty() ? "cloud" : "surface");
  return 0;
}
