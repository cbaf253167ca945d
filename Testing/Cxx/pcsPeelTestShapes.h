// Noise-free samples of closed surfaces whose shape is known, for the tests of
// vtkPerimeterPeelSurface (packed x, y, z coordinates; not part of the library).
#ifndef pcsPeelTestShapes_h
#define pcsPeelTestShapes_h

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <vector>

namespace pcstest
{
// Uniform random points on the unit sphere.
inline std::vector<double> SpherePoints(int n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<double> xyz;
  for (int i = 0; i < n; ++i)
  {
    const double p[3] = { g(rng), g(rng), g(rng) };
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    xyz.insert(xyz.end(), { p[0] / r, p[1] / r, p[2] / r });
  }
  return xyz;
}

// Area-uniform points on a torus (ring radius 1, tube radius 0.35) by rejection.
inline std::vector<double> TorusPoints(int n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xyz;
  while (static_cast<int>(xyz.size()) < 3 * n)
  {
    const double a = 2 * M_PI * u(rng), b = 2 * M_PI * u(rng);
    if (u(rng) > (1.0 + 0.35 * std::cos(b)) / 1.35)
    {
      continue;
    }
    const double r = 1.0 + 0.35 * std::cos(b);
    xyz.insert(xyz.end(), { r * std::cos(a), r * std::sin(a), 0.35 * std::sin(b) });
  }
  return xyz;
}

// Points on the torus of TorusPoints whose density grows as exp(rate * x) (about 25 times denser
// at x = 1.35 than at x = -1.35 for rate 1.2), by rejection.
inline std::vector<double> GradedTorusPoints(int n, unsigned seed, double rate)
{
  std::mt19937_64 rng(seed + 1000);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xyz;
  while (static_cast<int>(xyz.size()) < 3 * n)
  {
    const std::vector<double> p = TorusPoints(1, static_cast<unsigned>(rng()));
    if (u(rng) <= std::exp(rate * (p[0] - 1.35)))
    {
      xyz.insert(xyz.end(), p.begin(), p.end());
    }
  }
  return xyz;
}

// Fibonacci (golden spiral) points on the unit sphere.
inline std::vector<double> FibonacciSphere(int n)
{
  std::vector<double> xyz;
  for (int i = 0; i < n; ++i)
  {
    const double z = 1.0 - (2.0 * i + 1.0) / n, r = std::sqrt(1.0 - z * z);
    const double a = M_PI * (1.0 + std::sqrt(5.0)) * i;
    xyz.insert(xyz.end(), { r * std::cos(a), r * std::sin(a), z });
  }
  return xyz;
}

// A golden-ratio lattice on the torus of TorusPoints, area-uniform: the tube angle b solves (b +
// 0.35 sin b) / (2 pi) = u for evenly spaced u (Newton steps).
inline std::vector<double> FibonacciTorus(int n)
{
  const double golden = (std::sqrt(5.0) - 1.0) / 2.0;
  std::vector<double> xyz;
  for (int i = 0; i < n; ++i)
  {
    const double a = 2 * M_PI * std::fmod(i * golden, 1.0);
    const double u = 2 * M_PI * (i + 0.5) / n;
    double b = u;
    for (int k = 0; k < 50; ++k)
    {
      b -= (b + 0.35 * std::sin(b) - u) / (1.0 + 0.35 * std::cos(b));
    }
    const double r = 1.0 + 0.35 * std::cos(b);
    xyz.insert(xyz.end(), { r * std::cos(a), r * std::sin(a), 0.35 * std::sin(b) });
  }
  return xyz;
}

// A genus-2 surface: f = g^2 + z^2 - 0.1^2 = 0 with g = x^2 (1 - x^2) - y^2 (a tube around the
// figure-eight lemniscate of Gerono, smooth since 0.1 is no critical value of g). Random points of
// a box are projected onto it by Newton steps, then thinned to a blue-noise sample (no two points
// closer than `radius`, chosen for about n points): roughly uniform by area.
inline std::vector<double> Genus2Points(int n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(-1.2, 1.2), uy(-0.6, 0.6), uz(-0.15, 0.15);
  const double radius = 0.5 * std::sqrt(4.6 / n);
  std::map<std::array<long, 3>, std::vector<std::array<double, 3>>> grid;
  std::vector<double> xyz;
  for (int trial = 0; trial < 40 * n; ++trial)
  {
    double p[3] = { ux(rng), uy(rng), uz(rng) };
    double f = 1.0;
    for (int k = 0; k < 30; ++k)
    {
      const double g = p[0] * p[0] * (1 - p[0] * p[0]) - p[1] * p[1];
      f = g * g + p[2] * p[2] - 0.01;
      const double d[3] = { 2 * g * (2 * p[0] - 4 * p[0] * p[0] * p[0]), -4 * g * p[1], 2 * p[2] };
      const double d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      if (d2 < 1e-30)
      {
        break;
      }
      for (int j = 0; j < 3; ++j)
      {
        p[j] -= f / d2 * d[j];
      }
    }
    if (!(std::fabs(f) < 1e-12))
    {
      continue;
    }
    const std::array<long, 3> cell = { std::lround(std::floor(p[0] / radius)),
      std::lround(std::floor(p[1] / radius)), std::lround(std::floor(p[2] / radius)) };
    bool free = true;
    for (long dx = -1; dx <= 1 && free; ++dx)
    {
      for (long dy = -1; dy <= 1 && free; ++dy)
      {
        for (long dz = -1; dz <= 1 && free; ++dz)
        {
          auto it = grid.find({ cell[0] + dx, cell[1] + dy, cell[2] + dz });
          for (size_t k = 0; it != grid.end() && k < it->second.size() && free; ++k)
          {
            const auto& q = it->second[k];
            free = std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) >= radius;
          }
        }
      }
    }
    if (free)
    {
      grid[cell].push_back({ p[0], p[1], p[2] });
      xyz.insert(xyz.end(), { p[0], p[1], p[2] });
    }
  }
  return xyz;
}

