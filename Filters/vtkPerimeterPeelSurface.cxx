#include "vtkPerimeterPeelSurface.h"

#include "pcsCoordinateScaling.h"
#include "pcsDelaunay3D.h"
#include "pcsDisjointSets.h"
#include "pcsFieldData.h"
#include "pcsGatherInput.h"
#include "pcsOutliers.h"
#include "pcsPiles.h"
#include "pcsProjectedTests.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkPerimeterPeelSurface);

namespace
{
// The slots of facet j of a positively oriented cell (v0, v1, v2, v3), ordered so that the
// triangle's normal (right-hand rule) points away from the cell: the increasing-slot triple
// without slot j faces away from v_j when j is odd and towards it when j is even.
std::array<int, 3> FacetSlots(int j)
{
  std::array<int, 3> slots;
  for (int k = 0, m = 0; k < 4; ++k)
  {
    if (k != j)
    {
      slots[m++] = k;
    }
  }
  if (j % 2 == 0)
  {
    std::swap(slots[1], slots[2]);
  }
  return slots;
}

// The solid being peeled: the finite tetrahedra of a Delaunay tetrahedralization, each inside or
// outside (removed, or infinite), with the number of inside and outside cells around each vertex.
class PeelSolid
{
public:
  PeelSolid(const pcs::Delaunay3D& dt, const double* xyz, int measure, vtkIdType numberOfPoints)
    : DT(dt)
    , XYZ(xyz)
    , Measure(measure)
  {
    const int64_t cells = dt.GetNumberOfCells();
    this->Inside.assign((cells + 63) / 64, 0);
    this->Bottleneck.assign(cells, std::numeric_limits<float>::infinity());
    this->Star.assign(numberOfPoints, StarCounts());
    for (int64_t c = 0; c < cells; ++c)
    {
      const bool finite = !dt.IsInfinite(c);
      this->Inside[c >> 6] |= static_cast<uint64_t>(finite ? 1 : 0) << (c & 63);
      for (int k = 0; k < 4; ++k)
      {
        const int32_t v = dt.Vertex(c, k);
        if (v >= 0)
        {
          ++(finite ? this->Star[v].Inside : this->Star[v].Outside);
        }
      }
    }
  }

  bool IsInside(int64_t c) const { return (this->Inside[c >> 6] >> (c & 63)) & 1; }

  // Start loading the record of cell c and its state into the cache (a hint; none without
  // GCC's builtin).
  void Prefetch(int64_t c) const
  {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(this->DT.CellVertices(c));
    __builtin_prefetch(&this->Inside[c >> 6]);
#else
    (void)c;
#endif
  }

  // Start loading the Bottleneck of the cells around cell c (what WidestWayIn reads when c is
  // offered; a hint, as Prefetch).
  void PrefetchBottlenecks(int64_t c) const
  {
#if defined(__GNUC__) || defined(__clang__)
    for (int j = 0; j < 4; ++j)
    {
      __builtin_prefetch(&this->Bottleneck[this->DT.Neighbor(c, j)]);
    }
#else
    (void)c;
#endif
  }

  // Start loading what the facet measures and the rules read of vertex v (finite): its
  // coordinates, local spacing and cell counts (a hint, as Prefetch).
  void PrefetchVertex(int32_t v) const
  {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(this->XYZ + 3 * static_cast<int64_t>(v));
    __builtin_prefetch(&this->Star[v]);
    if (!this->Spacing.empty())
    {
      __builtin_prefetch(&this->Spacing[v]);
    }
#else
    (void)v;
#endif
  }

  // The widest way in to the inside cell c, whose largest exterior facet measures m: over its
  // exterior facets, the largest of min(the facet's measure, the Bottleneck of the outside cell
  // behind it). When every such Bottleneck is over `above` (often: the infinite cells), the
  // answer is m if m <= above and over `above` otherwise, and m is returned (no facet measured).
  double WidestWayIn(int64_t c, double m, double above) const
  {
    bool bounded = false;
    for (int j = 0; j < 4 && !bounded; ++j)
    {
      const int64_t n = this->DT.Neighbor(c, j);
      bounded = !this->IsInside(n) && this->Bottleneck[n] <= above;
    }
    if (!bounded)
    {
      return m;
    }
    double widest = -1.0;
    for (int j = 0; j < 4; ++j)
    {
      const int64_t n = this->DT.Neighbor(c, j);
      if (!this->IsInside(n) && this->Bottleneck[n] > widest)
      {
        widest = std::max(widest, std::min<double>(this->Bottleneck[n], this->FacetMeasure(c, j)));
      }
    }
    return widest;
  }

  // Facet j of c (opposite vertex j) is exterior: c inside, its neighbour across j not.
  bool IsExterior(int64_t c, int j) const
  {
    return this->IsInside(c) && !this->IsInside(this->DT.Neighbor(c, j));
  }

  // Bit j set when facet j of c is exterior.
  int ExteriorMask(int64_t c) const
  {
    int mask = 0;
    for (int j = 0; j < 4; ++j)
    {
      mask |= this->IsExterior(c, j) ? 1 << j : 0;
    }
    return mask;
  }

  // Whether vertex v is on the boundary of the solid (has inside and outside cells around it).
  bool OnBoundary(int32_t v) const
  {
    return this->Star[v].Inside > 0 && this->Star[v].Outside > 0;
  }

  // Visit the cells around the edge of c joining its slots i and j (c first), walking across the
  // facets that contain the edge, until `visit(cell, cross)` returns true (then returns true);
  // `cross` is the slot of the facet of `cell` through which the walk goes on.
  template <typename Visitor>
  bool AroundEdge(int64_t c, int i, int j, Visitor&& visit) const
  {
    int cross = -1, keep = -1;
    for (int k = 0; k < 4; ++k)
    {
      if (k != i && k != j)
      {
        (cross < 0 ? cross : keep) = k;
      }
    }
    int32_t kept = this->DT.Vertex(c, keep);
    int64_t cell = c;
    do
    {
      if (visit(cell, cross))
      {
        return true;
      }
      const int64_t next = this->DT.Neighbor(cell, cross);
      const int32_t entering = this->DT.Vertex(next, this->DT.MirrorIndex(cell, cross));
      cross = 0;
      while (this->DT.Vertex(next, cross) != kept)
      {
        ++cross;
      }
      kept = entering;
      cell = next;
    } while (cell != c);
    return false;
  }

  // Whether a cell around the edge of c joining its slots i and j is outside.
  bool EdgeTouchesOutside(int64_t c, int i, int j) const
  {
    return this->EdgeTouches(c, i, j, false);
  }

  // Whether a cell around the edge of c joining its slots i and j is inside (`inside`) or outside.
  // Walks around the edge both ways at once until the walks meet: two independent chains of
  // loads, which overlap (the cells are mostly out of the cache).
  bool EdgeTouches(int64_t c, int i, int j, bool inside) const
  {
    if (this->IsInside(c) == inside)
    {
      return true;
    }
    int first = -1, second = -1;
    for (int k = 0; k < 4; ++k)
    {
      if (k != i && k != j)
      {
        (first < 0 ? first : second) = k;
      }
    }
    // Each way crosses the facet opposite its `cross` slot and keeps the other vertex off the edge.
    int64_t cellA = c, cellB = c;
    int crossA = first, crossB = second;
    int32_t keptA = this->DT.Vertex(c, second), keptB = this->DT.Vertex(c, first);
    auto step = [this](int64_t& cell, int& cross, int32_t& kept)
    {
      const int64_t next = this->DT.Neighbor(cell, cross);
      const int32_t entering = this->DT.Vertex(next, this->DT.MirrorIndex(cell, cross));
      const int32_t* v = this->DT.CellVertices(next);
      cross = (v[1] == kept) + 2 * (v[2] == kept) + 3 * (v[3] == kept);
      kept = entering;
      cell = next;
    };
    for (;;)
    {
      step(cellA, crossA, keptA);
      if (cellA == cellB)
      {
        return false; // the ways met: no cell around the edge is in that state
      }
      if (this->IsInside(cellA) == inside)
      {
        return true;
      }
      step(cellB, crossB, keptB);
      if (cellB == cellA)
      {
        return false;
      }
      if (this->IsInside(cellB) == inside)
      {
        return true;
      }
    }
  }

  // Whether moving the finite cell c alone to the other state keeps the boundary a 2-manifold with
  // the same topology and the same points on it (the sculpting rules, both ways): the facets of c
  // on the boundary must be one whose opposite vertex has no cell of the other state (removal
  // only: every vertex has inside cells), or two whose opposite vertices' edge has none. With three
  // or four, the common vertex would be left in no cell of c's state.
  bool MayToggle(int64_t c) const
  {
    const bool inside = this->IsInside(c);
    int slots[4], k = 0;
    for (int j = 0; j < 4; ++j)
    {
      if (this->IsInside(this->DT.Neighbor(c, j)) != inside)
      {
        slots[k++] = j;
      }
    }
    if (k == 1)
    {
      return inside && !this->OnBoundary(this->DT.Vertex(c, slots[0]));
    }
    return k == 2 && !this->EdgeTouches(c, slots[0], slots[1], !inside);
  }

  // The triangle of facet j of the finite cell c, ordered so that its normal (right-hand rule)
  // points away from c (FacetSlots).
  std::array<int32_t, 3> FacetTriangle(int64_t c, int j) const
  {
    const std::array<int, 3> slots = FacetSlots(j);
    return { this->DT.Vertex(c, slots[0]), this->DT.Vertex(c, slots[1]),
      this->DT.Vertex(c, slots[2]) };
  }

  // The normal of facet j of the finite cell c pointing away from c (twice the area long).
  std::array<double, 3> FacetNormal(int64_t c, int j) const
  {
    const std::array<int32_t, 3> t = this->FacetTriangle(c, j);
    const double* a = this->XYZ + 3 * static_cast<int64_t>(t[0]);
    const double* b = this->XYZ + 3 * static_cast<int64_t>(t[1]);
    const double* d = this->XYZ + 3 * static_cast<int64_t>(t[2]);
    std::array<double, 3> normal;
    pcs::projected::TriangleNormal(a, b, d, normal.data());
    return normal;
  }

  // The outward normal of the boundary facet between the finite or infinite cell c and its
  // neighbour across slot j: FacetNormal of the inside one of them (c when `cInside`).
  std::array<double, 3> BoundaryNormal(int64_t c, int j, bool cInside) const
  {
    return cInside ? this->FacetNormal(c, j)
                   : this->FacetNormal(this->DT.Neighbor(c, j), this->DT.MirrorIndex(c, j));
  }

  // One walk around the edge of c joining its slots i and j for the current states (s = 0) and,
  // when `states` is 2, with the cells for which `moved(cell)` is true in the other state (s = 1).
  // cosine[s] (2 when not `normals`): the cosine of the angle between the outward normals of the
  // two boundary triangles on the edge, 2 when it does not have exactly two (the edge is a fold
  // when it is negative: one of the triangles faces into the solid there, see Unfolder);
  // onBoundary[s]: whether the edge is on the boundary (has cells of both states around it).
  template<typename Moved>
  void EdgeStates(int64_t c,
    int i,
    int j,
    int states,
    bool normals,
    Moved&& moved,
    double cosine[2],
    bool onBoundary[2]) const
  {
    std::array<double, 3> normal[2][2];
    int found[2] = { 0, 0 };
    this->AroundEdge(c,
      i,
      j,
      [&](int64_t cell, int cross)
      {
        const int64_t next = this->DT.Neighbor(cell, cross);
        for (int s = 0; s < states; ++s)
        {
          const bool cellInside = this->IsInside(cell) != (s == 1 && moved(cell));
          const bool nextInside = this->IsInside(next) != (s == 1 && moved(next));
          if (cellInside != nextInside && found[s]++ < 2 && normals)
          {
            normal[s][found[s] - 1] = this->BoundaryNormal(cell, cross, cellInside);
          }
        }
        return false;
      });
    for (int s = 0; s < states; ++s)
    {
      cosine[s] = normals ? NormalCosine(normal[s], found[s]) : 2.0;
      onBoundary[s] = found[s] > 0;
    }
  }

