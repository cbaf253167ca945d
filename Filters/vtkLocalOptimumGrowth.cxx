#include "vtkLocalOptimumGrowth.h"

#include "pcsCoordinateScaling.h"
#include "pcsDisjointSets.h"
#include "pcsDuplicatePoints.h"
#include "pcsFieldData.h"
#include "pcsFrontGrowth.h"
#include "pcsGatherInput.h"
#include "pcsHoleFilling.h"
#include "pcsNearestNeighbors.h"
#include "pcsNormalEstimation.h"
#include "pcsOutliers.h"
#include "pcsPiles.h"
#include "pcsPointInsertion.h"
#include "pcsPredicates.h"
#include "pcsProjectedTests.h"
#include "pcsSpatialSort.h"
#include "pcsSurfaceMesh.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkStaticPointLocator.h"
#include "vtkTypeInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

vtkStandardNewMacro(vtkLocalOptimumGrowth);
vtkCxxSetObjectMacro(vtkLocalOptimumGrowth, Locator, vtkStaticPointLocator);

namespace
{
using Id = int32_t;
namespace P = pcs::predicates;

// Vertex ids are 32-bit, and so are the triangle ids of pcs::SurfaceMesh (about 2 per point).
constexpr vtkIdType MaximumNumberOfPoints = 500000000;

// Seeds with SeparateSheets (Grower::TrySeed): P2 at most this many times as far from P1 as P1's
// nearest neighbour (3, the paper's k2, left more points unused: CGAL's spool vertices 19 -> 29).
constexpr double SeedReach = 4.0;
// Step 5: a separate piece of 2 to this many triangles (a closed polyhedron of up to 10 points)
// is taken apart when its points can be inserted into the surface around it.
constexpr int64_t SmallPieceTriangles = 16;

//------------------------------------------------------------------------------------------------
// Small vector helpers on double[3].
inline void Sub(const double* a, const double* b, double* r)
{
  r[0] = a[0] - b[0];
  r[1] = a[1] - b[1];
  r[2] = a[2] - b[2];
}
inline double Dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline void Cross(const double* a, const double* b, double* r)
{
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}
inline double Distance2(const double* a, const double* b)
{
  const double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
  return Dot(d, d);
}
// Twice the area of the triangle (a, b, c) over the square of its longest edge: 0 for collinear
// points, sqrt(3) / 2 for an equilateral triangle (a sliver's measure, scale free).
inline double Fatness(const double* a, const double* b, const double* c)
{
  double ab[3], ac[3], n[3];
  Sub(b, a, ab);
  Sub(c, a, ac);
  Cross(ab, ac, n);
  const double longest2 = std::max({ Dot(ab, ab), Dot(ac, ac), Distance2(b, c) });
  return longest2 > 0.0 ? std::sqrt(Dot(n, n)) / longest2 : 0.0;
}
// Normal of the triangle (a, b, c) (right-hand rule), normalized; false when it has no finite
// non-zero length.
inline bool UnitNormal(const double* a, const double* b, const double* c, double* n)
{
  double ab[3], ac[3];
  Sub(b, a, ab);
  Sub(c, a, ac);
  Cross(ab, ac, n);
  const double length = std::sqrt(Dot(n, n));
  if (!(length > 0.0) || !std::isfinite(length))
  {
    return false;
  }
  n[0] /= length;
  n[1] /= length;
  n[2] /= length;
  return true;
}

// Whether the unit normal m of the triangle (a, b, c) (UnitNormal) has m . n >= cosine with a
// margin of 10^-10 relative, far beyond the rounding of UnitNormal and of the dot product: the
// comparison made on the normalized vector gives the same answer. Decided without the square
// root and the divisions; false when not clear (then compare the normalized vector).
inline bool ClearlyWithin(
  const double* a, const double* b, const double* c, const double* n, double cosine)
{
  double ab[3], ac[3], m[3];
  Sub(b, a, ab);
  Sub(c, a, ac);
  Cross(ab, ac, m);
  const double length2 = Dot(m, m), along = Dot(m, n);
  return cosine > 0.0 && length2 > 0.0 && std::isfinite(length2) && along > 0.0 &&
    along * along > (1.0 + 1e-10) * (cosine * cosine) * length2;
}

// The angle between two vectors of lengths d and sqrt(l2) whose dot product is `dot` is wider
// than the angle of cosine `cosine`: dot < cosine d sqrt(l2). An acute angle is never wider than
// a right or obtuse bound, so the square root is taken only when it matters (same answer).
inline bool WiderThan(double dot, double cosine, double d, double l2)
{
  if (cosine <= 0.0 && dot >= 0.0)
  {
    return false;
  }
  return dot < cosine * d * std::sqrt(l2);
}

// Asks for the memory at `address` to be brought into the cache (a hint; no effect on results).
// The growth reads its tables (coordinates, K-nearest rows) at vertices known a little earlier:
// the vertices of a neighbourhood are collected before their coordinates are read, the next front
// edge of the queue and the admissible candidates before their neighbourhoods are collected.
inline void Prefetch(const void* address)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(address);
#else
  (void)address;
#endif
}
inline void PrefetchPoint(const double* x, Id v)
{
  Prefetch(x + 3 * static_cast<size_t>(v));
}

// Every member is set by MakeParameters (the defaults are pcs::FrontGrowthParameters').
struct Parameters
{
  int K;
  double CosNormal;
  double TanNormal;
  double CosHalfNormal; // preferred candidates bend by at most half
  double MinRatio;
  double MaxRatio;
  double CosBase;
  int MaxHoleEdges;
  bool Relax;
  // Constraint 2 follows the sampling's anisotropy (Grower::AnisotropyFactor):
  // vtkLocalOptimumGrowth only; vtkGreedySurfaceTriangulation's growth keeps the paper's ratios.
  bool FollowAnisotropy;
  // The last level's needle rule does not reach a sheet the front has not reached
  // (Grower::OnUnreachedSheet): vtkLocalOptimumGrowth only (greedy's growth unchanged).
  bool SeparateSheets;
};

// The internal form of the constraints (cosines, tangent) for K neighbours per point.
Parameters MakeParameters(int k, const pcs::FrontGrowthParameters& constraints)
{
  Parameters parameters;
  parameters.K = k;
  parameters.CosNormal = std::cos(vtkMath::RadiansFromDegrees(constraints.MaximumNormalAngle));
  parameters.CosHalfNormal =
    std::cos(vtkMath::RadiansFromDegrees(0.5 * constraints.MaximumNormalAngle));
  parameters.TanNormal = constraints.MaximumNormalAngle >= 90.0
    ? std::numeric_limits<double>::infinity()
    : std::tan(vtkMath::RadiansFromDegrees(constraints.MaximumNormalAngle));
  parameters.MinRatio = constraints.MinimumEdgeRatio;
  parameters.MaxRatio = constraints.MaximumEdgeRatio;
  parameters.CosBase = std::cos(vtkMath::RadiansFromDegrees(constraints.MaximumBaseAngle));
  parameters.MaxHoleEdges = constraints.MaximumHoleEdges;
  parameters.Relax = constraints.RelaxConstraints;
  parameters.FollowAnisotropy = false;
  parameters.SeparateSheets = false;
  return parameters;
}

//------------------------------------------------------------------------------------------------
// The growth (steps 2 to 6 of the class documentation) on distinct finite points X (packed
// x,y,z, internal ids 0..N-1) with their K nearest neighbours Knn (N*K ids, -1 padded).
class Grower
{
public:
  Grower(const double* x, Id n, const std::vector<Id>& knn, const Parameters& parameters,
    vtkAlgorithm* algorithm)
    : X(x)
    , N(n)
    , Knn(knn)
    , K(parameters.K)
    , Par(parameters)
    , Algorithm(algorithm)
  {
    this->Mesh.Initialize(n);
    this->Scratch.assign(n, PointScratch());
    this->Touched.assign(n, 0);
    this->InTouchedSinceRetry.assign(n, 0);
    this->SeedFailed.assign(n, 0);
  }

  void Run();
  // The input points when the growth runs on points projected onto their local planes
  // (LocalPlaneProjection): the folds (step 7) and the long edges are those of the output.
  const double* InputX = nullptr;
  // Whether constraint 2 and the seeds follow the sampling's anisotropy (AnisotropyFactor): only
  // on clouds sampled in scan lines or on a regular grid, i.e. when at least a third of a regular
  // subsample of the points (every 8th internal id) lie on lines next to lines (LineAnisotropy
  // widens there). Elsewhere the paper's ratios alone: on mesh vertex sets with a few rows of
  // points (CGAL's camel, man) the widening there left 20-30 % more boundary edges
  // (Benchmarks/results/local_optimum.md, task loganiso), and it costs a test per expanded edge.
  // Shares measured: CGAL's mesh vertex sets and real scans at most 26 % (turbine; radar 10 %,
  // man 9 %, camel 3 %) but rotor (81 %); tori sampled on a regular (u, v) grid whose outer band
  // has cells 2.8 to 3.2 times longer than wide (tube radius 0.45 to 0.54 of the ring's) 36 to
  // 48 %: with half as the bound there, a cell's diagonal, sqrt(1 + A^2) times its short side,
  // was left without its other half (its short side under d / 3) and the front made triangles
  // skipping rows instead (task gridlog).
  void DecideAnisotropy(bool allowed);
  // The expansion alone (steps 3 and 4 of the class documentation: no hole filling) from the front
  // of `mesh` (when expandFront), which the grower takes over with its triangle ids; then from
  // seeds at the points of SeedOrder when the front has stalled.
  void GrowFrom(pcs::SurfaceMesh&& mesh, bool expandFront);
  void Grow();

  pcs::SurfaceMesh Mesh;
  double ProgressBegin = 0.15, ProgressEnd = 0.9; // the algorithm's progress over the growth
  // The points in the order the seeds are tried (paper, step 1: the extreme point first): x
  // descending, then y, then z; a permutation of 0..N-1.
  std::vector<Id> SeedOrder;
  // The scan-line stretch of every point (3 per point, see pcs::AddOffLineNeighbors), or empty.
  void SetStretch(const std::vector<double>& stretch); // read, not copied: must outlive the grower
  vtkIdType Seeds = 0;
  vtkIdType HolesClosed = 0;
  vtkIdType Inserted = 0;
  bool Aborted = false;

private:
  struct Item
  {
    Id A, B;
    uint8_t Level; // stage of Expand (0: flat candidates only, 1: strict, 2, 3: relaxed)
  };
  struct Deferred
  {
    Id A, B; // as deferred: the front edge may run b->a since (OnFront)
    uint64_t Clock;
    int64_t Next[2]; // in the EdgesAt chains of A and B: the entry deferred before, -1 ends
    uint8_t Level;
    bool Active;   // false once requeued or dropped (the entry stays until CompactDeferred)
    uint32_t Seen; // RetryStamp of the last retry that collected it
  };

  const double* P3(Id v) const { return this->X + 3 * static_cast<size_t>(v); }
  const Id* Neighbors(Id v) const { return this->Knn.data() + static_cast<size_t>(v) * this->K; }
  void PrefetchNeighbors(Id v) const
  {
    const Id* row = this->Neighbors(v);
    Prefetch(row);
    Prefetch(row + (this->K - 1)); // a row of 20 spans two cache lines
  }

  // Projection frame: origin, in-plane axes U, V and normal W (right-handed).
  void SetFrame(const double* origin, const double* u, const double* w);
  const double* P2(Id v)
  {
    PointScratch& scratch = this->Scratch[v];
    if (scratch.Frame != this->Frame)
    {
      scratch.Frame = this->Frame;
      double d[3];
      Sub(this->P3(v), this->Origin, d);
      scratch.P[0] = Dot(d, this->U);
      scratch.P[1] = Dot(d, this->V);
    }
    return scratch.P;
  }
  double Height(Id v) const
  {
    double d[3];
    Sub(this->P3(v), this->Origin, d);
    return Dot(d, this->W);
  }

  bool Expand(Id a, Id b, int level, bool mayReverse = true);
  double LocalSpacing(Id v) const;
  bool OnUnreachedSheet(Id c, Id a, Id b) const;
  bool WideEarFits(Id u, Id w, Id apex);
  bool OnFrontLoop(Id a, Id b, Id c) const;
  bool ShortLoop(Id a, Id b);
  double CloudSpacing();
  bool PlantSeed();
  bool TrySeed(Id p1, bool relaxed);
  void ProcessQueue();
  bool RetryDeferred();
  bool Changed(const Deferred& d) const;
  void Defer(Id a, Id b, uint8_t level);
  void CollectWoken();
  void BuildDeferredIndex();
  void LinkEnds(size_t entry);
  bool OnFront(const Deferred& d, Id& a, Id& b) const;
  void Retire(size_t entry);
  void CompactDeferred();
  void FillHoles();
  void InsertOrphans();
  bool InsertOrphan(Id q, pcs::PointInsertionResult* record = nullptr);
  std::vector<std::vector<std::array<Id, 3>>> SmallPieces();
  void TakeApart(const std::vector<std::array<Id, 3>>& piece);
  bool FillHole(const std::vector<Id>& frontLoop);
  bool FoldsOntoMesh(const std::vector<Id>& triangles, bool allLoopEdges) const;
  bool FillNarrowLoop(const std::vector<Id>& frontLoop);
  void GatherAround(const std::vector<Id>& loop, std::vector<Id>& around);
  void OrientComponents();
  // The quadrilateral (a, c, b, d) of an interior edge a-b: its triangles (a, b, c) = t1 and
  // (b, a, d) = t2 with their unit normals n1, n2, the flipped ones (a, d, c) and (b, c, d) with
  // m1, m2, and the smallest normal dot product among its five edges before and after a flip.
  struct Quad
  {
    Id A, B, C, D;
    int64_t T1, T2;
    double N1[3], N2[3], M1[3], M2[3];
    double Before, After;
  };
  template<typename Candidate, typename Examine, typename Decide>
  void FlipEdges(const Candidate& candidate, const Examine& examine, const Decide& decide);
  void Unfold();
  bool NeighborDiagonal(Id c, Id d) const;
  void ShortenLongEdges();
  double NearestSampleDistance2(const double* x, const Id* around, int count) const;
  double FarthestFromSamples(Id p, Id q, Id r, Id u) const;
  void ReportProgress();

  // Neighbourhood of the current operation: candidate vertices (the K-neighbourhoods of the
  // centres) and the front edges at them.
  void CollectVertices(const Id* centers, int count);
  size_t AddUnmarked(const Id* ids, int count, size_t size);
  void CollectFrontEdges();
  void AddFrontEdges(Id v);
  void Extend(Id v);
  // Validity of a new triangle (x, y, z) in the current frame (see the class documentation).
  bool InWedge(Id apex, Id from, Id to, Id q);
  bool WedgesOk(Id x, Id y, Id z);
  bool CrossesFront(Id x, Id y, Id z);
  bool FacesFrame(Id s, Id e) const;
  bool Blocked(Id x, Id y, Id z, const std::vector<Id>& blockers, Id apex);
  bool OffPlaneAtVertex(Id x, Id y, Id z, Id apex, Id q, int& flat) const;
  // `acrossEdge`: (x, y, z) is (b, a, c) of the expansion of the current front edge a->b, whose
  // blocking points strictly on the near side of a->b are left out (EdgeBlockers). `apex`: the
  // third vertex of the edge's triangle (a, b, apex) when (b, a, c) takes a free point or closes
  // an ear (not a bridge; -1 otherwise): a point whose projection is exactly a vertex's is then
  // decided in space (Blocked).
  bool ProjectedValid(Id x, Id y, Id z, bool acrossEdge = false, Id apex = -1)
  {
    this->Extend(x);
    this->Extend(y);
    this->Extend(z);
    // Blocked before CrossesFront: it refuses more candidates (10^5 armadillo samples: 87,166
    // against 4,220 of the 178,000 tested after the wedges) and needs no front edge collection.
    return P::Orient2D(this->P2(x), this->P2(y), this->P2(z)) > 0 && this->WedgesOk(x, y, z) &&
      !this->Blocked(x, y, z, acrossEdge ? this->EdgeBlockers : this->Blockers, apex) &&
      !this->CrossesFront(x, y, z);
  }
  // Ear (v, u, w) closing the front angle u->v->w: the smallest cosine of the angles between its
  // normal and its neighbours' (constraint 1), or -2 when invalid.
  double EarScore(Id v, Id u, Id w, double cosNormal, double minimumRatio);
  bool EdgeRatiosOk(Id x, Id y, Id z, double minimum) const;
  double AnisotropyFactor(Id a, Id b, Id y, double ab2) const;
  double LineAnisotropy(Id v) const;
  double PointAnisotropy(Id v, Id& off) const;
  double ComputePointAnisotropy(Id v, Id& off) const;
  // Per point, computed when first needed: PointAnisotropy and its off-line neighbour.
  mutable std::vector<std::pair<float, Id>> AnisotropyCache;
  double SamplingFactor(double elongation, double anisotropy) const;
  double RatioLength2(Id u, Id v, double length2) const
  {
    return this->Stretched.empty() || !(this->Stretched[u] | this->Stretched[v])
      ? length2
      : this->StretchedLength2(u, v, length2);
  }
  double StretchedLength2(Id u, Id v, double length2) const;

