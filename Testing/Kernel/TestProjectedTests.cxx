// Standalone test of the projected point and edge tests of the constrained Delaunay advancing
// front (Filters/Kernel/pcsProjectedTests.h, paper 003 sections II.B-II.D), compiled together
// with the kernel sources it needs (no VTK).
//
// 1. The configurations of the paper's Fig. 1 (a)-(g), built by hand, give the paper's answers.
// 2. Randomized comparisons with CGAL's exact-construction kernel (Epeck) as the reference, on
//    integer coordinates from a tiny range (so that collinear points, segments through vertices,
//    along edges, of zero length, ... are frequent) and on general doubles:
//    - TrianglePlane::ClassifySegment (2D): "the segment has a point in the open triangle", the
//      reference computing the exact intersection of the segment and the closed triangle and
//      testing whether it reaches the interior;
//    - the same on triangles and segments lying exactly in a tilted 3D plane (z = x + 2y with
//      integer x, y: every point is representable), against CGAL's 3D intersection;
//    - LineCrossesTriangle: the line through p with an integer direction n (so p + n is exact)
//      crosses the open triangle, against the exact intersection of CGAL's Line_3 and Triangle_3;
//    - EdgePlaneSide against CGAL's exact orientation with the same plane point a + normal;
//    - Collinear against CGAL::collinear.
// 3. A small configuration far from the origin (spacing 10^-9 of the coordinates) with directions
//    far shorter than the coordinates (a cross product of short edges, a tiny normal): the
//    constructed second point must not round them away (EdgePlaneSide against CGAL with the
//    exact point a + normal, LineCrossesTriangle on lines that clearly cross or miss).
#include "pcsKernelTest.h"
#include "pcsProjectedTests.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>

