// Tests of the hole triangulation kernel (Filters/Kernel/pcsHoleFilling): the exact polygon
// tests, the 2D greedy triangulation and the hole filler of paper 001, steps 5 and 6. Every
// expected value is known by construction: simplicity and point positions of hand-made polygons,
// the triangle count of a triangulated polygon with m interior points (n + 2m - 2), its area
// (the polygon's), its edge structure (loop edges once, interior edges twice in opposite
// directions), the greedy choice of the shorter diagonal, and the surface a folded hole comes
// from.
#include "pcsHoleFilling.h"
#include "pcsSurfaceMesh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace
{
int Failures = 0;

#define CHECK(condition, ...)                                                                      \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::printf("FAILED line %d: %s -- ", __LINE__, #condition);                                 \
      std::printf(__VA_ARGS__);                                                                    \
      std::printf("\n");                                                                           \
      ++Failures;                                                                                  \
    }                                                                                              \
  } while (false)

using pcs::holes::GreedyTriangulation2D;
using pcs::holes::IsSimplePolygon;
using pcs::holes::PointInPolygon;
using pcs::holes::SegmentsIntersect;

std::vector<double> Lift(const std::vector<double>& uv)
{
  std::vector<double> xyz;
  for (size_t i = 0; i < uv.size(); i += 2)
  {
    xyz.insert(xyz.end(), { uv[i], uv[i + 1], 0.0 });
  }
  return xyz;
}

double Area2(const std::vector<double>& uv, int a, int b, int c)
{
  return (uv[2 * b] - uv[2 * a]) * (uv[2 * c + 1] - uv[2 * a + 1]) -
    (uv[2 * c] - uv[2 * a]) * (uv[2 * b + 1] - uv[2 * a + 1]);
}

// Checks a triangulation of the polygon 0..n-1 (counter-clockwise) with interior points n..:
// the count, positive triangles, the area, every loop edge used once in the loop direction and
// every other edge twice in opposite directions, every point used.
bool CheckTriangulation(const char* name, const std::vector<double>& uv, int n,
  const std::vector<int32_t>& triangles, bool expectComplete = true)
{
  const int count = static_cast<int>(uv.size() / 2);
  const int m = count - n;
  const int before = Failures;
  if (expectComplete)
  {
    CHECK(static_cast<int>(triangles.size()) == 3 * (n + 2 * m - 2), "%s: %d triangles, expected %d",
      name, static_cast<int>(triangles.size() / 3), n + 2 * m - 2);
  }
  double area = 0.0, polygon = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const int j = (i + 1) % n;
    polygon += uv[2 * i] * uv[2 * j + 1] - uv[2 * j] * uv[2 * i + 1];
  }
  std::map<std::pair<int, int>, int> halfEdges;
  std::set<int> used;
  for (size_t t = 0; t < triangles.size(); t += 3)
  {
    const double a = Area2(uv, triangles[t], triangles[t + 1], triangles[t + 2]);
    CHECK(a > 0, "%s: triangle %d not counter-clockwise", name, static_cast<int>(t / 3));
    area += a;
    for (int k = 0; k < 3; ++k)
    {
      halfEdges[{ triangles[t + k], triangles[t + (k + 1) % 3] }]++;
      used.insert(triangles[t + k]);
    }
  }
  if (expectComplete)
  {
    CHECK(std::fabs(area - polygon) <= 1e-9 * std::fabs(polygon), "%s: area %g, polygon %g", name,
      area, polygon);
    CHECK(static_cast<int>(used.size()) == count, "%s: %d of %d points used", name,
      static_cast<int>(used.size()), count);
    for (const auto& h : halfEdges)
    {
      CHECK(h.second == 1, "%s: half-edge %d-%d used %d times", name, h.first.first,
        h.first.second, h.second);
      const int a = h.first.first, b = h.first.second;
      const bool loopEdge = a < n && b == (a + 1) % n;
      if (!loopEdge)
      {
        CHECK(halfEdges.count({ b, a }) == 1, "%s: edge %d-%d has one triangle only", name, a, b);
      }
    }
    for (int i = 0; i < n; ++i)
    {
      CHECK(halfEdges.count({ i, (i + 1) % n }) == 1, "%s: loop edge %d not covered", name, i);
    }
  }
  return Failures == before;
}

void TestPolygonPredicates()
{
  const std::vector<double> square = { 0, 0, 1, 0, 1, 1, 0, 1 };
  CHECK(IsSimplePolygon(square), "square");
  CHECK(!IsSimplePolygon({ 0, 0, 1, 1, 1, 0, 0, 1 }), "bow-tie");
  CHECK(!IsSimplePolygon({ 0, 0, 1, 0, 2, 0 }), "collinear triangle");
  CHECK(!IsSimplePolygon({ 0, 0, 2, 0, 1, 0, 1, 1 }), "edge folding back on its predecessor");
  // A vertex touching a non-adjacent edge, and two equal non-adjacent vertices.
  CHECK(!IsSimplePolygon({ 0, 0, 4, 0, 4, 4, 2, 0, 0, 4 }), "vertex on an edge");
  CHECK(!IsSimplePolygon({ 0, 0, 2, 0, 2, 2, 1, 1, 0, 2, 1, 1 }), "repeated vertex");
  CHECK(!IsSimplePolygon({ 0, 0, 1, 0, 1, 0, 0, 1 }), "zero-length edge");
  // Comb: simple, concave.
  const std::vector<double> comb = { 0, 0, 5, 0, 5, 3, 4, 3, 4, 1, 3, 1, 3, 3, 2, 3, 2, 1, 1, 1,
    1, 3, 0, 3 };
  CHECK(IsSimplePolygon(comb), "comb");

  const double inside[2] = { 0.5, 2.0 }, notch[2] = { 1.5, 2.0 }, onEdge[2] = { 1.0, 2.0 },
               onVertex[2] = { 4, 3 }, far[2] = { -1, 0 }, onBottom[2] = { 2.5, 0.0 };
  CHECK(PointInPolygon(comb, inside) == 1, "inside the comb's tooth");
  CHECK(PointInPolygon(comb, notch) == -1, "in the comb's notch");
  CHECK(PointInPolygon(comb, onEdge) == 0, "on an edge");
  CHECK(PointInPolygon(comb, onVertex) == 0, "on a vertex");
  CHECK(PointInPolygon(comb, onBottom) == 0, "on a horizontal edge");
  CHECK(PointInPolygon(comb, far) == -1, "far outside");
  // Clockwise polygons: the winding number is -1, still inside.
  const std::vector<double> clockwise = { 0, 0, 0, 1, 1, 1, 1, 0 };
  const double centre[2] = { 0.5, 0.5 };
  CHECK(PointInPolygon(clockwise, centre) == 1, "inside a clockwise square");

  const double a[2] = { 0, 0 }, b[2] = { 2, 2 }, c[2] = { 0, 2 }, d[2] = { 2, 0 }, e[2] = { 1, 1 },
               f[2] = { 3, 3 }, g[2] = { 4, 4 };
  CHECK(SegmentsIntersect(a, b, c, d), "crossing diagonals");
  CHECK(SegmentsIntersect(a, b, e, c), "touching at an interior point");
  CHECK(SegmentsIntersect(a, f, e, g), "collinear overlap");
  CHECK(!SegmentsIntersect(a, e, f, g), "collinear, disjoint");
  CHECK(!SegmentsIntersect(a, c, d, b), "parallel");
}

