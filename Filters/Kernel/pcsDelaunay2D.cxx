// Incremental 2D Delaunay triangulation with Lawson flips (private kernel). See pcsDelaunay2D.h.
//
// Each point is located by a visibility walk. Inside a triangle it splits it in three; on an
// edge it splits the two triangles sharing that edge in four; outside the convex hull it splits
// the infinite triangle of a hull edge it sees. Every new triangle holds the new point p at
// index 0, and the edge opposite p is flipped while the triangle across it is in conflict with
// p (paper 002, section 3.1). Conflicts are decided exactly:
// - finite triangle (a,b,c): InCircleSoS(a,b,c,p) > 0 (symbolic perturbation for cocircular
//   points, so grids get a valid triangulation independent of insertion order);
// - infinite triangle (u,v,inf) of hull edge uv: p strictly beyond the line uv, or on it and
//   strictly between u and v.
#include "pcsDelaunay2D.h"

#include "pcsPredicates.h"
#include "pcsSpatialSort.h"

#include <algorithm>

namespace pcs
{
namespace
{
constexpr uint32_t NoTriangle = 0xffffffffu;

struct Triangle
{
  int32_t V[3];  // counter-clockwise; -1 is the infinite vertex
  uint32_t N[3]; // across the edge opposite V[i]: 4 * triangle + mirror index
};

enum class Location
{
  Inside,
  OnEdge,
  Outside,
  OnVertex
};

class Delaunay2DBuilder
{
public:
  explicit Delaunay2DBuilder(const double* xy)
    : XY(xy)
  {
  }

  bool Run(std::vector<int32_t> order, const Delaunay2D::ProgressFunction& progress);
  void Export(std::vector<int32_t>& triangles, std::vector<int32_t>& neighbors) const;

private:
  const double* P(int32_t id) const { return this->XY + 2 * static_cast<int64_t>(id); }
  static int InfiniteIndex(const Triangle& t)
  {
    return t.V[0] < 0 ? 0 : (t.V[1] < 0 ? 1 : (t.V[2] < 0 ? 2 : -1));
  }
  void Link(uint32_t a, int i, uint32_t b, int j)
  {
    this->T[a].N[i] = (b << 2) | static_cast<uint32_t>(j);
    this->T[b].N[j] = (a << 2) | static_cast<uint32_t>(i);
  }
  // Set the link of a's edge i to the outer link `outer` and the reverse link.
  void Attach(uint32_t a, int i, uint32_t outer)
  {
    this->Link(a, i, outer >> 2, static_cast<int>(outer & 3));
  }
  uint32_t NewTriangle()
  {
    this->T.emplace_back();
    return static_cast<uint32_t>(this->T.size() - 1);
  }

  bool InConflict(uint32_t t, const double* p) const;
  uint32_t Locate(const double* p, Location& where, int& edge);
  void Insert(int32_t id);
  void Legalize(const double* p);
  bool Initialize(std::vector<int32_t>& order);