  // Commit a triangle: mesh, then Register (front queue, neighbourhood clock, labels).
  int64_t Commit(Id x, Id y, Id z);
  void Register(int64_t t);
  void Touch(Id v)
  {
    this->Touched[v] = this->Clock;
    if (!this->InTouchedSinceRetry[v])
    {
      this->InTouchedSinceRetry[v] = 1;
      this->TouchedSinceRetry.push_back(v);
    }
  }
  int32_t TriangleLabel(int64_t t)
  {
    return t >= 0 && t < static_cast<int64_t>(this->Labels.size())
      ? this->LabelSets.Find(this->Labels[t])
      : -1;
  }

  const double* X;
  const Id N;
  const std::vector<Id>& Knn;
  const double* Stretch = nullptr; // 3 per point, or nullptr
  std::vector<uint8_t> Stretched; // per point: a stretch not zero (empty: none anywhere)
  const int K;
  Parameters Par;
  vtkAlgorithm* Algorithm;

  std::vector<Item> Queue;
  size_t QueueHead = 0;
  // Edges whose expansion failed, in deferral order (retired entries stay until
  // CompactDeferred), and the vertices touched since the last retry. When the deferred edges
  // outnumber those vertices, a retry checks only the edges with an end among them or their
  // reverse neighbours (ReverseKnn: the vertices that have them among their K nearest), found
  // through the chains of deferred edges at each vertex (EdgesAt, -1 ended).
  std::vector<Deferred> DeferredEdges;
  size_t RetiredEdges = 0;
  size_t RelaxFrom = 0; // the active deferred edges before it are at the last stage
  std::vector<Id> TouchedSinceRetry;
  std::vector<char> InTouchedSinceRetry;
  bool DeferredIndexed = false;
  std::vector<int64_t> ReverseStart;
  std::vector<Id> ReverseKnn;
  std::vector<int64_t> EdgesAt;
  std::vector<size_t> Woken;
  uint32_t RetryStamp = 0;
  std::vector<uint64_t> Touched;
  uint64_t Clock = 1;
  std::vector<int32_t> Labels;      // per triangle id: seed label
  pcs::DisjointSets<int32_t> LabelSets; // union-find over the seed labels
  std::vector<char> LabelReversed;  // per root label: its part was reversed once already
  std::vector<char> SeedFailed;
  size_t SeedCursor = 0;
  Id UsedVertices = 0;
  double MeanSpacing = -1.0; // mean nearest-neighbour distance, computed when first needed
  int64_t Work = 0;

  // Scratch.
  // Per point, together (one cache line read): its projection in the current frame (P, valid
  // when Frame is the current one) and its mark (set when Mark is MarkStamp).
  struct PointScratch
  {
    double P[2] = { 0.0, 0.0 };
    uint32_t Frame = 0;
    uint32_t Mark = 0;
  };
  std::vector<PointScratch> Scratch;
  uint32_t MarkStamp = 0;
  uint32_t Frame = 0;
  double Origin[3] = { 0, 0, 0 }, U[3] = { 1, 0, 0 }, V[3] = { 0, 1, 0 }, W[3] = { 0, 0, 1 };
  std::vector<Id> Near;     // neighbourhood vertices (not interior)
  std::vector<Id> Centers;  // vertices whose K-neighbourhood is in Near
  std::vector<Id> Blockers; // points that no new triangle may cover
  // The blocking points of a triangle (b, a, c) expanding the front edge a->b: Blockers less
  // those strictly on the near side of a->b in the frame (in the closed triangle, a point must
  // lie on the far side of b->a or on its line: Orient2D is exact, so never wrongly left out).
  std::vector<Id> EdgeBlockers;
  std::vector<std::pair<Id, Id>> FrontEdges;
  bool FrontEdgesReady = false; // FrontEdges is collected when first needed
  // The points of Near strictly on the far side of the edge expanded (Expand's candidates).
  std::vector<Id> FarSide;
  std::vector<Id> Admissible;
  std::vector<uint8_t> AdmissibleTier; // 0: bends by at most half of constraint 1, else 1
};

//------------------------------------------------------------------------------------------------
void Grower::SetFrame(const double* origin, const double* u, const double* w)
{
  ++this->Frame;
  if (this->Frame == 0) // wrapped around: forget every cached projection
  {
    for (PointScratch& scratch : this->Scratch)
    {
      scratch.Frame = 0;
    }
    this->Frame = 1;
  }
  this->Origin[0] = origin[0];
  this->Origin[1] = origin[1];
  this->Origin[2] = origin[2];
  // W = w normalized; U = u made orthogonal to W, normalized; V = W x U.
  double length = std::sqrt(Dot(w, w));
  for (int i = 0; i < 3; ++i)
  {
    this->W[i] = w[i] / length;
  }
  const double along = Dot(u, this->W);
  for (int i = 0; i < 3; ++i)
  {
    this->U[i] = u[i] - along * this->W[i];
  }
  length = std::sqrt(Dot(this->U, this->U));
  if (!(length > 0.0))
  {
    // u parallel to w: any perpendicular axis.
    const double axis[3] = { std::fabs(this->W[0]) < 0.9 ? 1.0 : 0.0,
      std::fabs(this->W[0]) < 0.9 ? 0.0 : 1.0, 0.0 };
    Cross(this->W, axis, this->U);
    length = std::sqrt(Dot(this->U, this->U));
  }
  for (int i = 0; i < 3; ++i)
  {
    this->U[i] /= length;
  }
  Cross(this->W, this->U, this->V);
}

void Grower::CollectVertices(const Id* centers, int count)
{
  if (++this->MarkStamp == 0)
  {
    for (PointScratch& scratch : this->Scratch)
    {
      scratch.Mark = 0;
    }
    this->MarkStamp = 1;
  }
  this->Centers.assign(centers, centers + count);
  // Interior points are never marked, nor in Near.
  this->Near.resize(static_cast<size_t>(count) * (this->K + 1));
  size_t size = 0;
  for (int i = 0; i < count; ++i)
  {
    size = this->AddUnmarked(centers + i, 1, size);
  }
  for (int i = 0; i < count; ++i)
  {
    size = this->AddUnmarked(this->Neighbors(centers[i]), this->K, size);
  }
  this->Near.resize(size);
  for (Id v : this->Near)
  {
    PrefetchPoint(this->X, v);
  }
}

// Writes the ids of `ids` (-1 for none) that are not interior nor marked at Near[size], ...,
// marking them, and returns the new size (Near must have room for `count` more). Branch-free:
// whether an id is kept is unpredictable (about half of a front vertex's neighbours lie behind
// the front, and the neighbourhoods of an edge's two ends overlap), so each id is written at the
// end and the size grows by one when it is kept; a mark not set is written back unchanged.
size_t Grower::AddUnmarked(const Id* ids, int count, size_t size)
{
  const uint32_t stamp = this->MarkStamp;
  Id* near = this->Near.data();
  for (int j = 0; j < count; ++j)
  {
    const Id v = ids[j];
    const uint32_t valid = static_cast<uint32_t>(v >= 0);
    const Id at = v & -static_cast<Id>(valid); // v, or 0 for none
    uint32_t& mark = this->Scratch[at].Mark;
    const uint32_t keep = valid & static_cast<uint32_t>(!this->Mesh.IsInterior(at)) &
      static_cast<uint32_t>(mark != stamp);
    mark ^= (mark ^ stamp) & (0u - keep); // stamp when kept, else unchanged
    near[size] = v;
    size += keep;
  }
  return size;
}

// The front edges at the front vertices of Near.
void Grower::CollectFrontEdges()
{
  this->FrontEdgesReady = true;
  this->FrontEdges.clear();
  for (Id v : this->Near)
  {
    this->AddFrontEdges(v);
  }
}

void Grower::AddFrontEdges(Id v)
{
  if (this->Mesh.GetVertexState(v) != pcs::SurfaceMesh::VertexState::Boundary)
  {
    return;
  }
  Id buffer[16];
  auto add = [this](Id s, Id e) { this->FrontEdges.emplace_back(s, e); };
  const int outs = std::min(this->Mesh.GetBoundaryOutVertices(v, buffer, 16), 16);
  for (int i = 0; i < outs; ++i)
  {
    add(v, buffer[i]);
  }
  const int ins = std::min(this->Mesh.GetBoundaryInVertices(v, buffer, 16), 16);
  for (int i = 0; i < ins; ++i)
  {
    if (this->Scratch[buffer[i]].Mark != this->MarkStamp || this->Mesh.IsInterior(buffer[i]))
    {
      add(buffer[i], v); // else listed as the other's out edge
    }
  }
}

// Add the K-neighbourhood of v to the current neighbourhood (once per operation): its vertices
// to Near and Blockers, their front edges to FrontEdges.
void Grower::Extend(Id v)
{
  if (std::find(this->Centers.begin(), this->Centers.end(), v) != this->Centers.end())
  {
    return;
  }
  this->Centers.push_back(v);
  const size_t first = this->Near.size();
  this->Near.resize(first + this->K);
  this->Near.resize(this->AddUnmarked(this->Neighbors(v), this->K, first));
  for (size_t i = first; i < this->Near.size(); ++i)
  {
    const Id q = this->Near[i];
    PrefetchPoint(this->X, q);
    this->Blockers.push_back(q);
    this->EdgeBlockers.push_back(q);
  }
  // (The front edges of the points added, all marked now: each edge between two of them is
  // listed once, as the out edge of its start.)
  for (size_t i = first; this->FrontEdgesReady && i < this->Near.size(); ++i)
  {
    this->AddFrontEdges(this->Near[i]);
  }
}

// q strictly inside the counter-clockwise angle from the ray apex->from to the ray apex->to.
bool Grower::InWedge(Id apex, Id from, Id to, Id q)
{
  const double* o = this->P2(apex);
  const double* f = this->P2(from);
  const double* t = this->P2(to);
  const double* x = this->P2(q);
  const int turn = P::Orient2D(o, f, t);
  if (turn > 0)
  {
    return P::Orient2D(o, f, x) > 0 && P::Orient2D(o, x, t) > 0;
  }
  return P::Orient2D(o, f, x) > 0 || P::Orient2D(o, x, t) > 0;
}

// At each vertex v of (x, y, z) that already has triangles, the new wedge (from its successor to
// its predecessor in the triangle) must lie in the free angle between v's front edges pv->v and
// v->nv, counter-clockwise from pv to nv.
bool Grower::WedgesOk(Id x, Id y, Id z)
{
  const Id t[3] = { x, y, z };
  for (int i = 0; i < 3; ++i)
  {
    const Id v = t[i], out = t[(i + 1) % 3], in = t[(i + 2) % 3];
    if (this->Mesh.IsFree(v))
    {
      continue;
    }
    // The new triangle owns v->out and in->v: it closes the gap exactly when their twins are
    // the front edges out->v and v->in (also at a vertex with two fans: a pinch repaired).
    if (this->Mesh.IsBoundaryHalfEdge(out, v) && this->Mesh.IsBoundaryHalfEdge(v, in))
    {
      continue;
    }
    Id pv, nv;
    if (this->Mesh.GetNumberOfFans(v) != 1 || this->Mesh.GetBoundaryInVertices(v, &pv, 1) != 1 ||
      this->Mesh.GetBoundaryOutVertices(v, &nv, 1) != 1)
    {
      return false;
    }
    const bool closesIn = out == pv; // the new triangle owns v->pv, twin of pv->v
    const bool closesOut = in == nv; // it owns nv->v, twin of v->nv
    if (closesOut)
    {
      if (!this->InWedge(v, pv, nv, out))
      {
        return false;
      }
    }
    else if (closesIn)
    {
      if (!this->InWedge(v, pv, nv, in))
      {
        return false;
      }
    }
    else if (!this->InWedge(v, pv, nv, out) || !this->InWedge(v, out, nv, in))
    {
      return false;
    }
  }
  return true;
}

// Closed segments pq and rs meet (exact orientations on the projected points).
bool SegmentsMeet(const double* p, const double* q, const double* r, const double* s)
{
  if (std::max(p[0], q[0]) < std::min(r[0], s[0]) || std::max(r[0], s[0]) < std::min(p[0], q[0]) ||
    std::max(p[1], q[1]) < std::min(r[1], s[1]) || std::max(r[1], s[1]) < std::min(p[1], q[1]))
  {
    return false;
  }
  const int o1 = P::Orient2D(p, q, r), o2 = P::Orient2D(p, q, s);
  if (o1 * o2 > 0)
  {
    return false;
  }
  const int o3 = P::Orient2D(r, s, p), o4 = P::Orient2D(r, s, q);
  if (o3 * o4 > 0)
  {
    return false;
  }
  // Proper crossing, touching, or collinear with overlapping boxes (i.e. overlapping).
  return true;
}

// A new edge of (x, y, z) (one that no triangle has yet) meets a front edge of the
// neighbourhood that does not share an end point with it.
bool Grower::CrossesFront(Id x, Id y, Id z)
{
  if (!this->FrontEdgesReady)
  {
    this->CollectFrontEdges();
  }
  const Id t[3] = { x, y, z };
  for (int i = 0; i < 3; ++i)
  {
    const Id s = t[i], e = t[(i + 1) % 3];
    if (this->Mesh.GetEdgeValence(s, e) > 0)
    {
      continue;
    }
    const double* ps = this->P2(s);
    const double* pe = this->P2(e);
    const double xmin = std::min(ps[0], pe[0]), xmax = std::max(ps[0], pe[0]);
    const double ymin = std::min(ps[1], pe[1]), ymax = std::max(ps[1], pe[1]);
    for (const auto& f : this->FrontEdges)
    {
      // A shared end, or boxes apart (SegmentsMeet's first test), combined without
      // short-circuits: one unpredictable branch instead of several.
      const double* pf = this->P2(f.first);
      const double* qf = this->P2(f.second);
      const bool apart = (f.first == s) | (f.first == e) | (f.second == s) | (f.second == e) |
        (std::max(pf[0], qf[0]) < xmin) | (xmax < std::min(pf[0], qf[0])) |
        (std::max(pf[1], qf[1]) < ymin) | (ymax < std::min(pf[1], qf[1]));
      if (apart)
      {
        continue;
      }
      if (SegmentsMeet(ps, pe, pf, qf) && this->FacesFrame(f.first, f.second))
      {
        return true;
      }
    }
  }
  return false;
}

// The triangle of the front edge s->e faces the frame's side (its normal makes an acute angle
// with W); a sheet facing the other way is another surface and does not conflict.
bool Grower::FacesFrame(Id s, Id e) const
{
  const Id o = this->Mesh.OppositeVertex(s, e);
  double n[3];
  return o >= 0 && UnitNormal(this->P3(s), this->P3(e), this->P3(o), n) && Dot(n, this->W) > 0.0;
}

// A blocking point lies in the closed projected triangle (x, y, z) (counter-clockwise). Points
// of another sheet (farther from the triangle's mean height than its longest edge) do not block,
// nor, when `apex` is given, a point exactly over a vertex (OffPlaneAtVertex).
bool Grower::Blocked(Id x, Id y, Id z, const std::vector<Id>& blockers, Id apex)
{
  const double* a = this->P2(x);
  const double* b = this->P2(y);
  const double* c = this->P2(z);
  const double xmin = std::min({ a[0], b[0], c[0] }), xmax = std::max({ a[0], b[0], c[0] });
  const double ymin = std::min({ a[1], b[1], c[1] }), ymax = std::max({ a[1], b[1], c[1] });
  // Points of another sheet (farther from the triangle's mean height than its longest edge)
  // do not block.
  const double level = (this->Height(x) + this->Height(y) + this->Height(z)) / 3.0;
  const double reach = std::sqrt(std::max({ Distance2(this->P3(x), this->P3(y)),
    Distance2(this->P3(y), this->P3(z)), Distance2(this->P3(z), this->P3(x)) }));
  int flat = -1; // (x, y, z) in the plane of the edge's triangle: unknown (-1), no (0), yes (1)
  // The tests of a point are combined without short-circuits (one branch each for the box and
  // for the triangle: their outcomes are unpredictable).
  for (Id q : blockers)
  {
    const double* p = this->P2(q);
    const bool away = (q == x) | (q == y) | (q == z) | (p[0] < xmin) | (p[0] > xmax) |
      (p[1] < ymin) | (p[1] > ymax) | (std::fabs(this->Height(q) - level) > reach);
    if (away)
    {
      continue;
    }
    const int sides[3] = { P::Orient2D(a, b, p), P::Orient2D(b, c, p), P::Orient2D(c, a, p) };
    if ((sides[0] >= 0) & (sides[1] >= 0) & (sides[2] >= 0))
    {
      // At a vertex: on the lines of the two edges there (a point on one edge line only, or
      // inside, always blocks).
      const bool atVertex = (sides[0] != 0) + (sides[1] != 0) + (sides[2] != 0) < 2;
      if (!atVertex || apex < 0 || !this->OffPlaneAtVertex(x, y, z, apex, q, flat))
      {
        return true;
      }
    }
  }
  return false;
}