void TestGreedy2D()
{
  // Convex polygon: n - 2 triangles.
  {
    std::vector<double> uv;
    const int n = 17;
    for (int i = 0; i < n; ++i)
    {
      const double t = 2 * M_PI * i / n;
      uv.insert(uv.end(), { std::cos(t), 0.7 * std::sin(t) });
    }
    std::vector<int32_t> triangles;
    CHECK(GreedyTriangulation2D(uv, Lift(uv), n, nullptr, triangles), "convex 17-gon complete");
    CheckTriangulation("convex 17-gon", uv, n, triangles);
  }
  // The greedy choice: a rhombus takes its shorter diagonal (1-3), not 0-2.
  {
    const std::vector<double> uv = { -2, 0, 0, -1, 2, 0, 0, 1 };
    std::vector<int32_t> triangles;
    GreedyTriangulation2D(uv, Lift(uv), 4, nullptr, triangles);
    CheckTriangulation("rhombus", uv, 4, triangles);
    bool shortDiagonal = true;
    for (size_t t = 0; t < triangles.size(); t += 3)
    {
      std::set<int> s(triangles.begin() + t, triangles.begin() + t + 3);
      shortDiagonal = shortDiagonal && s.count(1) && s.count(3);
    }
    CHECK(shortDiagonal, "rhombus: the short diagonal 1-3 is in both triangles");
  }
  // 3D lengths decide: the same rhombus lifted so that 0-2 is the shorter diagonal in 3D.
  {
    const std::vector<double> uv = { -2, 0, 0, -1, 2, 0, 0, 1 };
    std::vector<double> xyz = { -0.5, 0, 0, 0, -1, 2, 0.5, 0, 0, 0, 1, 2 };
    std::vector<int32_t> triangles;
    GreedyTriangulation2D(uv, xyz, 4, nullptr, triangles);
    bool longDiagonal = true;
    for (size_t t = 0; t < triangles.size(); t += 3)
    {
      std::set<int> s(triangles.begin() + t, triangles.begin() + t + 3);
      longDiagonal = longDiagonal && s.count(0) && s.count(2);
    }
    CHECK(longDiagonal, "3D lengths: the diagonal 0-2 (short in 3D) is chosen");
  }
  // Concave comb with interior points (jittered grid inside its teeth and base).
  {
    std::vector<double> uv = { 0, 0, 5, 0, 5, 3, 4, 3, 4, 1, 3, 1, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3,
      0, 3 };
    const int n = static_cast<int>(uv.size() / 2);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> jitter(-0.05, 0.05);
    for (double x = 0.25; x < 5; x += 0.5)
    {
      for (double y = 0.25; y < 3; y += 0.5)
      {
        const double p[2] = { x + jitter(rng), y + jitter(rng) };
        if (PointInPolygon(std::vector<double>(uv.begin(), uv.begin() + 2 * n), p) == 1)
        {
          uv.insert(uv.end(), { p[0], p[1] });
        }
      }
    }
    std::vector<int32_t> triangles;
    CHECK(GreedyTriangulation2D(uv, Lift(uv), n, nullptr, triangles), "comb complete");
    CheckTriangulation("comb with interior points", uv, n, triangles);
  }
  // Exact degeneracies: a square grid (cocircular quadruples, collinear rows) inside a square
  // whose sides carry collinear vertices.
  {
    std::vector<double> uv;
    for (int i = 0; i < 6; ++i)
    {
      uv.insert(uv.end(), { static_cast<double>(i), 0.0 });
    }
    for (int i = 0; i < 6; ++i)
    {
      uv.insert(uv.end(), { 6.0, static_cast<double>(i) });
    }
    for (int i = 6; i > 0; --i)
    {
      uv.insert(uv.end(), { static_cast<double>(i), 6.0 });
    }
    for (int i = 6; i > 0; --i)
    {
      uv.insert(uv.end(), { 0.0, static_cast<double>(i) });
    }
    const int n = static_cast<int>(uv.size() / 2);
    for (int i = 1; i < 6; ++i)
    {
      for (int j = 1; j < 6; ++j)
      {
        uv.insert(uv.end(), { static_cast<double>(i), static_cast<double>(j) });
      }
    }
    std::vector<int32_t> triangles;
    CHECK(GreedyTriangulation2D(uv, Lift(uv), n, nullptr, triangles), "grid complete");
    CheckTriangulation("6x6 grid", uv, n, triangles);
  }
  // A forbidden edge is never created.
  {
    std::vector<double> uv;
    const int n = 8;
    for (int i = 0; i < n; ++i)
    {
      const double t = 2 * M_PI * i / n;
      uv.insert(uv.end(), { std::cos(t), std::sin(t) });
    }
    uv.insert(uv.end(), { 0.01, 0.02 });
    std::vector<int32_t> triangles;
    auto forbidden = [](int i, int j) { return (i == 0 && j == 8) || (i == 8 && j == 0); };
    CHECK(GreedyTriangulation2D(uv, Lift(uv), n, forbidden, triangles), "forbidden: complete");
    CheckTriangulation("octagon with a forbidden spoke", uv, n, triangles);
    for (size_t t = 0; t < triangles.size(); t += 3)
    {
      std::set<int> s(triangles.begin() + t, triangles.begin() + t + 3);
      CHECK(!(s.count(0) && s.count(8)), "forbidden edge 0-8 created");
    }
  }
}

// Triangles (point ids) of a hole: every loop edge once in the loop direction, every other
// edge twice in opposite directions (a disk bounded by the loop, consistently oriented).
bool CheckDisk(const char* name, const std::vector<int32_t>& loop,
  const std::vector<int32_t>& triangles)
{
  const int before = Failures;
  std::map<std::pair<int, int>, int> halfEdges;
  std::set<int> vertices;
  for (size_t t = 0; t < triangles.size(); t += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      halfEdges[{ triangles[t + k], triangles[t + (k + 1) % 3] }]++;
      vertices.insert(triangles[t + k]);
    }
  }
  std::set<std::pair<int, int>> loopEdges;
  for (size_t i = 0; i < loop.size(); ++i)
  {
    loopEdges.insert({ loop[(i + 1) % loop.size()], loop[i] });
  }
  size_t edges = 0;
  for (const auto& h : halfEdges)
  {
    CHECK(h.second == 1, "%s: half-edge %d-%d used %d times", name, h.first.first, h.first.second,
      h.second);
    const bool boundary = halfEdges.count({ h.first.second, h.first.first }) == 0;
    if (boundary)
    {
      CHECK(loopEdges.count({ h.first.second, h.first.first }) == 1,
        "%s: boundary edge %d-%d is not a loop edge in the loop direction", name, h.first.first,
        h.first.second);
      ++edges;
    }
    else if (h.first.first < h.first.second)
    {
      ++edges;
    }
  }
  const long chi = static_cast<long>(vertices.size()) - static_cast<long>(edges) +
    static_cast<long>(triangles.size() / 3);
  CHECK(chi == 1, "%s: Euler characteristic %ld (a disk has 1)", name, chi);
  return Failures == before;
}