namespace
{
namespace T = pcs::projected;
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Vec3 = std::array<double, 3>;

using pcstest::Checks;
using pcstest::Failures;

std::ostream& operator<<(std::ostream& os, const Vec3& p)
{
  os.precision(17);
  return os << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
}

K::Point_2 P2(const Vec3& p)
{
  return K::Point_2(p[0], p[1]);
}
K::Point_3 P3(const Vec3& p)
{
  return K::Point_3(p[0], p[1], p[2]);
}

// Reference: the segment s0 s1 has a point in the open triangle (2D, exact constructions).
bool ReferenceCrossing2D(
  const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& s0, const Vec3& s1)
{
  const K::Triangle_2 triangle(P2(a), P2(b), P2(c));
  if (P2(s0) == P2(s1))
  {
    return triangle.bounded_side(P2(s0)) == CGAL::ON_BOUNDED_SIDE;
  }
  const auto result = CGAL::intersection(K::Segment_2(P2(s0), P2(s1)), triangle);
  if (!result)
  {
    return false;
  }
  if (const K::Point_2* p = boost::get<K::Point_2>(&*result))
  {
    return triangle.bounded_side(*p) == CGAL::ON_BOUNDED_SIDE;
  }
  // A chord of a closed convex set reaches the interior exactly when its midpoint does.
  const K::Segment_2* s = boost::get<K::Segment_2>(&*result);
  return s &&
    triangle.bounded_side(CGAL::midpoint(s->source(), s->target())) == CGAL::ON_BOUNDED_SIDE;
}

// Reference for coplanar 3D input: a point of the segment in the relative interior.
bool InRelativeInterior(const K::Triangle_3& t, const K::Point_3& p)
{
  return t.has_on(p) && !CGAL::collinear(t[0], t[1], p) && !CGAL::collinear(t[1], t[2], p) &&
    !CGAL::collinear(t[2], t[0], p);
}

bool ReferenceCrossing3D(
  const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& s0, const Vec3& s1)
{
  const K::Triangle_3 triangle(P3(a), P3(b), P3(c));
  if (P3(s0) == P3(s1))
  {
    return InRelativeInterior(triangle, P3(s0));
  }
  const auto result = CGAL::intersection(K::Segment_3(P3(s0), P3(s1)), triangle);
  if (!result)
  {
    return false;
  }
  if (const K::Point_3* p = boost::get<K::Point_3>(&*result))
  {
    return InRelativeInterior(triangle, *p);
  }
  const K::Segment_3* s = boost::get<K::Segment_3>(&*result);
  return s && InRelativeInterior(triangle, CGAL::midpoint(s->source(), s->target()));
}

// Reference: the line through p with direction n meets the open triangle in a single point (a
// line lying in the triangle's plane has no projection onto it: not a crossing).
bool ReferenceLineCrossing(
  const Vec3& p, const Vec3& n, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const K::Point_3 q(p[0] + n[0], p[1] + n[1], p[2] + n[2]);
  if (q == P3(p))
  {
    return false;
  }
  const K::Triangle_3 triangle(P3(a), P3(b), P3(c));
  const auto result = CGAL::intersection(K::Line_3(P3(p), q), triangle);
  if (!result)
  {
    return false;
  }
  const K::Point_3* x = boost::get<K::Point_3>(&*result);
  return x && InRelativeInterior(triangle, *x);
}

//------------------------------------------------------------------------------------------------
// 1. The paper's Fig. 1: triangle p1 p2 p3, segment p4 p5 (edge p2 p3 as the general case).
void TestPaperFigure1()
{
  const Vec3 p1{ 0, 4, 0 }, p2{ -4, -2, 0 }, p3{ 4, -2, 0 };
  T::TrianglePlane plane;
  EXPECT(plane.Set(p1.data(), p2.data(), p3.data()), "the triangle of Fig. 1 is not degenerate");
  struct Case
  {
    const char* Name;
    Vec3 P4, P5;
    T::SegmentCase Expected;
  };
  const Case cases[] = {
    // (a) both end points beyond edge p2 p3 (the side without the triangle).
    { "Fig. 1a", { -3, -4, 0 }, { 3, -5, 0 }, T::SegmentCase::SeparatedByTriangleEdge },
    // (b) p4 beyond edge p1 p2, p5 inside edge p1 p3's side, segment passing above the triangle:
    // the virtual triangle (p1, p4, p5) has n . n_virtual <= 0.
    { "Fig. 1b", { -4, 5, 0 }, { 3, 6, 0 }, T::SegmentCase::SeparatedBySegmentLine },
    // (c) the same sides, but the segment cuts the corner at p1: n . n_virtual > 0.
    { "Fig. 1c", { -3, 2, 0 }, { 1, 3.5, 0 }, T::SegmentCase::Crossing },
    // (d) end points beyond different edges, the segment through the triangle.
    { "Fig. 1d", { -6, 1, 0 }, { 6, 0, 0 }, T::SegmentCase::Crossing },
    // (e) end points beyond different edges, the segment passing outside near a vertex.
    { "Fig. 1e", { -6, -1, 0 }, { 1, -7, 0 }, T::SegmentCase::SeparatedBySegmentLine },
    // (f) the segment's line through p3 (n . n_virtual,3 = 0), an end point inside p3's wedge.
    { "Fig. 1f", { 8, -6, 0 }, { 0, 2, 0 }, T::SegmentCase::Crossing },
    // (g) the segment's line through p3, no end point inside p3's wedge.
    { "Fig. 1g", { 8, -6, 0 }, { 6, -4, 0 }, T::SegmentCase::SeparatedByTriangleEdge },
    { "Fig. 1g (through p3)", { 2, -4, 0 }, { 6, 0, 0 }, T::SegmentCase::SeparatedBySegmentLine },
    { "Fig. 1f (through p3)", { 6, -4, 0 }, { 2, 0, 0 }, T::SegmentCase::Crossing },
    // An end point strictly inside.
    { "end point inside", { 0, 0, 0 }, { 10, 10, 0 }, T::SegmentCase::Crossing },
    // Segments sharing a vertex: along an edge (no), into the wedge (yes), out of it (no).
    { "along edge p1 p2", { 0, 4, 0 }, { -2, 1, 0 }, T::SegmentCase::SeparatedByTriangleEdge },
    { "from p1 into the triangle", { 0, 4, 0 }, { 0, -5, 0 }, T::SegmentCase::Crossing },
    { "from p1 away", { 0, 4, 0 }, { 0, 9, 0 }, T::SegmentCase::SeparatedByTriangleEdge },
    { "through p1, outside", { -1, 3, 0 }, { 1, 5, 0 }, T::SegmentCase::SeparatedBySegmentLine },
    { "the edge p2 p3 itself", { -4, -2, 0 }, { 4, -2, 0 },
      T::SegmentCase::SeparatedByTriangleEdge },
  };
  for (const Case& c : cases)
  {
    const T::SegmentCase got = plane.ClassifySegment(c.P4.data(), c.P5.data());
    EXPECT(got == c.Expected,
      c.Name << ": case " << static_cast<int>(got) << " instead of "
             << static_cast<int>(c.Expected));
    EXPECT((got == T::SegmentCase::Crossing) == ReferenceCrossing2D(p1, p2, p3, c.P4, c.P5),
      c.Name << ": disagrees with CGAL");
    // The answer does not depend on the order of the end points or on the triangle's orientation.
    T::TrianglePlane reversed;
    reversed.Set(p1.data(), p3.data(), p2.data());
    EXPECT(reversed.SegmentCrosses(c.P5.data(), c.P4.data()) ==
        plane.SegmentCrosses(c.P4.data(), c.P5.data()),
      c.Name << ": depends on the orientation");
  }
}

//------------------------------------------------------------------------------------------------
// 2. Randomized comparisons.
Vec3 RandomInteger(std::mt19937_64& rng, int range, bool planar)
{
  std::uniform_int_distribution<int> d(-range, range);
  Vec3 p{ double(d(rng)), double(d(rng)), double(d(rng)) };
  if (planar)
  {
    p[2] = 0;
  }
  return p;
}

void TestSegmentsRandom(unsigned seed, int rounds)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int crossings = 0;
  for (int round = 0; round < rounds; ++round)
  {
    Vec3 v[5];
    const bool integer = round % 2 == 0;
    for (Vec3& p : v)
    {
      p = integer ? RandomInteger(rng, 3, true) : Vec3{ u(rng), u(rng), 0.0 };
    }
    if (round % 7 == 0)
    {
      v[3] = v[round % 3]; // a segment from a vertex of the triangle
    }
    T::TrianglePlane plane;
    const bool set = plane.Set(v[0].data(), v[1].data(), v[2].data());
    const bool collinear = CGAL::collinear(P2(v[0]), P2(v[1]), P2(v[2]));
    EXPECT(set == !collinear, "Set on " << v[0] << v[1] << v[2]);
    if (!set)
    {
      continue;
    }
    const bool got = plane.SegmentCrosses(v[3].data(), v[4].data());
    const bool expected = ReferenceCrossing2D(v[0], v[1], v[2], v[3], v[4]);
    crossings += expected ? 1 : 0;
    EXPECT(got == expected,
      "segment " << v[3] << v[4] << " triangle " << v[0] << v[1] << v[2] << ": " << got
                 << " instead of " << expected);
    for (int e = 0; e < 3; ++e)
    {
      const int side = plane.Side(e, v[3].data());
      // Side: the triangle's side of the edge line is where the opposite vertex lies.
      const CGAL::Orientation o = CGAL::orientation(P2(v[e]), P2(v[(e + 1) % 3]), P2(v[3]));
      const CGAL::Orientation third =
        CGAL::orientation(P2(v[e]), P2(v[(e + 1) % 3]), P2(v[(e + 2) % 3]));
      EXPECT(side == static_cast<int>(o) * static_cast<int>(third), "Side " << e);
    }
  }
  EXPECT(crossings > rounds / 20, "too few crossings to exercise the test: " << crossings);
}