  // The cosine of the angle between the two normals n when `found` (the boundary triangles on an
  // edge) is 2; 2 otherwise.
  static double NormalCosine(const std::array<double, 3> n[2], int found)
  {
    return found == 2 ? Cosine(n[0], n[1]) : 2.0;
  }

  // The cosine of the angle between the normals a and b (symmetric in a and b, to the bit).
  static double Cosine(const std::array<double, 3>& a, const std::array<double, 3>& b)
  {
    const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const double lengths = std::sqrt(
      (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
    return lengths > 0.0 ? dot / lengths : (dot < 0.0 ? -1.0 : 1.0);
  }

  // For the move of the finite cell c alone to the other state, when MayToggle(c) allows it and
  // the boundary is a closed 2-manifold: the cosines of EdgeStates for each edge e of c ((0, 1),
  // (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)) before (before[e]) and after (after[e]), with one
  // normal per facet of c and at most one short walk per edge instead of a walk around each edge
  // for both states. Each facet of c is on the boundary in exactly one of the two states, and an
  // edge of c lies in two of them: when both are on the boundary before, they are the edge's two
  // boundary triangles then and it has none after; when neither, the reverse (MayToggle: no cell
  // of the other state was around the edge); when one, the edge's other boundary triangle, found
  // by a walk from the other facet through cells of c's state, is the same before and after.
  void ToggleCosines(int64_t c, double before[6], double after[6]) const
  {
    const bool inside = this->IsInside(c);
    std::array<double, 3> normal[4];
    bool boundary[4]; // whether facet f of c is on the boundary before the move
    for (int f = 0; f < 4; ++f)
    {
      const bool crossing = this->IsInside(this->DT.Neighbor(c, f)) != inside;
      boundary[f] = crossing;
      // c is the inside side of facet f in the state in which it is on the boundary when it is
      // inside and the facet on the boundary before, or outside and the facet on it after.
      normal[f] = this->BoundaryNormal(c, f, inside == crossing);
    }
    // The facets of c that contain each edge: those opposite its other two vertices.
    static const int edgeFacets[6][2] = {
      { 2, 3 }, { 1, 3 }, { 1, 2 }, { 0, 3 }, { 0, 2 }, { 0, 1 }
    };
    for (int e = 0; e < 6; ++e)
    {
      const int k = edgeFacets[e][0], l = edgeFacets[e][1];
      const bool onK = boundary[k], onL = boundary[l];
      if (onK == onL)
      {
        const double both = Cosine(normal[k], normal[l]);
        before[e] = onK ? both : 2.0;
        after[e] = onK ? 2.0 : both;
      }
      else
      {
        const int on = onK ? k : l, off = onK ? l : k;
        const std::pair<int64_t, int> other = this->NextBoundaryFacet(c, on, off);
        const std::array<double, 3> otherNormal =
          this->BoundaryNormal(other.first, other.second, inside);
        before[e] = Cosine(normal[on], otherNormal);
        after[e] = Cosine(normal[off], otherNormal);
      }
    }
  }

  // The boundary facet next to the boundary facet j of c around the edge of c without slots j
  // and k: the walk around the edge starts across facet k and goes through cells of c's state
  // until the cell behind the facet it would cross is of the other state. Returns that facet
  // (cell, slot).
  std::pair<int64_t, int> NextBoundaryFacet(int64_t c, int j, int k) const
  {
    const bool inside = this->IsInside(c);
    int64_t cell = c;
    int cross = k;
    int32_t kept = this->DT.Vertex(c, j);
    for (;;)
    {
      const int64_t next = this->DT.Neighbor(cell, cross);
      if (this->IsInside(next) != inside)
      {
        return { cell, cross };
      }
      const int32_t entering = this->DT.Vertex(next, this->DT.MirrorIndex(cell, cross));
      const int32_t* v = this->DT.CellVertices(next);
      cross = (v[1] == kept) + 2 * (v[2] == kept) + 3 * (v[3] == kept);
      kept = entering;
      cell = next;
    }
  }

  // Relative measures: each facet's measure is divided by the local spacing at its vertices (the
  // mean of their Spacing), squared for the area.
  void SetLocalSpacing(int neighbors)
  {
    // For each point, the lengths of its `neighbors` shortest Delaunay edges (the nearest
    // neighbour graph is a subgraph of the Delaunay graph), kept sorted with the other end.
    const int64_t points = static_cast<int64_t>(this->Star.size());
    const int k = neighbors;
    std::vector<double> length(
      static_cast<size_t>(points) * k, std::numeric_limits<double>::infinity());
    std::vector<int32_t> other(static_cast<size_t>(points) * k, -1);
    auto offer = [&](int32_t v, int32_t w, double d)
    {
      double* l = &length[static_cast<size_t>(v) * k];
      int32_t* o = &other[static_cast<size_t>(v) * k];
      if (d >= l[k - 1])
      {
        return;
      }
      int i = k - 1;
      for (int m = 0; m < k; ++m)
      {
        if (o[m] == w)
        {
          return; // this edge is listed already (it has one length)
        }
      }
      while (i > 0 && l[i - 1] > d)
      {
        l[i] = l[i - 1];
        o[i] = o[i - 1];
        --i;
      }
      l[i] = d;
      o[i] = w;
    };
    // Each edge is measured in the finite cells around it that come before both their
    // neighbours around it (infinite cells count as last): at least one per edge, the first
    // finite one, and about a third of them instead of all. (Called before peeling: the
    // inside cells are the finite ones.)
    const int64_t cells = this->DT.GetNumberOfCells();
    auto before = [&](int64_t cell, int64_t c) { return this->IsInside(cell) && cell < c; };
    for (int64_t c = 0; c < cells; ++c)
    {
      if (!this->IsInside(c))
      {
        continue;
      }
      // Bit m: the neighbour across facet m comes before c (each tested once, not per edge).
      int earlier = 0;
      for (int m = 0; m < 4; ++m)
      {
        earlier |= before(this->DT.Neighbor(c, m), c) << m;
      }
      for (int i = 0; i < 3; ++i)
      {
        const int32_t v = this->DT.Vertex(c, i);
        const double* a = this->XYZ + 3 * static_cast<int64_t>(v);
        for (int j = i + 1; j < 4; ++j)
        {
          // The neighbours around edge (i, j): across the two facets that contain it, the
          // facets opposite the other two vertices.
          if (earlier & ~(1 << i) & ~(1 << j))
          {
            continue;
          }
          const int32_t w = this->DT.Vertex(c, j);
          const double* b = this->XYZ + 3 * static_cast<int64_t>(w);
          const double d = std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
            (b[2] - a[2]) * (b[2] - a[2]));
          offer(v, w, d);
          offer(w, v, d);
        }
      }
    }
    // The mean of those lengths; when the longest is over 8 times their median (an edge across
    // the inside of the object), at most 1.5 times the median. On a flat region a point's
    // Delaunay neighbours in the surface are its 2D Delaunay neighbours (6 on average, often 4 or
    // 5), and its other shortest edges cross the empty inside (a cube's faces: the mean was 2.7
    // times the true spacing at 10^5 points, and the peel dug through the faces). On a curved
    // surface's sample the shortest edges stay within a few spacings, and the mean is kept.
    this->Spacing.assign(points, 0.0);
    for (int64_t v = 0; v < points; ++v)
    {
      const double* l = &length[static_cast<size_t>(v) * k];
      double sum = 0.0;
      int n = 0;
      for (int m = 0; m < k && other[v * k + m] >= 0; ++m, ++n)
      {
        sum += l[m];
      }
      if (n > 0)
      {
        const double median = n % 2 ? l[n / 2] : 0.5 * (l[n / 2 - 1] + l[n / 2]);
        this->Spacing[v] = l[n - 1] > 8.0 * median ? std::min(sum / n, 1.5 * median) : sum / n;
      }
    }
    // Smoothed over the same neighbours: on a uniform random sample the spacing is then nearly
    // constant (the paper's absolute measure up to a factor), on a graded one it follows the
    // grading.
    const int passes = 2;
    std::vector<double> smoothed(points);
    for (int pass = 0; pass < passes; ++pass)
    {
      for (int64_t v = 0; v < points; ++v)
      {
        double sum = this->Spacing[v];
        int n = 1;
        for (int m = 0; m < k && other[v * k + m] >= 0; ++m, ++n)
        {
          sum += this->Spacing[other[v * k + m]];
        }
        smoothed[v] = sum / n;
      }
      this->Spacing.swap(smoothed);
    }
  }

  // The measure of facet j of c (perimeter, area or circumradius of its triangle), relative to
  // the local spacing when SetLocalSpacing was called.
  double FacetMeasure(int64_t c, int j) const
  {
    const double raw = this->AbsoluteFacetMeasure(c, j);
    if (this->Spacing.empty())
    {
      return raw;
    }
    double scale = 0.0;
    for (int k = 0; k < 4; ++k)
    {
      if (k != j)
      {
        scale += this->Spacing[this->DT.Vertex(c, k)];
      }
    }
    scale /= 3.0;
    if (this->Measure == vtkPerimeterPeelSurface::AREA)
    {
      scale *= scale;
    }
    return scale > 0.0 ? raw / scale : std::numeric_limits<double>::infinity();
  }

  // The measure of facet j of c in input units.
  double AbsoluteFacetMeasure(int64_t c, int j) const
  {
    const double* p[3];
    for (int k = 0, m = 0; k < 4; ++k)
    {
      if (k != j)
      {
        p[m++] = this->XYZ + 3 * static_cast<int64_t>(this->DT.Vertex(c, k));
      }
    }
    double e[3][3];
    double length[3];
    for (int i = 0; i < 3; ++i)
    {
      const double* a = p[i];
      const double* b = p[(i + 1) % 3];
      e[i][0] = b[0] - a[0];
      e[i][1] = b[1] - a[1];
      e[i][2] = b[2] - a[2];
      length[i] = std::sqrt(e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2]);
    }
    if (this->Measure == vtkPerimeterPeelSurface::PERIMETER)
    {
      return length[0] + length[1] + length[2];
    }
    const double n[3] = { e[0][1] * e[1][2] - e[0][2] * e[1][1],
      e[0][2] * e[1][0] - e[0][0] * e[1][2], e[0][0] * e[1][1] - e[0][1] * e[1][0] };
    const double twiceArea = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (this->Measure == vtkPerimeterPeelSurface::AREA)
    {
      return 0.5 * twiceArea;
    }
    // R = abc / (4 area); a flat triangle has an infinite circumradius.
    return twiceArea > 0.0 ? length[0] * length[1] * length[2] / (2.0 * twiceArea)
                           : std::numeric_limits<double>::infinity();
  }

  // The largest measure of the facets of c in `facets` (bit j: facet j; -1 when it is empty).
  double LargestFacet(int64_t c, int facets) const
  {
    double largest = -1.0;
    for (int j = 0; j < 4; ++j)
    {
      if (facets & (1 << j))
      {
        largest = std::max(largest, this->FacetMeasure(c, j));
      }
    }
    return largest;
  }

  // The largest measure of the exterior facets of c (-1 when it has none).
  double LargestExteriorFacet(int64_t c) const
  {
    return this->LargestFacet(c, this->ExteriorMask(c));
  }

