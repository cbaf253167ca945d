// Standalone test of the front/edge topology kernel (Filters/Kernel/pcsSurfaceMesh.h), compiled
// with Filters/Kernel/pcsSurfaceMesh.cxx alone (no VTK, no geometry).
//
// Every expectation is known by construction: an octahedron (closed, every vertex interior, 12
// edges of valence 2), an open fan and its ear, pinches and third triangles on an edge that must
// be refused, the boundary loops of a grid patch with and without a hole (lengths 2(n+m) and the
// hole's perimeter), a torus grid added in random order (closed, V - E + F = 0), random add/remove
// sequences that end empty, and component reversal. After every change the cached structure is
// compared with an independent recomputation from the triangle list (CheckConsistency).
#include "pcsKernelTest.h"
#include "pcsSurfaceMesh.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <iostream>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace
{
using pcs::SurfaceMesh;
using Check = SurfaceMesh::Check;
using State = SurfaceMesh::VertexState;

using pcstest::Checks;
using pcstest::Failures;

void ExpectConsistent(const SurfaceMesh& mesh, const std::string& where)
{
  std::string why;
  const bool ok = mesh.CheckConsistency(&why);
  EXPECT(ok, where << ": " << why);
}

// Every consecutive pair of a loop is a front edge, and the loop's edges are all distinct.
void ExpectValidLoops(
  const SurfaceMesh& mesh, const std::vector<std::vector<int32_t>>& loops, const std::string& where)
{
  std::set<std::pair<int32_t, int32_t>> seen;
  size_t total = 0;
  for (const auto& loop : loops)
  {
    for (size_t i = 0; i < loop.size(); ++i)
    {
      const int32_t a = loop[i], b = loop[(i + 1) % loop.size()];
      EXPECT(mesh.IsBoundaryHalfEdge(a, b), where << ": " << a << "->" << b << " not a front edge");
      EXPECT(seen.insert({ a, b }).second, where << ": edge listed twice");
      ++total;
    }
  }
  EXPECT(static_cast<int64_t>(total) == mesh.GetNumberOfBoundaryHalfEdges(),
    where << ": loops hold " << total << " edges, the mesh "
          << mesh.GetNumberOfBoundaryHalfEdges());
}

//------------------------------------------------------------------------------------------------
void TestOctahedron()
{
  // 0:+x 1:-x 2:+y 3:-y 4:+z 5:-z, faces oriented outwards.
  const std::array<std::array<int32_t, 3>, 8> faces = { { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 },
    { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } } };
  SurfaceMesh mesh(6);
  for (const auto& f : faces)
  {
    EXPECT(mesh.CanAddTriangle(f[0], f[1], f[2]) == Check::Ok, "octahedron face refused");
    EXPECT(mesh.AddTriangle(f[0], f[1], f[2]) >= 0, "octahedron face not added");
    ExpectConsistent(mesh, "octahedron");
  }
  EXPECT(mesh.GetNumberOfTriangles() == 8, "8 faces");
  EXPECT(mesh.GetNumberOfBoundaryHalfEdges() == 0, "closed");
  int edges = 0;
  for (int32_t a = 0; a < 6; ++a)
  {
    EXPECT(mesh.GetVertexState(a) == State::Interior, "vertex " << a << " interior");
    EXPECT(mesh.GetNumberOfFans(a) == 1, "one fan at " << a);
    EXPECT(mesh.GetVertexDegree(a) == 4, "degree 4 at " << a);
    for (int32_t b = a + 1; b < 6; ++b)
    {
      const int valence = mesh.GetEdgeValence(a, b);
      const bool opposite = (a / 2 == b / 2); // +x/-x, +y/-y, +z/-z are not joined
      EXPECT(valence == (opposite ? 0 : 2), "valence of " << a << "-" << b << " = " << valence);
      edges += valence > 0 ? 1 : 0;
    }
  }
  EXPECT(edges == 12, "12 edges");
  std::vector<std::vector<int32_t>> loops;
  mesh.GetBoundaryLoops(loops);
  EXPECT(loops.empty(), "no boundary loop");
  // Any face again, in either orientation, uses a half-edge that exists.
  for (const auto& f : faces)
  {
    EXPECT(mesh.CanAddTriangle(f[0], f[1], f[2]) == Check::HalfEdgeUsed, "duplicate face");
    EXPECT(mesh.CanAddTriangle(f[0], f[2], f[1]) == Check::HalfEdgeUsed, "reversed face");
    EXPECT(mesh.AddTriangle(f[0], f[2], f[1]) == -1, "reversed face added");
  }
  EXPECT(mesh.CanAddTriangle(0, 0, 1) == Check::RepeatedVertex, "repeated vertex");
  EXPECT(mesh.CanAddTriangle(0, 1, 6) == Check::InvalidVertex, "vertex out of range");
  // The opposite pair 0-1 is not an edge; a triangle on it touches interior vertices only.
  EXPECT(mesh.CanAddTriangle(0, 1, 2) != Check::Ok, "triangle at interior vertices");
  // Remove one face: a 3-edge hole whose loop is the face reversed.
  mesh.RemoveTriangle(0);
  ExpectConsistent(mesh, "octahedron minus a face");
  mesh.GetBoundaryLoops(loops);
  EXPECT(loops.size() == 1 && loops[0].size() == 3, "one loop of 3 edges");
  ExpectValidLoops(mesh, loops, "octahedron hole");
  EXPECT(
    mesh.IsBoundaryHalfEdge(2, 0) && mesh.IsBoundaryHalfEdge(4, 2) && mesh.IsBoundaryHalfEdge(0, 4),
    "hole edges are the removed face reversed");
  EXPECT(mesh.NextBoundaryVertex(2, 0) == 4 && mesh.PreviousBoundaryVertex(2, 0) == 4,
    "next/previous around a 3-loop");
  EXPECT(mesh.CanAddTriangle(0, 2, 4) == Check::Ok, "the face closes its hole");
  EXPECT(mesh.CanAddTriangle(0, 4, 2) == Check::HalfEdgeUsed, "wrong orientation refused");
  mesh.AddTriangle(0, 2, 4);
  EXPECT(mesh.GetNumberOfBoundaryHalfEdges() == 0, "closed again");
  ExpectConsistent(mesh, "octahedron closed again");
}