void TestHoleFiller()
{
  pcs::holes::HoleFiller filler;
  // A planar circular hole with points inside, tilted in 3D; the boundary vectors point out.
  {
    std::vector<double> xyz;
    std::vector<int32_t> loop, points;
    std::vector<double> vectors;
    const int n = 40;
    auto place = [&](double u, double v) {
      // Tilted plane: (u, v, 0.2 u - 0.3 v).
      xyz.insert(xyz.end(), { u, v, 0.2 * u - 0.3 * v });
    };
    for (int i = 0; i < n; ++i)
    {
      const double t = -2 * M_PI * i / n; // clockwise seen from +z
      place(std::cos(t), std::sin(t));
      loop.push_back(i);
      vectors.insert(vectors.end(), { std::cos(t), std::sin(t), 0.2 * std::cos(t) - 0.3 * std::sin(t) });
    }
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(-1, 1);
    int inside = 0;
    while (inside < 60)
    {
      const double a = u(rng), b = u(rng);
      if (a * a + b * b < 0.85)
      {
        place(a, b);
        points.push_back(static_cast<int32_t>(xyz.size() / 3 - 1));
        ++inside;
      }
    }
    // Points on the other side of the object (far from the plane) are not taken.
    xyz.insert(xyz.end(), { 0.1, 0.1, 5.0 });
    points.push_back(static_cast<int32_t>(xyz.size() / 3 - 1));
    filler.AuxiliaryDistance = 0.05;
    pcs::holes::FillResult result;
    CHECK(filler.Fill(xyz.data(), loop, vectors, points, result), "circle: filled");
    CHECK(result.Complete, "circle: complete");
    CHECK(result.Chords.empty(), "circle: %d chords, none needed",
      static_cast<int>(result.Chords.size()));
    CHECK(static_cast<int>(result.UsedPoints.size()) == 60, "circle: %d of 60 inside points used",
      static_cast<int>(result.UsedPoints.size()));
    CHECK(static_cast<int>(result.Triangles.size()) == 3 * (n + 2 * 60 - 2),
      "circle: %d triangles", static_cast<int>(result.Triangles.size() / 3));
    CheckDisk("circle", loop, result.Triangles);

    // The same hole with boundary vectors pointing INTO the hole: the auxiliary points project
    // inside, the projection is ambiguous.
    std::vector<double> inward(vectors);
    for (double& c : inward)
    {
      c = -c;
    }
    pcs::holes::Plane plane;
    CHECK(!filler.HasUnambiguousProjection(xyz.data(), loop, inward, plane),
      "inward boundary vectors: ambiguous");
    CHECK(filler.HasUnambiguousProjection(xyz.data(), loop, vectors, plane),
      "outward boundary vectors: unambiguous");

    // Too many points for one greedy triangulation: split by diagonals, still a disk.
    pcs::holes::HoleFiller small;
    small.MaximumGreedyPoints = 30;
    small.AuxiliaryDistance = 0.05;
    CHECK(small.Fill(xyz.data(), loop, vectors, points, result), "circle, split: filled");
    CHECK(result.Complete && !result.Chords.empty(), "circle, split: complete with chords (%d)",
      static_cast<int>(result.Chords.size()));
    CHECK(static_cast<int>(result.UsedPoints.size()) >= 55, "circle, split: %d points used",
      static_cast<int>(result.UsedPoints.size()));
    CheckDisk("circle split in pieces", loop, result.Triangles);
  }
  // A hole that wraps three quarters around a cylinder: its projection onto the average plane
  // folds, so it is split by chords (step 5). The result is a disk whose triangles lie close to
  // the cylinder and face outwards.
  {
    std::vector<double> xyz;
    std::vector<int32_t> loop;
    std::vector<double> vectors;
    const int arc = 36, rows = 8;
    const double span = 1.5 * M_PI;
    auto add = [&](double t, double z, double vz, double vt) {
      xyz.insert(xyz.end(), { std::cos(t), std::sin(t), z });
      loop.push_back(static_cast<int32_t>(xyz.size() / 3 - 1));
      // Boundary vector: out of the hole along the cylinder (z) or around it (t).
      vectors.insert(vectors.end(), { -vt * std::sin(t), vt * std::cos(t), vz });
    };
    // Counter-clockwise seen from outside: bottom edge with increasing t, then up, back, down.
    for (int i = 0; i < arc; ++i)
    {
      add(span * i / arc, 0.0, -1, 0);
    }
    for (int j = 0; j < rows; ++j)
    {
      add(span, 1.0 * j / rows, 0, 1);
    }
    for (int i = arc; i > 0; --i)
    {
      add(span * i / arc, 1.0, 1, 0);
    }
    for (int j = rows; j > 0; --j)
    {
      add(0.0, 1.0 * j / rows, 0, -1);
    }
    // Lost points on the cylinder inside the band (a jittered grid).
    std::vector<int32_t> points;
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    for (int i = 1; i < arc; ++i)
    {
      for (int j = 1; j < rows; ++j)
      {
        const double t = span * (i + jitter(rng)) / arc, z = (j + jitter(rng)) / rows;
        xyz.insert(xyz.end(), { std::cos(t), std::sin(t), z });
        points.push_back(static_cast<int32_t>(xyz.size() / 3 - 1));
      }
    }
    filler.AuxiliaryDistance = 0.02;
    pcs::holes::Plane plane;
    CHECK(!filler.HasUnambiguousProjection(xyz.data(), loop, vectors, plane),
      "cylinder band: ambiguous");
    pcs::holes::FillResult result;
    CHECK(filler.Fill(xyz.data(), loop, vectors, points, result), "cylinder band: filled");
    CHECK(result.Complete, "cylinder band: complete");
    CHECK(result.UsedPoints.size() == points.size(), "cylinder band: %d of %d points used",
      static_cast<int>(result.UsedPoints.size()), static_cast<int>(points.size()));
    CHECK(!result.Chords.empty(), "cylinder band: split by chords");
    CheckDisk("cylinder band", loop, result.Triangles);
    int outward = 0;
    for (size_t t = 0; t < result.Triangles.size(); t += 3)
    {
      const double* a = &xyz[3 * result.Triangles[t]];
      const double* b = &xyz[3 * result.Triangles[t + 1]];
      const double* c = &xyz[3 * result.Triangles[t + 2]];
      const double ab[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
      const double ac[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
      const double normal[3] = { ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
        ab[0] * ac[1] - ab[1] * ac[0] };
      const double centre[3] = { (a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, 0 };
      outward += normal[0] * centre[0] + normal[1] * centre[1] > 0 ? 1 : 0;
    }
    CHECK(outward == static_cast<int>(result.Triangles.size() / 3),
      "cylinder band: %d of %d triangles face outwards", outward,
      static_cast<int>(result.Triangles.size() / 3));
  }
  // A loop through the same vertex twice (two holes touching at a corner): two disks.
  {
    const std::vector<double> xyz = { 0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0, 0, -1, 0.0 };
    const std::vector<int32_t> loop = { 0, 1, 2, 0, 3, 4 };
    pcs::holes::FillResult result;
    filler.AuxiliaryDistance = 0;
    CHECK(filler.Fill(xyz.data(), loop, {}, {}, result), "pinched loop: filled");
    CHECK(result.Complete && result.Triangles.size() == 6, "pinched loop: two triangles (%d)",
      static_cast<int>(result.Triangles.size() / 3));
  }
  // An existing mesh edge is never created inside the hole: a quad hole whose short diagonal
  // 1-3 is already a mesh edge gets the other one.
  {
    const std::vector<double> xyz = { 0, 0, 0, 1, 0, 0, 1, 1.2, 0, 0, 1, 0 };
    pcs::holes::HoleFiller constrained;
    constrained.EdgeExists = [](int32_t a, int32_t b) {
      return (a == 1 && b == 3) || (a == 3 && b == 1);
    };
    pcs::holes::FillResult result;
    CHECK(constrained.Fill(xyz.data(), { 0, 1, 2, 3 }, {}, {}, result), "square: filled");
    for (size_t t = 0; t < result.Triangles.size(); t += 3)
    {
      std::set<int> s(result.Triangles.begin() + t, result.Triangles.begin() + t + 3);
      CHECK(s.count(0) && s.count(2), "square: the diagonal 0-2 is used (1-3 exists)");
    }
  }
}
} // namespace

// LeastDihedralFill on loops whose answer is known by construction.
void TestLeastDihedralFill()
{
  const auto noAcross = [](int, double[3]) { return false; };
  // A convex planar hexagon, counter-clockwise in the xy plane: 4 triangles, all facing +z, every
  // dihedral angle 0.
  std::vector<double> xyz;
  std::vector<int32_t> loop;
  for (int i = 0; i < 6; ++i)
  {
    const double a = 2.0 * std::acos(-1.0) * i / 6.0;
    xyz.insert(xyz.end(), { std::cos(a), std::sin(a), 0.0 });
    loop.push_back(i);
  }
  std::vector<int32_t> triangles;
  double worst = pcs::holes::LeastDihedralFill(xyz.data(), loop, nullptr, noAcross, triangles);
  CHECK(triangles.size() == 12, "hexagon: %d triangles, expected 4",
    static_cast<int>(triangles.size() / 3));
  CHECK(worst >= 0.0 && worst < 1e-9, "hexagon: largest dihedral angle %g, expected 0", worst);
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
  {
    const double* p = &xyz[3 * triangles[t]];
    const double* q = &xyz[3 * triangles[t + 1]];
    const double* r = &xyz[3 * triangles[t + 2]];
    const double z = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    CHECK(z > 0, "hexagon: triangle %d does not face +z", static_cast<int>(t / 3));
  }
  // A square whose diagonal 0-2 is a mesh edge already: the fill must use the diagonal 1-3.
  const double square[] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
  const std::vector<int32_t> four = { 0, 1, 2, 3 };
  const auto diagonal02 = [](int32_t a, int32_t b)
  { return (a == 0 && b == 2) || (a == 2 && b == 0); };
  triangles.clear();
  worst = pcs::holes::LeastDihedralFill(square, four, diagonal02, noAcross, triangles);
  CHECK(worst >= 0.0 && triangles.size() == 6, "square: 2 triangles expected");
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
  {
    const bool has0 = triangles[t] == 0 || triangles[t + 1] == 0 || triangles[t + 2] == 0;
    const bool has2 = triangles[t] == 2 || triangles[t + 1] == 2 || triangles[t + 2] == 2;
    CHECK(!(has0 && has2), "square: the existing edge 0-2 was used again");
  }
  // Three collinear vertices (0, 1, 2) and an apex: the degenerate triangle (0, 1, 2) is
  // forbidden, so both triangles use the apex 3.
  const double flat[] = { 0, 0, 0, 1, 0, 0, 2, 0, 0, 1, 1, 0 };
  triangles.clear();
  worst = pcs::holes::LeastDihedralFill(flat, four, nullptr, noAcross, triangles);
  CHECK(worst >= 0.0 && triangles.size() == 6, "collinear: 2 triangles expected");
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
  {
    CHECK(triangles[t] == 3 || triangles[t + 1] == 3 || triangles[t + 2] == 3,
      "collinear: a triangle without the apex");
  }
  // A loop of two vertices has no triangulation.
  triangles.clear();
  CHECK(pcs::holes::LeastDihedralFill(flat, { 0, 1 }, nullptr, noAcross, triangles) < 0,
    "two vertices: no triangulation");
  // A saddle (12 vertices on z = 0.4 cos 2a): its fill has some least largest angle A > 0. With
  // maximumAngle above A the fill is the same; below A no fill within maximumAngle is returned.
  std::vector<double> saddle;
  std::vector<int32_t> twelve;
  for (int i = 0; i < 12; ++i)
  {
    const double a = 2.0 * std::acos(-1.0) * i / 12.0;
    saddle.insert(saddle.end(), { std::cos(a), std::sin(a), 0.4 * std::cos(2.0 * a) });
    twelve.push_back(i);
  }
  std::vector<int32_t> uncapped, capped;
  const double least =
    pcs::holes::LeastDihedralFill(saddle.data(), twelve, nullptr, noAcross, uncapped);
  CHECK(
    least > 0.01 && uncapped.size() == 30, "saddle: 10 triangles with a positive angle expected");
  const double above =
    pcs::holes::LeastDihedralFill(saddle.data(), twelve, nullptr, noAcross, capped, least + 0.01);
  CHECK(above == least && capped == uncapped, "saddle: a cap above the angle changed the fill");
  capped.clear();
  const double below =
    pcs::holes::LeastDihedralFill(saddle.data(), twelve, nullptr, noAcross, capped, least - 0.01);
  CHECK(below < 0.0 || below > least - 0.01, "saddle: a fill within a cap below its angle");
}

// The largest dihedral angle of a triangulation of `loop` (fill triangles as LeastDihedralFill
// writes them): between the two triangles on each diagonal, and between a triangle and the mesh
// normal across a loop edge (`across`, indexed by the edge's first loop position).
double LargestDihedral(const std::vector<double>& xyz,
  const std::vector<int32_t>& loop,
  const std::vector<int32_t>& triangles,
  const std::vector<std::vector<double>>& across)
{
  const int n = static_cast<int>(loop.size());
  std::map<std::pair<int32_t, int32_t>, std::vector<std::vector<double>>> normalsOnEdge;
  for (int e = 0; e < n; ++e)
  {
    if (!across[e].empty())
    {
      const int32_t a = loop[e], b = loop[(e + 1) % n];
      normalsOnEdge[{ std::min(a, b), std::max(a, b) }].push_back(across[e]);
    }
  }
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
  {
    const double* p = &xyz[3 * triangles[t]];
    const double* q = &xyz[3 * triangles[t + 1]];
    const double* r = &xyz[3 * triangles[t + 2]];
    const double u[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
    const double v[3] = { r[0] - p[0], r[1] - p[1], r[2] - p[2] };
    std::vector<double> m = {
      u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]
    };
    const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    for (double& c : m)
    {
      c /= length;
    }
    for (int j = 0; j < 3; ++j)
    {
      const int32_t a = triangles[t + j], b = triangles[t + (j + 1) % 3];
      normalsOnEdge[{ std::min(a, b), std::max(a, b) }].push_back(m);
    }
  }
  double worst = 0.0;
  for (const auto& edge : normalsOnEdge)
  {
    if (edge.second.size() == 2)
    {
      const auto& a = edge.second[0];
      const auto& b = edge.second[1];
      const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      worst = std::max(worst, std::acos(std::max(-1.0, std::min(1.0, dot))));
    }
  }
  return worst;
}

// Liepa's recurrence as written (SGP 2003, section 3.1; no pruning), the reference for
// LeastDihedralFill, which skips the splits that cannot be taken: for each sub-polygon i..j in
// order of size, the split k of least (largest dihedral angle, then area), ties within 1e-9
// radians going to the smaller area and then to the first k. Returns the triangles.
std::vector<int32_t> PlainLeastDihedralFill(const std::vector<double>& xyz,
  const std::vector<int32_t>& loop,
  const std::set<std::pair<int32_t, int32_t>>& edges,
  const std::vector<std::vector<double>>& across)
{
  const int n = static_cast<int>(loop.size());
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<std::vector<double>> angle(n, std::vector<double>(n, inf)), area(angle);
  std::vector<std::vector<int>> best(n, std::vector<int>(n, -1));
  // The unit normal of the triangle of loop positions (a, b, c) and half its cross product's
  // length.
  auto normal = [&](int a, int b, int c, double m[3])
  {
    const double* p = &xyz[3 * loop[a]];
    const double* q = &xyz[3 * loop[b]];
    const double* r = &xyz[3 * loop[c]];
    const double u[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
    const double v[3] = { r[0] - p[0], r[1] - p[1], r[2] - p[2] };
    m[0] = u[1] * v[2] - u[2] * v[1];
    m[1] = u[2] * v[0] - u[0] * v[2];
    m[2] = u[0] * v[1] - u[1] * v[0];
    const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    for (int d = 0; d < 3 && length > 0.0; ++d)
    {
      m[d] /= length;
    }
    return 0.5 * length;
  };
  // The normal on the side (a, b): the mesh across a loop edge, else the best split's triangle.
  auto side = [&](int a, int b, double m[3])
  {
    if (b == a + 1 || (a == 0 && b == n - 1))
    {
      const auto& t = across[b == a + 1 ? a : n - 1];
      std::copy(t.begin(), t.end(), m);
      return !t.empty();
    }
    normal(a, best[a][b], b, m);
    return true;
  };
  for (int i = 0; i + 1 < n; ++i)
  {
    angle[i][i + 1] = area[i][i + 1] = 0.0;
  }
  for (int span = 2; span < n; ++span)
  {
    for (int i = 0, j = span; j < n; ++i, ++j)
    {
      if (span < n - 1 && edges.count({ std::min(loop[i], loop[j]), std::max(loop[i], loop[j]) }))
      {
        continue;
      }
      for (int k = i + 1; k < j; ++k)
      {
        double m[3], other[3];
        const double triangleArea = normal(i, k, j, m);
        if (!(angle[i][k] < inf && angle[k][j] < inf) || !(triangleArea > 0.0))
        {
          continue;
        }
        double worst = std::max(angle[i][k], angle[k][j]);
        const std::pair<int, int> sides[3] = { { i, k }, { k, j }, { 0, n - 1 } };
        for (int s = 0; s < (span == n - 1 ? 3 : 2); ++s)
        {
          if (side(sides[s].first, sides[s].second, other))
          {
            const double dot = m[0] * other[0] + m[1] * other[1] + m[2] * other[2];
            worst = std::max(worst, std::acos(std::max(-1.0, std::min(1.0, dot))));
          }
        }
        const double a = area[i][k] + area[k][j] + triangleArea;
        if (worst < angle[i][j] - 1e-9 || (worst <= angle[i][j] + 1e-9 && a < area[i][j]))
        {
          angle[i][j] = worst;
          area[i][j] = a;
          best[i][j] = k;
        }
      }
    }
  }
  std::vector<int32_t> triangles;
  std::vector<std::pair<int, int>> stack = { { 0, n - 1 } };
  while (!stack.empty() && best[0][n - 1] >= 0)
  {
    const auto range = stack.back();
    stack.pop_back();
    const int k = best[range.first][range.second];
    if (k >= 0)
    {
      triangles.insert(triangles.end(), { loop[range.first], loop[k], loop[range.second] });
      stack.push_back({ range.first, k });
      stack.push_back({ k, range.second });
    }
  }
  return triangles;
}

// LeastDihedralFill against the plain recurrence on random loops: bumpy, noisy rings of 4 to
// 60 vertices with mesh normals across most of their edges and some diagonals already in the
// mesh, which have many splits of equal largest angle (the one at a mesh edge). The same
// triangles, and their largest dihedral angle is the one returned.
void TestLeastDihedralFillSkipsOnlyUntakenSplits()
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 120; ++trial)
  {
    const int n = 4 + trial % 57;
    std::vector<double> xyz;
    std::vector<int32_t> loop;
    std::vector<std::vector<double>> across(n);
    for (int i = 0; i < n; ++i)
    {
      const double a = 2.0 * std::acos(-1.0) * i / n;
      const double bump = 0.4 * std::sin(3.0 * a);
      xyz.insert(xyz.end(),
        { std::cos(a) + 0.1 * unit(random),
          std::sin(a) + 0.1 * unit(random),
          bump + 0.1 * unit(random) });
      loop.push_back(i);
      if (unit(random) > -0.6)
      {
        std::vector<double> m = { 0.7 * unit(random), 0.7 * unit(random), -1.0 };
        const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        for (double& c : m)
        {
          c /= length;
        }
        across[i] = m;
      }
    }
    std::set<std::pair<int32_t, int32_t>> edges;
    for (int e = 0; e < n / 4; ++e)
    {
      const int32_t a = static_cast<int32_t>(random() % n), b = static_cast<int32_t>(random() % n);
      edges.insert({ std::min(a, b), std::max(a, b) });
    }
    const auto edgeExists = [&edges](int32_t a, int32_t b) {
      return edges.count({ std::min(a, b), std::max(a, b) }) > 0;
    };
    const auto acrossEdge = [&across](int e, double m[3])
    {
      std::copy(across[e].begin(), across[e].end(), m);
      return !across[e].empty();
    };
    std::vector<int32_t> triangles;
    const double worst =
      pcs::holes::LeastDihedralFill(xyz.data(), loop, edgeExists, acrossEdge, triangles);
    const std::vector<int32_t> expected = PlainLeastDihedralFill(xyz, loop, edges, across);
    CHECK(triangles == expected,
      "random loop %d (%d vertices): %d triangles, %d expected, "
      "not the same",
      trial,
      n,
      static_cast<int>(triangles.size() / 3),
      static_cast<int>(expected.size() / 3));
    CHECK(
      triangles.empty() || std::abs(LargestDihedral(xyz, loop, triangles, across) - worst) <= 1e-12,
      "random loop %d: the returned triangles do not have the returned angle",
      trial);
  }
}

// FillLoopNearSamples on a unit cube without its top face (the samples: the 8 corners, and the
// top face's centre when asked): the fill is the top's 2 triangles, whose farthest tested point,
// the diagonal's midpoint, is sqrt(1/2) from every corner, and whose dihedral angle with the
// sides is 90 degrees.
void TestFillLoopNearSamples()
{
  std::vector<double> xyz;
  for (int i = 0; i < 8; ++i)
  {
    xyz.insert(xyz.end(), { double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1) });
  }
  xyz.insert(xyz.end(), { 0.5, 0.5, 1.0 }); // point 8: the top face's centre, in no triangle
  const int32_t sides[10][3] = { { 0, 2, 3 },
    { 0, 3, 1 },
    { 0, 1, 5 },
    { 0, 5, 4 },
    { 2, 6, 7 },
    { 2, 7, 3 },
    { 0, 4, 6 },
    { 0, 6, 2 },
    { 1, 3, 7 },
    { 1, 7, 5 } };
  pcs::SurfaceMesh mesh(9);
  for (const auto& t : sides)
  {
    mesh.AddTriangle(t[0], t[1], t[2]);
  }
  std::vector<std::vector<int32_t>> loops;
  mesh.GetBoundaryLoops(loops);
  CHECK(loops.size() == 1 && loops[0].size() == 4, "open cube: one loop of 4 expected");
  if (loops.size() != 1)
  {
    return;
  }
  const double halfPi = 0.5 * std::acos(-1.0);
  int queries = 0;
  auto nearPoint = [&](int samples)
  {
    return [&xyz, &queries, samples](const double* x, double reach)
    {
      ++queries;
      for (int p = 0; p < samples; ++p)
      {
        const double* q = &xyz[3 * p];
        const double d[3] = { x[0] - q[0], x[1] - q[1], x[2] - q[2] };
        if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= reach * reach)
        {
          return true;
        }
      }
      return false;
    };
  };
  std::vector<int32_t> fill;
  const double* p = xyz.data();
  // The corners are within 1 of every tested point: kept, and it closes the cube.
  CHECK(pcs::holes::FillLoopNearSamples(p, loops[0], mesh, 1.0, 1.1 * halfPi, nearPoint(8), fill),
    "reach 1: the fill must be kept");
  std::vector<int64_t> added;
  CHECK(fill.size() == 6 && mesh.AddTriangles(fill.data(), 2, added) &&
      mesh.GetNumberOfBoundaryHalfEdges() == 0,
    "reach 1: 2 triangles closing the cube expected");
  for (int64_t t : added)
  {
    mesh.RemoveTriangle(t);
  }
  // The diagonal's midpoint is sqrt(1/2) > 0.6 from every corner: refused, unless the face's
  // centre is a sample.
  CHECK(!pcs::holes::FillLoopNearSamples(p, loops[0], mesh, 0.6, 1.1 * halfPi, nearPoint(8), fill),
    "reach 0.6, corners only: the fill must be refused");
  CHECK(fill.empty(), "a refused fill must be empty");
  CHECK(pcs::holes::FillLoopNearSamples(p, loops[0], mesh, 0.6, 1.1 * halfPi, nearPoint(9), fill),
    "reach 0.6 with the face's centre: the fill must be kept");
  // The fill meets the sides at 90 degrees: refused below that.
  CHECK(!pcs::holes::FillLoopNearSamples(p, loops[0], mesh, 1.0, 0.9 * halfPi, nearPoint(8), fill),
    "maximum dihedral 81 degrees: the fill must be refused");
  // Area 1 > 2 x perimeter 4 x reach 0.1: refused before any near-point query.
  queries = 0;
  CHECK(
    !pcs::holes::FillLoopNearSamples(p, loops[0], mesh, 0.1, 1.1 * halfPi, nearPoint(9), fill) &&
      queries == 0,
    "reach 0.1: refused by the area bound, %d queries",
    queries);
}

