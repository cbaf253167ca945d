// Incremental 3D Delaunay tetrahedralization (private kernel). See vtkIncrementalDelaunay3D.h
// for the algorithm and its references.
#ifndef pcsDelaunay3D_h
#define pcsDelaunay3D_h

#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pcs
{
class Delaunay3D
{
public:
  /// Progress/abort callback: receives a fraction in [0, 1]; returning false aborts.
  using ProgressFunction = std::function<bool(double)>;

  /// The infinite vertex that closes the triangulation around its convex hull.
  static constexpr int32_t Infinite = -1;

  /// Tetrahedralize the points `ids` of `xyz` (packed x,y,z triples). The referenced points
  /// must be finite. A point equal to one already inserted is not inserted again: it is listed in
  /// GetDuplicates() with the vertex that represents it. Returns false when all points are
  /// coplanar (or fewer than 4 distinct points) or when the progress callback aborted; the
  /// triangulation is then empty.
  bool Triangulate(const double* xyz, const std::vector<int32_t>& ids,
    const ProgressFunction& progress = ProgressFunction());

  /// Also compute the circumradius of every finite cell during Triangulate (GetCircumradii): the
  /// coordinates are then still laid out in insertion order, so the four vertices of a cell are
  /// close in memory. Default off.
  void SetComputeCircumradii(bool compute) { this->ComputeCircumradii = compute; }

  /// Circumradius of each finite cell, in cell order (the k-th finite cell has radius k), when
  /// requested; nullptr otherwise. The buffer holds one double per finite cell.
  const double* GetCircumradii() const { return this->Circumradii.get(); }

  /// Hand the circumradius buffer over to the caller, who releases it with free(). The
  /// triangulation then no longer holds radii.
  double* ReleaseCircumradii() { return this->Circumradii.release(); }

  /// Keep the insertion order after Triangulate, for RenumberByInsertion (4 bytes per point).
  /// Default off.
  void SetKeepInsertionOrder(bool keep) { this->KeepInsertionOrder = keep; }

  /// Renumber for memory locality (after Triangulate with SetKeepInsertionOrder on): vertex ids
  /// become insertion positions (BRIO rounds, each along a Hilbert curve; the last round holds
  /// 7/8 of the points) and the cells are sorted by their newest vertex (stable), so that cells
  /// and vertices close in space are mostly close in memory. Returns the point id at each
  /// insertion position (the caller's ids, duplicates included: no cell references those), that
  /// is, of each vertex id; Vertex() then returns vertex ids, not point ids. Returns an empty
  /// vector and changes nothing when the order was not kept. GetDuplicates() keeps point ids;
  /// circumradii are released (they follow the old cell order). Costs one pass over the cells
  /// and a copy of them.
  std::vector<int32_t> RenumberByInsertion();

  /// Number of finite cells.
  int64_t GetNumberOfFiniteCells() const { return this->NumberOfFiniteCells; }

  /// Finite cells per vertex beyond which the tetrahedralization is reported as unusually large:
  /// a well-spread sample has about 3 per point on a surface and 6.7 in a volume (lattices and
  /// scan rings included); points along a curve (a helix: n^1.5, the moment curve: n^2 / 2) or
  /// arranged on a cylinder (Erickson, "Nice point sets can have nasty Delaunay
  /// triangulations") have many more, and time and memory grow with them.
  static constexpr double LargeCellsPerVertex = 25.0;

  /// After Triangulate: a sentence for a warning when the finite cells exceed
  /// LargeCellsPerVertex per distinct vertex (`inserted` points given, duplicates left out),
  /// else an empty string.
  std::string DescribeLargeSize(size_t inserted) const;

  /// Circumcentre and circumradius of the tetrahedron abcd (NaN centre and infinite radius when
  /// it is flat in floating point).
  static void Circumsphere(const double* a, const double* b, const double* c, const double* d,
    double center[3], double& radius);

  /// Circumradius only (+inf when flat in floating point).
  static double Circumradius(const double* a, const double* b, const double* c, const double* d);

  /// Number of cells, finite and infinite.
  int64_t GetNumberOfCells() const { return static_cast<int64_t>(this->Cells.size()); }

  /// Vertex j (0..3) of cell c: a point id, or Infinite. Finite cells are positively oriented
  /// (Orient3D(v0, v1, v2, v3) > 0). In an infinite cell, the finite facet seen from the
  /// infinite vertex has the orientation of the finite cell facets: replacing Infinite by a
  /// point beyond the hull gives a positively oriented tetrahedron.
  int32_t Vertex(int64_t c, int j) const { return this->Cells[c].Vertices[j]; }

  /// The four vertices of cell c.
  const int32_t* CellVertices(int64_t c) const { return this->Cells[c].Vertices; }

  /// Neighbour of cell c across the facet opposite vertex j.
  int64_t Neighbor(int64_t c, int j) const { return this->Cells[c].Neighbors[j] >> 2; }

  /// Index, in the neighbour across facet j of c, of the vertex opposite that facet.
  int MirrorIndex(int64_t c, int j) const { return this->Cells[c].Neighbors[j] & 3; }

  bool IsInfinite(int64_t c) const
  {
    const int32_t* v = this->Cells[c].Vertices;
    return v[0] < 0 || v[1] < 0 || v[2] < 0 || v[3] < 0;
  }

  /// Points found equal to an inserted vertex: (point id, vertex id) pairs.
  const std::vector<std::pair<int32_t, int32_t>>& GetDuplicates() const { return this->Duplicates; }

  /// Release the memory of the triangulation.
  void Clear();

private:
  static double CircumsphereOffset(
    const double* a, const double* b, const double* c, const double* d, double offset[3]);

  // One 32-byte record per cell (vertices and links side by side: one cache line visit).
  struct Cell
  {
    int32_t Vertices[4];
    uint32_t Neighbors[4]; // 4 * neighbour cell + mirror index
  };
  std::vector<Cell> Cells;
  std::vector<std::pair<int32_t, int32_t>> Duplicates;
  struct FreeDeleter
  {
    void operator()(double* p) const { std::free(p); }
  };
  std::unique_ptr<double[], FreeDeleter> Circumradii;
  std::vector<int32_t> InsertionOrder; // point id of each insertion position, when kept
  int64_t NumberOfFiniteCells = 0;
  bool ComputeCircumradii = false;
  bool KeepInsertionOrder = false;
  friend class Delaunay3DBuilder;
};
} // namespace pcs

#endif
