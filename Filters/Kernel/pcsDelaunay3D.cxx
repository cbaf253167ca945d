// Incremental 3D Delaunay tetrahedralization (private kernel). See pcsDelaunay3D.h and the class
// documentation of vtkIncrementalDelaunay3D for the algorithm and its references.
//
// Bowyer-Watson insertion (paper 000, section 2): locate the new point p by a stochastic
// visibility walk, grow the cavity of the cells in conflict with p by a breadth-first search
// over cell adjacency, and replace it by the star of p over the cavity boundary. The cavity of a
// Delaunay triangulation is star-shaped from p, so every new cell (a boundary facet joined to p)
// is positively oriented without any test.
//
// Conflicts (all decided exactly, with symbolic perturbation):
// - finite cell (a,b,c,d): InSphereSoS(a,b,c,d,p) > 0;
// - infinite cell whose finite facet is (a,b,c): p strictly beyond the hull facet abc, or p in
//   its plane and inside its (perturbed) circumcircle.
#include "pcsDelaunay3D.h"

#include "pcsPredicates.h"
#include "pcsSpatialSort.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <new>
#include <sstream>
#include <utility>

namespace pcs
{
namespace
{
constexpr uint32_t NoCell = 0xffffffffu;
constexpr size_t MaximumMatrixVertices = 96;

struct BoundaryFacet
{
  int32_t Vertices[4]; // vertices of the new cell (p already in Slot)
  uint32_t Outside;    // link to the cell outside the cavity: 4 * cell + mirror index
  int16_t Slot;        // position of p in the new cell
  uint16_t Local[4];   // cavity-boundary numbers of the vertices (not of p)
};

// For p in slot s, the facet of the new cell opposite slot k != s holds p and the vertices of
// slots EdgeSlots[s][k][0] and EdgeSlots[s][k][1].
constexpr int8_t EdgeSlots[4][4][2] = {
  { { -1, -1 }, { 2, 3 }, { 1, 3 }, { 1, 2 } },
  { { 2, 3 }, { -1, -1 }, { 0, 3 }, { 0, 2 } },
  { { 1, 3 }, { 0, 3 }, { -1, -1 }, { 0, 1 } },
  { { 1, 2 }, { 0, 2 }, { 0, 1 }, { -1, -1 } },
};

bool SamePoint(const double* a, const double* b)
{
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

bool Collinear(const double* a, const double* b, const double* c)
{
  using predicates::Orient2D;
  if (Orient2D(a, b, c) != 0)
  {
    return false;
  }
  const double ayz[2] = { a[1], a[2] }, byz[2] = { b[1], b[2] }, cyz[2] = { c[1], c[2] };
  if (Orient2D(ayz, byz, cyz) != 0)
  {
    return false;
  }
  const double axz[2] = { a[0], a[2] }, bxz[2] = { b[0], b[2] }, cxz[2] = { c[0], c[2] };
  return Orient2D(axz, bxz, cxz) == 0;
}
} // namespace

//------------------------------------------------------------------------------------------------
class Delaunay3DBuilder
{
public:
  Delaunay3DBuilder(Delaunay3D& dt, const double* xyz)
    : Owner(dt)
    , Cells(dt.Cells)
    , Duplicates(dt.Duplicates)
    , XYZ(xyz)
  {
  }

  bool Run(std::vector<int32_t> order, const Delaunay3D::ProgressFunction& progress);

private:
  const double* P(int32_t id) const { return this->XYZ + 3 * static_cast<int64_t>(id); }

  uint32_t NewCell()
  {
    if (!this->Free.empty())
    {
      const uint32_t c = this->Free.back();
      this->Free.pop_back();
      return c;
    }
    const uint32_t c = static_cast<uint32_t>(this->Cells.size());
    this->Cells.emplace_back();
    this->State.push_back(0);
    return c;
  }

  static int InfiniteSlot(const int32_t* v)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (v[k] < 0)
      {
        return k;
      }
    }
    return -1;
  }