// The triangles of `triangles` (3 ids each) whose points of `xyz` have a zero cross product;
// exact for the small integer coordinates of the grids below.
int ZeroAreaTriangles(const std::vector<double>& xyz, const std::vector<int32_t>& triangles)
{
  int degenerate = 0;
  for (size_t t = 0; t < triangles.size(); t += 3)
  {
    const double* a = &xyz[3 * static_cast<size_t>(triangles[t])];
    const double* b = &xyz[3 * static_cast<size_t>(triangles[t + 1])];
    const double* c = &xyz[3 * static_cast<size_t>(triangles[t + 2])];
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double w[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const bool zero = u[1] * w[2] - u[2] * w[1] == 0 && u[2] * w[0] - u[0] * w[2] == 0 &&
      u[0] * w[1] - u[1] * w[0] == 0;
    degenerate += zero ? 1 : 0;
  }
  return degenerate;
}

// The zero-area triangles of a fill of the hole bounded by the border of the integer grid
// (i, j, p i + q j), 0 <= i, j <= 6, with its 25 inner points inside (boundary vectors outwards;
// `reversed`: the same hole seen from the other side). Whole rows of the grid are collinear in
// space, and the rounded projection on the fitted plane may put a row's middle point off the
// segment of its ends. Integer coordinates: the cross products are exact.
int ZeroAreaTrianglesOfGridFill(int p, int q, bool reversed, int& triangles)
{
  std::vector<double> xyz;
  auto id = [](int i, int j) { return 7 * i + j; };
  for (int i = 0; i <= 6; ++i)
  {
    for (int j = 0; j <= 6; ++j)
    {
      xyz.insert(xyz.end(), { double(i), double(j), double(p * i + q * j) });
    }
  }
  std::vector<int32_t> loop, inside;
  std::vector<double> vectors;
  auto border = [&](int i, int j, double di, double dj) {
    loop.push_back(id(i, j));
    vectors.insert(vectors.end(), { di, dj, p * di + q * dj });
  };
  for (int j = 0; j < 6; ++j)
  {
    border(0, j, -1, 0);
  }
  for (int i = 0; i < 6; ++i)
  {
    border(i, 6, 0, 1);
  }
  for (int j = 6; j > 0; --j)
  {
    border(6, j, 1, 0);
  }
  for (int i = 6; i > 0; --i)
  {
    border(i, 0, 0, -1);
  }
  for (int i = 1; i < 6; ++i)
  {
    for (int j = 1; j < 6; ++j)
    {
      inside.push_back(id(i, j));
    }
  }
  if (reversed)
  {
    std::reverse(loop.begin(), loop.end());
    for (size_t k = 0; k < loop.size() / 2; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        std::swap(vectors[3 * k + c], vectors[3 * (loop.size() - 1 - k) + c]);
      }
    }
  }
  pcs::holes::HoleFiller filler;
  pcs::holes::FillResult result;
  filler.Fill(xyz.data(), loop, vectors, inside, result);
  triangles = static_cast<int>(result.Triangles.size() / 3);
  return ZeroAreaTriangles(xyz, result.Triangles);
}

