// vtkReconstructionQuality on meshes whose measures are known by construction:
// - a closed octahedron (Euler 2, genus 0, orientation 1) with unused points (Coverage);
// - a 12 x 8 torus grid (Euler 0, genus 1), the torus and the octahedron together (2 closed
//   components, genus 0 + 1), the 6-vertex projective plane (closed, manifold, non-orientable:
//   genus -1);
// - one flipped triangle in the octahedron and in the torus: (E - 3) / E consistent edges;
// - an open n x m grid (2(n + m) boundary edges, 1 loop, Euler 1), the grid with a hole (2 loops,
//   Euler 0), with two holes touching at a corner (a pinched vertex, one merged hole), a bowtie;
// - a closed genus-2 voxel slab (two holes) and a Moebius strip (one boundary loop, one
//   inconsistent edge);
// - three triangles on one edge, two closed cones touching at their tip;
// - degenerate (collapsed, exactly collinear) and duplicate triangles, an almost-collinear one
//   that is not degenerate;
// - empty input, points without triangles, non-triangle polygons: warnings, valid output;
// - distances between parallel planes at distance d (reference surface and reference cloud, in
//   general position, with a reference wider than the mesh) and the same results with the
//   STDThread SMP backend;
// - distances between two parallel fans of long thin triangles (all meeting at one point);
// - coordinates of 1e300 and 1e-300 (same measures, scaled), a NaN point in a reference cloud.
#include "vtkReconstructionQuality.h"

#include "pcsQualityTestUtilities.h"
#include "pcsTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkMath.h"
#include "vtkSMPTools.h"
#include "vtkSignedCharArray.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>

namespace
{
using pcsqtest::Counter;
using pcsqtest::Field;
using pcsqtest::Mesh;
using pcsqtest::Run;
using pcsqtest::Tri;

// Octahedron with vertices on the axes, outward-oriented (counter-clockwise seen from outside).
Mesh Octahedron(double radius = 1.0)
{
  Mesh m;
  m.AddPoint(radius, 0, 0);  // 0 +x
  m.AddPoint(-radius, 0, 0); // 1 -x
  m.AddPoint(0, radius, 0);  // 2 +y
  m.AddPoint(0, -radius, 0); // 3 -y
  m.AddPoint(0, 0, radius);  // 4 +z
  m.AddPoint(0, 0, -radius); // 5 -z
  m.Triangles = { { { 0, 2, 4 } }, { { 2, 1, 4 } }, { { 1, 3, 4 } }, { { 3, 0, 4 } },
    { { 2, 0, 5 } }, { { 1, 2, 5 } }, { { 3, 1, 5 } }, { { 0, 3, 5 } } };
  return m;
}

// Torus grid of nu x nv vertices (wrap-around in both directions), each quad split in two
// consistently oriented triangles: V = nu nv, F = 2 nu nv, E = 3 nu nv.
Mesh Torus(int nu, int nv, double major = 3.0, double minor = 1.0)
{
  Mesh m;
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const double u = 2.0 * vtkMath::Pi() * i / nu, v = 2.0 * vtkMath::Pi() * j / nv;
      m.AddPoint((major + minor * std::cos(v)) * std::cos(u),
        (major + minor * std::cos(v)) * std::sin(u), minor * std::sin(v));
    }
  }
  auto id = [nu, nv](int i, int j) { return static_cast<vtkIdType>((i % nu) * nv + (j % nv)); };
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const vtkIdType a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      m.Triangles.push_back({ { a, b, c } });
      m.Triangles.push_back({ { a, c, d } });
    }
  }
  return m;
}

// Planar grid of n x m quads of side h at height z (point (i, j) has id i (m + 1) + j), each quad
// split along its (i, j)-(i+1, j+1) diagonal; quads listed in `skip` are left out.
Mesh Grid(
  int n, int m, double h = 1.0, double z = 0.0, const std::vector<std::pair<int, int>>& skip = {})
{
  Mesh g;
  for (int i = 0; i <= n; ++i)
  {
    for (int j = 0; j <= m; ++j)
    {
      g.AddPoint(i * h, j * h, z);
    }
  }
  auto id = [m](int i, int j) { return static_cast<vtkIdType>(i * (m + 1) + j); };
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < m; ++j)
    {
      if (std::find(skip.begin(), skip.end(), std::make_pair(i, j)) != skip.end())
      {
        continue;
      }
      g.Triangles.push_back({ { id(i, j), id(i + 1, j), id(i + 1, j + 1) } });
      g.Triangles.push_back({ { id(i, j), id(i + 1, j + 1), id(i, j + 1) } });
    }
  }
  return g;
}

// Closed cone: apex, a ring of k points, the centre of its base; lateral and base triangles
// oriented outwards. V = k + 2, E = 3k, F = 2k.
Mesh Cone(int k, double height)
{
  Mesh m;
  m.AddPoint(0, 0, 0); // apex, id 0
  for (int i = 0; i < k; ++i)
  {
    const double a = 2.0 * vtkMath::Pi() * i / k;
    m.AddPoint(std::cos(a), std::sin(a), height);
  }
  const vtkIdType centre = m.AddPoint(0, 0, height);
  for (int i = 0; i < k; ++i)
  {
    const vtkIdType r0 = 1 + i, r1 = 1 + (i + 1) % k;
    // Seen from outside, the lateral triangle of a cone opening downwards (height < 0) runs
    // apex -> r0 -> r1; opening upwards the other way round. Only consistency matters here.
    if (height < 0)
    {
      m.Triangles.push_back({ { 0, r0, r1 } });
      m.Triangles.push_back({ { centre, r1, r0 } });
    }
    else
    {
      m.Triangles.push_back({ { 0, r1, r0 } });
      m.Triangles.push_back({ { centre, r0, r1 } });
    }
  }
  return m;
}