  bool InConflict(uint32_t c, const double* p) const;
  uint32_t Locate(const double* p);
  void Insert(int32_t id);
  bool Initialize(std::vector<int32_t>& order);
  void Link(uint32_t cell, int slot, uint32_t other, int otherSlot)
  {
    this->Cells[cell].Neighbors[slot] = (other << 2) | static_cast<uint32_t>(otherSlot);
    this->Cells[other].Neighbors[otherSlot] = (cell << 2) | static_cast<uint32_t>(slot);
  }
  void Compact();

  // Open-addressing table from a cavity edge (two vertex ids) to the new cell and the slot of
  // the facet (p + that edge) waiting for its second cell.
  void LinkAroundEdge(int32_t a, int32_t b, uint32_t cell, int slot);
  void ClearEdgeTable();

  Delaunay3D& Owner;
  std::vector<Delaunay3D::Cell>& Cells;
  std::vector<std::pair<int32_t, int32_t>>& Duplicates;
  const double* XYZ;
  std::vector<uint8_t> State; // 0 untested, 1 in the cavity, 2 tested and outside
  std::vector<uint32_t> Free;
  std::vector<uint32_t> Cavity;
  std::vector<uint32_t> Stack;
  std::vector<uint32_t> Outside;
  std::vector<BoundaryFacet> Boundary;
  std::vector<uint64_t> EdgeKeys;
  std::vector<uint32_t> EdgeValues;
  std::vector<uint32_t> EdgeUsed;
  std::vector<int32_t> LocalIndex; // per point: number in the current cavity boundary, or -1
  int32_t InfiniteLocalIndex = -1;
  std::vector<int32_t> LocalVertices;
  std::vector<uint32_t> EdgeMatrix;
  uint32_t Hint = 0;
  double StaticInSphereBound = 0.0; // static filters from the extent of all points
  double StaticOrientBound = 0.0;
  uint64_t Random = 0x9E3779B97F4A7C15ull;
};

//------------------------------------------------------------------------------------------------
bool Delaunay3DBuilder::InConflict(uint32_t c, const double* p) const
{
  const int32_t* v = this->Cells[c].Vertices;
  const int inf = InfiniteSlot(v);
  if (inf < 0)
  {
    const double *a = this->P(v[0]), *b = this->P(v[1]), *c = this->P(v[2]), *d = this->P(v[3]);
    int side = predicates::InSphereStatic(a, b, c, d, p, this->StaticInSphereBound);
    if (side == 0)
    {
      side = predicates::InSphere(a, b, c, d, p, this->StaticInSphereBound);
    }
    return (side != 0 ? side : predicates::InSphereSoS(a, b, c, d, p)) > 0;
  }
  const double* w[4];
  for (int k = 0; k < 4; ++k)
  {
    w[k] = k == inf ? p : this->P(v[k]);
  }
  const int side = predicates::Orient3D(w[0], w[1], w[2], w[3]);
  if (side != 0)
  {
    return side > 0;
  }
  // p lies in the plane of the hull facet: in conflict when inside its circumcircle. The vertex
  // of the finite neighbour opposite the facet fixes the reference orientation.
  const uint32_t link = this->Cells[c].Neighbors[inf];
  w[inf] = this->P(this->Cells[link >> 2].Vertices[link & 3]);
  return predicates::InSphereSoS(w[0], w[1], w[2], w[3], p) *
      predicates::Orient3D(w[0], w[1], w[2], w[3]) >
    0;
}

