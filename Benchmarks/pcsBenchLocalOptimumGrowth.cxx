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

namespace
{
// Vertices (and, when asked, triangles) of an OFF file.
bool ReadOff(
  const std::string& path, std::vector<double>& xyz, std::vector<std::array<long, 3>>* tris)
{
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line) || line.compare(0, 3, "OFF") != 0)
  {
    return false;
  }
  long nv = -1, nf = 0, ne = 0;
  while (nv < 0 && std::getline(in, line))
  {
    if (!line.empty() && line[0] != '#' && !(std::istringstream(line) >> nv >> nf >> ne))
    {
      nv = -1;
    }
  }
  for (long i = 0; i < nv && std::getline(in, line);)
  {
    double p[3];
    if (std::istringstream(line) >> p[0] >> p[1] >> p[2])
    {
      xyz.insert(xyz.end(), p, p + 3);
      ++i;
    }
  }
  for (long f = 0; tris && f < nf && std::getline(in, line);)
  {
    std::istringstream s(line);
    long k;
    std::vector<long> ids;
    if (!(s >> k))
    {
      continue;
    }
    for (long j = 0, id; j < k && s >> id; ++j)
    {
      ids.push_back(id);
    }
    for (size_t j = 2; j < ids.size(); ++j) // fan of a polygon
    {
      tris->push_back({ ids[0], ids[j - 1], ids[j] });
    }
    ++f;
  }
  return nv > 0;
}

std::vector<double> LoadInput(const std::string& spec)
{
  std::vector<double> xyz;
  std::mt19937_64 rng(20130720);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  if (spec.rfind("sphere:", 0) == 0)
  {
    const long n = std::stol(spec.substr(7));
    std::normal_distribution<double> g(0.0, 1.0);
    while (static_cast<long>(xyz.size()) < 3 * n)
    {
      const double p[3] = { g(rng), g(rng), g(rng) };
      const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      if (r > 0)
      {
        xyz.insert(xyz.end(), { p[0] / r, p[1] / r, p[2] / r });
      }
    }
  }
  else if (spec.rfind("torus:", 0) == 0)
  {
    const long n = std::stol(spec.substr(6));
    const double big = 1.0, small = 0.35;
    while (static_cast<long>(xyz.size()) < 3 * n)
    {
      const double a = 2 * M_PI * u(rng), b = 2 * M_PI * u(rng);
      if (u(rng) * (big + small) <= big + small * std::cos(b))
      {
        xyz.insert(xyz.end(),
          { (big + small * std::cos(b)) * std::cos(a), (big + small * std::cos(b)) * std::sin(a),
            small * std::sin(b) });
      }
    }
  }
  else if (spec.rfind("sample:", 0) == 0)
  {
    const size_t colon = spec.rfind(':');
    const std::string path = spec.substr(7, colon - 7);
    const long n = std::stol(spec.substr(colon + 1));
    std::vector<double> v;
    std::vector<std::array<long, 3>> t;
    if (!ReadOff(path, v, &t) || t.empty())
    {
      std::cerr << "cannot read the mesh " << path << std::endl;
      std::exit(2);
    }
    std::vector<double> cumulative(t.size());
    double total = 0.0;
    for (size_t i = 0; i < t.size(); ++i)
    {
      const double* a = &v[3 * t[i][0]];
      const double* b = &v[3 * t[i][1]];
      const double* c = &v[3 * t[i][2]];
      const double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
      const double e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
      const double cr[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0] };
      total += 0.5 * std::sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
      cumulative[i] = total;
    }
    for (long k = 0; k < n; ++k)
    {
      const size_t i =
        std::lower_bound(cumulative.begin(), cumulative.end(), u(rng) * total) - cumulative.begin();
      double r1 = u(rng), r2 = u(rng);
      if (r1 + r2 > 1.0)
      {
        r1 = 1.0 - r1;
        r2 = 1.0 - r2;
      }
      const double* a = &v[3 * t[std::min(i, t.size() - 1)][0]];
      const double* b = &v[3 * t[std::min(i, t.size() - 1)][1]];
      const double* c = &v[3 * t[std::min(i, t.size() - 1)][2]];
      for (int j = 0; j < 3; ++j)
      {
        xyz.push_back(a[j] + r1 * (b[j] - a[j]) + r2 * (c[j] - a[j]));
      }
    }
  }
  else if (spec.size() > 4 && spec.compare(spec.size() - 4, 4, ".off") == 0)
  {
    if (!ReadOff(spec, xyz, nullptr))
    {
      std::cerr << "cannot read " << spec << std::endl;
      std::exit(2);
    }
  }
  else
  {
    std::ifstream in(spec);
    std::string line;
    while (std::getline(in, line))
    {
      double p[3];
      if (std::istringstream(line) >> p[0] >> p[1] >> p[2])
      {
        xyz.insert(xyz.end(), p, p + 3);
      }
    }
  }
  if (xyz.empty())
  {
    std::cerr << "no points in " << spec << std::endl;
    std::exit(2);
  }
  return xyz;
}

// VmHWM (peak) or VmRSS (current) of this process, in megabytes.
double StatusMegabytes(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::string prefix = std::string(field) + ":";
  while (std::getline(status, line))
  {
    if (line.compare(0, prefix.size(), prefix) == 0)
    {
      return std::stod(line.substr(prefix.size())) / 1024.0;
    }
  }
  return 0.0;
}
} // namespace

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
  const std::vector<double> xyz = LoadInput(input);
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
    baseline = StatusMegabytes("VmRSS");
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
    baseline = StatusMegabytes("VmRSS");
    const auto start = Clock::now();
    const std::clock_t cpuStart = std::clock();
    growth->Update();
    cpuSeconds = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
    auto iter = vtk::TakeSmartPointer(growth->GetOutput()->GetPolys()->NewIterator());
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
    {
      vtkIdType npts;
      const vtkIdType* pts;
      iter->GetCurrentCell(npts, pts);
      triangles.push_back(
        { static_cast<long>(pts[0]), static_cast<long>(pts[1]), static_cast<long>(pts[2]) });
    }
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
    StatusMegabytes("VmHWM"), baseline, extra.c_str());
  return 0;
}