//------------------------------------------------------------------------------------------------
void TestFanEarPinch()
{
  // Centre 0, ring 1..6 counter-clockwise; free vertices 7..12.
  SurfaceMesh mesh(13);
  for (int32_t i = 1; i <= 5; ++i)
  {
    EXPECT(mesh.CanAddTriangle(0, i, i + 1) == Check::Ok, "fan triangle " << i);
    mesh.AddTriangle(0, i, i + 1);
  }
  ExpectConsistent(mesh, "open fan");
  EXPECT(mesh.GetVertexState(0) == State::Boundary && mesh.GetNumberOfFans(0) == 1, "open fan");
  EXPECT(mesh.GetVertexState(7) == State::Free && mesh.GetNumberOfFans(7) == 0, "free");
  EXPECT(mesh.GetNumberOfBoundaryHalfEdges() == 7, "7 front edges");
  std::vector<std::vector<int32_t>> loops;
  mesh.GetBoundaryLoops(loops);
  EXPECT(loops.size() == 1 && loops[0].size() == 7, "one loop of 7");
  ExpectValidLoops(mesh, loops, "fan");
  EXPECT(mesh.NextBoundaryVertex(1, 2) == 3, "next of 1->2");
  EXPECT(mesh.NextBoundaryVertex(5, 6) == 0, "next of 5->6");
  EXPECT(mesh.NextBoundaryVertex(6, 0) == 1, "next of 6->0 turns around the centre");
  EXPECT(mesh.PreviousBoundaryVertex(0, 1) == 6, "previous of 0->1");
  EXPECT(mesh.PreviousBoundaryVertex(2, 3) == 1, "previous of 2->3");
  EXPECT(mesh.NextBoundaryVertex(0, 2) == -1, "not a front edge");
  EXPECT(mesh.OppositeVertex(2, 3) == 0 && mesh.FindTriangle(2, 3) == 1, "triangle of 2->3");
  EXPECT(mesh.OppositeVertex(3, 2) == -1 && mesh.FindTriangle(3, 2) == -1, "no triangle on 3->2");
  int32_t out[4], in[4];
  EXPECT(mesh.GetBoundaryOutVertices(0, out, 4) == 1 && out[0] == 1, "front edge 0->1");
  EXPECT(mesh.GetBoundaryInVertices(0, in, 4) == 1 && in[0] == 6, "front edge 6->0");
  EXPECT(mesh.GetBoundaryOutVertices(3, out, 4) == 1 && out[0] == 4, "front edge 3->4");

  // Extension: a free vertex on front edge 2->3 gives (3, 2, 7).
  EXPECT(mesh.CanAddTriangle(3, 2, 7) == Check::Ok, "extension");
  // Same orientation as the existing triangle on 2->3: refused.
  EXPECT(mesh.CanAddTriangle(2, 3, 7) == Check::HalfEdgeUsed, "orientation conflict");
  // Pinches: touching vertex 3 (on the front) or vertex 0 only at the vertex.
  int32_t offending = -1;
  EXPECT(mesh.CanAddTriangle(3, 8, 9, &offending) == Check::NonManifoldVertex && offending == 3,
    "pinch at 3 (offending " << offending << ")");
  EXPECT(mesh.CanAddTriangle(9, 8, 0, &offending) == Check::NonManifoldVertex && offending == 0,
    "pinch at 0");
  // A triangle on the front edge 2->3 whose third vertex is a non-adjacent front vertex: pinch.
  EXPECT(mesh.CanAddTriangle(3, 2, 5, &offending) == Check::NonManifoldVertex && offending == 5,
    "bridge to vertex 5 is a pinch");

  // The ear at 0 closes the fan: 0 becomes interior.
  EXPECT(mesh.CanAddTriangle(0, 6, 1) == Check::Ok, "ear");
  mesh.AddTriangle(0, 6, 1);
  ExpectConsistent(mesh, "after the ear");
  EXPECT(mesh.GetVertexState(0) == State::Interior, "centre interior after the ear");
  mesh.GetBoundaryLoops(loops);
  EXPECT(loops.size() == 1 && loops[0].size() == 6, "hexagon loop");
  ExpectValidLoops(mesh, loops, "hexagon");
  EXPECT(mesh.CanAddTriangle(0, 8, 9, &offending) == Check::NonManifoldVertex && offending == 0,
    "interior vertex refuses triangles");

  // A third triangle on an edge: 1-2 has (0,1,2); add (2,1,7), then any other on 1-2 is refused.
  EXPECT(mesh.CanAddTriangle(2, 1, 7) == Check::Ok, "second triangle on 1-2");
  mesh.AddTriangle(2, 1, 7);
  EXPECT(mesh.GetEdgeValence(1, 2) == 2, "valence 2");
  EXPECT(mesh.CanAddTriangle(1, 2, 8) == Check::HalfEdgeUsed, "third triangle (1,2,8)");
  EXPECT(mesh.CanAddTriangle(2, 1, 8) == Check::HalfEdgeUsed, "third triangle (2,1,8)");

  // A pinch added deliberately, then repaired by the ear on one side: the fans merge. Front
  // here: ... 6->1->7->2->3->4 ...; the bridge triangle (4, 3, 6) on 3->4 touches 6 only.
  EXPECT(mesh.CanAddTriangle(4, 3, 6, &offending) == Check::NonManifoldVertex && offending == 6,
    "bridge to 6");
  const int64_t bridge = mesh.AddTriangle(4, 3, 6);
  EXPECT(bridge >= 0, "pinch added on request");
  ExpectConsistent(mesh, "pinch");
  EXPECT(mesh.GetNumberOfFans(6) == 2, "two fans at the pinch");
  mesh.GetBoundaryLoops(loops);
  // Turning around each fan, the walk passes the pinch twice: one loop 6->1->7->2->3->6->4->5.
  EXPECT(loops.size() == 1 && loops[0].size() == 8 &&
      std::count(loops[0].begin(), loops[0].end(), 6) == 2,
    "one loop through the pinch twice");
  ExpectValidLoops(mesh, loops, "pinch");
  // Closing the small side 6->4->5->6 with (6, 5, 4) merges the two fans of 6.
  EXPECT(mesh.IsBoundaryHalfEdge(3, 6) && mesh.IsBoundaryHalfEdge(6, 4), "bridge front edges");
  EXPECT(mesh.CanAddTriangle(6, 5, 4) == Check::Ok, "ear repairing the pinch");
  mesh.AddTriangle(6, 5, 4);
  ExpectConsistent(mesh, "pinch repaired");
  EXPECT(mesh.GetNumberOfFans(6) == 1, "one fan after the repair");
  // Removal of the bridge restores the pinch-free state of the ear's vertices.
  mesh.RemoveTriangle(bridge);
  ExpectConsistent(mesh, "bridge removed");
}