//------------------------------------------------------------------------------------------------
// Stochastic visibility walk. Returns a cell in conflict with p: the finite cell that contains
// it (p inside a closed tetrahedron and not one of its vertices is strictly inside its
// circumsphere), or the infinite cell behind a hull facet that p sees strictly.
uint32_t Delaunay3DBuilder::Locate(const double* p)
{
  uint32_t c = this->Hint;
  {
    const int inf = InfiniteSlot(this->Cells[c].Vertices);
    if (inf >= 0)
    {
      c = this->Cells[c].Neighbors[inf] >> 2;
    }
  }
  uint32_t previous = NoCell;
  for (;;)
  {
    const int32_t* v = this->Cells[c].Vertices;
    if (InfiniteSlot(v) >= 0)
    {
      return c;
    }
    const double* w[4] = { this->P(v[0]), this->P(v[1]), this->P(v[2]), this->P(v[3]) };
    this->Random ^= this->Random << 13;
    this->Random ^= this->Random >> 7;
    this->Random ^= this->Random << 17;
    const int start = static_cast<int>(this->Random >> 62);
    uint32_t next = NoCell;
    for (int t = 0; t < 4; ++t)
    {
      const int j = (start + t) & 3;
      const uint32_t n = this->Cells[c].Neighbors[j] >> 2;
      if (n == previous)
      {
        continue;
      }
      const double* saved = w[j];
      w[j] = p;
      int side = predicates::Orient3DStatic(w[0], w[1], w[2], w[3], this->StaticOrientBound);
      if (side == 0)
      {
        side = predicates::Orient3D(w[0], w[1], w[2], w[3], this->StaticOrientBound);
      }
      w[j] = saved;
      if (side < 0)
      {
        next = n;
        break;
      }
    }
    if (next == NoCell)
    {
      return c;
    }
    previous = c;
    c = next;
  }
}

//------------------------------------------------------------------------------------------------
void Delaunay3DBuilder::LinkAroundEdge(int32_t a, int32_t b, uint32_t cell, int slot)
{
  const uint32_t ua = static_cast<uint32_t>(a), ub = static_cast<uint32_t>(b);
  const uint64_t key =
    ua < ub ? (uint64_t(ua) << 32 | ub) + 1 : (uint64_t(ub) << 32 | ua) + 1; // 0 marks empty
  const size_t mask = this->EdgeKeys.size() - 1;
  size_t h = static_cast<size_t>((key * 0x9E3779B97F4A7C15ull) >> 40) & mask;
  for (;; h = (h + 1) & mask)
  {
    if (this->EdgeKeys[h] == key)
    {
      const uint32_t other = this->EdgeValues[h];
      this->Link(cell, slot, other >> 2, static_cast<int>(other & 3));
      return;
    }
    if (this->EdgeKeys[h] == 0)
    {
      this->EdgeKeys[h] = key;
      this->EdgeValues[h] = (cell << 2) | static_cast<uint32_t>(slot);
      this->EdgeUsed.push_back(static_cast<uint32_t>(h));
      return;
    }
  }
}

void Delaunay3DBuilder::ClearEdgeTable()
{
  for (uint32_t h : this->EdgeUsed)
  {
    this->EdgeKeys[h] = 0;
  }
  this->EdgeUsed.clear();
}