bool Near(double a, double b, double tolerance = 1e-9)
{
  return std::fabs(a - b) <= tolerance;
}

// Expected topological field data.
struct Topology
{
  vtkIdType Triangles, UsedPoints, NonManifoldEdges, NonManifoldVertices, BoundaryEdges,
    BoundaryLoops, Components, Euler, Genus, Degenerate = 0, Duplicates = 0;
};

bool CheckTopology(vtkPolyData* out, const Topology& e, const std::string& label)
{
  using pcstest::FieldCount;
  PCS_CHECK(FieldCount(out, "NumberOfTriangles") == e.Triangles, label << ": triangles");
  PCS_CHECK(FieldCount(out, "NumberOfUsedPoints") == e.UsedPoints, label << ": used points");
  PCS_CHECK(FieldCount(out, "NumberOfNonManifoldEdges") == e.NonManifoldEdges,
    label << ": non-manifold edges " << FieldCount(out, "NumberOfNonManifoldEdges"));
  PCS_CHECK(FieldCount(out, "NumberOfNonManifoldVertices") == e.NonManifoldVertices,
    label << ": non-manifold vertices " << FieldCount(out, "NumberOfNonManifoldVertices"));
  PCS_CHECK(FieldCount(out, "NumberOfBoundaryEdges") == e.BoundaryEdges,
    label << ": boundary edges " << FieldCount(out, "NumberOfBoundaryEdges"));
  PCS_CHECK(FieldCount(out, "NumberOfBoundaryLoops") == e.BoundaryLoops,
    label << ": boundary loops " << FieldCount(out, "NumberOfBoundaryLoops"));
  PCS_CHECK(FieldCount(out, "NumberOfConnectedComponents") == e.Components,
    label << ": components " << FieldCount(out, "NumberOfConnectedComponents"));
  PCS_CHECK(FieldCount(out, "EulerCharacteristic") == e.Euler,
    label << ": Euler characteristic " << FieldCount(out, "EulerCharacteristic"));
  PCS_CHECK(FieldCount(out, "Genus") == e.Genus, label << ": genus " << FieldCount(out, "Genus"));
  PCS_CHECK(FieldCount(out, "NumberOfDegenerateTriangles") == e.Degenerate,
    label << ": degenerate " << FieldCount(out, "NumberOfDegenerateTriangles"));
  PCS_CHECK(FieldCount(out, "NumberOfDuplicateTriangles") == e.Duplicates,
    label << ": duplicates " << FieldCount(out, "NumberOfDuplicateTriangles"));

  // Cell data agrees with the counts: every boundary (non-manifold) edge is counted by each of
  // its 1 (3 or more) triangles; here every non-manifold edge has exactly 3.
  auto* boundary = vtkSignedCharArray::SafeDownCast(out->GetCellData()->GetArray("BoundaryEdge"));
  auto* nonManifold =
    vtkSignedCharArray::SafeDownCast(out->GetCellData()->GetArray("NonManifoldEdge"));
  auto* used = vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("Used"));
  auto* fans =
    vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("NonManifoldVertex"));
  PCS_CHECK(boundary && nonManifold && used && fans, label << ": arrays present");
  vtkIdType boundarySum = 0, nonManifoldSum = 0, usedSum = 0, fanSum = 0;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    boundarySum += std::max(0, static_cast<int>(boundary->GetValue(c)));
    nonManifoldSum += std::max(0, static_cast<int>(nonManifold->GetValue(c)));
  }
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    usedSum += used->GetValue(p);
    fanSum += fans->GetValue(p);
  }
  PCS_CHECK(boundarySum == e.BoundaryEdges, label << ": sum of BoundaryEdge " << boundarySum);
  PCS_CHECK(nonManifoldSum == 3 * e.NonManifoldEdges,
    label << ": sum of NonManifoldEdge " << nonManifoldSum);
  PCS_CHECK(usedSum == e.UsedPoints, label << ": sum of Used");
  PCS_CHECK(fanSum == e.NonManifoldVertices, label << ": sum of NonManifoldVertex");
  return true;
}