//------------------------------------------------------------------------------------------------
// Grid patch of nx x ny cells (vertex (i, j) = j * (nx + 1) + i), two triangles per cell,
// oriented counter-clockwise seen from +z; cells in `skip` are left out.
std::vector<std::array<int32_t, 3>> GridTriangles(
  int nx, int ny, const std::set<std::pair<int, int>>& skip, bool wrap)
{
  std::vector<std::array<int32_t, 3>> triangles;
  const int columns = wrap ? nx : nx + 1;
  const int rows = wrap ? ny : ny + 1;
  auto id = [&](
              int i, int j) { return static_cast<int32_t>((j % rows) * columns + (i % columns)); };
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      if (skip.count({ i, j }))
      {
        continue;
      }
      triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return triangles;
}

void TestGridLoops()
{
  std::mt19937 rng(7);
  const int nx = 7, ny = 5;
  const int32_t vertices = (nx + 1) * (ny + 1);
  for (int withHole = 0; withHole < 2; ++withHole)
  {
    std::set<std::pair<int, int>> skip;
    if (withHole)
    {
      for (int j = 2; j <= 3; ++j)
      {
        for (int i = 2; i <= 4; ++i)
        {
          skip.insert({ i, j }); // a 3 x 2 hole, perimeter 10
        }
      }
    }
    auto triangles = GridTriangles(nx, ny, skip, false);
    std::shuffle(triangles.begin(), triangles.end(), rng);
    SurfaceMesh mesh(vertices);
    int pinches = 0;
    for (const auto& t : triangles)
    {
      const Check check = mesh.CanAddTriangle(t[0], t[1], t[2]);
      EXPECT(check == Check::Ok || check == Check::NonManifoldVertex, "grid triangle refused");
      pinches += check == Check::NonManifoldVertex ? 1 : 0;
      mesh.AddTriangle(t[0], t[1], t[2]);
      ExpectConsistent(mesh, "grid");
    }
    EXPECT(pinches > 0, "random order makes temporary pinches (the test exercises them)");
    std::vector<std::vector<int32_t>> loops;
    mesh.GetBoundaryLoops(loops);
    ExpectValidLoops(mesh, loops, "grid");
    std::vector<size_t> lengths;
    for (const auto& loop : loops)
    {
      lengths.push_back(loop.size());
    }
    std::sort(lengths.begin(), lengths.end());
    const std::vector<size_t> expected =
      withHole ? std::vector<size_t>{ 10, 2 * (nx + ny) } : std::vector<size_t>{ 2 * (nx + ny) };
    EXPECT(lengths == expected, "grid loops (hole " << withHole << ")");
    for (int32_t v = 0; v < vertices; ++v)
    {
      // The two vertices inside the hole have no triangle.
      const bool inside = withHole && (v == 3 * (nx + 1) + 3 || v == 3 * (nx + 1) + 4);
      EXPECT(mesh.GetNumberOfFans(v) == (inside ? 0 : 1), "grid vertex " << v << " fans");
    }
    // The outer loop runs counter-clockwise: corner 0 is followed by vertex 1.
    EXPECT(mesh.IsBoundaryHalfEdge(0, 1) && mesh.NextBoundaryVertex(0, 1) == 2, "outer loop");
  }
}