// Triangles and segments exactly in the plane z = x + 2 y (tilted: the kept coordinates are not
// x, y), compared with CGAL's 3D intersection.
void TestTiltedPlane(unsigned seed, int rounds)
{
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> d(-4, 4);
  for (int round = 0; round < rounds; ++round)
  {
    Vec3 v[5];
    for (Vec3& p : v)
    {
      p = { double(d(rng)), double(d(rng)), 0.0 };
      p[2] = p[0] + 2 * p[1];
      if (round % 3 == 1)
      {
        std::swap(p[0], p[2]); // the plane x = z + 2y: another dominant axis
      }
    }
    T::TrianglePlane plane;
    if (!plane.Set(v[0].data(), v[1].data(), v[2].data()))
    {
      EXPECT(CGAL::collinear(P3(v[0]), P3(v[1]), P3(v[2])), "Set refused a triangle");
      continue;
    }
    const bool got = plane.SegmentCrosses(v[3].data(), v[4].data());
    const bool expected = ReferenceCrossing3D(v[0], v[1], v[2], v[3], v[4]);
    EXPECT(got == expected,
      "tilted segment " << v[3] << v[4] << " triangle " << v[0] << v[1] << v[2] << ": " << got
                        << " instead of " << expected);
  }
}

void TestLinesRandom(unsigned seed, int rounds)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int crossings = 0;
  for (int round = 0; round < rounds; ++round)
  {
    const bool integer = round % 2 == 0;
    Vec3 v[4];
    for (Vec3& p : v)
    {
      p = integer ? RandomInteger(rng, 3, false) : Vec3{ u(rng), u(rng), u(rng) };
    }
    Vec3 n = RandomInteger(rng, 2, false); // integer direction: p + n is exact
    if (round % 5 == 0)
    {
      v[0] = v[1 + round % 3]; // the line through a vertex of the triangle
    }
    const bool got =
      T::LineCrossesTriangle(v[0].data(), n.data(), v[1].data(), v[2].data(), v[3].data());
    const bool expected = !CGAL::collinear(P3(v[1]), P3(v[2]), P3(v[3])) &&
      ReferenceLineCrossing(v[0], n, v[1], v[2], v[3]);
    crossings += expected ? 1 : 0;
    EXPECT(got == expected,
      "line " << v[0] << " dir " << n << " triangle " << v[1] << v[2] << v[3] << ": " << got
              << " instead of " << expected);
    // RayParameter puts p + t n on the plane (within rounding).
    const Vec3 e1{ v[2][0] - v[1][0], v[2][1] - v[1][1], v[2][2] - v[1][2] };
    const Vec3 e2{ v[3][0] - v[1][0], v[3][1] - v[1][1], v[3][2] - v[1][2] };
    const Vec3 normal{ e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
      e1[0] * e2[1] - e1[1] * e2[0] };
    double t = 0;
    if (got)
    {
      EXPECT(T::RayParameter(v[0].data(), n.data(), v[1].data(), normal.data(), t),
        "no ray parameter for a crossing line");
      const Vec3 x{ v[0][0] + t * n[0], v[0][1] + t * n[1], v[0][2] + t * n[2] };
      const double off =
        (x[0] - v[1][0]) * normal[0] + (x[1] - v[1][1]) * normal[1] + (x[2] - v[1][2]) * normal[2];
      const double scale =
        std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
      EXPECT(std::fabs(off) <= 1e-12 * scale * 16, "projected point off the plane by " << off);
    }
  }
  EXPECT(crossings > rounds / 50, "too few line crossings: " << crossings);
}

