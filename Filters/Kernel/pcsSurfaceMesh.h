// Front/edge topology of a triangle mesh under construction (private kernel, plain C++).
//
// SurfaceMesh is the one topology structure of the mesh-growing filters of PointCloudSurface
// (vtkLocalOptimumGrowth, vtkCDTAdvancingFront, vtkGreedySurfaceTriangulation): it holds the
// triangles added so far over a fixed set of vertices (point ids 0..n-1) and answers, in O(1)
// expected time per query, whether a new triangle keeps the mesh an ORIENTED 2-MANIFOLD (with
// boundary). It knows nothing of coordinates: the geometric rules (angles, distances, overlap)
// belong to the filters; the topology belongs here.
//
// Invariants kept by AddTriangle after a successful CanAddTriangle:
// - orientation: triangle (a, b, c) owns the directed half-edges a->b, b->c, c->a, and every
//   half-edge is owned by at most one triangle. Hence an edge has at most two triangles, and two
//   triangles sharing an edge traverse it in opposite directions (consistent orientation);
// - vertex umbrella: the triangles around each vertex form a single fan (an open fan for a
//   vertex on the front, a closed disk for an interior vertex): no non-manifold vertex.
//
// Vocabulary:
// - a vertex is Free (no triangle), Boundary ("on the front": its fan is open) or Interior (its
//   umbrella is closed; no triangle can be added at it any more);
// - a boundary half-edge (front edge) a->b is a half-edge whose twin b->a has no triangle; a
//   new triangle on it is (b, a, c): it owns b->a, so the front moves across the edge;
// - the front edges form closed loops (front loops); at the end of a reconstruction the
//   remaining loops are the boundaries (holes) of the surface (GetBoundaryLoops);
// - an ear at front vertex b (front a->b->n) is the triangle (b, a, n) that closes the angle
//   between its two front edges; a "pinch" is a triangle that touches a Boundary vertex only at
//   that vertex: it would give the vertex a second fan (CanAddTriangle reports
//   NonManifoldVertex). The growing filters never keep a pinch: they may add one and repair it
//   at once with an ear on either side, or RemoveTriangle it (see vtkLocalOptimumGrowth).
//
// Data structure: per vertex, the list of its "wedges", one per incident triangle: the triangle
// id and the two other vertices in orientation order (triangle (v, x, y) gives v the wedge
// out = x, in = y: it owns v->x and y->v). Lists live in 128-byte blocks of 10 wedges (one
// allocation per vertex of degree <= 10, chained blocks beyond), so a query on a vertex reads
// one or two cache lines. Half-edge a->b exists iff a has a wedge with out == b; the fan
// structure of a vertex is a chain of its wedges (wedge W is followed, counter-clockwise, by the
// wedge whose out is W's in), so every query is a scan of at most deg(v) wedges: O(1) for the
// bounded degrees of surface meshes. A state byte and a fan count per vertex are cached.
// Memory: 12 bytes per triangle, 128 bytes per used vertex (256 above degree 10), 14 bytes per
// vertex (block index, state, fan count, and the two front neighbours of a single-fan vertex,
// cached so that the front queries of the common case read no wedge list: those are inline, and
// AddTriangle updates the cache without a scan when a triangle extends or closes a single fan).
#ifndef pcsSurfaceMesh_h
#define pcsSurfaceMesh_h