//------------------------------------------------------------------------------------------------
void TestTorusAndRemoval()
{
  std::mt19937 rng(11);
  const int nx = 9, ny = 6;
  auto triangles = GridTriangles(nx, ny, {}, true);
  std::shuffle(triangles.begin(), triangles.end(), rng);
  SurfaceMesh mesh(nx * ny);
  std::vector<int64_t> ids;
  for (const auto& t : triangles)
  {
    ids.push_back(mesh.AddTriangle(t[0], t[1], t[2]));
    EXPECT(ids.back() >= 0, "torus triangle added");
    ExpectConsistent(mesh, "torus");
  }
  EXPECT(mesh.GetNumberOfBoundaryHalfEdges() == 0, "torus closed");
  int64_t edges = 0;
  for (int32_t a = 0; a < nx * ny; ++a)
  {
    EXPECT(mesh.GetVertexState(a) == State::Interior && mesh.GetNumberOfFans(a) == 1,
      "torus vertex interior");
    for (int32_t b = a + 1; b < nx * ny; ++b)
    {
      edges += mesh.GetEdgeValence(a, b) > 0 ? 1 : 0;
    }
  }
  EXPECT(nx * ny - edges + mesh.GetNumberOfTriangles() == 0, "Euler characteristic 0");

  // Random removals and re-additions, then remove everything: the structure ends empty.
  std::vector<char> present(ids.size(), 1);
  for (int step = 0; step < 400; ++step)
  {
    const size_t k = rng() % ids.size();
    if (present[k])
    {
      mesh.RemoveTriangle(ids[k]);
      present[k] = 0;
    }
    else
    {
      const auto& t = triangles[k];
      ids[k] = mesh.AddTriangle(t[0], t[1], t[2]);
      EXPECT(ids[k] >= 0, "re-added");
      present[k] = 1;
    }
    ExpectConsistent(mesh, "random add/remove");
  }
  for (size_t k = 0; k < ids.size(); ++k)
  {
    if (present[k])
    {
      mesh.RemoveTriangle(ids[k]);
    }
  }
  ExpectConsistent(mesh, "all removed");
  EXPECT(mesh.GetNumberOfTriangles() == 0 && mesh.GetNumberOfBoundaryHalfEdges() == 0, "empty");
  for (int32_t a = 0; a < nx * ny; ++a)
  {
    EXPECT(mesh.GetVertexState(a) == State::Free && mesh.GetVertexDegree(a) == 0, "all free");
  }
}