// The blocking point q projects exactly onto a vertex of (x, y, z) = (b, a, c), the expansion of
// the front edge a->b of the triangle (a, b, apex): q does not block when (b, a, c) lies in the
// plane of (a, b, apex), the frame's plane, and q off it (both exact, Orient3D). The projection
// is then along the triangle's own normal, and q lies on the normal line through the vertex:
// its foot is the vertex itself, covered by no triangle at it. Such exact ties come from points
// on a regular grid: on a box sampled on a grid per face, the points of the face beyond an edge
// project exactly onto the edge's points in the frame of a face triangle, and blocked every
// triangle with a vertex on the edge (375 of the 20,888 points of a 60 x 60 grid per face were
// left unused, 10 components instead of the 6 faces). A new triangle tilted from the frame keeps
// such a point blocking: along the frame's normal the point may lie over the triangle (without
// the plane condition, triangles across the creases of CGAL's rotor and spool vertices came
// through: accuracy maximum 1.69 -> 2.99 and 2.41 -> 3.96 mean spacings). `flat` caches the
// plane test of (b, a, c) for the current triangle (-1: not yet made).
bool Grower::OffPlaneAtVertex(Id x, Id y, Id z, Id apex, Id q, int& flat) const
{
  const double* pb = this->P3(x);
  const double* pa = this->P3(y);
  const double* py = this->P3(apex);
  if (flat < 0)
  {
    flat = P::Orient3D(pa, pb, py, this->P3(z)) == 0 ? 1 : 0;
  }
  return flat == 1 && P::Orient3D(pa, pb, py, this->P3(q)) != 0;
}

void Grower::SetStretch(const std::vector<double>& stretch)
{
  this->Stretch = stretch.data();
  this->Stretched.clear();
  for (size_t v = 0; 3 * v + 2 < stretch.size(); ++v)
  {
    const double* s = &stretch[3 * v];
    if (s[0] != 0.0 || s[1] != 0.0 || s[2] != 0.0)
    {
      this->Stretched.resize(stretch.size() / 3, 0);
      this->Stretched[v] = 1;
    }
  }
}

// The squared length of the edge (u, v) for constraint 2, `length2` its Euclidean one: on a scan
// line (stretch of u or v not zero) the component along the line is stretched by the sampling's
// anisotropy there (averaged over u and v), so that a triangle between two scan lines, whose
// edge along its line is the short one, has edges of comparable lengths. (RatioLength2 returns
// `length2` itself when neither is stretched: this formula gives it exactly then.)
double Grower::StretchedLength2(Id u, Id v, double length2) const
{
  const double* su = &this->Stretch[3 * static_cast<size_t>(u)];
  const double* sv = &this->Stretch[3 * static_cast<size_t>(v)];
  double w[3];
  Sub(this->P3(v), this->P3(u), w);
  const double alongU = Dot(w, su), alongV = Dot(w, sv);
  return length2 + 0.5 * (alongU * alongU + alongV * alongV);
}

bool Grower::EdgeRatiosOk(Id x, Id y, Id z, double minimum) const
{
  const double l0 = this->RatioLength2(x, y, Distance2(this->P3(x), this->P3(y)));
  const double l1 = this->RatioLength2(y, z, Distance2(this->P3(y), this->P3(z)));
  const double l2 = this->RatioLength2(z, x, Distance2(this->P3(z), this->P3(x)));
  const double longest = std::max({ l0, l1, l2 }), shortest = std::min({ l0, l1, l2 });
  return shortest >= minimum * minimum * longest;
}

// The factor f >= 1 that widens constraint 2 to [k1 / f, k2 f] (Euclidean lengths) for the
// expansion of the edge a-b of the triangle (a, b, y) (`ab2` its squared length): 1, unless that
// triangle is more elongated than constraint 2 allows (shortest edge below k1 times the longest,
// elongation E = longest / shortest > 1 / k1) and so is the sampling at a and b (LineAnisotropy A
// of both above 9 / 4): then f = 4/3 k1 min(E, A), the new triangle may be as elongated as the
// one across the edge and as the sampling, with a margin of 4/3, but not beyond the first
// relaxation level (f at most 2). Scan lines A = 3 to 6 times denser along than across (below 5
// to 6 the scan-line stretch of step 1 does not see them) have every triangle between two lines
// with an edge along a line A times shorter than its others: with the paper's ratios alone every
// front edge waited for the relaxed stages, and an edge across the lines skipped a line's point
// (too close to it) for the next one, leaving that point to a sliver along the line, standing
// across the surface, whose edges no front could expand (the front broke into thousands of
// pieces). A candidate admitted only by the widened bounds must lie on such lines too.
double Grower::AnisotropyFactor(Id a, Id b, Id y, double ab2) const
{
  if (!this->Par.FollowAnisotropy)
  {
    return 1.0;
  }
  const double ay2 = Distance2(this->P3(a), this->P3(y));
  const double by2 = Distance2(this->P3(b), this->P3(y));
  const double shortest2 = std::min({ ab2, ay2, by2 }), longest2 = std::max({ ab2, ay2, by2 });
  const double k1 = this->Par.MinRatio;
  if (!(shortest2 < k1 * k1 * longest2))
  {
    return 1.0;
  }
  const double rho = std::sqrt(shortest2 / longest2);
  return this->SamplingFactor(
    rho > 0.0 ? 1.0 / rho : 6.0, std::min(this->LineAnisotropy(a), this->LineAnisotropy(b)));
}

// f = 4/3 k1 min(elongation, anisotropy), within [1, 2] (see AnisotropyFactor).
double Grower::SamplingFactor(double elongation, double anisotropy) const
{
  const double k1 = this->Par.MinRatio;
  return std::min(2.0, std::max(1.0, (4.0 / 3.0) * k1 * std::min(elongation, anisotropy)));
}

// The scan-line anisotropy at v: PointAnisotropy of v, and when it is above 9/4 (SamplingFactor
// would widen), at most that of its nearest point off its line: lines next to lines, a scan's
// pattern. A lone dense row among scattered points (an arc, a feature curve of a mesh) is not
// one: there the widening left more boundary edges (arc spheres of
// Benchmarks/run_arc_spheres.py, LOG: 721 -> 945 over 40 clouds with v alone).
double Grower::LineAnisotropy(Id v) const
{
  Id off = -1;
  const double own = this->PointAnisotropy(v, off);
  if (this->SamplingFactor(6.0, own) == 1.0 || off < 0)
  {
    return own;
  }
  Id unused = -1;
  const double across = std::min(own, this->PointAnisotropy(off, unused));
  // The pattern of the region, not of a close pair: at least half of v's K nearest are on lines
  // too (as pcs::AddOffLineNeighbors' minimumShare).
  const Id* nb = this->Neighbors(v);
  int onLines = 0, count = 0;
  for (int j = 0; j < this->K && nb[j] >= 0; ++j, ++count)
  {
    onLines += this->SamplingFactor(6.0, this->PointAnisotropy(nb[j], unused)) > 1.0 ? 1 : 0;
  }
  return 2 * onLines >= count ? across : 1.0;
}

// The sampling's anisotropy at v: the distance to its nearest neighbour off the line through v and
// its nearest neighbour (more than 45 degrees from it; `off` gets it, else -1), over the distance
// to that nearest neighbour; when every neighbour is on that line, the farthest's distance.
double Grower::PointAnisotropy(Id v, Id& off) const
{
  if (this->AnisotropyCache.empty())
  {
    this->AnisotropyCache.assign(static_cast<size_t>(this->N), std::make_pair(-1.0f, Id(-1)));
  }
  auto& cached = this->AnisotropyCache[v];
  if (cached.first < 0.0f)
  {
    cached.first = static_cast<float>(this->ComputePointAnisotropy(v, cached.second));
  }
  off = cached.second;
  return cached.first;
}

double Grower::ComputePointAnisotropy(Id v, Id& off) const
{
  off = -1;
  const Id* nb = this->Neighbors(v);
  if (nb[0] < 0)
  {
    return 1.0;
  }
  double e[3];
  Sub(this->P3(nb[0]), this->P3(v), e);
  const double nearest2 = Dot(e, e);
  double w2 = nearest2;
  for (int j = 1; j < this->K && nb[j] >= 0; ++j)
  {
    double w[3], c[3];
    Sub(this->P3(nb[j]), this->P3(v), w);
    Cross(w, e, c);
    const double along = Dot(w, e);
    w2 = Dot(w, w);
    if (Dot(c, c) > along * along)
    {
      off = nb[j];
      break;
    }
  }
  return nearest2 > 0.0 ? std::sqrt(w2 / nearest2) : 1.0;
}

void Grower::DecideAnisotropy(bool allowed)
{
  this->Par.FollowAnisotropy = false;
  if (!allowed || this->N < 3)
  {
    return;
  }
  Id sampled = 0, onLines = 0;
  for (Id v = 0; v < this->N; v += 8, ++sampled)
  {
    onLines += this->SamplingFactor(6.0, this->LineAnisotropy(v)) > 1.0 ? 1 : 0;
  }
  this->Par.FollowAnisotropy = 3 * onLines >= sampled;
}

//------------------------------------------------------------------------------------------------
int64_t Grower::Commit(Id x, Id y, Id z)
{
  const Id t[3] = { x, y, z };
  Id fresh = 0;
  for (Id v : t)
  {
    fresh += this->Mesh.IsFree(v) ? 1 : 0;
  }
  const int64_t id = this->Mesh.AddTriangle(x, y, z);
  if (id >= 0)
  {
    this->UsedVertices += fresh;
    this->Register(id);
  }
  return id;
}

// Bookkeeping of a triangle already in the mesh: neighbourhood clock, seed label (merged with
// the labels of the triangles across its edges), and its front edges into the queue.
void Grower::Register(int64_t t)
{
  const int32_t* v = this->Mesh.GetTriangle(t);
  ++this->Clock;
  int32_t label = -1;
  for (int j = 0; j < 3; ++j)
  {
    this->Touch(v[j]);
    const int32_t other = this->TriangleLabel(this->Mesh.FindTriangle(v[(j + 1) % 3], v[j]));
    if (other < 0)
    {
      continue;
    }
    if (label < 0)
    {
      label = other;
    }
    else if (other != label)
    {
      const char reversed = this->LabelReversed[label] | this->LabelReversed[other];
      label = this->LabelSets.Link(label, other);
      this->LabelReversed[label] = reversed;
    }
  }
  if (label < 0)
  {
    label = this->LabelSets.Add();
    this->LabelReversed.push_back(0);
  }
  if (static_cast<int64_t>(this->Labels.size()) <= t)
  {
    this->Labels.resize(static_cast<size_t>(t) + 1, -1);
  }
  this->Labels[t] = label;
  for (int j = 0; j < 3; ++j)
  {
    if (this->Mesh.IsBoundaryHalfEdge(v[j], v[(j + 1) % 3]))
    {
      this->Queue.push_back({ v[j], v[(j + 1) % 3], 0 });
    }
  }
}

//------------------------------------------------------------------------------------------------
// The ear (v, u, w) that closes the front angle u->v->w, in the current frame with the current
// neighbourhood: constraint 1 towards every triangle it shares an edge with, constraint 2
// relaxed (every edge at least MinRatio / 2 of the longest), the topology and the projected
// tests. Returns the smallest cosine of constraint 1, or -2 when the ear is not valid.
double Grower::EarScore(Id v, Id u, Id w, double cosNormal, double minimumRatio)
{
  if (this->Mesh.CanAddTriangle(v, u, w) != pcs::SurfaceMesh::Check::Ok ||
    pcs::projected::Collinear(this->P3(v), this->P3(u), this->P3(w)) ||
    !this->EdgeRatiosOk(v, u, w, minimumRatio))
  {
    return -2.0;
  }
  double n[3];
  if (!UnitNormal(this->P3(v), this->P3(u), this->P3(w), n))
  {
    return -2.0;
  }
  double worst = 2.0;
  const Id t[3] = { v, u, w };
  for (int j = 0; j < 3; ++j)
  {
    // The ear owns t[j]->t[j+1]; its twin's triangle is a neighbour.
    const Id s = t[(j + 1) % 3], e = t[j];
    const Id o = this->Mesh.OppositeVertex(s, e);
    if (o < 0)
    {
      continue;
    }
    double m[3];
    if (!UnitNormal(this->P3(s), this->P3(e), this->P3(o), m))
    {
      return -2.0;
    }
    worst = std::min(worst, Dot(n, m));
  }
  if (worst < cosNormal || !this->ProjectedValid(v, u, w))
  {
    return -2.0;
  }
  return worst;
}