#include "pcsDisjointSets.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcs
{
class SurfaceMesh
{
public:
  enum class VertexState : uint8_t
  {
    Free = 0,     ///< no triangle
    Boundary = 1, ///< on the front: at least one open fan
    Interior = 2  ///< closed umbrella: nothing can be added at this vertex
  };

  /// Answer of CanAddTriangle.
  enum class Check : uint8_t
  {
    Ok = 0,
    InvalidVertex,    ///< a vertex id out of range
    RepeatedVertex,   ///< two equal vertex ids
    HalfEdgeUsed,     ///< a half-edge already has a triangle: the edge would get a third
                      ///< triangle, or two triangles with opposite orientations
    NonManifoldVertex ///< a vertex would get a second fan (a pinch), or an interior vertex
  };

  SurfaceMesh() = default;
  explicit SurfaceMesh(int32_t numberOfVertices) { this->Initialize(numberOfVertices); }

  /// Remove every triangle and set the number of vertices (all Free).
  void Initialize(int32_t numberOfVertices);

  /// Reserve room for this many triangles (optional).
  void ReserveTriangles(int64_t numberOfTriangles);

  int32_t GetNumberOfVertices() const { return static_cast<int32_t>(this->Head.size()); }

  /// Triangles currently in the mesh (added minus removed).
  int64_t GetNumberOfTriangles() const { return this->NumberOfTriangles; }

  /// Triangle ids are never reused: ids range over [0, GetNumberOfTriangleIds()); removed ones
  /// report IsTriangleRemoved().
  int64_t GetNumberOfTriangleIds() const
  {
    return static_cast<int64_t>(this->Triangles.size() / 3);
  }
  bool IsTriangleRemoved(int64_t t) const { return this->Triangles[3 * t] < 0; }

  /// The three vertices of triangle t, in orientation order.
  const int32_t* GetTriangle(int64_t t) const { return &this->Triangles[3 * t]; }

  /// Number of boundary (front) half-edges.
  int64_t GetNumberOfBoundaryHalfEdges() const { return this->NumberOfBoundaryHalfEdges; }

  //----------------------------------------------------------------------------------------------
  // Changes.

  /// Can the oriented triangle (a, b, c) be added keeping an oriented 2-manifold? On
  /// NonManifoldVertex, `vertex` (when given) receives the offending vertex. Cost: one scan of
  /// the wedges of a, b and c; none when a free vertex faces a front edge of a single-fan vertex
  /// (the triangle (a, b, c) with c free and b->a on the front, or a rotation of it).
  Check CanAddTriangle(int32_t a, int32_t b, int32_t c, int32_t* vertex = nullptr) const;

  /// Add the oriented triangle (a, b, c) and return its id. Precondition: CanAddTriangle() is
  /// Ok, or NonManifoldVertex when the caller deliberately creates a pinch that it repairs or
  /// removes before relying on the invariants (the half-edge rule must hold in any case:
  /// AddTriangle returns -1 and changes nothing when a vertex is invalid or repeated or a
  /// half-edge is used).
  int64_t AddTriangle(int32_t a, int32_t b, int32_t c);

  /// Add the `count` oriented triangles of `vertices` (3 ids each) together, as one change: a
  /// vertex may be pinched between two of the additions (a fan closed by its last triangle), but
  /// when AddTriangle refuses one of them or, once all are in, one of their vertices has more
  /// than one fan, the triangles added are removed again and false is returned (the structure
  /// is as before). The ids of the triangles added are written to `added` (cleared first); no
  /// triangle (count 0) is a success that changes nothing.
  bool AddTriangles(const int32_t* vertices, size_t count, std::vector<int64_t>& added);

  /// Remove triangle t (no-op when already removed). The structure is exactly as if t had
  /// never been added (except that its id stays unused).
  void RemoveTriangle(int64_t t);

  /// Reverse the orientation of every triangle of the edge-connected component of triangle t
  /// (e.g. to merge two components grown with opposite orientations). Returns the number of
  /// triangles reversed. Cost: linear in the component size.
  int64_t ReverseComponent(int64_t t);

  /// Joins in `pieces` (sets over the triangle ids, at least GetNumberOfTriangleIds() of them)
  /// each triangle with the triangles across its edges: afterwards the sets of the triangles in
  /// the mesh are its edge-connected components. Cost: linear in the number of triangle ids.
  void JoinAcrossEdges(DisjointSets<int64_t>& pieces) const;

  //----------------------------------------------------------------------------------------------
  // Edge queries.

  /// The triangle that owns the half-edge a->b, or -1.
  int64_t FindTriangle(int32_t a, int32_t b) const;

  /// The third vertex of the triangle that owns a->b (the triangle (a, b, x)), or -1.
  int32_t OppositeVertex(int32_t a, int32_t b) const;

  /// Number of triangles on the undirected edge {a, b}: 0, 1 or 2.
  int GetEdgeValence(int32_t a, int32_t b) const;

  /// True when a->b has a triangle and b->a has none (a front edge).
  bool IsBoundaryHalfEdge(int32_t a, int32_t b) const
  {
    // A vertex with a single open fan (the common case) knows its front edge out: inline.
    if (a >= 0 && a < this->GetNumberOfVertices() && this->FrontOut[a] >= 0)
    {
      return this->FrontOut[a] == b;
    }
    return this->IsBoundaryHalfEdgeScan(a, b);
  }

  //----------------------------------------------------------------------------------------------
  // Vertex queries.

  VertexState GetVertexState(int32_t v) const { return static_cast<VertexState>(this->State[v]); }
  bool IsFree(int32_t v) const { return this->State[v] == 0; }
  bool IsInterior(int32_t v) const { return this->State[v] == 2; }

  /// Number of fans (maximal chains of triangles linked through shared edges) around v: 0 for
  /// a free vertex, 1 for a manifold vertex, more for a pinch. Saturates at 255.
  int GetNumberOfFans(int32_t v) const { return this->Fans[v]; }

  /// Number of triangles at v.
  int GetVertexDegree(int32_t v) const;

  /// The neighbours x of v such that v->x is a front edge (one per open fan); returns how many,
  /// writes at most `capacity` of them.
  int GetBoundaryOutVertices(int32_t v, int32_t* out, int capacity) const
  {
    return this->FrontOut[v] >= 0 ? OneVertex(this->FrontOut[v], out, capacity)
                                  : this->GetBoundaryOutVerticesScan(v, out, capacity);
  }

  /// The neighbours x of v such that x->v is a front edge.
  int GetBoundaryInVertices(int32_t v, int32_t* in, int capacity) const
  {
    return this->FrontIn[v] >= 0 ? OneVertex(this->FrontIn[v], in, capacity)
                                 : this->GetBoundaryInVerticesScan(v, in, capacity);
  }

  /// The triangles at v (ids), in storage order; returns how many, writes at most `capacity`.
  int GetVertexTriangles(int32_t v, int64_t* triangles, int capacity) const;

  //----------------------------------------------------------------------------------------------
  // Front.

  /// For the front edge a->b: the vertex z of the front edge b->z that follows it in its loop
  /// (turning around b through the fan of the triangle of a->b). -1 if a->b is not a front edge.
  int32_t NextBoundaryVertex(int32_t a, int32_t b) const
  {
    if (a >= 0 && a < this->GetNumberOfVertices() && this->FrontOut[a] >= 0 && b >= 0 &&
      b < this->GetNumberOfVertices() && this->FrontOut[b] >= 0)
    {
      return this->FrontOut[a] == b ? this->FrontOut[b] : -1;
    }
    return this->NextBoundaryVertexWalk(a, b);
  }

  /// For the front edge a->b: the vertex z of the front edge z->a that precedes it. -1 if a->b
  /// is not a front edge.
  int32_t PreviousBoundaryVertex(int32_t a, int32_t b) const
  {
    if (a >= 0 && a < this->GetNumberOfVertices() && this->FrontOut[a] >= 0)
    {
      return this->FrontOut[a] == b ? this->FrontIn[a] : -1;
    }
    return this->PreviousBoundaryVertexWalk(a, b);
  }

  /// The ear at the front edge a->b on the side of b: the triangle (b, a, n) with n =
  /// NextBoundaryVertex(a, b); returns n (or -1). The ear on the side of a is (b, a, p) with
  /// p = PreviousBoundaryVertex(a, b).
  int32_t EarAfter(int32_t a, int32_t b) const { return this->NextBoundaryVertex(a, b); }

  /// Every front loop, as the sequence of its vertices (v0 -> v1 -> ... -> v0 are front edges).
  /// A vertex with several open fans appears in several loops (or several times in one).
  void GetBoundaryLoops(std::vector<std::vector<int32_t>>& loops) const;

  /// Live triangles, 3 vertex ids each, in id order.
  void GetTriangles(std::vector<int32_t>& connectivity) const;

  /// Bytes held by the structure.
  size_t GetMemorySize() const;

  /// Recompute every cached quantity from the triangle list alone and compare (tests): returns
  /// true when consistent and, when `why` is given, describes the first difference otherwise.
  bool CheckConsistency(std::string* why = nullptr) const;

private:
  static constexpr int BlockSize = 10;
  // The wedges of one vertex; 128 bytes, blocks chained through Next.
  struct alignas(64) Block
  {
    int32_t Out[BlockSize];
    int32_t In[BlockSize];
    int32_t Tri[BlockSize];
    int32_t Count;
    int32_t Next;
  };

  // Wedge scan over the blocks of v: f(out, in, tri) returns true to stop.
  template <typename F>
  bool ForEachWedge(int32_t v, F&& f) const;
  void AddWedge(int32_t v, int32_t out, int32_t in, int32_t tri);
  void RemoveWedge(int32_t v, int32_t tri);
  int32_t NewBlock();
  void UpdateVertex(int32_t v);
  void UpdateVertexAfterAdd(int32_t v, int32_t out, int32_t in);
  bool HasOut(int32_t v, int32_t x) const;
  // The general cases of the inline queries above (any number of fans).
  static int OneVertex(int32_t x, int32_t* list, int capacity)
  {
    if (capacity > 0)
    {
      list[0] = x;
    }
    return 1;
  }
  bool IsBoundaryHalfEdgeScan(int32_t a, int32_t b) const;
  int GetBoundaryOutVerticesScan(int32_t v, int32_t* out, int capacity) const;
  int GetBoundaryInVerticesScan(int32_t v, int32_t* in, int capacity) const;
  int32_t NextBoundaryVertexWalk(int32_t a, int32_t b) const;
  int32_t PreviousBoundaryVertexWalk(int32_t a, int32_t b) const;
  bool HasIn(int32_t v, int32_t x) const;

  std::vector<int32_t> Triangles;
  std::vector<int32_t> Head; // first block of each vertex, -1 when free
  std::vector<uint8_t> State;
  std::vector<uint8_t> Fans;
  // For a front vertex with a single fan: its front edges v->FrontOut[v] and FrontIn[v]->v
  // (-1 otherwise), so that the front queries of the common case read no wedge list.
  std::vector<int32_t> FrontOut;
  std::vector<int32_t> FrontIn;
  std::vector<Block> Blocks;
  std::vector<int32_t> FreeBlocks;
  // ReverseComponent's visited flags per triangle id, all 0 between calls (cleared over the
  // component only, so that a small component does not cost a pass over every triangle id).
  std::vector<uint8_t> ReverseVisited;
  int64_t NumberOfTriangles = 0;
  int64_t NumberOfBoundaryHalfEdges = 0;
};
} // namespace pcs

#endif