//------------------------------------------------------------------------------------------------
void TestReverseComponent()
{
  // Two squares (0,1,2,3) and (4,5,6,7) side by side sharing no vertex, the second one built
  // with the opposite orientation; a strip between edge 1-2 and edge 4-7 needs the second one
  // reversed first.
  SurfaceMesh mesh(8);
  mesh.AddTriangle(0, 1, 2);
  mesh.AddTriangle(0, 2, 3);
  const int64_t second = mesh.AddTriangle(4, 6, 5); // clockwise
  mesh.AddTriangle(4, 7, 6);
  ExpectConsistent(mesh, "two squares");
  // The strip (2, 1, 4) + (2, 4, 7): the second triangle must own 4->7, which the clockwise
  // square already owns: refused until that square is reversed.
  mesh.AddTriangle(2, 1, 4); // a pinch at 4, repaired by the second strip triangle
  EXPECT(mesh.CanAddTriangle(2, 4, 7) == Check::HalfEdgeUsed, "opposite orientations refuse");
  EXPECT(mesh.ReverseComponent(second) == 2, "the second square has 2 triangles");
  ExpectConsistent(mesh, "reversed");
  EXPECT(mesh.GetTriangle(second)[1] == 5 && mesh.GetTriangle(second)[2] == 6, "mirrored");
  EXPECT(mesh.CanAddTriangle(2, 4, 7) == Check::Ok, "the strip closes after the reversal");
  mesh.AddTriangle(2, 4, 7);
  ExpectConsistent(mesh, "merged");
  std::vector<std::vector<int32_t>> loops;
  mesh.GetBoundaryLoops(loops);
  EXPECT(loops.size() == 1 && loops[0].size() == 8, "one loop of 8 around the merged strip");
  for (int32_t v = 0; v < 8; ++v)
  {
    EXPECT(mesh.GetNumberOfFans(v) == 1, "manifold vertex " << v);
  }
  // Reversed again, from either square: each call finds the whole component (its visited flags
  // are kept between calls and must be cleared after each).
  EXPECT(mesh.ReverseComponent(second) == 6, "the merged strip has 6 triangles");
  EXPECT(mesh.ReverseComponent(0) == 6, "all 6 again from the first square");
  ExpectConsistent(mesh, "reversed twice");
  EXPECT(mesh.GetTriangle(second)[1] == 5 && mesh.GetTriangle(second)[2] == 6, "as merged");
}