//------------------------------------------------------------------------------------------------
// The free point c, a candidate for the expansion of the front edge a->b that only the last
// level's needle rule admits, lies on another sheet, one the front has not reached: it stands more
// than 1.5 local spacings (the mean of a's and b's) off the frame's plane, and none of its K
// nearest at its own level (less than half its height from it along the frame's normal) has a
// triangle. The needle rule takes such a point for one close to the edge -- it lies almost below
// it -- and its triangle stood across the gap between two sheets a few spacings apart (concentric
// spheres 2.8 mean spacings apart were joined into one surface); the other sheet gets its own
// seed instead. The points of a thin tip or a sharply bent spot that the rule is for have meshed
// neighbours at their level, or lie within 1.5 spacings of the frame (Benchmarks/results/
// local_optimum.md, task logsharp).
bool Grower::OnUnreachedSheet(Id c, Id a, Id b) const
{
  const double height = this->Height(c);
  if (!this->Mesh.IsFree(c) ||
    std::fabs(height) <= 0.75 * (this->LocalSpacing(a) + this->LocalSpacing(b)))
  {
    return false;
  }
  const Id* nb = this->Neighbors(c);
  for (int j = 0; j < this->K && nb[j] >= 0; ++j)
  {
    if (std::fabs(this->Height(nb[j]) - height) < 0.5 * std::fabs(height) &&
      !this->Mesh.IsFree(nb[j]))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------------------------
// The local spacing of v: the mean distance to its 6 nearest neighbours (fewer when K < 6).
double Grower::LocalSpacing(Id v) const
{
  const Id* nb = this->Neighbors(v);
  double sum = 0.0;
  int count = 0;
  for (int j = 0; j < std::min(6, this->K) && nb[j] >= 0; ++j)
  {
    sum += std::sqrt(Distance2(this->P3(v), this->P3(nb[j])));
    ++count;
  }
  return count > 0 ? sum / count : 0.0;
}

// The new edge u-w of an ear (apex between u and w on the front) that exceeds constraint 3, at
// the last relaxation level, is already a front edge (the ear closes a front loop of three
// edges), or at most WideEarSpacings local spacings long (the mean of its ends'), or the thin
// sliver of unmeshed surface that justifies such ears is there: a candidate of the current
// expansion (FarSide) lies strictly across u-w from the apex (in the frame) and inside the sphere
// on u-w as diameter (the other front). On an open border (a scan's edge) nothing lies beyond
// the front, and such ears, each new edge up to 2 MaximumEdgeRatio times the one it expands, cut
// ever longer chords across the border: a lid over a hemisphere's opening, edges of 30 h.
bool Grower::WideEarFits(Id u, Id w, Id apex)
{
  constexpr double WideEarSpacings = 3.0;
  if (this->Mesh.IsBoundaryHalfEdge(w, u))
  {
    return true;
  }
  const double bound = WideEarSpacings * 0.5 * (this->LocalSpacing(u) + this->LocalSpacing(w));
  if (Distance2(this->P3(u), this->P3(w)) <= bound * bound)
  {
    return true;
  }
  const double* u2 = this->P2(u);
  const double* w2 = this->P2(w);
  const int apexSide = P::Orient2D(u2, w2, this->P2(apex));
  for (Id q : this->FarSide)
  {
    if (q == u || q == w || P::Orient2D(u2, w2, this->P2(q)) != -apexSide)
    {
      continue;
    }
    double qu[3], qw[3];
    Sub(this->P3(u), this->P3(q), qu);
    Sub(this->P3(w), this->P3(q), qw);
    if (Dot(qu, qw) < 0.0)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------------------------
// Expansion of the front edge a->b (triangle (a, b, y)) by the triangle (b, a, c).
// Stages (RelaxConstraints on): 0, only the candidates whose triangle bends by at most half of
// constraint 1; 1, every candidate, the paper's constraints; 2 and 3, constraint 2 relaxed
// (relaxation levels 1 and 2). Without RelaxConstraints only stage 0 is used, with every
// candidate.
bool Grower::Expand(Id a, Id b, int stage, bool mayReverse)
{
  const bool flatOnly = this->Par.Relax && stage == 0;
  const int level = this->Par.Relax ? std::max(0, stage - 1) : 0;
  const Id y = this->Mesh.OppositeVertex(a, b);
  double ne[3];
  if (y < 0 || !UnitNormal(this->P3(a), this->P3(b), this->P3(y), ne))
  {
    return false;
  }
  double mid[3], ab[3];
  for (int i = 0; i < 3; ++i)
  {
    mid[i] = 0.5 * (this->P3(a)[i] + this->P3(b)[i]);
  }
  Sub(this->P3(b), this->P3(a), ab);
  this->SetFrame(mid, ab, ne);
  const Id n = this->Mesh.NextBoundaryVertex(a, b);
  const Id p = this->Mesh.PreviousBoundaryVertex(a, b);
  const Id centers[2] = { a, b };
  this->CollectVertices(centers, 2);
  for (Id v : { n, p })
  {
    if (v >= 0 && this->Scratch[v].Mark != this->MarkStamp && !this->Mesh.IsInterior(v))
    {
      this->Scratch[v].Mark = this->MarkStamp;
      this->Near.push_back(v);
    }
  }
  this->FrontEdgesReady = false;

  // Candidates on the far side of the edge, on this sheet (constraint 1), not interior; the
  // admissible ones also meet constraints 2 and 3.
  const double d2 = Dot(ab, ab);
  const double dab = std::sqrt(d2);
  const double rd2 = this->RatioLength2(a, b, d2);
  const double minimum =
    level == 0 ? this->Par.MinRatio : (level == 1 ? 0.5 * this->Par.MinRatio : 0.0);
  const double maximum = level == 0 ? this->Par.MaxRatio : 2.0 * this->Par.MaxRatio;
  // On an anisotropic sampling the Euclidean lengths may also meet the bounds widened by the
  // elongation of the triangle across the edge (AnisotropyFactor).
  const double widen = this->AnisotropyFactor(a, b, y, d2);
  const double wideMinimum = std::min(minimum, this->Par.MinRatio / widen);
  const double wideMaximum = std::max(maximum, widen * this->Par.MaxRatio);
  const double* a2 = this->P2(a);
  const double* b2 = this->P2(b);
  this->Admissible.clear();
  this->AdmissibleTier.clear();
  // Blockers: Near less a, b and y; EdgeBlockers: those not strictly on the far side of a->b;
  // FarSide: those strictly on it, the candidates. Filed without a branch on the side
  // (unpredictable): each point is written at the end of both lists, one of which grows.
  this->Blockers.resize(this->Near.size());
  this->EdgeBlockers.resize(this->Near.size());
  this->FarSide.resize(this->Near.size());
  size_t blockers = 0, edgeBlockers = 0, farSide = 0;
  for (Id c : this->Near)
  {
    if (c == a || c == b || c == y)
    {
      continue;
    }
    this->Blockers[blockers++] = c;
    const int side = P::Orient2D(a2, b2, this->P2(c));
    this->EdgeBlockers[edgeBlockers] = c;
    this->FarSide[farSide] = c;
    edgeBlockers += static_cast<size_t>(side <= 0);
    farSide += static_cast<size_t>(side < 0);
  }
  this->Blockers.resize(blockers);
  this->EdgeBlockers.resize(edgeBlockers);
  this->FarSide.resize(farSide);
  for (Id c : this->FarSide)
  {
    // Constraint 2 (an ear has no lower bound: it closes an angle of the front) and
    // constraint 3: the angles at a and b.
    double ac[3], bc[3];
    Sub(this->P3(c), this->P3(a), ac);
    Sub(this->P3(c), this->P3(b), bc);
    const double la2 = Dot(ac, ac), lb2 = Dot(bc, bc);
    const double ra2 = this->RatioLength2(a, c, la2), rb2 = this->RatioLength2(b, c, lb2);
    const bool ear = c == n || c == p;
    auto within = [ear](double l1, double l2, double base2, double lower, double upper)
    {
      return (ear || (l1 >= lower * lower * base2 && l2 >= lower * lower * base2)) &&
        l1 <= upper * upper * base2 && l2 <= upper * upper * base2;
    };
    if (!within(ra2, rb2, rd2, minimum, maximum) &&
      !(widen > 1.0 && within(la2, lb2, d2, wideMinimum, wideMaximum) &&
        this->SamplingFactor(6.0, this->LineAnisotropy(c)) > 1.0))
    {
      continue;
    }
    // Constraint 3. At the last relaxation level an ear may exceed it: its angle at the shared
    // end is the front's own angle there, which a thin sliver of unmeshed surface (two fronts
    // meeting almost along a line) has close to 180 degrees at every vertex. Such an ear must
    // then meet constraint 1 strictly towards both triangles it closes between, and its new
    // edge must be short or span a sliver (WideEarFits).
    const double dotA = Dot(ab, ac), dotB = -Dot(ab, bc);
    const bool wideBase =
      WiderThan(dotA, this->Par.CosBase, dab, la2) || WiderThan(dotB, this->Par.CosBase, dab, lb2);
    if (wideBase &&
      (!ear || level < 2 || !this->WideEarFits(c == n ? a : p, c == n ? n : b, c == n ? b : a)))
    {
      continue;
    }
    // Constraint 1: the angle between the normals of (b, a, c) and (a, b, y).
    if (!wideBase &&
      ClearlyWithin(this->P3(b), this->P3(a), this->P3(c), ne, this->Par.CosHalfNormal))
    {
      // Flat (tier 0), hence within constraint 1 too: decided without normalizing (same answer).
      this->Admissible.push_back(c);
      this->AdmissibleTier.push_back(0);
      this->PrefetchNeighbors(c); // read by Extend if c is tested
      continue;
    }
    double nt[3];
    if (!UnitNormal(this->P3(b), this->P3(a), this->P3(c), nt))
    {
      continue;
    }
    if (wideBase)
    {
      // The other triangle: across the front edge b->n (c == n) or p->a (c == p).
      const Id s = c == n ? b : p, e = c == n ? n : a;
      const Id o = this->Mesh.OppositeVertex(s, e);
      double no[3];
      if (Dot(nt, ne) < this->Par.CosNormal || o < 0 ||
        !UnitNormal(this->P3(s), this->P3(e), this->P3(o), no) || Dot(nt, no) < this->Par.CosNormal)
      {
        continue;
      }
    }
    else if (Dot(nt, ne) < this->Par.CosNormal)
    {
      // Constraint 1 measures how far (b, a, c) bends about the edge: |height| / distance to the
      // edge's line. At the last level the distance is taken at least d / 2, so that a point
      // close to the edge (a needle, whose normal is dominated by the curvature) stays usable,
      // unless that point lies on another sheet, one the front has not reached (ours).
      const double offset = std::max(-this->P2(c)[1], 0.5 * dab);
      const double height = std::fabs(this->Height(c));
      if (level < 2 || height > this->Par.TanNormal * offset ||
        (this->Par.SeparateSheets && height > -this->Par.TanNormal * this->P2(c)[1] &&
          this->OnUnreachedSheet(c, a, b)))
      {
        continue;
      }
    }
    const uint8_t tier = Dot(nt, ne) >= this->Par.CosHalfNormal ? 0 : 1;
    if (flatOnly && tier != 0)
    {
      continue;
    }
    this->Admissible.push_back(c);
    this->AdmissibleTier.push_back(tier);
    this->PrefetchNeighbors(c); // read by Extend if c is tested
  }

  while (!this->Admissible.empty())
  {
    // The local optimum: no other admissible candidate inside the circle through b, a, c,
    // among the candidates of the lowest tier left (tier 0: bending by at most half of
    // constraint 1).
    size_t best = 0;
    for (size_t i = 1; i < this->Admissible.size(); ++i)
    {
      if (this->AdmissibleTier[i] != this->AdmissibleTier[best])
      {
        if (this->AdmissibleTier[i] < this->AdmissibleTier[best])
        {
          best = i;
        }
        continue;
      }
      const Id c = this->Admissible[best], q = this->Admissible[i];
      const int inside = P::InCircle(b2, a2, this->P2(c), this->P2(q));
      if (inside > 0)
      {
        best = i;
      }
      else if (inside == 0)
      {
        const double sc = std::sqrt(Distance2(this->P3(a), this->P3(c))) +
          std::sqrt(Distance2(this->P3(b), this->P3(c)));
        const double sq = std::sqrt(Distance2(this->P3(a), this->P3(q))) +
          std::sqrt(Distance2(this->P3(b), this->P3(q)));
        if (sq < sc || (sq == sc && q < c))
        {
          best = i;
        }
      }
    }
    const Id c = this->Admissible[best];
    this->Admissible[best] = this->Admissible.back();
    this->Admissible.pop_back();
    this->AdmissibleTier[best] = this->AdmissibleTier.back();
    this->AdmissibleTier.pop_back();

    if (pcs::projected::Collinear(this->P3(a), this->P3(b), this->P3(c)))
    {
      continue;
    }
    Id offending = -1;
    const pcs::SurfaceMesh::Check check = this->Mesh.CanAddTriangle(b, a, c, &offending);
    if (check == pcs::SurfaceMesh::Check::Ok)
    {
      // A free point or an ear: a point exactly over a vertex is decided in space (y). A bridge
      // below does not pass y: there such ties keep blocking (with them, bridges along the
      // creases of CGAL's rotor vertices, a CAD part, left 170 -> 209 boundary edges).
      if (this->ProjectedValid(b, a, c, true, y))
      {
        this->Commit(b, a, c);
        return true;
      }
      continue;
    }
    if (check != pcs::SurfaceMesh::Check::NonManifoldVertex || offending != c ||
      this->Mesh.GetNumberOfFans(c) != 1)
    {
      continue;
    }
    // c is a front vertex away from a and b: a bridge between two parts of the front.
    Id pc = -1, nc = -1;
    if (this->Mesh.GetBoundaryInVertices(c, &pc, 1) != 1 ||
      this->Mesh.GetBoundaryOutVertices(c, &nc, 1) != 1)
    {
      continue;
    }
    const Id oc = this->Mesh.OppositeVertex(c, nc);
    double nc3[3];
    if (oc < 0 || !UnitNormal(this->P3(c), this->P3(nc), this->P3(oc), nc3))
    {
      continue;
    }
    if (Dot(nc3, ne) <= 0.0)
    {
      // The other part faces the other way. When it was grown from another seed, reverse it
      // and expand this edge again; within one part this is a fold, refused.
      const int64_t tc = this->Mesh.FindTriangle(c, nc);
      const int64_t tab = this->Mesh.FindTriangle(a, b);
      const int32_t labelC = this->TriangleLabel(tc);
      if (mayReverse && labelC != this->TriangleLabel(tab) && !this->LabelReversed[labelC])
      {
        // Once per part: two parts that face each other for good (the two sides of a thin
        // feature) would otherwise reverse each other in turn.
        this->LabelReversed[labelC] = 1;
        this->Mesh.ReverseComponent(tc);
        // The reversed part's front edges now run the other way: queue them again lazily.
        const int32_t* tri = this->Mesh.GetTriangle(tc);
        for (int j = 0; j < 3; ++j)
        {
          this->Queue.push_back({ tri[j], tri[(j + 1) % 3], 0 });
        }
        return this->Expand(a, b, stage, false);
      }
      continue;
    }
    if (!this->ProjectedValid(b, a, c, true))
    {
      continue;
    }
    // A bridge between two different front loops of one part adds a handle. That is how the
    // front closes around a torus's tube, but after the first stage it is refused: there it came
    // only from near-contacts of the front with itself, folding the mesh over (a handle on
    // random sphere and torus samples, and on CGAL's knot2 vertices).
    // At the first stage it is also refused when either loop is a hole (ShortLoop): a handle
    // between a hole and the rest of the front does not close around a tube, it jumps across the
    // surface (CGAL's armadillo vertices: loops of 3 and 5 edges; diplodocus: 9 and 13 edges,
    // 4.1 and 19.8 mean spacings long); the hole is closed on its own (step 6). Unless both loops
    // go around a tube (pcs::holes::JoinsLoopsAroundTube, ours): a loop around a thin tube is as
    // short as a hole, and refusing the join capped the tube twice (a knot tube of 12 points
    // around came out genus 0).
    if (this->TriangleLabel(this->Mesh.FindTriangle(c, nc)) ==
        this->TriangleLabel(this->Mesh.FindTriangle(a, b)) &&
      (stage > 0 ||
        ((this->ShortLoop(a, b) || this->ShortLoop(c, nc)) &&
          !pcs::holes::JoinsLoopsAroundTube(this->Mesh, this->X, a, b, c, nc))) &&
      !this->OnFrontLoop(a, b, c))
    {
      continue;
    }
    const int64_t t1 = this->Mesh.AddTriangle(b, a, c);
    if (t1 < 0)
    {
      continue;
    }
    this->FrontEdgesReady = false;
    // The pinch at c is removed by the ear on either side: (c, a, nc) or (c, pc, b).
    const double scoreA = this->EarScore(c, a, nc, this->Par.CosNormal, 0.5 * this->Par.MinRatio);
    const double scoreB = this->EarScore(c, pc, b, this->Par.CosNormal, 0.5 * this->Par.MinRatio);
    if (std::max(scoreA, scoreB) < -1.0)
    {
      this->Mesh.RemoveTriangle(t1);
      this->FrontEdgesReady = false;
      continue;
    }
    this->Register(t1);
    if (scoreA >= scoreB)
    {
      this->Commit(c, a, nc);
    }
    else
    {
      this->Commit(c, pc, b);
    }
    return true;
  }
  return false;
}

//------------------------------------------------------------------------------------------------
// c is a vertex of the front loop through the front edge a->b (walked once around).
bool Grower::OnFrontLoop(Id a, Id b, Id c) const
{
  Id s = a, e = b;
  const int64_t limit = 3 * this->Mesh.GetNumberOfTriangleIds() + 3;
  for (int64_t steps = 0; steps <= limit; ++steps)
  {
    if (e == c || s == c)
    {
      return true;
    }
    const Id next = this->Mesh.NextBoundaryVertex(s, e);
    s = e;
    e = next;
    if (e < 0 || (s == a && e == b))
    {
      return false;
    }
  }
  return false;
}

//------------------------------------------------------------------------------------------------
// The front loop through the front edge a->b is a hole: it has at most max(3, MaximumHoleEdges)
// edges, or a perimeter below 2 pi times 2 mean spacings (the loop around a tube of radius below
// 2 spacings, which step 6 cannot tell from a sampling gap either).
bool Grower::ShortLoop(Id a, Id b)
{
  return pcs::holes::IsShortLoop(this->Mesh, this->X, a, b, std::max(3, this->Par.MaxHoleEdges),
    4.0 * vtkMath::Pi() * this->CloudSpacing());
}

// The cloud's mean nearest-neighbour distance (computed once).
double Grower::CloudSpacing()
{
  if (this->MeanSpacing < 0.0)
  {
    double sum = 0.0;
    int64_t count = 0;
    for (Id v = 0; v < this->N; ++v)
    {
      const Id nearest = this->Neighbors(v)[0];
      if (nearest >= 0)
      {
        sum += std::sqrt(Distance2(this->P3(v), this->P3(nearest)));
        ++count;
      }
    }
    this->MeanSpacing = count > 0 ? sum / static_cast<double>(count) : 0.0;
  }
  return this->MeanSpacing;
}

//------------------------------------------------------------------------------------------------
// Seed (paper, step 1): P1 the extreme point, P2 its nearest unused neighbour, P3 minimizing
// |P1P3| + |P2P3| under constraints 2 and 3; the next neighbour as P2 when no P3 exists.
// With SeparateSheets (ours), P2 is at most SeedReach times as far from P1 as P1's nearest
// neighbour (used or not; lengths of constraint 2, RatioLength2): a point left unused among
// meshed neighbours has its nearest free ones on another sheet, and its seed triangle stood
// across the gap between two sheets a few spacings apart (concentric spheres 2.8 mean spacings
// apart: one seed of six; task logsharp). Such a point is left to the orphan insertion (step 5).
bool Grower::TrySeed(Id p1, bool relaxed)
{
  const double strictMinimum = relaxed ? 0.5 * this->Par.MinRatio : this->Par.MinRatio;
  const double strictMaximum = relaxed ? 2.0 * this->Par.MaxRatio : this->Par.MaxRatio;
  const Id* nb = this->Neighbors(p1);
  bool firstFree = true;
  for (int j = 0; j < this->K; ++j)
  {
    const Id p2 = nb[j];
    if (p2 < 0)
    {
      break;
    }
    if (!this->Mesh.IsFree(p2))
    {
      continue;
    }
    const double* x1 = this->P3(p1);
    const double* x2 = this->P3(p2);
    double e[3];
    Sub(x2, x1, e);
    const double d2 = Dot(e, e), d = std::sqrt(d2);
    const double rd2 = this->RatioLength2(p1, p2, d2);
    if (this->Par.SeparateSheets && j > 0 &&
      rd2 > SeedReach * SeedReach * this->RatioLength2(p1, nb[0], Distance2(x1, this->P3(nb[0]))))
    {
      continue;
    }
    // With the nearest free neighbour as P2, constraint 2 widened by the sampling's anisotropy
    // at P1 and P2 (SamplingFactor): on scan lines 3 to 6 times denser along than across, that
    // neighbour, on P1's line, has no P3 within [k1 d, k2 d] (the next line is A d away), and the
    // farther P2 along the line made a seed over a line's point (a sliver, or an edge skipping
    // it) from which no front grew.
    const double widen = this->Par.FollowAnisotropy && firstFree
      ? this->SamplingFactor(this->LineAnisotropy(p1), this->LineAnisotropy(p2))
      : 1.0;
    firstFree = false;
    const double minimum = std::min(strictMinimum, this->Par.MinRatio / widen);
    const double maximum = std::max(strictMaximum, widen * this->Par.MaxRatio);
    const Id centers[2] = { p1, p2 };
    this->CollectVertices(centers, 2);
    Id best = -1;
    double bestScore = std::numeric_limits<double>::infinity();
    for (Id q : this->Near)
    {
      if (q == p1 || q == p2 || !this->Mesh.IsFree(q))
      {
        continue;
      }
      double e1[3], e2[3];
      Sub(this->P3(q), x1, e1);
      Sub(this->P3(q), x2, e2);
      const double l1 = Dot(e1, e1), l2 = Dot(e2, e2);
      const double r1 = this->RatioLength2(p1, q, l1), r2 = this->RatioLength2(p2, q, l2);
      if (r1 < minimum * minimum * rd2 || r2 < minimum * minimum * rd2 ||
        r1 > maximum * maximum * rd2 || r2 > maximum * maximum * rd2 ||
        Dot(e, e1) < this->Par.CosBase * d * std::sqrt(l1) ||
        -Dot(e, e2) < this->Par.CosBase * d * std::sqrt(l2))
      {
        continue;
      }
      const double score = std::sqrt(r1) + std::sqrt(r2);
      if ((score < bestScore || (score == bestScore && q < best)) &&
        !pcs::projected::Collinear(x1, x2, this->P3(q)))
      {
        best = q;
        bestScore = score;
      }
    }
    if (best < 0)
    {
      continue;
    }
    // Orientation: the normal's x component positive (then y, then z), decided exactly.
    const double* x3 = this->P3(best);
    int sign = 0;
    const int planes[3][2] = { { 1, 2 }, { 2, 0 }, { 0, 1 } };
    for (const auto& plane : planes)
    {
      const double q1[2] = { x1[plane[0]], x1[plane[1]] };
      const double q2[2] = { x2[plane[0]], x2[plane[1]] };
      const double q3[2] = { x3[plane[0]], x3[plane[1]] };
      sign = P::Orient2D(q1, q2, q3);
      if (sign != 0)
      {
        break;
      }
    }
    if (sign >= 0)
    {
      this->Commit(p1, p2, best);
    }
    else
    {
      this->Commit(p1, best, p2);
    }
    ++this->Seeds;
    return true;
  }
  return false;
}

bool Grower::PlantSeed()
{
  for (; this->SeedCursor < this->SeedOrder.size(); ++this->SeedCursor)
  {
    const Id p1 = this->SeedOrder[this->SeedCursor];
    if (!this->Mesh.IsFree(p1) || this->SeedFailed[p1])
    {
      continue;
    }
    if (this->TrySeed(p1, false) || (this->Par.Relax && this->TrySeed(p1, true)))
    {
      return true;
    }
    this->SeedFailed[p1] = 1;
  }
  return false;
}

//------------------------------------------------------------------------------------------------
void Grower::ReportProgress()
{
  if ((++this->Work & 1023) == 0)
  {
    this->Algorithm->UpdateProgress(this->ProgressBegin +
      (this->ProgressEnd - this->ProgressBegin) * this->UsedVertices /
        std::max<double>(this->N, 1));
    this->Aborted = this->Algorithm->GetAbortExecute() != 0;
  }
}

void Grower::ProcessQueue()
{
  while (this->QueueHead < this->Queue.size() && !this->Aborted)
  {
    const Item item = this->Queue[this->QueueHead++];
    if (this->QueueHead < this->Queue.size())
    {
      // The next edge's neighbourhood is collected right after this one's expansion.
      this->PrefetchNeighbors(this->Queue[this->QueueHead].A);
      this->PrefetchNeighbors(this->Queue[this->QueueHead].B);
    }
    if (this->QueueHead >= (size_t(1) << 16) && 2 * this->QueueHead >= this->Queue.size())
    {
      this->Queue.erase(this->Queue.begin(), this->Queue.begin() + this->QueueHead);
      this->QueueHead = 0;
    }
    Id a = item.A, b = item.B;
    if (!this->Mesh.IsBoundaryHalfEdge(a, b))
    {
      // Stale, unless its part of the mesh was reversed (a twin is never a front edge too).
      if (!this->Mesh.IsBoundaryHalfEdge(b, a))
      {
        continue;
      }
      std::swap(a, b);
    }
    this->ReportProgress();
    if (!this->Expand(a, b, item.Level))
    {
      this->Defer(a, b, item.Level);
    }
  }
}

bool Grower::Changed(const Deferred& d) const
{
  for (Id v : { d.A, d.B })
  {
    if (this->Touched[v] > d.Clock)
    {
      return true;
    }
    const Id* nb = this->Neighbors(v);
    for (int j = 0; j < this->K; ++j)
    {
      if (nb[j] >= 0 && this->Touched[nb[j]] > d.Clock)
      {
        return true;
      }
    }
  }
  return false;
}

void Grower::Defer(Id a, Id b, uint8_t level)
{
  this->DeferredEdges.push_back({ a, b, this->Clock, { -1, -1 }, level, true, this->RetryStamp });
  if (this->DeferredIndexed)
  {
    this->LinkEnds(this->DeferredEdges.size() - 1);
  }
}

void Grower::LinkEnds(size_t entry)
{
  Deferred& d = this->DeferredEdges[entry];
  for (int end = 0; end < 2; ++end)
  {
    const Id v = end == 0 ? d.A : d.B;
    d.Next[end] = this->EdgesAt[v];
    this->EdgesAt[v] = static_cast<int64_t>(entry);
  }
}

void Grower::BuildDeferredIndex()
{
  this->ReverseStart.assign(static_cast<size_t>(this->N) + 1, 0);
  for (Id nb : this->Knn)
  {
    if (nb >= 0)
    {
      ++this->ReverseStart[static_cast<size_t>(nb) + 1];
    }
  }
  std::partial_sum(
    this->ReverseStart.begin(), this->ReverseStart.end(), this->ReverseStart.begin());
  this->ReverseKnn.resize(static_cast<size_t>(this->ReverseStart.back()));
  std::vector<int64_t> fill(this->ReverseStart.begin(), this->ReverseStart.end() - 1);
  for (Id v = 0; v < this->N; ++v)
  {
    const Id* nb = this->Neighbors(v);
    for (int j = 0; j < this->K; ++j)
    {
      if (nb[j] >= 0)
      {
        this->ReverseKnn[fill[nb[j]]++] = v;
      }
    }
  }
  this->EdgesAt.assign(this->N, -1);
  for (size_t entry = 0; entry < this->DeferredEdges.size(); ++entry)
  {
    this->LinkEnds(entry);
  }
  this->DeferredIndexed = true;
}

// Woken: the active deferred edges, in deferral order, that Changed may accept, i.e. those with
// a vertex touched since the last retry in their neighbourhood (all of them when they are not
// more than those vertices). The retired entries met in the chains are unlinked.
void Grower::CollectWoken()
{
  ++this->RetryStamp;
  this->Woken.clear();
  const size_t active = this->DeferredEdges.size() - this->RetiredEdges;
  if (active <= this->TouchedSinceRetry.size())
  {
    for (size_t entry = 0; entry < this->DeferredEdges.size(); ++entry)
    {
      if (this->DeferredEdges[entry].Active)
      {
        this->Woken.push_back(entry);
      }
    }
  }
  else
  {
    if (!this->DeferredIndexed)
    {
      this->BuildDeferredIndex();
    }
    auto collectAt = [this](Id v) {
      int64_t* link = &this->EdgesAt[v];
      while (*link >= 0)
      {
        Deferred& d = this->DeferredEdges[*link];
        int64_t* next = &d.Next[d.A == v ? 0 : 1];
        if (!d.Active)
        {
          *link = *next;
          continue;
        }
        if (d.Seen != this->RetryStamp)
        {
          d.Seen = this->RetryStamp;
          this->Woken.push_back(static_cast<size_t>(*link));
        }
        link = next;
      }
    };
    for (Id w : this->TouchedSinceRetry)
    {
      collectAt(w);
      for (int64_t r = this->ReverseStart[w]; r < this->ReverseStart[w + 1]; ++r)
      {
        collectAt(this->ReverseKnn[r]);
      }
    }
    std::sort(this->Woken.begin(), this->Woken.end());
  }
  for (Id w : this->TouchedSinceRetry)
  {
    this->InTouchedSinceRetry[w] = 0;
  }
  this->TouchedSinceRetry.clear();
}

// The front edge between the ends of a deferred edge, a->b (its part of the mesh may have been
// reversed since it was deferred); false when the edge is no longer on the front.
bool Grower::OnFront(const Deferred& d, Id& a, Id& b) const
{
  a = d.A;
  b = d.B;
  if (this->Mesh.IsBoundaryHalfEdge(a, b))
  {
    return true;
  }
  std::swap(a, b);
  return this->Mesh.IsBoundaryHalfEdge(a, b);
}

void Grower::Retire(size_t entry)
{
  this->DeferredEdges[entry].Active = false;
  ++this->RetiredEdges;
}

// Drops the retired entries, keeping the order of the others, and relinks the chains.
void Grower::CompactDeferred()
{
  size_t kept = 0, relaxFrom = 0;
  for (size_t entry = 0; entry < this->DeferredEdges.size(); ++entry)
  {
    const Deferred& d = this->DeferredEdges[entry];
    if (this->DeferredIndexed)
    {
      this->EdgesAt[d.A] = this->EdgesAt[d.B] = -1;
    }
    relaxFrom = entry == this->RelaxFrom ? kept : relaxFrom;
    if (d.Active)
    {
      this->DeferredEdges[kept++] = d;
    }
  }
  this->RelaxFrom = this->RelaxFrom < this->DeferredEdges.size() ? relaxFrom : kept;
  this->DeferredEdges.resize(kept);
  this->RetiredEdges = 0;
  for (size_t entry = 0; this->DeferredIndexed && entry < kept; ++entry)
  {
    this->LinkEnds(entry);
  }
}

// The front has stalled: retry the edges set aside whose neighbourhood changed since they were
// tried, in the order they were set aside; failing that, the ones never tried with relaxed
// constraints. An edge no longer on the front is dropped. While the front grows, triangles are
// only added, each touching its corners: an edge that left the front is among the woken ones
// of the next retry or dropped by the relaxed pass, and it never comes back to the front.
bool Grower::RetryDeferred()
{
  this->CollectWoken();
  bool any = false;
  Id a, b;
  for (size_t entry : this->Woken)
  {
    const Deferred& d = this->DeferredEdges[entry];
    if (!this->OnFront(d, a, b))
    {
      this->Retire(entry);
    }
    else if (this->Changed(d))
    {
      this->Queue.push_back({ a, b, d.Level });
      this->Retire(entry);
      any = true;
    }
  }
  if (!any && this->Par.Relax)
  {
    // The entries before RelaxFrom are at the last stage already.
    for (size_t entry = this->RelaxFrom; entry < this->DeferredEdges.size(); ++entry)
    {
      const Deferred& d = this->DeferredEdges[entry];
      if (!d.Active)
      {
        continue;
      }
      if (!this->OnFront(d, a, b))
      {
        this->Retire(entry);
      }
      else if (d.Level < 3)
      {
        this->Queue.push_back({ a, b, static_cast<uint8_t>(d.Level + 1) });
        this->Retire(entry);
        any = true;
      }
    }
    this->RelaxFrom = this->DeferredEdges.size();
  }
  if (this->RetiredEdges >= 1024 && 2 * this->RetiredEdges >= this->DeferredEdges.size())
  {
    this->CompactDeferred();
  }
  return any;
}

//------------------------------------------------------------------------------------------------
// A boundary loop closed with the shared hole triangulation kernel (pcs::holes::HoleFiller,
// paper 001 steps 5-6: projection on the loop's average plane, chord splitting until the
// projection is unambiguous, 2D greedy triangulation with the unused points inside). The
// triangles are kept only when they all fit the mesh (no edge with a third triangle, no vertex
// with a second fan) and face the side of the triangles around the loop.
// Does the fill lie folded back onto the mesh: a fill triangle in the same plane as the mesh
// triangle across one of its edges (exact Orient3D) and on the same side of that edge (exact
// Orient2D in the coordinate plane where the fill triangle's projection is largest), so that
// the two overlap? Such a fill covers the mesh with a second layer, back to back with it: the
// border loop of a small flat patch (a planar scan, a face of a box) was "closed" that way into a
// component enclosing no volume, and CAD vertex sets kept such layers on their flat faces
// (turbine: 213 pairs of overlapping coplanar triangles; Benchmarks/results/local_optimum.md,
// "Fills folded back onto flat faces"). With `allLoopEdges` the fill counts as folded only when
// it folds at every loop edge it shares with the mesh in one plane (the whole fill is a second
// layer), otherwise at any one: the small loops of step 6 (FillHole) include holes next to a fold
// of the growth itself (a latitude-circle sphere: one of six edges), where the fill closes the
// surface. Only exact coplanarity counts: a fill bent by any angle is left to the fills' rules.
bool Grower::FoldsOntoMesh(const std::vector<Id>& triangles, bool allLoopEdges) const
{
  int coplanar = 0, folded = 0;
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
  {
    const Id* v = &triangles[t];
    for (int i = 0; i < 3; ++i)
    {
      const Id a = v[i], b = v[(i + 1) % 3], c = v[(i + 2) % 3];
      const Id o = this->Mesh.OppositeVertex(b, a);
      if (o < 0 || o == c || P::Orient3D(this->P3(a), this->P3(b), this->P3(c), this->P3(o)) != 0)
      {
        continue;
      }
      ++coplanar;
      double ab[3], ac[3], n[3];
      Sub(this->P3(b), this->P3(a), ab);
      Sub(this->P3(c), this->P3(a), ac);
      Cross(ab, ac, n);
      int drop = 0;
      for (int k = 1; k < 3; ++k)
      {
        drop = std::fabs(n[k]) > std::fabs(n[drop]) ? k : drop;
      }
      const int u = (drop + 1) % 3, w = (drop + 2) % 3;
      const double a2[2] = { this->P3(a)[u], this->P3(a)[w] };
      const double b2[2] = { this->P3(b)[u], this->P3(b)[w] };
      const double c2[2] = { this->P3(c)[u], this->P3(c)[w] };
      const double o2[2] = { this->P3(o)[u], this->P3(o)[w] };
      const int sideC = P::Orient2D(a2, b2, c2);
      folded += sideC != 0 && sideC == P::Orient2D(a2, b2, o2) ? 1 : 0;
    }
  }
  return folded > 0 && (!allLoopEdges || folded == coplanar);
}

bool Grower::FillHole(const std::vector<Id>& frontLoop)
{
  const size_t m = frontLoop.size();
  // The hole's triangles own the twins of the front edges: the loop is walked backwards.
  std::vector<Id> loop(frontLoop.rbegin(), frontLoop.rend());
  std::vector<double> boundaryVectors(3 * m, 0.0);
  double normal[3] = { 0, 0, 0 };
  double perimeter = 0.0;
  for (size_t i = 0; i < m; ++i)
  {
    const Id s = frontLoop[i], e = frontLoop[(i + 1) % m];
    const Id o = this->Mesh.OppositeVertex(s, e);
    double t[3];
    if (o < 0 || !UnitNormal(this->P3(s), this->P3(e), this->P3(o), t))
    {
      return false;
    }
    for (int k = 0; k < 3; ++k)
    {
      normal[k] += t[k];
    }
    perimeter += std::sqrt(Distance2(this->P3(s), this->P3(e)));
    // Towards the mesh: from both end points of the edge to the third vertex of its triangle.
    for (Id v : { s, e })
    {
      const size_t j = (m - 1) - static_cast<size_t>(v == s ? i : (i + 1) % m);
      for (int k = 0; k < 3; ++k)
      {
        boundaryVectors[3 * j + k] += this->P3(o)[k] - this->P3(v)[k];
      }
    }
  }
  std::vector<Id> candidates;
  const Id* const centers = frontLoop.data();
  this->CollectVertices(centers, static_cast<int>(m));
  for (Id q : this->Near)
  {
    if (this->Mesh.IsFree(q))
    {
      candidates.push_back(q);
    }
  }
  pcs::holes::HoleFiller filler;
  filler.AuxiliaryDistance = 0.05 * perimeter / static_cast<double>(m);
  filler.EdgeExists = [this](int32_t a, int32_t b) { return this->Mesh.GetEdgeValence(a, b) > 0; };
  pcs::holes::FillResult result;
  if (!filler.Fill(this->X, loop, boundaryVectors, candidates, result) || !result.Complete)
  {
    return false;
  }
  // No hole triangle may be a mesh triangle reversed (the loop of a lone triangle would be
  // "closed" by the same triangle with the other orientation: two coincident triangles).
  for (size_t t = 0; t + 2 < result.Triangles.size(); t += 3)
  {
    const Id* v = &result.Triangles[t];
    if (this->Mesh.OppositeVertex(v[1], v[0]) == v[2])
    {
      return false;
    }
  }
  for (size_t t = 0; t + 2 < result.Triangles.size(); t += 3)
  {
    const Id* v = &result.Triangles[t];
    if (pcs::projected::Collinear(this->P3(v[0]), this->P3(v[1]), this->P3(v[2])))
    {
      return false;
    }
  }
  if (this->FoldsOntoMesh(result.Triangles, true) ||
    !pcs::holes::FillIsSmallPartOfSurface(this->X, this->Mesh, result.Triangles))
  {
    return false;
  }
  std::vector<int64_t> added;
  if (!this->Mesh.AddTriangles(result.Triangles.data(), result.Triangles.size() / 3, added))
  {
    return false;
  }
  for (Id q : result.UsedPoints)
  {
    ++this->UsedVertices;
    (void)q;
  }
  for (int64_t id : added)
  {
    this->Register(id);
  }
  return true;
}

// The loop's vertices and their K nearest neighbours, each once, appended to `around`.
void Grower::GatherAround(const std::vector<Id>& loop, std::vector<Id>& around)
{
  if (++this->MarkStamp == 0)
  {
    for (PointScratch& scratch : this->Scratch)
    {
      scratch.Mark = 0;
    }
    this->MarkStamp = 1;
  }
  for (Id v : loop)
  {
    const Id* nb = this->Neighbors(v);
    for (int j = -1; j < this->K; ++j)
    {
      const Id q = j < 0 ? v : nb[j];
      if (q >= 0 && this->Scratch[q].Mark != this->MarkStamp)
      {
        this->Scratch[q].Mark = this->MarkStamp;
        around.push_back(q);
      }
    }
  }
}

// A loop longer than MaximumHoleEdges (or one the projected triangulation could not close)
// closed by the triangulation of its own vertices of least largest dihedral angle, kept only
// when the fill stays on the sampled surface (pcs::holes::FillLoopNearSamples, shared with
// vtkCDTAdvancingFront; no bound on the dihedral angle here): the
// centroid and the midpoints of the new edges of each of its triangles lie within 2 local
// spacings of an input point (the accuracy bound asked of the whole mesh), the local spacing
// being the mean distance of the loop's vertices to their nearest neighbours, or the cloud's
// mean spacing when larger. A sampling gap on
// a thin or sharply bent feature passes; a membrane across an open border, a slit, or between
// parts that only come close passes through empty space and is refused.
bool Grower::FillNarrowLoop(const std::vector<Id>& frontLoop)
{
  const size_t m = frontLoop.size();
  if (m > pcs::holes::MaximumFillLoopEdges)
  {
    return false; // the least-dihedral triangulation is cubic in the loop's length
  }
  // The loop as the fill walks it (backwards), the order of the sum below.
  const std::vector<Id> loop(frontLoop.rbegin(), frontLoop.rend());
  double spacing = 0.0;
  for (Id v : loop)
  {
    double nearest = std::numeric_limits<double>::infinity();
    const Id* nb = this->Neighbors(v);
    for (int j = 0; j < this->K && nb[j] >= 0; ++j)
    {
      nearest = std::min(nearest, Distance2(this->P3(v), this->P3(nb[j])));
    }
    spacing += std::sqrt(nearest);
  }
  spacing /= static_cast<double>(m);
  // Not below the cloud's mean spacing, the unit of the Hausdorff bound: on a densely and
  // anisotropically sampled thin feature the nearest neighbour is much closer than the mesh's
  // edges (the camel's ears: 0.26 mean spacings, edges 0.7-0.9), and the local value alone
  // refused fills that stay within 0.8 mean spacings of the points.
  spacing = std::max(spacing, this->CloudSpacing());
  if (!(spacing > 0.0))
  {
    return false;
  }
  // The input points around the loop: its vertices and their K nearest neighbours, gathered
  // at the first query (most loops are refused before).
  std::vector<Id> around;
  auto nearSomePoint = [this, &loop, &around](const double* x, double reach)
  {
    if (around.empty())
    {
      this->GatherAround(loop, around);
    }
    for (Id p : around)
    {
      if (Distance2(x, this->P3(p)) <= reach * reach)
      {
        return true;
      }
    }
    return false;
  };
  std::vector<Id> triangles;
  if (!pcs::holes::FillLoopNearSamples(this->X,
        frontLoop,
        this->Mesh,
        2.0 * spacing,
        std::numeric_limits<double>::infinity(),
        nearSomePoint,
        triangles) ||
    this->FoldsOntoMesh(triangles, false))
  {
    return false;
  }
  std::vector<int64_t> added;
  if (!this->Mesh.AddTriangles(triangles.data(), triangles.size() / 3, added))
  {
    return false;
  }
  for (int64_t id : added)
  {
    this->Register(id);
  }
  return true;
}

void Grower::FillHoles()
{
  if (this->Par.MaxHoleEdges < 1)
  {
    return;
  }
  std::vector<std::vector<Id>> loops;
  this->Mesh.GetBoundaryLoops(loops);
  for (const auto& loop : loops)
  {
    if (loop.size() < 3)
    {
      continue;
    }
    std::vector<Id> sorted(loop);
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    {
      continue; // a loop through a vertex twice
    }
    // Small loops with the projected hole triangulation; longer ones, and small ones it could
    // not close, only when narrow.
    if ((static_cast<int>(loop.size()) <= this->Par.MaxHoleEdges && this->FillHole(loop)) ||
      this->FillNarrowLoop(loop))
    {
      ++this->HolesClosed;
    }
  }
}

// A free point that the growth left under a triangle (it lies within the triangle's projection
// onto its plane, typically very close to an edge, where the triangle across that edge could
// only have been a needle) is inserted by the shared kernel (pcs::InsertFreePoint): the nearest
// triangle among those at its K nearest neighbours is split into three, or, when the point is
// close to (or exactly on) an edge, that edge is split; a point beside a boundary edge gets the
// triangle that edge lacks. Points farther from the triangle than its longest edge are not on
// the surface and stay unused. The new triangles (and any the kernel had to put back) are
// registered like grown ones.
bool Grower::InsertOrphan(Id q, pcs::PointInsertionResult* record)
{
  pcs::PointInsertionResult local;
  pcs::PointInsertionResult& result = record ? *record : local;
  const bool inserted =
    pcs::InsertFreePoint(this->Mesh, this->X, q, this->Neighbors(q), this->K, true, result);
  for (const auto& restored : result.Restored)
  {
    this->Register(restored.second);
  }
  if (!inserted)
  {
    return false;
  }
  ++this->UsedVertices;
  for (int64_t t : result.Added)
  {
    this->Register(t);
  }
  return true;
}

void Grower::InsertOrphans()
{
  // A lone triangle (no neighbour, each vertex in it alone) is a seed that could not grow: its
  // points usually lie on a surface meshed around them. It is taken out, its points inserted
  // like the other free points, and restored when none of them could be.
  std::vector<std::array<Id, 3>> lone;
  const int64_t count = this->Mesh.GetNumberOfTriangleIds();
  for (int64_t t = 0; t < count; ++t)
  {
    if (this->Mesh.IsTriangleRemoved(t))
    {
      continue;
    }
    const int32_t* v = this->Mesh.GetTriangle(t);
    bool alone = true;
    for (int j = 0; j < 3 && alone; ++j)
    {
      alone = this->Mesh.GetVertexDegree(v[j]) == 1;
    }
    if (alone)
    {
      lone.push_back({ { v[0], v[1], v[2] } });
      this->Mesh.RemoveTriangle(t);
      this->UsedVertices -= 3;
    }
  }
  for (Id q = 0; q < this->N; ++q)
  {
    if (this->Mesh.IsFree(q) && this->InsertOrphan(q))
    {
      ++this->Inserted;
    }
  }
  for (const auto& t : lone)
  {
    if (this->Mesh.IsFree(t[0]) && this->Mesh.IsFree(t[1]) && this->Mesh.IsFree(t[2]))
    {
      this->Commit(t[0], t[1], t[2]);
    }
    else
    {
      for (Id q : t)
      {
        if (this->Mesh.IsFree(q) && this->InsertOrphan(q))
        {
          ++this->Inserted;
        }
      }
    }
  }
  // Then the other small separate pieces, one at a time (the smallest first): on noisy scans a
  // seed planted among points the growth left in the noise layer grows a few triangles, which
  // step 6 would close into a tiny polyhedron (a tetrahedron, a bipyramid) crossing the surface.
  for (const auto& piece : this->SmallPieces())
  {
    this->TakeApart(piece);
  }
}

// The separate pieces of 2 to SmallPieceTriangles triangles (no vertex shared with another
// piece), smallest first, each as its triangles in the order of their ids.
std::vector<std::vector<std::array<Id, 3>>> Grower::SmallPieces()
{
  const int64_t count = this->Mesh.GetNumberOfTriangleIds();
  // The seed labels join every triangle grown from one seed (and the parts that met): one label
  // among the triangles, one piece (the usual case, decided without the search below).
  int32_t single = -1;
  bool several = false;
  for (int64_t t = 0; t < count && !several; ++t)
  {
    if (!this->Mesh.IsTriangleRemoved(t))
    {
      const int32_t label = this->TriangleLabel(t);
      several = label < 0 || (single >= 0 && label != single);
      single = label;
    }
  }
  if (!several)
  {
    return {};
  }
  pcs::DisjointSets<int64_t> pieces(count);
  this->Mesh.JoinAcrossEdges(pieces);
  constexpr int64_t Pinched = std::numeric_limits<int64_t>::max();
  std::vector<int64_t> size(static_cast<size_t>(count), 0);
  std::vector<int64_t> pieceAt(static_cast<size_t>(this->N), -1);
  for (int64_t t = 0; t < count; ++t)
  {
    if (this->Mesh.IsTriangleRemoved(t))
    {
      continue;
    }
    const int64_t root = pieces.Find(t);
    size[root] = size[root] == Pinched ? Pinched : size[root] + 1;
    const int32_t* v = this->Mesh.GetTriangle(t);
    for (int j = 0; j < 3; ++j)
    {
      int64_t& at = pieceAt[v[j]];
      if (at >= 0 && at != root)
      {
        size[at] = Pinched; // (two pieces at a vertex: neither is separate)
        size[root] = Pinched;
      }
      at = root;
    }
  }
  std::vector<std::vector<std::array<Id, 3>>> small;
  std::vector<int64_t> smallOf(static_cast<size_t>(count), -1);
  for (int64_t t = 0; t < count; ++t)
  {
    const int64_t root = this->Mesh.IsTriangleRemoved(t) ? -1 : pieces.Find(t);
    if (root < 0 || size[root] < 2 || size[root] > SmallPieceTriangles)
    {
      continue;
    }
    if (smallOf[root] < 0)
    {
      smallOf[root] = static_cast<int64_t>(small.size());
      small.emplace_back();
    }
    const int32_t* v = this->Mesh.GetTriangle(t);
    small[smallOf[root]].push_back({ { v[0], v[1], v[2] } });
  }
  std::stable_sort(small.begin(), small.end(),
    [](const std::vector<std::array<Id, 3>>& a, const std::vector<std::array<Id, 3>>& b)
    { return a.size() < b.size(); });
  return small;
}

// A small piece taken out and its points inserted into the mesh around it (pcs::InsertFreePoint,
// as the free points), in passes while one fits. It stays out when at least three quarters of its
// points went in (the others stay unused: typically one point of a bubble in the noise that no
// triangle around can take without folding); otherwise the insertions are undone, last first, and
// the piece is put back as it was (a small object on its own, or a part the surface does not
// cover: taking it apart would leave points out and holes).
void Grower::TakeApart(const std::vector<std::array<Id, 3>>& piece)
{
  std::vector<Id> points;
  for (const auto& t : piece)
  {
    if (this->Mesh.FindTriangle(t[0], t[1]) < 0)
    {
      return; // (changed by an earlier piece's insertions: no longer separate)
    }
    points.insert(points.end(), t.begin(), t.end());
  }
  std::sort(points.begin(), points.end());
  // Separate still: no triangle attached to it since (each point's triangles are the piece's).
  for (size_t i = 0; i < points.size();)
  {
    size_t j = i;
    while (j < points.size() && points[j] == points[i])
    {
      ++j;
    }
    if (this->Mesh.GetVertexDegree(points[i]) != static_cast<int>(j - i))
    {
      return;
    }
    i = j;
  }
  points.erase(std::unique(points.begin(), points.end()), points.end());
  for (const auto& t : piece)
  {
    this->Mesh.RemoveTriangle(this->Mesh.FindTriangle(t[0], t[1]));
  }
  struct Step
  {
    std::vector<std::array<Id, 3>> Added, Removed;
  };
  std::vector<Step> steps;
  // (A point may fit only once its neighbours are in: passes over the others while one fits.)
  std::vector<Id> left = points;
  for (size_t before = 0; !left.empty() && left.size() != before;)
  {
    before = left.size();
    std::vector<Id> next;
    for (Id q : left)
    {
      pcs::PointInsertionResult result;
      if (!this->InsertOrphan(q, &result))
      {
        next.push_back(q);
        continue;
      }
      Step step;
      for (int64_t t : result.Added)
      {
        const int32_t* v = this->Mesh.GetTriangle(t);
        step.Added.push_back({ { v[0], v[1], v[2] } });
      }
      step.Removed = std::move(result.Removed);
      steps.push_back(std::move(step));
    }
    left.swap(next);
  }
  if (4 * left.size() <= points.size())
  {
    this->Inserted += static_cast<vtkIdType>(points.size() - left.size());
    return;
  }
  for (auto step = steps.rbegin(); step != steps.rend(); ++step)
  {
    for (const auto& t : step->Added)
    {
      this->Mesh.RemoveTriangle(this->Mesh.FindTriangle(t[0], t[1]));
    }
    for (const auto& t : step->Removed)
    {
      const int64_t id = this->Mesh.AddTriangle(t[0], t[1], t[2]);
      if (id >= 0)
      {
        this->Register(id);
      }
    }
  }
  for (const auto& t : piece)
  {
    const int64_t id = this->Mesh.AddTriangle(t[0], t[1], t[2]);
    if (id >= 0)
    {
      this->Register(id);
    }
  }
}

// The edge flips of step 7 (both passes), driven by three tests: `candidate(a, b, c)` picks the
// edges a-b of triangle (a, b, c) examined at first (cheap; the edges around a flipped edge are
// examined again whatever it says), `examine(quad)` asks for the normals of the two triangles only,
// `decide(quad)` for the flipped ones and the five edges' smallest dot products too. An edge is
// examined only when it has two triangles whose third vertices differ and are not joined by an
// edge already, and the flipped triangles are not degenerate. Topology: the flip keeps every vertex
// and boundary edge, and the two new triangles are checked by the mesh before they are kept.
template<typename Candidate, typename Examine, typename Decide>
void Grower::FlipEdges(const Candidate& candidate, const Examine& examine, const Decide& decide)
{
  auto normalOf = [this](Id x, Id y, Id z, double* n) {
    return UnitNormal(this->P3(x), this->P3(y), this->P3(z), n);
  };
  auto thirdVertex = [this](int64_t t, Id a, Id b) {
    const int32_t* v = this->Mesh.GetTriangle(t);
    return static_cast<Id>(
      static_cast<int64_t>(v[0]) + v[1] + v[2] - static_cast<int64_t>(a) - static_cast<int64_t>(b));
  };
  std::vector<std::pair<Id, Id>> stack;
  const int64_t count = this->Mesh.GetNumberOfTriangleIds();
  stack.reserve(2 * static_cast<size_t>(count)); // each edge once (3 / 2 per triangle), and room
  for (int64_t t = 0; t < count; ++t)
  {
    if (!this->Mesh.IsTriangleRemoved(t))
    {
      const int32_t* v = this->Mesh.GetTriangle(t);
      for (int j = 0; j < 3; ++j)
      {
        if (v[j] < v[(j + 1) % 3] && candidate(v[j], v[(j + 1) % 3], v[(j + 2) % 3]))
        {
          stack.emplace_back(v[j], v[(j + 1) % 3]);
        }
      }
    }
  }
  // Each flip raises a local minimum; the budget bounds the work whatever the geometry.
  int64_t budget = 4 * count + 64;
  Quad q;
  while (!stack.empty() && budget > 0 && !this->Aborted)
  {
    const Id a = stack.back().first, b = stack.back().second;
    stack.pop_back();
    q.T1 = this->Mesh.FindTriangle(a, b);
    q.T2 = this->Mesh.FindTriangle(b, a);
    if (q.T1 < 0 || q.T2 < 0)
    {
      continue;
    }
    // The third vertices read from the two triangles found (no second scan of the wedges).
    const Id c = thirdVertex(q.T1, a, b), d = thirdVertex(q.T2, a, b);
    q.A = a;
    q.B = b;
    q.C = c;
    q.D = d;
    if (c == d || !normalOf(a, b, c, q.N1) || !normalOf(b, a, d, q.N2) || !examine(q) ||
      this->Mesh.GetEdgeValence(c, d) > 0)
    {
      continue;
    }
    if (pcs::projected::Collinear(this->P3(a), this->P3(d), this->P3(c)) ||
      pcs::projected::Collinear(this->P3(b), this->P3(c), this->P3(d)) ||
      !normalOf(a, d, c, q.M1) || !normalOf(b, c, d, q.M2))
    {
      continue;
    }
    q.Before = Dot(q.N1, q.N2);
    q.After = Dot(q.M1, q.M2);
    // The four edges around: (s, e) with the triangle owning s->e before and after the flip.
    const Id ring[4][2] = { { b, c }, { c, a }, { a, d }, { d, b } };
    const double* owners[4][2] = { { q.N1, q.M2 }, { q.N1, q.M1 }, { q.N2, q.M1 }, { q.N2, q.M2 } };
    for (int i = 0; i < 4; ++i)
    {
      const Id s = ring[i][0], e = ring[i][1];
      const Id o = this->Mesh.OppositeVertex(e, s);
      double no[3];
      if (o >= 0 && normalOf(e, s, o, no))
      {
        q.Before = std::min(q.Before, Dot(no, owners[i][0]));
        q.After = std::min(q.After, Dot(no, owners[i][1]));
      }
    }
    if (!decide(q))
    {
      continue;
    }
    --budget;
    this->Mesh.RemoveTriangle(q.T1);
    this->Mesh.RemoveTriangle(q.T2);
    int64_t x = -1, y = -1;
    if (this->Mesh.CanAddTriangle(a, d, c) == pcs::SurfaceMesh::Check::Ok)
    {
      x = this->Mesh.AddTriangle(a, d, c);
    }
    if (x >= 0 && this->Mesh.CanAddTriangle(b, c, d) == pcs::SurfaceMesh::Check::Ok)
    {
      y = this->Mesh.AddTriangle(b, c, d);
    }
    if (x < 0 || y < 0)
    {
      if (x >= 0)
      {
        this->Mesh.RemoveTriangle(x);
      }
      this->Mesh.AddTriangle(a, b, c);
      this->Mesh.AddTriangle(b, a, d);
      continue;
    }
    for (const auto& edge : ring)
    {
      stack.emplace_back(edge[0], edge[1]);
    }
  }
}

// Step 7: folds repaired by edge flips. An edge whose two triangles bend by more than constraint 1
// allows is flipped when the other diagonal of its quadrilateral is absent from the mesh and
// shorter, or joins two K nearest neighbours (NeighborDiagonal), and the flip raises the smallest
// normal dot product among the five edges of the quadrilateral (the edge itself and the four around
// it).
void Grower::Unfold()
{
  this->FlipEdges([](Id, Id, Id) { return true; },
    [this](const Quad& q)
    {
      return Dot(q.N1, q.N2) < this->Par.CosNormal &&
        (Distance2(this->P3(q.C), this->P3(q.D)) < Distance2(this->P3(q.A), this->P3(q.B)) ||
          this->NeighborDiagonal(q.C, q.D));
    },
    [](const Quad& q) { return q.After > q.Before; });
}

// Squared distance from x to the nearest of the points `around` and their K nearest neighbours.
double Grower::NearestSampleDistance2(const double* x, const Id* around, int count) const
{
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < count; ++i)
  {
    const Id* nb = this->Neighbors(around[i]);
    for (int j = -1; j < this->K; ++j)
    {
      const Id u = j < 0 ? around[i] : nb[j];
      if (u >= 0)
      {
        best = std::min(best, Distance2(x, this->P3(u)));
      }
    }
  }
  return best;
}

// The largest squared distance from the centroids of the triangles (p, q, r) and (q, p, u) and
// from the midpoint of p-q to the nearest input point among p, q, r, u and their K nearest.
double Grower::FarthestFromSamples(Id p, Id q, Id r, Id u) const
{
  const Id quad[4] = { p, q, r, u };
  double x[3][3];
  for (int k = 0; k < 3; ++k)
  {
    x[0][k] = (this->P3(p)[k] + this->P3(q)[k] + this->P3(r)[k]) / 3.0;
    x[1][k] = (this->P3(p)[k] + this->P3(q)[k] + this->P3(u)[k]) / 3.0;
    x[2][k] = 0.5 * (this->P3(p)[k] + this->P3(q)[k]);
  }
  double farthest = 0.0;
  for (const auto& y : x)
  {
    farthest = std::max(farthest, this->NearestSampleDistance2(y, quad, 4));
  }
  return farthest;
}

// Step 7, second pass: long edges across thin tips. An edge a-b longer than LongEdgeFactor local
// spacings (the mean, over a, b, c, d, of the mean distance to the 6 nearest neighbours) whose
// quadrilateral (a, c, b, d) has the other diagonal c-d absent from the mesh and shorter than
// ShorterDiagonal |ab| is flipped when the flip folds nothing (the smallest normal dot product
// among the five edges of the quadrilateral stays at least min(before, cos MaximumNormalAngle)), or
// when it brings the two triangles closer to the points (FarthestFromSamples falls by the factor
// ShorterDiagonal) without folding over (normals more than 90 degrees apart) a quadrilateral
// that was not folded over before nor making a sliver (Fatness).
void Grower::ShortenLongEdges()
{
  constexpr double LongEdgeFactor = 3.0;
  constexpr double ShorterDiagonal = 0.8;
  // The local spacing of a vertex, computed when first needed (-1: not yet).
  std::vector<double> local(static_cast<size_t>(this->N), -1.0);
  auto localSpacing = [this, &local](Id v)
  {
    if (local[v] < 0.0)
    {
      local[v] = this->LocalSpacing(v);
    }
    return local[v];
  };
  // The edges that may be long: |ab| over the bound even without the fourth vertex's spacing
  // (most edges fail this, before any search of the triangle across).
  auto candidate = [&](Id a, Id b, Id c)
  {
    const double bound =
      LongEdgeFactor * 0.25 * (localSpacing(a) + localSpacing(b) + localSpacing(c));
    return Distance2(this->P3(a), this->P3(b)) > bound * bound;
  };
  auto examine = [&](const Quad& q)
  {
    const double ab2 = Distance2(this->P3(q.A), this->P3(q.B));
    const double bound = LongEdgeFactor * 0.25 *
      (localSpacing(q.A) + localSpacing(q.B) + localSpacing(q.C) + localSpacing(q.D));
    return ab2 > bound * bound &&
      Distance2(this->P3(q.C), this->P3(q.D)) < ShorterDiagonal * ShorterDiagonal * ab2;
  };
  auto decide = [&](const Quad& q)
  {
    if (q.After >= std::min(q.Before, this->Par.CosNormal))
    {
      return true;
    }
    // Nearer to the points, but not folding a quadrilateral that was not folded, and not making
    // a sliver: the thinner new triangle at least a quarter as fat as the thinner old one (three
    // points of one scan line: the sliver lies on the points, so it is "nearer", but stands
    // across the surface).
    const double fatBefore = std::min(Fatness(this->P3(q.A), this->P3(q.B), this->P3(q.C)),
      Fatness(this->P3(q.B), this->P3(q.A), this->P3(q.D)));
    const double fatAfter = std::min(Fatness(this->P3(q.A), this->P3(q.D), this->P3(q.C)),
      Fatness(this->P3(q.B), this->P3(q.C), this->P3(q.D)));
    return (q.Before < 0.0 || q.After >= 0.0) && fatAfter >= 0.25 * fatBefore &&
      this->FarthestFromSamples(q.C, q.D, q.A, q.B) <
      ShorterDiagonal * ShorterDiagonal * this->FarthestFromSamples(q.A, q.B, q.C, q.D);
  };
  this->FlipEdges(candidate, examine, decide);
}

// May the fold of the quadrilateral (a, c, b, d) be flipped to its longer diagonal c-d? When c
// and d are K nearest neighbours (one of the other): an edge the growth could have made, at the
// scale of the sampling and of its noise. A longer diagonal across a quadrilateral larger than
// that, on a sharply bent part, leaves the surface (10^5 samples of CGAL's armadillo: Hausdorff
// 1.79 -> 2.12 mean spacings when any longer diagonal was allowed).
bool Grower::NeighborDiagonal(Id c, Id d) const
{
  const Id* nc = this->Neighbors(c);
  const Id* nd = this->Neighbors(d);
  return std::find(nc, nc + this->K, d) != nc + this->K ||
    std::find(nd, nd + this->K, c) != nd + this->K;
}

// Closed components are turned outwards: positive signed volume. The triangles across the edges
// are found vertex by vertex: the umbrella of a vertex with a single fan is edge-connected, so
// its triangles join the component together (one wedge scan per vertex rather than one per
// triangle edge), and the component is open when the fan is (the vertex is not Interior). Only an
// edge between two vertices of more than one fan is looked up on its own.
void Grower::OrientComponents()
{
  const int64_t count = this->Mesh.GetNumberOfTriangleIds();
  std::vector<char> visited(static_cast<size_t>(count), 0);
  std::vector<char> vertexDone(static_cast<size_t>(this->N), 0);
  std::vector<int64_t> component;
  std::vector<int64_t> umbrella(16);
  auto join = [&](int64_t other) {
    if (!visited[other])
    {
      visited[other] = 1;
      component.push_back(other);
    }
  };
  for (int64_t t = 0; t < count; ++t)
  {
    if (visited[t] || this->Mesh.IsTriangleRemoved(t))
    {
      continue;
    }
    component.assign(1, t);
    visited[t] = 1;
    bool closed = true;
    double volume = 0.0;
    const double* ref = this->P3(this->Mesh.GetTriangle(t)[0]);
    for (size_t i = 0; i < component.size(); ++i)
    {
      const int32_t* v = this->Mesh.GetTriangle(component[i]);
      double e0[3], e1[3], e2[3], c[3];
      Sub(this->P3(v[0]), ref, e0);
      Sub(this->P3(v[1]), ref, e1);
      Sub(this->P3(v[2]), ref, e2);
      Cross(e1, e2, c);
      volume += Dot(e0, c);
      for (int j = 0; j < 3; ++j)
      {
        const Id s = v[j], e = v[(j + 1) % 3];
        if (this->Mesh.GetNumberOfFans(s) > 1 && this->Mesh.GetNumberOfFans(e) > 1)
        {
          const int64_t other = this->Mesh.FindTriangle(e, s);
          closed = closed && other >= 0;
          if (other >= 0)
          {
            join(other);
          }
        }
        if (this->Mesh.GetNumberOfFans(s) > 1 || vertexDone[s])
        {
          continue;
        }
        vertexDone[s] = 1;
        closed = closed && this->Mesh.IsInterior(s);
        int degree =
          this->Mesh.GetVertexTriangles(s, umbrella.data(), static_cast<int>(umbrella.size()));
        if (degree > static_cast<int>(umbrella.size()))
        {
          umbrella.resize(static_cast<size_t>(degree));
          degree = this->Mesh.GetVertexTriangles(s, umbrella.data(), degree);
        }
        std::for_each(umbrella.begin(), umbrella.begin() + degree, join);
      }
    }
    if (closed && volume < 0.0)
    {
      this->Mesh.ReverseComponent(t);
    }
  }
}

void Grower::GrowFrom(pcs::SurfaceMesh&& mesh, bool expandFront)
{
  this->Mesh = std::move(mesh);
  for (Id v = 0; v < this->N; ++v)
  {
    this->UsedVertices += this->Mesh.IsFree(v) ? 0 : 1;
  }
  const int64_t count = this->Mesh.GetNumberOfTriangleIds();
  for (int64_t t = 0; t < count; ++t)
  {
    if (!this->Mesh.IsTriangleRemoved(t))
    {
      this->Register(t);
    }
  }
  if (!expandFront)
  {
    this->Queue.clear();
  }
  this->Grow();
}

// The front expanded until it stalls, then a new seed planted, until none can be.
void Grower::Grow()
{
  while (!this->Aborted)
  {
    this->ProcessQueue();
    if (this->Aborted || this->RetryDeferred())
    {
      continue;
    }
    if (!this->PlantSeed())
    {
      break;
    }
  }
}

void Grower::Run()
{
  this->Mesh.ReserveTriangles(2 * static_cast<int64_t>(this->N));
  if (!this->PlantSeed())
  {
    return;
  }
  this->Grow();
  if (!this->Aborted)
  {
    this->InsertOrphans();
    this->FillHoles();
    if (this->InputX)
    {
      this->X = this->InputX; // the folds and long edges of the output's points
    }
    this->Unfold();
    this->ShortenLongEdges();
  }
  this->OrientComponents();
}

} // namespace

//------------------------------------------------------------------------------------------------
int64_t pcs::GrowFront(pcs::SurfaceMesh& mesh,
  const double* x,
  int32_t n,
  const std::vector<int32_t>& knn,
  int k,
  const std::vector<double>& stretch,
  bool expandFront,
  const std::vector<int32_t>& seeds,
  const pcs::FrontGrowthParameters& parameters,
  vtkAlgorithm* algorithm,
  double progressBegin,
  double progressEnd,
  bool& aborted)
{
  const int64_t before = mesh.GetNumberOfTriangles();
  Grower grower(x, n, knn, MakeParameters(k, parameters), algorithm);
  grower.SeedOrder = seeds;
  grower.SetStretch(stretch);
  grower.ProgressBegin = progressBegin;
  grower.ProgressEnd = progressEnd;
  grower.GrowFrom(std::move(mesh), expandFront);
  aborted = grower.Aborted;
  mesh = std::move(grower.Mesh);
  return mesh.GetNumberOfTriangles() - before;
}

//------------------------------------------------------------------------------------------------
// The constraints' defaults are pcs::FrontGrowthParameters' (one place, shared with greedy's
// GrowRegions).
vtkLocalOptimumGrowth::vtkLocalOptimumGrowth()
{
  const pcs::FrontGrowthParameters defaults;
  this->MaximumNormalAngle = defaults.MaximumNormalAngle;
  this->MinimumEdgeRatio = defaults.MinimumEdgeRatio;
  this->MaximumEdgeRatio = defaults.MaximumEdgeRatio;
  this->MaximumBaseAngle = defaults.MaximumBaseAngle;
  this->MaximumHoleEdges = defaults.MaximumHoleEdges;
  this->RelaxConstraints = defaults.RelaxConstraints;
}

vtkLocalOptimumGrowth::~vtkLocalOptimumGrowth()
{
  this->SetLocator(nullptr);
}

vtkMTimeType vtkLocalOptimumGrowth::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->Locator)
  {
    mtime = std::max(mtime, this->Locator->GetMTime());
  }
  return mtime;
}