void TestEdgePlaneAndCollinear(unsigned seed, int rounds)
{
  std::mt19937_64 rng(seed);
  for (int round = 0; round < rounds; ++round)
  {
    Vec3 v[4];
    for (Vec3& p : v)
    {
      p = RandomInteger(rng, 2, false);
    }
    const Vec3 normal = RandomInteger(rng, 2, false);
    const Vec3 m{ v[0][0] + normal[0], v[0][1] + normal[1], v[0][2] + normal[2] };
    const int got = T::EdgePlaneSide(v[0].data(), v[1].data(), normal.data(), v[3].data());
    const int expected = static_cast<int>(CGAL::orientation(P3(v[0]), P3(v[1]), P3(m), P3(v[3])));
    // pcs Orient3D(a, b, c, d) = det[a - d; b - d; c - d], CGAL's orientation(p, q, r, s) =
    // sign det[q - p; r - p; s - p]: opposite signs.
    EXPECT(got == -expected, "EdgePlaneSide " << got << " vs CGAL " << expected);
    EXPECT(T::Collinear(v[0].data(), v[1].data(), v[2].data()) ==
        CGAL::collinear(P3(v[0]), P3(v[1]), P3(v[2])),
      "Collinear " << v[0] << v[1] << v[2]);
  }
  // A nearly collinear triple that only exact arithmetic separates.
  const Vec3 a{ 0.1, 0.2, 0.3 }, b{ 0.7, 1.4, 2.1 };
  Vec3 c{ 1.3, 2.6, 3.9 };
  EXPECT(T::Collinear(a.data(), b.data(), c.data()) == CGAL::collinear(P3(a), P3(b), P3(c)),
    "near-collinear triple");
  c[2] = std::nextafter(c[2], 10.0);
  EXPECT(!T::Collinear(a.data(), b.data(), c.data()), "one ulp off the line is not collinear");
}