//------------------------------------------------------------------------------------------------
bool TestClosedSurfaces()
{
  // Octahedron: V 6, E 12, F 8; two unused points -> Coverage 6 / 8; all angles 60 degrees.
  {
    Mesh m = Octahedron();
    m.AddPoint(5, 5, 5);
    m.AddPoint(-5, 5, 5);
    auto out = Run(m.PolyData());
    if (!CheckTopology(out, { 8, 6, 0, 0, 0, 0, 1, 2, 0 }, "octahedron"))
    {
      return false;
    }
    PCS_CHECK(Field(out, "OrientationConsistency") == 1.0, "octahedron: orientation");
    PCS_CHECK(
      Field(out, "Coverage") == 6.0 / 8.0, "octahedron: coverage " << Field(out, "Coverage"));
    PCS_CHECK(Near(Field(out, "MinAngleP1"), 60.0), "octahedron: MinAngleP1");
    auto* used = out->GetPointData()->GetArray("Used");
    PCS_CHECK(used->GetTuple1(6) == 0 && used->GetTuple1(7) == 0 && used->GetTuple1(0) == 1,
      "octahedron: Used flags");
    auto* angles = out->GetCellData()->GetArray("MinAngle");
    for (vtkIdType c = 0; c < 8; ++c)
    {
      PCS_CHECK(Near(angles->GetTuple1(c), 60.0), "octahedron: MinAngle of cell " << c);
    }
    PCS_CHECK(!out->GetFieldData()->GetArray("AccuracyMean"), "no distances without reference");
    PCS_CHECK(!out->GetPointData()->GetArray("DistanceToReference"), "no point distances");

    // One flipped triangle: its 3 edges become inconsistent among E = 12 interior edges.
    std::swap(m.Triangles[3][1], m.Triangles[3][2]);
    out = Run(m.PolyData());
    PCS_CHECK(Field(out, "OrientationConsistency") == 9.0 / 12.0,
      "flipped octahedron: orientation " << Field(out, "OrientationConsistency"));
    PCS_CHECK(pcstest::FieldCount(out, "Genus") == 0, "flipped octahedron: still genus 0");
  }

  // Torus 12 x 8: V 96, F 192, E 288, chi 0, genus 1.
  {
    Mesh m = Torus(12, 8);
    auto out = Run(m.PolyData());
    if (!CheckTopology(out, { 192, 96, 0, 0, 0, 0, 1, 0, 1 }, "torus"))
    {
      return false;
    }
    PCS_CHECK(Field(out, "OrientationConsistency") == 1.0, "torus: orientation");
    PCS_CHECK(Field(out, "Coverage") == 1.0, "torus: coverage");

    std::swap(m.Triangles[17][0], m.Triangles[17][1]);
    out = Run(m.PolyData());
    PCS_CHECK(Field(out, "OrientationConsistency") == 285.0 / 288.0,
      "flipped torus: orientation " << Field(out, "OrientationConsistency"));
    if (!CheckTopology(out, { 192, 96, 0, 0, 0, 0, 1, 0, 1 }, "flipped torus"))
    {
      return false;
    }
  }

  // Octahedron + torus, disjoint: 2 closed components, chi 2 + 0, genus 0 + 1.
  {
    Mesh m = Octahedron(0.5);
    m.Append(Torus(12, 8, 3.0, 1.0));
    auto out = Run(m.PolyData());
    if (!CheckTopology(out, { 200, 102, 0, 0, 0, 0, 2, 2, 1 }, "octahedron + torus"))
    {
      return false;
    }
  }

  // The 6-vertex real projective plane: every edge in 2 triangles, every vertex link a 5-cycle,
  // V 6, E 15, F 10, chi 1; not orientable, so no genus (-1).
  {
    Mesh m;
    for (int i = 0; i < 6; ++i)
    {
      const double a = 2.0 * vtkMath::Pi() * i / 6;
      m.AddPoint(std::cos(a), std::sin(a), (i % 2) * 0.5);
    }
    const int rp2[10][3] = { { 1, 2, 3 }, { 1, 3, 4 }, { 1, 4, 5 }, { 1, 5, 6 }, { 1, 6, 2 },
      { 2, 3, 5 }, { 3, 4, 6 }, { 4, 5, 2 }, { 5, 6, 3 }, { 6, 2, 4 } };
    for (const auto& t : rp2)
    {
      m.Triangles.push_back({ { t[0] - 1, t[1] - 1, t[2] - 1 } });
    }
    auto out = Run(m.PolyData());
    if (!CheckTopology(out, { 10, 6, 0, 0, 0, 0, 1, 1, -1 }, "projective plane"))
    {
      return false;
    }
    PCS_CHECK(Field(out, "OrientationConsistency") < 1.0, "projective plane: not orientable");
  }
  return true;
}

//------------------------------------------------------------------------------------------------
bool TestOpenSurfaces()
{
  // Open n x m grid: V (n+1)(m+1), E n(m+1) + m(n+1) + nm, F 2nm -> chi 1; 2(n+m) boundary
  // edges in one loop; right isosceles triangles (min angle 45).
  const int n = 5, m = 4;
  const vtkIdType v = (n + 1) * (m + 1), e = n * (m + 1) + m * (n + 1) + n * m, f = 2 * n * m;
  {
    auto out = Run(Grid(n, m).PolyData());
    if (!CheckTopology(out, { f, v, 0, 0, 2 * (n + m), 1, 1, v - e + f, -1 }, "grid"))
    {
      return false;
    }
    PCS_CHECK(v - e + f == 1, "grid: chi by construction");
    PCS_CHECK(Field(out, "OrientationConsistency") == 1.0, "grid: orientation");
    PCS_CHECK(Near(Field(out, "MinAngleP1"), 45.0), "grid: MinAngleP1");
  }
  // One interior quad removed: 2 triangles and 1 diagonal fewer, 4 more boundary edges in a
  // second loop; an annulus, chi 0.
  {
    auto out = Run(Grid(n, m, 1.0, 0.0, { { 2, 2 } }).PolyData());
    if (!CheckTopology(
          out, { f - 2, v, 0, 0, 2 * (n + m) + 4, 2, 1, v - (e - 1) + (f - 2), -1 }, "holed grid"))
    {
      return false;
    }
    PCS_CHECK(v - (e - 1) + (f - 2) == 0, "holed grid: chi by construction");
  }
  // Quads (1,1) and (2,2) removed: the two holes touch at point (2,2), whose 2 remaining
  // triangles (from quads (2,1) and (1,2)) share no edge: a pinched, non-manifold vertex. With
  // that vertex split in two (one per fan) the surface is an annulus, so the walk finds 2 loops:
  // the outer one and one hole made of both squares. E 67, F 36, chi 30 - 67 + 36 = -1.
  {
    auto out = Run(Grid(n, m, 1.0, 0.0, { { 1, 1 }, { 2, 2 } }).PolyData());
    if (!CheckTopology(out, { f - 4, v, 0, 1, 2 * (n + m) + 8, 2, 1, v - (e - 2) + (f - 4), -1 },
          "pinched grid"))
    {
      return false;
    }
    PCS_CHECK(v - (e - 2) + (f - 4) == -1, "pinched grid: chi by construction");
    PCS_CHECK(out->GetPointData()->GetArray("NonManifoldVertex")->GetTuple1(2 * (m + 1) + 2) == 1,
      "pinched grid: the pinched point is flagged");
  }
  // Bowtie: two triangles sharing one point. 2 fans at it, 2 components, 2 loops, chi 5 - 6 + 2.
  {
    Mesh b;
    b.AddPoint(0, 0, 0);
    b.AddPoint(1, 1, 0);
    b.AddPoint(1, -1, 0);
    b.AddPoint(-1, 1, 0);
    b.AddPoint(-1, -1, 0);
    b.Triangles = { { { 0, 2, 1 } }, { { 0, 3, 4 } } };
    auto out = Run(b.PolyData());
    if (!CheckTopology(out, { 2, 5, 0, 1, 6, 2, 2, 1, -1 }, "bowtie"))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------------------------
// The outer faces of a set of unit voxels (cells (x, y, z) of `filled`), each split in two
// triangles, counter-clockwise seen from outside; lattice points shared.
Mesh VoxelSurface(const std::vector<std::array<int, 3>>& filled)
{
  Mesh m;
  std::map<std::array<int, 3>, vtkIdType> ids;
  auto id = [&m, &ids](const std::array<int, 3>& p)
  {
    auto found = ids.find(p);
    if (found != ids.end())
    {
      return found->second;
    }
    const vtkIdType i = m.AddPoint(p[0], p[1], p[2]);
    ids[p] = i;
    return i;
  };
  auto isFilled = [&filled](const std::array<int, 3>& c)
  { return std::find(filled.begin(), filled.end(), c) != filled.end(); };
  for (const auto& cell : filled)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      for (int side : { -1, 1 })
      {
        std::array<int, 3> next = cell;
        next[axis] += side;
        if (isFilled(next))
        {
          continue;
        }
        // Corners (0, 0), (1, 0), (1, 1), (0, 1) along the axes u, v after `axis` (cyclic):
        // counter-clockwise seen from +axis; reversed on the - side.
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        vtkIdType corner[4];
        const int du[4] = { 0, 1, 1, 0 }, dv[4] = { 0, 0, 1, 1 };
        for (int k = 0; k < 4; ++k)
        {
          std::array<int, 3> p = cell;
          p[axis] += side > 0 ? 1 : 0;
          p[u] += du[k];
          p[v] += dv[k];
          corner[k] = id(p);
        }
        if (side < 0)
        {
          std::swap(corner[1], corner[3]);
        }
        m.Triangles.push_back({ { corner[0], corner[1], corner[2] } });
        m.Triangles.push_back({ { corner[0], corner[2], corner[3] } });
      }
    }
  }
  return m;
}

