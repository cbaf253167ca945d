// One Delaunay construction per process, timed, with the process's peak memory:
//   pcsBenchDelaunay <ours|kernel|vtk|cgal> <uniform:N | surface:N | file.xyz | file.off>
// ours: the vtkIncrementalDelaunay3D filter (tetrahedra output on); kernel: its triangulation
// kernel alone (no VTK arrays).
// prints one JSON line. One method per process, so getrusage's peak RSS is the method's own.
#include "vtkIncrementalDelaunay3D.h"

#include "pcsDelaunay3D.h"

#include "vtkDelaunay3D.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
std::vector<double> LoadInput(const std::string& spec)
{
  std::vector<double> xyz;
  if (spec.rfind("uniform:", 0) == 0 || spec.rfind("surface:", 0) == 0)
  {
    const long n = std::stol(spec.substr(8));
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> noise(0.0, 0.001);
    for (long i = 0; i < n; ++i)
    {
      if (spec[0] == 'u')
      {
        xyz.insert(xyz.end(), { u(rng), u(rng), u(rng) });
      }
      else // noisy torus: a large surface-like cloud
      {
        const double a = 2 * M_PI * u(rng), b = 2 * M_PI * u(rng), r = 0.3 + noise(rng);
        xyz.insert(xyz.end(),
          { (1 + r * std::cos(b)) * std::cos(a), (1 + r * std::cos(b)) * std::sin(a),
            r * std::sin(b) });
      }
    }
    return xyz;
  }
  std::ifstream in(spec);
  if (!in)
  {
    std::cerr << "cannot read " << spec << std::endl;
    std::exit(2);
  }
  std::string line;
  if (spec.size() > 4 && spec.compare(spec.size() - 4, 4, ".off") == 0)
  {
    std::getline(in, line); // OFF
    long nv = 0, nf = 0, ne = 0;
    while (std::getline(in, line))
    {
      if (!line.empty() && line[0] != '#')
      {
        std::istringstream(line) >> nv >> nf >> ne;
        break;
      }
    }
    for (long i = 0; i < nv && std::getline(in, line); ++i)
    {
      double x, y, z;
      std::istringstream(line) >> x >> y >> z;
      xyz.insert(xyz.end(), { x, y, z });
    }
    return xyz;
  }
  while (std::getline(in, line))
  {
    std::istringstream s(line);
    double x, y, z;
    if (s >> x >> y >> z)
    {
      xyz.insert(xyz.end(), { x, y, z });
    }
  }
  return xyz;
}

double PeakMegabytes()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0; // kilobytes on Linux
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: pcsBenchDelaunay <ours|vtk|cgal> <uniform:N|surface:N|file>" << std::endl;
    return 2;
  }
  const std::string method = argv[1], input = argv[2];
  const std::vector<double> xyz = LoadInput(input);
  const long n = static_cast<long>(xyz.size() / 3);
  long cells = 0;
  double seconds = 0.0;
  using Clock = std::chrono::steady_clock;

  if (method == "kernel")
  {
    std::vector<int32_t> ids(n);
    for (long i = 0; i < n; ++i)
    {
      ids[i] = static_cast<int32_t>(i);
    }
    pcs::Delaunay3D dt;
    const auto start = Clock::now();
    dt.Triangulate(xyz.data(), ids);
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
    for (int64_t c = 0; c < dt.GetNumberOfCells(); ++c)
    {
      cells += dt.IsInfinite(c) ? 0 : 1;
    }
  }
  else if (method == "cgal")
  {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<K::Point_3> points;
    points.reserve(n);
    for (long i = 0; i < n; ++i)
    {
      points.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    }
    const auto start = Clock::now();
    CGAL::Delaunay_triangulation_3<K> dt(points.begin(), points.end());
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
    cells = static_cast<long>(dt.number_of_finite_cells());
  }
  else
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
    if (method == "ours")
    {
      vtkNew<vtkIncrementalDelaunay3D> delaunay;
      delaunay->SetInputData(cloud);
      const auto start = Clock::now();
      delaunay->Update();
      seconds = std::chrono::duration<double>(Clock::now() - start).count();
      cells = delaunay->GetTetrahedraOutput()->GetNumberOfCells();
    }
    else if (method == "vtk")
    {
      vtkNew<vtkDelaunay3D> delaunay;
      delaunay->SetInputData(cloud);
      const auto start = Clock::now();
      delaunay->Update();
      seconds = std::chrono::duration<double>(Clock::now() - start).count();
      cells = delaunay->GetOutput()->GetNumberOfCells();
    }
    else
    {
      std::cerr << "unknown method " << method << std::endl;
      return 2;
    }
  }
  std::printf("{\"method\": \"%s\", \"input\": \"%s\", \"points\": %ld, \"seconds\": %.4f, "
              "\"tetrahedra\": %ld, \"peak_mb\": %.1f}\n",
    method.c_str(), input.c_str(), n, seconds, cells, PeakMegabytes());
  return 0;
}