  // Whether removing c would leave one of its vertices in no inside tetrahedron.
  bool Orphans(int64_t c) const
  {
    for (int k = 0; k < 4; ++k)
    {
      if (this->Star[this->DT.Vertex(c, k)].Inside <= 1)
      {
        return true;
      }
    }
    return false;
  }

  // Whether removing the exposed inside cell c, whose exterior facets are `mask` (ExteriorMask),
  // keeps the boundary a 2-manifold, given that it is one now (the sculpting rules of Boissonnat
  // 1984): with one exterior facet, the opposite vertex
  // must not be on the boundary; with two, the edge joining their opposite vertices must not be on
  // it; with three or four, a vertex would be left in no tetrahedron.
  bool KeepsManifold(int64_t c, int mask) const
  {
    int slots[4], k = 0;
    for (int j = 0; j < 4; ++j)
    {
      if (mask & (1 << j))
      {
        slots[k++] = j;
      }
    }
    if (k == 1)
    {
      return !this->OnBoundary(this->DT.Vertex(c, slots[0]));
    }
    if (k == 2)
    {
      return !this->EdgeTouchesOutside(c, slots[0], slots[1]);
    }
    return false;
  }

  void SetInside(int64_t c, bool inside)
  {
    if (this->IsInside(c) == inside)
    {
      return;
    }
    this->Inside[c >> 6] ^= uint64_t(1) << (c & 63);
    for (int k = 0; k < 4; ++k)
    {
      const int32_t v = this->DT.Vertex(c, k);
      this->Star[v].Inside += inside ? 1 : -1;
      this->Star[v].Outside += inside ? -1 : 1;
    }
  }

  const pcs::Delaunay3D& DT;
  const double* XYZ;
  int Measure;
  // Whether each cell is inside, one bit per cell: the peel and the unfolding pass test the
  // states of the cells around those they visit at every step (10^6 points: 3 to 6.5 million
  // cells, 0.4 to 0.8 MB of bits, which stay in the core's cache, against 3 to 6.5 MB of bytes).
  std::vector<uint64_t> Inside;
  // For each removed cell: the smallest facet the peel passed through on the widest way to it
  // (its WidestWayIn when it went; for a group's cells, that of the group's first cell); infinite
  // for the infinite cells (the hull) and the inside ones. Single precision: it feeds a factor-1.5
  // test (rule 2 of the class docs).
  std::vector<float> Bottleneck;
  // The cells around each vertex, inside and outside (removed or infinite), side by side: the
  // tests read both or one right before updating both.
  struct StarCounts
  {
    int32_t Inside = 0;
    int32_t Outside = 0;
  };
  std::vector<StarCounts> Star;
  std::vector<double> Spacing;       // local spacing of each point (relative measures only)
};

// Group removals that the one-cell sculpting rules cannot make. Removing one cell from a solid
// whose boundary is a manifold, so that it stays one, never changes the solid's topology: a handle
// (the hole of a torus) only opens when a whole layer of cells goes at once, which the one-cell
// rules refuse at every step (each step alone pinches the boundary). A group removal starts at a
// refused cell c that shows the outside a facet over the threshold and grows, largest facet first,
// across the facets over the threshold into the cells behind them (the paper's rule applied to the
// group), until the boundary is a manifold again; it never enters a cell that shows the outside a
// facet under the threshold (that facet is already part of the surface), and it gives up, restoring
// the group, when a point would be left in no cell, when nothing is left to enter, after
// MaximumGroup cells, or when the group would split a component off. Cells that a failed group
// visited are not tried again at this threshold (a later group reaching them fails too), so a
// threshold costs O(cells) at most.
class GroupPeeler
{
public:
  GroupPeeler(PeelSolid& solid, int64_t maximumGroup)
    : Solid(solid)
    , DT(solid.DT)
    , MaximumGroup(maximumGroup)
  {
    this->Stamp.assign(this->DT.GetNumberOfCells(), 0);
    this->Failed.assign(this->DT.GetNumberOfCells(), false);
    this->Bad.assign(solid.Star.size(), 0);
    this->Dirty.assign(solid.Star.size(), 0);
  }

  // Forget the failed groups (a new threshold).
  void Reset() { std::fill(this->Failed.begin(), this->Failed.end(), false); }

  bool HasFailed(int64_t c) const { return this->Failed[c]; }

  // Try the group that starts at cell c; on success the cells are removed and listed in Group.
  // A group that opens a handle is accepted only when c's largest exterior facet exceeds
  // handleThreshold or the group holds more than 8 cells. With keepTopology (rule 7 of the class
  // docs) the group goes on past a manifold state that opened a handle, and is accepted only when
  // the topology is the same or a handle closed (the solid staying connected) and it shows the
  // outside no facet larger than c's largest. Facets over clearFacet are clearly not surface
  // triangles (-1: none is): a point may be left in no cell when its last cell holds it by such
  // facets only (rule 8: a strut), at most MaximumStrutPoints per group, never by a group that
  // opens a handle; such points are listed in StrutPoints. Without keepTopology, a group that
  // splits a part off is accepted when every facet it takes off the boundary is such a facet
  // (rule 9: a neck between two objects).
  bool Try(int64_t c,
    double threshold,
    double handleThreshold,
    bool keepTopology = false,
    double clearFacet = -1.0)
  {
    this->Group.clear();
    this->StrutPoints.clear();
    this->ClearFacet = clearFacet;
    this->BadCount = 0;
    this->DirtyBadCount = 0;
    const double startFacet = this->Solid.LargestExteriorFacet(c);
    const bool mayOpenHandle = startFacet > handleThreshold;
    std::priority_queue<std::pair<double, int64_t>> grow;
    bool ok = this->Add(c, threshold, grow);
    int64_t change = 0; // EulerChange, when known for the group as it is
    bool changeKnown = false;
    while (ok)
    {
      if (keepTopology && this->FailsAtTop(grow, startFacet, threshold))
      {
        ok = false;
        break;
      }
      // The group stops at the first cell after which the boundary is a manifold again: a group
      // that went on (its links were once checked only when it doubled) could pinch the boundary
      // again and grow, largest facet first, along a torus's tube to the size bound instead of
      // closing up across the hole.
      if (this->IsManifold())
      {
        if (!keepTopology)
        {
          break;
        }
        change = this->EulerChange();
        if (change >= 0)
        {
          changeKnown = true;
          break;
        }
      }
      if (grow.empty() || static_cast<int64_t>(this->Group.size()) >= this->MaximumGroup)
      {
        ok = false;
        break;
      }
      const int64_t n = grow.top().second;
      grow.pop();
      if (!this->Solid.IsInside(n) || this->ShowsSmallFacet(n, threshold))
      {
        continue;
      }
      if (!this->MayEnter(n))
      {
        continue; // never entered: a point would be left in no cell
      }
      if (this->Failed[n])
      {
        ok = false;
        break;
      }
      ok = this->Add(n, threshold, grow);
    }
    if (ok)
    {
      // The Euler characteristic of the boundary drops when a handle opens, stays when the
      // topology does, and grows when a handle closes (a bridge goes) or a component splits off:
      // the last only when the group took nothing but clear facets off the boundary (a neck
      // between two objects, rule 9; the solid must stay connected around any other group), and
      // a handle opened by a short group (at most 8 cells) only when its start facet is over
      // handleThreshold (HandleFactor; by default every group start passes: the short groups
      // punch the webs of flat tetrahedra left across concave regions, see the class docs).
      if (!changeKnown)
      {
        change = this->EulerChange();
      }
      if (keepTopology)
      {
        // Rule 7: the topology kept, or a handle closed with the solid still in one piece (a
        // bridge: e.g. a strip left between two punches through a web across a slot), never a
        // handle opened; and no facet shown larger than the start facet.
        ok = !this->ShowsLargerFacet(startFacet) &&
          (change == 0 || (change > 0 && this->StaysConnected(true)));
      }
      else if (change < 0)
      {
        // A group that leaves points in no cell removes a strut (rule 8): never to open a handle.
        ok = (mayOpenHandle || this->Group.size() > 8) && this->StrutPoints.empty();
      }
      else
      {
        ok = change == 0 || this->TookOnlyClearFacets() || this->StaysConnected(true);
      }
    }
    if (!ok)
    {
      for (int64_t g : this->Group)
      {
        this->Solid.SetInside(g, true);
        this->Failed[g] = true;
      }
      for (int64_t g : this->Group)
      {
        for (int k = 0; k < 4; ++k)
        {
          this->Bad[this->DT.Vertex(g, k)] = 0;
          this->Dirty[this->DT.Vertex(g, k)] = 0;
        }
      }
      this->Group.clear();
      this->StrutPoints.clear();
      this->DirtyVertices.clear();
    }
    return ok;
  }

  // Move the cells (all of one state, finite) to the other state when every vertex of them keeps
  // a manifold link and the cells of the old state around them stay connected (no part split
  // off, no void enclosed). The caller has checked that the boundary's Euler characteristic does
  // not change and that every vertex of the cells stays on the boundary (Evaluate):
  // the boundary then stays a closed 2-manifold of the same topology on the same points. Returns
  // whether they moved; the failed groups' marks are not touched.
  bool Toggle(const int64_t* cells, size_t size)
  {
    const bool inside = this->Solid.IsInside(cells[0]);
    this->Group.assign(cells, cells + size);
    for (int64_t c : this->Group)
    {
      this->Solid.SetInside(c, !inside);
    }
    this->VertexCells.clear();
    for (int64_t c : this->Group)
    {
      for (int k = 0; k < 4; ++k)
      {
        this->VertexCells.emplace_back(this->DT.Vertex(c, k), c);
      }
    }
    std::sort(this->VertexCells.begin(), this->VertexCells.end());
    bool ok = true;
    for (size_t i = 0; i < this->VertexCells.size() && ok; ++i)
    {
      const int32_t v = this->VertexCells[i].first;
      if (i > 0 && this->VertexCells[i - 1].first == v)
      {
        continue;
      }
      ok = this->ManifoldAt(v, this->VertexCells[i].second);
    }
    ok = ok && this->StaysConnected(inside);
    if (!ok)
    {
      for (int64_t c : this->Group)
      {
        this->Solid.SetInside(c, inside);
      }
    }
    this->Group.clear();
    return ok;
  }

  std::vector<int64_t> Group;
  // The points that the group leaves in no cell (rule 8 of the class docs).
  std::vector<int32_t> StrutPoints;

  // Whether the (removed) group shows the outside a facet larger than `measure`.
  bool ShowsLargerFacet(double measure) const
  {
    for (int64_t g : this->Group)
    {
      for (int k = 0; k < 4; ++k)
      {
        if (this->Solid.IsInside(this->DT.Neighbor(g, k)) &&
          this->Solid.FacetMeasure(g, k) > measure)
        {
          return true;
        }
      }
    }
    return false;
  }

  // Whether every facet that the (removed) group took off the boundary (a facet of a group cell
  // facing an outside cell not in the group) measures over ClearFacet: a neck whose surface
  // triangles are all clearly not surface triangles (rule 9 of the class docs). A sampled thin part
  // of an object keeps triangles of the sampling's size on its surface, which no group takes.
  bool TookOnlyClearFacets()
  {
    if (!(this->ClearFacet > 0.0))
    {
      return false;
    }
    ++this->Generation;
    for (int64_t g : this->Group)
    {
      this->Stamp[g] = this->Generation;
    }
    for (int64_t g : this->Group)
    {
      for (int k = 0; k < 4; ++k)
      {
        const int64_t n = this->DT.Neighbor(g, k);
        if (!this->Solid.IsInside(n) && this->Stamp[n] != this->Generation &&
          !(this->Solid.FacetMeasure(g, k) > this->ClearFacet))
        {
          return false;
        }
      }
    }
    return true;
  }