// The hole bounded by the 4 corners of the integer grid (i, j, p i + q j), 0 <= i, j <= 6, with
// every other grid point as a candidate: the 20 on the sides lie exactly on the loop's edges in
// space (a lost point on a boundary edge of the mesh), and only a zero-area triangle would join
// one to its edge. Counts the zero-area triangles and the side points used.
int ZeroAreaTrianglesOfSideFill(int p, int q, int& triangles, int& sidePointsUsed)
{
  std::vector<double> xyz;
  std::vector<int32_t> inside;
  auto id = [](int i, int j) { return 7 * i + j; };
  for (int i = 0; i <= 6; ++i)
  {
    for (int j = 0; j <= 6; ++j)
    {
      xyz.insert(xyz.end(), { double(i), double(j), double(p * i + q * j) });
      const bool corner = (i == 0 || i == 6) && (j == 0 || j == 6);
      if (!corner)
      {
        inside.push_back(id(i, j));
      }
    }
  }
  const std::vector<int32_t> loop = { id(0, 0), id(0, 6), id(6, 6), id(6, 0) };
  const double out[4][2] = { { -1, -1 }, { -1, 1 }, { 1, 1 }, { 1, -1 } };
  std::vector<double> vectors;
  for (const auto& o : out)
  {
    vectors.insert(vectors.end(), { o[0], o[1], p * o[0] + q * o[1] });
  }
  pcs::holes::HoleFiller filler;
  pcs::holes::FillResult result;
  filler.Fill(xyz.data(), loop, vectors, inside, result);
  triangles = static_cast<int>(result.Triangles.size() / 3);
  sidePointsUsed = 0;
  for (int32_t v : result.UsedPoints)
  {
    const int i = v / 7, j = v % 7;
    sidePointsUsed += (i == 0 || i == 6 || j == 0 || j == 6) ? 1 : 0;
  }
  return ZeroAreaTriangles(xyz, result.Triangles);
}