//------------------------------------------------------------------------------------------------
void Delaunay3DBuilder::Insert(int32_t id)
{
  const double* p = this->P(id);
  const uint32_t seed = this->Locate(p);
  // A point equal to a vertex stops the walk in a finite cell of that vertex.
  const int32_t* sv = this->Cells[seed].Vertices;
  for (int k = 0; k < 4; ++k)
  {
    if (sv[k] >= 0 && SamePoint(this->P(sv[k]), p))
    {
      this->Duplicates.emplace_back(id, sv[k]);
      return;
    }
  }

  this->Cavity.clear();
  this->Outside.clear();
  this->Boundary.clear();
  this->State[seed] = 1;
  this->Cavity.push_back(seed);
  this->Stack.push_back(seed);
  while (!this->Stack.empty())
  {
    const uint32_t c = this->Stack.back();
    this->Stack.pop_back();
    for (int j = 0; j < 4; ++j)
    {
      const uint32_t link = this->Cells[c].Neighbors[j];
      const uint32_t n = link >> 2;
      uint8_t& state = this->State[n];
      if (state == 1)
      {
        continue;
      }
      if (state == 0)
      {
        if (this->InConflict(n, p))
        {
          state = 1;
          this->Cavity.push_back(n);
          this->Stack.push_back(n);
          continue;
        }
        state = 2;
        this->Outside.push_back(n);
      }
      this->Boundary.emplace_back();
      BoundaryFacet& facet = this->Boundary.back();
      const int32_t* cv = this->Cells[c].Vertices;
      for (int k = 0; k < 4; ++k)
      {
        facet.Vertices[k] = k == j ? id : cv[k];
      }
      facet.Slot = static_cast<int16_t>(j);
      facet.Outside = link;
    }
  }
  for (uint32_t c : this->Outside)
  {
    this->State[c] = 0;
  }
  for (uint32_t c : this->Cavity)
  {
    this->State[c] = 0;
  }

  // Each new cell has three facets through p, one per edge of its boundary facet; every such
  // edge is shared by exactly two boundary facets.
  const size_t keys = 3 * this->Boundary.size();
  if (2 * keys > this->EdgeKeys.size())
  {
    size_t size = 64;
    while (size < 2 * keys)
    {
      size *= 2;
    }
    this->EdgeKeys.assign(size, 0);
    this->EdgeValues.resize(size);
    this->EdgeUsed.clear();
  }

  const size_t reused = std::min(this->Cavity.size(), this->Boundary.size());
  for (size_t i = this->Boundary.size(); i < this->Cavity.size(); ++i)
  {
    this->Free.push_back(this->Cavity[i]);
  }
  // Small cavities (the usual case) pair the edges through a matrix indexed by local vertex
  // numbers; large ones through the hash table.
  size_t local = 0;
  for (BoundaryFacet& facet : this->Boundary)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (k == facet.Slot)
      {
        continue;
      }
      const int32_t v = facet.Vertices[k];
      int32_t& index = v < 0 ? this->InfiniteLocalIndex : this->LocalIndex[v];
      if (index < 0)
      {
        index = static_cast<int32_t>(local++);
        this->LocalVertices.push_back(v);
      }
      facet.Local[k] = static_cast<uint16_t>(index);
    }
  }
  const bool useMatrix = local <= MaximumMatrixVertices;
  if (useMatrix)
  {
    this->EdgeMatrix.assign(local * local, NoCell);
  }

  uint32_t cell = NoCell;
  for (size_t i = 0; i < this->Boundary.size(); ++i)
  {
    const BoundaryFacet& facet = this->Boundary[i];
    cell = i < reused ? this->Cavity[i] : this->NewCell();
    std::copy_n(facet.Vertices, 4, this->Cells[cell].Vertices);
    this->Link(cell, facet.Slot, facet.Outside >> 2, static_cast<int>(facet.Outside & 3));
    for (int k = 0; k < 4; ++k)
    {
      if (k == facet.Slot)
      {
        continue;
      }
      const int a = EdgeSlots[facet.Slot][k][0], b = EdgeSlots[facet.Slot][k][1];
      if (!useMatrix)
      {
        this->LinkAroundEdge(facet.Vertices[a], facet.Vertices[b], cell, k);
        continue;
      }
      size_t la = facet.Local[a], lb = facet.Local[b];
      if (la > lb)
      {
        std::swap(la, lb);
      }
      uint32_t& entry = this->EdgeMatrix[la * local + lb];
      if (entry == NoCell)
      {
        entry = (cell << 2) | static_cast<uint32_t>(k);
      }
      else
      {
        this->Link(cell, k, entry >> 2, static_cast<int>(entry & 3));
      }
    }
  }
  this->ClearEdgeTable();
  for (int32_t v : this->LocalVertices)
  {
    (v < 0 ? this->InfiniteLocalIndex : this->LocalIndex[v]) = -1;
  }
  this->LocalVertices.clear();
  this->Hint = cell;
}