  // The change of the boundary's Euler characteristic that the (removed) group made: -2 for each
  // handle opened, 0 when the topology stayed.
  int64_t EulerChange()
  {
    // Evaluate gives the change of putting the group back.
    return -this->Evaluate<false>(this->Group.data(), this->Group.size(), false, nullptr)
              .EulerChange;
  }

  // What moving the finite cells (all of one state) to the other state would change, found without
  // moving them. V - E + F of the boundary changes only among the faces of the cells: their
  // vertices and facets from the state counts, their edges by one walk around each distinct edge,
  // which also gives (with Folds) the cosine of the angle between the outward normals of its two
  // boundary triangles before and after (PeelSolid::EdgeStates): the folds (negative cosines)
  // and the bending (1 - cosine, summed over the edges with two boundary triangles, in the order
  // of the edges' end point ids). With stopWhenVertexLeaves, returns as soon as a vertex of the
  // cells is found to leave the boundary (no inside or no outside cell around it after). With
  // Folds, after[6 k + e] receives the cosine after the move of edge e of cells[k] (edges (0, 1),
  // (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)).
  struct MoveEffect
  {
    int64_t EulerChange = 0;
    bool VertexLeaves = false;
    int64_t FoldsBefore = 0, FoldsAfter = 0;
    double BendBefore = 0.0, BendAfter = 0.0;

    void Tally(const double cosine[2])
    {
      this->FoldsBefore += cosine[0] < 0.0 ? 1 : 0;
      this->FoldsAfter += cosine[1] < 0.0 ? 1 : 0;
      this->BendBefore += cosine[0] <= 1.0 ? 1.0 - cosine[0] : 0.0;
      this->BendAfter += cosine[1] <= 1.0 ? 1.0 - cosine[1] : 0.0;
    }
  };
  template<bool Folds>
  MoveEffect Evaluate(const int64_t* cells, size_t size, bool stopWhenVertexLeaves, double* after)
  {
    MoveEffect effect;
    if (this->Moving.empty())
    {
      this->Moving.assign(this->Stamp.size(), false);
    }
    for (size_t k = 0; k < size; ++k)
    {
      this->Moving[cells[k]] = true;
    }
    const bool inside = this->Solid.IsInside(cells[0]);
    this->Vertices.clear();
    this->Edges.clear();
    for (size_t k = 0; k < size; ++k)
    {
      const int64_t c = cells[k];
      for (int j = 0; j < 4; ++j)
      {
        this->Vertices.push_back(this->DT.Vertex(c, j));
        // A facet between two moved cells is never on the boundary; the others change sides.
        const int64_t n = this->DT.Neighbor(c, j);
        if (!this->Moving[n])
        {
          effect.EulerChange += this->Solid.IsInside(n) == inside ? 1 : -1;
        }
      }
      for (int i = 0, e = 0; i < 3; ++i)
      {
        for (int j = i + 1; j < 4; ++j, ++e)
        {
          const int32_t v = this->DT.Vertex(c, i), w = this->DT.Vertex(c, j);
          this->Edges.push_back({ std::min(v, w), std::max(v, w), c, i, j, 6 * k + e });
        }
      }
    }
    std::sort(this->Vertices.begin(), this->Vertices.end());
    for (size_t i = 0; i < this->Vertices.size();)
    {
      const int32_t v = this->Vertices[i];
      size_t end = i + 1;
      while (end < this->Vertices.size() && this->Vertices[end] == v)
      {
        ++end;
      }
      const int32_t moved = static_cast<int32_t>(end - i);
      const int32_t insideAfter = this->Solid.Star[v].Inside + (inside ? -moved : moved);
      const int32_t outsideAfter = this->Solid.Star[v].Outside + (inside ? moved : -moved);
      const bool after = insideAfter > 0 && outsideAfter > 0;
      effect.VertexLeaves = effect.VertexLeaves || !after;
      effect.EulerChange += (after ? 1 : 0) - (this->Solid.OnBoundary(v) ? 1 : 0);
      i = end;
    }
    if (!(stopWhenVertexLeaves && effect.VertexLeaves))
    {
      std::sort(this->Edges.begin(),
        this->Edges.end(),
        [](const GroupEdge& x, const GroupEdge& y)
        { return std::tie(x.V, x.W) < std::tie(y.V, y.W); });
      auto moving = [this](int64_t cell) { return static_cast<bool>(this->Moving[cell]); };
      for (size_t k = 0; k < this->Edges.size();)
      {
        const GroupEdge& e = this->Edges[k];
        double cosine[2];
        bool onBoundary[2];
        this->Solid.EdgeStates(e.Cell, e.I, e.J, 2, Folds, moving, cosine, onBoundary);
        effect.EulerChange -= (onBoundary[1] ? 1 : 0) - (onBoundary[0] ? 1 : 0);
        if (Folds)
        {
          effect.Tally(cosine);
        }
        for (; k < this->Edges.size() && this->Edges[k].V == e.V && this->Edges[k].W == e.W; ++k)
        {
          if (Folds)
          {
            after[this->Edges[k].Index] = cosine[1];
          }
        }
      }
    }
    for (size_t k = 0; k < size; ++k)
    {
      this->Moving[cells[k]] = false;
    }
    return effect;
  }

private:
  // Whether the cells of state `inside` next to the group (of the other state now) are still
  // connected to each other through cells of that state: a breadth-first search from each of them,
  // merging searches that meet, until one is left (connected) or a search runs out of cells while
  // others remain (a part split off).
  bool StaysConnected(bool inside)
  {
    ++this->Generation;
    this->Fill.clear();
    if (this->Label.empty())
    {
      this->Label.resize(this->Stamp.size());
    }
    this->Searches.Reset(0);
    std::vector<int64_t> pending; // per search root: its cells still to visit
    for (int64_t g : this->Group)
    {
      for (int k = 0; k < 4; ++k)
      {
        const int64_t n = this->DT.Neighbor(g, k);
        if (this->Solid.IsInside(n) == inside && this->Stamp[n] != this->Generation)
        {
          this->Stamp[n] = this->Generation;
          this->Label[n] = static_cast<int32_t>(this->Searches.Add());
          pending.push_back(1);
          this->Fill.push_back(n);
        }
      }
    }
    int64_t components = this->Searches.GetNumberOfIds();
    for (size_t head = 0; head < this->Fill.size() && components > 1; ++head)
    {
      const int64_t c = this->Fill[head];
      int64_t r = this->Searches.Find(this->Label[c]);
      for (int k = 0; k < 4; ++k)
      {
        const int64_t n = this->DT.Neighbor(c, k);
        if (this->Solid.IsInside(n) != inside)
        {
          continue;
        }
        if (this->Stamp[n] != this->Generation)
        {
          this->Stamp[n] = this->Generation;
          this->Label[n] = static_cast<int32_t>(r);
          ++pending[r];
          this->Fill.push_back(n);
        }
        else
        {
          const int64_t other = this->Searches.Find(this->Label[n]);
          if (other != r)
          {
            const int64_t merged = pending[r] + pending[other];
            r = this->Searches.Link(r, other);
            pending[r] = merged;
            --components;
          }
        }
      }
      if (--pending[r] == 0 && components > 1)
      {
        return false; // this search is over: its cells are cut off from the others
      }
    }
    return components <= 1;
  }

  // Whether the boundary is a manifold at every vertex of the group. Lazy, since it is asked after
  // every cell and the link of a vertex on the rim of a large flat layer holds thousands of cells:
  // a vertex found non-manifold whose cells have not changed since is still non-manifold (then
  // nothing is checked), and the vertices whose cells changed (the last changed first) are
  // checked until one is non-manifold. The answer is the same as checking every vertex. A vertex
  // found at once to be non-manifold (IsolatedAt, no walk) is looked for among them first.
  bool IsManifold()
  {
    if (this->BadCount > this->DirtyBadCount)
    {
      return false;
    }
    for (size_t i = 0; i < this->DirtyVertices.size(); ++i)
    {
      const std::pair<int32_t, int64_t> vc = this->DirtyVertices[i];
      if (this->IsolatedAt(vc.first, vc.second))
      {
        this->DirtyVertices[i] = this->DirtyVertices.back();
        this->DirtyVertices.pop_back();
        this->Dirty[vc.first] = 0;
        this->DirtyBadCount -= this->Bad[vc.first];
        this->BadCount += 1 - this->Bad[vc.first];
        this->Bad[vc.first] = 1;
        return false;
      }
    }
    while (!this->DirtyVertices.empty())
    {
      const std::pair<int32_t, int64_t> vc = this->DirtyVertices.back();
      this->DirtyVertices.pop_back();
      const int32_t v = vc.first;
      this->Dirty[v] = 0;
      this->DirtyBadCount -= this->Bad[v];
      const uint8_t bad = this->ManifoldAt(v, vc.second) ? 0 : 1;
      this->BadCount += bad - this->Bad[v];
      this->Bad[v] = bad;
      if (bad)
      {
        return false;
      }
    }
    return this->BadCount == 0;
  }

  // Under rule 7, whether the group must fail whatever its links (checked first: they are the
  // cost of a try): the largest facet it shows (the top of `grow`, once the entries of cells
  // already in the group are dropped) is larger than the start facet, and the cell behind it is
  // a failed group's cell (the group fails on entering it, or stops at a manifold state showing
  // that facet) or one it never enters (a facet under the threshold shown or a point left in no
  // cell: while the group grows, a cell's exterior facets only grow and its vertices' cell counts
  // only drop), so the facet stays shown. In the last case the group stops before growing on, and
  // fewer cells are marked failed than if it had grown to its end.
  bool FailsAtTop(std::priority_queue<std::pair<double, int64_t>>& grow,
    double startFacet,
    double threshold)
  {
    while (!grow.empty() && !this->Solid.IsInside(grow.top().second))
    {
      grow.pop();
    }
    if (grow.empty() || !(grow.top().first > startFacet))
    {
      return false;
    }
    const int64_t n = grow.top().second;
    return this->Failed[n] || this->ShowsSmallFacet(n, threshold) || !this->MayEnter(n);
  }

  // Whether c shows the outside a facet whose measure is at most the threshold.
  bool ShowsSmallFacet(int64_t c, double threshold) const
  {
    for (int j = 0; j < 4; ++j)
    {
      if (this->Solid.IsExterior(c, j) && this->Solid.FacetMeasure(c, j) <= threshold)
      {
        return true;
      }
    }
    return false;
  }

  // Whether the inside cell c is the last cell of its vertex in slot k and holds it only by a
  // strut: its three facets through the vertex all measure over ClearFacet (clearly not surface
  // triangles), so the vertex has no surface triangle left (rule 8 of the class docs).
  bool HoldsOnlyStrut(int64_t c, int k) const
  {
    if (!(this->ClearFacet > 0.0))
    {
      return false;
    }
    for (int j = 0; j < 4; ++j)
    {
      if (j != k && !(this->Solid.FacetMeasure(c, j) > this->ClearFacet))
      {
        return false;
      }
    }
    return true;
  }

  // Whether the group may enter the inside cell c: each vertex of c that would be left in no cell
  // is held only by a strut (HoldsOnlyStrut), and the group leaves at most MaximumStrutPoints
  // points in no cell.
  bool MayEnter(int64_t c) const
  {
    size_t leaving = this->StrutPoints.size();
    for (int k = 0; k < 4; ++k)
    {
      if (this->Solid.Star[this->DT.Vertex(c, k)].Inside <= 1)
      {
        if (!this->HoldsOnlyStrut(c, k) || ++leaving > MaximumStrutPoints)
        {
          return false;
        }
      }
    }
    return true;
  }