// Fills that would need a zero-area triangle: three collinear loop vertices (a slit), and grid
// holes on 48 tilted planes (before the 3D segment test, 8 of the 96 fills had such triangles),
// and the same planes' holes whose edges pass through candidate points.
void TestDegenerateFills()
{
  {
    pcs::holes::HoleFiller filler;
    const std::vector<double> xyz = { 0, 0, 0, 1, 1, 1, 2, 2, 2 };
    pcs::holes::FillResult result;
    filler.Fill(xyz.data(), { 0, 1, 2 }, std::vector<double>(9, 0.0), {}, result);
    CHECK(result.Triangles.empty(), "collinear loop: %d triangle(s), none has an area",
      static_cast<int>(result.Triangles.size() / 3));
  }
  for (int p = -3; p <= 3; ++p)
  {
    for (int q = -3; q <= 3; ++q)
    {
      for (bool reversed : { false, true })
      {
        if (p == 0 && q == 0)
        {
          continue;
        }
        int triangles = 0;
        const int degenerate = ZeroAreaTrianglesOfGridFill(p, q, reversed, triangles);
        CHECK(triangles > 0, "grid p %d q %d: no triangle", p, q);
        CHECK(degenerate == 0, "grid p %d q %d%s: %d zero-area triangle(s) of %d", p, q,
          reversed ? " reversed" : "", degenerate, triangles);
      }
      int triangles = 0, sideUsed = 0;
      const int degenerate = ZeroAreaTrianglesOfSideFill(p, q, triangles, sideUsed);
      CHECK(triangles > 0, "sides p %d q %d: no triangle", p, q);
      CHECK(degenerate == 0 && sideUsed == 0,
        "sides p %d q %d: %d zero-area triangle(s) of %d, %d point(s) on the loop's edges used",
        p,
        q,
        degenerate,
        triangles,
        sideUsed);
    }
  }
}