// Surfaces not covered above: higher genus and a non-orientable surface with boundary.
bool TestGenusTwoAndMoebius()
{
  // A 5 x 3 x 1 slab of voxels with two holes, at (1, 1) and (3, 1): a closed orientable surface
  // of genus 2. 13 voxels: 26 top and bottom squares, 16 outer and 8 hole walls: F = 100; the
  // 6 x 4 lattice points of both faces: V = 48; E = 150, chi = -2.
  std::vector<std::array<int, 3>> slab;
  for (int x = 0; x < 5; ++x)
  {
    for (int y = 0; y < 3; ++y)
    {
      if (!(y == 1 && (x == 1 || x == 3)))
      {
        slab.push_back({ { x, y, 0 } });
      }
    }
  }
  auto out = Run(VoxelSurface(slab).PolyData());
  if (!CheckTopology(out, { 100, 48, 0, 0, 0, 0, 1, -2, 2 }, "genus-2 slab"))
  {
    return false;
  }
  PCS_CHECK(Field(out, "OrientationConsistency") == 1.0, "genus-2 slab: oriented");

  // Moebius strip of n quads: points t_i = (i, 0), b_i = (i, 1) on a band around a circle, quad
  // i (t_i, b_i, b_i+1, t_i+1) split into (t_i, b_i, b_i+1) and (t_i, b_i+1, t_i+1), the last
  // quad closing with a half twist (t_n = b_0, b_n = t_0). V = 2n, F = 2n, E = 4n (n rungs and n
  // diagonals of valence 2, 2n boundary edges in one loop), chi 0; every triangle agrees with its
  // neighbours but across the rung t_0 b_0, which both traverse from t_0 to b_0: consistency
  // (2n - 1) / 2n. Open, so no genus (-1).
  const int n = 12;
  Mesh strip;
  for (int i = 0; i < n; ++i)
  {
    const double angle = 2.0 * vtkMath::Pi() * i / n, twist = 0.5 * angle;
    for (double w : { -0.3, 0.3 })
    {
      const double r = 2.0 + w * std::cos(twist);
      strip.AddPoint(r * std::cos(angle), r * std::sin(angle), w * std::sin(twist));
    }
  }
  auto top = [n](int i) { return i < n ? 2 * i : 1; };        // t_n = b_0
  auto bottom = [n](int i) { return i < n ? 2 * i + 1 : 0; }; // b_n = t_0
  for (int i = 0; i < n; ++i)
  {
    strip.Triangles.push_back({ { top(i), bottom(i), bottom(i + 1) } });
    strip.Triangles.push_back({ { top(i), bottom(i + 1), top(i + 1) } });
  }
  out = Run(strip.PolyData());
  if (!CheckTopology(out, { 2 * n, 2 * n, 0, 0, 2 * n, 1, 1, 0, -1 }, "Moebius strip"))
  {
    return false;
  }
  PCS_CHECK(Near(Field(out, "OrientationConsistency"), (2.0 * n - 1) / (2.0 * n)),
    "Moebius strip: consistency " << Field(out, "OrientationConsistency"));
  return true;
}

