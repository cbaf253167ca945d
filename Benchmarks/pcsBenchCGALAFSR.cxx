// Peer of the reconstruction benchmark: CGAL's Advancing Front Surface Reconstruction
// (CGAL/Advancing_front_surface_reconstruction.h, default parameters) on a point file.
//
//   pcsBenchCGALAFSR <cloud.xyz> [mesh.off]
//
// The cloud file holds one point per line (x y z, further columns ignored). Prints one JSON line
// (points, seconds of the reconstruction alone as wall-clock and as processor time, triangles,
// peak resident megabytes of the process and its resident megabytes just before the
// reconstruction, from /proc/self/status) and, when asked, writes the mesh as OFF over ALL input
// points (vertex i is input point i, so the mesh can be compared point by point with the other
// methods').
#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

// A field of /proc/self/status in megabytes: VmRSS (current resident set) or VmHWM (its peak).
// VmHWM belongs to this process's address space; getrusage's ru_maxrss would keep the peak of
// the parent process across exec.
double StatusMegabytes(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::string prefix = std::string(field) + ":";
  while (std::getline(status, line))
  {
    if (line.compare(0, prefix.size(), prefix) == 0)
    {
      return std::stod(line.substr(prefix.size())) / 1024.0; // kB
    }
  }
  return 0.0;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: pcsBenchCGALAFSR <cloud.xyz> [mesh.off]" << std::endl;
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in)
  {
    std::cerr << "cannot read " << argv[1] << std::endl;
    return 2;
  }
  std::vector<Point> points;
  std::string line;
  while (std::getline(in, line))
  {
    std::istringstream s(line);
    double x, y, z;
    if (s >> x >> y >> z)
    {
      points.emplace_back(x, y, z);
    }
  }

  std::vector<std::array<std::size_t, 3>> facets;
  const double baseline = StatusMegabytes("VmRSS");
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpuStart = std::clock();
  CGAL::advancing_front_surface_reconstruction(
    points.begin(), points.end(), std::back_inserter(facets));
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpuSeconds = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;

  if (argc > 2)
  {
    std::ofstream out(argv[2]);
    out.precision(17);
    out << "OFF\n" << points.size() << " " << facets.size() << " 0\n";
    for (const Point& p : points)
    {
      out << p.x() << " " << p.y() << " " << p.z() << "\n";
    }
    for (const auto& f : facets)
    {
      out << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
    }
  }
  std::printf("{\"method\": \"cgal-afsr\", \"points\": %zu, \"seconds\": %.4f, \"cpu_seconds\": %.4f, "
              "\"triangles\": %zu, \"peak_mb\": %.1f, \"baseline_mb\": %.1f}\n",
    points.size(), seconds, cpuSeconds, facets.size(), StatusMegabytes("VmHWM"), baseline);
  return 0;
}