// TrianglesIntersect on configurations whose answer is known by construction: crossing,
// touching at a vertex, along an edge or at an edge crossing, coplanar overlap and containment,
// and the same with a small gap (which each must not see), in both argument orders.
void TestTrianglesIntersect()
{
  using pcs::holes::TrianglesIntersect;
  struct Case
  {
    const char* Name;
    double T[6][3];
    bool Meet;
  };
  const Case cases[] = {
    { "crossing",
      { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, { 0.5, 0.5, -1 }, { 0.5, 0.5, 1 }, { 3, 3, 0.5 } },
      true },
    { "vertex on the face",
      { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, { 0.5, 0.5, 0 }, { 0.5, 0.5, 1 }, { 1, 2, 1 } },
      true },
    { "vertex above the face",
      { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, { 0.5, 0.5, 1e-12 }, { 0.5, 0.5, 1 }, { 1, 2, 1 } },
      false },
    { "edges crossing",
      { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, { 1, -1, 0 }, { 1, 1, 0 }, { 1, 0, 1 } },
      true },
    { "edges apart",
      { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, { 1, -1, 1e-9 }, { 1, 1, 1e-9 }, { 1, 0, 1 } },
      false },
    { "coplanar overlap",
      { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, { 1, 1, 0 }, { 3, 1, 0 }, { 1, 3, 0 } },
      true },
    { "coplanar inside",
      { { 0, 0, 0 }, { 4, 0, 0 }, { 0, 4, 0 }, { 1, 1, 0 }, { 2, 1, 0 }, { 1, 2, 0 } },
      true },
    { "coplanar apart",
      { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, { 1.5, 1.5, 0 }, { 3, 1.5, 0 }, { 1.5, 3, 0 } },
      false },
    { "tilted coplanar touch",
      { { 0, 0, 0 }, { 2, 0, 2 }, { 0, 2, 0 }, { 1, 1, 1 }, { 3, 1, 3 }, { 1, 3, 1 } },
      true },
    { "parallel planes",
      { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, { 0, 0, 1 }, { 2, 0, 1 }, { 0, 2, 1 } },
      false },
  };
  for (const Case& c : cases)
  {
    const auto& t = c.T;
    CHECK(TrianglesIntersect(t[0], t[1], t[2], t[3], t[4], t[5]) == c.Meet, "%s", c.Name);
    CHECK(TrianglesIntersect(t[3], t[4], t[5], t[0], t[1], t[2]) == c.Meet, "%s (swapped)", c.Name);
  }
  const double flat[3][3] = { { 0, 0, 0 }, { 1, 1, 1 }, { 2, 2, 2 } };
  const double any[3][3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 } };
  CHECK(!TrianglesIntersect(flat[0], flat[1], flat[2], any[0], any[1], any[2]), "zero area");
}