//------------------------------------------------------------------------------------------------
// Build the first tetrahedron from the first four affinely independent points of the order and
// its four infinite neighbours; the points passed over are moved behind them.
bool Delaunay3DBuilder::Initialize(std::vector<int32_t>& order)
{
  const size_t n = order.size();
  if (n < 4)
  {
    return false;
  }
  size_t second = 1;
  while (second < n && SamePoint(this->P(order[0]), this->P(order[second])))
  {
    ++second;
  }
  if (second == n)
  {
    return false;
  }
  size_t third = 1;
  while (third < n &&
    (third == second ||
      Collinear(this->P(order[0]), this->P(order[second]), this->P(order[third]))))
  {
    ++third;
  }
  if (third == n)
  {
    return false;
  }
  size_t fourth = n;
  for (size_t i = 1; i < n; ++i)
  {
    if (i != second && i != third &&
      predicates::Orient3D(this->P(order[0]), this->P(order[second]), this->P(order[third]),
        this->P(order[i])) != 0)
    {
      fourth = i;
      break;
    }
  }
  if (fourth == n)
  {
    return false;
  }
  // Move the four chosen points to the front, keeping the relative order of the others.
  std::array<int32_t, 4> first = { order[0], order[second], order[third], order[fourth] };
  std::vector<int32_t> rest;
  rest.reserve(n - 4);
  for (size_t i = 1; i < n; ++i)
  {
    if (i != second && i != third && i != fourth)
    {
      rest.push_back(order[i]);
    }
  }
  std::copy(first.begin(), first.end(), order.begin());
  std::copy(rest.begin(), rest.end(), order.begin() + 4);

  if (predicates::Orient3D(
        this->P(first[0]), this->P(first[1]), this->P(first[2]), this->P(first[3])) < 0)
  {
    std::swap(first[0], first[1]);
  }
  this->Cells.clear();
  this->State.clear();
  this->Free.clear();
  for (int c = 0; c < 5; ++c)
  {
    this->NewCell();
  }
  std::copy(first.begin(), first.end(), this->Cells[0].Vertices);
  for (int j = 0; j < 4; ++j)
  {
    // Infinite cell j replaces vertex j by the infinite vertex; swapping two finite vertices
    // gives it the orientation seen from outside the hull.
    int32_t* v = this->Cells[j + 1].Vertices;
    std::copy(first.begin(), first.end(), v);
    v[j] = Delaunay3D::Infinite;
    std::swap(v[(j + 1) & 3], v[(j + 2) & 3]);
  }
  // Link the five cells by matching their facets.
  std::map<std::array<int32_t, 3>, std::pair<uint32_t, int>> facets;
  for (uint32_t c = 0; c < 5; ++c)
  {
    for (int j = 0; j < 4; ++j)
    {
      std::array<int32_t, 3> key;
      for (int m = 0, k = 0; m < 4; ++m)
      {
        if (m != j)
        {
          key[k++] = this->Cells[c].Vertices[m];
        }
      }
      std::sort(key.begin(), key.end());
      auto it = facets.find(key);
      if (it == facets.end())
      {
        facets.emplace(key, std::make_pair(c, j));
      }
      else
      {
        this->Link(c, j, it->second.first, it->second.second);
      }
    }
  }
  this->Hint = 0;
  return true;
}

//------------------------------------------------------------------------------------------------
// Drop the cells left on the free list and renumber the others.
void Delaunay3DBuilder::Compact()
{
  if (this->Free.empty())
  {
    return;
  }
  const size_t cells = this->Cells.size();
  std::vector<uint32_t> index(cells, 0);
  for (uint32_t c : this->Free)
  {
    index[c] = NoCell;
  }
  uint32_t next = 0;
  for (size_t c = 0; c < cells; ++c)
  {
    if (index[c] != NoCell)
    {
      index[c] = next++;
    }
  }
  for (size_t c = 0; c < cells; ++c)
  {
    const uint32_t to = index[c];
    if (to == NoCell)
    {
      continue;
    }
    Delaunay3D::Cell cell = this->Cells[c];
    for (int j = 0; j < 4; ++j)
    {
      cell.Neighbors[j] = (index[cell.Neighbors[j] >> 2] << 2) | (cell.Neighbors[j] & 3);
    }
    this->Cells[to] = cell;
  }
  this->Cells.resize(next);
  // Shrinking copies every cell: worth it only when much of the capacity is unused (after a
  // reallocation beyond the initial reservation).
  if (this->Cells.capacity() > this->Cells.size() + this->Cells.size() / 4)
  {
    this->Cells.shrink_to_fit();
  }
  this->Free.clear();
}