//------------------------------------------------------------------------------------------------
bool TestNonManifold()
{
  // Three triangles on edge (0, 1): 1 non-manifold edge, its 2 end points flagged, the other 6
  // edges on the boundary; the boundary walks stop at the non-manifold edge: no closed loop.
  // V 5, E 7, F 3 -> chi 1.
  {
    Mesh m;
    m.AddPoint(0, 0, 0);
    m.AddPoint(1, 0, 0);
    m.AddPoint(0.5, 1, 0);
    m.AddPoint(0.5, -1, 0);
    m.AddPoint(0.5, 0, 1);
    m.Triangles = { { { 0, 1, 2 } }, { { 1, 0, 3 } }, { { 0, 1, 4 } } };
    auto out = Run(m.PolyData());
    if (!CheckTopology(out, { 3, 5, 1, 2, 6, 0, 1, 1, -1 }, "three triangles on an edge"))
    {
      return false;
    }
    auto* cells = out->GetCellData()->GetArray("NonManifoldEdge");
    for (vtkIdType c = 0; c < 3; ++c)
    {
      PCS_CHECK(cells->GetTuple1(c) == 1, "three triangles: NonManifoldEdge of cell " << c);
    }
    // No valence-2 edge: orientation consistency is 1 by convention.
    PCS_CHECK(Field(out, "OrientationConsistency") == 1.0, "three triangles: orientation");
  }
  // Two closed cones (k = 6) touching at their apex: apex shared, V 2 (k + 2) - 1 = 15,
  // E 2 (3k) = 36, F 2 (2k) = 24, chi 3; 2 components through edges; apex non-manifold.
  {
    Mesh m = Cone(6, -1.0);
    Mesh upper = Cone(6, 1.0);
    const vtkIdType shift = m.NumberOfPoints() - 1; // upper's points after the apex
    m.Points.insert(m.Points.end(), upper.Points.begin() + 3, upper.Points.end());
    for (Tri t : upper.Triangles)
    {
      for (vtkIdType& p : t)
      {
        p = p == 0 ? 0 : p + shift;
      }
      m.Triangles.push_back(t);
    }
    auto out = Run(m.PolyData());
    if (!CheckTopology(out, { 24, 15, 0, 1, 0, 0, 2, 3, -1 }, "two cones"))
    {
      return false;
    }
    PCS_CHECK(out->GetPointData()->GetArray("NonManifoldVertex")->GetTuple1(0) == 1,
      "two cones: the apex is the non-manifold vertex");
    PCS_CHECK(Field(out, "OrientationConsistency") == 1.0, "two cones: orientation");
  }
  return true;
}

//------------------------------------------------------------------------------------------------
bool TestDegenerate()
{
  // Octahedron (ids 0-5) + a duplicate of triangle 0 (0, 2, 4) with the reverse orientation
  // (2, 0, 4) + a collapsed triangle (0, 0, 1) + an exactly collinear triangle (exact binary
  // coordinates, c - a = 3 (b - a)) + an almost collinear one (not degenerate).
  Mesh m = Octahedron();
  const vtkIdType a = m.AddPoint(10, 0, 0);
  const vtkIdType b = m.AddPoint(10.5, 1, 1.5);
  const vtkIdType c = m.AddPoint(11.5, 3, 4.5);
  const vtkIdType p = m.AddPoint(20, 0, 0);
  const vtkIdType q = m.AddPoint(21, 1, 1);
  const vtkIdType r = m.AddPoint(22, 2, 2 + std::ldexp(1.0, -40));
  m.Triangles.push_back({ { 2, 0, 4 } }); // 8: duplicate of 0
  m.Triangles.push_back({ { 0, 0, 1 } }); // 9: collapsed
  m.Triangles.push_back({ { a, b, c } }); // 10: zero area
  m.Triangles.push_back({ { p, q, r } }); // 11: tiny but non-zero area
  auto out = Run(m.PolyData());
  // Edges of the duplicate: (0,2), (2,4), (4,0) now in 3 triangles (non-manifold), their 3
  // points flagged. V 6 + 6, E 12 + 3 + 3, F 8 + 1 + 2 (collapsed excluded) -> chi 12 - 18 + 11.
  // Boundary: the 6 edges of the two isolated triangles; each is a loop of 3 edges.
  // Components: octahedron (with its duplicate), and the two isolated triangles.
  Topology expected{ 12, 12, 3, 3, 6, 2, 3, 12 - 18 + 11, -1 };
  expected.Degenerate = 2;
  expected.Duplicates = 1;
  if (!CheckTopology(out, expected, "degenerate"))
  {
    return false;
  }
  auto* angles = out->GetCellData()->GetArray("MinAngle");
  PCS_CHECK(angles->GetTuple1(9) == 0.0 && angles->GetTuple1(10) == 0.0,
    "degenerate: MinAngle 0 for collapsed and collinear triangles");
  PCS_CHECK(angles->GetTuple1(11) > 0.0, "degenerate: the almost collinear triangle has an angle");
  // 12 triangles: the 1st percentile (nearest rank) is the smallest angle, 0.
  PCS_CHECK(Field(out, "MinAngleP1") == 0.0, "degenerate: MinAngleP1");
  PCS_CHECK(out->GetCellData()->GetArray("BoundaryEdge")->GetTuple1(9) == -1,
    "degenerate: collapsed triangle not analysed");
  // The edges of the duplicate have valence 3 and do not enter the orientation measure, which
  // sees the 9 other (valence-2) edges of the octahedron: all consistent.
  PCS_CHECK(Field(out, "OrientationConsistency") == 1.0, "degenerate: orientation");
  return true;
}