  // Remove c (tentatively) and queue the cells behind its facets over the threshold. Returns false
  // when a vertex of c is left in no cell, unless the group may leave it (HoldsOnlyStrut; listed
  // in StrutPoints).
  bool Add(int64_t c, double threshold, std::priority_queue<std::pair<double, int64_t>>& grow)
  {
    this->Solid.SetInside(c, false);
    this->Group.push_back(c);
    for (int k = 0; k < 4; ++k)
    {
      const int32_t v = this->DT.Vertex(c, k);
      if (this->Solid.Star[v].Inside == 0)
      {
        if (!this->HoldsOnlyStrut(c, k) || this->StrutPoints.size() >= MaximumStrutPoints)
        {
          return false;
        }
        this->StrutPoints.push_back(v);
      }
      if (!this->Dirty[v])
      {
        this->Dirty[v] = 1;
        this->DirtyBadCount += this->Bad[v];
        this->DirtyVertices.emplace_back(v, c);
      }
    }
    for (int k = 0; k < 4; ++k)
    {
      const int64_t n = this->DT.Neighbor(c, k);
      if (this->Solid.IsInside(n))
      {
        const double m = this->Solid.FacetMeasure(c, k);
        if (m > threshold)
        {
          grow.emplace(m, n);
        }
      }
    }
    return true;
  }

  // Whether the outside cell c alone is an outside component of the star of its vertex v, which
  // has other outside cells and inside cells: its facets through v all face inside cells. The
  // boundary is then not a manifold at v (ManifoldAt is false), found without a walk.
  bool IsolatedAt(int32_t v, int64_t c) const
  {
    const PeelSolid::StarCounts& star = this->Solid.Star[v];
    if (this->Solid.IsInside(c) || star.Inside == 0 || star.Outside < 2)
    {
      return false;
    }
    for (int j = 0; j < 4; ++j)
    {
      if (this->DT.Vertex(c, j) != v && !this->Solid.IsInside(this->DT.Neighbor(c, j)))
      {
        return false;
      }
    }
    return true;
  }

  // Whether the boundary is a 2-manifold at vertex v (a cell of which is `start`): in the link of
  // v, the inside cells form one component, the outside cells one component, and around each edge
  // (v, w) the state changes at most twice (at most two boundary triangles on the edge).
  bool ManifoldAt(int32_t v, int64_t start)
  {
    const int32_t insideCells = this->Solid.Star[v].Inside;
    const int32_t outsideCells = this->Solid.Star[v].Outside;
    if (insideCells == 0 || outsideCells == 0)
    {
      return true; // v inside the solid (or in no cell: checked by the caller)
    }
    // The star of v is connected through the facets that contain v: each state forms one
    // component when the flood fill from one of its cells reaches all of them (the counts).
    ++this->Generation;
    const bool startInside = this->Solid.IsInside(start);
    int64_t other = -1; // a cell of the other state, next to the first fill
    if (this->FillState(v, start, other) != (startInside ? insideCells : outsideCells) || other < 0)
    {
      return false;
    }
    int64_t unused = -1;
    if (this->FillState(v, other, unused) != (startInside ? outsideCells : insideCells))
    {
      return false;
    }
    // Boundary triangles per edge (v, w), listed by the fill of the inside cells.
    std::sort(this->EdgeEnds.begin(), this->EdgeEnds.end());
    for (size_t i = 0; i + 2 < this->EdgeEnds.size(); ++i)
    {
      if (this->EdgeEnds[i] == this->EdgeEnds[i + 2])
      {
        return false;
      }
    }
    return true;
  }

  // Flood fill from `seed` through the facets that contain v, over the cells of seed's state;
  // returns the number of cells reached. Sets `other` to a cell of the other state next to them;
  // when the state is inside, lists in EdgeEnds the two other ends of each boundary triangle on v
  // (the edges (v, w)).
  int64_t FillState(int32_t v, int64_t seed, int64_t& other)
  {
    const bool inside = this->Solid.IsInside(seed);
    if (inside)
    {
      this->EdgeEnds.clear();
    }
    int64_t reached = 1;
    this->Stack.clear();
    this->Stack.push_back(seed);
    this->Stamp[seed] = this->Generation;
    while (!this->Stack.empty())
    {
      const int64_t c = this->Stack.back();
      this->Stack.pop_back();
      for (int j = 0; j < 4; ++j)
      {
        if (this->DT.Vertex(c, j) == v)
        {
          continue;
        }
        const int64_t n = this->DT.Neighbor(c, j);
        if (this->Solid.IsInside(n) != inside)
        {
          other = n;
          if (inside)
          {
            for (int k = 0; k < 4; ++k)
            {
              const int32_t w = this->DT.Vertex(c, k);
              if (k != j && w != v)
              {
                this->EdgeEnds.push_back(w);
              }
            }
          }
        }
        else if (this->Stamp[n] != this->Generation)
        {
          this->Stamp[n] = this->Generation;
          this->Stack.push_back(n);
          ++reached;
        }
      }
    }
    return reached;
  }

  struct GroupEdge
  {
    int32_t V, W;
    int64_t Cell;
    int I, J;     // slots of V and W in Cell
    size_t Index; // 6 x the cell's place in the cells evaluated + the edge's
  };
  std::vector<GroupEdge> Edges;
  std::vector<int32_t> Vertices;

  PeelSolid& Solid;
  const pcs::Delaunay3D& DT;
  int64_t MaximumGroup;
  std::vector<uint32_t> Stamp;
  uint32_t Generation = 0;
  // One bit per cell (std::vector<bool>), as PeelSolid::Inside.
  std::vector<bool> Failed;
  std::vector<bool> Moving; // the cells being evaluated (sized to the cells at the first use)
  std::vector<uint8_t> Bad, Dirty;
  std::vector<std::pair<int32_t, int64_t>> DirtyVertices; // vertex, a cell of it
  int64_t BadCount = 0;      // vertices of the group found non-manifold when last checked
  int64_t DirtyBadCount = 0; // those of them whose cells changed since
  std::vector<int64_t> Stack, Fill;
  // Search of each cell stamped in StaysConnected (sized to the cells at its first call), and the
  // searches that met (union-find).
  std::vector<int32_t> Label;
  pcs::DisjointSets<int64_t> Searches;
  std::vector<int32_t> EdgeEnds;
  std::vector<std::pair<int32_t, int64_t>> VertexCells;
  // Facets over ClearFacet are clearly not surface triangles (-1: none is): a group may leave a
  // point in no cell when the point's last cell holds it by such facets only, at most
  // MaximumStrutPoints points per group (rule 8), and split a part off when it takes only such
  // facets off the boundary (rule 9).
  double ClearFacet = -1.0;
  static constexpr size_t MaximumStrutPoints = 2;
};

// Folds left by the peel: boundary edges whose two triangles face opposite ways (outward normals
// more than 90 degrees apart). On samples of smooth surfaces the peel leaves thin flaps of flat
// tetrahedra (nearly cospherical points) kept while a neighbour went, so that a triangle of the
// flap faces into the solid (dark specks when shaded). Run moves cells next to the folds to the
// other state (all the inside or all the outside cells around a fold's edge, or one cell on either
// side of its two triangles) when that keeps the boundary a closed 2-manifold of the same topology
// with every point on it and the edges of the moved cells then have fewer folds, or as many and
// less bending (the sum of 1 - cosine of the angle between the two normals, lower by 1e-6 at
// least). Each move lowers the whole surface's (folds, bending), so the pass ends; it is also
// bounded by the number of cells. Each trial is local: one walk around each edge of the moved
// cells gives their folds and bending before and after, and (for several cells) the change of the
// Euler characteristic; the links and the connectivity are checked last, only for the moves that
// pass the rest.
class Unfolder
{
public:
  Unfolder(PeelSolid& solid, GroupPeeler& groups, std::function<bool(double)> progress)
    : Solid(solid)
    , DT(solid.DT)
    , Groups(groups)
    , Progress(std::move(progress))
  {
  }

  // Returns the number of moves, or -1 when `progress` (called with the share of the folds met so
  // far) returned false.
  int64_t Run()
  {
    this->QueueAllFolds();
    int64_t moves = 0, visited = 0;
    double done = 0.0;
    const int64_t maximumMoves = this->DT.GetNumberOfCells();
    while (!this->Work.empty() && moves < maximumMoves)
    {
      if (++visited % 4096 == 0)
      {
        // The queue grows as moves make new folds: the share never runs backwards.
        done = std::max(done, visited / static_cast<double>(visited + this->Work.size()));
        if (!this->Progress(done))
        {
          return -1;
        }
      }
      const EdgeRef e = this->Work.back();
      this->Work.pop_back();
      // The folds are mostly met in queue order: start loading the records of the fold after
      // next and the neighbours of the next one (whose record was requested at the last turn).
      const size_t left = this->Work.size();
      if (left >= 2)
      {
        this->Solid.Prefetch(this->Work[left - 2].Cell);
      }
      if (left >= 1)
      {
        for (int k = 0; k < 4; ++k)
        {
          this->Solid.Prefetch(this->DT.Neighbor(this->Work[left - 1].Cell, k));
        }
      }
      if (!this->ListMoves(e))
      {
        continue; // no longer a fold
      }
      for (size_t m = 0; m + 1 < this->MoveStart.size(); ++m)
      {
        const size_t first = this->MoveStart[m];
        if (this->TryMove(&this->MoveCells[first], this->MoveStart[m + 1] - first))
        {
          ++moves;
          break;
        }
      }
    }
    return moves;
  }

private:
  struct EdgeRef
  {
    int64_t Cell;
    int I, J; // slots of the edge's end points in Cell
  };

  // Queue every fold, sorted by its end points' ids (a spatial order: the ids follow the
  // insertion order). Each boundary edge is walked once, from the exterior facet in which it runs
  // from its smaller end point id to the larger (the boundary is oriented: its other facet has it
  // the other way): a walk through the inside cells around the edge finds that other facet. The
  // edge's reference (where the walks of ListMoves start, which orders the moves tried) is the
  // cell of the facet that comes last (cell, then slot), the edge's slots in it increasing.
  void QueueAllFolds()
  {
    struct Fold
    {
      int32_t V, W;
      EdgeRef Ref;
    };
    std::vector<Fold> folds;
    const int64_t cells = this->DT.GetNumberOfCells();
    for (int64_t c = 0; c < cells; ++c)
    {
      for (int j = 0; j < 4; ++j)
      {
        if (!this->Solid.IsExterior(c, j))
        {
          continue;
        }
        // The slots of the facet's triangle in the order of PeelSolid::FacetTriangle.
        const std::array<int, 3> slot = FacetSlots(j);
        std::array<double, 3> normal;
        bool measured = false;
        for (int e = 0; e < 3; ++e)
        {
          const int a = slot[e], b = slot[(e + 1) % 3];
          const int32_t v = this->DT.Vertex(c, a), w = this->DT.Vertex(c, b);
          if (v > w)
          {
            continue; // walked from the other facet
          }
          const std::pair<int64_t, int> other = this->Solid.NextBoundaryFacet(c, j, 6 - a - b - j);
          if (!measured)
          {
            normal = this->Solid.FacetNormal(c, j);
            measured = true;
          }
          const std::array<double, 3> n = this->Solid.FacetNormal(other.first, other.second);
          if (!(normal[0] * n[0] + normal[1] * n[1] + normal[2] * n[2] < 0.0))
          {
            continue;
          }
          EdgeRef ref{ c, std::min(a, b), std::max(a, b) };
          if (other.first > c || (other.first == c && other.second > j))
          {
            int sv = 0, sw = 0;
            for (int k = 0; k < 4; ++k)
            {
              const int32_t u = this->DT.Vertex(other.first, k);
              sv = u == v ? k : sv;
              sw = u == w ? k : sw;
            }
            ref = { other.first, std::min(sv, sw), std::max(sv, sw) };
          }
          folds.push_back({ v, w, ref });
        }
      }
    }
    std::sort(folds.begin(),
      folds.end(),
      [](const Fold& x, const Fold& y) { return std::tie(x.V, x.W) < std::tie(y.V, y.W); });
    this->Work.clear();
    for (const Fold& f : folds)
    {
      this->Work.push_back(f.Ref);
    }
  }