//------------------------------------------------------------------------------------------------
bool Delaunay3DBuilder::Run(std::vector<int32_t> order, const Delaunay3D::ProgressFunction& progress)
{
  BRIOHilbertOrder(this->XYZ, 3, order);
  // Work on a copy of the coordinates laid out in insertion order: consecutive insertions then
  // touch nearby memory. Vertex numbers are positions in that copy until the end.
  const size_t n = order.size();
  std::vector<double> coordinates(3 * n);
  for (size_t i = 0; i < n; ++i)
  {
    std::copy_n(this->XYZ + 3 * static_cast<int64_t>(order[i]), 3, &coordinates[3 * i]);
  }
  const double* original = this->XYZ;
  this->XYZ = coordinates.data();
  {
    double lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 };
    for (size_t i = 0; i < n; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        const double x = coordinates[3 * i + k];
        lo[k] = i == 0 ? x : std::min(lo[k], x);
        hi[k] = i == 0 ? x : std::max(hi[k], x);
      }
    }
    const double extent = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
    this->StaticInSphereBound = predicates::InSphereStaticBound(extent);
    this->StaticOrientBound = predicates::Orient3DStaticBound(extent);
  }
  std::vector<int32_t> insertion(n);
  for (size_t i = 0; i < n; ++i)
  {
    insertion[i] = static_cast<int32_t>(i);
  }
  this->LocalIndex.assign(n, -1);
  const bool initialized = this->Initialize(insertion);
  if (initialized)
  {
    // About 6.5 cells per point in a uniform cloud, plus the infinite cells.
    this->Cells.reserve(7 * n + 64);
    this->State.reserve(7 * n + 64);
    const size_t step = std::max<size_t>(n / 100, 1000);
    for (size_t i = 4; i < n; ++i)
    {
      if (i % step == 0 && progress && !progress(static_cast<double>(i) / n))
      {
        this->XYZ = original;
        return false;
      }
      this->Insert(insertion[i]);
    }
  }
  this->XYZ = original;
  if (!initialized)
  {
    return false;
  }
  this->State = std::vector<uint8_t>();
  this->LocalIndex = std::vector<int32_t>();
  this->Compact();
  // One pass over the cells: count the finite ones, compute their circumradii (coordinates
  // still in insertion order) and map the vertices back to the caller's point ids.
  double* radii = nullptr;
  if (this->Owner.ComputeCircumradii)
  {
    // At most one radius per cell; malloc so that the caller may adopt the buffer
    // (ReleaseCircumradii) without a copy. Pages past the finite count are never touched.
    radii = static_cast<double*>(std::malloc(sizeof(double) * (this->Cells.size() + 1)));
    if (!radii)
    {
      throw std::bad_alloc();
    }
    this->Owner.Circumradii.reset(radii);
  }
  const double* xyz = coordinates.data();
  int64_t finite = 0;
  for (Delaunay3D::Cell& cell : this->Cells)
  {
    int32_t* v = cell.Vertices;
    if (InfiniteSlot(v) < 0)
    {
      if (radii)
      {
        radii[finite] = Delaunay3D::Circumradius(xyz + 3 * static_cast<size_t>(v[0]),
          xyz + 3 * static_cast<size_t>(v[1]), xyz + 3 * static_cast<size_t>(v[2]),
          xyz + 3 * static_cast<size_t>(v[3]));
      }
      ++finite;
      for (int k = 0; k < 4; ++k)
      {
        v[k] = order[v[k]];
      }
    }
    else
    {
      for (int k = 0; k < 4; ++k)
      {
        v[k] = v[k] >= 0 ? order[v[k]] : v[k];
      }
    }
  }
  this->Owner.NumberOfFiniteCells = finite;
  for (auto& duplicate : this->Duplicates)
  {
    duplicate.first = order[duplicate.first];
    duplicate.second = order[duplicate.second];
  }
  if (this->Owner.KeepInsertionOrder)
  {
    this->Owner.InsertionOrder = std::move(order);
  }
  return true;
}

