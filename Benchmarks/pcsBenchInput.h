// Inputs of the reconstruction benchmarks that run one method per process (pcsBench*.cxx), so
// that every method of a comparison gets the same cloud (fixed random seeds):
//   sphere:N            N uniform random points on the unit sphere
//   torus:N             N uniform random points on the torus of radii 1 and 0.35
//   sample:<file.off>:N N uniform random points on the triangles of an OFF mesh (area weighted)
//   <file.off>          the vertices of an OFF mesh
//   <file.xyz>          one point per line, x y z [nx ny nz]
// Each input also has normals (unit, or zero where none is known): the exact ones of the sphere
// and the torus, the normal of the sampled triangle, the mesh's vertex normals (sum of the
// normals of the incident triangles, i.e. area weighted, in the file's orientation), or the
// file's columns. A reference surface comes with the mesh inputs. Plus the process's memory.
#ifndef pcsBenchInput_h
#define pcsBenchInput_h

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace pcsbench
{
struct Input
{
  std::vector<double> XYZ;                     // 3 per point
  std::vector<double> Normals;                 // 3 per point (0 0 0: unknown)
  std::vector<double> ReferenceXYZ;            // the reference surface, when there is one
  std::vector<std::array<long, 3>> Reference;  // its triangles
  long Size() const { return static_cast<long>(this->XYZ.size() / 3); }
};

// Normal of the triangle a b c (right-hand rule), of length twice its area.
inline std::array<double, 3> TriangleNormal(const double* a, const double* b, const double* c)
{
  const double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  return { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
    e1[0] * e2[1] - e1[1] * e2[0] };
}

inline void Normalize(double* n)
{
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (length > 0.0)
  {
    n[0] /= length;
    n[1] /= length;
    n[2] /= length;
  }
}

// Vertices (and, when asked, triangles: polygons as fans) of an OFF file.
inline bool ReadOff(
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
    for (size_t j = 2; j < ids.size(); ++j)
    {
      tris->push_back({ ids[0], ids[j - 1], ids[j] });
    }
    ++f;
  }
  return nv > 0;
}

inline Input LoadInput(const std::string& spec)
{
  Input input;
  std::vector<double>& xyz = input.XYZ;
  std::vector<double>& normals = input.Normals;
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
        normals.insert(normals.end(), { p[0] / r, p[1] / r, p[2] / r });
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
        normals.insert(
          normals.end(), { std::cos(b) * std::cos(a), std::cos(b) * std::sin(a), std::sin(b) });
      }
    }
  }
  else if (spec.rfind("sample:", 0) == 0)
  {
    const size_t colon = spec.rfind(':');
    const std::string path = spec.substr(7, colon - 7);
    const long n = std::stol(spec.substr(colon + 1));
    std::vector<double>& v = input.ReferenceXYZ;
    std::vector<std::array<long, 3>>& t = input.Reference;
    if (!ReadOff(path, v, &t) || t.empty())
    {
      std::cerr << "cannot read the mesh " << path << std::endl;
      std::exit(2);
    }
    std::vector<double> cumulative(t.size());
    double total = 0.0;
    for (size_t i = 0; i < t.size(); ++i)
    {
      const auto cr = TriangleNormal(&v[3 * t[i][0]], &v[3 * t[i][1]], &v[3 * t[i][2]]);
      total += 0.5 * std::sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
      cumulative[i] = total;
    }
    for (long k = 0; k < n; ++k)
    {
      const size_t i = std::min<size_t>(
        std::lower_bound(cumulative.begin(), cumulative.end(), u(rng) * total) - cumulative.begin(),
        t.size() - 1);
      double r1 = u(rng), r2 = u(rng);
      if (r1 + r2 > 1.0)
      {
        r1 = 1.0 - r1;
        r2 = 1.0 - r2;
      }
      const double* a = &v[3 * t[i][0]];
      const double* b = &v[3 * t[i][1]];
      const double* c = &v[3 * t[i][2]];
      for (int j = 0; j < 3; ++j)
      {
        xyz.push_back(a[j] + r1 * (b[j] - a[j]) + r2 * (c[j] - a[j]));
      }
      auto normal = TriangleNormal(a, b, c);
      Normalize(normal.data());
      normals.insert(normals.end(), normal.begin(), normal.end());
    }
  }
  else if (spec.size() > 4 && spec.compare(spec.size() - 4, 4, ".off") == 0)
  {
    if (!ReadOff(spec, xyz, &input.Reference))
    {
      std::cerr << "cannot read " << spec << std::endl;
      std::exit(2);
    }
    input.ReferenceXYZ = xyz;
    normals.assign(xyz.size(), 0.0);
    for (const auto& t : input.Reference)
    {
      const auto normal = TriangleNormal(&xyz[3 * t[0]], &xyz[3 * t[1]], &xyz[3 * t[2]]);
      for (long id : t)
      {
        for (int j = 0; j < 3; ++j)
        {
          normals[3 * id + j] += normal[j];
        }
      }
    }
    for (size_t i = 0; i < normals.size(); i += 3)
    {
      Normalize(&normals[i]);
    }
  }
  else
  {
    std::ifstream in(spec);
    std::string line;
    while (std::getline(in, line))
    {
      std::istringstream s(line);
      double p[3], n[3] = { 0.0, 0.0, 0.0 };
      if (s >> p[0] >> p[1] >> p[2])
      {
        xyz.insert(xyz.end(), p, p + 3);
        if (!(s >> n[0] >> n[1] >> n[2]))
        {
          n[0] = n[1] = n[2] = 0.0;
        }
        normals.insert(normals.end(), n, n + 3);
      }
    }
  }
  if (xyz.empty())
  {
    std::cerr << "no points in " << spec << std::endl;
    std::exit(2);
  }
  return input;
}

// VmHWM (peak) or VmRSS (current) of this process, in megabytes.
inline double StatusMegabytes(const char* field)
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
} // namespace pcsbench

#endif