int vtkLocalOptimumGrowth::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

//------------------------------------------------------------------------------------------------
int vtkLocalOptimumGrowth::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  // Under MPI the whole cloud is meshed on process 0; the other processes' outputs stay empty.
  vtkSmartPointer<vtkPointSet> input =
    pcs::GatherInputOnFirstProcess(vtkPointSet::GetData(inputVector[0]));
  if (!input && output)
  {
    return 1;
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
  this->NumberOfInputPoints = this->NumberOfTriangles = this->NumberOfSeeds = 0;
  this->NumberOfHolesClosed = this->NumberOfUnusedPoints = this->NumberOfDuplicatePoints = 0;
  this->NumberOfSkippedPoints = this->NumberOfBoundaryEdges = this->NumberOfOutliers = 0;
  this->ProjectedOntoLocalPlanes = false;
  this->NoiseLevel = this->NoiseShare = 0.0;

  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  this->NumberOfInputPoints = numberOfPoints;
  if (input->GetPoints())
  {
    output->SetPoints(input->GetPoints());
  }
  output->GetPointData()->PassData(input->GetPointData());
  vtkNew<vtkUnsignedCharArray> used;
  used->SetName("Used");
  used->SetNumberOfValues(numberOfPoints);
  used->FillValue(0);
  vtkNew<vtkIdTypeArray> representative;
  representative->SetName("RepresentativeId");
  representative->SetNumberOfValues(numberOfPoints);
  output->GetPointData()->AddArray(used);
  output->GetPointData()->AddArray(representative);
  vtkNew<vtkCellArray> polys;
  output->SetPolys(polys);

  auto finish = [&]() {
    vtkFieldData* fd = output->GetFieldData();
    pcs::AddFieldCount(fd, "NumberOfInputPoints", this->NumberOfInputPoints);
    pcs::AddFieldCount(fd, "NumberOfTriangles", this->NumberOfTriangles);
    pcs::AddFieldCount(fd, "NumberOfSeeds", this->NumberOfSeeds);
    pcs::AddFieldCount(fd, "NumberOfHolesClosed", this->NumberOfHolesClosed);
    pcs::AddFieldCount(fd, "NumberOfUnusedPoints", this->NumberOfUnusedPoints);
    pcs::AddFieldCount(fd, "NumberOfDuplicatePoints", this->NumberOfDuplicatePoints);
    pcs::AddFieldCount(fd, "NumberOfSkippedPoints", this->NumberOfSkippedPoints);
    pcs::AddFieldCount(fd, "NumberOfBoundaryEdges", this->NumberOfBoundaryEdges);
    pcs::AddFieldCount(fd, "NumberOfOutliers", this->NumberOfOutliers);
    pcs::AddFieldCount(fd, "ProjectedOntoLocalPlanes", this->ProjectedOntoLocalPlanes ? 1 : 0);
    pcs::AddFieldValue(fd, "NoiseLevel", this->NoiseLevel);
    pcs::AddFieldValue(fd, "NoiseShare", this->NoiseShare);
    return 1;
  };

  if (numberOfPoints == 0)
  {
    vtkWarningMacro("The input has no points: the output is empty.");
    return finish();
  }
  if (numberOfPoints > MaximumNumberOfPoints)
  {
    vtkErrorMacro("The input has " << numberOfPoints << " points; at most " << MaximumNumberOfPoints
                                   << " are supported.");
    representative->FillValue(-1);
    this->NumberOfUnusedPoints = numberOfPoints;
    return finish();
  }
  const std::string nanParameters =
    pcs::NaNParametersError({ { "MaximumNormalAngle", this->MaximumNormalAngle },
      { "MinimumEdgeRatio", this->MinimumEdgeRatio },
      { "MaximumEdgeRatio", this->MaximumEdgeRatio },
      { "MaximumBaseAngle", this->MaximumBaseAngle },
      { "OutlierFactor", this->OutlierFactor } });
  if (!nanParameters.empty())
  {
    vtkErrorMacro(<< nanParameters);
    representative->FillValue(-1);
    this->NumberOfUnusedPoints = numberOfPoints;
    return finish();
  }

  // Coordinates as doubles (the non-finite points skipped: RepresentativeId -1); those far from 1
  // in magnitude are scaled by a power of two (exact), so that squared lengths and the
  // predicates never overflow or underflow.
  std::vector<double> xyz;
  std::vector<Id> ids;
  this->NumberOfSkippedPoints = pcs::ReadFiniteCoordinates(input->GetPoints(), xyz, ids);
  representative->FillValue(-1);
  if (this->NumberOfSkippedPoints > 0)
  {
    vtkWarningMacro(
      "Skipped " << this->NumberOfSkippedPoints << " point(s) with NaN or infinite coordinates.");
  }
  const int exponent = pcs::PredicateSafeExponent(xyz.data(), 3, ids);
  if (exponent != 0)
  {
    for (Id i : ids)
    {
      for (int c = 0; c < 3; ++c)
      {
        xyz[3 * static_cast<size_t>(i) + c] =
          std::ldexp(xyz[3 * static_cast<size_t>(i) + c], exponent);
      }
    }
  }

  // Internal order along a Hilbert curve; exact duplicates merged into the first of their group
  // along the curve (pcs::MergeExactDuplicates keeps the order of `ids`). The distinct points'
  // ids in lexicographic (x, y, z) order are kept for the seeds' order.
  pcs::HilbertSort(xyz.data(), 3, ids.data(), ids.data() + ids.size());
  std::vector<Id> lexicographic;
  {
    std::vector<std::pair<int32_t, int32_t>> merged;
    this->NumberOfDuplicatePoints =
      pcs::MergeExactDuplicates(xyz.data(), 3, ids, merged, &lexicographic);
    for (const Id id : ids)
    {
      representative->SetValue(id, id);
    }
    for (const auto& copy : merged)
    {
      representative->SetValue(copy.first, copy.second);
    }
  }
  // A pile copy (a point of a pile of near-coincident points but its first along the curve,
  // pcs::FindPiles) is a duplicate of the pile's first: it and its exact copies are represented
  // by that point.
  auto mergePileCopies = [&](const std::vector<std::pair<int32_t, int32_t>>& pileCopies)
  {
    this->NumberOfDuplicatePoints +=
      pcs::RepresentPilesByFirst(representative->GetPointer(0), numberOfPoints, pileCopies);
  };
  auto warnDuplicates = [&]()
  {
    if (this->NumberOfDuplicatePoints > 0)
    {
      vtkWarningMacro(<< pcs::DuplicatesWarning(this->NumberOfDuplicatePoints,
                        "each group is merged into its first point along the Hilbert curve (point "
                        "data RepresentativeId; the others are not triangle vertices)"));
    }
  };
  // Far outliers and piles: from the K-neighbour table below when K >= pcs::OutlierNeighbors,
  // else here.
  const bool outliersFromTable = this->NumberOfNeighbors >= pcs::OutlierNeighbors;
  if (!outliersFromTable)
  {
    std::vector<std::pair<int32_t, int32_t>> pileCopies;
    this->NumberOfOutliers = pcs::RemoveOutliersAndPiles(xyz.data(),
      ids,
      this->OutlierFactor,
      pileCopies,
      [this](double) { return !this->GetAbortExecute(); });
    mergePileCopies(pileCopies);
  }
  Id n = static_cast<Id>(ids.size());
  if (n < 3)
  {
    warnDuplicates();
    vtkWarningMacro("Fewer than 3 distinct finite points (" << n << "): no triangles are made.");
    this->NumberOfUnusedPoints = this->NumberOfOutliers + n;
    return finish();
  }
  this->UpdateProgress(0.05);

  // Internal coordinates and the K nearest neighbours (thread-safe queries of the static
  // locator, built once; again without the far outliers when there are any).
  std::vector<double> x;
  std::vector<Id> knn;
  std::vector<double> stretch;
  int k = 0;
  bool neighborsFound = false;
  // The grid the neighbours were searched in, for the scan-line search below: the locator set
  // (built on the cloud), else the search's own bins.
  vtkSmartPointer<vtkStaticPointLocator> locator = this->Locator;
  pcs::PointBins bins;
  auto findNeighbors = [&]() {
    x.resize(3 * static_cast<size_t>(n));
    for (Id i = 0; i < n; ++i)
    {
      std::copy_n(&xyz[3 * static_cast<size_t>(ids[i])], 3, &x[3 * static_cast<size_t>(i)]);
    }
    k = std::min<int>(this->NumberOfNeighbors, n - 1);
    knn.assign(static_cast<size_t>(n) * k, -1);
    vtkNew<vtkDoubleArray> coordinates;
    coordinates->SetNumberOfComponents(3);
    coordinates->SetArray(x.data(), 3 * static_cast<vtkIdType>(n), 1);
    vtkNew<vtkPoints> internalPoints;
    internalPoints->SetData(coordinates);
    vtkNew<vtkPolyData> cloud;
    cloud->SetPoints(internalPoints);
    // The shared K-nearest-neighbour search (adaptive radius queries, ties broken by index,
    // threaded in blocks); abort stops it between blocks and the growth is then skipped.
    auto progress = [this](double fraction)
    {
      if (this->GetAbortExecute())
      {
        return false;
      }
      this->UpdateProgress(0.05 + 0.1 * fraction);
      return !this->GetAbortExecute();
    };
    if (locator)
    {
      locator->SetDataSet(cloud);
      locator->BuildLocator();
      neighborsFound = pcs::FindNearestNeighbors(locator, x.data(), n, k, knn, progress);
    }
    else
    {
      // A surface sample fills only a thin layer of the bins of its bounding box: about 4 bins
      // per point keep the radius queries short (see the class documentation). No locator: the
      // search files the points into its own bucket grid (their coordinates are filed only when
      // the scan-line search below needs them).
      double bounds[6];
      pcs::BuildSurfaceSampleBins(bins, x.data(), n, /*withCoordinates=*/false, bounds);
      neighborsFound = pcs::FindNearestNeighbors(bins, x.data(), n, k, knn, progress);
    }
  };
  findNeighbors();
  if (outliersFromTable && !this->GetAbortExecute())
  {
    std::vector<uint8_t> far;
    std::vector<std::pair<Id, Id>> pileCopies;
    this->NumberOfOutliers =
      pcs::DropOutliersAndPilesByTable(x, ids, knn, k, this->OutlierFactor, far, pileCopies);
    mergePileCopies(pileCopies);
    if (this->NumberOfOutliers > 0 || !pileCopies.empty())
    {
      n = static_cast<Id>(ids.size());
      if (n < 3)
      {
        warnDuplicates();
        vtkWarningMacro(
          "Fewer than 3 distinct finite points (" << n << ") left: no triangles are made.");
        this->NumberOfUnusedPoints = this->NumberOfOutliers + n;
        if (this->Locator)
        {
          this->Locator->SetDataSet(nullptr);
        }
        return finish();
      }
      findNeighbors();
    }
  }
  // Scan-line sampling: a point whose K nearest all lie on its own line also gets the nearest
  // points of the lines beside it (see pcsNearestNeighbors.h). After the outlier rule, which
  // reads the plain nearest-first table.
  stretch.clear();
  if (neighborsFound && !this->GetAbortExecute() &&
    (locator ? pcs::AddOffLineNeighbors(locator, x.data(), n, k, knn, &stretch)
             : pcs::AddOffLineNeighbors(bins, x.data(), n, k, knn, &stretch)) == 0)
  {
    stretch.clear();
  }
  if (this->Locator)
  {
    this->Locator->SetDataSet(nullptr);
  }
  locator = nullptr;
  bins = pcs::PointBins();
  xyz.clear();
  xyz.shrink_to_fit();
  warnDuplicates();
  if (this->NumberOfOutliers > 0)
  {
    vtkWarningMacro("Excluded " << this->NumberOfOutliers << " far outlier(s) (OutlierFactor "
                                << this->OutlierFactor
                                << "): point data Used = 0, field data NumberOfOutliers.");
  }
  this->NumberOfUnusedPoints = this->NumberOfOutliers;
  // Noisy clouds: the triangles are chosen on the points projected onto their local planes
  // (LocalPlaneProjection); the table, the scan-line stretch and the seed order stay those of
  // the input points.
  std::vector<double> inputX; // the input points when x is projected
  if (neighborsFound && !this->GetAbortExecute() &&
    this->LocalPlaneProjection != pcs::ProjectionOff)
  {
    bool project = this->LocalPlaneProjection == pcs::ProjectionOn;
    if (this->LocalPlaneProjection == pcs::ProjectionAutomatic)
    {
      const pcs::SamplingNoiseMeasure noise =
        pcs::MeasureSamplingNoise(x.data(), n, knn, k, pcs::NoiseNeighbors);
      this->NoiseLevel = noise.Level;
      this->NoiseShare = noise.Share;
      project = noise.Noisy;
    }
    if (project)
    {
      pcs::ProjectOntoLocalPlanes(x.data(), n, knn, k, pcs::ProjectionNeighbors, inputX);
      x.swap(inputX);
      this->ProjectedOntoLocalPlanes = true;
    }
  }
  this->UpdateProgress(0.15);

  pcs::FrontGrowthParameters constraints;
  constraints.MaximumNormalAngle = this->MaximumNormalAngle;
  constraints.MinimumEdgeRatio = this->MinimumEdgeRatio;
  constraints.MaximumEdgeRatio = this->MaximumEdgeRatio;
  constraints.MaximumBaseAngle = this->MaximumBaseAngle;
  constraints.MaximumHoleEdges = this->MaximumHoleEdges;
  constraints.RelaxConstraints = this->RelaxConstraints != 0;
  Parameters parameters = MakeParameters(k, constraints);
  parameters.SeparateSheets = true;
  Grower grower(x.data(), n, knn, parameters, this);
  grower.SetStretch(stretch);
  grower.InputX = this->ProjectedOntoLocalPlanes ? inputX.data() : nullptr;
  grower.DecideAnisotropy(true);
  {
    // Seeds: the points in decreasing lexicographic order (internal ids; outliers left out).
    std::vector<Id> internal(static_cast<size_t>(numberOfPoints), -1);
    for (Id i = 0; i < n; ++i)
    {
      internal[ids[i]] = i;
    }
    grower.SeedOrder.reserve(n);
    for (auto it = lexicographic.rbegin(); it != lexicographic.rend(); ++it)
    {
      if (internal[*it] >= 0)
      {
        grower.SeedOrder.push_back(internal[*it]);
      }
    }
  }
  if (!this->GetAbortExecute())
  {
    grower.Run();
  }
  this->UpdateProgress(0.9);

  // Output: triangles over the input point ids.
  const pcs::SurfaceMesh& mesh = grower.Mesh;
  std::vector<int32_t> triangles;
  mesh.GetTriangles(triangles);
  const vtkIdType numberOfTriangles = static_cast<vtkIdType>(triangles.size() / 3);
  vtkNew<vtkTypeInt32Array> offsets;
  offsets->SetNumberOfValues(numberOfTriangles + 1);
  for (vtkIdType t = 0; t <= numberOfTriangles; ++t)
  {
    offsets->SetValue(t, static_cast<int32_t>(3 * t));
  }
  vtkNew<vtkTypeInt32Array> connectivity;
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(triangles.size()));
  for (size_t j = 0; j < triangles.size(); ++j)
  {
    connectivity->SetValue(static_cast<vtkIdType>(j), ids[triangles[j]]);
  }
  polys->SetData(offsets, connectivity);
  for (Id v = 0; v < n; ++v)
  {
    if (!mesh.IsFree(v))
    {
      used->SetValue(ids[v], 1);
    }
    else
    {
      ++this->NumberOfUnusedPoints;
    }
  }
  this->NumberOfTriangles = numberOfTriangles;
  this->NumberOfSeeds = grower.Seeds;
  this->NumberOfHolesClosed = grower.HolesClosed;
  this->NumberOfBoundaryEdges = mesh.GetNumberOfBoundaryHalfEdges();
  if (numberOfTriangles == 0 && !grower.Aborted)
  {
    vtkWarningMacro("No triangle could be made (collinear points, or no neighbours meeting the "
                    "constraints).");
  }
  else if (this->NumberOfUnusedPoints > 0)
  {
    vtkWarningMacro(<< this->NumberOfUnusedPoints
                    << " point(s) were left unused (point data Used = 0).");
  }
  this->UpdateProgress(1.0);
  return finish();
}