void TestFarFromOrigin(unsigned seed, int rounds)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Vec3 centre{ 10.0, -20.0, 5.0 };
  const double h = 1e-8;
  auto near = [&]() {
    return Vec3{ centre[0] + h * unit(rng), centre[1] + h * unit(rng), centre[2] + h * unit(rng) };
  };
  int compared = 0;
  for (int round = 0; round < rounds; ++round)
  {
    const Vec3 a = near(), b = near(), x = near();
    const Vec3 u{ b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const Vec3 w{ h * unit(rng), h * unit(rng), h * unit(rng) };
    const Vec3 normal{ u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
      u[0] * w[1] - u[1] * w[0] }; // about 10^-16: below the coordinates' last place
    const K::Point_3 m(K::Point_3(a[0], a[1], a[2]) + K::Vector_3(normal[0], normal[1], normal[2]));
    // The exact plane through a, b, a + normal; skip points within 10^-6 h of it (where the
    // rounding of the constructed point may decide).
    const K::Plane_3 plane(P3(a), P3(b), m);
    const K::Vector_3 perpendicular = plane.orthogonal_vector();
    const double distance = CGAL::to_double((P3(x) - P3(a)) * perpendicular) /
      std::sqrt(CGAL::to_double(perpendicular.squared_length()));
    if (!(std::fabs(distance) > 1e-6 * h))
    {
      continue;
    }
    ++compared;
    const int expected = static_cast<int>(CGAL::orientation(P3(a), P3(b), m, P3(x)));
    const int got = T::EdgePlaneSide(a.data(), b.data(), normal.data(), x.data());
    EXPECT(got == -expected, "far EdgePlaneSide " << got << " vs CGAL " << expected);
  }
  EXPECT(compared > rounds / 2, "too few far configurations compared: " << compared);
  // A line along a tiny direction through a point above the centre of a small far triangle
  // crosses it; one beside the triangle does not.
  const Vec3 t0{ centre[0], centre[1], centre[2] }, t1{ centre[0] + h, centre[1], centre[2] },
    t2{ centre[0], centre[1] + h, centre[2] };
  const Vec3 tiny{ 1e-18, -2e-18, -1e-17 };
  const Vec3 above{ centre[0] + 0.3 * h, centre[1] + 0.3 * h, centre[2] + 0.5 * h };
  const Vec3 beside{ centre[0] + 2 * h, centre[1] + 2 * h, centre[2] + 0.5 * h };
  EXPECT(T::LineCrossesTriangle(above.data(), tiny.data(), t0.data(), t1.data(), t2.data()),
    "a tiny direction far from the origin: the line through the triangle does not cross it");
  EXPECT(!T::LineCrossesTriangle(beside.data(), tiny.data(), t0.data(), t1.data(), t2.data()),
    "a tiny direction far from the origin: the line beside the triangle crosses it");
}
} // namespace

int main(int argc, char* argv[])
{
  const int rounds = argc > 1 ? std::atoi(argv[1]) : 20000;
  TestPaperFigure1();
  TestSegmentsRandom(1, rounds);
  TestTiltedPlane(2, rounds);
  TestLinesRandom(3, rounds);
  TestEdgePlaneAndCollinear(4, rounds);
  TestFarFromOrigin(5, rounds / 10);
  std::cout << Checks << " checks, " << Failures << " failure(s)" << std::endl;
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
