#include "pcsSurfaceMesh.h"

#include "pcsDisjointSets.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <utility>

namespace pcs
{
//------------------------------------------------------------------------------------------------
void SurfaceMesh::Initialize(int32_t numberOfVertices)
{
  numberOfVertices = std::max<int32_t>(numberOfVertices, 0);
  this->Triangles.clear();
  this->Head.assign(numberOfVertices, -1);
  this->State.assign(numberOfVertices, 0);
  this->Fans.assign(numberOfVertices, 0);
  this->FrontOut.assign(numberOfVertices, -1);
  this->FrontIn.assign(numberOfVertices, -1);
  // One block per vertex that gets a triangle (most of them), and a second one for the few of
  // degree above 10: reserved, not touched, so that the growing mesh does not copy its blocks at
  // a reallocation (with exactly one per vertex, 10^5 samples of CGAL's armadillo copied all
  // 12.8 MB once: their vertices of degree above 10 need a second block).
  this->Blocks.clear();
  this->Blocks.reserve(static_cast<size_t>(numberOfVertices) + numberOfVertices / 8 + 16);
  this->FreeBlocks.clear();
  this->NumberOfTriangles = 0;
  this->NumberOfBoundaryHalfEdges = 0;
}

void SurfaceMesh::ReserveTriangles(int64_t numberOfTriangles)
{
  this->Triangles.reserve(3 * static_cast<size_t>(std::max<int64_t>(numberOfTriangles, 0)));
}

size_t SurfaceMesh::GetMemorySize() const
{
  return this->Triangles.capacity() * sizeof(int32_t) + this->Head.capacity() * sizeof(int32_t) +
    this->State.capacity() + this->Fans.capacity() + this->Blocks.capacity() * sizeof(Block) +
    (this->FrontOut.capacity() + this->FrontIn.capacity()) * sizeof(int32_t) +
    this->FreeBlocks.capacity() * sizeof(int32_t);
}

//------------------------------------------------------------------------------------------------
template <typename F>
bool SurfaceMesh::ForEachWedge(int32_t v, F&& f) const
{
  for (int32_t k = this->Head[v]; k >= 0; k = this->Blocks[k].Next)
  {
    const Block& block = this->Blocks[k];
    for (int i = 0; i < block.Count; ++i)
    {
      if (f(block.Out[i], block.In[i], block.Tri[i]))
      {
        return true;
      }
    }
  }
  return false;
}

bool SurfaceMesh::HasOut(int32_t v, int32_t x) const
{
  for (int32_t k = this->Head[v]; k >= 0; k = this->Blocks[k].Next)
  {
    const Block& block = this->Blocks[k];
    for (int i = 0; i < block.Count; ++i)
    {
      if (block.Out[i] == x)
      {
        return true;
      }
    }
  }
  return false;
}

bool SurfaceMesh::HasIn(int32_t v, int32_t x) const
{
  for (int32_t k = this->Head[v]; k >= 0; k = this->Blocks[k].Next)
  {
    const Block& block = this->Blocks[k];
    for (int i = 0; i < block.Count; ++i)
    {
      if (block.In[i] == x)
      {
        return true;
      }
    }
  }
  return false;
}

int32_t SurfaceMesh::NewBlock()
{
  int32_t k;
  if (!this->FreeBlocks.empty())
  {
    k = this->FreeBlocks.back();
    this->FreeBlocks.pop_back();
  }
  else
  {
    k = static_cast<int32_t>(this->Blocks.size());
    this->Blocks.emplace_back();
  }
  this->Blocks[k].Count = 0;
  this->Blocks[k].Next = -1;
  return k;
}

// Wedges are kept packed: every block but the last of a vertex is full.
void SurfaceMesh::AddWedge(int32_t v, int32_t out, int32_t in, int32_t tri)
{
  int32_t k = this->Head[v];
  if (k < 0)
  {
    k = this->NewBlock();
    this->Head[v] = k;
  }
  else
  {
    while (this->Blocks[k].Count == BlockSize)
    {
      if (this->Blocks[k].Next < 0)
      {
        const int32_t fresh = this->NewBlock(); // may reallocate Blocks
        this->Blocks[k].Next = fresh;
      }
      k = this->Blocks[k].Next;
    }
  }
  Block& block = this->Blocks[k];
  block.Out[block.Count] = out;
  block.In[block.Count] = in;
  block.Tri[block.Count] = tri;
  ++block.Count;
}

// The wedge of triangle `tri` is overwritten by the last wedge of v; an emptied last block is
// released.
void SurfaceMesh::RemoveWedge(int32_t v, int32_t tri)
{
  int32_t found = -1, foundIndex = -1;
  int32_t last = -1, beforeLast = -1;
  for (int32_t k = this->Head[v]; k >= 0; k = this->Blocks[k].Next)
  {
    const Block& block = this->Blocks[k];
    if (found < 0)
    {
      for (int i = 0; i < block.Count; ++i)
      {
        if (block.Tri[i] == tri)
        {
          found = k;
          foundIndex = i;
          break;
        }
      }
    }
    beforeLast = last;
    last = k;
  }
  if (found < 0)
  {
    return;
  }
  Block& tail = this->Blocks[last];
  const int li = tail.Count - 1;
  Block& target = this->Blocks[found];
  target.Out[foundIndex] = tail.Out[li];
  target.In[foundIndex] = tail.In[li];
  target.Tri[foundIndex] = tail.Tri[li];
  --tail.Count;
  if (tail.Count == 0)
  {
    if (beforeLast >= 0)
    {
      this->Blocks[beforeLast].Next = -1;
    }
    else
    {
      this->Head[v] = -1;
    }
    this->FreeBlocks.push_back(last);
  }
}

// Recompute the state and fan count of v from its wedges. A wedge W (out, in) is followed
// counter-clockwise by the wedge whose out is W's in; a chain with a first wedge is an open fan,
// the other chains are closed.
void SurfaceMesh::UpdateVertex(int32_t v)
{
  constexpr int LocalCapacity = 64;
  int32_t localOut[LocalCapacity], localIn[LocalCapacity];
  std::vector<int32_t> heapOut, heapIn;
  int n = 0;
  int32_t* out = localOut;
  int32_t* in = localIn;
  this->ForEachWedge(v, [&](int32_t o, int32_t i, int32_t) {
    if (n == LocalCapacity && heapOut.empty())
    {
      heapOut.assign(localOut, localOut + n);
      heapIn.assign(localIn, localIn + n);
    }
    if (n >= LocalCapacity)
    {
      heapOut.push_back(o);
      heapIn.push_back(i);
    }
    else
    {
      localOut[n] = o;
      localIn[n] = i;
    }
    ++n;
    return false;
  });
  if (n > LocalCapacity)
  {
    out = heapOut.data();
    in = heapIn.data();
  }
  this->FrontOut[v] = this->FrontIn[v] = -1;
  if (n == 0)
  {
    this->State[v] = static_cast<uint8_t>(VertexState::Free);
    this->Fans[v] = 0;
    return;
  }
  std::vector<char> heapVisited;
  char localVisited[LocalCapacity];
  char* visited = localVisited;
  if (n > LocalCapacity)
  {
    heapVisited.assign(n, 0);
    visited = heapVisited.data();
  }
  else
  {
    std::fill(localVisited, localVisited + n, 0);
  }
  auto successor = [&](int w) {
    for (int j = 0; j < n; ++j)
    {
      if (out[j] == in[w])
      {
        return j;
      }
    }
    return -1;
  };
  int open = 0, closed = 0, seen = 0;
  int32_t firstOut = -1, lastIn = -1;
  for (int w = 0; w < n; ++w)
  {
    bool first = true; // no wedge precedes w
    for (int j = 0; j < n; ++j)
    {
      if (in[j] == out[w])
      {
        first = false;
        break;
      }
    }
    if (!first)
    {
      continue;
    }
    ++open;
    firstOut = out[w];
    for (int x = w; x >= 0 && !visited[x]; x = successor(x))
    {
      visited[x] = 1;
      ++seen;
      lastIn = in[x];
    }
  }
  for (int w = 0; w < n && seen < n; ++w)
  {
    if (visited[w])
    {
      continue;
    }
    ++closed;
    for (int x = w; x >= 0 && !visited[x]; x = successor(x))
    {
      visited[x] = 1;
      ++seen;
    }
  }
  this->State[v] = static_cast<uint8_t>(open > 0 ? VertexState::Boundary : VertexState::Interior);
  this->Fans[v] = static_cast<uint8_t>(std::min(open + closed, 255));
  if (open == 1 && closed == 0)
  {
    this->FrontOut[v] = firstOut;
    this->FrontIn[v] = lastIn;
  }
}

// After AddWedge(v, out, in) of a triangle whose half-edges were free: the common cases from the
// cached state, the same answer as UpdateVertex. A free vertex gets one open fan. On a vertex with
// one open fan and nothing else (front edges v->FrontOut and FrontIn->v), the new wedge extends
// the fan at its out side (in == FrontOut: it owns the twin of v->FrontOut), at its in side
// (out == FrontIn), or at both (the umbrella closes); no other wedge can meet it, as v->out and
// in->v were unused. Anything else (a second fan: a pinch) is recomputed.
void SurfaceMesh::UpdateVertexAfterAdd(int32_t v, int32_t out, int32_t in)
{
  if (this->State[v] == static_cast<uint8_t>(VertexState::Free))
  {
    this->State[v] = static_cast<uint8_t>(VertexState::Boundary);
    this->Fans[v] = 1;
    this->FrontOut[v] = out;
    this->FrontIn[v] = in;
    return;
  }
  if (this->FrontOut[v] >= 0)
  {
    const bool atOut = in == this->FrontOut[v], atIn = out == this->FrontIn[v];
    if (atOut && atIn)
    {
      this->State[v] = static_cast<uint8_t>(VertexState::Interior);
      this->FrontOut[v] = this->FrontIn[v] = -1;
      return;
    }
    if (atOut)
    {
      this->FrontOut[v] = out;
      return;
    }
    if (atIn)
    {
      this->FrontIn[v] = in;
      return;
    }
  }
  this->UpdateVertex(v);
}

//------------------------------------------------------------------------------------------------
SurfaceMesh::Check SurfaceMesh::CanAddTriangle(
  int32_t a, int32_t b, int32_t c, int32_t* vertex) const
{
  const int32_t n = this->GetNumberOfVertices();
  if (a < 0 || b < 0 || c < 0 || a >= n || b >= n || c >= n)
  {
    return Check::InvalidVertex;
  }
  if (a == b || b == c || c == a)
  {
    return Check::RepeatedVertex;
  }
  // The common case of a growing front, answered from the cache without a wedge scan: a free
  // vertex, say c, facing a front edge b->a of a single-fan vertex b. Then a->b (the twin of a
  // front edge) and b->c, c->a (at a free vertex) are unused, and the new wedges at a and b
  // attach to the triangle of b->a.
  if ((this->Head[c] < 0 && this->FrontOut[b] == a) ||
    (this->Head[a] < 0 && this->FrontOut[c] == b) || (this->Head[b] < 0 && this->FrontOut[a] == c))
  {
    return Check::Ok;
  }
  // For each vertex v with new wedge (x, y): the half-edges v->x and y->v must be unused, and
  // a vertex that already has triangles must see the new wedge attach to one of its fans: an
  // existing wedge whose in is x (it owns x->v, twin of the new v->x) or whose out is y.
  const int32_t corner[3][3] = { { a, b, c }, { b, c, a }, { c, a, b } };
  Check answer = Check::Ok;
  for (const auto& vxy : corner)
  {
    const int32_t v = vxy[0], x = vxy[1], y = vxy[2];
    if (this->Head[v] < 0)
    {
      continue;
    }
    bool used = false, attached = false;
    this->ForEachWedge(v, [&](int32_t out, int32_t in, int32_t) {
      if (out == x || in == y)
      {
        used = true;
        return true;
      }
      attached = attached || in == x || out == y;
      return false;
    });
    if (used)
    {
      return Check::HalfEdgeUsed;
    }
    if (!attached && answer == Check::Ok)
    {
      answer = Check::NonManifoldVertex;
      if (vertex)
      {
        *vertex = v;
      }
    }
  }
  return answer;
}

int64_t SurfaceMesh::AddTriangle(int32_t a, int32_t b, int32_t c)
{
  const int32_t n = this->GetNumberOfVertices();
  if (a < 0 || b < 0 || c < 0 || a >= n || b >= n || c >= n || a == b || b == c || c == a)
  {
    return -1;
  }
  if (this->HasOut(a, b) || this->HasOut(b, c) || this->HasOut(c, a))
  {
    return -1;
  }
  const int64_t t = this->GetNumberOfTriangleIds();
  const int32_t e[3][2] = { { a, b }, { b, c }, { c, a } };
  for (const auto& h : e)
  {
    this->NumberOfBoundaryHalfEdges += this->HasOut(h[1], h[0]) ? -1 : 1;
  }
  this->Triangles.push_back(a);
  this->Triangles.push_back(b);
  this->Triangles.push_back(c);
  this->AddWedge(a, b, c, static_cast<int32_t>(t));
  this->AddWedge(b, c, a, static_cast<int32_t>(t));
  this->AddWedge(c, a, b, static_cast<int32_t>(t));
  this->UpdateVertexAfterAdd(a, b, c);
  this->UpdateVertexAfterAdd(b, c, a);
  this->UpdateVertexAfterAdd(c, a, b);
  ++this->NumberOfTriangles;
  return t;
}

bool SurfaceMesh::AddTriangles(const int32_t* vertices, size_t count, std::vector<int64_t>& added)
{
  added.clear();
  bool ok = true;
  for (size_t t = 0; t < count && ok; ++t)
  {
    const int32_t* v = vertices + 3 * t;
    const int64_t id = this->AddTriangle(v[0], v[1], v[2]);
    ok = id >= 0;
    if (ok)
    {
      added.push_back(id);
    }
  }
  for (size_t i = 0; i < 3 * count && ok; ++i)
  {
    ok = this->GetNumberOfFans(vertices[i]) == 1;
  }
  if (!ok)
  {
    for (auto it = added.rbegin(); it != added.rend(); ++it)
    {
      this->RemoveTriangle(*it);
    }
  }
  return ok;
}

void SurfaceMesh::RemoveTriangle(int64_t t)
{
  if (t < 0 || t >= this->GetNumberOfTriangleIds() || this->IsTriangleRemoved(t))
  {
    return;
  }
  const int32_t a = this->Triangles[3 * t], b = this->Triangles[3 * t + 1],
                c = this->Triangles[3 * t + 2];
  this->RemoveWedge(a, static_cast<int32_t>(t));
  this->RemoveWedge(b, static_cast<int32_t>(t));
  this->RemoveWedge(c, static_cast<int32_t>(t));
  const int32_t e[3][2] = { { a, b }, { b, c }, { c, a } };
  for (const auto& h : e)
  {
    this->NumberOfBoundaryHalfEdges += this->HasOut(h[1], h[0]) ? 1 : -1;
  }
  this->UpdateVertex(a);
  this->UpdateVertex(b);
  this->UpdateVertex(c);
  this->Triangles[3 * t] = this->Triangles[3 * t + 1] = this->Triangles[3 * t + 2] = -1;
  --this->NumberOfTriangles;
}

void SurfaceMesh::JoinAcrossEdges(DisjointSets<int64_t>& pieces) const
{
  const int64_t count = this->GetNumberOfTriangleIds();
  for (int64_t t = 0; t < count; ++t)
  {
    if (this->IsTriangleRemoved(t))
    {
      continue;
    }
    const int32_t* v = this->GetTriangle(t);
    for (int j = 0; j < 3; ++j)
    {
      const int64_t across = this->FindTriangle(v[(j + 1) % 3], v[j]);
      if (across >= 0)
      {
        pieces.Union(t, across);
      }
    }
  }
}

int64_t SurfaceMesh::ReverseComponent(int64_t t)
{
  if (t < 0 || t >= this->GetNumberOfTriangleIds() || this->IsTriangleRemoved(t))
  {
    return 0;
  }
  std::vector<uint8_t>& visited = this->ReverseVisited;
  visited.resize(static_cast<size_t>(this->GetNumberOfTriangleIds()), 0);
  std::vector<int64_t> component{ t };
  visited[t] = 1;
  for (size_t i = 0; i < component.size(); ++i)
  {
    const int32_t* v = this->GetTriangle(component[i]);
    for (int j = 0; j < 3; ++j)
    {
      const int64_t other = this->FindTriangle(v[(j + 1) % 3], v[j]);
      if (other >= 0 && !visited[other])
      {
        visited[other] = 1;
        component.push_back(other);
      }
    }
  }
  // Mirroring every triangle of the component swaps out and in of each of its wedges; fans and
  // states are unchanged, and no half-edge can collide (the component shares no edge with the
  // rest of the mesh).
  std::vector<int32_t> touched;
  for (int64_t c : component)
  {
    visited[c] = 0;
    int32_t* v = &this->Triangles[3 * c];
    touched.insert(touched.end(), v, v + 3);
    std::swap(v[1], v[2]);
    for (int j = 0; j < 3; ++j)
    {
      for (int32_t k = this->Head[v[j]]; k >= 0; k = this->Blocks[k].Next)
      {
        Block& block = this->Blocks[k];
        for (int i = 0; i < block.Count; ++i)
        {
          if (block.Tri[i] == c)
          {
            std::swap(block.Out[i], block.In[i]);
          }
        }
      }
    }
  }
  // The cached front neighbours of the component's vertices change direction.
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  for (int32_t v : touched)
  {
    this->UpdateVertex(v);
  }
  return static_cast<int64_t>(component.size());
}

//------------------------------------------------------------------------------------------------
int64_t SurfaceMesh::FindTriangle(int32_t a, int32_t b) const
{
  if (a < 0 || a >= this->GetNumberOfVertices())
  {
    return -1;
  }
  int64_t found = -1;
  this->ForEachWedge(a, [&](int32_t out, int32_t, int32_t tri) {
    if (out == b)
    {
      found = tri;
      return true;
    }
    return false;
  });
  return found;
}

int32_t SurfaceMesh::OppositeVertex(int32_t a, int32_t b) const
{
  if (a < 0 || a >= this->GetNumberOfVertices())
  {
    return -1;
  }
  int32_t found = -1;
  this->ForEachWedge(a, [&](int32_t out, int32_t in, int32_t) {
    if (out == b)
    {
      found = in;
      return true;
    }
    return false;
  });
  return found;
}

int SurfaceMesh::GetEdgeValence(int32_t a, int32_t b) const
{
  const int32_t n = this->GetNumberOfVertices();
  if (a < 0 || b < 0 || a >= n || b >= n)
  {
    return 0;
  }
  return (this->HasOut(a, b) ? 1 : 0) + (this->HasOut(b, a) ? 1 : 0);
}

bool SurfaceMesh::IsBoundaryHalfEdgeScan(int32_t a, int32_t b) const
{
  const int32_t n = this->GetNumberOfVertices();
  if (a < 0 || b < 0 || a >= n || b >= n)
  {
    return false;
  }
  if (this->FrontOut[a] >= 0) // a single open fan: its only front edge out of a
  {
    return this->FrontOut[a] == b;
  }
  if (this->State[a] != static_cast<uint8_t>(VertexState::Boundary))
  {
    return false;
  }
  // a->b exists iff a has a wedge with out b; b->a exists iff a has a wedge with in b.
  bool forward = false, backward = false;
  this->ForEachWedge(a, [&](int32_t out, int32_t in, int32_t) {
    forward = forward || out == b;
    backward = backward || in == b;
    return false;
  });
  return forward && !backward;
}

int SurfaceMesh::GetVertexDegree(int32_t v) const
{
  int degree = 0;
  for (int32_t k = this->Head[v]; k >= 0; k = this->Blocks[k].Next)
  {
    degree += this->Blocks[k].Count;
  }
  return degree;
}

int SurfaceMesh::GetBoundaryOutVerticesScan(int32_t v, int32_t* out, int capacity) const
{
  if (this->State[v] != static_cast<uint8_t>(VertexState::Boundary))
  {
    return 0;
  }
  if (this->FrontOut[v] >= 0)
  {
    if (capacity > 0)
    {
      out[0] = this->FrontOut[v];
    }
    return 1;
  }
  int count = 0;
  this->ForEachWedge(v, [&](int32_t x, int32_t, int32_t) {
    if (!this->HasIn(v, x))
    {
      if (count < capacity)
      {
        out[count] = x;
      }
      ++count;
    }
    return false;
  });
  return count;
}

int SurfaceMesh::GetBoundaryInVerticesScan(int32_t v, int32_t* in, int capacity) const
{
  if (this->State[v] != static_cast<uint8_t>(VertexState::Boundary))
  {
    return 0;
  }
  if (this->FrontIn[v] >= 0)
  {
    if (capacity > 0)
    {
      in[0] = this->FrontIn[v];
    }
    return 1;
  }
  int count = 0;
  this->ForEachWedge(v, [&](int32_t, int32_t y, int32_t) {
    if (!this->HasOut(v, y))
    {
      if (count < capacity)
      {
        in[count] = y;
      }
      ++count;
    }
    return false;
  });
  return count;
}

int SurfaceMesh::GetVertexTriangles(int32_t v, int64_t* triangles, int capacity) const
{
  int count = 0;
  this->ForEachWedge(v, [&](int32_t, int32_t, int32_t tri) {
    if (count < capacity)
    {
      triangles[count] = tri;
    }
    ++count;
    return false;
  });
  return count;
}

//------------------------------------------------------------------------------------------------
int32_t SurfaceMesh::NextBoundaryVertexWalk(int32_t a, int32_t b) const
{
  if (!this->IsBoundaryHalfEdge(a, b))
  {
    return -1;
  }
  if (this->FrontOut[b] >= 0)
  {
    return this->FrontOut[b];
  }
  // At b, the triangle (a, b, y) is the wedge (out y, in a), the last of its fan
  // counter-clockwise; walk clockwise (to the wedge whose in is the current out) to the first.
  int32_t current = this->OppositeVertex(a, b);
  const int degree = this->GetVertexDegree(b);
  for (int step = 0; step <= degree; ++step)
  {
    int32_t previous = -1;
    this->ForEachWedge(b, [&](int32_t out, int32_t in, int32_t) {
      if (in == current)
      {
        previous = out;
        return true;
      }
      return false;
    });
    if (previous < 0)
    {
      return current;
    }
    current = previous;
  }
  return -1; // not reached for a consistent structure
}

int32_t SurfaceMesh::PreviousBoundaryVertexWalk(int32_t a, int32_t b) const
{
  if (!this->IsBoundaryHalfEdge(a, b))
  {
    return -1;
  }
  if (this->FrontIn[a] >= 0)
  {
    return this->FrontIn[a];
  }
  // At a, the triangle (a, b, y) is the wedge (out b, in y), the first of its fan; walk
  // counter-clockwise (to the wedge whose out is the current in) to the last.
  int32_t current = -1;
  this->ForEachWedge(a, [&](int32_t out, int32_t in, int32_t) {
    if (out == b)
    {
      current = in;
      return true;
    }
    return false;
  });
  const int degree = this->GetVertexDegree(a);
  for (int step = 0; step <= degree; ++step)
  {
    int32_t next = -1;
    this->ForEachWedge(a, [&](int32_t out, int32_t in, int32_t) {
      if (out == current)
      {
        next = in;
        return true;
      }
      return false;
    });
    if (next < 0)
    {
      return current;
    }
    current = next;
  }
  return -1;
}

void SurfaceMesh::GetBoundaryLoops(std::vector<std::vector<int32_t>>& loops) const
{
  loops.clear();
  std::vector<std::pair<int32_t, int32_t>> edges;
  edges.reserve(static_cast<size_t>(std::max<int64_t>(this->NumberOfBoundaryHalfEdges, 0)));
  const int32_t n = this->GetNumberOfVertices();
  for (int32_t v = 0; v < n; ++v)
  {
    if (this->State[v] != static_cast<uint8_t>(VertexState::Boundary))
    {
      continue;
    }
    this->ForEachWedge(v, [&](int32_t x, int32_t, int32_t) {
      if (!this->HasIn(v, x))
      {
        edges.emplace_back(v, x);
      }
      return false;
    });
  }
  std::sort(edges.begin(), edges.end());
  std::vector<char> visited(edges.size(), 0);
  auto index = [&edges](int32_t a, int32_t b) {
    const auto it = std::lower_bound(edges.begin(), edges.end(), std::make_pair(a, b));
    return it != edges.end() && it->first == a && it->second == b ? it - edges.begin()
                                                                  : static_cast<ptrdiff_t>(-1);
  };
  for (size_t e = 0; e < edges.size(); ++e)
  {
    if (visited[e])
    {
      continue;
    }
    std::vector<int32_t> loop;
    int32_t a = edges[e].first, b = edges[e].second;
    ptrdiff_t current = static_cast<ptrdiff_t>(e);
    while (current >= 0 && !visited[current])
    {
      visited[current] = 1;
      loop.push_back(a);
      const int32_t z = this->NextBoundaryVertex(a, b);
      a = b;
      b = z;
      current = index(a, b);
    }
    loops.push_back(std::move(loop));
  }
}

void SurfaceMesh::GetTriangles(std::vector<int32_t>& connectivity) const
{
  connectivity.clear();
  connectivity.reserve(3 * static_cast<size_t>(this->NumberOfTriangles));
  for (size_t i = 0; i < this->Triangles.size(); i += 3)
  {
    if (this->Triangles[i] >= 0)
    {
      connectivity.insert(connectivity.end(), &this->Triangles[i], &this->Triangles[i] + 3);
    }
  }
}

//------------------------------------------------------------------------------------------------
// Independent recomputation: half-edges in a std::map, fans by union-find of the triangles
// around each vertex linked through the edges they share there.
bool SurfaceMesh::CheckConsistency(std::string* why) const
{
  std::ostringstream message;
  auto fail = [&](const std::string& text) {
    if (why)
    {
      *why = text;
    }
    return false;
  };
  const int32_t n = this->GetNumberOfVertices();
  std::map<std::pair<int32_t, int32_t>, int64_t> halfEdges;
  std::vector<std::vector<int64_t>> around(n);
  int64_t live = 0;
  for (int64_t t = 0; t < this->GetNumberOfTriangleIds(); ++t)
  {
    if (this->IsTriangleRemoved(t))
    {
      continue;
    }
    ++live;
    const int32_t* v = this->GetTriangle(t);
    for (int j = 0; j < 3; ++j)
    {
      if (v[j] < 0 || v[j] >= n || v[j] == v[(j + 1) % 3])
      {
        message << "triangle " << t << " has an invalid vertex";
        return fail(message.str());
      }
      if (!halfEdges.emplace(std::make_pair(v[j], v[(j + 1) % 3]), t).second)
      {
        message << "half-edge " << v[j] << "->" << v[(j + 1) % 3] << " used twice";
        return fail(message.str());
      }
      around[v[j]].push_back(t);
    }
  }
  if (live != this->NumberOfTriangles)
  {
    return fail("triangle count differs");
  }
  int64_t boundary = 0;
  for (const auto& h : halfEdges)
  {
    const int64_t t = this->FindTriangle(h.first.first, h.first.second);
    if (t != h.second)
    {
      message << "FindTriangle(" << h.first.first << ", " << h.first.second << ") = " << t
              << ", expected " << h.second;
      return fail(message.str());
    }
    const bool isBoundary = !halfEdges.count(std::make_pair(h.first.second, h.first.first));
    boundary += isBoundary ? 1 : 0;
    if (isBoundary != this->IsBoundaryHalfEdge(h.first.first, h.first.second))
    {
      return fail("IsBoundaryHalfEdge differs");
    }
  }
  if (boundary != this->NumberOfBoundaryHalfEdges)
  {
    message << "boundary half-edges: cached " << this->NumberOfBoundaryHalfEdges << ", actual "
            << boundary;
    return fail(message.str());
  }
  for (int32_t v = 0; v < n; ++v)
  {
    const auto& tris = around[v];
    if (static_cast<int>(tris.size()) != this->GetVertexDegree(v))
    {
      message << "vertex " << v << ": degree differs";
      return fail(message.str());
    }
    for (int64_t t : tris)
    {
      bool found = false;
      this->ForEachWedge(v, [&](int32_t out, int32_t in, int32_t tri) {
        if (tri != t)
        {
          return false;
        }
        const int32_t* w = this->GetTriangle(t);
        const int j = w[0] == v ? 0 : (w[1] == v ? 1 : 2);
        found = out == w[(j + 1) % 3] && in == w[(j + 2) % 3];
        return true;
      });
      if (!found)
      {
        message << "vertex " << v << ": wedge of triangle " << t << " missing or wrong";
        return fail(message.str());
      }
    }
    // Fans: triangles at v linked when they share an edge {v, x}.
    DisjointSets<int64_t> fansAt(static_cast<int64_t>(tris.size()));
    bool open = false;
    for (size_t i = 0; i < tris.size(); ++i)
    {
      const int32_t* w = this->GetTriangle(tris[i]);
      for (int j = 0; j < 3; ++j)
      {
        if (w[j] == v)
        {
          continue;
        }
        // Does another triangle at v have the edge {v, w[j]}?
        bool shared = false;
        for (size_t k = 0; k < tris.size(); ++k)
        {
          if (k == i)
          {
            continue;
          }
          const int32_t* u = this->GetTriangle(tris[k]);
          if (u[0] == w[j] || u[1] == w[j] || u[2] == w[j])
          {
            fansAt.Union(static_cast<int64_t>(i), static_cast<int64_t>(k));
            shared = true;
          }
        }
        open = open || !shared;
      }
    }
    int fans = 0;
    for (size_t i = 0; i < tris.size(); ++i)
    {
      fans += fansAt.Find(static_cast<int64_t>(i)) == static_cast<int64_t>(i) ? 1 : 0;
    }
    const VertexState expected =
      tris.empty() ? VertexState::Free : (open ? VertexState::Boundary : VertexState::Interior);
    if (expected == VertexState::Boundary && fans == 1)
    {
      // The single fan's front edges, from the half-edge map.
      int32_t out = -1, in = -1;
      for (int64_t t : tris)
      {
        const int32_t* w = this->GetTriangle(t);
        const int j = w[0] == v ? 0 : (w[1] == v ? 1 : 2);
        if (!halfEdges.count(std::make_pair(w[(j + 1) % 3], v)))
        {
          out = w[(j + 1) % 3];
        }
        if (!halfEdges.count(std::make_pair(v, w[(j + 2) % 3])))
        {
          in = w[(j + 2) % 3];
        }
      }
      if (out != this->FrontOut[v] || in != this->FrontIn[v])
      {
        message << "vertex " << v << ": cached front neighbours " << this->FrontIn[v] << "->v->"
                << this->FrontOut[v] << ", actual " << in << "->v->" << out;
        return fail(message.str());
      }
    }
    else if (this->FrontOut[v] >= 0 || this->FrontIn[v] >= 0)
    {
      message << "vertex " << v
              << ": front neighbours cached for a vertex without a single open fan";
      return fail(message.str());
    }
    if (expected != this->GetVertexState(v) || std::min(fans, 255) != this->GetNumberOfFans(v))
    {
      message << "vertex " << v << ": state " << int(this->GetVertexState(v)) << " fans "
              << this->GetNumberOfFans(v) << ", expected " << int(expected) << " / " << fans;
      return fail(message.str());
    }
  }
  return true;
}
} // namespace pcs