  // When the edge e is a fold, list the moves tried there and return true: each finite cell on
  // either side of its two boundary triangles alone, then all the inside cells around its edge
  // and all the outside ones (when finite), when they are 2 to MaximumFan cells (more were not
  // seen to help). One walk around the edge.
  bool ListMoves(const EdgeRef& e)
  {
    this->MoveCells.clear();
    this->MoveStart.assign(1, 0);
    this->Fans[0].clear();
    this->Fans[1].clear();
    bool infinite = false;
    std::array<double, 3> normal[2];
    int found = 0;
    this->Solid.AroundEdge(e.Cell,
      e.I,
      e.J,
      [&](int64_t cell, int cross)
      {
        const bool inside = this->Solid.IsInside(cell);
        this->Fans[inside ? 0 : 1].push_back(cell);
        infinite = infinite || this->DT.IsInfinite(cell);
        const int64_t next = this->DT.Neighbor(cell, cross);
        if (inside != this->Solid.IsInside(next))
        {
          if (found++ < 2)
          {
            normal[found - 1] = this->Solid.BoundaryNormal(cell, cross, inside);
          }
          for (int64_t c : { cell, next })
          {
            if (!this->DT.IsInfinite(c))
            {
              this->MoveCells.push_back(c);
              this->MoveStart.push_back(this->MoveCells.size());
            }
          }
        }
        return false;
      });
    if (!(PeelSolid::NormalCosine(normal, found) < 0.0))
    {
      return false;
    }
    for (int side = 0; side < 2; ++side)
    {
      const size_t size = this->Fans[side].size();
      if (size >= 2 && size <= MaximumFan && !(side == 1 && infinite))
      {
        this->MoveCells.insert(
          this->MoveCells.end(), this->Fans[side].begin(), this->Fans[side].end());
        this->MoveStart.push_back(this->MoveCells.size());
      }
    }
    return true;
  }

  // Move the cells to the other state when that is allowed and improves the surface, and queue
  // the folds among their edges then. One cell: the sculpting rules (cheap) first, then its edges'
  // folds and bending before and after (PeelSolid::ToggleCosines). Several (a fan):
  // GroupPeeler::Evaluate, then the links and the connectivity (GroupPeeler::Toggle).
  bool TryMove(const int64_t* cells, size_t size)
  {
    if (size == 1)
    {
      const int64_t c = cells[0];
      if (!this->Solid.MayToggle(c))
      {
        return false;
      }
      GroupPeeler::MoveEffect effect;
      double before[6], after[6];
      this->Solid.ToggleCosines(c, before, after);
      for (int e = 0; e < 6; ++e)
      {
        const double cosine[2] = { before[e], after[e] };
        effect.Tally(cosine);
      }
      if (!Better(effect))
      {
        return false;
      }
      this->Solid.SetInside(c, !this->Solid.IsInside(c));
      this->QueueFolds(c, after);
      return true;
    }
    // A fan: the vertices, the Euler characteristic and the folds, then the links and the
    // connectivity.
    this->FanAfter.resize(6 * size);
    const GroupPeeler::MoveEffect effect =
      this->Groups.Evaluate<true>(cells, size, true, this->FanAfter.data());
    if (effect.VertexLeaves || effect.EulerChange != 0 || !Better(effect) ||
      !this->Groups.Toggle(cells, size))
    {
      return false;
    }
    for (size_t k = 0; k < size; ++k)
    {
      this->QueueFolds(cells[k], &this->FanAfter[6 * k]);
    }
    return true;
  }

  // Whether (folds, bending) after a move is lower than before: fewer folds, or as many and less
  // bending by 1e-6 at least.
  static bool Better(const GroupPeeler::MoveEffect& e)
  {
    return e.FoldsAfter < e.FoldsBefore ||
      (e.FoldsAfter == e.FoldsBefore && e.BendAfter < e.BendBefore - 1e-6);
  }

  // Queue the folds among the edges of c, whose cosines (PeelSolid::EdgeStates) are `cosine`, for
  // the edges (0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3) in this order.
  void QueueFolds(int64_t c, const double* cosine)
  {
    for (int i = 0, e = 0; i < 3; ++i)
    {
      for (int j = i + 1; j < 4; ++j, ++e)
      {
        if (cosine[e] < 0.0)
        {
          this->Work.push_back({ c, i, j });
        }
      }
    }
  }

  PeelSolid& Solid;
  const pcs::Delaunay3D& DT;
  GroupPeeler& Groups;
  std::function<bool(double)> Progress;
  std::vector<EdgeRef> Work;
  std::vector<double> FanAfter;
  // The moves listed at a fold: move m is MoveCells[MoveStart[m], MoveStart[m + 1]).
  std::vector<int64_t> MoveCells;
  std::vector<size_t> MoveStart;
  std::vector<int64_t> Fans[2];
  static constexpr size_t MaximumFan = 8;
};

// A max-heap of (measure, payload) entries with four children per node (the children of node i
// are 4i + 1 to 4i + 4): half the levels of a binary heap, each level's children side by side in
// memory. The peel's queue holds hundreds of thousands of entries on 10^6 points (376,000 at
// once on a random sphere), whose deep levels miss the cache at every pop. The entries come out in
// the same order as from any max-heap: largest first, equal measures by larger payload (entries
// equal in both are the same entry; the measures are never NaN).
class FourHeap
{
public:
  using Entry = std::pair<double, int64_t>;

  bool Empty() const { return this->Heap.empty(); }
  size_t Size() const { return this->Heap.size(); }
  // The entry at position i of the heap (0: the largest; 1 to 4: the next largest's candidates).
  const Entry& operator[](size_t i) const { return this->Heap[i]; }

  void Push(const Entry& e)
  {
    size_t i = this->Heap.size();
    this->Heap.push_back(e);
    while (i > 0)
    {
      const size_t parent = (i - 1) / 4;
      if (!(this->Heap[parent] < e))
      {
        break;
      }
      this->Heap[i] = this->Heap[parent];
      i = parent;
    }
    this->Heap[i] = e;
  }

  // Remove and return the largest entry (the heap must not be empty).
  Entry Pop()
  {
    const Entry top = this->Heap[0];
    const Entry last = this->Heap.back();
    this->Heap.pop_back();
    const size_t size = this->Heap.size();
    if (size == 0)
    {
      return top;
    }
    size_t i = 0;
    for (;;)
    {
      const size_t first = 4 * i + 1;
      if (first >= size)
      {
        break;
      }
      size_t largest = first;
      const size_t end = std::min(first + 4, size);
      for (size_t k = first + 1; k < end; ++k)
      {
        largest = this->Heap[largest] < this->Heap[k] ? k : largest;
      }
      if (!(last < this->Heap[largest]))
      {
        break;
      }
      this->Heap[i] = this->Heap[largest];
      i = largest;
    }
    this->Heap[i] = last;
    return top;
  }

private:
  std::vector<Entry> Heap;
};

// The exterior facets as oriented triangles (outward from the solid).
std::vector<std::array<int32_t, 3>> ExteriorTriangles(const PeelSolid& solid)
{
  std::vector<std::array<int32_t, 3>> triangles;
  const int64_t cells = solid.DT.GetNumberOfCells();
  for (int64_t c = 0; c < cells; ++c)
  {
    if (!solid.IsInside(c))
    {
      continue;
    }
    for (int j = 0; j < 4; ++j)
    {
      if (!solid.IsExterior(c, j))
      {
        continue;
      }
      triangles.push_back(solid.FacetTriangle(c, j));
    }
  }
  return triangles;
}

} // namespace

//------------------------------------------------------------------------------------------------
vtkPerimeterPeelSurface::vtkPerimeterPeelSurface() = default;

int vtkPerimeterPeelSurface::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