//------------------------------------------------------------------------------------------------
void Delaunay3D::Circumsphere(const double* a, const double* b, const double* c, const double* d,
  double center[3], double& radius)
{
  double offset[3];
  radius = CircumsphereOffset(a, b, c, d, offset);
  for (int i = 0; i < 3; ++i)
  {
    center[i] = a[i] + offset[i];
  }
}

// Radius only: |N| / |2 det| with N the numerator vector of CircumsphereOffset (no division
// per component; this runs once per tetrahedron of the output).
double Delaunay3D::Circumradius(const double* a, const double* b, const double* c, const double* d)
{
  const double bx = b[0] - a[0], by = b[1] - a[1], bz = b[2] - a[2];
  const double cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
  const double dx = d[0] - a[0], dy = d[1] - a[1], dz = d[2] - a[2];
  const double cdx = cy * dz - cz * dy, cdy = cz * dx - cx * dz, cdz = cx * dy - cy * dx;
  const double dbx = dy * bz - dz * by, dby = dz * bx - dx * bz, dbz = dx * by - dy * bx;
  const double bcx = by * cz - bz * cy, bcy = bz * cx - bx * cz, bcz = bx * cy - by * cx;
  const double determinant = bx * cdx + by * cdy + bz * cdz;
  const double lb = bx * bx + by * by + bz * bz;
  const double lc = cx * cx + cy * cy + cz * cz;
  const double ld = dx * dx + dy * dy + dz * dz;
  const double nx = lb * cdx + lc * dbx + ld * bcx;
  const double ny = lb * cdy + lc * dby + ld * bcy;
  const double nz = lb * cdz + lc * dbz + ld * bcz;
  return determinant == 0.0 ? std::numeric_limits<double>::infinity()
                            : std::sqrt(nx * nx + ny * ny + nz * nz) / std::fabs(2.0 * determinant);
}

// Centre minus a, from the three edge vectors at a; returns the radius.
double Delaunay3D::CircumsphereOffset(
  const double* a, const double* b, const double* c, const double* d, double offset[3])
{
  double ba[3], ca[3], da[3];
  for (int i = 0; i < 3; ++i)
  {
    ba[i] = b[i] - a[i];
    ca[i] = c[i] - a[i];
    da[i] = d[i] - a[i];
  }
  const double cxd[3] = { ca[1] * da[2] - ca[2] * da[1], ca[2] * da[0] - ca[0] * da[2],
    ca[0] * da[1] - ca[1] * da[0] };
  const double dxb[3] = { da[1] * ba[2] - da[2] * ba[1], da[2] * ba[0] - da[0] * ba[2],
    da[0] * ba[1] - da[1] * ba[0] };
  const double bxc[3] = { ba[1] * ca[2] - ba[2] * ca[1], ba[2] * ca[0] - ba[0] * ca[2],
    ba[0] * ca[1] - ba[1] * ca[0] };
  const double denominator = 2.0 * (ba[0] * cxd[0] + ba[1] * cxd[1] + ba[2] * cxd[2]);
  if (denominator == 0.0)
  {
    offset[0] = offset[1] = offset[2] = std::numeric_limits<double>::quiet_NaN();
    return std::numeric_limits<double>::infinity();
  }
  const double lb = ba[0] * ba[0] + ba[1] * ba[1] + ba[2] * ba[2];
  const double lc = ca[0] * ca[0] + ca[1] * ca[1] + ca[2] * ca[2];
  const double ld = da[0] * da[0] + da[1] * da[1] + da[2] * da[2];
  const double inverse = 1.0 / denominator;
  double squared = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    offset[i] = (lb * cxd[i] + lc * dxb[i] + ld * bxc[i]) * inverse;
    squared += offset[i] * offset[i];
  }
  return std::sqrt(squared);
}