// AddTriangles: a fan added in an order that pinches its centre until the last triangle is
// accepted; a set that leaves a vertex with two fans is refused and the mesh is unchanged.
void TestAddTriangles()
{
  // Hexagon 1..6 around centre 0, triangles (0, i, i + 1); (0, 1, 2) and (0, 4, 5) first, so 0
  // has two fans until the others close its fan.
  SurfaceMesh mesh(7);
  std::vector<int64_t> added;
  const int32_t fan[] = { 0, 1, 2, 0, 4, 5, 0, 2, 3, 0, 3, 4, 0, 5, 6, 0, 6, 1 };
  EXPECT(mesh.AddTriangles(fan, 6, added), "a closed fan is accepted whatever the order");
  EXPECT(added.size() == 6 && mesh.GetNumberOfTriangles() == 6, "six triangles added");
  EXPECT(mesh.GetNumberOfFans(0) == 1, "the centre has one fan");
  ExpectConsistent(mesh, "fan");

  SurfaceMesh pinch(7);
  const int32_t two[] = { 0, 1, 2, 0, 4, 5 };
  EXPECT(!pinch.AddTriangles(two, 2, added), "two fans at vertex 0 are refused");
  EXPECT(pinch.GetNumberOfTriangles() == 0 && pinch.GetNumberOfBoundaryHalfEdges() == 0 &&
      pinch.GetNumberOfFans(0) == 0,
    "the refused set leaves the mesh empty");
  ExpectConsistent(pinch, "refused pinch");

  // A half-edge used twice: the second triangle is refused, the first removed again.
  const int32_t twice[] = { 0, 1, 2, 0, 1, 3 };
  EXPECT(!pinch.AddTriangles(twice, 2, added), "a repeated half-edge is refused");
  EXPECT(pinch.GetNumberOfTriangles() == 0, "nothing left after the refusal");
  EXPECT(pinch.AddTriangles(twice, 0, added) && added.empty(), "no triangle: success, no change");
}
} // namespace

int main()
{
  TestOctahedron();
  TestFanEarPinch();
  TestGridLoops();
  TestTorusAndRemoval();
  TestReverseComponent();
  TestAddTriangles();
  std::cout << Checks << " checks, " << Failures << " failures" << std::endl;
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
