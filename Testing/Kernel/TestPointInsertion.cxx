// Standalone test of the insertion of a free point into a surface mesh
// (Filters/Kernel/pcsPointInsertion.h), compiled with the kernel sources it needs (no VTK). The
// mesh is the unit square z = 0 made of the triangles (0, 1, 2) and (0, 2, 3); every expected
// result is known by construction: the operation chosen (split into three, edge split, attach
// across a boundary edge, refusal), the triangle count, the new vertex's state, and the mesh's
// own consistency check.
#include "pcsKernelTest.h"
#include "pcsPointInsertion.h"

#include <iostream>
#include <string>
#include <vector>

namespace
{
using pcstest::Failures;

// The square's 4 corners and the point q (id 4).
struct Square
{
  std::vector<double> XYZ = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 0 };
  pcs::SurfaceMesh Mesh{ 5 };
  const int32_t Neighbors[4] = { 0, 1, 2, 3 };

  explicit Square(double x, double y, double z)
  {
    this->XYZ[12] = x;
    this->XYZ[13] = y;
    this->XYZ[14] = z;
    this->Mesh.AddTriangle(0, 1, 2);
    this->Mesh.AddTriangle(0, 2, 3);
  }
  bool Insert(bool attach, pcs::PointInsertionResult& result)
  {
    return pcs::InsertFreePoint(this->Mesh, this->XYZ.data(), 4, this->Neighbors, 4, attach, result);
  }
  bool Consistent()
  {
    std::string why;
    const bool ok = this->Mesh.CheckConsistency(&why);
    if (!ok)
    {
      std::cerr << "inconsistent mesh: " << why << std::endl;
    }
    return ok;
  }
};
} // namespace

int main()
{
  using State = pcs::SurfaceMesh::VertexState;
  pcs::PointInsertionResult result;
  {
    // Inside the triangle (0, 1, 2), slightly above it: split into three.
    Square s(0.7, 0.2, 0.05);
    EXPECT(s.Insert(true, result), "inside: inserted");
    EXPECT(s.Mesh.GetNumberOfTriangles() == 4, "inside: 4 triangles");
    EXPECT(result.Added.size() == 3 && result.OldEdges.size() == 3, "inside: 3 added");
    EXPECT(s.Mesh.GetVertexState(4) == State::Interior, "inside: q interior");
    EXPECT(s.Mesh.GetNumberOfBoundaryHalfEdges() == 4, "inside: the square's boundary");
    EXPECT(s.Consistent(), "inside");
  }
  {
    // Almost on the diagonal 0-2 (angle at q near 180 degrees): both triangles split in four.
    Square s(0.5, 0.501, 0.0);
    EXPECT(s.Insert(true, result), "diagonal: inserted");
    EXPECT(s.Mesh.GetNumberOfTriangles() == 4 && result.Added.size() == 4, "diagonal: 4 triangles");
    EXPECT(s.Mesh.GetEdgeValence(0, 2) == 0, "diagonal: the edge 0-2 is gone");
    EXPECT(s.Mesh.GetVertexState(4) == State::Interior, "diagonal: q interior");
    EXPECT(s.Consistent(), "diagonal");
  }
  {
    // Almost on the boundary edge 0-1 inside: the triangle split in two, q on the boundary.
    Square s(0.5, 0.001, 0.0);
    EXPECT(s.Insert(true, result), "on boundary edge: inserted");
    EXPECT(s.Mesh.GetNumberOfTriangles() == 3, "on boundary edge: 3 triangles");
    EXPECT(s.Mesh.GetEdgeValence(0, 1) == 0 && s.Mesh.IsBoundaryHalfEdge(0, 4) &&
        s.Mesh.IsBoundaryHalfEdge(4, 1),
      "on boundary edge: the boundary runs 0 -> q -> 1");
    EXPECT(s.Consistent(), "on boundary edge");
  }
  {
    // Exactly on the boundary edge 0-1 (decided exactly): the triangle split in two, as any
    // triangle joining q to the edge would have zero area.
    Square s(0.5, 0.0, 0.0);
    EXPECT(s.Insert(true, result), "exactly on boundary edge: inserted");
    EXPECT(s.Mesh.GetNumberOfTriangles() == 3 && result.Added.size() == 2,
      "exactly on boundary edge: 3 triangles");
    EXPECT(s.Mesh.GetEdgeValence(0, 1) == 0 && s.Mesh.IsBoundaryHalfEdge(0, 4) &&
        s.Mesh.IsBoundaryHalfEdge(4, 1),
      "exactly on boundary edge: the boundary runs 0 -> q -> 1");
    EXPECT(s.Consistent(), "exactly on boundary edge");
  }
  {
    // Exactly on the diagonal 0-2: both triangles split in four.
    Square s(0.5, 0.5, 0.0);
    EXPECT(s.Insert(true, result), "exactly on diagonal: inserted");
    EXPECT(s.Mesh.GetNumberOfTriangles() == 4 && s.Mesh.GetEdgeValence(0, 2) == 0,
      "exactly on diagonal: 4 triangles, the edge 0-2 gone");
    EXPECT(s.Mesh.GetVertexState(4) == State::Interior, "exactly on diagonal: q interior");
    EXPECT(s.Consistent(), "exactly on diagonal");
  }
  {
    // Beyond the boundary edge 0-1: a triangle attached across it, or nothing when not allowed.
    Square s(0.5, -0.3, 0.0);
    EXPECT(!s.Insert(false, result), "beyond, no attachment: refused");
    EXPECT(s.Mesh.GetNumberOfTriangles() == 2 && s.Mesh.IsFree(4), "refused: unchanged");
    EXPECT(s.Insert(true, result), "beyond: attached");
    EXPECT(s.Mesh.GetNumberOfTriangles() == 3 && result.Added.size() == 1, "beyond: 3 triangles");
    EXPECT(s.Mesh.GetEdgeValence(0, 1) == 2 && s.Mesh.GetVertexState(4) == State::Boundary,
      "beyond: edge 0-1 interior, q on the boundary");
    EXPECT(s.Consistent(), "beyond");
  }
  {
    // Farther from every triangle than its longest edge (sqrt 2): refused, mesh unchanged.
    Square s(0.5, 0.5, 1.5);
    EXPECT(!s.Insert(true, result), "far: refused");
    EXPECT(s.Mesh.GetNumberOfTriangles() == 2 && s.Mesh.IsFree(4) && result.Added.empty(),
      "far: unchanged");
    EXPECT(s.Consistent(), "far");
  }
  {
    // Not a free point: refused.
    Square s(0.7, 0.2, 0.0);
    EXPECT(s.Insert(true, result), "first insertion");
    EXPECT(!s.Insert(true, result), "second insertion of the same point refused");
    EXPECT(s.Mesh.GetNumberOfTriangles() == 4, "second insertion: unchanged");
  }
  {
    // Exactly on the boundary edge's line beyond its end: the attached triangle would be
    // degenerate (collinear points, exact test): refused.
    Square s(1.5, 0.0, 0.0);
    EXPECT(!s.Insert(true, result), "collinear attachment refused");
    EXPECT(s.Mesh.GetNumberOfTriangles() == 2 && s.Mesh.IsFree(4), "collinear: unchanged");
    EXPECT(s.Consistent(), "collinear");
  }
  if (Failures > 0)
  {
    std::cerr << Failures << " failure(s)" << std::endl;
    return 1;
  }
  std::cout << "pcsTestPointInsertion: all checks passed" << std::endl;
  return 0;
}