//------------------------------------------------------------------------------------------------
bool TestBadInput()
{
  using pcstest::FieldCount;
  // Empty input.
  {
    Counter counter;
    vtkNew<vtkPolyData> empty;
    auto out = Run(empty, nullptr, 3, &counter);
    PCS_CHECK(counter.Warnings >= 1 && counter.Errors == 0, "empty: one warning, no error");
    PCS_CHECK(
      FieldCount(out, "NumberOfTriangles") == 0 && FieldCount(out, "NumberOfUsedPoints") == 0,
      "empty: zero counts");
    PCS_CHECK(Field(out, "Coverage") == 0.0 && FieldCount(out, "Genus") == -1, "empty: coverage");
    PCS_CHECK(std::isnan(Field(out, "MinAngleP1")), "empty: MinAngleP1 undefined");
  }
  // Points only (a cloud), with a reference: warnings, Coverage 0, NaN distances.
  {
    Counter counter;
    auto cloud = pcstest::MakeCloud(pcstest::UniformCube(50, 7));
    auto reference = Grid(2, 2).PolyData();
    auto out = Run(cloud, reference, 3, &counter);
    PCS_CHECK(counter.Warnings >= 2 && counter.Errors == 0, "cloud: warnings, no error");
    PCS_CHECK(out->GetNumberOfPoints() == 50, "cloud: points passed through");
    PCS_CHECK(Field(out, "Coverage") == 0.0 && FieldCount(out, "NumberOfUsedPoints") == 0,
      "cloud: nothing used");
    PCS_CHECK(std::isnan(Field(out, "AccuracyMean")) && std::isnan(Field(out, "Hausdorff")),
      "cloud: distances undefined");
  }
  // A quad and a strip are ignored with a warning; their cell data say "not analysed".
  {
    Counter counter;
    Mesh m = Octahedron();
    auto data = m.PolyData();
    const vtkIdType quad[4] = { 0, 2, 1, 3 };
    data->GetPolys()->InsertNextCell(4, quad);
    vtkNew<vtkCellArray> strips;
    const vtkIdType strip[4] = { 0, 2, 3, 1 };
    strips->InsertNextCell(4, strip);
    data->SetStrips(strips);
    vtkNew<vtkCellArray> verts;
    const vtkIdType vertex = 5;
    verts->InsertNextCell(1, &vertex);
    data->SetVerts(verts); // cell 0 is now the vertex, the triangles are cells 1-8
    auto out = Run(data, nullptr, 3, &counter);
    PCS_CHECK(counter.Warnings == 1 && counter.Errors == 0,
      "polygons: one warning (" << counter.Warnings << ")");
    if (!CheckTopology(out, { 8, 6, 0, 0, 0, 0, 1, 2, 0 }, "octahedron with quad and strip"))
    {
      return false;
    }
    auto* boundary = out->GetCellData()->GetArray("BoundaryEdge");
    auto* angles = out->GetCellData()->GetArray("MinAngle");
    PCS_CHECK(out->GetNumberOfCells() == 11, "polygons: all cells passed through");
    for (vtkIdType cell : { 0, 9, 10 })
    {
      PCS_CHECK(boundary->GetTuple1(cell) == -1 && std::isnan(angles->GetTuple1(cell)),
        "polygons: cell " << cell << " not analysed");
    }
    PCS_CHECK(Near(angles->GetTuple1(1), 60.0), "polygons: cell ids follow vertices");
  }
  return true;
}

//------------------------------------------------------------------------------------------------
// Rotation about the axis (1, 2, 3) by 0.7 rad, to put the planes in general position.
void Rotate(Mesh& m)
{
  double axis[3] = { 1, 2, 3 };
  vtkMath::Normalize(axis);
  const double angle = 0.7, c = std::cos(angle), s = std::sin(angle);
  for (size_t i = 0; i < m.Points.size(); i += 3)
  {
    double* x = &m.Points[i];
    double cross[3];
    vtkMath::Cross(axis, x, cross);
    const double dot = vtkMath::Dot(axis, x);
    double y[3];
    for (int j = 0; j < 3; ++j)
    {
      y[j] = x[j] * c + cross[j] * s + axis[j] * dot * (1 - c);
    }
    std::copy(y, y + 3, x);
  }
}

bool CheckDistances(vtkPolyData* out, double expected, double spacing, const std::string& label)
{
  for (const char* name :
    { "AccuracyMean", "AccuracyMax", "CompletenessMean", "CompletenessMax", "Hausdorff" })
  {
    PCS_CHECK(Near(Field(out, name), expected),
      label << ": " << name << " = " << Field(out, name) << ", expected " << expected);
    const std::string scaled = std::string(name) + "OverSpacing";
    PCS_CHECK(Near(Field(out, scaled.c_str()), expected / spacing),
      label << ": " << scaled << " = " << Field(out, scaled.c_str()));
  }
  PCS_CHECK(Near(Field(out, "MeanSpacing"), spacing),
    label << ": MeanSpacing " << Field(out, "MeanSpacing"));
  return true;
}