//------------------------------------------------------------------------------------------------
bool Delaunay3D::Triangulate(
  const double* xyz, const std::vector<int32_t>& ids, const ProgressFunction& progress)
{
  this->Clear();
  Delaunay3DBuilder builder(*this, xyz);
  if (!builder.Run(ids, progress))
  {
    this->Clear();
    return false;
  }
  return true;
}

std::vector<int32_t> Delaunay3D::RenumberByInsertion()
{
  std::vector<int32_t> order = std::move(this->InsertionOrder);
  this->InsertionOrder = std::vector<int32_t>();
  if (order.empty())
  {
    return order;
  }
  this->Circumradii.reset();
  const int32_t largestId = *std::max_element(order.begin(), order.end());
  std::vector<int32_t> position(static_cast<size_t>(largestId) + 1, -1);
  for (size_t i = 0; i < order.size(); ++i)
  {
    position[order[i]] = static_cast<int32_t>(i);
  }
  // Counting sort of the cells by their newest vertex: first[v + 1] counts the cells whose
  // newest vertex is v, then holds where they start.
  const size_t cells = this->Cells.size();
  std::vector<uint32_t> index(cells);
  std::vector<uint32_t> first(order.size() + 1, 0);
  for (size_t c = 0; c < cells; ++c)
  {
    int32_t* v = this->Cells[c].Vertices;
    int32_t newest = 0;
    for (int k = 0; k < 4; ++k)
    {
      v[k] = v[k] >= 0 ? position[v[k]] : v[k];
      newest = std::max(newest, v[k]);
    }
    index[c] = static_cast<uint32_t>(newest);
    ++first[newest + 1];
  }
  for (size_t i = 1; i < first.size(); ++i)
  {
    first[i] += first[i - 1];
  }
  for (size_t c = 0; c < cells; ++c)
  {
    index[c] = first[index[c]]++;
  }
  std::vector<Cell> sorted(cells);
  for (size_t c = 0; c < cells; ++c)
  {
    Cell cell = this->Cells[c];
    for (int j = 0; j < 4; ++j)
    {
      cell.Neighbors[j] = (index[cell.Neighbors[j] >> 2] << 2) | (cell.Neighbors[j] & 3);
    }
    sorted[index[c]] = cell;
  }
  this->Cells.swap(sorted);
  return order;
}

void Delaunay3D::Clear()
{
  this->Cells = std::vector<Cell>();
  this->InsertionOrder = std::vector<int32_t>();
  this->Circumradii.reset();
  this->NumberOfFiniteCells = 0;
  this->Duplicates.clear();
}

std::string Delaunay3D::DescribeLargeSize(size_t inserted) const
{
  const double vertices =
    static_cast<double>(inserted) - static_cast<double>(this->Duplicates.size());
  const double cells = static_cast<double>(this->NumberOfFiniteCells);
  if (!(vertices > 0.0) || !(cells > LargeCellsPerVertex * vertices))
  {
    return std::string();
  }
  std::ostringstream text;
  text.precision(3);
  text << "The Delaunay tetrahedralization has " << this->NumberOfFiniteCells << " tetrahedra for "
       << static_cast<int64_t>(vertices) << " distinct points (" << cells / vertices
       << " per point; a well-spread sample has about 3 on a surface, 6.7 in a volume): the points "
          "lie along curves or in another configuration whose Delaunay size grows faster than "
          "the number of points (up to n^2 / 2 tetrahedra), and time and memory grow with it.";
  return text.str();
}
} // namespace pcs
