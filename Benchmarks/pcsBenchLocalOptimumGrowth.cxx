// vtkLocalOptimumGrowth against CGAL's Advancing Front Surface Reconstruction, one run per
// process (so that the peak memory is the method's own):
//   pcsBenchLocalOptimumGrowth <ours|cgal> <input> [mesh.off]
// Inputs (fixed random seeds, so both methods get the same cloud):
//   sphere:N            N uniform random points on the unit sphere
//   torus:N             N uniform random points on the torus of radii 1 and 0.35
//   sample:<file.off>:N N uniform random points on the triangles of an OFF mesh (area weighted)
//   <file.xyz|file.off> the points of a file (OFF: its vertices)
// Prints one JSON line: method, input, points, seconds (wall clock of the reconstruction alone),
// cpu_seconds (the process's CPU time over the same span, std::clock: the figure to compare on a
// shared machine), triangles,
// peak_mb and baseline_mb (VmHWM, and VmRSS before the reconstruction, from /proc/self/status),
// and for ours the unused points, boundary edges and seeds. With a third argument the mesh is
// written as OFF over all input points (vertex i is input point i). CGAL is used here only: the
// library never links it.
#include "pcsBenchInput.h"
#include "pcsBenchTriangles.h"

#include "vtkLocalOptimumGrowth.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

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

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: pcsBenchLocalOptimumGrowth <ours|cgal> <sphere:N|torus:N|"
                 "sample:mesh.off:N|file.xyz|file.off> [mesh.off]"
              << std::endl;
    return 2;
  }
  const std::string method = argv[1], input = argv[2];
  // The cloud alone (its normals and reference surface are not used here).
  const std::vector<double> xyz = std::move(pcsbench::LoadInput(input).XYZ);
  const long n = static_cast<long>(xyz.size() / 3);
  std::vector<std::array<long, 3>> triangles;
  std::string extra;
  double seconds = 0.0, cpuSeconds = 0.0, baseline = 0.0;
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
    const auto start = Clock::now();
    const std::clock_t cpuStart = std::clock();
    CGAL::advancing_front_surface_reconstruction(
      points.begin(), points.end(), std::back_inserter(facets));
    cpuSeconds = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
    for (const auto& f : facets)
    {
      triangles.push_back(
        { static_cast<long>(f[0]), static_cast<long>(f[1]), static_cast<long>(f[2]) });
    }
  }
  else if (method == "ours")
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
    vtkNew<vtkLocalOptimumGrowth> growth;
    growth->SetInputData(cloud);
    baseline = pcsbench::StatusMegabytes("VmRSS");
    const auto start = Clock::now();
    const std::clock_t cpuStart = std::clock();
    growth->Update();
    cpuSeconds = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
    pcsbench::AppendTriangles(growth->GetOutput(), triangles);
    std::ostringstream s;
    s << ", \"unused\": " << growth->GetNumberOfUnusedPoints()
      << ", \"boundary_edges\": " << growth->GetNumberOfBoundaryEdges()
      << ", \"seeds\": " << growth->GetNumberOfSeeds();
    extra = s.str();
  }
  else
  {
    std::cerr << "unknown method " << method << std::endl;
    return 2;
  }
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
  std::printf("{\"method\": \"%s\", \"input\": \"%s\", \"points\": %ld, \"seconds\": %.4f, "
              "\"cpu_seconds\": %.4f, \"triangles\": %zu, \"peak_mb\": %.1f, "
              "\"baseline_mb\": %.1f%s}\n",
    method.c_str(), input.c_str(), n, seconds, cpuSeconds, triangles.size(),
    pcsbench::StatusMegabytes("VmHWM"), baseline, extra.c_str());
  return 0;
}