bool TestDistances()
{
  // Mesh: a 10 x 8 grid of spacing h at z = 0, plus one unused point; reference: the same grid
  // at z = d. Every mesh sample lies under the reference and vice versa: all distances are d.
  // The spacing (used mesh points, reference is a surface) is h.
  const double h = 0.1, d = 0.037;
  for (bool general : { false, true })
  {
    Mesh mesh = Grid(10, 8, h, 0.0);
    const vtkIdType unused = mesh.AddPoint(0.3, 0.3, 5.0);
    Mesh reference = Grid(10, 8, h, d);
    if (general)
    {
      Rotate(mesh);
      Rotate(reference);
    }
    const std::string label = general ? "rotated planes" : "planes";
    for (int samples : { 0, 3, 100 })
    {
      auto out = Run(mesh.PolyData(), reference.PolyData(), samples);
      if (!CheckDistances(out, d, h, label + " samples " + std::to_string(samples)))
      {
        return false;
      }
      auto* distance = out->GetPointData()->GetArray("DistanceToReference");
      PCS_CHECK(distance, label << ": DistanceToReference present");
      PCS_CHECK(std::isnan(distance->GetTuple1(unused)), label << ": unused point has NaN");
      for (vtkIdType p = 0; p < unused; ++p)
      {
        PCS_CHECK(Near(distance->GetTuple1(p), d), label << ": DistanceToReference of " << p);
      }
    }

    // The reference as a cloud (its points only). With vertex samples only, each mesh vertex
    // has a reference point straight above it: accuracy d; completeness (cloud points to the
    // mesh triangles) d; spacing from the cloud, h.
    auto cloud = pcstest::MakeCloud(reference.Points);
    auto out = Run(mesh.PolyData(), cloud, 0);
    if (!CheckDistances(out, d, h, label + " cloud"))
    {
      return false;
    }
    // With samples inside the triangles the nearest cloud point is up to h / sqrt(2) away
    // sideways (the centre of a grid square): d < accuracy <= sqrt(d^2 + h^2 / 2).
    out = Run(mesh.PolyData(), cloud, 3);
    PCS_CHECK(Field(out, "AccuracyMean") > d + 1e-6 &&
        Field(out, "AccuracyMax") <= std::sqrt(d * d + h * h / 2) + 1e-12,
      label << ": cloud accuracy with samples " << Field(out, "AccuracyMax"));
    PCS_CHECK(Near(Field(out, "CompletenessMax"), d), label << ": cloud completeness");
  }

  // A reference one column wider (x from -h): its points at x = -h are sqrt(d^2 + h^2) from the
  // mesh (nearest mesh point on the edge x = 0); that is the completeness maximum and the
  // Hausdorff distance. Accuracy stays d.
  {
    Mesh mesh = Grid(10, 8, h, 0.0);
    Mesh reference = Grid(11, 8, h, d);
    for (size_t i = 0; i < reference.Points.size(); i += 3)
    {
      reference.Points[i] -= h;
    }
    auto out = Run(mesh.PolyData(), reference.PolyData(), 3);
    const double farthest = std::sqrt(d * d + h * h);
    PCS_CHECK(Near(Field(out, "AccuracyMax"), d) && Near(Field(out, "AccuracyMean"), d),
      "wider reference: accuracy");
    PCS_CHECK(Near(Field(out, "CompletenessMax"), farthest),
      "wider reference: completeness max " << Field(out, "CompletenessMax"));
    PCS_CHECK(Field(out, "CompletenessMean") > d && Field(out, "CompletenessMean") < farthest,
      "wider reference: completeness mean");
    PCS_CHECK(Near(Field(out, "Hausdorff"), farthest), "wider reference: Hausdorff");
    PCS_CHECK(Near(Field(out, "HausdorffOverSpacing"), farthest / h), "wider reference: scaled");
  }

  // ComputeDistances off: no distance arrays even with a reference.
  {
    vtkNew<vtkReconstructionQuality> quality;
    PCS_CHECK(quality->GetComputeDistances() && quality->GetSamplesPerTriangle() == 3, "defaults");
    quality->SetSamplesPerTriangle(1000);
    PCS_CHECK(quality->GetSamplesPerTriangle() == 100, "SamplesPerTriangle clamped to 100");
    quality->SetInputData(Grid(2, 2).PolyData());
    quality->SetReferenceData(Grid(2, 2, 1.0, 1.0).PolyData());
    quality->ComputeDistancesOff();
    quality->Update();
    PCS_CHECK(!quality->GetOutput()->GetFieldData()->GetArray("Hausdorff") &&
        !quality->GetOutput()->GetPointData()->GetArray("DistanceToReference"),
      "ComputeDistances off");
  }
  return true;
}

// A fan of n triangles from the centre of the unit disk to its rim, at height z.
Mesh Fan(int n, double z)
{
  Mesh fan;
  fan.AddPoint(0.0, 0.0, z);
  for (int i = 0; i < n; ++i)
  {
    const double angle = 2.0 * vtkMath::Pi() * i / n;
    fan.AddPoint(std::cos(angle), std::sin(angle), z);
  }
  for (int i = 0; i < n; ++i)
  {
    fan.Triangles.push_back({ { 0, 1 + i, 1 + (i + 1) % n } });
  }
  return fan;
}

// Long thin triangles: the fan of 16000 triangles at z = 0 against the same fan at z = d. Every
// sample of one fan is straight under (over) the other fan: all distances are d. Every triangle
// spans the disk's radius and all of them meet at the centre, so the nearest vertex of a query
// is often the centre, with thousands of triangles within that distance. A cell locator, which
// bins each triangle in every bin its box touches and searches within the nearest-vertex
// distance, took over a minute here (quadratic); the query tree takes a fraction of a second.
bool TestLongTriangles()
{
  const int n = 16000;
  const double d = 0.25;
  Mesh mesh = Fan(n, 0.0);
  Mesh reference = Fan(n, d);
  auto out = Run(mesh.PolyData(), reference.PolyData(), 3);
  if (!CheckTopology(out, { n, n + 1, 0, 0, n, 1, 1, 1, -1 }, "fan"))
  {
    return false;
  }
  for (const char* name :
    { "AccuracyMean", "AccuracyMax", "CompletenessMean", "CompletenessMax", "Hausdorff" })
  {
    PCS_CHECK(Near(Field(out, name), d), "fan: " << name << " = " << Field(out, name));
  }
  auto* distance = out->GetPointData()->GetArray("DistanceToReference");
  PCS_CHECK(distance && distance->GetNumberOfTuples() == n + 1, "fan: DistanceToReference");
  for (vtkIdType p = 0; p <= n; ++p)
  {
    PCS_CHECK(Near(distance->GetTuple1(p), d), "fan: DistanceToReference of " << p);
  }
  return true;
}