//------------------------------------------------------------------------------------------------
void vtkLocalOptimumGrowth::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfNeighbors: " << this->NumberOfNeighbors << "\n";
  os << indent << "OutlierFactor: " << this->OutlierFactor << "\n";
  os << indent << "LocalPlaneProjection: " << this->LocalPlaneProjection << "\n";
  os << indent << "MaximumNormalAngle: " << this->MaximumNormalAngle << "\n";
  os << indent << "MinimumEdgeRatio: " << this->MinimumEdgeRatio << "\n";
  os << indent << "MaximumEdgeRatio: " << this->MaximumEdgeRatio << "\n";
  os << indent << "MaximumBaseAngle: " << this->MaximumBaseAngle << "\n";
  os << indent << "MaximumHoleEdges: " << this->MaximumHoleEdges << "\n";
  os << indent << "RelaxConstraints: " << this->RelaxConstraints << "\n";
  os << indent << "Locator: " << this->Locator << "\n";
  os << indent << "NumberOfInputPoints: " << this->NumberOfInputPoints << "\n";
  os << indent << "NumberOfTriangles: " << this->NumberOfTriangles << "\n";
  os << indent << "NumberOfSeeds: " << this->NumberOfSeeds << "\n";
  os << indent << "NumberOfHolesClosed: " << this->NumberOfHolesClosed << "\n";
  os << indent << "NumberOfUnusedPoints: " << this->NumberOfUnusedPoints << "\n";
  os << indent << "NumberOfDuplicatePoints: " << this->NumberOfDuplicatePoints << "\n";
  os << indent << "NumberOfSkippedPoints: " << this->NumberOfSkippedPoints << "\n";
  os << indent << "NumberOfBoundaryEdges: " << this->NumberOfBoundaryEdges << "\n";
  os << indent << "ProjectedOntoLocalPlanes: " << this->ProjectedOntoLocalPlanes << "\n";
  os << indent << "NoiseLevel: " << this->NoiseLevel << "\n";
  os << indent << "NoiseShare: " << this->NoiseShare << "\n";
}