//------------------------------------------------------------------------------------------------
int vtkPerimeterPeelSurface::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  vtkSmartPointer<vtkPointSet> input =
    pcs::GatherInputOnFirstProcess(vtkPointSet::GetData(inputVector[0]));
  if (!input && output)
  {
    return 1; // another MPI process: process 0 computes the surface
  }
  if (!input || !output)
  {
    vtkErrorMacro("Missing input or output data object.");
    return 0;
  }
  const std::string mismatched = pcs::DropMismatchedPointArrays(input);
  if (!mismatched.empty())
  {
    vtkWarningMacro(<< mismatched);
  }

  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  if (input->GetPoints())
  {
    output->SetPoints(input->GetPoints());
  }
  output->GetPointData()->PassData(input->GetPointData());
  vtkNew<vtkUnsignedCharArray> used;
  used->SetName("Used");
  used->SetNumberOfValues(numberOfPoints);
  used->FillValue(0);
  output->GetPointData()->AddArray(used);

  vtkIdType iterations = 0, removedCount = 0, groupCount = 0, tetrahedra = 0, outliers = 0;
  vtkIdType duplicates = 0, pileDuplicates = 0;
  vtkIdType unfoldMoves = 0, strutPoints = 0;
  double finalThreshold = 0.0, delaunayTime = 0.0, peelTime = 0.0;
  double delaunayCPUTime = 0.0, peelCPUTime = 0.0;
  std::clock_t startCPU = std::clock();
  std::clock_t peelStartCPU = startCPU;
  using Clock = std::chrono::steady_clock;
  Clock::time_point start = Clock::now();
  Clock::time_point peelStart = start;
  vtkNew<vtkCellArray> polys;
  auto finish = [&]()
  {
    output->SetPolys(polys);
    vtkIdType usedPoints = 0;
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      usedPoints += used->GetValue(i);
    }
    vtkFieldData* fd = output->GetFieldData();
    pcs::AddFieldCount(fd, "NumberOfIterations", iterations);
    pcs::AddFieldValue(fd, "FinalThreshold", finalThreshold);
    pcs::AddFieldCount(fd, "NumberOfTetrahedra", tetrahedra);
    pcs::AddFieldCount(fd, "NumberOfRemovedTetrahedra", removedCount);
    pcs::AddFieldCount(fd, "NumberOfGroupRemovals", groupCount);
    pcs::AddFieldCount(fd, "NumberOfUnfoldingMoves", unfoldMoves);
    pcs::AddFieldCount(fd, "NumberOfStrutPoints", strutPoints);
    pcs::AddFieldCount(fd, "NumberOfTriangles", polys->GetNumberOfCells());
    pcs::AddFieldCount(fd, "NumberOfUsedPoints", usedPoints);
    pcs::AddFieldCount(fd, "NumberOfUnusedPoints", numberOfPoints - usedPoints);
    pcs::AddFieldCount(fd, "NumberOfOutliers", outliers);
    pcs::AddFieldCount(fd, "NumberOfDuplicatePoints", duplicates);
    pcs::AddFieldValue(fd, "DelaunayTime", delaunayTime);
    pcs::AddFieldValue(fd, "PeelTime", peelTime);
    pcs::AddFieldValue(fd, "DelaunayCPUTime", delaunayCPUTime);
    pcs::AddFieldValue(fd, "PeelCPUTime", peelCPUTime);
    if (numberOfPoints > usedPoints && polys->GetNumberOfCells() > 0)
    {
      vtkWarningMacro(<< numberOfPoints - usedPoints << " of " << numberOfPoints
                      << " point(s) are not on the surface (duplicates, non-finite points, "
                         "outliers or points inside the solid): see the point data array Used.");
    }
    return 1;
  };

  if (numberOfPoints == 0)
  {
    vtkWarningMacro("The input has no points: the output is empty.");
    return finish();
  }
  if (numberOfPoints > 150000000)
  {
    vtkErrorMacro(
      "The input has " << numberOfPoints << " points; at most 150000000 are supported.");
    return finish();
  }
  const std::string nanParameters =
    pcs::NaNParametersError({ { "ThresholdFactor", this->ThresholdFactor },
      { "ConvergenceTolerance", this->ConvergenceTolerance },
      { "Threshold", this->Threshold },
      { "GroupFactor", this->GroupFactor },
      { "HandleFactor", this->HandleFactor },
      { "CaveLimit", this->CaveLimit },
      { "GroupStartLimit", this->GroupStartLimit },
      { "OutlierFactor", this->OutlierFactor } });
  if (!nanParameters.empty())
  {
    vtkErrorMacro(<< nanParameters);
    return finish();
  }

  // Finite coordinates, scaled by a power of two into the predicates' range when needed.
  std::vector<double> xyz;
  std::vector<int32_t> ids;
  const vtkIdType skipped = pcs::ReadFiniteCoordinates(input->GetPoints(), xyz, ids);
  if (skipped > 0)
  {
    vtkWarningMacro("Skipped " << skipped << " point(s) with NaN or infinite coordinates.");
  }
  const int exponent = pcs::PredicateSafeExponent(xyz.data(), 3, ids);
  if (exponent != 0)
  {
    xyz = pcs::ScaledCopy(xyz.data(), xyz.size(), exponent);
  }
  // Far outliers, and piles of near-coincident points (pcs::FindPiles) on the same table: the
  // tetrahedralization gets one point per pile (its first, smallest id), the others are
  // duplicates. Exact copies too, merged here into the copy of smallest id: the kernel would
  // insert every id (its insertion order, its cell numbering and which copy represents a point
  // then depend on the copies, and the peel's order-dependent steps follow the numbering).
  std::vector<std::pair<int32_t, int32_t>> pileCopies;
  outliers = pcs::RemoveOutliersAndPiles(
    xyz.data(),
    ids,
    this->OutlierFactor,
    pileCopies,
    [this](double) { return !this->GetAbortExecute(); },
    /*withExactCopies=*/true);
  pileDuplicates = static_cast<vtkIdType>(pileCopies.size());
  duplicates = pileDuplicates;
  if (outliers > 0)
  {
    vtkWarningMacro("Excluded " << outliers << " far outlier(s) of "
                                << ids.size() + outliers + pileDuplicates
                                << " point(s) (OutlierFactor " << this->OutlierFactor
                                << "): point data Used = 0, field data NumberOfOutliers.");
  }
  // DelaunayTime and DelaunayCPUTime measure the tetrahedralization, not the outlier rule.
  start = Clock::now();
  startCPU = std::clock();

  pcs::Delaunay3D dt;
  dt.SetKeepInsertionOrder(true);
  auto progress = [this](double fraction)
  {
    this->UpdateProgress(0.6 * fraction);
    return !this->GetAbortExecute();
  };
  if (!dt.Triangulate(xyz.data(), ids, progress))
  {
    if (!this->GetAbortExecute())
    {
      vtkWarningMacro("Fewer than 4 distinct non-coplanar points among the "
        << ids.size() << " usable point(s): no surface is produced.");
    }
    return finish();
  }
  tetrahedra = dt.GetNumberOfFiniteCells();
  duplicates = pileDuplicates + static_cast<vtkIdType>(dt.GetDuplicates().size());
  if (duplicates > 0)
  {
    vtkWarningMacro(<< pcs::DuplicatesWarning(duplicates,
                      "one point of each group is tetrahedralized (of a pile, its point of "
                      "smallest id; point data Used = 0 for the others)"));
  }
  const std::string large = dt.DescribeLargeSize(ids.size());
  if (!large.empty())
  {
    vtkWarningMacro(<< large);
  }
  peelStart = Clock::now();
  delaunayTime = std::chrono::duration<double>(peelStart - start).count();
  peelStartCPU = std::clock();
  delaunayCPUTime = static_cast<double>(peelStartCPU - startCPU) / CLOCKS_PER_SEC;
  this->UpdateProgress(0.6);

  // Peeling (paper section 3, steps 3-7), on vertices numbered in insertion order and cells
  // sorted by their newest vertex: the peel's queue visits cells all over the surface, and the
  // cells around each one and their points are then mostly near it in memory. The numbering
  // decides only between exactly equal measures (the queue's order) and the rounding of the
  // means' sums (camel's vertex set: 2 of 19,240 triangles differ, same quality).
  const std::vector<int32_t> pointOfVertex = dt.RenumberByInsertion();
  {
    std::vector<double> vertexXYZ(3 * pointOfVertex.size());
    for (size_t v = 0; v < pointOfVertex.size(); ++v)
    {
      std::copy_n(&xyz[3 * static_cast<size_t>(pointOfVertex[v])], 3, &vertexXYZ[3 * v]);
    }
    xyz.swap(vertexXYZ);
  }
  PeelSolid solid(dt, xyz.data(), this->FacetMeasure, numberOfPoints);
  const bool relative = this->LocalSpacingNeighbors > 0 && this->Threshold <= 0.0;
  if (relative)
  {
    solid.SetLocalSpacing(this->LocalSpacingNeighbors);
  }
  const int64_t cells = dt.GetNumberOfCells();
  // The mean measure of the exterior facets (paper steps 4 and 7). Lists the inside cells that
  // have exterior facets, with the largest measure of them, in `exposed` (the next threshold's
  // first candidates: the solid does not change in between).
  using Entry = std::pair<double, int64_t>; // largest exterior facet measure, cell
  std::vector<Entry> exposed;
  auto exteriorMean = [&]()
  {
    double sum = 0.0;
    int64_t exterior = 0;
    exposed.clear();
    for (int64_t c = 0; c < cells; ++c)
    {
      if (!solid.IsInside(c))
      {
        continue;
      }
      double largest = -1.0;
      for (int j = 0; j < 4; ++j)
      {
        if (solid.IsExterior(c, j))
        {
          const double m = solid.FacetMeasure(c, j);
          sum += m;
          ++exterior;
          largest = std::max(largest, m);
        }
      }
      if (largest >= 0.0)
      {
        exposed.emplace_back(largest, c);
      }
    }
    return exterior > 0 ? sum / exterior : 0.0;
  };
  const bool fixed = this->Threshold > 0.0;
  double mean = exteriorMean();
  double threshold = fixed ? std::ldexp(this->Threshold, exponent) : mean * this->ThresholdFactor;

  const bool manifold = this->ManifoldOutput;
  // GroupFactor is a ratio of lengths: squared for the area measure.
  const double groupFactor =
    this->GroupFactor * (this->FacetMeasure == AREA ? this->GroupFactor : 1.0);
  // A short group that opens a handle needs a start facet over HandleFactor x GroupFactor x
  // threshold (rule 3 of the class docs; a ratio of lengths, squared for the area measure).
  const double handleFactor =
    groupFactor * this->HandleFactor * (this->FacetMeasure == AREA ? this->HandleFactor : 1.0);
  // The cave limit (rule 4 of the class docs): the measure of an equilateral triangle of
  // perimeter CaveLimit local spacings; -1 (never reached) without relative measures or when 0.
  double caveLimit = -1.0;
  if (relative && this->CaveLimit > 0.0)
  {
    const double side = this->CaveLimit / 3.0;
    caveLimit = this->FacetMeasure == AREA
      ? 0.25 * std::sqrt(3.0) * side * side
      : (this->FacetMeasure == CIRCUMRADIUS ? side / std::sqrt(3.0) : this->CaveLimit);
  }
  // The group start limit (rule 5 of the class docs), converted like the cave limit; -1 (off)
  // without relative measures, without ManifoldOutput or when 0. Active once the peel has
  // converged with GroupFactor x threshold over it; group removals then start at facets over
  // the limit as well.
  double groupStartLimit = -1.0;
  if (relative && this->ManifoldOutput && this->GroupStartLimit > 0.0)
  {
    const double side = this->GroupStartLimit / 3.0;
    groupStartLimit = this->FacetMeasure == AREA
      ? 0.25 * std::sqrt(3.0) * side * side
      : (this->FacetMeasure == CIRCUMRADIUS ? side / std::sqrt(3.0) : this->GroupStartLimit);
  }
  bool limitedStart = false;
  auto normalStart = [&]()
  {
    return limitedStart ? std::min(threshold * groupFactor, groupStartLimit)
                        : threshold * groupFactor;
  };
  // Once the peel has converged (rule 7 of the class docs), groups that keep the topology and
  // show no facet larger than their start facet may start at facets over twice the threshold (a
  // ratio of lengths: squared for the area measure).
  const double keepTopologyFactor = this->FacetMeasure == AREA ? 4.0 : 2.0;
  bool converged = false;
  auto groupStart = [&]()
  { return converged ? std::min(normalStart(), keepTopologyFactor * threshold) : normalStart(); };
  // Whether the inside cell c, whose exterior facets are `mask` and the largest of them m, may
  // not be removed now. With ManifoldOutput, a cell is not removed when it would show a facet more
  // than 1.5 times larger than the bottleneck of its widest way in (WidestWayIn: the smallest facet
  // the peel passed through to reach it, at most m) if that is not clearly too large for the
  // surface (at most GroupFactor x threshold): a cave under a true surface triangle, dug at once or
  // in steps that each grow by less than 1.5 times (neighbouring surface triangles of a uniform
  // random sample differ by less; a peel coming from the hull meets shrinking facets). Nor is a
  // cell whose exterior facets are all within the cave limit when it would show one over it. With
  // the AREA measure the bottleneck is m (slivers give surface triangles of nearly no area).
  // Each rule, once true, stays true while the other cells go and none of c's face neighbours
  // does: the counts of inside cells only drop, a boundary vertex or edge stays on the boundary,
  // and c's own facets and its widest way in change only with its neighbours (which offer c again
  // when they go).
  // `edgeRule` false leaves out the sculpting rule of two exterior facets (a walk around an edge,
  // the costliest test; when a cell is offered it nearly always passes, so it is left to the
  // cell's turn in the queue).
  // `way`, when given, receives the widest way in to c, computed in full (the bottleneck c records
  // when it goes); otherwise only as far as the rule needs it (see WidestWayIn). It is left
  // unchanged when c is refused before the rule, or without ManifoldOutput.
  // The verdict tells the rules that do not depend on the threshold (no point left in no cell, the
  // sculpting rules: RefusedForGood, until a face neighbour goes) from rules 2 and 4.
  enum Verdict
  {
    Allowed,
    RefusedForGood,
    RefusedAtThreshold
  };
  const bool pathRule = this->FacetMeasure != AREA;
  // At a cell's turn, when its exterior facets are those it was offered with: the rules of
  // `refused` that depend on more than them (no point left in no cell, the sculpting rules).
  auto pointsAndSculptingAllow = [&](int64_t c, int mask)
  { return !solid.Orphans(c) && (!manifold || solid.KeepsManifold(c, mask)); };
  auto refused = [&](int64_t c, int mask, double m, bool edgeRule, double* way)
  {
    if (solid.Orphans(c))
    {
      return RefusedForGood;
    }
    if (!manifold)
    {
      return Allowed;
    }
    // The cheap tests first: the sculpting rules but for two exterior facets, rules 2 and 4, the
    // walk around an edge for two exterior facets.
    const bool twoFacets =
      mask == 3 || mask == 5 || mask == 6 || mask == 9 || mask == 10 || mask == 12;
    if (!twoFacets && !solid.KeepsManifold(c, mask))
    {
      return RefusedForGood;
    }
    const double above = way ? std::numeric_limits<float>::max() : threshold * groupFactor;
    const double smallest = pathRule ? solid.WidestWayIn(c, m, above) : m;
    if (way)
    {
      *way = smallest;
    }
    const bool pathBound = smallest <= threshold * groupFactor;
    if (pathBound || m <= caveLimit)
    {
      const double hidden = solid.LargestFacet(c, 15 & ~mask);
      if ((pathBound && hidden > 1.5 * smallest) || (m <= caveLimit && hidden > caveLimit))
      {
        return RefusedAtThreshold;
      }
    }
    return twoFacets && edgeRule && !solid.KeepsManifold(c, mask) ? RefusedForGood : Allowed;
  };
  // The cells refused RefusedForGood at their last offer or turn, one bit per cell: the first
  // offers of a new threshold skip them (every cell whose face neighbour goes is offered again).
  std::vector<bool> refusedForGood(cells, false);
  // Cells with an exterior facet over the threshold, largest first. A cell refused now is not
  // queued (it would be refused when its turn came: see `refused`); it is offered again when a
  // neighbour goes. The largest exterior facet of an inside cell only grows, so an entry whose
  // measure is no longer the cell's is stale: the cell was queued again with its new measure,
  // and that entry came first. An entry holds 16 x cell + the cell's exterior facets (its
  // mask) when offered. A max-heap with four children per node, open for the prefetches of
  // peelQueue.
  FourHeap queue;
  // With ManifoldOutput, the cells refused with a facet over the group start (GroupFactor x
  // threshold, or the group start limit: rule 5) (group candidates; some may be listed twice or
  // have gone since).
  std::vector<int64_t> refusedLarge;
  auto listRefused = [&](int64_t c, double m)
  {
    if (manifold && m > groupStart())
    {
      refusedLarge.push_back(c);
    }
  };
  auto offer = [&](int64_t c, int mask, double m)
  {
    if (m <= threshold)
    {
      refusedForGood[c] = false;
      return;
    }
    const Verdict verdict = refused(c, mask, m, false, nullptr);
    refusedForGood[c] = verdict == RefusedForGood;
    if (verdict != Allowed)
    {
      listRefused(c, m);
      return;
    }
    queue.Push({ m, c << 4 | mask });
  };
  auto push = [&](int64_t c)
  {
    const int mask = solid.ExteriorMask(c);
    offer(c, mask, solid.LargestFacet(c, mask));
  };
  bool aborted = false;
  auto removed = [&]()
  {
    ++removedCount;
    if (removedCount % 65536 == 0)
    {
      this->UpdateProgress(std::min(0.9, 0.6 + 0.3 * removedCount / double(tetrahedra)));
      aborted = this->GetAbortExecute() != 0;
    }
  };
  // One cell at a time (paper steps 5-6), with the sculpting rules when ManifoldOutput is on.
  auto peelQueue = [&]()
  {
    while (!queue.Empty() && !aborted)
    {
      const Entry top = queue.Pop();
      const int64_t c = top.second >> 4;
      // The cells come from all over the surface, and their records and states are mostly out
      // of the cache: start loading what the next turns read so that the loads overlap. The
      // candidates for the turn after next (the children of the heap's top), the neighbours of
      // the next cell (its record was loaded as such a candidate) and of this one.
      for (size_t i = 1; i < 5 && i < queue.Size(); ++i)
      {
        solid.Prefetch(queue[i].second >> 4);
      }
      if (!queue.Empty())
      {
        const int64_t next = queue[0].second >> 4;
        for (int k = 0; k < 4; ++k)
        {
          solid.Prefetch(dt.Neighbor(next, k));
        }
      }
      for (int k = 0; k < 4; ++k)
      {
        solid.Prefetch(dt.Neighbor(c, k));
      }
      // What the offers of c's neighbours read when c goes (their records were requested at the
      // previous turn): the vertex of each opposite c (its facet measures) and the bottlenecks
      // of their neighbours (their widest ways in).
      for (int k = 0; k < 4; ++k)
      {
        const int64_t n = dt.Neighbor(c, k);
        const int32_t apex = dt.Vertex(n, dt.MirrorIndex(c, k));
        if (apex >= 0)
        {
          solid.PrefetchVertex(apex);
          solid.PrefetchBottlenecks(n);
        }
      }
      if (!solid.IsInside(c))
      {
        continue;
      }
      const int mask = solid.ExteriorMask(c);
      // With the exterior facets it was offered with, rules 2 and 4 (which depend on them
      // alone) passed then and still pass (see `refused`).
      const bool offeredMask = mask == (top.second & 15);
      const double m = offeredMask ? top.first : solid.LargestFacet(c, mask);
      if (m != top.first)
      {
        continue; // stale
      }
      double way = m;
      Verdict verdict = Allowed;
      if (offeredMask)
      {
        verdict = pointsAndSculptingAllow(c, mask) ? Allowed : RefusedForGood;
        if (verdict == Allowed && manifold && pathRule)
        {
          way = solid.WidestWayIn(c, m, std::numeric_limits<float>::max());
        }
      }
      else
      {
        verdict = refused(c, mask, m, true, &way);
      }
      if (verdict != Allowed)
      {
        refusedForGood[c] = verdict == RefusedForGood;
        listRefused(c, m);
        continue; // refused; offered again when a neighbour goes
      }
      solid.Bottleneck[c] = static_cast<float>(way);
      solid.SetInside(c, false);
      for (int k = 0; k < 4; ++k)
      {
        const int64_t n = dt.Neighbor(c, k);
        if (solid.IsInside(n))
        {
          push(n);
        }
      }
      removed();
    }
  };
  std::unique_ptr<GroupPeeler> groups;
  if (manifold)
  {
    // Successful groups are small (at most a few hundred cells on the test shapes and CGAL's
    // mesh vertices); a failing one may burrow into the solid through its large inner facets
    // until the bound, so the bound sets the cost of the failures.
    groups.reset(new GroupPeeler(solid, std::max<int64_t>(8192, cells / 256)));
  }
  std::vector<Entry> candidates;
  while (!aborted)
  {
    refusedLarge.clear();
    for (const Entry& e : exposed)
    {
      if (e.first > threshold)
      {
        if (refusedForGood[e.second])
        {
          listRefused(e.second, e.first); // as offer would
        }
        else
        {
          offer(e.second, solid.ExteriorMask(e.second), e.first);
        }
      }
    }
    peelQueue();
    if (groups)
    {
      groups->Reset();
      for (bool more = true; more && !aborted;)
      {
        // The cells with an exterior facet over the group start, largest facet first.
        // Every such cell was refused when last offered (its measure changes only when a
        // neighbour goes, which offers it), so refusedLarge lists them all.
        candidates.clear();
        for (int64_t c : refusedLarge)
        {
          if (solid.IsInside(c))
          {
            const double m = solid.LargestExteriorFacet(c);
            if (m > groupStart())
            {
              candidates.emplace_back(m, c);
            }
          }
        }
        std::sort(candidates.begin(), candidates.end(), std::greater<Entry>());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        refusedLarge.clear();
        for (const Entry& candidate : candidates)
        {
          refusedLarge.push_back(candidate.second);
        }
        more = false;
        for (const Entry& candidate : candidates)
        {
          const int64_t c = candidate.second;
          if (aborted || !solid.IsInside(c) || groups->HasFailed(c))
          {
            continue;
          }
          const double m = solid.LargestExteriorFacet(c);
          // The group's cells are on the widest way in to its first cell (rule 2): a group
          // started under a small bottleneck (a cave's wall) does not open a free way inwards.
          const double way = pathRule ? solid.WidestWayIn(c, m, std::numeric_limits<float>::max())
                                      : std::numeric_limits<double>::infinity();
          if (m <= threshold ||
            !groups->Try(c, threshold, threshold * handleFactor, m <= normalStart(), normalStart()))
          {
            continue;
          }
          more = true;
          ++groupCount;
          strutPoints += static_cast<vtkIdType>(groups->StrutPoints.size());
          for (int64_t g : groups->Group)
          {
            solid.Bottleneck[g] = static_cast<float>(way);
            removed();
            for (int k = 0; k < 4; ++k)
            {
              const int64_t n = dt.Neighbor(g, k);
              if (solid.IsInside(n))
              {
                push(n);
              }
            }
          }
          peelQueue();
        }
      }
    }
    ++iterations;
    if (aborted || fixed || iterations >= this->MaximumIterations)
    {
      break;
    }
    const double updated = exteriorMean();
    if (updated == 0.0 || std::fabs(updated - mean) <= this->ConvergenceTolerance * mean)
    {
      if (updated > 0.0 && manifold && !converged)
      {
        // Converged: go on with groups starting at the group start limit (rule 5) when the
        // group start is over it, and groups that keep the topology from facets over twice the
        // threshold (rule 7); the threshold stays until the mean moves again.
        converged = true;
        limitedStart = groupStartLimit > 0.0 && groupStartLimit < threshold * groupFactor;
        continue;
      }
      break;
    }
    mean = updated;
    threshold = mean * this->ThresholdFactor;
  }
  finalThreshold = relative ? threshold : std::ldexp(threshold, -exponent);
  if (aborted)
  {
    return finish();
  }
  this->UpdateProgress(0.9);

  if (groups)
  {
    // Folds: flaps of flat tetrahedra with a triangle facing into the solid (see Unfolder).
    auto progress = [this](double fraction)
    {
      this->UpdateProgress(0.9 + 0.08 * fraction);
      return !this->GetAbortExecute();
    };
    unfoldMoves = Unfolder(solid, *groups, progress).Run();
    if (unfoldMoves < 0)
    {
      unfoldMoves = 0;
      return finish();
    }
  }
  std::vector<std::array<int32_t, 3>> triangles = ExteriorTriangles(solid);

  vtkNew<vtkTypeInt32Array> connectivity;
  connectivity->SetNumberOfValues(3 * static_cast<vtkIdType>(triangles.size()));
  vtkNew<vtkTypeInt32Array> offsets;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(triangles.size()) + 1);
  for (size_t t = 0; t < triangles.size(); ++t)
  {
    offsets->SetValue(static_cast<vtkIdType>(t), static_cast<int32_t>(3 * t));
    for (int k = 0; k < 3; ++k)
    {
      const int32_t point = pointOfVertex[triangles[t][k]];
      connectivity->SetValue(static_cast<vtkIdType>(3 * t + k), point);
      used->SetValue(point, 1);
    }
  }
  offsets->SetValue(
    static_cast<vtkIdType>(triangles.size()), static_cast<int32_t>(3 * triangles.size()));
  polys->SetData(offsets, connectivity);
  peelTime = std::chrono::duration<double>(Clock::now() - peelStart).count();
  peelCPUTime = static_cast<double>(std::clock() - peelStartCPU) / CLOCKS_PER_SEC;
  this->UpdateProgress(1.0);
  return finish();
}

//------------------------------------------------------------------------------------------------
void vtkPerimeterPeelSurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ThresholdFactor: " << this->ThresholdFactor << "\n";
  os << indent << "GroupFactor: " << this->GroupFactor << "\n";
  os << indent << "HandleFactor: " << this->HandleFactor << "\n";
  os << indent << "CaveLimit: " << this->CaveLimit << "\n";
  os << indent << "GroupStartLimit: " << this->GroupStartLimit << "\n";
  os << indent << "ConvergenceTolerance: " << this->ConvergenceTolerance << "\n";
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "FacetMeasure: " << this->FacetMeasure << "\n";
  os << indent << "MaximumIterations: " << this->MaximumIterations << "\n";
  os << indent << "ManifoldOutput: " << this->ManifoldOutput << "\n";
  os << indent << "LocalSpacingNeighbors: " << this->LocalSpacingNeighbors << "\n";
  os << indent << "OutlierFactor: " << this->OutlierFactor << "\n";
}