// The closed profile (r, z) of a goblet (paper Fig. 1), from the axis under the foot round to the
// axis at the bottom of the cup: foot (radius 0.6, 0.12 thick at its edge, 0.3 at the stem), stem
// (radius 0.1), cup (outer radius 0.6 and inner radius 0.5 at the rim, z = 1.5; inner bottom at
// z = 0.9). Walls are 0.1-0.2 thick.
inline std::array<double, 2> GobletProfile(double s)
{
  // s in [0, 7): one unit per piece.
  const int piece = std::min(6, static_cast<int>(s));
  const double t = s - piece, q = 0.5 * M_PI * t;
  switch (piece)
  {
    case 0:
      return { 0.6 * t, 0.0 }; // under the foot
    case 1:
      return { 0.6, 0.12 * t }; // edge of the foot
    case 2:
      return { 0.6 - 0.5 * t, 0.12 + 0.18 * t }; // top of the foot (a cone)
    case 3:
      return { 0.1, 0.3 + 0.4 * t }; // stem
    case 4:
      return { 0.1 + 0.5 * std::sin(q), 0.7 + 0.8 * (1.0 - std::cos(q)) }; // outer wall
    case 5:
      return { 0.6 - 0.1 * t, 1.5 }; // rim
    default:
      return { 0.5 * std::cos(q), 0.9 + 0.6 * (1.0 - std::sin(q)) }; // inner wall to the axis
  }
}

// Random points on the goblet, uniform by area: the profile is cut into small pieces weighted by
// r x length (the area they sweep), a piece is drawn by weight, then a point along it and an angle.
inline std::vector<double> GobletPoints(int n, unsigned seed)
{
  const int pieces = 7 * 4000;
  std::vector<double> cumulative(pieces + 1, 0.0);
  for (int i = 0; i < pieces; ++i)
  {
    const auto a = GobletProfile(7.0 * i / pieces), b = GobletProfile(7.0 * (i + 1) / pieces);
    cumulative[i + 1] = cumulative[i] + 0.5 * (a[0] + b[0]) * std::hypot(b[0] - a[0], b[1] - a[1]);
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xyz;
  for (int k = 0; k < n; ++k)
  {
    const double w = u(rng) * cumulative[pieces];
    const int i = static_cast<int>(std::upper_bound(cumulative.begin(), cumulative.end(), w) -
                    cumulative.begin()) -
      1;
    const double f = (w - cumulative[i]) / std::max(1e-300, cumulative[i + 1] - cumulative[i]);
    const auto p = GobletProfile(7.0 * (i + std::min(1.0, std::max(0.0, f))) / pieces);
    const double angle = 2 * M_PI * u(rng);
    xyz.insert(xyz.end(), { p[0] * std::cos(angle), p[0] * std::sin(angle), p[1] });
  }
  return xyz;
}
} // namespace pcstest

#endif