  const double* XY;
  std::vector<Triangle> T;
  std::vector<uint32_t> Stack;
  uint32_t Hint = 0;
  uint64_t Random = 0x2545F4914F6CDD1Dull;

public:
  int64_t Flips = 0;
};

//------------------------------------------------------------------------------------------------
bool Delaunay2DBuilder::InConflict(uint32_t t, const double* p) const
{
  const Triangle& tri = this->T[t];
  const int inf = InfiniteIndex(tri);
  if (inf < 0)
  {
    return predicates::InCircleSoS(this->P(tri.V[0]), this->P(tri.V[1]), this->P(tri.V[2]), p) > 0;
  }
  const double* u = this->P(tri.V[(inf + 1) % 3]);
  const double* v = this->P(tri.V[(inf + 2) % 3]);
  const int side = predicates::Orient2D(u, v, p);
  if (side != 0)
  {
    return side > 0;
  }
  const int cu = predicates::CompareLexicographic(p, u, 2);
  const int cv = predicates::CompareLexicographic(p, v, 2);
  return cu * cv < 0; // strictly between u and v on their line
}

//------------------------------------------------------------------------------------------------
uint32_t Delaunay2DBuilder::Locate(const double* p, Location& where, int& edge)
{
  uint32_t t = this->Hint;
  {
    const int inf = InfiniteIndex(this->T[t]);
    if (inf >= 0)
    {
      t = this->T[t].N[inf] >> 2;
    }
  }
  uint32_t previous = NoTriangle;
  for (;;)
  {
    const Triangle& tri = this->T[t];
    if (InfiniteIndex(tri) >= 0)
    {
      where = Location::Outside;
      return t;
    }
    this->Random ^= this->Random << 13;
    this->Random ^= this->Random >> 7;
    this->Random ^= this->Random << 17;
    const int start = static_cast<int>(this->Random % 3);
    uint32_t next = NoTriangle;
    int zeros = 0;
    int zeroEdge = -1;
    for (int s = 0; s < 3; ++s)
    {
      const int i = (start + s) % 3;
      const uint32_t n = tri.N[i] >> 2;
      const int side =
        predicates::Orient2D(this->P(tri.V[(i + 1) % 3]), this->P(tri.V[(i + 2) % 3]), p);
      if (side < 0)
      {
        if (n != previous)
        {
          next = n;
          break;
        }
        // Coming back through the edge we crossed cannot happen for a strict side; keep
        // looking at the other edges.
        next = n;
      }
      else if (side == 0)
      {
        ++zeros;
        zeroEdge = i;
      }
    }
    if (next != NoTriangle)
    {
      previous = t;
      t = next;
      continue;
    }
    where = zeros == 0 ? Location::Inside : (zeros == 1 ? Location::OnEdge : Location::OnVertex);
    edge = zeroEdge;
    return t;
  }
}

//------------------------------------------------------------------------------------------------
void Delaunay2DBuilder::Insert(int32_t id)
{
  const double* p = this->P(id);
  Location where;
  int edge = -1;
  const uint32_t t = this->Locate(p, where, edge);
  if (where == Location::OnVertex)
  {
    return; // a duplicate: the caller merges them beforehand
  }
  this->Stack.clear();
  if (where == Location::Inside || where == Location::Outside)
  {
    // 1 -> 3 split of (a, b, c); each new triangle has p first.
    const Triangle old = this->T[t];
    const int32_t a = old.V[0], b = old.V[1], c = old.V[2];
    const uint32_t A = t, B = this->NewTriangle(), C = this->NewTriangle();
    this->T[A].V[0] = id, this->T[A].V[1] = b, this->T[A].V[2] = c;
    this->T[B].V[0] = id, this->T[B].V[1] = c, this->T[B].V[2] = a;
    this->T[C].V[0] = id, this->T[C].V[1] = a, this->T[C].V[2] = b;
    this->Attach(A, 0, old.N[0]);
    this->Attach(B, 0, old.N[1]);
    this->Attach(C, 0, old.N[2]);
    this->Link(A, 1, B, 2);
    this->Link(B, 1, C, 2);
    this->Link(C, 1, A, 2);
    this->Stack.insert(this->Stack.end(), { A, B, C });
  }
  else
  {
    // 2 -> 4 split of the edge (x, y) shared by t = (u, x, y) and o = (w, y, x).
    const Triangle old = this->T[t];
    const int32_t u = old.V[edge], x = old.V[(edge + 1) % 3], y = old.V[(edge + 2) % 3];
    const uint32_t o = old.N[edge] >> 2;
    const int m = static_cast<int>(old.N[edge] & 3);
    const Triangle other = this->T[o];
    const int32_t w = other.V[m];
    // In o = (w, y, x): the edge opposite y is (x, w), the edge opposite x is (w, y).
    const uint32_t outerXW = other.N[(m + 1) % 3];
    const uint32_t outerWY = other.N[(m + 2) % 3];
    const uint32_t outerUX = old.N[(edge + 2) % 3];
    const uint32_t outerYU = old.N[(edge + 1) % 3];
    const uint32_t T1 = t, T2 = o, T3 = this->NewTriangle(), T4 = this->NewTriangle();
    this->T[T1].V[0] = id, this->T[T1].V[1] = u, this->T[T1].V[2] = x;
    this->T[T2].V[0] = id, this->T[T2].V[1] = y, this->T[T2].V[2] = u;
    this->T[T3].V[0] = id, this->T[T3].V[1] = x, this->T[T3].V[2] = w;
    this->T[T4].V[0] = id, this->T[T4].V[1] = w, this->T[T4].V[2] = y;
    this->Attach(T1, 0, outerUX);
    this->Attach(T2, 0, outerYU);
    this->Attach(T3, 0, outerXW);
    this->Attach(T4, 0, outerWY);
    this->Link(T1, 1, T3, 2);
    this->Link(T1, 2, T2, 1);
    this->Link(T2, 2, T4, 1);
    this->Link(T3, 1, T4, 2);
    this->Stack.insert(this->Stack.end(), { T1, T2, T3, T4 });
  }
  this->Legalize(p);
}

//------------------------------------------------------------------------------------------------
// Flip the edge opposite p (index 0) of every stacked triangle while the triangle across it is
// in conflict with p.
void Delaunay2DBuilder::Legalize(const double* p)
{
  while (!this->Stack.empty())
  {
    const uint32_t t = this->Stack.back();
    this->Stack.pop_back();
    const uint32_t link = this->T[t].N[0];
    const uint32_t o = link >> 2;
    const int m = static_cast<int>(link & 3);
    if (!this->InConflict(o, p))
    {
      this->Hint = t;
      continue;
    }
    ++this->Flips;
    // t = (p, x, y), o = (z, y, x) with z at m: flip xy into pz.
    const Triangle tri = this->T[t];
    const Triangle other = this->T[o];
    const int32_t q = tri.V[0], x = tri.V[1], z = other.V[m];
    const int32_t y = tri.V[2];
    const uint32_t outerXZ = other.N[(m + 1) % 3]; // opposite y in o
    const uint32_t outerZY = other.N[(m + 2) % 3]; // opposite x in o
    const uint32_t outerYQ = tri.N[1];
    const uint32_t outerQX = tri.N[2];
    this->T[t].V[0] = q, this->T[t].V[1] = x, this->T[t].V[2] = z;
    this->T[o].V[0] = q, this->T[o].V[1] = z, this->T[o].V[2] = y;
    this->Attach(t, 0, outerXZ);
    this->Attach(t, 2, outerQX);
    this->Attach(o, 0, outerZY);
    this->Attach(o, 1, outerYQ);
    this->Link(t, 1, o, 2);
    this->Stack.push_back(t);
    this->Stack.push_back(o);
  }
}

//------------------------------------------------------------------------------------------------
bool Delaunay2DBuilder::Initialize(std::vector<int32_t>& order)
{
  const size_t n = order.size();
  if (n < 3)
  {
    return false;
  }
  size_t second = 1;
  while (second < n && predicates::CompareLexicographic(this->P(order[0]), this->P(order[second]), 2) == 0)
  {
    ++second;
  }
  size_t third = n;
  for (size_t i = second + 1; i < n; ++i)
  {
    if (predicates::Orient2D(this->P(order[0]), this->P(order[second]), this->P(order[i])) != 0)
    {
      third = i;
      break;
    }
  }
  if (third == n)
  {
    return false;
  }
  int32_t a = order[0], b = order[second], c = order[third];
  if (predicates::Orient2D(this->P(a), this->P(b), this->P(c)) < 0)
  {
    std::swap(a, b);
  }
  std::vector<int32_t> rest;
  rest.reserve(n - 3);
  for (size_t i = 1; i < n; ++i)
  {
    if (i != second && i != third)
    {
      rest.push_back(order[i]);
    }
  }
  order[0] = a;
  order[1] = b;
  order[2] = c;
  std::copy(rest.begin(), rest.end(), order.begin() + 3);

  // The finite triangle and the infinite triangles of its edges: (b, a, inf) is across the
  // edge opposite c, and so on.
  this->T.assign(4, Triangle());
  this->T[0] = { { a, b, c }, { 0, 0, 0 } };
  this->T[1] = { { b, a, -1 }, { 0, 0, 0 } }; // across edge ab (opposite c, index 2)
  this->T[2] = { { c, b, -1 }, { 0, 0, 0 } }; // across edge bc (opposite a, index 0)
  this->T[3] = { { a, c, -1 }, { 0, 0, 0 } }; // across edge ca (opposite b, index 1)
  this->Link(0, 2, 1, 2);
  this->Link(0, 0, 2, 2);
  this->Link(0, 1, 3, 2);
  // Infinite triangles share the edges (x, inf): (b, a, inf) and (a, c, inf) share (a, inf).
  this->Link(1, 0, 3, 1); // T1 opposite b: (a, inf); T3 opposite c: (inf, a)
  this->Link(1, 1, 2, 0); // T1 opposite a: (inf, b); T2 opposite c: (b, inf)
  this->Link(2, 1, 3, 0); // T2 opposite b: (inf, c); T3 opposite a: (c, inf)
  this->Hint = 0;
  return true;
}

//------------------------------------------------------------------------------------------------
bool Delaunay2DBuilder::Run(std::vector<int32_t> order, const Delaunay2D::ProgressFunction& progress)
{
  BRIOHilbertOrder(this->XY, 2, order);
  if (!this->Initialize(order))
  {
    return false;
  }
  const size_t n = order.size();
  this->T.reserve(2 * n + 16);
  const size_t step = std::max<size_t>(n / 100, 1000);
  for (size_t i = 3; i < n; ++i)
  {
    if (i % step == 0 && progress && !progress(static_cast<double>(i) / n))
    {
      return false;
    }
    this->Insert(order[i]);
  }
  return true;
}

//------------------------------------------------------------------------------------------------
void Delaunay2DBuilder::Export(std::vector<int32_t>& triangles, std::vector<int32_t>& neighbors) const
{
  std::vector<int32_t> index(this->T.size(), -1);
  int32_t finite = 0;
  for (size_t t = 0; t < this->T.size(); ++t)
  {
    if (InfiniteIndex(this->T[t]) < 0)
    {
      index[t] = finite++;
    }
  }
  triangles.resize(3 * static_cast<size_t>(finite));
  neighbors.resize(3 * static_cast<size_t>(finite));
  for (size_t t = 0; t < this->T.size(); ++t)
  {
    const int32_t f = index[t];
    if (f < 0)
    {
      continue;
    }
    for (int i = 0; i < 3; ++i)
    {
      triangles[3 * f + i] = this->T[t].V[i];
      neighbors[3 * f + i] = index[this->T[t].N[i] >> 2];
    }
  }
}
} // namespace

//------------------------------------------------------------------------------------------------
bool Delaunay2D::Triangulate(
  const double* xy, const std::vector<int32_t>& ids, const ProgressFunction& progress)
{
  this->Triangles.clear();
  this->Neighbors.clear();
  this->NumberOfFlips = 0;
  Delaunay2DBuilder builder(xy);
  if (!builder.Run(ids, progress))
  {
    return false;
  }
  builder.Export(this->Triangles, this->Neighbors);
  this->NumberOfFlips = builder.Flips;
  return true;
}
} // namespace pcs