// The vector area of a small non-convex loop far from the origin: the coordinates are exact
// (a 2^-10 square grid at 2^20), so the area from loop[0] is exact too, 3 s^2 along +z; a sum of
// the points' own cross products (terms of 2^40) loses it to rounding.
void TestLoopVectorArea()
{
  const double s = std::ldexp(1.0, -10), o = std::ldexp(1.0, 20);
  const double uv[5][2] = { { 0, 0 }, { 2, 0 }, { 2, 2 }, { 1, 1 }, { 0, 2 } };
  std::vector<double> xyz;
  for (const auto& p : uv)
  {
    xyz.insert(xyz.end(), { o + s * p[0], -o + s * p[1], 3.0 * o });
  }
  std::vector<int32_t> loop = { 0, 1, 2, 3, 4 };
  double area[3];
  pcs::holes::LoopVectorArea(xyz.data(), loop, area);
  CHECK(area[0] == 0.0 && area[1] == 0.0 && area[2] == 3.0 * s * s,
    "area (%g, %g, %g), expected (0, 0, %g)", area[0], area[1], area[2], 3.0 * s * s);
  std::reverse(loop.begin(), loop.end());
  pcs::holes::LoopVectorArea(xyz.data(), loop, area);
  CHECK(area[2] == -3.0 * s * s, "reversed loop's area %g, expected %g", area[2], -3.0 * s * s);
}

// JoinsLoopsAroundTube on one mesh of three pieces: an open cylinder (radius 1, 4 rings of 12
// points), a flat annulus (radii 1 and 2, 12 points each) and a shallow cap (a disc of 12 points
// of radius 1 lifted to the sphere of radius 4: its border is a hole of a curved surface). The two
// rims of the cylinder go around a tube (LV above 0.99, see below); the annulus's loops and the
// cap's border do not (LV 0 and about 0.13), whichever loop they are paired with.
void TestJoinsLoopsAroundTube()
{
  const int m = 12;
  const double pi = std::acos(-1.0);
  std::vector<double> xyz;
  auto angle = [&](int j) { return 2.0 * pi * j / m; };
  for (int k = 0; k < 4; ++k) // cylinder: points k m + j
  {
    for (int j = 0; j < m; ++j)
    {
      xyz.insert(xyz.end(), { std::cos(angle(j)), std::sin(angle(j)), 0.5 * k });
    }
  }
  const int annulus = 4 * m; // inner ring, then outer ring, at z = 10
  for (double radius : { 1.0, 2.0 })
  {
    for (int j = 0; j < m; ++j)
    {
      xyz.insert(xyz.end(), { radius * std::cos(angle(j)), radius * std::sin(angle(j)), 10.0 });
    }
  }
  const int cap = annulus + 2 * m; // centre, then the border ring, on the sphere of radius 4
  xyz.insert(xyz.end(), { 0.0, 0.0, 24.0 });
  for (int j = 0; j < m; ++j)
  {
    xyz.insert(xyz.end(), { std::cos(angle(j)), std::sin(angle(j)), 20.0 + std::sqrt(15.0) });
  }
  pcs::SurfaceMesh mesh(static_cast<int32_t>(xyz.size() / 3));
  bool built = true;
  auto quads = [&](int first, int second)
  {
    for (int j = 0; j < m; ++j)
    {
      const int32_t a = first + j, b = first + (j + 1) % m, c = second + (j + 1) % m,
                    d = second + j;
      built = mesh.AddTriangle(a, b, c) >= 0 && mesh.AddTriangle(a, c, d) >= 0 && built;
    }
  };
  for (int k = 0; k < 3; ++k)
  {
    quads(k * m, (k + 1) * m);
  }
  quads(annulus, annulus + m);
  for (int j = 0; j < m; ++j)
  {
    built = mesh.AddTriangle(cap, cap + 1 + j, cap + 1 + (j + 1) % m) >= 0 && built;
  }
  CHECK(built, "tube test mesh: a triangle was refused");
  // Each loop by one of its boundary half-edges.
  std::map<int, std::pair<int32_t, int32_t>> loops; // first point of the piece's ring -> half-edge
  for (int32_t v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    for (int32_t w = 0; w < mesh.GetNumberOfVertices(); ++w)
    {
      if (v != w && mesh.FindTriangle(v, w) >= 0 && mesh.IsBoundaryHalfEdge(v, w))
      {
        loops.emplace(v < cap ? v - v % m : cap + 1, std::make_pair(v, w));
      }
    }
  }
  CHECK(loops.size() == 5, "tube test mesh: %d loops, expected 5", static_cast<int>(loops.size()));
  if (loops.size() != 5)
  {
    return;
  }
  const auto bottom = loops[0], top = loops[3 * m], inner = loops[annulus],
             outer = loops[annulus + m], rim = loops[cap + 1];
  auto joins = [&](const std::pair<int32_t, int32_t>& e, const std::pair<int32_t, int32_t>& f)
  {
    return pcs::holes::JoinsLoopsAroundTube(mesh, xyz.data(), e.first, e.second, f.first, f.second);
  };
  CHECK(joins(bottom, top) && joins(top, bottom), "the cylinder's rims go around a tube");
  CHECK(!joins(bottom, inner) && !joins(inner, top), "the annulus's inner loop is a hole");
  CHECK(!joins(outer, top) && !joins(inner, outer), "the annulus's loops are not around a tube");
  CHECK(!joins(rim, bottom) && !joins(top, rim), "the cap's border is a hole of a curved surface");
  CHECK(!joins(rim, rim), "the cap's border paired with itself");
}

int main()
{
  TestPolygonPredicates();
  TestGreedy2D();
  TestHoleFiller();
  TestLeastDihedralFill();
  TestLeastDihedralFillSkipsOnlyUntakenSplits();
  TestFillLoopNearSamples();
  TestLoopVectorArea();
  TestDegenerateFills();
  TestTrianglesIntersect();
  TestJoinsLoopsAroundTube();
  std::printf("%d failure(s)\n", Failures);
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