// Coordinates near the ends of the double range: the octahedron of radius s against the one of
// radius 1.5 s, for s = 1, 1e300, 1e-300. Faces are parallel, and each point of an inner face
// projects into the outer parallel face: accuracy is the plane gap 0.5 s / sqrt(3) everywhere;
// completeness peaks at the outer vertices, 0.5 s from the inner ones; the spacing is s sqrt(2);
// no triangle is degenerate and all angles are 60 degrees. (Before the power-of-two scaling,
// 1e300 overflowed in EvaluatePosition, a VTK assertion, and 1e-300 underflowed: 8 "degenerate"
// triangles, NaN spacing.) A NaN point in a reference cloud is neither a target nor a sample,
// with a warning: the distances are those of the cloud without it (one such point made
// CompletenessMean, CompletenessMax and Hausdorff NaN).
bool TestExtremeCoordinates()
{
  for (double s : { 1.0, 1e300, 1e-300 })
  {
    Counter counter;
    auto out = Run(Octahedron(s).PolyData(), Octahedron(1.5 * s).PolyData(), 3, &counter);
    const std::string label = "scale " + std::to_string(std::log10(s));
    PCS_CHECK(counter.Warnings == 0 && counter.Errors == 0, label << ": no warning");
    PCS_CHECK(pcstest::FieldCount(out, "NumberOfDegenerateTriangles") == 0 &&
        Near(Field(out, "MinAngleP1"), 60.0),
      label << ": degenerate " << pcstest::FieldCount(out, "NumberOfDegenerateTriangles")
            << ", angle " << Field(out, "MinAngleP1"));
    const double gap = 0.5 / std::sqrt(3.0);
    for (const auto& expected :
      std::vector<std::pair<const char*, double>>{ { "AccuracyMean", gap },
        { "AccuracyMax", gap },
        { "CompletenessMax", 0.5 },
        { "Hausdorff", 0.5 },
        { "MeanSpacing", std::sqrt(2.0) } })
    {
      PCS_CHECK(Near(Field(out, expected.first) / s, expected.second, 1e-12),
        label << ": " << expected.first << " / s = " << Field(out, expected.first) / s);
    }
    PCS_CHECK(Field(out, "CompletenessMean") / s > gap && Field(out, "CompletenessMean") / s < 0.5,
      label << ": CompletenessMean");
  }
  {
    Counter counter;
    Mesh outer = Octahedron(1.5);
    outer.AddPoint(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
    auto cloud = pcstest::MakeCloud(outer.Points);
    auto out = Run(Octahedron(1.0).PolyData(), cloud, 3, &counter);
    PCS_CHECK(counter.Warnings == 1 && counter.Errors == 0,
      "NaN cloud point: one warning (" << counter.Warnings << ")");
    PCS_CHECK(std::isfinite(Field(out, "AccuracyMax")) && Field(out, "AccuracyMax") <= 1.5,
      "NaN cloud point: accuracy " << Field(out, "AccuracyMax"));
    auto clean =
      Run(Octahedron(1.0).PolyData(), pcstest::MakeCloud(Octahedron(1.5).Points), 3, nullptr);
    const char* measures[] = { "AccuracyMean",
      "AccuracyMax",
      "CompletenessMean",
      "CompletenessMax",
      "Hausdorff",
      "MeanSpacing" };
    for (const char* name : measures)
    {
      PCS_CHECK(Field(out, name) == Field(clean, name),
        "NaN cloud point: " << name << " " << Field(out, name) << " instead of "
                            << Field(clean, name));
    }
  }
  return true;
}

// The distance queries run through vtkSMPTools: the STDThread backend gives bit-identical
// results to the sequential one (values are stored per sample and reduced in order).
bool TestThreads()
{
  Mesh mesh = Torus(80, 40, 3.0, 1.0);
  Mesh reference = Torus(60, 30, 3.0, 1.05);
  const std::string initial = vtkSMPTools::GetBackend();
  std::vector<std::vector<double>> results;
  for (const char* backend : { "Sequential", "STDThread" })
  {
    if (!vtkSMPTools::SetBackend(backend))
    {
      std::cout << "SMP backend " << backend << " not available, skipped" << std::endl;
      continue;
    }
    vtkSMPTools::Initialize(2);
    std::cout << "threads: backend " << vtkSMPTools::GetBackend() << ", "
              << vtkSMPTools::GetEstimatedNumberOfThreads() << " thread(s)" << std::endl;
    auto out = Run(mesh.PolyData(), reference.PolyData(), 5);
    std::vector<double> values;
    vtkFieldData* fd = out->GetFieldData();
    for (int i = 0; i < fd->GetNumberOfArrays(); ++i)
    {
      values.push_back(fd->GetArray(i)->GetTuple1(0));
    }
    auto* distance = out->GetPointData()->GetArray("DistanceToReference");
    for (vtkIdType p = 0; p < distance->GetNumberOfTuples(); ++p)
    {
      values.push_back(distance->GetTuple1(p));
    }
    results.push_back(values);
  }
  vtkSMPTools::SetBackend(initial.c_str());
  PCS_CHECK(!results.empty(), "threads: at least one backend");
  // Minor radii 1 and 1.05 on the same axis circle: the distances lie in [0, 0.05 + chord
  // sag], all finite.
  for (double x : results[0])
  {
    PCS_CHECK(std::isfinite(x), "threads: finite values");
  }
  if (results.size() == 2)
  {
    PCS_CHECK(results[0] == results[1], "threads: Sequential and STDThread differ");
  }
  return true;
}
} // namespace

int TestReconstructionQuality(int, char*[])
{
  const std::vector<pcsqtest::NamedTest> tests = {
    { "closed surfaces", TestClosedSurfaces },
    { "open surfaces", TestOpenSurfaces },
    { "genus 2, Moebius strip", TestGenusTwoAndMoebius },
    { "non-manifold", TestNonManifold },
    { "degenerate and duplicate triangles", TestDegenerate },
    { "bad input", TestBadInput },
    { "distances", TestDistances },
    { "long triangles", TestLongTriangles },
    { "extreme coordinates", TestExtremeCoordinates },
    { "threads", TestThreads },
  };
  return pcsqtest::RunTests(tests);
}
