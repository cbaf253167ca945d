#include "vtkGreedySurfaceTriangulation.h"

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
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkIncrementalOctreePointLocator.h"
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
#include "vtkStringArray.h"
#include "vtkTypeInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkGreedySurfaceTriangulation);

namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
// CapOpenEnds: a loop is capped when its piece's area is at least this multiple of the area the
// loop spans (twice a hemisphere bowl's), by a least-dihedral fill folding at most this much.
constexpr double CapAreaRatio = 4.0;
constexpr double MaximumCapDihedral = 150.0; // degrees
// CapOpenEnds: no cap on a loop where the mesh makes an angle of more than this with the cap on
// the side of the material (a tube's cut end 90, a smooth surface's hole about 180, the mouth of a
// hole through the object 270 and more); judged on a piece whose volume is at least its area
// times this many mean spacings (a body whose inside its orientation tells).
constexpr double MaximumCapFold = 240.0; // degrees
constexpr double MinimumCapVolumeThickness = 0.25;
// A natural border (IsNaturalBorder): a rim within this fraction of its diameter (rms) of its
// plane, met by the surface at more than 60 degrees on average (mean |cos| below this).
constexpr double NaturalBorderFlatness = 0.05;
constexpr double NaturalBorderSteepness = 0.5;
// Points of a ragged rim (lost points, noise) lie up to a few spacings beyond its plane.
constexpr double NaturalBorderClearance = 3.0;
// FillMeetsMesh searches the mesh vertices within a fill triangle's radius plus this many mean
// spacings; the triangles with a longer edge are kept in a list and all tested.
constexpr double LongEdgeSpacings = 4.0;
// Scan-line sampling is taken for the pattern of a region when at least this share of a point's
// K nearest lie along their lines too (pcs::AddOffLineNeighbors' minimumShare).
constexpr double ScanLineShare = 0.5;
// Step 1 with the crossing test (issue 7): a triangle stands across the surface when its angle
// at its third point exceeds 150 degrees (StandingAngleCosine), its normal makes more than 70
// degrees with the normals of its three points (StandingCosine) and their nearest points lie on
// both sides of its plane, farther than StandingSides times its edge ab.
constexpr double StandingCosine = 0.3420201433256687;       // cos 70 degrees
constexpr double StandingAngleCosine = -0.8660254037844386; // cos 150 degrees
constexpr double StandingSides = 0.5;
// Step 7 on every triangle (SwapObtuseEdges): the two new triangles of a swap fold by at most
// this many degrees.
constexpr double ObtuseSwapFold = 30.0;
// Point ids are 32-bit in the kernels (pcs::SurfaceMesh).
constexpr vtkIdType MaximumNumberOfPoints = 500000000;

inline double Distance(const double* a, const double* b)
{
  return std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
}

// Six times the signed volume of the tetrahedron (origin, a, b, c): positive when a, b, c turn
// counterclockwise seen from the side away from the origin.
inline double TetrahedronVolume6(const double* origin,
  const double* a,
  const double* b,
  const double* c)
{
  double u[3], v[3], w[3], vw[3];
  vtkMath::Subtract(a, origin, u);
  vtkMath::Subtract(b, origin, v);
  vtkMath::Subtract(c, origin, w);
  vtkMath::Cross(v, w, vw);
  return vtkMath::Dot(u, vw);
}

// Axis-aligned bounding box (xmin, xmax, ymin, ymax, zmin, zmax) of the points `ids` of `xyz`.
void BoundingBox(const double* xyz, const int32_t* ids, size_t count, double box[6])
{
  for (int c = 0; c < 3; ++c)
  {
    box[2 * c] = std::numeric_limits<double>::infinity();
    box[2 * c + 1] = -std::numeric_limits<double>::infinity();
  }
  for (size_t i = 0; i < count; ++i)
  {
    const double* p = xyz + 3 * static_cast<size_t>(ids[i]);
    for (int c = 0; c < 3; ++c)
    {
      box[2 * c] = std::min(box[2 * c], p[c]);
      box[2 * c + 1] = std::max(box[2 * c + 1], p[c]);
    }
  }
}

// Closed boxes with a common point.
bool BoxesOverlap(const double a[6], const double b[6])
{
  return a[0] <= b[1] && b[0] <= a[1] && a[2] <= b[3] && b[2] <= a[3] && a[4] <= b[5] &&
    b[4] <= a[5];
}

// Distance between the segments pq and rs (floating point; a metric threshold only).
double SegmentDistance(const double* p, const double* q, const double* r, const double* s)
{
  double u[3], v[3], w[3];
  vtkMath::Subtract(q, p, u);
  vtkMath::Subtract(s, r, v);
  vtkMath::Subtract(p, r, w);
  const double a = vtkMath::Dot(u, u), b = vtkMath::Dot(u, v), c = vtkMath::Dot(v, v);
  const double d = vtkMath::Dot(u, w), e = vtkMath::Dot(v, w);
  const double denominator = a * c - b * b;
  double sN, sD = denominator, tN, tD = denominator;
  if (denominator <= 1e-14 * a * c)
  {
    sN = 0.0;
    sD = 1.0;
    tN = e;
    tD = c;
  }
  else
  {
    sN = b * e - c * d;
    tN = a * e - b * d;
    if (sN < 0.0)
    {
      sN = 0.0;
      tN = e;
      tD = c;
    }
    else if (sN > sD)
    {
      sN = sD;
      tN = e + b;
      tD = c;
    }
  }
  if (tN < 0.0)
  {
    tN = 0.0;
    sN = std::min(std::max(-d, 0.0), a);
    sD = a > 0 ? a : 1.0;
  }
  else if (tN > tD)
  {
    tN = tD;
    sN = std::min(std::max(b - d, 0.0), a);
    sD = a > 0 ? a : 1.0;
  }
  const double sc = std::fabs(sN) > 0 && sD > 0 ? sN / sD : 0.0;
  const double tc = std::fabs(tN) > 0 && tD > 0 ? tN / tD : 0.0;
  double delta[3];
  for (int i = 0; i < 3; ++i)
  {
    delta[i] = w[i] + sc * u[i] - tc * v[i];
  }
  return vtkMath::Norm(delta);
}

//------------------------------------------------------------------------------------------------
// The reconstruction of one cloud, on its distinct finite points (local ids 0..n-1).
class Reconstruction
{
public:
  vtkGreedySurfaceTriangulation* Self;
  std::vector<double> X; // 3 per local point
  int32_t N = 0;
  int K = 0;
  std::vector<int32_t> Neighbors; // K per point, nearest first, -1 padded
  // Scan-line stretch (3 per point, pcs::AddOffLineNeighbors), empty when no row was extended.
  std::vector<double> Stretch;
  std::vector<double> Uniformity;
  double MedianUniformity = NaN;
  std::vector<double> Normals; // 3 per point (unoriented), for the projected crossing test
  std::vector<char> CrossingPoints; // the points whose edges it tests (empty: every point)
  double Spacing = 0.0;
  // X = input coordinates x 2^CoordinateExponent (0 unless the coordinates are extreme, see
  // RequestData and pcsCoordinateScaling.h).
  int CoordinateExponent = 0;
  vtkSmartPointer<vtkStaticPointLocator> Locator;
  vtkSmartPointer<vtkPolyData> Cloud;

  // Step 1.
  std::vector<int32_t> Step1Triangles;
  // Step 2 onwards.
  pcs::SurfaceMesh Mesh;
  std::vector<uint8_t> Status;         // vtkGreedySurfaceTriangulation::PointStatus
  std::vector<uint8_t> Stage;          // per mesh triangle id
  std::vector<int32_t> Component;      // per vertex (-1 without triangles)
  std::vector<double> BoundaryVectors; // 3 per vertex (boundary vertices only), smoothed over b
  std::vector<double> EdgeVectors;     // the same from the vertex's own two edges (step 5)
  std::vector<std::array<int32_t, 2>> Links; // bridges and chords (step 7)
  std::vector<int32_t> Dissolved;            // the points of the islands step 2 dissolved
  std::vector<char> InsertedPoints;          // per point, by InsertLostPoints (empty: none)

  // Loops (steps 3 to 6).
  struct Node
  {
    int32_t Vertex;
    int32_t Next, Prev;
    int32_t Loop; // original loop
  };
  std::vector<Node> Nodes;
  std::vector<int32_t> NodeOf; // per vertex, -1 when not on a loop
  std::vector<char> LoopIsHole;
  std::vector<std::vector<int32_t>> FinalLoops; // node sequences after step 4
  std::vector<char> FinalIsHole;
  struct Band
  {
    std::vector<int32_t> First, Second; // two original loops, from the ends of their gap
    std::vector<int32_t> Triangles;     // the strip (ZipBand)
    std::vector<std::array<int32_t, 2>> Gaps;
  };
  std::vector<Band> Bands; // narrow bands between two loops (Step4Bridges, FillBands)

  // Counts.
  vtkIdType LostPoints = 0, Islands = 0, Holes = 0, Bridges = 0, Chords = 0, HolesFilled = 0,
            HolesLeftOpen = 0, Swaps = 0, ObtuseSwaps = 0, Inserted = 0, Added = 0, LoopsClosed = 0,
            LoopsFilledByDihedral = 0, EndsCapped = 0, Grown = 0, FillsRefused = 0,
            PiecesExchanged = 0;
  bool Aborted = false;
  struct LongTriangle
  {
    int32_t Ids[3];
    double Box[6];
  };
  std::vector<LongTriangle> LongTriangles; // FillMeetsMesh's triangles beyond its pad
  // LongTriangles by the cells (of the pad's size) their boxes overlap, those over more than
  // LongCellsLimit cells listed apart (Oversized): FillMeetsMesh tests only the long triangles
  // whose cells a fill triangle's box overlaps (all of them grew with the cloud: quadratic).
  std::unordered_map<int64_t, std::vector<int32_t>> LongCells;
  std::vector<int32_t> OversizedLong;
  mutable std::vector<int64_t> LongStamp; // per long triangle: the query that last tested it
  mutable int64_t LongQuery = 0;
  bool LongCellRange(const double box[6], int64_t range[6]) const;
  static int64_t LongCellKey(int64_t i, int64_t j, int64_t k)
  {
    return (i & 0x1FFFFF) | ((j & 0x1FFFFF) << 21) | ((k & 0x1FFFFF) << 42);
  }
  std::vector<char> OnRefusedLoop;         // per vertex: on a hole whose fill step 6 refused
  bool OnRefusedLoopAny(const std::vector<int32_t>& loop) const
  {
    for (int32_t v : loop)
    {
      if (!this->OnRefusedLoop.empty() && this->OnRefusedLoop[v])
      {
        return true;
      }
    }
    return false;
  }

  const double* P(int32_t i) const { return &this->X[3 * static_cast<size_t>(i)]; }
  double SamplingDistance(int32_t a, int32_t b) const;
  void UseSamplingMetric(pcs::holes::HoleFiller& filler) const;

  bool Progress(double fraction)
  {
    this->Self->UpdateProgress(fraction);
    this->Aborted = this->Aborted || this->Self->GetAbortExecute();
    return !this->Aborted;
  }

  void FindNeighbors(double begin, double end);
  void ExtendNeighbors();
  void ComputeUniformity();
  void ComputeNormals(bool local);
  void Step1GreedyEdges(double begin, double end);
  void Step2Umbrella(double begin, double end);
  void GrowRegions(double begin, double end, bool expandFront);
  void RemoveSmallOpenGrownParts();
  void RemoveGrownFlaps();
  vtkIdType TakeBetterPieces(const Reconstruction& other, bool tiesOnly, bool checkEach);
  void Topology(int64_t& components, int64_t& handles) const;
  void TakeBack(int64_t t);
  void Step3Status();
  struct BridgeCandidate
  {
    double Length;
    int32_t A, B;
  };
  std::vector<BridgeCandidate> BridgeCandidates(double limit) const;
  void Step4Bridges();
  void Step6FillHoles(double begin, double end);
  void RecordFill(const pcs::holes::FillResult& result);
  void CollectLongTriangles();
  void AccountForFill(const std::vector<int32_t>& triangles);
  bool FarApart(const int32_t* f, const int32_t* g) const;
  bool FillMeetsMesh(const std::vector<int32_t>& fill) const;
  bool FillsMeet(const std::vector<int32_t>& first, const std::vector<int32_t>& second) const;
  bool LeastDihedralFill(const std::vector<int32_t>& loop,
    double maximumDihedral,
    std::vector<int32_t>& triangles);
  void InsertLostPoints(double begin, double end);
  void CloseSharpEars(int32_t start);
  void CloseSmallLoops();
  bool FillOpenLoop(const pcs::holes::HoleFiller& filler, const std::vector<int32_t>& loop,
    const double centre[3], double radius, double maximumDihedral, bool& byDihedral);
  void LostFreePointsNear(const double centre[3],
    double radius,
    vtkIdList* near,
    std::vector<int32_t>& candidates) const;
  void CapOpenEnds();
  bool IsNaturalBorder(const std::vector<int32_t>& loop, const double centre[3], double radius);
  bool IsWidePlanarRim(
    const std::vector<int32_t>& loop, double radius, pcs::holes::Plane& plane) const;
  bool TangentNormal(int32_t v, double normal[3]) const;
  void MeshHalfEdge(const std::vector<int32_t>& loop, size_t i, int32_t& a, int32_t& b) const;
  void PieceAreasAndVolumes(const std::vector<int32_t>& piece,
    const std::vector<std::vector<int32_t>>& loops,
    std::vector<double>& area,
    std::vector<double>& volume) const;
  bool CapsWellMouth(const std::vector<int32_t>& loop,
    const double centre[3],
    double radius,
    double area,
    double volume) const;
  double CapFoldAngle(const std::vector<int32_t>& loop,
    const double centre[3],
    double outward) const;
  void Step7Swaps();
  bool SwapEdge(int32_t a, int32_t b, uint8_t stage, bool byAngle, int64_t made[2]);
  void TriangleNormal(int32_t a, int32_t b, int32_t c, double n[3]) const;
  void AngleCosines(int32_t a, int32_t b, int32_t c, double cosines[3]) const;
  double LargestCosine(int32_t a, int32_t b, int32_t c) const;
  void SwapObtuseEdges();
  void OrientOutwards();
  void RefineAndFairFills(std::vector<int32_t>& triangles, std::vector<uint8_t>& stages,
    std::vector<double>& added, double begin, double end);

private:
  enum class Umbrella
  {
    None,
    Closed,
    Open,
    Fail
  };
  Umbrella CheckUmbrella(int32_t v, const std::vector<int64_t>& offsets,
    const std::vector<int32_t>& vertexTriangles, const std::vector<char>& alive) const;
  bool IsHole(const std::vector<int32_t>& vertices) const;
  void ComputeComponents();
  std::vector<int32_t> VertexPieces() const;
  void ClearPinches(std::vector<int32_t>& pending);
  void SheetNormal(int32_t v, int64_t t0, int64_t t1, double normal[3]) const;
  bool LeavesSheetsAtBothEnds(int32_t u, int32_t v, int64_t t0, int64_t t1) const;
  void FillBands();
  bool ZipBand(Band& band) const;
  bool RunsAlongside(const std::vector<int32_t>& a, const std::vector<int32_t>& b) const;
  void RemoveHandleStrips();
  bool ConnectedAroundEdge(int32_t u,
    int32_t v,
    int64_t t0,
    int64_t t1,
    std::vector<uint32_t>& seen,
    uint32_t& stamp) const;
};

//------------------------------------------------------------------------------------------------
// K nearest neighbours of every point (vtkStaticPointLocator, nearest first), in blocks so that
// progress and abort are handled between threaded passes.
void Reconstruction::FindNeighbors(double begin, double end)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetArray(this->X.data(), 3 * static_cast<vtkIdType>(this->N), 1);
  points->SetData(coordinates);
  this->Cloud = vtkSmartPointer<vtkPolyData>::New();
  this->Cloud->SetPoints(points);
  this->Locator = vtkSmartPointer<vtkStaticPointLocator>::New();
  // A surface sample fills a thin layer of the bins of its box: about 4 bins per point keep
  // the neighbour queries (ours, the bridge and hole searches) short.
  double bounds[6];
  points->GetBounds(bounds);
  pcs::SetSurfaceSampleDivisions(this->Locator, bounds, this->N);
  this->Locator->SetDataSet(this->Cloud);
  this->Locator->BuildLocator();

  const int k = this->K;
  if (!pcs::FindNearestNeighbors(this->Locator, this->X.data(), this->N, k, this->Neighbors,
        [&](double fraction) { return this->Progress(begin + (end - begin) * fraction); }))
  {
    this->Aborted = true; // (the progress callback stopped it)
  }
}

// The neighbour table extended on scan lines, then the mean spacing.
void Reconstruction::ExtendNeighbors()
{
  const int k = this->K;

  // Scan-line sampling: a point whose K / 2 nearest lie along one line, as do those of half of
  // its K nearest, also gets the nearest points of the lines beside it, and its stretch
  // (pcsNearestNeighbors.h). The share keeps the few points of an ordinary sample that happen to
  // lie along a curve as they were: the paper's Euclidean greedy triangulation is right there.
  if (pcs::AddOffLineNeighbors(this->Locator,
        this->X.data(),
        this->N,
        k,
        this->Neighbors,
        &this->Stretch,
        0.05,
        4.0,
        ScanLineShare) <= 0)
  {
    this->Stretch.clear();
  }
  // The mean spacing: the mean distance to the nearest neighbour, in the sampling's metric on
  // scan lines (SamplingDistance: there the spacing across the lines).
  double sum = 0.0;
  vtkIdType counted = 0;
  for (int32_t i = 0; i < this->N; ++i)
  {
    const int32_t* row = &this->Neighbors[static_cast<size_t>(i) * k];
    if (row[0] < 0)
    {
      continue;
    }
    double nearest = Distance(this->P(i), this->P(row[0]));
    if (!this->Stretch.empty())
    {
      nearest = VTK_DOUBLE_MAX;
      for (int j = 0; j < k && row[j] >= 0; ++j)
      {
        nearest = std::min(nearest, this->SamplingDistance(i, row[j]));
      }
    }
    sum += nearest;
    ++counted;
  }
  this->Spacing = counted > 0 ? sum / counted : 0.0;
}

// The length of the edge ab in the sampling's metric (pcs::StretchedLength2): Euclidean, except
// on scan lines, where the spacing along a line measures about the spacing across the lines.
double Reconstruction::SamplingDistance(int32_t a, int32_t b) const
{
  if (this->Stretch.empty())
  {
    return Distance(this->P(a), this->P(b));
  }
  double w[3];
  vtkMath::Subtract(this->P(b), this->P(a), w);
  return std::sqrt(pcs::StretchedLength2(
    w, &this->Stretch[3 * static_cast<size_t>(a)], &this->Stretch[3 * static_cast<size_t>(b)]));
}

// On scan lines, step 6's 2D greedy triangulation orders its edges in the sampling's metric too
// (SamplingDistance; 3D lengths for points added after the input's), as step 1 does: with 3D
// lengths it joined the points of a line first, a fan of slivers along it.
void Reconstruction::UseSamplingMetric(pcs::holes::HoleFiller& filler) const
{
  if (this->Stretch.empty())
  {
    return;
  }
  filler.Length2 = [this](int32_t a, int32_t b)
  {
    if (a < 0 || b < 0 || a >= this->N || b >= this->N)
    {
      return -1.0;
    }
    const double length = this->SamplingDistance(a, b);
    return length * length;
  };
}

// The local uniformity factor m of paper section 3 (see the class documentation).
void Reconstruction::ComputeUniformity()
{
  const int k = this->K;
  const int wanted = this->Self->GetUniformityNeighbors();
  const double cosine = std::cos(vtkMath::RadiansFromDegrees(this->Self->GetUniformityAngle()));
  this->Uniformity.assign(this->N, NaN);
  vtkSMPTools::For(0, this->N, [&](int32_t b, int32_t e) {
    std::vector<double> admitted;
    for (int32_t i = b; i < e; ++i)
    {
      admitted.clear();
      double longest = 0.0, shortest = VTK_DOUBLE_MAX;
      for (int j = 0; j < k && static_cast<int>(admitted.size() / 3) < wanted; ++j)
      {
        const int32_t q = this->Neighbors[static_cast<size_t>(i) * k + j];
        if (q < 0)
        {
          break;
        }
        double v[3];
        vtkMath::Subtract(this->P(q), this->P(i), v);
        const double length = vtkMath::Norm(v);
        if (!(length > 0))
        {
          continue;
        }
        vtkMath::MultiplyScalar(v, 1.0 / length);
        bool separate = true;
        for (size_t a = 0; a < admitted.size() && separate; a += 3)
        {
          separate = vtkMath::Dot(v, &admitted[a]) <= cosine;
        }
        if (separate)
        {
          admitted.insert(admitted.end(), v, v + 3);
          longest = std::max(longest, length);
          shortest = std::min(shortest, length);
        }
      }
      if (admitted.size() >= 6)
      {
        this->Uniformity[i] = longest / shortest;
      }
    }
  });
}

// Unoriented normals of the points, for the crossing test: the planes of the shared estimator
// (pcs::EstimatePlaneNormals) over each point and its K nearest points, from the neighbour table
// already made (vtkPCANormalEstimation with SampleSize K + 1 searched the same neighbours again,
// point by point: about half of the filter's CPU time on noisy clouds). With `nearLost`
// (automatic mode, after the first pass with the paper's test), the test will examine only the
// edges at the points that pass lost and at their nearest neighbours (CrossingPoints):
// elsewhere the paper's test alone gave correct umbrellas.
void Reconstruction::ComputeNormals(bool nearLost)
{
  this->CrossingPoints.clear();
  if (nearLost)
  {
    this->CrossingPoints.assign(this->N, 0);
    for (int32_t v = 0; v < this->N; ++v)
    {
      if (this->Status[v] != vtkGreedySurfaceTriangulation::LOST)
      {
        continue;
      }
      this->CrossingPoints[v] = 1;
      const int32_t* list = &this->Neighbors[static_cast<size_t>(v) * this->K];
      for (int j = 0; j < this->K && list[j] >= 0; ++j)
      {
        this->CrossingPoints[list[j]] = 1;
      }
    }
  }
  std::vector<double> variation; // not used by the crossing test
  pcs::EstimatePlaneNormals(
    this->X.data(), this->N, this->Neighbors, this->K, this->Normals, variation);
}

//------------------------------------------------------------------------------------------------
// Step 1: 3D greedy triangulation with the topological compatibility test.
//
// The step works on the points renumbered along a Hilbert curve (pcs::HilbertSort): the edges are
// taken in order of length, from all over the cloud, and each test reads the lists and positions
// of the points around its edge, which in the cloud's own order lie anywhere in memory (cache
// misses made this step 47 % of the CPU on 10^6 random sphere points, against 10 % at 10^5). In
// curve order they are near each other. Edges are sorted, ties broken, and triangles reported
// with the cloud's ids, so the result does not depend on the renumbering.
void Reconstruction::Step1GreedyEdges(double begin, double end)
{
  const int k = this->K;
  struct Edge
  {
    float Length;
    int32_t A, B; // the cloud's ids, A < B
  };
  // Curve order: the cloud id of each position, the position of each cloud id.
  std::vector<int32_t> cloudId(static_cast<size_t>(this->N));
  std::iota(cloudId.begin(), cloudId.end(), 0);
  pcs::HilbertSort(this->X.data(), 3, cloudId.data(), cloudId.data() + cloudId.size());
  std::vector<int32_t> position(static_cast<size_t>(this->N));
  std::vector<double> xyz(3 * static_cast<size_t>(this->N));
  for (int32_t i = 0; i < this->N; ++i)
  {
    position[cloudId[i]] = i;
    std::copy_n(this->P(cloudId[i]), 3, &xyz[3 * static_cast<size_t>(i)]);
  }
  std::vector<int32_t> neighbors(static_cast<size_t>(this->N) * k);
  for (int32_t i = 0; i < this->N; ++i)
  {
    const int32_t* list = &this->Neighbors[static_cast<size_t>(cloudId[i]) * k];
    for (int j = 0; j < k; ++j)
    {
      neighbors[static_cast<size_t>(i) * k + j] = list[j] < 0 ? -1 : position[list[j]];
    }
  }
  auto at = [&xyz](int32_t i) { return &xyz[3 * static_cast<size_t>(i)]; };

  // Candidate edges: each point to its neighbours, each pair once (a pair listed both ways from
  // the smaller cloud id; the length measured from the point that lists the other).
  std::vector<int64_t> offsets(static_cast<size_t>(this->N) + 1, 0);
  std::vector<Edge> edges;
  edges.reserve(static_cast<size_t>(this->N) * k * 3 / 4);
  for (int32_t i = 0; i < this->N; ++i)
  {
    const int32_t* mine = &neighbors[static_cast<size_t>(i) * k];
    for (int j = 0; j < k && mine[j] >= 0; ++j)
    {
      const int32_t q = mine[j];
      const int32_t ci = cloudId[i], cq = cloudId[q];
      if (ci > cq)
      {
        const int32_t* theirs = &neighbors[static_cast<size_t>(q) * k];
        if (std::find(theirs, theirs + k, i) != theirs + k)
        {
          continue;
        }
      }
      const double length =
        this->Stretch.empty() ? Distance(at(i), at(q)) : this->SamplingDistance(ci, cq);
      edges.push_back({ static_cast<float>(length), std::min(ci, cq), std::max(ci, cq) });
      ++offsets[i + 1];
      ++offsets[q + 1];
    }
  }
  if (!this->Progress(begin + 0.1 * (end - begin)))
  {
    return;
  }
  vtkSMPTools::Sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
    return a.Length != b.Length ? a.Length < b.Length : (a.A != b.A ? a.A < b.A : a.B < b.B);
  });
  if (!this->Progress(begin + 0.3 * (end - begin)))
  {
    return;
  }

  // Accepted edges: per vertex, room for all its candidate edges; triangle count per edge end.
  for (int32_t i = 0; i < this->N; ++i)
  {
    offsets[i + 1] += offsets[i];
  }
  std::vector<int32_t> adjacent(offsets.back());
  std::vector<uint8_t> triangles(offsets.back(), 0);
  std::vector<int32_t> degree(this->N, 0);
  auto slot = [&](int32_t a, int32_t b) -> int64_t {
    for (int64_t s = offsets[a], e = offsets[a] + degree[a]; s < e; ++s)
    {
      if (adjacent[s] == b)
      {
        return s;
      }
    }
    return -1;
  };

  // Optional guard: in the tangent plane of a and b (mean of their PCA normals), the new edge
  // must not cross an accepted edge at a neighbour of a or b (exact 2D tests on the projected
  // points). All accepted edges are shorter, so an edge crossing ab has an end point near a or b.
  const bool crossing = !this->Normals.empty();
  // The points near a and b are marked with a stamp (no sort), their projections computed once.
  std::vector<int32_t> near;
  std::vector<double> nearUV;
  std::vector<uint32_t> mark(crossing ? this->N : 0, 0);
  std::vector<int32_t> nearIndex(crossing ? this->N : 0, 0);
  uint32_t stamp = 0;
  std::vector<double> normals(crossing ? 3 * static_cast<size_t>(this->N) : 0);
  for (int32_t i = 0; crossing && i < this->N; ++i)
  {
    std::copy_n(
      &this->Normals[3 * static_cast<size_t>(cloudId[i])], 3, &normals[3 * static_cast<size_t>(i)]);
  }
  // Every accepted edge is no longer than ab (edges by length; `reach` bounds their lengths,
  // a hair above ab's), so only the points whose projections are within `reach` of ab's box can
  // have an edge that crosses ab: the others' edges are not examined.
  std::vector<char> nearReaches;
  auto crosses = [&](int32_t a, int32_t b, double reach)
  {
    const double* na = &normals[3 * static_cast<size_t>(a)];
    const double* nb = &normals[3 * static_cast<size_t>(b)];
    double n[3];
    const double s = vtkMath::Dot(na, nb) < 0 ? -1.0 : 1.0;
    for (int i = 0; i < 3; ++i)
    {
      n[i] = na[i] + s * nb[i];
    }
    if (!(vtkMath::Normalize(n) > 0))
    {
      return false;
    }
    double u[3], w[3];
    vtkMath::Perpendiculars(n, u, w, 0.0);
    const double* pa = at(a);
    auto project = [&](int32_t x, double q[2]) {
      double d[3];
      vtkMath::Subtract(at(x), pa, d);
      q[0] = vtkMath::Dot(d, u);
      q[1] = vtkMath::Dot(d, w);
    };
    const double qa[2] = { 0.0, 0.0 };
    double qb[2];
    project(b, qb);
    const double lo[2] = { std::min(qa[0], qb[0]), std::min(qa[1], qb[1]) };
    const double hi[2] = { std::max(qa[0], qb[0]), std::max(qa[1], qb[1]) };
    if (++stamp == 0)
    {
      std::fill(mark.begin(), mark.end(), 0);
      stamp = 1;
    }
    near.clear();
    nearUV.clear();
    nearReaches.clear();
    auto add = [&](int32_t x) {
      if (x >= 0 && x != a && x != b && mark[x] != stamp)
      {
        mark[x] = stamp;
        nearIndex[x] = static_cast<int32_t>(near.size());
        near.push_back(x);
        double q[2];
        project(x, q);
        nearUV.push_back(q[0]);
        nearUV.push_back(q[1]);
        const double dx = std::max({ lo[0] - q[0], 0.0, q[0] - hi[0] });
        const double dy = std::max({ lo[1] - q[1], 0.0, q[1] - hi[1] });
        nearReaches.push_back(dx * dx + dy * dy <= reach * reach ? 1 : 0);
      }
    };
    for (int32_t x : { a, b })
    {
      const int32_t* list = &neighbors[static_cast<size_t>(x) * k];
      for (int j = 0; j < k; ++j)
      {
        add(list[j]);
      }
      for (int64_t s2 = offsets[x], e2 = offsets[x] + degree[x]; s2 < e2; ++s2)
      {
        add(adjacent[s2]);
      }
    }
    for (size_t i = 0; i < near.size(); ++i)
    {
      if (!nearReaches[i])
      {
        continue;
      }
      const int32_t c = near[i];
      const double* qc = &nearUV[2 * i];
      for (int64_t s2 = offsets[c], e2 = offsets[c] + degree[c]; s2 < e2; ++s2)
      {
        const int32_t d = adjacent[s2];
        const bool marked = mark[d] == stamp;
        if (d == a || d == b || (marked && d < c && nearReaches[nearIndex[d]]))
        {
          continue; // shares an end point, or tested from d
        }
        double projected[2];
        const double* qd = projected;
        if (marked)
        {
          qd = &nearUV[2 * static_cast<size_t>(nearIndex[d])];
        }
        else
        {
          project(d, projected);
        }
        if (std::max(qc[0], qd[0]) < lo[0] || std::min(qc[0], qd[0]) > hi[0] ||
          std::max(qc[1], qd[1]) < lo[1] || std::min(qc[1], qd[1]) > hi[1])
        {
          continue;
        }
        if (pcs::holes::SegmentsIntersect(qa, qb, qc, qd))
        {
          return true;
        }
      }
    }
    return false;
  };

  // A triangle abc standing across the surface (issue 7): its angle at c above 150 degrees, its
  // normal more than 70 degrees from the unoriented normals of a, b and c, and the nearest points
  // of a, b and c on both sides of its plane, farther than half of ab. Three points of a sampling
  // line that curves out of the surface (a circle around a torus's tube, sampled more densely than
  // the circles are apart) make one: in the tangent plane it projects onto a segment with c on it,
  // a tie that the exact crossing test on rounded projections cannot decide. On a sharp edge, where
  // the normals are those of neither side, a sliver of the face beyond has that face's points in
  // its plane and the other face's on one side only: it is not refused.
  auto stands = [&](int32_t a, int32_t b, int32_t c)
  {
    double ca[3], cb[3], t[3];
    vtkMath::Subtract(at(a), at(c), ca);
    vtkMath::Subtract(at(b), at(c), cb);
    if (!(vtkMath::Dot(ca, cb) <
          StandingAngleCosine * std::sqrt(vtkMath::Dot(ca, ca) * vtkMath::Dot(cb, cb))))
    {
      return false;
    }
    vtkMath::Cross(ca, cb, t);
    if (!(vtkMath::Normalize(t) > 0))
    {
      return false;
    }
    for (int32_t x : { a, b, c })
    {
      if (std::abs(vtkMath::Dot(t, &normals[3 * static_cast<size_t>(x)])) >= StandingCosine)
      {
        return false;
      }
    }
    const double reach = StandingSides * Distance(at(a), at(b));
    bool above = false, below = false;
    for (int32_t x : { a, b, c })
    {
      const int32_t* list = &neighbors[static_cast<size_t>(x) * k];
      for (int j = 0; j < k && list[j] >= 0 && !(above && below); ++j)
      {
        double w[3];
        vtkMath::Subtract(at(list[j]), at(c), w);
        const double h = vtkMath::Dot(w, t);
        above = above || h > reach;
        below = below || h < -reach;
      }
    }
    return above && below;
  };

  std::vector<int32_t>& result = this->Step1Triangles;
  result.clear();
  result.reserve(2 * static_cast<size_t>(this->N) * 3);
  const size_t count = edges.size();
  for (size_t e = 0; e < count; ++e)
  {
    if ((e & 0xffff) == 0 &&
      !this->Progress(begin + (end - begin) * (0.3 + 0.7 * e / static_cast<double>(count))))
    {
      return;
    }
    const int32_t a = position[edges[e].A], b = position[edges[e].B];
    // Common neighbours: the triangles the edge would close.
    int32_t common[3];
    int64_t commonSlotA[3];
    int numberOfCommon = 0;
    bool compatible = true;
    for (int64_t s = offsets[a], end2 = offsets[a] + degree[a]; s < end2 && compatible; ++s)
    {
      const int32_t c = adjacent[s];
      for (int64_t t = offsets[b], e2 = offsets[b] + degree[b]; t < e2; ++t)
      {
        if (adjacent[t] == c)
        {
          if (numberOfCommon == 2 || triangles[s] >= 2 || triangles[t] >= 2)
          {
            compatible = false; // an edge would get a third triangle
          }
          else
          {
            commonSlotA[numberOfCommon] = s;
            common[numberOfCommon++] = c;
          }
          break;
        }
      }
    }
    if (!compatible)
    {
      continue;
    }
    // Two closed triangles whose third vertices are adjacent would close a tetrahedron.
    if (numberOfCommon == 2 && slot(common[0], common[1]) >= 0)
    {
      continue;
    }
    // Guard: no exactly degenerate triangle.
    bool degenerate = false;
    for (int c = 0; c < numberOfCommon && !degenerate; ++c)
    {
      // Three points of one scan line: a sliver along it (pcs::OnOneScanLine).
      degenerate = pcs::projected::Collinear(at(a), at(b), at(common[c])) ||
        (!this->Stretch.empty() &&
          pcs::OnOneScanLine(
            this->X.data(), this->Stretch.data(), edges[e].A, edges[e].B, cloudId[common[c]]));
    }
    // Guard with the crossing test (issue 7): no triangle standing across the surface made of ab
    // and an accepted edge at a or b (the triangles ab closes among them).
    if (crossing && !degenerate &&
      (this->CrossingPoints.empty() || this->CrossingPoints[edges[e].A] ||
        this->CrossingPoints[edges[e].B]))
    {
      for (int32_t x : { a, b })
      {
        for (int64_t s = offsets[x], e2 = offsets[x] + degree[x]; s < e2 && !degenerate; ++s)
        {
          degenerate = stands(a, b, adjacent[s]);
        }
      }
    }
    if (degenerate)
    {
      continue;
    }
    if (crossing &&
      (this->CrossingPoints.empty() || this->CrossingPoints[edges[e].A] ||
        this->CrossingPoints[edges[e].B]) &&
      crosses(a, b, edges[e].Length * (1.0 + 1e-6)))
    {
      continue;
    }
    adjacent[offsets[a] + degree[a]] = b;
    triangles[offsets[a] + degree[a]++] = static_cast<uint8_t>(numberOfCommon);
    adjacent[offsets[b] + degree[b]] = a;
    triangles[offsets[b] + degree[b]++] = static_cast<uint8_t>(numberOfCommon);
    for (int c = 0; c < numberOfCommon; ++c)
    {
      const int32_t v = common[c];
      ++triangles[commonSlotA[c]];
      ++triangles[slot(v, a)];
      ++triangles[slot(b, v)];
      ++triangles[slot(v, b)];
      result.insert(result.end(), { edges[e].A, edges[e].B, cloudId[v] });
    }
  }
}

//------------------------------------------------------------------------------------------------
// Step 2: the umbrella test of a vertex over its alive triangles.
Reconstruction::Umbrella Reconstruction::CheckUmbrella(int32_t v,
  const std::vector<int64_t>& offsets, const std::vector<int32_t>& vertexTriangles,
  const std::vector<char>& alive) const
{
  // Link edges: the edge opposite v in each triangle.
  constexpr int Capacity = 64;
  int32_t linkA[Capacity], linkB[Capacity];
  int k = 0;
  for (int64_t s = offsets[v]; s < offsets[v + 1]; ++s)
  {
    const int32_t t = vertexTriangles[s];
    if (!alive[t])
    {
      continue;
    }
    if (k == Capacity)
    {
      return Umbrella::Fail;
    }
    const int32_t* tri = &this->Step1Triangles[3 * static_cast<size_t>(t)];
    const int j = tri[0] == v ? 0 : (tri[1] == v ? 1 : 2);
    linkA[k] = tri[(j + 1) % 3];
    linkB[k] = tri[(j + 2) % 3];
    ++k;
  }
  if (k == 0)
  {
    return Umbrella::None;
  }
  // Link vertices and their (at most 2) link edges.
  int32_t vertex[Capacity + 1];
  int edgeOf[Capacity + 1][2];
  int degreeOf[Capacity + 1];
  int m = 0;
  auto index = [&](int32_t x) {
    for (int i = 0; i < m; ++i)
    {
      if (vertex[i] == x)
      {
        return i;
      }
    }
    vertex[m] = x;
    degreeOf[m] = 0;
    return m++;
  };
  for (int e = 0; e < k; ++e)
  {
    for (int32_t x : { linkA[e], linkB[e] })
    {
      const int i = index(x);
      if (degreeOf[i] == 2)
      {
        return Umbrella::Fail; // an edge with a third triangle (cannot happen after step 1)
      }
      edgeOf[i][degreeOf[i]++] = e;
    }
  }
  int ends = 0, start = 0;
  for (int i = 0; i < m; ++i)
  {
    if (degreeOf[i] == 1)
    {
      ++ends;
      start = i;
    }
  }
  if (ends != 0 && ends != 2)
  {
    return Umbrella::Fail; // several chains
  }
  const bool closed = ends == 0;
  // Walk the chain: ordered link vertices.
  int32_t chain[Capacity + 1];
  int length = 0;
  int current = start, previousEdge = -1;
  for (int step = 0; step < k; ++step)
  {
    chain[length++] = vertex[current];
    const int e = (degreeOf[current] == 2 && edgeOf[current][0] == previousEdge)
      ? edgeOf[current][1]
      : edgeOf[current][0];
    if (e == previousEdge)
    {
      break;
    }
    const int32_t other = linkA[e] == vertex[current] ? linkB[e] : linkA[e];
    previousEdge = e;
    current = index(other);
    if (closed && current == start && step + 1 < k)
    {
      return Umbrella::Fail; // back at the start early: several cycles
    }
  }
  if (length != k)
  {
    return Umbrella::Fail; // not connected
  }
  if (!closed)
  {
    chain[length++] = vertex[current];
  }
  else if (vertex[current] != chain[0])
  {
    return Umbrella::Fail;
  }
  // Triangles (v, chain[i], chain[i + 1]) are consistently oriented along the chain.
  const double* pv = this->P(v);
  double normals[Capacity][3];
  double mean[3] = { 0, 0, 0 };
  for (int i = 0; i < k; ++i)
  {
    const int32_t x = chain[i], y = closed ? chain[(i + 1) % k] : chain[i + 1];
    double a[3], b[3];
    vtkMath::Subtract(this->P(x), pv, a);
    vtkMath::Subtract(this->P(y), pv, b);
    vtkMath::Cross(a, b, normals[i]);
    const double length2 = vtkMath::Norm(normals[i]);
    if (!(length2 > 0))
    {
      return Umbrella::Fail;
    }
    vtkMath::MultiplyScalar(normals[i], 1.0 / length2);
    vtkMath::Add(mean, normals[i], mean);
  }
  // Smoothness (paper section 3): pairwise normal deviation.
  const double cosine = std::cos(vtkMath::RadiansFromDegrees(this->Self->GetMaximumNormalDeviation()));
  if (this->Self->GetMaximumNormalDeviation() < 180.0)
  {
    for (int i = 0; i < k; ++i)
    {
      for (int j = i + 1; j < k; ++j)
      {
        if (!(vtkMath::Dot(normals[i], normals[j]) > cosine))
        {
          return Umbrella::Fail;
        }
      }
    }
  }
  // The chain projected onto the plane normal to the mean winds once around v.
  if (!(vtkMath::Normalize(mean) > 0))
  {
    return Umbrella::Fail;
  }
  double u[3], w[3];
  vtkMath::Perpendiculars(mean, u, w, 0.0);
  const double origin[2] = { 0.0, 0.0 };
  double total = 0.0;
  for (int i = 0; i < k; ++i)
  {
    const int32_t x = chain[i], y = closed ? chain[(i + 1) % k] : chain[i + 1];
    double a[3], b[3];
    vtkMath::Subtract(this->P(x), pv, a);
    vtkMath::Subtract(this->P(y), pv, b);
    const double qa[2] = { vtkMath::Dot(a, u), vtkMath::Dot(a, w) };
    const double qb[2] = { vtkMath::Dot(b, u), vtkMath::Dot(b, w) };
    if (pcs::predicates::Orient2D(origin, qa, qb) <= 0)
    {
      return Umbrella::Fail;
    }
    total += std::atan2(qa[0] * qb[1] - qa[1] * qb[0], qa[0] * qb[0] + qa[1] * qb[1]);
  }
  if (closed ? total > 3 * Pi : total >= 2 * Pi)
  {
    return Umbrella::Fail; // the umbrella wraps more than once around the point
  }
  return closed ? Umbrella::Closed : Umbrella::Open;
}

// Step 2: umbrella filtering until stable, then the oriented manifold mesh.
void Reconstruction::Step2Umbrella(double begin, double end)
{
  this->LostPoints = 0;
  this->Dissolved.clear();
  const size_t numberOfTriangles = this->Step1Triangles.size() / 3;
  std::vector<int64_t> offsets(static_cast<size_t>(this->N) + 1, 0);
  for (int32_t v : this->Step1Triangles)
  {
    ++offsets[v + 1];
  }
  for (int32_t i = 0; i < this->N; ++i)
  {
    offsets[i + 1] += offsets[i];
  }
  std::vector<int32_t> vertexTriangles(offsets.back());
  {
    std::vector<int64_t> fill(offsets.begin(), offsets.end() - 1);
    for (size_t t = 0; t < numberOfTriangles; ++t)
    {
      for (int j = 0; j < 3; ++j)
      {
        vertexTriangles[fill[this->Step1Triangles[3 * t + j]]++] = static_cast<int32_t>(t);
      }
    }
  }
  std::vector<char> alive(numberOfTriangles, 1);
  std::vector<char> rejected(this->N, 0);

  // First pass in parallel; then the cascade of the removals, sequentially.
  std::vector<uint8_t> first(this->N);
  vtkSMPTools::For(0, this->N, [&](int32_t b, int32_t e) {
    for (int32_t v = b; v < e; ++v)
    {
      first[v] = static_cast<uint8_t>(this->CheckUmbrella(v, offsets, vertexTriangles, alive));
    }
  });
  if (!this->Progress(begin + 0.4 * (end - begin)))
  {
    return;
  }
  std::vector<int32_t> work;
  std::vector<char> queued(this->N, 0);
  auto reject = [&](int32_t v) {
    rejected[v] = 1;
    for (int64_t s = offsets[v]; s < offsets[v + 1]; ++s)
    {
      const int32_t t = vertexTriangles[s];
      if (!alive[t])
      {
        continue;
      }
      alive[t] = 0;
      for (int j = 0; j < 3; ++j)
      {
        const int32_t x = this->Step1Triangles[3 * static_cast<size_t>(t) + j];
        if (!rejected[x] && !queued[x])
        {
          queued[x] = 1;
          work.push_back(x);
        }
      }
    }
  };
  for (int32_t v = 0; v < this->N; ++v)
  {
    if (first[v] == static_cast<uint8_t>(Umbrella::Fail))
    {
      reject(v);
    }
  }
  while (!work.empty())
  {
    const int32_t v = work.back();
    work.pop_back();
    queued[v] = 0;
    if (!rejected[v] && this->CheckUmbrella(v, offsets, vertexTriangles, alive) == Umbrella::Fail)
    {
      reject(v);
    }
  }
  if (!this->Progress(begin + 0.6 * (end - begin)))
  {
    return;
  }

  // Orientation: breadth-first over the alive triangles through their shared edges; each
  // triangle is added to the oriented mesh with the orientation its parent imposes.
  this->Mesh.Initialize(this->N);
  this->Mesh.ReserveTriangles(static_cast<int64_t>(2.2 * this->N));
  std::vector<char> visited(numberOfTriangles, 0);
  std::vector<std::array<int32_t, 3>> queue;
  auto neighbor = [&](int32_t t, int32_t a, int32_t b) -> int32_t {
    for (int64_t s = offsets[a]; s < offsets[a + 1]; ++s)
    {
      const int32_t u = vertexTriangles[s];
      if (u == t || !alive[u])
      {
        continue;
      }
      const int32_t* tri = &this->Step1Triangles[3 * static_cast<size_t>(u)];
      if (tri[0] == b || tri[1] == b || tri[2] == b)
      {
        return u;
      }
    }
    return -1;
  };
  std::vector<int32_t> queueIds;
  for (size_t seed = 0; seed < numberOfTriangles; ++seed)
  {
    if (!alive[seed] || visited[seed])
    {
      continue;
    }
    visited[seed] = 1;
    queueIds.assign(1, static_cast<int32_t>(seed));
    queue.assign(1, { this->Step1Triangles[3 * seed], this->Step1Triangles[3 * seed + 1],
                      this->Step1Triangles[3 * seed + 2] });
    for (size_t q = 0; q < queue.size(); ++q)
    {
      const std::array<int32_t, 3> tri = queue[q];
      const int32_t t = queueIds[q];
      if (this->Mesh.AddTriangle(tri[0], tri[1], tri[2]) < 0)
      {
        alive[t] = 0; // a Moebius-like orientation conflict: dropped
        continue;
      }
      for (int j = 0; j < 3; ++j)
      {
        const int32_t a = tri[j], b = tri[(j + 1) % 3];
        const int32_t u = neighbor(t, a, b);
        if (u < 0 || visited[u])
        {
          continue;
        }
        visited[u] = 1;
        const int32_t* other = &this->Step1Triangles[3 * static_cast<size_t>(u)];
        const int32_t c = other[0] != a && other[0] != b
          ? other[0]
          : (other[1] != a && other[1] != b ? other[1] : other[2]);
        queue.push_back({ b, a, c }); // traverses the shared edge b -> a
        queueIds.push_back(u);
      }
    }
  }
  // Vertices with several fans (after dropped triangles) lose their triangles, until none.
  std::vector<int32_t> pending;
  for (int32_t v = 0; v < this->N; ++v)
  {
    if (this->Mesh.GetNumberOfFans(v) > 1)
    {
      pending.push_back(v);
    }
  }
  this->ClearPinches(pending);
  this->RemoveHandleStrips();
  this->Stage.assign(static_cast<size_t>(this->Mesh.GetNumberOfTriangleIds()), 1);

  this->Status.assign(this->N, vtkGreedySurfaceTriangulation::LOST);
  for (int32_t v = 0; v < this->N; ++v)
  {
    switch (this->Mesh.GetVertexState(v))
    {
      case pcs::SurfaceMesh::VertexState::Interior:
        this->Status[v] = vtkGreedySurfaceTriangulation::CORRECT;
        break;
      case pcs::SurfaceMesh::VertexState::Boundary:
        this->Status[v] = vtkGreedySurfaceTriangulation::BOUNDARY;
        break;
      default:
        ++this->LostPoints;
        break;
    }
  }
  this->ComputeComponents();

  // Small islands (fewer than MinimumIslandTriangles triangles, except the largest component)
  // are dissolved: their points become lost points of the hole around them.
  const int64_t ids = this->Mesh.GetNumberOfTriangleIds();
  std::vector<int64_t> sizes;
  for (int64_t t = 0; t < ids; ++t)
  {
    if (!this->Mesh.IsTriangleRemoved(t))
    {
      const int32_t c = this->Component[this->Mesh.GetTriangle(t)[0]];
      if (c >= static_cast<int32_t>(sizes.size()))
      {
        sizes.resize(c + 1, 0);
      }
      ++sizes[c];
    }
  }
  const int64_t minimum = this->Self->GetMinimumIslandTriangles();
  const size_t largest = sizes.empty() ? 0 : std::max_element(sizes.begin(), sizes.end()) - sizes.begin();
  bool dissolved = false;
  for (int64_t t = 0; t < ids; ++t)
  {
    if (this->Mesh.IsTriangleRemoved(t))
    {
      continue;
    }
    const int32_t c = this->Component[this->Mesh.GetTriangle(t)[0]];
    if (static_cast<size_t>(c) != largest && sizes[c] < minimum)
    {
      this->Mesh.RemoveTriangle(t);
      dissolved = true;
    }
  }
  if (dissolved)
  {
    for (int32_t v = 0; v < this->N; ++v)
    {
      if (this->Status[v] != vtkGreedySurfaceTriangulation::LOST && this->Mesh.IsFree(v))
      {
        this->Status[v] = vtkGreedySurfaceTriangulation::LOST;
        this->Dissolved.push_back(v);
        ++this->LostPoints;
      }
    }
    this->ComputeComponents();
  }
}

// The vertices of `pending` with several fans lose their triangles, and so do the vertices
// left with several fans by that, until none.
void Reconstruction::ClearPinches(std::vector<int32_t>& pending)
{
  std::vector<int64_t> around;
  while (!pending.empty())
  {
    const int32_t v = pending.back();
    pending.pop_back();
    if (this->Mesh.GetNumberOfFans(v) <= 1)
    {
      continue;
    }
    around.resize(std::max(this->Mesh.GetVertexDegree(v), 1));
    const int count =
      this->Mesh.GetVertexTriangles(v, around.data(), static_cast<int>(around.size()));
    for (int i = 0; i < count; ++i)
    {
      const int32_t* tri = this->Mesh.GetTriangle(around[i]);
      const int32_t others[3] = { tri[0], tri[1], tri[2] };
      this->Mesh.RemoveTriangle(around[i]);
      for (int32_t x : others)
      {
        if (x != v && this->Mesh.GetNumberOfFans(x) > 1)
        {
          pending.push_back(x);
        }
      }
    }
  }
}

// The unit normal of the triangles at v other than t0 and t1, summed weighted by their areas
// (zero when there are none).
void Reconstruction::SheetNormal(int32_t v, int64_t t0, int64_t t1, double normal[3]) const
{
  normal[0] = normal[1] = normal[2] = 0.0;
  constexpr int Capacity = 64;
  int64_t around[Capacity];
  const int count = this->Mesh.GetVertexTriangles(v, around, Capacity);
  for (int i = 0; i < std::min(count, Capacity); ++i)
  {
    if (around[i] == t0 || around[i] == t1)
    {
      continue;
    }
    const int32_t* tri = this->Mesh.GetTriangle(around[i]);
    double a[3], b[3], n[3];
    vtkMath::Subtract(this->P(tri[1]), this->P(tri[0]), a);
    vtkMath::Subtract(this->P(tri[2]), this->P(tri[0]), b);
    vtkMath::Cross(a, b, n);
    vtkMath::Add(normal, n, normal);
  }
  vtkMath::Normalize(normal);
}

// Whether the edge uv of the triangles t0 and t1 makes more than 30 degrees with the tangent
// planes of u and of v (SheetNormal: their triangles other than t0 and t1).
bool Reconstruction::LeavesSheetsAtBothEnds(int32_t u, int32_t v, int64_t t0, int64_t t1) const
{
  static const double steep = std::sin(vtkMath::RadiansFromDegrees(30.0));
  double chord[3], nu[3], nv[3];
  vtkMath::Subtract(this->P(v), this->P(u), chord);
  vtkMath::Normalize(chord);
  this->SheetNormal(u, t0, t1, nu);
  this->SheetNormal(v, t0, t1, nv);
  return std::abs(vtkMath::Dot(nu, chord)) > steep && std::abs(vtkMath::Dot(nv, chord)) > steep;
}

// Step 4 (issue 7): whether the loop `a` runs alongside the loop `b` across a narrow band of
// missing surface: for at least half of the points v of `a`, the nearest point q of `b` is within
// MaximumBridgeLength spacings and the gap v -> q runs along the surface, within 30 degrees of v's
// tangent plane (the area-weighted normal of v's triangles), as the gap between the two rims of a
// band around a thin part does; across the space between two facing sheets (two holes facing each
// other) it leaves the surface. Half, not all: step 2 leaves the rims ragged, a few spacings
// farther apart in places than the band is wide. Quadratic in the loop sizes.
bool Reconstruction::RunsAlongside(const std::vector<int32_t>& a,
  const std::vector<int32_t>& b) const
{
  const double limit = this->Self->GetMaximumBridgeLength() * this->Spacing;
  const double flat = std::sin(vtkMath::RadiansFromDegrees(30.0));
  size_t along = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    const double* p = this->P(a[i]);
    int32_t nearest = -1;
    double best = limit * limit;
    for (int32_t q : b)
    {
      const double d = vtkMath::Distance2BetweenPoints(p, this->P(q));
      if (d <= best)
      {
        best = d;
        nearest = q;
      }
    }
    if (nearest >= 0)
    {
      double gap[3], normal[3];
      vtkMath::Subtract(this->P(nearest), p, gap);
      this->SheetNormal(a[i], -1, -1, normal);
      along += vtkMath::Normalize(gap) > 0 && std::abs(vtkMath::Dot(gap, normal)) <= flat ? 1 : 0;
    }
    if (2 * (along + a.size() - 1 - i) < a.size())
    {
      return false; // half out of reach
    }
  }
  return 2 * along >= a.size();
}

// Whether the triangles t0 and t1 on the two sides of the edge uv stay connected through their
// edges when uv is cut. Breadth-first from both sides in turn, so that a cut that separates a
// small piece costs the size of that piece. `seen` (per triangle id) holds marks above `stamp`
// for the two sides, and `stamp` is advanced past them.
bool Reconstruction::ConnectedAroundEdge(int32_t u,
  int32_t v,
  int64_t t0,
  int64_t t1,
  std::vector<uint32_t>& seen,
  uint32_t& stamp) const
{
  if (seen.size() < static_cast<size_t>(this->Mesh.GetNumberOfTriangleIds()))
  {
    seen.resize(static_cast<size_t>(this->Mesh.GetNumberOfTriangleIds()), 0);
  }
  if (stamp > std::numeric_limits<uint32_t>::max() - 3)
  {
    std::fill(seen.begin(), seen.end(), 0);
    stamp = 0;
  }
  const uint32_t side[2] = { stamp + 1, stamp + 2 };
  stamp += 2;
  std::vector<int64_t> queue[2] = { { t0 }, { t1 } };
  size_t head[2] = { 0, 0 };
  seen[t0] = side[0];
  seen[t1] = side[1];
  for (int s = 0; head[0] < queue[0].size() && head[1] < queue[1].size(); s = 1 - s)
  {
    const int32_t* tri = this->Mesh.GetTriangle(queue[s][head[s]++]);
    for (int e = 0; e < 3; ++e)
    {
      const int32_t x = tri[e], y = tri[(e + 1) % 3];
      const int64_t next = this->Mesh.FindTriangle(y, x);
      if (next < 0 || (x == u && y == v) || (x == v && y == u) || seen[next] == side[s])
      {
        continue;
      }
      if (seen[next] == side[1 - s])
      {
        return true;
      }
      seen[next] = side[s];
      queue[s].push_back(next);
    }
  }
  return false;
}

// Issue 7 (clean surfaces): step 1 may join the open borders of two sheets that face each other
// across a narrow gap (about 2 spacings: on CGAL's elephant, the two ends of a bent part) by
// a strip of triangles whose end points all lie on the borders; every fan turns onto the strip by
// less than the umbrella test's bound, so step 2 keeps it, and it makes a handle: the true
// surface joins the two sheets elsewhere. Such a strip is found by its chord: an edge of two
// triangles whose end points u and v are boundary points of one boundary loop, such that
// - the two triangles stay connected through their edges when the chord is cut: the cut splits
//   the loop without splitting the piece, so the piece's genus drops by one (on a piece of genus
//   0 every such chord separates it: nothing is removed there), and
// - the chord leaves the surface at both ends: it makes more than 30 degrees with the tangent
//   planes of u and of v, each the plane of the point's triangles other than the two at the chord
//   (their area-weighted normal); an edge of a sampled surface lies in its tangent planes up to
//   the curvature over a spacing. (Not the PCA plane of the K nearest, as IsNaturalBorder uses:
//   about 2 spacings from the other sheet, the K nearest straddle both sheets and their plane
//   tilts towards the chord.)
// The two triangles at such a chord are removed (and the triangles of the vertices left with two
// fans, ClearPinches), one chord at a time, the conditions checked again on the current mesh.
// Their points become lost points for the later steps. A true handle is cut this way only when
// step 2 left a hole across it and a chord there leaves the surface at both ends: the inner rim
// of a plate with a through-hole, about 2 spacings thick, crossed by a single strip.
void Reconstruction::RemoveHandleStrips()
{
  // Candidates: the chords u -> v (u < v) between boundary points that leave the surface at both
  // ends.
  std::vector<std::array<int32_t, 2>> candidates;
  for (int32_t u = 0; u < this->N; ++u)
  {
    if (this->Mesh.GetVertexState(u) != pcs::SurfaceMesh::VertexState::Boundary)
    {
      continue;
    }
    constexpr int Capacity = 64;
    int64_t around[Capacity];
    const int count = std::min(this->Mesh.GetVertexTriangles(u, around, Capacity), Capacity);
    for (int i = 0; i < count; ++i)
    {
      const int32_t* tri = this->Mesh.GetTriangle(around[i]);
      const int j = tri[0] == u ? 0 : (tri[1] == u ? 1 : 2);
      const int32_t v = tri[(j + 1) % 3];
      if (v < u || this->Mesh.GetVertexState(v) != pcs::SurfaceMesh::VertexState::Boundary ||
        this->Mesh.IsBoundaryHalfEdge(u, v))
      {
        continue;
      }
      if (this->LeavesSheetsAtBothEnds(u, v, around[i], this->Mesh.FindTriangle(v, u)))
      {
        candidates.push_back({ u, v });
      }
    }
  }
  std::vector<uint32_t> seen;
  uint32_t stamp = 0;
  std::vector<int32_t> pending;
  for (const auto& candidate : candidates)
  {
    const int32_t u = candidate[0], v = candidate[1];
    const int64_t t0 = this->Mesh.FindTriangle(u, v), t1 = this->Mesh.FindTriangle(v, u);
    if (t0 < 0 || t1 < 0 || this->Mesh.GetNumberOfFans(u) != 1 ||
      this->Mesh.GetNumberOfFans(v) != 1 ||
      this->Mesh.GetVertexState(u) != pcs::SurfaceMesh::VertexState::Boundary ||
      this->Mesh.GetVertexState(v) != pcs::SurfaceMesh::VertexState::Boundary)
    {
      continue; // changed by an earlier removal
    }
    // u and v on one loop?
    int32_t a = u, b = -1;
    this->Mesh.GetBoundaryOutVertices(u, &b, 1);
    while (b != u && b != v && b >= 0)
    {
      const int32_t next = this->Mesh.NextBoundaryVertex(a, b);
      a = b;
      b = next;
    }
    if (b != v)
    {
      continue;
    }
    if (!this->LeavesSheetsAtBothEnds(u, v, t0, t1) ||
      !this->ConnectedAroundEdge(u, v, t0, t1, seen, stamp))
    {
      continue;
    }
    for (int64_t t : { t0, t1 })
    {
      const int32_t* tri = this->Mesh.GetTriangle(t);
      const int32_t corners[3] = { tri[0], tri[1], tri[2] };
      this->Mesh.RemoveTriangle(t);
      for (int32_t x : corners)
      {
        if (this->Mesh.GetNumberOfFans(x) > 1)
        {
          pending.push_back(x);
        }
      }
    }
    this->ClearPinches(pending);
  }
}

// Connected pieces of the mesh through shared vertices (a pinch joins two pieces): per vertex,
// the id of a vertex of its piece (the vertex itself when it has no triangle).
std::vector<int32_t> Reconstruction::VertexPieces() const
{
  pcs::DisjointSets<int32_t> pieces(this->N);
  const int64_t ids = this->Mesh.GetNumberOfTriangleIds();
  for (int64_t t = 0; t < ids; ++t)
  {
    if (!this->Mesh.IsTriangleRemoved(t))
    {
      const int32_t* tri = this->Mesh.GetTriangle(t);
      pieces.Union(tri[0], tri[1]);
      pieces.Union(tri[0], tri[2]);
    }
  }
  std::vector<int32_t> piece(static_cast<size_t>(this->N));
  for (int32_t v = 0; v < this->N; ++v)
  {
    piece[v] = pieces.Find(v);
  }
  return piece;
}

// Connected components of the mesh triangles (through shared edges), per vertex.
void Reconstruction::ComputeComponents()
{
  this->Component.assign(this->N, -1);
  const int64_t ids = this->Mesh.GetNumberOfTriangleIds();
  std::vector<int32_t> component(ids, -1);
  std::vector<int64_t> stack;
  int32_t next = 0;
  for (int64_t seed = 0; seed < ids; ++seed)
  {
    if (this->Mesh.IsTriangleRemoved(seed) || component[seed] >= 0)
    {
      continue;
    }
    component[seed] = next;
    stack.assign(1, seed);
    while (!stack.empty())
    {
      const int64_t t = stack.back();
      stack.pop_back();
      const int32_t* tri = this->Mesh.GetTriangle(t);
      for (int j = 0; j < 3; ++j)
      {
        this->Component[tri[j]] = next;
        const int64_t u = this->Mesh.FindTriangle(tri[(j + 1) % 3], tri[j]);
        if (u >= 0 && component[u] < 0)
        {
          component[u] = next;
          stack.push_back(u);
        }
      }
    }
    ++next;
  }
}

//------------------------------------------------------------------------------------------------
// A grown triangle removed; its vertices left without triangles are lost points again.
void Reconstruction::TakeBack(int64_t t)
{
  const int32_t* tri = this->Mesh.GetTriangle(t);
  const int32_t v[3] = { tri[0], tri[1], tri[2] };
  this->Mesh.RemoveTriangle(t);
  for (int32_t x : v)
  {
    if (this->Mesh.IsFree(x))
    {
      this->Status[x] = vtkGreedySurfaceTriangulation::LOST;
    }
  }
}

//------------------------------------------------------------------------------------------------
// After the small loops and the caps: a piece with grown triangles (stage 2) that is still open
// and has fewer than MinimumIslandTriangles triangles is taken back, as step 2 dissolves its
// small islands (a seed that grew into a strip the later steps could not join or close); its
// points are lost again.
void Reconstruction::RemoveSmallOpenGrownParts()
{
  if (this->Grown == 0)
  {
    return;
  }
  const int64_t ids = std::min<int64_t>(this->Mesh.GetNumberOfTriangleIds(), this->Stage.size());
  const int64_t minimum = this->Self->GetMinimumIslandTriangles();
  std::vector<char> visited(static_cast<size_t>(this->Mesh.GetNumberOfTriangleIds()), 0);
  std::vector<int64_t> part;
  for (int64_t seed = 0; seed < ids; ++seed)
  {
    if (this->Mesh.IsTriangleRemoved(seed) || visited[seed] || this->Stage[seed] != 2)
    {
      continue;
    }
    visited[seed] = 1;
    part.assign(1, seed);
    bool open = false;
    for (size_t i = 0; i < part.size(); ++i)
    {
      const int32_t* tri = this->Mesh.GetTriangle(part[i]);
      for (int j = 0; j < 3; ++j)
      {
        const int64_t u = this->Mesh.FindTriangle(tri[(j + 1) % 3], tri[j]);
        open = open || u < 0;
        if (u >= 0 && !visited[u])
        {
          visited[u] = 1;
          part.push_back(u);
        }
      }
    }
    if (!open || static_cast<int64_t>(part.size()) >= minimum)
    {
      continue;
    }
    std::vector<int32_t> vertices;
    for (int64_t t : part)
    {
      const int32_t* tri = this->Mesh.GetTriangle(t);
      vertices.insert(vertices.end(), tri, tri + 3);
      this->TakeBack(t);
    }
    // A lost point inserted into the piece (stage 8) is lost again: no longer counted inserted.
    for (int32_t v : vertices)
    {
      if (this->Mesh.IsFree(v) && !this->InsertedPoints.empty() && this->InsertedPoints[v])
      {
        this->InsertedPoints[v] = 0;
        --this->Inserted;
      }
    }
  }
}

//------------------------------------------------------------------------------------------------
// Grown triangles (stage 2) hanging by one edge (two boundary edges) are taken back, until none:
// expansions the later steps folded against.
void Reconstruction::RemoveGrownFlaps()
{
  if (this->Grown == 0)
  {
    return;
  }
  auto boundaryEdges = [this](int64_t t)
  {
    const int32_t* tri = this->Mesh.GetTriangle(t);
    int count = 0;
    for (int j = 0; j < 3; ++j)
    {
      count += this->Mesh.FindTriangle(tri[(j + 1) % 3], tri[j]) < 0 ? 1 : 0;
    }
    return count;
  };
  const int64_t ids = std::min<int64_t>(this->Mesh.GetNumberOfTriangleIds(), this->Stage.size());
  auto isFlap = [&](int64_t t)
  {
    return t >= 0 && t < ids && !this->Mesh.IsTriangleRemoved(t) && this->Stage[t] == 2 &&
      boundaryEdges(t) >= 2;
  };
  // A worklist: taking a flap back can make only its edge neighbours flaps (a strip is peeled
  // from its end in linear time, not one pass over every triangle per step).
  std::vector<int64_t> work;
  for (int64_t t = 0; t < ids; ++t)
  {
    if (isFlap(t))
    {
      work.push_back(t);
    }
  }
  while (!work.empty())
  {
    const int64_t t = work.back();
    work.pop_back();
    if (!isFlap(t))
    {
      continue;
    }
    const int32_t* tri = this->Mesh.GetTriangle(t);
    int64_t neighbours[3];
    for (int j = 0; j < 3; ++j)
    {
      neighbours[j] = this->Mesh.FindTriangle(tri[(j + 1) % 3], tri[j]);
    }
    this->TakeBack(t);
    for (int64_t u : neighbours)
    {
      if (isFlap(u))
      {
        work.push_back(u);
      }
    }
  }
}

//------------------------------------------------------------------------------------------------
// The mesh's edge-connected components and twice the sum of their genera (2 c - loops - chi).
void Reconstruction::Topology(int64_t& components, int64_t& handles) const
{
  const pcs::SurfaceMesh& mesh = this->Mesh;
  pcs::DisjointSets<int64_t> sets(mesh.GetNumberOfTriangleIds());
  mesh.JoinAcrossEdges(sets);
  components = 0;
  for (int64_t t = 0; t < mesh.GetNumberOfTriangleIds(); ++t)
  {
    components += !mesh.IsTriangleRemoved(t) && sets.Find(t) == t ? 1 : 0;
  }
  int64_t vertices = 0;
  for (int32_t v = 0; v < this->N; ++v)
  {
    vertices += mesh.IsFree(v) ? 0 : 1;
  }
  const int64_t faces = mesh.GetNumberOfTriangles();
  const int64_t edges = (3 * faces + mesh.GetNumberOfBoundaryHalfEdges()) / 2;
  std::vector<std::vector<int32_t>> loops;
  mesh.GetBoundaryLoops(loops);
  handles = 2 * components - static_cast<int64_t>(loops.size()) - (vertices - edges + faces);
}

//------------------------------------------------------------------------------------------------
// The choice between the two repaired candidates (GrowRegions), piece by piece, when the grown
// one (`other`) was not kept whole. The triangles of one candidate that the other does not have
// (same three vertices, either orientation) are joined through their vertices into pieces; every
// triangle at a vertex of a piece that is not one of the piece's is in both candidates. So once a
// piece is exchanged, each of its vertices has exactly the other candidate's triangles around it,
// and the edges at those vertices their valence there: which points the exchange uses and how
// many boundary edges it leaves are read from `other` before anything is changed. A piece is
// exchanged when the other candidate's version uses more of its points without more boundary
// half-edges at them (the rule of the whole choice, applied to each piece), and kept when the mesh
// then has no more edge-connected components and no larger sum of genera. With tiesOnly (the
// result whose front was grown into the holes, issue 7), only pieces that use as many points
// are compared (see below). Without checkEach the topology is not checked here (the caller
// checks it once for all pieces). Returns the number of pieces exchanged.
vtkIdType Reconstruction::TakeBetterPieces(
  const Reconstruction& other, bool tiesOnly, bool checkEach)
{
  const pcs::SurfaceMesh& there = other.Mesh;
  // The triangle of `mesh` with the vertices of tri in either orientation: its id, and whether
  // it runs the other way round (-1 when none).
  auto find = [](const pcs::SurfaceMesh& mesh, const int32_t* tri, bool& reversed)
  {
    int64_t t = mesh.FindTriangle(tri[0], tri[1]);
    if (t >= 0 && mesh.OppositeVertex(tri[0], tri[1]) == tri[2])
    {
      reversed = false;
      return t;
    }
    t = mesh.FindTriangle(tri[1], tri[0]);
    if (t >= 0 && mesh.OppositeVertex(tri[1], tri[0]) == tri[2])
    {
      reversed = true;
      return t;
    }
    return int64_t(-1);
  };
  // Stage of a triangle (the hole fills' triangles may lie beyond the Stage array: 6).
  auto stageOf = [](const Reconstruction& x, int64_t t)
  { return t < static_cast<int64_t>(x.Stage.size()) ? x.Stage[t] : uint8_t(6); };
  std::vector<int64_t> mine, theirs; // triangles of one candidate only
  pcs::DisjointSets<int32_t> pieces(this->N);
  auto collect =
    [&](const pcs::SurfaceMesh& from, const pcs::SurfaceMesh& to, std::vector<int64_t>& only)
  {
    bool reversed;
    for (int64_t t = 0; t < from.GetNumberOfTriangleIds(); ++t)
    {
      if (!from.IsTriangleRemoved(t) && find(to, from.GetTriangle(t), reversed) < 0)
      {
        only.push_back(t);
        const int32_t* tri = from.GetTriangle(t);
        pieces.Union(tri[0], tri[1]);
        pieces.Union(tri[0], tri[2]);
      }
    }
  };
  collect(this->Mesh, there, mine);
  collect(there, this->Mesh, theirs);
  if (theirs.empty())
  {
    return 0;
  }
  // Pieces indexed by root: their triangles in each candidate and their vertices.
  struct Piece
  {
    std::vector<int64_t> Mine, Theirs;
    std::vector<int32_t> Vertices;
  };
  std::unordered_map<int32_t, Piece> byRoot;
  std::vector<char> seen(static_cast<size_t>(this->N), 0);
  auto add = [&](const pcs::SurfaceMesh& mesh, int64_t t, bool isMine)
  {
    const int32_t* tri = mesh.GetTriangle(t);
    Piece& piece = byRoot[pieces.Find(tri[0])];
    (isMine ? piece.Mine : piece.Theirs).push_back(t);
    for (int j = 0; j < 3; ++j)
    {
      if (!seen[tri[j]])
      {
        seen[tri[j]] = 1;
        piece.Vertices.push_back(tri[j]);
      }
    }
  };
  for (int64_t t : mine)
  {
    add(this->Mesh, t, true);
  }
  for (int64_t t : theirs)
  {
    add(there, t, false);
  }
  // In a fixed order (the smallest vertex of each piece), so that the result does not depend on
  // the hash map's.
  std::vector<Piece*> order;
  for (auto& entry : byRoot)
  {
    order.push_back(&entry.second);
  }
  std::sort(order.begin(), order.end(),
    [](const Piece* a, const Piece* b)
    {
      return *std::min_element(a->Vertices.begin(), a->Vertices.end()) <
        *std::min_element(b->Vertices.begin(), b->Vertices.end());
    });
  // An exchange that would raise the number of components or the sum of genera is undone.
  int64_t componentsNow = 0, handlesNow = 0;
  if (checkEach)
  {
    this->Topology(componentsNow, handlesNow);
  }
  std::vector<char> inPiece(static_cast<size_t>(this->N), 0);
  vtkIdType exchanged = 0;
  for (Piece* piece : order)
  {
    for (int32_t v : piece->Vertices)
    {
      inPiece[v] = 1;
    }
    // Points used and boundary half-edges with an end in the piece, in each candidate.
    auto measure = [&](const pcs::SurfaceMesh& mesh, vtkIdType& used, vtkIdType& boundary)
    {
      used = boundary = 0;
      std::vector<int32_t> ends(64);
      for (int32_t v : piece->Vertices)
      {
        used += mesh.IsFree(v) ? 0 : 1;
        // (The counts are whole; the ids are read again into a larger buffer when they did not
        // fit.)
        boundary += mesh.GetBoundaryOutVertices(v, ends.data(), static_cast<int>(ends.size()));
        const int in = mesh.GetBoundaryInVertices(v, ends.data(), static_cast<int>(ends.size()));
        if (in > static_cast<int>(ends.size()))
        {
          ends.resize(static_cast<size_t>(in));
          mesh.GetBoundaryInVertices(v, ends.data(), in);
        }
        for (int j = 0; j < in; ++j)
        {
          boundary += inPiece[ends[j]] ? 0 : 1;
        }
      }
    };
    vtkIdType usedHere, boundaryHere, usedThere, boundaryThere;
    measure(this->Mesh, usedHere, boundaryHere);
    measure(there, usedThere, boundaryThere);
    // With tiesOnly (ours, issue 7: the result grown into the holes): as many points used, no
    // more boundary half-edges, and at most half as many triangles made by the repairs (stages
    // above 2: fills, swaps, insertions), at least one here.
    bool take = !tiesOnly && usedThere > usedHere && boundaryThere <= boundaryHere;
    if (tiesOnly && usedThere == usedHere && boundaryThere <= boundaryHere)
    {
      size_t repairsHere = 0, repairsThere = 0;
      for (int64_t t : piece->Mine)
      {
        repairsHere += stageOf(*this, t) > 2 ? 1 : 0;
      }
      for (int64_t t : piece->Theirs)
      {
        repairsThere += stageOf(other, t) > 2 ? 1 : 0;
      }
      take = 2 * repairsThere <= repairsHere && repairsHere > 0;
    }
    if (!take)
    {
      for (int32_t v : piece->Vertices)
      {
        inPiece[v] = 0;
      }
      continue;
    }
    std::vector<int32_t> removed, added;
    std::vector<uint8_t> removedStages;
    for (int64_t t : piece->Mine)
    {
      const int32_t* tri = this->Mesh.GetTriangle(t);
      removed.insert(removed.end(), tri, tri + 3);
      removedStages.push_back(stageOf(*this, t));
      this->Mesh.RemoveTriangle(t);
    }
    for (int64_t t : piece->Theirs)
    {
      const int32_t* tri = there.GetTriangle(t);
      added.insert(added.end(), tri, tri + 3);
    }
    // The triangles both candidates have at the piece's points take the other's orientation
    // (a bridge may have reversed a region in one candidate only): their edge-connected
    // components here are reversed where they run the other way round there (the closed ones
    // are oriented outwards at the end). A component running both ways is left as it is, and
    // the piece with it (AddTriangles refuses it).
    std::vector<int64_t> reversedSeeds;
    std::vector<int64_t> around(256);
    for (int32_t v : piece->Vertices)
    {
      const int count =
        this->Mesh.GetVertexTriangles(v, around.data(), static_cast<int>(around.size()));
      if (count > static_cast<int>(around.size()))
      {
        around.resize(static_cast<size_t>(count));
        this->Mesh.GetVertexTriangles(v, around.data(), count);
      }
      for (int j = 0; j < count; ++j)
      {
        bool reversed = false;
        if (find(there, this->Mesh.GetTriangle(around[j]), reversed) >= 0 && reversed)
        {
          this->Mesh.ReverseComponent(around[j]);
          reversedSeeds.push_back(around[j]);
        }
      }
    }
    std::vector<int64_t> ids;
    bool done = this->Mesh.AddTriangles(added.data(), added.size() / 3, ids);
    if (done && checkEach)
    {
      int64_t components, handles;
      this->Topology(components, handles);
      done = components <= componentsNow && handles <= handlesNow;
      if (done)
      {
        componentsNow = components;
        handlesNow = handles;
      }
      else
      {
        for (int64_t t : ids)
        {
          this->Mesh.RemoveTriangle(t);
        }
      }
    }
    if (!done)
    {
      // Put back (the stars are the other candidate's, so AddTriangles refuses only a component
      // running both ways).
      for (auto seed = reversedSeeds.rbegin(); seed != reversedSeeds.rend(); ++seed)
      {
        this->Mesh.ReverseComponent(*seed);
      }
      this->Mesh.AddTriangles(removed.data(), removed.size() / 3, ids);
    }
    this->Stage.resize(static_cast<size_t>(this->Mesh.GetNumberOfTriangleIds()), 6);
    for (size_t k = 0; k < ids.size(); ++k)
    {
      this->Stage[ids[k]] = done ? stageOf(other, piece->Theirs[k]) : removedStages[k];
    }
    if (done)
    {
      ++exchanged;
      for (int32_t v : piece->Vertices)
      {
        this->Status[v] = other.Status[v];
        const char before = this->InsertedPoints.empty() ? 0 : this->InsertedPoints[v];
        const char after = other.InsertedPoints.empty() ? 0 : other.InsertedPoints[v];
        if (before != after)
        {
          this->InsertedPoints.resize(static_cast<size_t>(this->N), 0);
          this->InsertedPoints[v] = after;
          this->Inserted += after ? 1 : -1;
        }
      }
    }
    for (int32_t v : piece->Vertices)
    {
      inPiece[v] = 0;
    }
  }
  return exchanged;
}

//------------------------------------------------------------------------------------------------
// After step 2: the regions grown into the lost points by vtkLocalOptimumGrowth's expansion
// (pcs::GrowFront, its default constraints, on this filter's K). The new triangles are stage 2, the points they use
// "lost and used" (Status 3).
void Reconstruction::GrowRegions(double begin, double end, bool expandFront)
{
  if (!this->Self->GetGrowRegions() || this->Mesh.GetNumberOfTriangles() == 0)
  {
    return;
  }
  const int64_t before = this->Mesh.GetNumberOfTriangleIds();
  pcs::FrontGrowthParameters parameters;
  bool aborted = false;
  if (pcs::GrowFront(this->Mesh, this->X.data(), this->N, this->Neighbors, this->K, this->Stretch,
        expandFront, this->Dissolved, parameters, this->Self, begin, end, aborted) > 0)
  {
    this->Stage.resize(static_cast<size_t>(this->Mesh.GetNumberOfTriangleIds()), 2);
    std::fill(this->Stage.begin() + before, this->Stage.end(), 2);
    for (int32_t v = 0; v < this->N; ++v)
    {
      if (this->Status[v] == vtkGreedySurfaceTriangulation::LOST && !this->Mesh.IsFree(v))
      {
        this->Status[v] = vtkGreedySurfaceTriangulation::LOST_USED_BY_HOLE_FILLING;
        ++this->Grown;
      }
    }
    this->ComputeComponents();
  }
  this->Aborted = this->Aborted || aborted;
}

//------------------------------------------------------------------------------------------------
// Step 3 test on a loop (vertex sequence in the direction of the mesh's boundary edges): true
// for a hole.
bool Reconstruction::IsHole(const std::vector<int32_t>& vertices) const
{
  const size_t n = vertices.size();
  if (n < 3)
  {
    return false;
  }
  auto I = [this](int32_t v) { return &this->BoundaryVectors[3 * static_cast<size_t>(v)]; };
  // The paper's test. P1 is searched among the loop points at least a third of the loop away
  // from P0, so that it is never a neighbour of P0 on a thin loop.
  const size_t gap = std::max<size_t>(1, (n + 2) / 3);
  const double neutral = std::sin(vtkMath::RadiansFromDegrees(this->Self->GetStatusNeutralAngle()));
  int positive = 0, negative = 0;
  const size_t tries = std::min<size_t>(16, n);
  for (size_t attempt = 0; attempt < tries; ++attempt)
  {
    const size_t i0 = (attempt * n) / tries;
    const int32_t p0 = vertices[i0];
    int32_t p1 = p0;
    double farthest = -1.0;
    for (size_t k = gap; k + gap <= n; ++k)
    {
      const int32_t v = vertices[(i0 + k) % n];
      const double d = vtkMath::Distance2BetweenPoints(this->P(p0), this->P(v));
      if (d > farthest)
      {
        farthest = d;
        p1 = v;
      }
    }
    double d01[3];
    vtkMath::Subtract(this->P(p1), this->P(p0), d01);
    const double length = vtkMath::Norm(d01);
    // A dot product votes when the angle between P0P1 and the boundary vector is at least
    // StatusNeutralAngle away from 90 degrees.
    for (int end = 0; end < 2; ++end)
    {
      const double* vector = I(end == 0 ? p0 : p1);
      const double scale = length * vtkMath::Norm(vector);
      const double cosine = scale > 0 ? (end == 0 ? -1.0 : 1.0) * vtkMath::Dot(d01, vector) / scale : 0.0;
      positive += cosine > neutral ? 1 : 0;
      negative += cosine < -neutral ? 1 : 0;
    }
    // Neutral products count in the total: they never make a majority.
    const int total = 2 * static_cast<int>(attempt + 1);
    if (4 * positive >= 3 * total)
    {
      return true;
    }
    if (4 * negative >= 3 * total)
    {
      return false;
    }
  }
  // Undecided: the orientation of the loop against the mesh beside it. The loop follows the
  // boundary edges of consistently oriented triangles, so it turns clockwise around a hole and
  // counter-clockwise around an island, seen along the normals of those triangles: the sign of
  // (loop vector area) . (sum of the triangle normals), when that is clear (the two vectors
  // within 60 degrees of parallel); otherwise an island (left open).
  double area[3] = { 0, 0, 0 }, normal[3] = { 0, 0, 0 };
  double normalLengths = 0.0;
  const double* origin = this->P(vertices[0]);
  for (size_t i = 0; i < n; ++i)
  {
    const int32_t a = vertices[i], b = vertices[(i + 1) % n];
    double pa[3], pb[3], cross[3];
    vtkMath::Subtract(this->P(a), origin, pa);
    vtkMath::Subtract(this->P(b), origin, pb);
    vtkMath::Cross(pa, pb, cross);
    vtkMath::Add(area, cross, area);
    const int32_t c = this->Mesh.OppositeVertex(a, b);
    if (c >= 0)
    {
      double u[3], w[3], t[3];
      vtkMath::Subtract(this->P(b), this->P(a), u);
      vtkMath::Subtract(this->P(c), this->P(a), w);
      vtkMath::Cross(u, w, t);
      vtkMath::Add(normal, t, normal);
      normalLengths += vtkMath::Norm(t);
    }
  }
  const double scale = vtkMath::Norm(area) * vtkMath::Norm(normal);
  const double cosine = scale > 0 ? vtkMath::Dot(area, normal) / scale : 0.0;
  return cosine < -0.5 && vtkMath::Norm(normal) >= 0.25 * normalLengths;
}

void Reconstruction::Step3Status()
{
  std::vector<std::vector<int32_t>> loops;
  this->Mesh.GetBoundaryLoops(loops);
  this->NodeOf.assign(this->N, -1);
  this->Nodes.clear();
  this->BoundaryVectors.assign(3 * static_cast<size_t>(this->N), 0.0);
  this->EdgeVectors.assign(3 * static_cast<size_t>(this->N), 0.0);

  // Boundary vectors (paper Fig. 8): the direction from a boundary point into its region, as
  // the sum of the unit inward perpendiculars of its two boundary edges, each in the plane of
  // its triangle (see the class documentation for why not the paper's neighbourhood mean).
  auto inward = [this](int32_t a, int32_t b, double* sum) {
    const int32_t c = this->Mesh.OppositeVertex(a, b); // triangle (a, b, c) owns a -> b
    if (c < 0)
    {
      return;
    }
    double e[3], f[3], n[3], d[3];
    vtkMath::Subtract(this->P(b), this->P(a), e);
    vtkMath::Subtract(this->P(c), this->P(a), f);
    vtkMath::Cross(e, f, n);
    vtkMath::Cross(n, e, d); // in the triangle's plane, towards c
    if (vtkMath::Normalize(d) > 0)
    {
      vtkMath::Add(sum, d, sum);
    }
  };
  const double window = this->Self->GetBoundaryVectorRadius() * this->Spacing;
  std::vector<double> raw;
  for (const auto& loop : loops)
  {
    const size_t n = loop.size();
    raw.assign(3 * n, 0.0);
    for (size_t i = 0; i < n; ++i)
    {
      inward(loop[(i + n - 1) % n], loop[i], &raw[3 * i]);
      inward(loop[i], loop[(i + 1) % n], &raw[3 * i]);
      std::copy_n(&raw[3 * i], 3, &this->EdgeVectors[3 * static_cast<size_t>(loop[i])]);
    }
    // Mean over the loop points within BoundaryVectorRadius along the loop (the paper's b):
    // smooths the jagged boundaries of random samples.
    for (size_t i = 0; i < n; ++i)
    {
      double* vector = &this->BoundaryVectors[3 * static_cast<size_t>(loop[i])];
      vtkMath::Add(vector, &raw[3 * i], vector);
      for (int direction : { 1, -1 })
      {
        double along = 0.0;
        for (size_t step = 1; step < n / 2 + (direction > 0 ? 1 : 0); ++step)
        {
          const size_t j = (i + n + direction * static_cast<long>(step)) % n;
          const size_t k = (j + n - direction) % n;
          along += Distance(this->P(loop[j]), this->P(loop[k]));
          if (along > window)
          {
            break;
          }
          vtkMath::Add(vector, &raw[3 * j], vector);
        }
      }
    }
  }

  // Loop nodes (a doubly linked list per loop, in the direction of the mesh's boundary edges).
  this->LoopIsHole.assign(loops.size(), 0);
  for (size_t l = 0; l < loops.size(); ++l)
  {
    const auto& loop = loops[l];
    const int32_t firstNode = static_cast<int32_t>(this->Nodes.size());
    const int32_t n = static_cast<int32_t>(loop.size());
    for (int32_t i = 0; i < n; ++i)
    {
      this->NodeOf[loop[i]] = firstNode + i;
      this->Nodes.push_back(
        { loop[i], firstNode + (i + 1) % n, firstNode + (i + n - 1) % n, static_cast<int32_t>(l) });
    }
    this->LoopIsHole[l] = this->IsHole(loop) ? 1 : 0;
    this->Islands += this->LoopIsHole[l] ? 0 : 1;
  }
}

//------------------------------------------------------------------------------------------------
// Step 4's candidate bridges: from each point of an island loop, the shortest to each other loop
// within `limit` that leaves both loops on their outer side (against the boundary vectors),
// sorted by length (ties by the ends' ids), each pair once. The balls are searched among the loop
// points only (pcs::PointBins), and the best per loop is found by the loop's slot, not by a search
// of the loops already seen: in a volume a ball of 10 spacings holds thousands of points and
// hundreds of loops.
std::vector<Reconstruction::BridgeCandidate> Reconstruction::BridgeCandidates(double limit) const
{
  std::vector<int32_t> onLoop; // the points with a node
  std::vector<double> xyz;
  for (int32_t v = 0; v < this->N; ++v)
  {
    if (this->NodeOf[v] >= 0)
    {
      onLoop.push_back(v);
      xyz.insert(xyz.end(), this->P(v), this->P(v) + 3);
    }
  }
  pcs::PointBins bins;
  double bounds[6];
  pcs::BuildSurfaceSampleBins(bins, xyz.data(), static_cast<int32_t>(onLoop.size()), true, bounds);

  auto I = [this](int32_t v) { return &this->BoundaryVectors[3 * static_cast<size_t>(v)]; };
  auto leaves = [&](int32_t a, int32_t b)
  {
    double d[3];
    vtkMath::Subtract(this->P(b), this->P(a), d);
    return vtkMath::Dot(d, I(a)) < 0;
  };
  struct Best
  {
    double Length;
    int32_t Vertex, Loop;
  };
  std::vector<BridgeCandidate> candidates;
  std::vector<Best> best;                                 // per other loop in reach
  std::vector<int32_t> slot(this->LoopIsHole.size(), -1); // loop -> index in best
  for (const Node& node : this->Nodes)
  {
    if (this->LoopIsHole[node.Loop])
    {
      continue;
    }
    const int32_t a = node.Vertex;
    bins.ForEachPointWithinRadius(limit,
      this->P(a),
      [&](int32_t id, double)
      {
        const int32_t b = onLoop[id];
        const int32_t loop = this->Nodes[this->NodeOf[b]].Loop;
        if (loop == node.Loop || !leaves(a, b) || !leaves(b, a))
        {
          return true;
        }
        const double length = Distance(this->P(a), this->P(b));
        if (slot[loop] < 0)
        {
          slot[loop] = static_cast<int32_t>(best.size());
          best.push_back({ length, b, loop });
        }
        else
        {
          Best& x = best[slot[loop]];
          if (length < x.Length || (length == x.Length && b < x.Vertex))
          {
            x.Length = length;
            x.Vertex = b;
          }
        }
        return true;
      });
    for (const Best& x : best)
    {
      candidates.push_back({ x.Length, std::min(a, x.Vertex), std::max(a, x.Vertex) });
      slot[x.Loop] = -1;
    }
    best.clear();
  }
  std::sort(candidates.begin(),
    candidates.end(),
    [](const BridgeCandidate& x, const BridgeCandidate& y)
    { return x.Length != y.Length ? x.Length < y.Length : (x.A != y.A ? x.A < y.A : x.B < y.B); });
  candidates.erase(
    std::unique(candidates.begin(),
      candidates.end(),
      [](const BridgeCandidate& x, const BridgeCandidate& y) { return x.A == y.A && x.B == y.B; }),
    candidates.end());
  return candidates;
}

//------------------------------------------------------------------------------------------------
// The loops and orientation groups of step 4 while bridges are installed.
//
// Groups: the components joined by bridges (union-find); a bridge between two groups whose loops
// run the same way reverses one group as a whole. The reversal is lazy: a flag per group, and per
// component its orientation relative to its group's, so that reversing a group costs one flag
// and the triangles and node links of each component are reversed once, at the end (Finish).
// Reversing them at each bridge was quadratic: on a 35^3 lattice volume, 1,400 components, 3,200
// bridges reversed 150 times the mesh's triangles.
//
// Loops: a label per node and the number of nodes per label, so that whether two nodes are on
// one loop is a lookup, not a walk around the loop. A join relabels the smaller of the two
// loops, a split the smaller of the two parts (both walked in turn).
class BridgeLoops
{
public:
  using Node = Reconstruction::Node;
  BridgeLoops(std::vector<Node>& nodes, const std::vector<int32_t>& component, size_t loops)
    : Nodes(nodes)
    , Component(component)
  {
    const int32_t components =
      1 + (component.empty() ? -1 : *std::max_element(component.begin(), component.end()));
    this->Groups.Reset(std::max(components, 0));
    this->Members.resize(this->Groups.GetNumberOfIds());
    for (int32_t c = 0; c < components; ++c)
    {
      this->Members[c].push_back(c);
    }
    this->Reversed.assign(this->Members.size(), 0);
    this->GroupReversed.assign(this->Members.size(), 0);
    this->NodesOfComponent.resize(this->Members.size());
    this->Size.assign(loops, 0);
    for (int32_t n = 0; n < static_cast<int32_t>(nodes.size()); ++n)
    {
      this->NodesOfComponent[this->ComponentOf(n)].push_back(n);
      this->Label.push_back(nodes[n].Loop);
      ++this->Size[nodes[n].Loop];
    }
  }

  // The group of component c.
  int32_t Find(int32_t c) { return this->Groups.Find(c); }
  // Groups ga and gb (distinct) become one; every component keeps its orientation (those of the
  // smaller group are moved into the larger).
  void Join(int32_t ga, int32_t gb)
  {
    const int32_t kept = this->Groups.Link(ga, gb);
    const int32_t moved = kept == ga ? gb : ga;
    for (int32_t c : this->Members[moved])
    {
      this->Reversed[c] ^= this->GroupReversed[kept] ^ this->GroupReversed[moved];
    }
    this->Members[kept].insert(
      this->Members[kept].end(), this->Members[moved].begin(), this->Members[moved].end());
    this->Members[moved].clear();
  }
  void Reverse(int32_t g) { this->GroupReversed[g] ^= 1; }

  // Node links as they are with the reversals so far.
  int32_t Next(int32_t n)
  {
    return this->IsReversed(n) ? this->Nodes[n].Prev : this->Nodes[n].Next;
  }
  int32_t Prev(int32_t n)
  {
    return this->IsReversed(n) ? this->Nodes[n].Next : this->Nodes[n].Prev;
  }

  bool SameLoop(int32_t m, int32_t n) const { return this->Label[m] == this->Label[n]; }

  // The bridge na - nb with the copies A' of na and B' of nb (new nodes):
  // ... A0 A -> B B1 ... B0 B' -> A' A1 ...
  void Splice(int32_t na, int32_t nb)
  {
    const bool split = this->SameLoop(na, nb);
    const int32_t aCopy = static_cast<int32_t>(this->Nodes.size());
    const int32_t bCopy = aCopy + 1;
    const int32_t aNext = this->Next(na), bPrev = this->Prev(nb);
    this->AddNode(this->Nodes[na].Vertex, this->Nodes[na].Loop, aNext, bCopy);
    this->AddNode(this->Nodes[nb].Vertex, this->Nodes[nb].Loop, aCopy, bPrev);
    this->SetPrev(aNext, aCopy);
    this->SetNext(bPrev, bCopy);
    this->SetNext(na, nb);
    this->SetPrev(nb, na);
    const int32_t la = this->Label[na], lb = this->Label[nb];
    this->Label.push_back(la);
    this->Label.push_back(lb);
    ++this->Size[la];
    ++this->Size[lb];
    if (split)
    {
      // na -> nb ... na and aCopy ... bCopy -> aCopy: the smaller gets a new label.
      const int32_t fresh = static_cast<int32_t>(this->Size.size());
      this->Size.push_back(0);
      for (int32_t p = this->Next(na), q = this->Next(aCopy);; p = this->Next(p), q = this->Next(q))
      {
        if (p == na || q == aCopy)
        {
          const int32_t start = p == na ? na : aCopy;
          this->Relabel(start, start, fresh);
          break;
        }
      }
    }
    else if (this->Size[la] < this->Size[lb])
    {
      this->Relabel(aCopy, nb, lb); // aCopy ... na
    }
    else
    {
      this->Relabel(nb, aCopy, la); // nb ... bCopy
    }
  }

  // The reversals applied: the triangles of each reversed component (from its triangle seeds[c])
  // and the links of its nodes.
  void Finish(pcs::SurfaceMesh& mesh, const std::vector<int64_t>& seeds)
  {
    for (int32_t c = 0; c < static_cast<int32_t>(this->Members.size()); ++c)
    {
      if (this->Reversed[c] ^ this->GroupReversed[this->Find(c)])
      {
        mesh.ReverseComponent(seeds[c]);
        for (int32_t n : this->NodesOfComponent[c])
        {
          std::swap(this->Nodes[n].Next, this->Nodes[n].Prev);
        }
      }
    }
  }

private:
  int32_t ComponentOf(int32_t n) const { return this->Component[this->Nodes[n].Vertex]; }
  bool IsReversed(int32_t n)
  {
    const int32_t c = this->ComponentOf(n);
    return (this->Reversed[c] ^ this->GroupReversed[this->Find(c)]) != 0;
  }
  void SetNext(int32_t n, int32_t m)
  {
    (this->IsReversed(n) ? this->Nodes[n].Prev : this->Nodes[n].Next) = m;
  }
  void SetPrev(int32_t n, int32_t m)
  {
    (this->IsReversed(n) ? this->Nodes[n].Next : this->Nodes[n].Prev) = m;
  }
  void AddNode(int32_t vertex, int32_t loop, int32_t next, int32_t prev)
  {
    const int32_t n = static_cast<int32_t>(this->Nodes.size());
    this->Nodes.push_back({ vertex, next, prev, loop });
    this->NodesOfComponent[this->ComponentOf(n)].push_back(n);
    if (this->IsReversed(n))
    {
      std::swap(this->Nodes[n].Next, this->Nodes[n].Prev);
    }
  }
  // The nodes from `start` (included) to `stop` (excluded) get `label`; the whole loop when
  // stop == start.
  void Relabel(int32_t start, int32_t stop, int32_t label)
  {
    int32_t n = start;
    do
    {
      --this->Size[this->Label[n]];
      this->Label[n] = label;
      ++this->Size[label];
      n = this->Next(n);
    } while (n != stop);
  }

  std::vector<Node>& Nodes;
  const std::vector<int32_t>& Component; // per vertex
  pcs::DisjointSets<int32_t> Groups;     // of components
  std::vector<std::vector<int32_t>> Members; // per group root: its components
  std::vector<uint8_t> Reversed;      // per component, relative to its group
  std::vector<uint8_t> GroupReversed; // per group root
  std::vector<std::vector<int32_t>> NodesOfComponent;
  std::vector<int32_t> Label; // per node: its current loop
  std::vector<int32_t> Size;  // per label
};

//------------------------------------------------------------------------------------------------
// Step 4: bridges between islands, then the final loops and their status.
void Reconstruction::Step4Bridges()
{
  const double limit = this->Self->GetMaximumBridgeLength() * this->Spacing;
  std::vector<char> bridged(this->N, 0);
  std::vector<int32_t> nodeChanged;                          // loops touched by a bridge
  std::vector<char> inBand(this->LoopIsHole.size(), 0);      // original loops taken as a band
  std::vector<char> loopBridged(this->LoopIsHole.size(), 0); // original loops with a bridge
  const size_t originalNodes = this->Nodes.size();
  if (this->Self->GetBridgeIslands() && this->Islands > 0 && limit > 0 && !this->Nodes.empty())
  {
    const std::vector<BridgeCandidate> candidates = this->BridgeCandidates(limit);
    vtkNew<vtkIdList> near;

    BridgeLoops loops(this->Nodes, this->Component, this->LoopIsHole.size());
    const int32_t components = 1 +
      (this->Component.empty() ? -1
                               : *std::max_element(this->Component.begin(), this->Component.end()));
    std::vector<int64_t> seeds(std::max(components, 0), -1);
    for (int64_t t = 0; t < this->Mesh.GetNumberOfTriangleIds(); ++t)
    {
      if (!this->Mesh.IsTriangleRemoved(t))
      {
        const int32_t c = this->Component[this->Mesh.GetTriangle(t)[0]];
        if (seeds[c] < 0)
        {
          seeds[c] = t;
        }
      }
    }
    // Auxiliary point at about one spacing from node n along its loop (direction: +1 next).
    auto along = [&](int32_t n, int direction) {
      const double* origin = this->P(this->Nodes[n].Vertex);
      int32_t m = n;
      for (int step = 0; step < 8; ++step)
      {
        m = direction > 0 ? loops.Next(m) : loops.Prev(m);
        if (m == n || Distance(origin, this->P(this->Nodes[m].Vertex)) >= this->Spacing)
        {
          break;
        }
      }
      return this->P(this->Nodes[m].Vertex);
    };
    auto angle = [](const double* p, const double* q, const double* r, const double* s) {
      double u[3], v[3];
      vtkMath::Subtract(q, p, u);
      vtkMath::Subtract(s, r, v);
      return vtkMath::AngleBetweenVectors(u, v);
    };

    vtkNew<vtkIncrementalOctreePointLocator> admitted;
    {
      vtkNew<vtkPoints> midpoints;
      midpoints->SetDataTypeToDouble();
      double bounds[6];
      this->Cloud->GetBounds(bounds);
      for (int i = 0; i < 3; ++i)
      {
        const double pad = limit + this->Spacing;
        bounds[2 * i] -= pad;
        bounds[2 * i + 1] += pad;
      }
      admitted->InitPointInsertion(midpoints, bounds);
    }
    // Issue 7: two island loops of one connected group that run alongside each other
    // (RunsAlongside, both ways) bound a narrow band of missing surface, a gap that winds around
    // a thin part: the two rims of a band of lost points around a leg, or of a band cut across a
    // torus's tube. Each alone is a loop around the part whose farthest-point votes are neutral
    // and whose triangle normals cancel (an island); a bridge would join them into one hole whose
    // projection (steps 5 and 6) folds both rims onto one circle, and left to CapOpenEnds each
    // would get a cap across the part's inside (CGAL's camel, random samples: fills 17 to 18
    // spacings off the surface). They are triangulated as a strip instead (FillBands). The pair
    // is tested once (original loops of step 3).
    std::vector<std::vector<int32_t>> loopVertices;
    std::map<std::pair<int32_t, int32_t>, bool> bands;
    auto bandOf = [&](int32_t la, int32_t lb)
    {
      if (loopVertices.empty())
      {
        // The original loops in order: the nodes of step 3 (the copies come after them).
        loopVertices.resize(this->LoopIsHole.size());
        for (size_t i = 0; i < originalNodes; ++i)
        {
          loopVertices[this->Nodes[i].Loop].push_back(this->Nodes[i].Vertex);
        }
      }
      const auto key = std::make_pair(std::min(la, lb), std::max(la, lb));
      auto it = bands.find(key);
      if (it == bands.end())
      {
        it = bands
               .emplace(key,
                 !this->LoopIsHole[la] && !this->LoopIsHole[lb] &&
                   this->RunsAlongside(loopVertices[la], loopVertices[lb]) &&
                   this->RunsAlongside(loopVertices[lb], loopVertices[la]))
               .first;
      }
      return it->second;
    };
    // The original loop `l` starting at its point v.
    auto rotated = [&](int32_t l, int32_t v)
    {
      std::vector<int32_t> ring(loopVertices[l]);
      std::rotate(ring.begin(), std::find(ring.begin(), ring.end(), v), ring.end());
      return ring;
    };
    std::vector<std::array<int32_t, 2>> installed;
    const double separation = this->Self->GetMinimumBridgeSeparation() * this->Spacing;
    // Whether the bridge ab stays `separation` away from every admitted bridge. The admitted ones
    // are no longer than ab (candidates by length), so only those whose midpoints are within
    // |ab| + separation of ab's can be nearer: the query reaches one separation farther, a margin
    // for rounding (the whole MaximumBridgeLength before, a ball of 10 spacings in a volume).
    auto separate = [&](int32_t a, int32_t b, double length, const double middle[3])
    {
      if (installed.empty())
      {
        return true;
      }
      admitted->FindPointsWithinRadius(length + 2.0 * separation, middle, near);
      for (vtkIdType j = 0; j < near->GetNumberOfIds(); ++j)
      {
        const auto& other = installed[near->GetId(j)];
        if (SegmentDistance(this->P(a), this->P(b), this->P(other[0]), this->P(other[1])) <
          separation)
        {
          return false;
        }
      }
      return true;
    };
    for (const BridgeCandidate& c : candidates)
    {
      const int32_t a = c.A, b = c.B;
      if (bridged[a] || bridged[b] || this->Mesh.GetEdgeValence(a, b) > 0)
      {
        continue;
      }
      const int32_t na = this->NodeOf[a], nb = this->NodeOf[b];
      const int32_t ga = loops.Find(this->Component[a]), gb = loops.Find(this->Component[b]);
      const int32_t la = this->Nodes[na].Loop, lb = this->Nodes[nb].Loop;
      if (inBand[la] || inBand[lb])
      {
        continue; // taken as a band
      }
      // Within one connected group a bridge may only split a loop (closing a hole between two
      // bridges); joining two of its loops would make a handle. Two loops not bridged yet that
      // bound a narrow band are kept for FillBands instead. (The tests that need no geometry
      // come first: in a volume most candidates join two loops of one group.)
      const bool joinsOwnGroup = ga == gb && !loops.SameLoop(na, nb);
      if (joinsOwnGroup && (loopBridged[la] || loopBridged[lb]))
      {
        continue;
      }
      double middle[3];
      for (int i = 0; i < 3; ++i)
      {
        middle[i] = 0.5 * (this->P(a)[i] + this->P(b)[i]);
      }
      if (!separate(a, b, c.Length, middle))
      {
        continue;
      }
      if (joinsOwnGroup)
      {
        if (bandOf(la, lb))
        {
          Band band{ rotated(la, a), rotated(lb, b), {}, {} };
          if (this->ZipBand(band))
          {
            inBand[la] = inBand[lb] = 1;
            this->Bands.push_back(std::move(band));
          }
        }
        continue;
      }
      // The paper's angle rule with the auxiliary points A0, A1 (before / after A along its
      // loop) and B0, B1: the splice below joins A0's side to B1's and A1's to B0's.
      const double* a0 = along(na, -1);
      const double* a1 = along(na, +1);
      const double* b0 = along(nb, -1);
      const double* b1 = along(nb, +1);
      const bool consistent = angle(a0, b1, a1, b0) <= angle(a0, b0, a1, b1);
      if (!consistent)
      {
        if (ga == gb)
        {
          continue; // would need to reverse a group it already belongs to
        }
        loops.Reverse(gb);
      }
      loopBridged[la] = loopBridged[lb] = 1;
      if (ga != gb)
      {
        loops.Join(ga, gb);
      }
      loops.Splice(na, nb);
      bridged[a] = bridged[b] = 1;
      installed.push_back({ a, b });
      admitted->InsertNextPoint(middle);
      this->Links.push_back({ a, b });
    }
    loops.Finish(this->Mesh, seeds);
    this->Bridges = static_cast<vtkIdType>(installed.size());
  }

  // The final loops: holes, and islands (left open).
  std::vector<char> seen(this->Nodes.size(), 0);
  for (int32_t start = 0; start < static_cast<int32_t>(this->Nodes.size()); ++start)
  {
    if (seen[start])
    {
      continue;
    }
    std::vector<int32_t> sequence;
    bool changed = false, touchesHole = false, band = false;
    for (int32_t n = start; !seen[n]; n = this->Nodes[n].Next)
    {
      seen[n] = 1;
      sequence.push_back(n);
      changed = changed || bridged[this->Nodes[n].Vertex] ||
        this->Nodes[n].Loop != this->Nodes[start].Loop;
      touchesHole = touchesHole || this->LoopIsHole[this->Nodes[n].Loop];
      band = band || inBand[this->Nodes[n].Loop];
    }
    if (band)
    {
      continue; // FillBands
    }
    bool hole;
    if (!changed)
    {
      hole = this->LoopIsHole[this->Nodes[start].Loop] != 0;
    }
    else if (touchesHole)
    {
      hole = true;
    }
    else
    {
      std::vector<int32_t> vertices;
      for (int32_t n : sequence)
      {
        vertices.push_back(this->Nodes[n].Vertex);
      }
      hole = this->IsHole(vertices);
    }
    this->FinalLoops.push_back(std::move(sequence));
    this->FinalIsHole.push_back(hole ? 1 : 0);
    this->Holes += hole ? 1 : 0;
  }
  this->Holes += static_cast<vtkIdType>(this->Bands.size());
}

//------------------------------------------------------------------------------------------------
// The strip of FillBands between the loops `first` and `second` (each starting at an end of
// their shortest gap). False when the loops do not run around the part in opposite directions,
// as the two rims of a band of one consistently oriented surface do (the strip would cross the
// part): walking along `first`, the nearest point of `second` must move backwards along it, by
// more than half its length in all; and false when a triangle would be degenerate or a gap of the
// strip would leave the surface, more than 45 degrees from the tangent plane of one of its ends
// (RunsAlongside asks 30 degrees of half the rim points; here every gap, ragged rims included,
// is bounded: where one rim makes an excursion away from the band, the gap would cross the part).
bool Reconstruction::ZipBand(Band& band) const
{
  const std::vector<int32_t>& first = band.First;
  const std::vector<int32_t>& second = band.Second;
  const size_t n = first.size(), m = second.size();
  auto nearest = [&](int32_t v)
  {
    size_t best = 0;
    for (size_t k = 1; k < m; ++k)
    {
      if (vtkMath::Distance2BetweenPoints(this->P(v), this->P(second[k])) <
        vtkMath::Distance2BetweenPoints(this->P(v), this->P(second[best])))
      {
        best = k;
      }
    }
    return static_cast<long>(best);
  };
  long drift = 0, previous = nearest(first[0]);
  const long half = static_cast<long>(m / 2);
  for (size_t i = 1; i <= n; ++i)
  {
    const long current = nearest(first[i % n]);
    const long step =
      (current - previous + static_cast<long>(m) + half) % static_cast<long>(m) - half;
    drift += step;
    previous = current;
  }
  if (2 * drift > -static_cast<long>(m))
  {
    return false;
  }
  const double flat = std::sin(vtkMath::RadiansFromDegrees(45.0));
  auto alongSurface = [&](int32_t u, int32_t v)
  {
    double gap[3], nu[3], nv[3];
    vtkMath::Subtract(this->P(v), this->P(u), gap);
    this->SheetNormal(u, -1, -1, nu);
    this->SheetNormal(v, -1, -1, nv);
    return vtkMath::Normalize(gap) > 0 && std::abs(vtkMath::Dot(gap, nu)) <= flat &&
      std::abs(vtkMath::Dot(gap, nv)) <= flat;
  };
  band.Triangles.clear();
  band.Gaps.clear();
  for (size_t i = 0, j = 0; i < n || j < m;)
  {
    const int32_t a = first[i % n], b = second[(m - j % m) % m];
    const int32_t nextA = first[(i + 1) % n], nextB = second[(2 * m - j % m - 1) % m];
    const double viaA = Distance(this->P(nextA), this->P(b));
    const double viaB = Distance(this->P(a), this->P(nextB));
    const bool alongFirst = j == m || (i < n && viaA <= viaB);
    const std::array<int32_t, 3> triangle =
      alongFirst ? std::array<int32_t, 3>{ nextA, a, b } : std::array<int32_t, 3>{ b, nextB, a };
    if (pcs::projected::Collinear(
          this->P(triangle[0]), this->P(triangle[1]), this->P(triangle[2])) ||
      !alongSurface(alongFirst ? nextA : a, alongFirst ? b : nextB))
    {
      return false;
    }
    band.Triangles.insert(band.Triangles.end(), triangle.begin(), triangle.end());
    band.Gaps.push_back({ a, b });
    (alongFirst ? i : j) += 1;
  }
  return true;
}

// Issue 7: the band of missing surface between two loops that run alongside each other
// (Step4Bridges: a gap around a thin part) is triangulated as a strip, as a ruled surface between
// two curves: from the shortest gap between them, the two loops are walked in the same sense
// around the part (the first along its direction, the second against it: the mesh runs the two
// rims of a band in opposite directions) and each triangle joins the current gap to the next
// point of one loop, the one that gives the shorter new gap. Projected like a hole (steps 5 and
// 6), the two rims of a band around a tube fall onto one circle and the fill crosses the tube.
// The lost points in the band are connected later (InsertLostPoints). A strip with a degenerate
// triangle, or that meets the mesh (FillMeetsMesh) or would break the manifold, is left open, and
// so are its loops in the later steps.
void Reconstruction::FillBands()
{
  if (this->Bands.empty())
  {
    return;
  }
  this->CollectLongTriangles();
  std::vector<int64_t> added;
  for (const Band& band : this->Bands)
  {
    if (this->FillMeetsMesh(band.Triangles) ||
      !this->Mesh.AddTriangles(band.Triangles.data(), band.Triangles.size() / 3, added))
    {
      ++this->HolesLeftOpen;
      ++this->FillsRefused;
      this->OnRefusedLoop.resize(static_cast<size_t>(this->N), 0);
      for (const auto* loop : { &band.First, &band.Second })
      {
        for (int32_t v : *loop)
        {
          this->OnRefusedLoop[v] = 1;
        }
      }
      continue;
    }
    pcs::holes::FillResult result; // the gaps join the step 7 swap candidates
    result.Chords = band.Gaps;
    this->RecordFill(result);
    this->AccountForFill(band.Triangles);
    ++this->HolesFilled;
  }
}

//------------------------------------------------------------------------------------------------
// Steps 5 and 6: every hole is split and triangulated with its lost points.
void Reconstruction::Step6FillHoles(double begin, double end)
{
  if (!this->Self->GetFillHoles())
  {
    this->HolesLeftOpen = this->Holes;
    return;
  }
  this->FillBands();
  const double diameterLimit = this->Self->GetMaximumHoleDiameter();
  pcs::holes::HoleFiller filler;
  filler.AuxiliaryDistance = this->Self->GetAuxiliaryPointDistance() * this->Spacing;
  filler.MaximumGreedyPoints = this->Self->GetMaximumHolePoints();
  // A vertex twice in a loop is a bridge end point and its copy (A, A').
  filler.SplitAtRepeatedVertices = false;
  filler.EdgeExists = [this](int32_t a, int32_t b) { return this->Mesh.GetEdgeValence(a, b) > 0; };
  this->UseSamplingMetric(filler);
  vtkNew<vtkIdList> near;
  std::vector<int32_t> loop, candidates;
  std::vector<double> vectors;
  std::vector<int64_t> added;
  // The fills are first made for every hole, then checked: a fill that meets the mesh or the
  // fill of another hole is not kept (FillMeetsMesh, FillsMeet), then the others are added.
  struct Candidate
  {
    std::vector<int32_t> Loop;
    std::vector<double> Vectors;
    std::vector<int32_t> Lost;
    pcs::holes::FillResult Result;
    double Box[6];
    bool MeetsMesh = false, MeetsFill = false;
  };
  std::vector<Candidate> fills;
  const size_t count = this->FinalLoops.size();
  for (size_t l = 0; l < count; ++l)
  {
    if ((l & 63) == 0 &&
      !this->Progress(begin + 0.5 * (end - begin) * l / static_cast<double>(count)))
    {
      return;
    }
    if (!this->FinalIsHole[l])
    {
      continue;
    }
    // The loop reversed: hole triangles traverse the boundary edges against the mesh.
    const auto& sequence = this->FinalLoops[l];
    loop.clear();
    vectors.clear();
    double centre[3] = { 0, 0, 0 };
    for (auto it = sequence.rbegin(); it != sequence.rend(); ++it)
    {
      const int32_t v = this->Nodes[*it].Vertex;
      loop.push_back(v);
      const double* I = &this->EdgeVectors[3 * static_cast<size_t>(v)];
      vectors.insert(vectors.end(), I, I + 3);
      vtkMath::Add(centre, this->P(v), centre);
    }
    vtkMath::MultiplyScalar(centre, 1.0 / loop.size());
    double radius = 0.0;
    for (int32_t v : loop)
    {
      radius = std::max(radius, Distance(centre, this->P(v)));
    }
    if (2 * radius > diameterLimit * this->Spacing || this->IsNaturalBorder(loop, centre, radius))
    {
      ++this->HolesLeftOpen;
      continue;
    }
    // A 3-vertex loop around an existing triangle is a one-triangle island, not a hole.
    if (loop.size() == 3 && this->Mesh.OppositeVertex(loop[1], loop[0]) == loop[2])
    {
      ++this->HolesLeftOpen;
      continue;
    }
    this->LostFreePointsNear(centre, radius, near, candidates);
    Candidate fill;
    filler.Fill(this->X.data(), loop, vectors, candidates, fill.Result);
    if (fill.Result.Triangles.empty())
    {
      ++this->HolesLeftOpen;
      continue;
    }
    fill.Loop = loop;
    fill.Vectors = vectors;
    fill.Lost = candidates;
    BoundingBox(
      this->X.data(), fill.Result.Triangles.data(), fill.Result.Triangles.size(), fill.Box);
    fills.push_back(std::move(fill));
  }
  this->CollectLongTriangles();
  for (size_t i = 0; i < fills.size(); ++i)
  {
    if ((i & 15) == 0 &&
      !this->Progress(begin + (0.5 + 0.3 * i / static_cast<double>(fills.size())) * (end - begin)))
    {
      return;
    }
    Candidate& fill = fills[i];
    fill.MeetsMesh = this->FillMeetsMesh(fill.Result.Triangles);
  }
  // The pairs of fills whose boxes overlap, each once: in order of their boxes' lower x, a fill
  // meets only the next ones that start before its box ends (all pairs were compared: quadratic
  // in the number of holes).
  std::vector<size_t> byLowerX(fills.size());
  std::iota(byLowerX.begin(), byLowerX.end(), 0);
  std::sort(byLowerX.begin(),
    byLowerX.end(),
    [&fills](size_t a, size_t b) { return fills[a].Box[0] < fills[b].Box[0]; });
  for (size_t s = 0; s < byLowerX.size(); ++s)
  {
    Candidate& fill = fills[byLowerX[s]];
    for (size_t r = s + 1; r < byLowerX.size() && !(fills[byLowerX[r]].Box[0] > fill.Box[1]); ++r)
    {
      Candidate& other = fills[byLowerX[r]];
      if (BoxesOverlap(fill.Box, other.Box) &&
        this->FillsMeet(fill.Result.Triangles, other.Result.Triangles))
      {
        fill.MeetsFill = true;
        other.MeetsFill = true;
      }
    }
  }
  const double maximumDihedral =
    vtkMath::RadiansFromDegrees(this->Self->GetMaximumNormalDeviation());
  for (Candidate& fill : fills)
  {
    // A lost point taken by an earlier fill: this hole is filled again without it, and checked
    // again against the mesh.
    bool taken = false;
    for (int32_t q : fill.Result.UsedPoints)
    {
      taken =
        taken || this->Status[q] != vtkGreedySurfaceTriangulation::LOST || !this->Mesh.IsFree(q);
    }
    if (taken && !fill.MeetsFill)
    {
      candidates.clear();
      for (int32_t q : fill.Lost)
      {
        if (this->Status[q] == vtkGreedySurfaceTriangulation::LOST && this->Mesh.IsFree(q))
        {
          candidates.push_back(q);
        }
      }
      fill.Result = pcs::holes::FillResult();
      filler.Fill(this->X.data(), fill.Loop, fill.Vectors, candidates, fill.Result);
      fill.MeetsMesh = this->FillMeetsMesh(fill.Result.Triangles);
    }
    // A fill meeting the mesh: the loop's least-dihedral triangulation instead, if it meets
    // nothing. A loop whose fill meets another's, or with neither fill, stays open (and is not
    // filled by the later steps either).
    if (fill.MeetsMesh && !fill.MeetsFill)
    {
      fill.Result = pcs::holes::FillResult();
      fill.MeetsMesh = !this->LeastDihedralFill(fill.Loop, maximumDihedral, fill.Result.Triangles);
      fill.Result.Complete = !fill.MeetsMesh;
    }
    if (fill.MeetsMesh || fill.MeetsFill)
    {
      ++this->HolesLeftOpen;
      ++this->FillsRefused;
      this->OnRefusedLoop.resize(static_cast<size_t>(this->N), 0);
      for (int32_t v : fill.Loop)
      {
        this->OnRefusedLoop[v] = 1;
      }
      continue;
    }
    // Add the triangles; undo the whole hole if the mesh would not stay a manifold.
    const pcs::holes::FillResult& result = fill.Result;
    if (result.Triangles.empty() ||
      !this->Mesh.AddTriangles(result.Triangles.data(), result.Triangles.size() / 3, added))
    {
      ++this->HolesLeftOpen;
      continue;
    }
    this->RecordFill(result);
    this->AccountForFill(result.Triangles);
    ++this->HolesFilled;
    if (!result.Complete)
    {
      ++this->HolesLeftOpen; // partly filled
    }
  }
}

//------------------------------------------------------------------------------------------------
// Issue 7: a fill is a guess of missing surface; it may not pass through or touch the mesh
// (a cap across a rim that another part of the mesh crosses or lies on, such as the outer rim of
// a washer whose faces were not sampled: the inner tube ends on its flat cap) nor another fill
// (the caps of two rims that bound one gap, such as the inner and outer rims of the washer's
// face, overlap). The search: the mesh triangles with an edge longer than LongEdgeSpacings are
// listed (CollectLongTriangles at the start of each filling step, AccountForFill after each fill)
// and all tested; every other mesh triangle that meets a fill triangle has a vertex within that
// fill triangle's radius around its centroid plus LongEdgeSpacings (the point locator).
void Reconstruction::CollectLongTriangles()
{
  this->LongTriangles.clear();
  this->LongCells.clear();
  this->OversizedLong.clear();
  this->LongStamp.clear();
  const int64_t ids = this->Mesh.GetNumberOfTriangleIds();
  for (int64_t t = 0; t < ids; ++t)
  {
    if (!this->Mesh.IsTriangleRemoved(t))
    {
      this->AccountForFill(
        std::vector<int32_t>(this->Mesh.GetTriangle(t), this->Mesh.GetTriangle(t) + 3));
    }
  }
}

// Keeps the triangles (3 point ids each) with an edge longer than the search pad of
// FillMeetsMesh, which tests them all.
void Reconstruction::AccountForFill(const std::vector<int32_t>& triangles)
{
  const double pad = LongEdgeSpacings * this->Spacing;
  for (size_t t = 0; t < triangles.size(); t += 3)
  {
    const int32_t* v = &triangles[t];
    if (Distance(this->P(v[0]), this->P(v[1])) > pad ||
      Distance(this->P(v[1]), this->P(v[2])) > pad || Distance(this->P(v[2]), this->P(v[0])) > pad)
    {
      LongTriangle t = { { v[0], v[1], v[2] }, {} };
      BoundingBox(this->X.data(), v, 3, t.Box);
      const int32_t index = static_cast<int32_t>(this->LongTriangles.size());
      this->LongTriangles.push_back(t);
      this->LongStamp.push_back(-1);
      int64_t range[6];
      if (!this->LongCellRange(t.Box, range))
      {
        this->OversizedLong.push_back(index);
        continue;
      }
      for (int64_t i = range[0]; i <= range[1]; ++i)
      {
        for (int64_t j = range[2]; j <= range[3]; ++j)
        {
          for (int64_t k = range[4]; k <= range[5]; ++k)
          {
            this->LongCells[LongCellKey(i, j, k)].push_back(index);
          }
        }
      }
    }
  }
}

// The cells (cubes of the pad's size) that `box` overlaps; false when they are more than
// LongCellsLimit or the box is not finite (the box is then handled apart). Cell keys wrap every
// 2^21 cells along an axis: a shared key only adds candidates, each tested by its box.
bool Reconstruction::LongCellRange(const double box[6], int64_t range[6]) const
{
  constexpr double LongCellsLimit = 64.0;
  const double size = LongEdgeSpacings * this->Spacing;
  double cells = 1.0;
  for (int c = 0; c < 3; ++c)
  {
    const double low = std::floor(box[2 * c] / size);
    const double high = std::floor(box[2 * c + 1] / size);
    if (!(size > 0.0) || !(std::fabs(low) < 1e15) || !(std::fabs(high) < 1e15))
    {
      return false;
    }
    cells *= high - low + 1.0;
    range[2 * c] = static_cast<int64_t>(low);
    range[2 * c + 1] = static_cast<int64_t>(high);
  }
  return cells <= LongCellsLimit;
}

// Two triangles (3 point ids each) whose vertices are all farther apart than MaximumBridgeLength
// spacings: parts of the surface that the sampling does not join, so a contact between them is a
// crossing. Nearer, a contact is a fold at the resolution of the sampling (a fill projected flat
// grazing the ring beyond its ragged rim, a fill on a thin part grazing its other side, the flat
// fills of two neighbouring holes before fairing) and is tolerated.
bool Reconstruction::FarApart(const int32_t* f, const int32_t* g) const
{
  const double limit = this->Self->GetMaximumBridgeLength() * this->Spacing;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      if (!(Distance(this->P(f[i]), this->P(g[j])) > limit))
      {
        return false;
      }
    }
  }
  return true;
}

// True when a triangle of `fill` (point ids, 3 per triangle, not in the mesh) meets a mesh
// triangle far apart from it (FarApart; pcs::holes::TrianglesIntersect, exact).
bool Reconstruction::FillMeetsMesh(const std::vector<int32_t>& fill) const
{
  std::vector<int64_t> around(64);
  auto meet = [this](const int32_t* f, const int32_t* g)
  {
    return this->FarApart(f, g) &&
      pcs::holes::TrianglesIntersect(
        this->P(f[0]), this->P(f[1]), this->P(f[2]), this->P(g[0]), this->P(g[1]), this->P(g[2]));
  };
  const double pad = LongEdgeSpacings * this->Spacing;
  vtkNew<vtkIdList> near;
  for (size_t t = 0; t < fill.size(); t += 3)
  {
    const int32_t* f = &fill[t];
    double box[6];
    BoundingBox(this->X.data(), f, 3, box);
    auto meetsLong = [&](int32_t index)
    {
      if (this->LongStamp[index] == this->LongQuery)
      {
        return false; // (tested from another cell)
      }
      this->LongStamp[index] = this->LongQuery;
      const LongTriangle& g = this->LongTriangles[index];
      return BoxesOverlap(box, g.Box) && meet(f, g.Ids);
    };
    ++this->LongQuery;
    int64_t range[6];
    if (this->LongCellRange(box, range))
    {
      for (int32_t index : this->OversizedLong)
      {
        if (meetsLong(index))
        {
          return true;
        }
      }
      for (int64_t i = range[0]; i <= range[1]; ++i)
      {
        for (int64_t j = range[2]; j <= range[3]; ++j)
        {
          for (int64_t k = range[4]; k <= range[5]; ++k)
          {
            const auto cell = this->LongCells.find(LongCellKey(i, j, k));
            if (cell == this->LongCells.end())
            {
              continue;
            }
            for (int32_t index : cell->second)
            {
              if (meetsLong(index))
              {
                return true;
              }
            }
          }
        }
      }
    }
    else
    {
      for (int32_t index = 0; index < static_cast<int32_t>(this->LongTriangles.size()); ++index)
      {
        if (meetsLong(index))
        {
          return true;
        }
      }
    }
    // Every other triangle meeting f at a point x has a vertex within the pad of x, and x is
    // within f's longest edge of each vertex of f: when these two add up to at most
    // MaximumBridgeLength spacings, no such triangle is far apart from f.
    const double longest = std::max({ Distance(this->P(f[0]), this->P(f[1])),
      Distance(this->P(f[1]), this->P(f[2])),
      Distance(this->P(f[2]), this->P(f[0])) });
    if (longest + pad <= this->Self->GetMaximumBridgeLength() * this->Spacing)
    {
      continue;
    }
    // Otherwise those triangles have a vertex within f's radius around its centroid plus the
    // pad (a triangle may be tested from each of its vertices).
    double centre[3] = { 0, 0, 0 };
    for (int j = 0; j < 3; ++j)
    {
      vtkMath::Add(centre, this->P(f[j]), centre);
    }
    vtkMath::MultiplyScalar(centre, 1.0 / 3.0);
    double radius = 0.0;
    for (int j = 0; j < 3; ++j)
    {
      radius = std::max(radius, Distance(centre, this->P(f[j])));
    }
    this->Locator->FindPointsWithinRadius(radius + pad, centre, near);
    for (vtkIdType k = 0; k < near->GetNumberOfIds(); ++k)
    {
      const int32_t v = static_cast<int32_t>(near->GetId(k));
      if (this->Mesh.IsFree(v))
      {
        continue;
      }
      int n = this->Mesh.GetVertexTriangles(v, around.data(), static_cast<int>(around.size()));
      if (n > static_cast<int>(around.size()))
      {
        around.resize(static_cast<size_t>(n));
        n = this->Mesh.GetVertexTriangles(v, around.data(), n);
      }
      for (int m = 0; m < n; ++m)
      {
        const int32_t* g = this->Mesh.GetTriangle(around[m]);
        bool overlap = true;
        for (int c = 0; c < 3 && overlap; ++c)
        {
          const double a = this->P(g[0])[c], b = this->P(g[1])[c], d = this->P(g[2])[c];
          overlap = std::min({ a, b, d }) <= box[2 * c + 1] && std::max({ a, b, d }) >= box[2 * c];
        }
        if (overlap && meet(f, g))
        {
          return true;
        }
      }
    }
  }
  return false;
}

// True when a triangle of `first` meets a triangle of `second` far apart from it (FarApart).
bool Reconstruction::FillsMeet(const std::vector<int32_t>& first,
  const std::vector<int32_t>& second) const
{
  std::vector<double> boxes(2 * second.size());
  for (size_t t = 0; t < second.size(); t += 3)
  {
    BoundingBox(this->X.data(), &second[t], 3, &boxes[2 * t]);
  }
  for (size_t s = 0; s < first.size(); s += 3)
  {
    const int32_t* f = &first[s];
    double box[6];
    BoundingBox(this->X.data(), f, 3, box);
    for (size_t t = 0; t < second.size(); t += 3)
    {
      const int32_t* g = &second[t];
      if (BoxesOverlap(box, &boxes[2 * t]) && this->FarApart(f, g) &&
        pcs::holes::TrianglesIntersect(
          this->P(f[0]), this->P(f[1]), this->P(f[2]), this->P(g[0]), this->P(g[1]), this->P(g[2])))
      {
        return true;
      }
    }
  }
  return false;
}

//------------------------------------------------------------------------------------------------
// Bookkeeping of a fill kept in the mesh: its triangles are step 6's, its lost points are used by
// hole filling, its chords join the step 7 swap candidates.
void Reconstruction::RecordFill(const pcs::holes::FillResult& result)
{
  this->Stage.resize(static_cast<size_t>(this->Mesh.GetNumberOfTriangleIds()), 6);
  for (int32_t q : result.UsedPoints)
  {
    this->Status[q] = vtkGreedySurfaceTriangulation::LOST_USED_BY_HOLE_FILLING;
  }
  for (const auto& chord : result.Chords)
  {
    this->Links.push_back(chord);
  }
  this->Chords += static_cast<vtkIdType>(result.Chords.size());
}

//------------------------------------------------------------------------------------------------
// After step 6: the lost points still unused are connected to the nearest triangle within reach
// (pcsPointInsertion.h), in passes until no more can be (a point far from the mesh becomes
// reachable once its neighbours are inserted). The edges of the replaced triangles join the
// step 7 swap candidates.
void Reconstruction::InsertLostPoints(double begin, double end)
{
  if (!this->Self->GetInsertLostPoints() || !this->Self->GetFillHoles())
  {
    return;
  }
  std::vector<int32_t> pending;
  for (int32_t v = 0; v < this->N; ++v)
  {
    if (this->Status[v] == vtkGreedySurfaceTriangulation::LOST && this->Mesh.IsFree(v))
    {
      pending.push_back(v);
    }
  }
  const size_t initial = pending.size();
  pcs::PointInsertionResult result;
  bool progress = true;
  while (progress && !pending.empty())
  {
    if (!this->Progress(begin + (end - begin) * (1.0 - pending.size() / static_cast<double>(initial))))
    {
      return;
    }
    progress = false;
    size_t kept = 0;
    for (int32_t q : pending)
    {
      const bool inserted = pcs::InsertFreePoint(this->Mesh, this->X.data(), q,
        &this->Neighbors[static_cast<size_t>(q) * this->K], this->K, true, result);
      const size_t ids = static_cast<size_t>(this->Mesh.GetNumberOfTriangleIds());
      this->Stage.resize(ids, 8);
      for (const auto& moved : result.Restored)
      {
        this->Stage[moved.second] = this->Stage[moved.first];
      }
      if (!inserted)
      {
        pending[kept++] = q;
        continue;
      }
      this->Status[q] = vtkGreedySurfaceTriangulation::LOST_USED_BY_HOLE_FILLING;
      this->Links.insert(this->Links.end(), result.OldEdges.begin(), result.OldEdges.end());
      ++this->Inserted;
      this->InsertedPoints.resize(static_cast<size_t>(this->N), 0);
      this->InsertedPoints[q] = 1;
      progress = true;
      if (result.Added.size() == 1)
      {
        this->CloseSharpEars(q); // attached across a boundary edge
      }
    }
    pending.resize(kept);
  }
}

// A point attached across a boundary edge a -> b leaves the boundary a -> q -> b: the ears at a,
// q and b whose angle is below 90 degrees are closed (triangle (v, p, n) over the front
// p -> v -> n), and then those at the ends of each new front edge, so that the attachments of a
// row of lost points do not leave a zig-zag boundary. An ear is closed only when it keeps the
// manifold, is not degenerate and does not fold against its two neighbouring triangles.
void Reconstruction::CloseSharpEars(int32_t start)
{
  std::vector<int32_t> work;
  auto push = [&](int32_t v) {
    if (this->Mesh.GetVertexState(v) == pcs::SurfaceMesh::VertexState::Boundary &&
      this->Mesh.GetNumberOfFans(v) == 1)
    {
      work.push_back(v);
    }
  };
  push(start);
  int32_t ends[2];
  if (this->Mesh.GetBoundaryOutVertices(start, ends, 1) == 1)
  {
    push(ends[0]);
  }
  if (this->Mesh.GetBoundaryInVertices(start, ends, 1) == 1)
  {
    push(ends[0]);
  }
  auto normal = [this](int32_t a, int32_t b, int32_t c, double n[3]) {
    double u[3], v[3];
    vtkMath::Subtract(this->P(b), this->P(a), u);
    vtkMath::Subtract(this->P(c), this->P(a), v);
    vtkMath::Cross(u, v, n);
  };
  for (size_t i = 0; i < work.size() && i < 64; ++i)
  {
    const int32_t v = work[i];
    int32_t n = -1, p = -1;
    if (this->Mesh.GetNumberOfFans(v) != 1 || this->Mesh.GetBoundaryOutVertices(v, &n, 1) != 1 ||
      this->Mesh.GetBoundaryInVertices(v, &p, 1) != 1 || n == p)
    {
      continue;
    }
    double u[3], w[3];
    vtkMath::Subtract(this->P(p), this->P(v), u);
    vtkMath::Subtract(this->P(n), this->P(v), w);
    if (!(vtkMath::Dot(u, w) > 0)) // 90 degrees or more
    {
      continue;
    }
    // The triangles owning p -> v and v -> n.
    const int32_t c1 = this->Mesh.OppositeVertex(p, v), c2 = this->Mesh.OppositeVertex(v, n);
    if (c1 < 0 || c2 < 0 ||
      this->Mesh.CanAddTriangle(v, p, n) != pcs::SurfaceMesh::Check::Ok ||
      pcs::projected::Collinear(this->P(v), this->P(p), this->P(n)))
    {
      continue;
    }
    double ear[3], n1[3], n2[3];
    normal(v, p, n, ear);
    normal(p, v, c1, n1);
    normal(v, n, c2, n2);
    if (!(vtkMath::Dot(ear, n1) > 0 && vtkMath::Dot(ear, n2) > 0))
    {
      continue;
    }
    this->Mesh.AddTriangle(v, p, n);
    this->Stage.resize(static_cast<size_t>(this->Mesh.GetNumberOfTriangleIds()), 8);
    push(p);
    push(n);
  }
}

//------------------------------------------------------------------------------------------------
// The width of a boundary loop: for each of its vertices, the distance to the nearest loop
// vertex at least a quarter of the loop's length away along the loop (the other side of the
// gap); the width is the lower third of these distances times sqrt(2), so that a circle gives
// its diameter d (the quarter-loop chord is d / sqrt(2)), while a slit of width w gives about
// 1.4 w whatever its length. A zig-zag of the boundary lengthens the loop but moves the quarter
// with it. Quadratic in the loop's size.
double LoopWidth(const double* xyz, const std::vector<int32_t>& loop)
{
  const size_t n = loop.size();
  std::vector<double> arc(n + 1, 0.0);
  for (size_t i = 0; i < n; ++i)
  {
    arc[i + 1] = arc[i] +
      Distance(
        xyz + 3 * static_cast<size_t>(loop[i]), xyz + 3 * static_cast<size_t>(loop[(i + 1) % n]));
  }
  const double length = arc[n];
  std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < n; ++i)
  {
    const double* p = xyz + 3 * static_cast<size_t>(loop[i]);
    for (size_t j = i + 1; j < n; ++j)
    {
      const double along = arc[j] - arc[i];
      if (std::min(along, length - along) < 0.25 * length)
      {
        continue;
      }
      const double d = vtkMath::Distance2BetweenPoints(p, xyz + 3 * static_cast<size_t>(loop[j]));
      nearest[i] = std::min(nearest[i], d);
      nearest[j] = std::min(nearest[j], d);
    }
  }
  const size_t k = n / 3;
  std::nth_element(nearest.begin(), nearest.begin() + k, nearest.end());
  return std::sqrt(2.0 * nearest[k]);
}

//------------------------------------------------------------------------------------------------
// After lost point insertion: a boundary loop still open whose width (LoopWidth) is at most
// MaximumBridgeLength spacings and whose diameter is at most MaximumHoleDiameter, while its
// connected piece of mesh extends over more than twice that diameter, is a sampling gap,
// whatever step 3 called it: it is triangulated like a hole (steps 5 and 6, with the lost points
// inside it). Such loops are the small holes whose few boundary vectors step 3 could not read
// (noise: 7 boundary edges on the noisy knot, loops of 4 or 5 vertices on the noisy camel), the
// loops that lost point insertion reshaped, and long narrow gaps along thin parts (the camel's
// legs, sampled in rings: a 68-vertex loop 20 spacings across but 4.8 wide, whose farthest-point
// votes step 3 cannot read either). The outer border of an open surface is never one: it spans
// its piece.
void Reconstruction::CloseSmallLoops()
{
  if (!this->Self->GetFillHoles())
  {
    return;
  }
  const double limit = this->Self->GetMaximumBridgeLength() * this->Spacing;
  const double diameterLimit = this->Self->GetMaximumHoleDiameter() * this->Spacing;
  std::vector<std::vector<int32_t>> loops;
  this->Mesh.GetBoundaryLoops(loops);
  if (loops.empty())
  {
    return;
  }
  // Connected pieces of the mesh (through shared vertices) and their bounding boxes.
  const std::vector<int32_t> piece = this->VertexPieces();
  std::vector<double> box(6 * static_cast<size_t>(this->N), 0.0);
  std::vector<char> seen(static_cast<size_t>(this->N), 0);
  for (int32_t v = 0; v < this->N; ++v)
  {
    if (this->Mesh.IsFree(v))
    {
      continue;
    }
    const int32_t r = piece[v];
    double* b = &box[6 * static_cast<size_t>(r)];
    for (int j = 0; j < 3; ++j)
    {
      const double x = this->P(v)[j];
      b[2 * j] = seen[r] ? std::min(b[2 * j], x) : x;
      b[2 * j + 1] = seen[r] ? std::max(b[2 * j + 1], x) : x;
    }
    seen[r] = 1;
  }
  pcs::holes::HoleFiller filler;
  filler.AuxiliaryDistance = this->Self->GetAuxiliaryPointDistance() * this->Spacing;
  filler.MaximumGreedyPoints = this->Self->GetMaximumHolePoints();
  filler.EdgeExists = [this](int32_t a, int32_t b) { return this->Mesh.GetEdgeValence(a, b) > 0; };
  this->UseSamplingMetric(filler);
  this->CollectLongTriangles();
  std::vector<int32_t> loop;
  for (const auto& front : loops)
  {
    if (front.size() < 3)
    {
      continue;
    }
    // Reversed: the fill traverses the boundary edges against the mesh (as in step 6).
    loop.assign(front.rbegin(), front.rend());
    double centre[3] = { 0, 0, 0 };
    for (int32_t v : loop)
    {
      vtkMath::Add(centre, this->P(v), centre);
    }
    vtkMath::MultiplyScalar(centre, 1.0 / loop.size());
    double radius = 0.0;
    for (int32_t v : loop)
    {
      radius = std::max(radius, Distance(centre, this->P(v)));
    }
    const double* b = &box[6 * static_cast<size_t>(piece[loop[0]])];
    const double extent = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
      (b[5] - b[4]) * (b[5] - b[4]));
    if (2 * radius > diameterLimit || extent <= 4 * radius)
    {
      continue;
    }
    const double width = LoopWidth(this->X.data(), loop);
    if (width > limit)
    {
      continue;
    }
    // A vertex twice in the loop (the loop touches itself) is left to step 5's chords; a loop
    // through a hole whose fill step 6 refused stays open.
    if (this->OnRefusedLoopAny(loop))
    {
      continue;
    }
    std::vector<int32_t> sorted(loop);
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    {
      continue;
    }
    bool byDihedral = false;
    if (this->FillOpenLoop(filler, loop, centre, radius,
          vtkMath::RadiansFromDegrees(this->Self->GetMaximumNormalDeviation()), byDihedral))
    {
      ++this->LoopsClosed;
      this->LoopsFilledByDihedral += byDihedral ? 1 : 0;
    }
  }
}

// The triangulation of `loop` (reversed, as a hole) on its own vertices of least largest dihedral
// angle (pcs::holes::LeastDihedralFill, the mesh triangles across the loop included), appended to
// `triangles` when that angle is at most `maximumDihedral` (radians) and the fill meets no mesh
// triangle (FillMeetsMesh). False (and a refused fill counted) otherwise.
bool Reconstruction::LeastDihedralFill(const std::vector<int32_t>& loop,
  double maximumDihedral,
  std::vector<int32_t>& triangles)
{
  auto across = [this, &loop](int e, double nrm[3])
  {
    const int32_t a = loop[e], b = loop[(e + 1) % loop.size()];
    const int32_t x = this->Mesh.OppositeVertex(b, a); // the mesh triangle (b, a, x)
    if (x < 0)
    {
      return false;
    }
    double u[3], v[3];
    vtkMath::Subtract(this->P(a), this->P(b), u);
    vtkMath::Subtract(this->P(x), this->P(b), v);
    vtkMath::Cross(u, v, nrm);
    return vtkMath::Normalize(nrm) > 0.0;
  };
  auto edgeExists = [this](int32_t a, int32_t b) { return this->Mesh.GetEdgeValence(a, b) > 0; };
  std::vector<int32_t> fill;
  // Fills beyond maximumDihedral are refused below: the programme does not keep them either.
  const double worst =
    pcs::holes::LeastDihedralFill(this->X.data(), loop, edgeExists, across, fill, maximumDihedral);
  if (!(worst >= 0.0 && worst <= maximumDihedral))
  {
    return false;
  }
  if (this->FillMeetsMesh(fill))
  {
    ++this->FillsRefused;
    return false;
  }
  triangles.insert(triangles.end(), fill.begin(), fill.end());
  return true;
}

// The lost points no triangle uses yet within `radius` of `centre` (the points a hole's fill may
// insert), in increasing id order, in `candidates`; `near` is scratch for the locator's answer.
void Reconstruction::LostFreePointsNear(const double centre[3],
  double radius,
  vtkIdList* near,
  std::vector<int32_t>& candidates) const
{
  candidates.clear();
  this->Locator->FindPointsWithinRadius(radius, centre, near);
  for (vtkIdType j = 0; j < near->GetNumberOfIds(); ++j)
  {
    const int32_t q = static_cast<int32_t>(near->GetId(j));
    if (this->Status[q] == vtkGreedySurfaceTriangulation::LOST && this->Mesh.IsFree(q))
    {
      candidates.push_back(q);
    }
  }
  std::sort(candidates.begin(), candidates.end());
}

// The fill of a loop left open after step 6 (`loop` reversed, as a hole; no vertex twice): steps
// 5 and 6 with the lost points within `radius` of `centre`; when that fill is incomplete, the
// loop's triangulation of least largest dihedral angle on its own vertices, kept when that angle
// (the mesh triangles across the loop included) is at most `maximumDihedral` (radians). The
// triangles are added as one change, refused as a whole when they would break the manifold.
// True when the loop was closed; `byDihedral` tells which fill closed it.
bool Reconstruction::FillOpenLoop(const pcs::holes::HoleFiller& filler,
  const std::vector<int32_t>& loop, const double centre[3], double radius, double maximumDihedral,
  bool& byDihedral)
{
  byDihedral = false;
  std::vector<double> vectors;
  for (int32_t v : loop)
  {
    const double* I = &this->EdgeVectors[3 * static_cast<size_t>(v)];
    vectors.insert(vectors.end(), I, I + 3);
  }
  std::vector<int32_t> candidates;
  vtkNew<vtkIdList> near;
  this->LostFreePointsNear(centre, radius, near, candidates);
  pcs::holes::FillResult result;
  filler.Fill(this->X.data(), loop, vectors, candidates, result);
  // A partial fill would leave a more ragged loop, a fill meeting the mesh may not be made: the
  // triangulation of the loop of least largest dihedral angle instead (no lost point used).
  if (!result.Complete || this->FillMeetsMesh(result.Triangles))
  {
    result = pcs::holes::FillResult();
    if (!this->LeastDihedralFill(loop, maximumDihedral, result.Triangles))
    {
      return false;
    }
    byDihedral = true;
  }
  std::vector<int64_t> added;
  if (!this->Mesh.AddTriangles(result.Triangles.data(), result.Triangles.size() / 3, added))
  {
    return false;
  }
  this->RecordFill(result);
  this->AccountForFill(result.Triangles);
  return true;
}

//------------------------------------------------------------------------------------------------
// After the small loops (CapOpenEnds): a loop still open is the cut end of a tube or of a part
// separated from a closed object (an ear behind a removed band, a leg cut from its body) rather
// than the border of an open surface when its piece of mesh is much larger than the area the
// loop spans: the piece's area is at least CapAreaRatio times the norm of the loop's vector area
// (the flat disc it bounds). The outer border of an open surface spans about its piece (a flat
// sheet 1, a half cylinder pi / 2, a hemisphere bowl 2), a tube end reaching h beyond a
// hemisphere of the rim's radius r gives 2 + 2 h / r, and a narrow slit going back along itself
// spans almost nothing. Such a loop whose diameter is at most MaximumHoleDiameter is closed like
// a small loop, its least-dihedral fallback kept up to MaximumCapDihedral: a cap meets the tube's
// wall at about 90 degrees, more where the cut is ragged. Neither a natural border
// (IsNaturalBorder) nor the mouth of a well (CapsWellMouth) is capped.
void Reconstruction::CapOpenEnds()
{
  if (!this->Self->GetFillHoles() || !this->Self->GetCapOpenEnds())
  {
    return;
  }
  const double diameterLimit = this->Self->GetMaximumHoleDiameter() * this->Spacing;
  std::vector<std::vector<int32_t>> loops;
  this->Mesh.GetBoundaryLoops(loops);
  if (loops.empty())
  {
    return;
  }
  // Connected pieces of the mesh (through shared vertices), their areas and volumes.
  const std::vector<int32_t> piece = this->VertexPieces();
  std::vector<double> area, volume;
  this->PieceAreasAndVolumes(piece, loops, area, volume);
  pcs::holes::HoleFiller filler;
  filler.AuxiliaryDistance = this->Self->GetAuxiliaryPointDistance() * this->Spacing;
  filler.MaximumGreedyPoints = this->Self->GetMaximumHolePoints();
  filler.EdgeExists = [this](int32_t a, int32_t b) { return this->Mesh.GetEdgeValence(a, b) > 0; };
  this->UseSamplingMetric(filler);
  this->CollectLongTriangles();
  std::vector<int32_t> loop, sorted;
  for (const auto& front : loops)
  {
    if (front.size() < 3)
    {
      continue;
    }
    // Reversed: the fill traverses the boundary edges against the mesh (as in step 6). A loop
    // touching itself at a vertex, or through a hole whose fill step 6 refused, is left open.
    loop.assign(front.rbegin(), front.rend());
    sorted = loop;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end() ||
      this->OnRefusedLoopAny(loop))
    {
      continue;
    }
    double centre[3] = { 0, 0, 0 };
    for (int32_t v : loop)
    {
      vtkMath::Add(centre, this->P(v), centre);
    }
    vtkMath::MultiplyScalar(centre, 1.0 / loop.size());
    double radius = 0.0, spanned[3] = { 0, 0, 0 };
    for (size_t i = 0; i < loop.size(); ++i)
    {
      radius = std::max(radius, Distance(centre, this->P(loop[i])));
      double a[3], b[3], c[3];
      vtkMath::Subtract(this->P(loop[i]), centre, a);
      vtkMath::Subtract(this->P(loop[(i + 1) % loop.size()]), centre, b);
      vtkMath::Cross(a, b, c);
      vtkMath::Add(spanned, c, spanned);
    }
    if (2 * radius > diameterLimit ||
      !(area[piece[loop[0]]] >= CapAreaRatio * 0.5 * vtkMath::Norm(spanned)) ||
      this->IsNaturalBorder(loop, centre, radius) ||
      this->CapsWellMouth(loop, centre, radius, area[piece[loop[0]]], volume[piece[loop[0]]]))
    {
      continue;
    }
    bool byDihedral = false;
    if (this->FillOpenLoop(
          filler, loop, centre, radius, vtkMath::RadiansFromDegrees(MaximumCapDihedral), byDihedral))
    {
      ++this->EndsCapped;
      this->LoopsFilledByDihedral += byDihedral ? 1 : 0;
    }
  }
}

//------------------------------------------------------------------------------------------------
// The area of each piece (indexed by its VertexPieces root) and the signed volume it encloses once
// each of its boundary loops is closed by a fan at the loop's centroid: positive when the piece is
// oriented outwards.
void Reconstruction::PieceAreasAndVolumes(const std::vector<int32_t>& piece,
  const std::vector<std::vector<int32_t>>& loops,
  std::vector<double>& area,
  std::vector<double>& volume) const
{
  area.assign(static_cast<size_t>(this->N), 0.0);
  volume.assign(static_cast<size_t>(this->N), 0.0);
  const double* origin = this->P(0);
  const int64_t ids = this->Mesh.GetNumberOfTriangleIds();
  for (int64_t t = 0; t < ids; ++t)
  {
    if (!this->Mesh.IsTriangleRemoved(t))
    {
      const int32_t* tri = this->Mesh.GetTriangle(t);
      double u[3], v[3], n[3];
      vtkMath::Subtract(this->P(tri[1]), this->P(tri[0]), u);
      vtkMath::Subtract(this->P(tri[2]), this->P(tri[0]), v);
      vtkMath::Cross(u, v, n);
      area[piece[tri[0]]] += 0.5 * vtkMath::Norm(n);
      volume[piece[tri[0]]] +=
        TetrahedronVolume6(origin, this->P(tri[0]), this->P(tri[1]), this->P(tri[2])) / 6.0;
    }
  }
  for (const auto& front : loops)
  {
    double centre[3] = { 0, 0, 0 };
    for (int32_t v : front)
    {
      vtkMath::Add(centre, this->P(v), centre);
    }
    vtkMath::MultiplyScalar(centre, 1.0 / front.size());
    for (size_t i = 0; i < front.size(); ++i)
    {
      // The fan's triangle holds the twin of the mesh's half-edge on the loop.
      int32_t a, b;
      this->MeshHalfEdge(front, i, a, b);
      volume[piece[front[0]]] += TetrahedronVolume6(origin, centre, this->P(b), this->P(a)) / 6.0;
    }
  }
}

// The unit normal (unoriented) of the plane through v's K nearest points and v (as
// pcs::EstimatePlaneNormals): the surface's tangent plane at a rim point, which the mesh
// triangles on a ragged rim need not follow. False when fewer than 3 offsets are finite.
bool Reconstruction::TangentNormal(int32_t v, double normal[3]) const
{
  const int32_t* row = &this->Neighbors[static_cast<size_t>(v) * this->K];
  double covariance[3][3], values[3];
  if (pcs::OffsetCovariance(this->X.data(), this->P(v), row, this->K, true, covariance) < 3)
  {
    return false;
  }
  pcs::SmallestEigenvector(covariance, values, normal);
  return true;
}

// Edge i of `loop` (loop[i], loop[i + 1]) as the mesh's half-edge a -> b (its triangle holds
// a -> b; a cap or a fan across the loop holds b -> a).
void Reconstruction::MeshHalfEdge(
  const std::vector<int32_t>& loop, size_t i, int32_t& a, int32_t& b) const
{
  a = loop[i];
  b = loop[(i + 1) % loop.size()];
  if (this->Mesh.FindTriangle(a, b) < 0)
  {
    std::swap(a, b);
  }
}

// The rim test shared by IsNaturalBorder and CapsWellMouth: the loop is wider than
// MaximumBridgeLength spacings (a narrower loop is a sampling gap) and planar: the rms distance of
// its points to their least-squares plane (returned in `plane`) is at most NaturalBorderFlatness
// times its diameter.
bool Reconstruction::IsWidePlanarRim(
  const std::vector<int32_t>& loop, double radius, pcs::holes::Plane& plane) const
{
  if (loop.size() < 3 || 2.0 * radius <= this->Self->GetMaximumBridgeLength() * this->Spacing ||
    !plane.Fit(this->X.data(), loop.data(), loop.size()))
  {
    return false;
  }
  double squares = 0.0;
  for (int32_t v : loop)
  {
    const double d = plane.Distance(this->P(v));
    squares += d * d;
  }
  return std::sqrt(squares / loop.size()) <= NaturalBorderFlatness * 2.0 * radius;
}

// A loop at the mouth of a well (CapOpenEnds): wider than MaximumBridgeLength spacings (a
// narrower loop is a sampling gap, closed as the small loops are), planar as a natural border's
// rim (NaturalBorderFlatness), with no lost point within half its radius of its centre, where the
// mesh beyond the loop rises over the outer side of the cap, making an angle of more than
// MaximumCapFold degrees with it on the side of the material (CapFoldAngle). The piece's
// orientation is read from the sign of its volume, when that volume is at least its area times
// MinimumCapVolumeThickness mean spacings.
bool Reconstruction::CapsWellMouth(const std::vector<int32_t>& loop,
  const double centre[3],
  double radius,
  double area,
  double volume) const
{
  // A wide planar rim (as a natural border's): the angle with one cap plane means nothing on a
  // loop winding in space.
  pcs::holes::Plane plane;
  if (!(std::abs(volume) >= MinimumCapVolumeThickness * this->Spacing * area) ||
    !this->IsWidePlanarRim(loop, radius, plane))
  {
    return false;
  }
  // Lost points within half the loop's radius of its centre: samples of the surface across the
  // loop (a hole to fill, as IsNaturalBorder's).
  vtkNew<vtkIdList> near;
  this->Locator->FindPointsWithinRadius(0.5 * radius, centre, near);
  for (vtkIdType j = 0; j < near->GetNumberOfIds(); ++j)
  {
    const int32_t q = static_cast<int32_t>(near->GetId(j));
    if (this->Status[q] == vtkGreedySurfaceTriangulation::LOST && this->Mesh.IsFree(q))
    {
      return false;
    }
  }
  return this->CapFoldAngle(loop, centre, volume) > MaximumCapFold;
}

// The angle (degrees, 0 to 360) that the mesh makes with a cap of `loop` across the loop, on the
// side of the material (inside the piece closed by the cap, oriented outwards when `outward` is
// positive): about 90 at the cut end of a tube, 180 where the cap continues the surface, 270 at the
// mouth of a hole through the object whose wall leaves the loop at a right angle to the cap.
double Reconstruction::CapFoldAngle(const std::vector<int32_t>& loop,
  const double centre[3],
  double outward) const
{
  // The cap's normal: its triangles hold the twins of the mesh's half-edges on the loop.
  double normal[3] = { 0, 0, 0 };
  for (size_t i = 0; i < loop.size(); ++i)
  {
    int32_t a, b;
    this->MeshHalfEdge(loop, i, a, b);
    double u[3], v[3], n[3];
    vtkMath::Subtract(this->P(b), centre, u);
    vtkMath::Subtract(this->P(a), centre, v);
    vtkMath::Cross(u, v, n);
    vtkMath::Add(normal, n, normal);
  }
  if (vtkMath::Normalize(normal) == 0.0 || outward == 0.0)
  {
    return NaN;
  }
  // The cap lies on the side of each edge that its own normal (the loop's orientation) tells; the
  // outward normal is the cap's, or its opposite when the piece is oriented inwards.
  const double capNormal[3] = { normal[0], normal[1], normal[2] };
  vtkMath::MultiplyScalar(normal, outward > 0.0 ? 1.0 : -1.0);
  // Per loop edge, the direction from the edge into its mesh triangle, perpendicular to the edge,
  // against the direction from the edge into the cap (in the cap's plane, on the cap's side of
  // the edge: its triangle holds the edge's twin) and the outward normal.
  double acrossSum = 0.0, heightSum = 0.0;
  for (size_t i = 0; i < loop.size(); ++i)
  {
    int32_t a, b;
    this->MeshHalfEdge(loop, i, a, b);
    const int32_t c = this->Mesh.OppositeVertex(a, b);
    if (c < 0)
    {
      continue;
    }
    // The cap holds b -> a. The surface leaves the edge in the tangent plane of b's K nearest
    // points (as IsNaturalBorder's: the triangles on a ragged rim may fold anywhere), on the side
    // of the mesh triangle's third vertex.
    double edge[3], towards[3], into[3], capward[3], tangentNormal[3];
    if (!this->TangentNormal(b, tangentNormal))
    {
      continue;
    }
    vtkMath::Subtract(this->P(a), this->P(b), edge);
    const double length = vtkMath::Normalize(edge);
    vtkMath::Subtract(this->P(c), this->P(b), towards);
    vtkMath::Cross(tangentNormal, edge, into);
    if (vtkMath::Dot(into, towards) < 0.0)
    {
      vtkMath::MultiplyScalar(into, -1.0);
    }
    vtkMath::Cross(capNormal, edge, capward);
    if (vtkMath::Normalize(into) == 0.0 || vtkMath::Normalize(capward) == 0.0)
    {
      continue;
    }
    acrossSum += length * vtkMath::Dot(into, capward);
    heightSum += length * vtkMath::Dot(into, normal);
  }
  // The cap leaves the loop at angle 0; the material lies below it (against the normal).
  const double angle = vtkMath::DegreesFromRadians(std::atan2(-heightSum, acrossSum));
  return angle < 0.0 ? angle + 360.0 : angle;
}

//------------------------------------------------------------------------------------------------
// A loop is the natural border of an open scan (a cut: the neck of a head, the ends of a tube, the
// mouth of a vase), not a hole to fill, when it is wider than MaximumBridgeLength spacings (a
// narrower gap is a sampling gap, as for the small loops), its rim is planar (rms distance to its
// least-squares plane at most NaturalBorderFlatness times its diameter), the surface meets that
// plane steeply (the mean |cos| of the angle between the plane's normal and the tangent planes of
// the rim points is below NaturalBorderSteepness: more than 60 degrees) and no input point lies
// within half the rim's radius of its centre (samples inside the rim: a flat end whose points
// step 2 lost) nor beyond the plane, more than NaturalBorderClearance spacings from it, within the
// ball of the rim's radius tangent to the plane at the rim's centre on the side away from the
// surface. A removed region of a curved surface leaves a rim the surface crosses at a shallow
// angle (a sphere's cap of half-angle a: cos a; caps up to about 55 degrees are filled, one of 60
// degrees is left open); a part cut off from a body by a removed band (an ear, a capsule's half)
// faces the body across the gap.
bool Reconstruction::IsNaturalBorder(const std::vector<int32_t>& loop,
  const double centre[3],
  double radius)
{
  pcs::holes::Plane plane;
  if (!this->IsWidePlanarRim(loop, radius, plane))
  {
    return false;
  }
  // The surface's tangent planes at the rim: each rim point's plane through its K nearest
  // points (as pcs::EstimatePlaneNormals), not the mesh triangles on the loop, which can lie in
  // the rim's plane (a fan of step 1 across the end ring of a scan-line cylinder).
  double cosines = 0.0, side = 0.0;
  for (int32_t v : loop)
  {
    const int32_t* row = &this->Neighbors[static_cast<size_t>(v) * this->K];
    double normal[3];
    if (!this->TangentNormal(v, normal))
    {
      return false;
    }
    cosines += std::abs(vtkMath::Dot(normal, plane.N));
    for (int j = 0; j < this->K && row[j] >= 0; ++j)
    {
      side += plane.Distance(this->P(row[j]));
    }
  }
  if (!(cosines < NaturalBorderSteepness * loop.size()) || side == 0.0)
  {
    return false;
  }
  const double away = side > 0.0 ? -1.0 : 1.0;
  double ball[3];
  for (int k = 0; k < 3; ++k)
  {
    ball[k] = centre[k] + away * radius * plane.N[k];
  }
  // Samples inside the rim (a flat end whose points step 2 lost) make it a hole to fill.
  vtkNew<vtkIdList> near;
  this->Locator->FindPointsWithinRadius(0.5 * radius, centre, near);
  for (vtkIdType j = 0; j < near->GetNumberOfIds(); ++j)
  {
    const int32_t q = static_cast<int32_t>(near->GetId(j));
    if (this->Status[q] != vtkGreedySurfaceTriangulation::NOT_TRIANGULATED)
    {
      return false;
    }
  }
  this->Locator->FindPointsWithinRadius(radius, ball, near);
  for (vtkIdType j = 0; j < near->GetNumberOfIds(); ++j)
  {
    const int32_t q = static_cast<int32_t>(near->GetId(j));
    if (this->Status[q] != vtkGreedySurfaceTriangulation::NOT_TRIANGULATED &&
      away * plane.Distance(this->P(q)) > NaturalBorderClearance * this->Spacing)
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------------------------
// The edge ab of the triangles (a, b, c) and (b, a, d) replaced by cd (triangles (c, a, d) and
// (d, b, c)) when cd is not an edge yet, the new triangles face like the old ones, are not
// degenerate (exact) and leave a, b, c and d with one fan each, and: cd is shorter than ab
// (byAngle false, the paper's step 7), or the smallest angle of the pair grows (byAngle true).
// The new triangles get `stage`, or with 0 the stages of the triangles they replace; their ids
// are written to `made`.
bool Reconstruction::SwapEdge(int32_t a, int32_t b, uint8_t stage, bool byAngle, int64_t made[2])
{
  if (this->Mesh.GetEdgeValence(a, b) != 2)
  {
    return false;
  }
  const int64_t t1 = this->Mesh.FindTriangle(a, b), t2 = this->Mesh.FindTriangle(b, a);
  const int32_t c = this->Mesh.OppositeVertex(a, b), d = this->Mesh.OppositeVertex(b, a);
  if (c < 0 || d < 0 || c == d || this->Mesh.GetEdgeValence(c, d) > 0)
  {
    return false;
  }
  if (byAngle ? !(std::max(this->LargestCosine(c, a, d), this->LargestCosine(d, b, c)) <
                  std::max(this->LargestCosine(a, b, c), this->LargestCosine(b, a, d)))
              : !(Distance(this->P(c), this->P(d)) < Distance(this->P(a), this->P(b))))
  {
    return false;
  }
  // New triangles (c, a, d) and (d, b, c) must face like the old ones.
  double n1[3], n2[3], old1[3], old2[3], sum[3];
  this->TriangleNormal(a, b, c, old1);
  this->TriangleNormal(b, a, d, old2);
  vtkMath::Add(old1, old2, sum);
  this->TriangleNormal(c, a, d, n1);
  this->TriangleNormal(d, b, c, n2);
  if (!(vtkMath::Dot(n1, sum) > 0 && vtkMath::Dot(n2, sum) > 0) ||
    pcs::projected::Collinear(this->P(c), this->P(a), this->P(d)) ||
    pcs::projected::Collinear(this->P(d), this->P(b), this->P(c)))
  {
    return false;
  }
  const uint8_t s1 = this->Stage[t1], s2 = this->Stage[t2];
  this->Mesh.RemoveTriangle(t1);
  this->Mesh.RemoveTriangle(t2);
  const int64_t u1 = this->Mesh.AddTriangle(c, a, d);
  const int64_t u2 = u1 >= 0 ? this->Mesh.AddTriangle(d, b, c) : -1;
  bool ok = u1 >= 0 && u2 >= 0;
  for (int32_t v : { a, b, c, d })
  {
    ok = ok && this->Mesh.GetNumberOfFans(v) == 1;
  }
  if (!ok)
  {
    if (u2 >= 0)
    {
      this->Mesh.RemoveTriangle(u2);
    }
    if (u1 >= 0)
    {
      this->Mesh.RemoveTriangle(u1);
    }
    const int64_t r1 = this->Mesh.AddTriangle(a, b, c);
    const int64_t r2 = this->Mesh.AddTriangle(b, a, d);
    this->Stage.resize(static_cast<size_t>(this->Mesh.GetNumberOfTriangleIds()), 6);
    if (r1 >= 0 && r2 >= 0)
    {
      this->Stage[r1] = s1;
      this->Stage[r2] = s2;
    }
    return false;
  }
  this->Stage.resize(static_cast<size_t>(this->Mesh.GetNumberOfTriangleIds()), 6);
  this->Stage[u1] = stage > 0 ? stage : s1;
  this->Stage[u2] = stage > 0 ? stage : s2;
  made[0] = u1;
  made[1] = u2;
  return true;
}

// The normal of the triangle (a, b, c), not normalised (pcs::projected::TriangleNormal).
void Reconstruction::TriangleNormal(int32_t a, int32_t b, int32_t c, double n[3]) const
{
  pcs::projected::TriangleNormal(this->P(a), this->P(b), this->P(c), n);
}

// The cosines of the angles of the triangle (a, b, c) at a, b and c (1 at a repeated point).
void Reconstruction::AngleCosines(int32_t a, int32_t b, int32_t c, double cosines[3]) const
{
  const int32_t ids[3] = { a, b, c };
  for (int i = 0; i < 3; ++i)
  {
    double u[3], v[3];
    vtkMath::Subtract(this->P(ids[(i + 1) % 3]), this->P(ids[i]), u);
    vtkMath::Subtract(this->P(ids[(i + 2) % 3]), this->P(ids[i]), v);
    const double nu = vtkMath::Norm(u), nv = vtkMath::Norm(v);
    cosines[i] = nu > 0 && nv > 0 ? vtkMath::Dot(u, v) / (nu * nv) : 1.0;
  }
}

// The cosine of the smallest angle of the triangle (a, b, c).
double Reconstruction::LargestCosine(int32_t a, int32_t b, int32_t c) const
{
  double cosines[3];
  this->AngleCosines(a, b, c, cosines);
  return std::max(std::max(cosines[0], cosines[1]), cosines[2]);
}

//------------------------------------------------------------------------------------------------
// Step 7: bridge and chord edges replaced by the shorter diagonal of their two triangles.
void Reconstruction::Step7Swaps()
{
  if (!this->Self->GetSwapBridgeEdges())
  {
    return;
  }
  for (const auto& link : this->Links)
  {
    int64_t made[2];
    if (this->SwapEdge(link[0], link[1], 7, false, made))
    {
      ++this->Swaps;
    }
  }
}

//------------------------------------------------------------------------------------------------
// Step 7 on every triangle (ours, issue 7): the edge ab opposite an obtuse angle at c is swapped
// for cd when the smallest angle of the two triangles grows (Lawson's local max-min angle swap)
// and the new triangles fold by at most ObtuseSwapFold (they stay in the surface the old pair
// lies in), for two triangles of one stage other than hole filling. Step 1 joins three nearly
// collinear points of a regular sampling by their two short edges and the long one (the
// shortest-edge order takes ab before the edges to d); the paper's "cd shorter than ab" does not
// hold there (cd is as long as ab). New triangles are examined in turn; every swap raises the
// sorted vector of the mesh's angles, so the pass ends.
void Reconstruction::SwapObtuseEdges()
{
  if (!this->Self->GetSwapBridgeEdges())
  {
    return;
  }
  const double cosineFold = std::cos(vtkMath::RadiansFromDegrees(ObtuseSwapFold));
  std::vector<int64_t> pending;
  for (int64_t t = this->Mesh.GetNumberOfTriangleIds() - 1; t >= 0; --t)
  {
    if (!this->Mesh.IsTriangleRemoved(t))
    {
      pending.push_back(t);
    }
  }
  while (!pending.empty())
  {
    const int64_t t = pending.back();
    pending.pop_back();
    if (this->Mesh.IsTriangleRemoved(t))
    {
      continue;
    }
    const int32_t* tri = this->Mesh.GetTriangle(t);
    double cosines[3];
    this->AngleCosines(tri[0], tri[1], tri[2], cosines);
    const int corner =
      static_cast<int>(std::min_element(cosines, cosines + 3) - cosines); // the largest angle
    if (!(cosines[corner] < 0.0))
    {
      continue;
    }
    const int32_t c = tri[corner], a = tri[(corner + 1) % 3], b = tri[(corner + 2) % 3];
    const int32_t d = this->Mesh.OppositeVertex(b, a);
    if (d < 0 || d == c)
    {
      continue;
    }
    // Pairs of one stage, not of hole filling: the stages stay true (a step 1 triangle has only
    // correct or boundary points), and the fills are refined and faired afterwards.
    const uint8_t stage = this->Stage[t];
    if (stage == 6 || stage == 7 || this->Stage[this->Mesh.FindTriangle(b, a)] != stage)
    {
      continue;
    }
    double n1[3], n2[3];
    this->TriangleNormal(c, a, d, n1);
    this->TriangleNormal(d, b, c, n2);
    if (!(vtkMath::Normalize(n1) > 0 && vtkMath::Normalize(n2) > 0 &&
          vtkMath::Dot(n1, n2) >= cosineFold))
    {
      continue;
    }
    int64_t made[2];
    if (this->SwapEdge(a, b, 0, true, made))
    {
      ++this->ObtuseSwaps;
      pending.push_back(made[0]);
      pending.push_back(made[1]);
    }
  }
}

// Closed components are oriented outwards (positive signed volume).
void Reconstruction::OrientOutwards()
{
  const int64_t ids = this->Mesh.GetNumberOfTriangleIds();
  std::vector<char> seen(ids, 0);
  std::vector<int64_t> stack;
  for (int64_t seed = 0; seed < ids; ++seed)
  {
    if (this->Mesh.IsTriangleRemoved(seed) || seen[seed])
    {
      continue;
    }
    seen[seed] = 1;
    stack.assign(1, seed);
    bool closed = true;
    double volume = 0.0;
    const double* origin = this->P(this->Mesh.GetTriangle(seed)[0]);
    while (!stack.empty())
    {
      const int64_t t = stack.back();
      stack.pop_back();
      const int32_t* tri = this->Mesh.GetTriangle(t);
      volume += TetrahedronVolume6(origin, this->P(tri[0]), this->P(tri[1]), this->P(tri[2]));
      for (int j = 0; j < 3; ++j)
      {
        const int64_t u = this->Mesh.FindTriangle(tri[(j + 1) % 3], tri[j]);
        if (u < 0)
        {
          closed = false;
        }
        else if (!seen[u])
        {
          seen[u] = 1;
          stack.push_back(u);
        }
      }
    }
    if (closed && volume < 0)
    {
      this->Mesh.ReverseComponent(seed);
    }
  }
}

//------------------------------------------------------------------------------------------------
// After steps 6 to 8 (FairHoleFills): the hole-filling triangles (stages 6 and 7) are refined to
// the spacing of the mesh around them and the new vertices faired, after Liepa ("Filling holes
// in meshes", 2003, sections 3.2-3.3). The projected fill of step 6 is flat and, across a wide
// removed region, made of long thin triangles between its rim points; the refinement places
// points inside it at the local density and the fairing bends the patch to continue the surface
// around it (smoothly, with the rim and its outer ring of vertices fixed).
// - Patches: only the fill patches that span a region without input points are treated (below).
// - Density: sigma(v) of an input vertex is the mean length of its edges in the triangles not
//   made by hole filling (the global mean of those edges for a vertex with none). A fill
//   triangle (i, j, k) with centroid c and sigma_c = mean of its sigmas is split at c into three
//   when sqrt(2) |c - v| > max(sigma_c, sigma_v) for each of its vertices v; c gets sigma_c.
// - Relaxation: after each round of splits, an edge between two fill triangles (a, b, c) and
//   (b, a, d) is flipped to c-d when the angles at c and d sum to more than 180 degrees (it is
//   not locally Delaunay), unless c-d is an edge already or the flip would fold the patch.
// - Fairing: the new vertices (only they move) minimise the sum over the vertices whose
//   umbrella involves them of d(v)^2 |U(v)|^2 / A(v), U(v) = mean of the d(v) neighbours - v
//   (uniform weights), A(v) a third of the area of v's triangles: the discrete thin-plate
//   energy, the integral of the squared Laplacian (U(v) d(v) / A(v) estimates it whatever the
//   edge lengths), solved by conjugate gradients on the normal equations preconditioned by
//   their diagonal, twice (the second pass with the areas of the first's shape).
// The input points of the fill (rim and lost points) stay where they are. The triangles keep
// their stage. Returns the coordinates of the new points (ids N, N + 1, ...).
void Reconstruction::RefineAndFairFills(std::vector<int32_t>& triangles,
  std::vector<uint8_t>& stages, std::vector<double>& added, double begin, double end)
{
  added.clear();
  const size_t count = stages.size();
  auto isFill = [&stages](size_t t) { return stages[t] == 6 || stages[t] == 7; };
  auto point = [this, &added](int32_t v) -> const double* {
    return v < this->N ? this->P(v) : &added[3 * static_cast<size_t>(v - this->N)];
  };
  // Sigma of the input vertices from the edges of the other triangles.
  std::vector<double> sigma(static_cast<size_t>(this->N), 0.0);
  std::vector<int32_t> edgeCount(static_cast<size_t>(this->N), 0);
  double sum = 0.0;
  int64_t edges = 0;
  bool anyFill = false;
  for (size_t t = 0; t < count; ++t)
  {
    if (isFill(t))
    {
      anyFill = true;
      continue;
    }
    const int32_t* tri = &triangles[3 * t];
    for (int j = 0; j < 3; ++j)
    {
      // Per triangle, each edge counts for its two end points (an edge between two such
      // triangles counts twice: a mean weighted by the number of triangles).
      const double length = Distance(this->P(tri[j]), this->P(tri[(j + 1) % 3]));
      for (int32_t v : { tri[j], tri[(j + 1) % 3] })
      {
        sigma[v] += length;
        ++edgeCount[v];
      }
      sum += length;
      ++edges;
    }
  }
  if (!anyFill)
  {
    return;
  }
  const double globalSigma = edges > 0 ? sum / edges : this->Spacing;
  for (int32_t v = 0; v < this->N; ++v)
  {
    sigma[v] = edgeCount[v] > 0 ? sigma[v] / edgeCount[v] : globalSigma;
  }
  edgeCount.clear();
  edgeCount.shrink_to_fit();

  // The fill patches (fill triangles connected through their edges) that span a region without
  // input points: one of their triangles has its centroid farther than 3 sigma_c from every
  // input point. Fills among the input points (the common small holes of step 2) are left
  // as they are.
  std::vector<int64_t> fill; // fill index -> triangle index in `triangles`
  {
    std::vector<int64_t> all;
    for (size_t t = 0; t < count; ++t)
    {
      if (isFill(t))
      {
        all.push_back(static_cast<int64_t>(t));
      }
    }
    std::unordered_map<uint64_t, int64_t> firstOnEdge;
    pcs::DisjointSets<int64_t> patches(static_cast<int64_t>(all.size()));
    for (int64_t f = 0; f < static_cast<int64_t>(all.size()); ++f)
    {
      const int32_t* tri = &triangles[3 * all[f]];
      for (int j = 0; j < 3; ++j)
      {
        const int32_t a = tri[j], b = tri[(j + 1) % 3];
        const uint64_t k =
          (static_cast<uint64_t>(std::max(a, b)) << 32) | static_cast<uint32_t>(std::min(a, b));
        auto it = firstOnEdge.emplace(k, f);
        if (!it.second)
        {
          patches.Union(f, it.first->second);
        }
      }
    }
    std::vector<char> empty(all.size(), 0);
    // Measured largest centroid distances over sigma_c: 1.1 to 1.95 in the fills of clean and
    // noisy surfaces (5,000-point sphere and torus, bunny00, camel, noisy bunny00), 7.9 to 12.9
    // in those of the removed regions of the benchmark's damaged bunny and armadillo.
    const double emptyFactor = 3.0;
    for (size_t f = 0; f < all.size(); ++f)
    {
      const int32_t* tri = &triangles[3 * all[f]];
      double c[3] = { 0, 0, 0 };
      double sc = 0.0;
      for (int j = 0; j < 3; ++j)
      {
        vtkMath::Add(c, this->P(tri[j]), c);
        sc += sigma[tri[j]];
      }
      vtkMath::MultiplyScalar(c, 1.0 / 3.0);
      sc /= 3.0;
      const vtkIdType nearest = this->Locator->FindClosestPoint(c);
      const double d = nearest >= 0 ? Distance(c, this->P(static_cast<int32_t>(nearest))) : 0.0;
      if (d > emptyFactor * sc)
      {
        empty[patches.Find(static_cast<int64_t>(f))] = 1;
      }
    }
    for (size_t f = 0; f < all.size(); ++f)
    {
      if (empty[patches.Find(static_cast<int64_t>(f))])
      {
        fill.push_back(all[f]);
      }
    }
  }
  if (fill.empty())
  {
    return;
  }
  auto key = [](int32_t a, int32_t b) {
    const uint32_t lo = static_cast<uint32_t>(std::min(a, b));
    const uint32_t hi = static_cast<uint32_t>(std::max(a, b));
    return (static_cast<uint64_t>(hi) << 32) | lo;
  };
  // Edge -> the fill triangles on it (-1: none, or a triangle not made by hole filling).
  std::unordered_map<uint64_t, std::array<int64_t, 2>> edgeTriangles;
  edgeTriangles.reserve(3 * fill.size());
  auto attach = [&](int32_t a, int32_t b, int64_t f) {
    auto it = edgeTriangles.emplace(key(a, b), std::array<int64_t, 2>{ -1, -1 }).first;
    it->second[it->second[0] < 0 ? 0 : 1] = f;
  };
  auto detach = [&](int32_t a, int32_t b, int64_t f) {
    auto it = edgeTriangles.find(key(a, b));
    if (it != edgeTriangles.end())
    {
      for (auto& slot : it->second)
      {
        slot = slot == f ? -1 : slot;
      }
      if (it->second[0] < 0 && it->second[1] < 0)
      {
        edgeTriangles.erase(it);
      }
    }
  };
  for (size_t f = 0; f < fill.size(); ++f)
  {
    const int32_t* tri = &triangles[3 * fill[f]];
    for (int j = 0; j < 3; ++j)
    {
      attach(tri[j], tri[(j + 1) % 3], static_cast<int64_t>(f));
    }
  }
  // An edge of the mesh: of a fill triangle now, or of any triangle of the mesh before (an edge
  // of a fill triangle flipped away is still refused: a missed flip, never a third triangle).
  auto edgeExists = [&](int32_t a, int32_t b) {
    return edgeTriangles.count(key(a, b)) > 0 ||
      (a < this->N && b<this->N&& this->Mesh.GetEdgeValence(a, b)> 0);
  };
  auto normal = [&](int32_t a, int32_t b, int32_t c, double n[3]) {
    double u[3], w[3];
    vtkMath::Subtract(point(b), point(a), u);
    vtkMath::Subtract(point(c), point(a), w);
    vtkMath::Cross(u, w, n);
  };
  auto angle = [&](int32_t apex, int32_t a, int32_t b) {
    double u[3], w[3];
    vtkMath::Subtract(point(a), point(apex), u);
    vtkMath::Subtract(point(b), point(apex), w);
    return vtkMath::AngleBetweenVectors(u, w);
  };
  // Flip the edge {a, b} of two fill triangles when it is not locally Delaunay.
  auto relax = [&](int32_t a, int32_t b) {
    auto it = edgeTriangles.find(key(a, b));
    if (it == edgeTriangles.end() || it->second[0] < 0 || it->second[1] < 0)
    {
      return false;
    }
    int64_t f1 = it->second[0], f2 = it->second[1];
    int32_t* t1 = &triangles[3 * fill[f1]];
    // Orient: f1 = (a, b, c) owns a -> b.
    int j1 = 0;
    while (j1 < 3 && t1[j1] != a)
    {
      ++j1;
    }
    if (j1 == 3)
    {
      return false;
    }
    if (t1[(j1 + 1) % 3] != b)
    {
      std::swap(f1, f2); // the other triangle owns a -> b
      t1 = &triangles[3 * fill[f1]];
    }
    int32_t* t2 = &triangles[3 * fill[f2]];
    int32_t c = -1, d = -1;
    for (int j = 0; j < 3; ++j)
    {
      if (t1[j] != a && t1[j] != b)
      {
        c = t1[j];
      }
      if (t2[j] != a && t2[j] != b)
      {
        d = t2[j];
      }
    }
    if (c < 0 || d < 0 || c == d || edgeExists(c, d))
    {
      return false;
    }
    if (!(angle(c, a, b) + angle(d, a, b) > vtkMath::Pi() * (1.0 + 1e-9)))
    {
      return false;
    }
    double n1[3], n2[3], o1[3], o2[3], s[3];
    normal(a, b, c, o1);
    normal(b, a, d, o2);
    vtkMath::Add(o1, o2, s);
    normal(d, b, c, n1);
    normal(a, d, c, n2);
    if (!(vtkMath::Dot(n1, s) > 0 && vtkMath::Dot(n2, s) > 0 && vtkMath::Dot(n1, n2) > 0))
    {
      return false;
    }
    for (int32_t* t : { t1, t2 })
    {
      for (int j = 0; j < 3; ++j)
      {
        detach(t[j], t[(j + 1) % 3], t == t1 ? f1 : f2);
      }
    }
    t1[0] = d;
    t1[1] = b;
    t1[2] = c;
    t2[0] = a;
    t2[1] = d;
    t2[2] = c;
    for (int32_t* t : { t1, t2 })
    {
      for (int j = 0; j < 3; ++j)
      {
        attach(t[j], t[(j + 1) % 3], t == t1 ? f1 : f2);
      }
    }
    return true;
  };
  auto relaxAll = [&](std::vector<std::array<int32_t, 2>>& queue) {
    // Each flip queues the four outer edges of its quad; bounded to avoid cycling on folded
    // patches (the angle criterion has no global potential in 3D).
    size_t budget = 20 * (queue.size() + 16);
    while (!queue.empty() && budget-- > 0)
    {
      const auto e = queue.back();
      queue.pop_back();
      int32_t a = e[0], b = e[1];
      auto it = edgeTriangles.find(key(a, b));
      if (it == edgeTriangles.end() || it->second[0] < 0 || it->second[1] < 0)
      {
        continue;
      }
      // The quad's corners before the flip.
      std::array<int32_t, 4> quad = { a, b, -1, -1 };
      for (int s = 0; s < 2; ++s)
      {
        const int32_t* t = &triangles[3 * fill[it->second[s]]];
        for (int j = 0; j < 3; ++j)
        {
          quad[2 + s] = (t[j] != a && t[j] != b) ? t[j] : quad[2 + s];
        }
      }
      if (relax(a, b))
      {
        queue.push_back({ quad[0], quad[2] });
        queue.push_back({ quad[2], quad[1] });
        queue.push_back({ quad[1], quad[3] });
        queue.push_back({ quad[3], quad[0] });
      }
    }
    queue.clear();
  };

  // Refinement rounds.
  const double alpha = std::sqrt(2.0);
  std::vector<std::array<int32_t, 2>> queue;
  for (size_t f = 0; f < fill.size(); ++f)
  {
    const int32_t* tri = &triangles[3 * fill[f]];
    for (int j = 0; j < 3; ++j)
    {
      queue.push_back({ tri[j], tri[(j + 1) % 3] });
    }
  }
  relaxAll(queue);
  const size_t limit = 64 * (fill.size() + static_cast<size_t>(this->N) / 64 + 16);
  for (int round = 0; round < 64; ++round)
  {
    if (!this->Progress(begin + (end - begin) * 0.5 * round / 64.0))
    {
      return;
    }
    bool split = false;
    const size_t current = fill.size();
    for (size_t f = 0; f < current && fill.size() < limit; ++f)
    {
      int32_t tri[3];
      std::copy_n(&triangles[3 * fill[f]], 3, tri);
      double c[3] = { 0, 0, 0 };
      double sc = 0.0;
      for (int32_t v : tri)
      {
        vtkMath::Add(c, point(v), c);
        sc += sigma[v];
      }
      vtkMath::MultiplyScalar(c, 1.0 / 3.0);
      sc /= 3.0;
      bool dense = false;
      for (int32_t v : tri)
      {
        const double d = alpha * Distance(c, point(v));
        dense = dense || !(d > sc && d > sigma[v]);
      }
      if (dense)
      {
        continue;
      }
      const int32_t m = this->N + static_cast<int32_t>(added.size() / 3);
      added.insert(added.end(), c, c + 3);
      sigma.push_back(sc);
      for (int j = 0; j < 3; ++j)
      {
        detach(tri[j], tri[(j + 1) % 3], static_cast<int64_t>(f));
      }
      // (a, b, m) in place, (b, c, m) and (c, a, m) appended with the same stage.
      const int64_t t = fill[f];
      triangles[3 * t + 2] = m;
      const uint8_t stage = stages[t];
      for (int j = 1; j < 3; ++j)
      {
        triangles.insert(triangles.end(), { tri[j], tri[(j + 1) % 3], m });
        stages.push_back(stage);
        fill.push_back(static_cast<int64_t>(stages.size()) - 1);
      }
      const int64_t ids[3] = { static_cast<int64_t>(f), static_cast<int64_t>(fill.size()) - 2,
        static_cast<int64_t>(fill.size()) - 1 };
      for (int j = 0; j < 3; ++j)
      {
        const int32_t* u = &triangles[3 * fill[ids[j]]];
        for (int i = 0; i < 3; ++i)
        {
          attach(u[i], u[(i + 1) % 3], ids[j]);
        }
        queue.push_back({ tri[j], tri[(j + 1) % 3] });
      }
      split = true;
    }
    if (!split)
    {
      break;
    }
    relaxAll(queue);
  }
  const int32_t newCount = static_cast<int32_t>(added.size() / 3);
  if (newCount == 0)
  {
    return;
  }

  // Fairing: adjacency of every vertex (CSR over all triangles).
  const int32_t total = this->N + newCount;
  std::vector<int64_t> offsets(static_cast<size_t>(total) + 1, 0);
  const size_t triangleCount = triangles.size() / 3;
  for (size_t t = 0; t < triangleCount; ++t)
  {
    for (int j = 0; j < 3; ++j)
    {
      offsets[triangles[3 * t + j] + 1] += 2;
    }
  }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<int32_t> adjacency(static_cast<size_t>(offsets.back()));
  {
    std::vector<int64_t> fillAt(offsets.begin(), offsets.end() - 1);
    for (size_t t = 0; t < triangleCount; ++t)
    {
      for (int j = 0; j < 3; ++j)
      {
        const int32_t v = triangles[3 * t + j];
        adjacency[fillAt[v]++] = triangles[3 * t + (j + 1) % 3];
        adjacency[fillAt[v]++] = triangles[3 * t + (j + 2) % 3];
      }
    }
  }
  // Distinct neighbours (each edge was listed from both of its triangles).
  std::vector<int64_t> start(static_cast<size_t>(total) + 1, 0);
  {
    int64_t write = 0;
    for (int32_t v = 0; v < total; ++v)
    {
      const int64_t b = offsets[v], e = offsets[v + 1];
      std::sort(adjacency.begin() + b, adjacency.begin() + e);
      start[v] = write;
      for (int64_t i = b; i < e; ++i)
      {
        if (i == b || adjacency[i] != adjacency[i - 1])
        {
          adjacency[write++] = adjacency[i];
        }
      }
    }
    start[total] = write;
    adjacency.resize(static_cast<size_t>(write));
  }
  // Rows: the new vertices and their neighbours.
  std::vector<char> isRow(static_cast<size_t>(total), 0);
  for (int32_t v = this->N; v < total; ++v)
  {
    isRow[v] = 1;
    for (int64_t i = start[v]; i < start[v + 1]; ++i)
    {
      isRow[adjacency[i]] = 1;
    }
  }
  std::vector<int32_t> rows;
  for (int32_t v = 0; v < total; ++v)
  {
    if (isRow[v] && start[v + 1] > start[v])
    {
      rows.push_back(v);
    }
  }
  std::vector<double> rowValue(static_cast<size_t>(total), 0.0);
  // Row weights. The energy is the thin plate's, the integral of the squared Laplacian; the
  // umbrella U(r) estimates the Laplacian times about the square of r's edge lengths, so the
  // row of r is weighted by d(r)^2 / A(r) (d(r) neighbours, A(r) a third of the area of its
  // triangles): sum of A(r) (d(r) U(r) / A(r))^2. Unweighted, the coarse fill (longer edges,
  // larger umbrellas) was flattened against the finer mesh around it: an 8,000-point unit sphere
  // with a cap of half-angle 20 degrees removed came back 0.8 to 1.5 mean spacings inside the
  // sphere (10 random samples), 0.3 to 1.0 weighted.
  std::vector<double> rowWeight(static_cast<size_t>(total), 0.0);
  auto weighRows = [&]()
  {
    std::vector<double> area(static_cast<size_t>(total), 0.0);
    for (size_t t = 0; t < triangleCount; ++t)
    {
      const int32_t* tri = &triangles[3 * t];
      if (isRow[tri[0]] || isRow[tri[1]] || isRow[tri[2]])
      {
        double n[3];
        normal(tri[0], tri[1], tri[2], n);
        const double third = vtkMath::Norm(n) / 6.0;
        for (int j = 0; j < 3; ++j)
        {
          area[tri[j]] += third;
        }
      }
    }
    for (int32_t r : rows)
    {
      const double d = static_cast<double>(start[r + 1] - start[r]);
      rowWeight[r] = area[r] > 0.0 ? d * d / area[r] : 0.0;
    }
  };
  // y = A p (p on the new vertices, 0 elsewhere), per row.
  auto apply = [&](const std::vector<double>& p) {
    for (int32_t r : rows)
    {
      double s = 0.0;
      for (int64_t i = start[r]; i < start[r + 1]; ++i)
      {
        const int32_t u = adjacency[i];
        s += u >= this->N ? p[u - this->N] : 0.0;
      }
      s /= static_cast<double>(start[r + 1] - start[r]);
      rowValue[r] = s - (r >= this->N ? p[r - this->N] : 0.0);
    }
  };
  // g = A^T W y on the new vertices (W: the row weights).
  auto applyTranspose = [&](std::vector<double>& g) {
    for (int32_t u = this->N; u < total; ++u)
    {
      double s = 0.0;
      for (int64_t i = start[u]; i < start[u + 1]; ++i)
      {
        const int32_t r = adjacency[i];
        s += rowWeight[r] * rowValue[r] / static_cast<double>(start[r + 1] - start[r]);
      }
      g[u - this->N] = s - rowWeight[u] * rowValue[u];
    }
  };
  std::vector<double> x(newCount), rhs(newCount), residual(newCount), direction(newCount),
    product(newCount), diagonal(newCount);
  const int maxIterations = 2000;
  // Two passes: the second reads its weights on the shape the first gives (where the fill
  // bulges, its faired triangles are larger than the flat ones).
  const int passes = 2;
  double stop[3] = { 0.0, 0.0, 0.0 };
  for (int pass = 0; pass < passes; ++pass)
  {
    weighRows();
    // The diagonal of A^T W A: row u (entry -1) and the rows of u's neighbours (1 / d).
    for (int32_t u = this->N; u < total; ++u)
    {
      double d = rowWeight[u];
      for (int64_t i = start[u]; i < start[u + 1]; ++i)
      {
        const int32_t r = adjacency[i];
        const double count = static_cast<double>(start[r + 1] - start[r]);
        d += rowWeight[r] / (count * count);
      }
      diagonal[u - this->N] = d > 0.0 ? d : 1.0;
    }
    for (int k = 0; k < 3; ++k)
    {
      if (!this->Progress(begin + (end - begin) * (0.5 + (pass * 3 + k) / (6.0 * passes))))
      {
        return;
      }
      // Right-hand side -A^T W U0, U0 the umbrellas of the current positions.
      for (int32_t r : rows)
      {
        double s = 0.0;
        for (int64_t i = start[r]; i < start[r + 1]; ++i)
        {
          s += point(adjacency[i])[k];
        }
        rowValue[r] = s / static_cast<double>(start[r + 1] - start[r]) - point(r)[k];
      }
      applyTranspose(rhs);
      // Conjugate gradients preconditioned by the diagonal of A^T W A (the row weights vary with
      // the inverse square of the local edge length).
      double rr = 0.0, rz = 0.0;
      for (int32_t i = 0; i < newCount; ++i)
      {
        rhs[i] = -rhs[i];
        x[i] = 0.0;
        residual[i] = rhs[i];
        direction[i] = rhs[i] / diagonal[i];
        rr += rhs[i] * rhs[i];
        rz += rhs[i] * direction[i];
      }
      // The second pass starts from the first's solution: its tolerance is the first's (relative
      // to the flat fill's residual), not relative to its own, already small, residual.
      stop[k] = pass == 0 ? 1e-16 * rr : stop[k];
      for (int iteration = 0; iteration < maxIterations && rr > stop[k] && rz > 0; ++iteration)
      {
        apply(direction);
        applyTranspose(product);
        double pAp = 0.0;
        for (int32_t i = 0; i < newCount; ++i)
        {
          pAp += direction[i] * product[i];
        }
        if (!(pAp > 0))
        {
          break;
        }
        const double step = rz / pAp;
        double nextRz = 0.0;
        rr = 0.0;
        for (int32_t i = 0; i < newCount; ++i)
        {
          x[i] += step * direction[i];
          residual[i] -= step * product[i];
          rr += residual[i] * residual[i];
          nextRz += residual[i] * residual[i] / diagonal[i];
        }
        const double beta = nextRz / rz;
        rz = nextRz;
        for (int32_t i = 0; i < newCount; ++i)
        {
          direction[i] = residual[i] / diagonal[i] + beta * direction[i];
        }
      }
      for (int32_t i = 0; i < newCount; ++i)
      {
        if (std::isfinite(x[i]))
        {
          added[3 * static_cast<size_t>(i) + k] += x[i];
        }
      }
    }
  }
}

} // namespace

//------------------------------------------------------------------------------------------------
vtkGreedySurfaceTriangulation::vtkGreedySurfaceTriangulation() = default;
vtkGreedySurfaceTriangulation::~vtkGreedySurfaceTriangulation() = default;

int vtkGreedySurfaceTriangulation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkGreedySurfaceTriangulation::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const auto start = std::chrono::steady_clock::now();
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  // Under MPI the whole cloud is reconstructed on process 0; the other outputs stay empty.
  vtkSmartPointer<vtkPointSet> input =
    pcs::GatherInputOnFirstProcess(vtkPointSet::GetData(inputVector[0]));
  if (!input && output)
  {
    return 1;
  }
  if (!output)
  {
    vtkErrorMacro("Missing output data object.");
    return 0;
  }
  const std::string mismatched = pcs::DropMismatchedPointArrays(input);
  if (!mismatched.empty())
  {
    vtkWarningMacro(<< mismatched);
  }
  this->NumberOfTriangles = 0;
  this->NumberOfLostPoints = 0;
  this->NumberOfIslands = 0;
  this->NumberOfBridges = 0;
  this->NumberOfHolesFilled = 0;
  this->NumberOfUnusedPoints = 0;
  this->NumberOfAddedPoints = 0;
  this->MeanSpacing = 0.0;

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
  vtkNew<vtkUnsignedCharArray> status;
  status->SetName("Status");
  status->SetNumberOfValues(numberOfPoints);
  status->FillValue(NOT_TRIANGULATED);
  vtkNew<vtkDoubleArray> uniformity;
  uniformity->SetName("LocalUniformity");
  uniformity->SetNumberOfValues(numberOfPoints);
  uniformity->FillValue(NaN);
  vtkNew<vtkUnsignedCharArray> stage;
  stage->SetName("Stage");

  Reconstruction r;
  r.Self = this;
  vtkIdType duplicates = 0, skipped = 0, outliers = 0;
  std::string steps;
  double ssrArea = 0.0, totalArea = 0.0, ssrUniformity = 0.0;
  vtkIdType ssrPoints = 0, ssrUniformityCount = 0;
  std::vector<int32_t> connectivity;
  std::vector<vtkIdType> inputIds; // local -> input id
  std::vector<int32_t> localOf;    // input id -> local id (-1: skipped)

  auto finish = [&]() {
    output->GetPointData()->AddArray(used);
    output->GetPointData()->AddArray(status);
    output->GetPointData()->AddArray(uniformity);
    output->GetCellData()->AddArray(stage);
    this->NumberOfTriangles = static_cast<vtkIdType>(connectivity.size() / 3);
    this->NumberOfLostPoints = r.LostPoints;
    this->NumberOfIslands = r.Islands;
    this->NumberOfBridges = r.Bridges;
    this->NumberOfHolesFilled = r.HolesFilled;
    this->NumberOfAddedPoints = r.Added;
    this->MeanSpacing = std::ldexp(r.Spacing, -r.CoordinateExponent);
    this->NumberOfUnusedPoints = 0;
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      this->NumberOfUnusedPoints += used->GetValue(i) ? 0 : 1;
    }
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    vtkFieldData* fd = output->GetFieldData();
    pcs::AddFieldCount(fd, "NumberOfTriangles", this->NumberOfTriangles);
    pcs::AddFieldCount(fd, "NumberOfLostPoints", r.LostPoints);
    pcs::AddFieldCount(fd, "NumberOfIslands", r.Islands);
    pcs::AddFieldCount(fd, "NumberOfHoles", r.Holes);
    pcs::AddFieldCount(fd, "NumberOfBridges", r.Bridges);
    pcs::AddFieldCount(fd, "NumberOfChords", r.Chords);
    pcs::AddFieldCount(fd, "NumberOfHolesFilled", r.HolesFilled);
    pcs::AddFieldCount(fd, "NumberOfHolesLeftOpen", r.HolesLeftOpen);
    pcs::AddFieldCount(fd, "NumberOfSwaps", r.Swaps);
    pcs::AddFieldCount(fd, "NumberOfObtuseSwaps", r.ObtuseSwaps);
    pcs::AddFieldCount(fd, "NumberOfInsertedPoints", r.Inserted);
    pcs::AddFieldCount(fd, "NumberOfAddedPoints", r.Added);
    pcs::AddFieldCount(fd, "NumberOfSmallLoopsClosed", r.LoopsClosed);
    pcs::AddFieldCount(fd, "NumberOfSmallLoopsFilledByDihedral", r.LoopsFilledByDihedral);
    pcs::AddFieldCount(fd, "NumberOfEndsCapped", r.EndsCapped);
    pcs::AddFieldCount(fd, "NumberOfFillsRefused", r.FillsRefused);
    pcs::AddFieldCount(fd, "NumberOfPiecesExchanged", r.PiecesExchanged);
    pcs::AddFieldCount(fd, "NumberOfUnusedPoints", this->NumberOfUnusedPoints);
    pcs::AddFieldCount(fd, "NumberOfDuplicatePoints", duplicates);
    pcs::AddFieldCount(fd, "NumberOfSkippedPoints", skipped);
    pcs::AddFieldCount(fd, "NumberOfOutliers", outliers);
    pcs::AddFieldValue(fd, "MeanSpacing", this->MeanSpacing);
    pcs::AddFieldValue(fd, "MedianUniformity", r.MedianUniformity);
    pcs::AddFieldCount(fd, "CrossingTestUsed", r.Normals.empty() ? 0 : 1);
    pcs::AddFieldCount(fd, "NumberOfPoints", numberOfPoints);
    pcs::AddFieldValue(fd, "AverageUniformityInSSR",
      ssrUniformityCount > 0 ? ssrUniformity / ssrUniformityCount : NaN);
    pcs::AddFieldValue(fd, "SSRAreaPercent", totalArea > 0 ? 100.0 * ssrArea / totalArea : 0.0);
    pcs::AddFieldValue(fd, "SSRPointsPercent",
      r.N > 0 ? 100.0 * static_cast<double>(ssrPoints) / r.N : 0.0);
    vtkNew<vtkStringArray> stepsArray;
    stepsArray->SetName("StepsUsed");
    stepsArray->InsertNextValue(steps);
    fd->AddArray(stepsArray);
    pcs::AddFieldValue(fd, "Seconds", seconds);
    pcs::AddFieldValue(fd, "PointsPerSecond", seconds > 0 ? numberOfPoints / seconds : 0.0);
    this->UpdateProgress(1.0);
    return 1;
  };

  if (numberOfPoints == 0)
  {
    vtkWarningMacro("The input has no points: the output is empty.");
    return finish();
  }
  if (numberOfPoints > MaximumNumberOfPoints)
  {
    vtkErrorMacro("The input has " << numberOfPoints << " points; at most "
                                   << MaximumNumberOfPoints << " are supported.");
    return finish();
  }
  const std::string nanParameters =
    pcs::NaNParametersError({ { "OutlierFactor", this->OutlierFactor },
      { "AutomaticCorrectFraction", this->AutomaticCorrectFraction },
      { "UniformityAngle", this->UniformityAngle },
      { "MaximumNormalDeviation", this->MaximumNormalDeviation },
      { "BoundaryVectorRadius", this->BoundaryVectorRadius },
      { "StatusNeutralAngle", this->StatusNeutralAngle },
      { "MaximumBridgeLength", this->MaximumBridgeLength },
      { "MinimumBridgeSeparation", this->MinimumBridgeSeparation },
      { "MaximumHoleDiameter", this->MaximumHoleDiameter },
      { "AuxiliaryPointDistance", this->AuxiliaryPointDistance } });
  if (!nanParameters.empty())
  {
    vtkErrorMacro(<< nanParameters);
    return finish();
  }

  // Distinct finite points: non-finite ones are skipped, exact duplicates merged.
  std::vector<double> xyz;
  std::vector<int32_t> order;
  skipped = pcs::ReadFiniteCoordinates(input->GetPoints(), xyz, order);
  if (skipped > 0)
  {
    vtkWarningMacro("Skipped " << skipped << " point(s) with NaN or infinite coordinates.");
  }
  // Coordinates far from 1 (beyond 2^60 or below 2^-60 in magnitude) are scaled by a power of
  // two, which is exact and keeps every comparison: squared lengths, PCA covariances and the
  // single-precision edge lengths of step 1 then neither overflow nor underflow. Added points
  // and the reported spacing are scaled back.
  {
    r.CoordinateExponent = pcs::PredicateSafeExponent(xyz.data(), 3, order);
    if (r.CoordinateExponent != 0)
    {
      for (int32_t i : order)
      {
        for (int c = 0; c < 3; ++c)
        {
          xyz[3 * static_cast<size_t>(i) + c] =
            std::ldexp(xyz[3 * static_cast<size_t>(i) + c], r.CoordinateExponent);
        }
      }
    }
  }
  // Far outliers and piles of near-coincident points (pcs::FindPiles): read from the neighbour
  // table below when it holds enough neighbours per point (pcs::FlagOutliersAndPiles), else found
  // here by their own search.
  const bool outliersFromTable = this->NumberOfNeighbors >= pcs::OutlierNeighbors;
  std::vector<std::pair<int32_t, int32_t>> pileCopies;
  if (!outliersFromTable)
  {
    outliers = pcs::RemoveOutliersAndPiles(xyz.data(),
      order,
      this->OutlierFactor,
      pileCopies,
      [this](double) { return !this->GetAbortExecute(); });
  }
  // Exact duplicates: each copy is mapped to the copy of smallest id (order is ascending); so is
  // each point of a pile but its first (smallest id), and its exact copies.
  std::vector<std::pair<int32_t, int32_t>> merged;
  duplicates = pcs::MergeExactDuplicates(xyz.data(), 3, order, merged);
  duplicates += static_cast<vtkIdType>(pileCopies.size());
  std::vector<int32_t> representative(numberOfPoints, -1);
  for (const auto& copy : merged)
  {
    representative[copy.first] = copy.second;
  }
  for (const auto& copy : pileCopies)
  {
    representative[copy.first] = copy.second;
  }
  // Local ids in input order.
  localOf.assign(numberOfPoints, -1);
  for (int32_t id : order)
  {
    representative[id] = id;
    localOf[id] = static_cast<int32_t>(inputIds.size());
    inputIds.push_back(id);
  }
  r.N = static_cast<int32_t>(inputIds.size());
  r.X.resize(3 * static_cast<size_t>(r.N));
  for (int32_t i = 0; i < r.N; ++i)
  {
    std::copy_n(&xyz[3 * static_cast<size_t>(inputIds[i])], 3, &r.X[3 * static_cast<size_t>(i)]);
  }
  xyz.clear();
  xyz.shrink_to_fit();
  this->UpdateProgress(0.02);

  // Neighbours (the plain nearest-first table, which the outlier rule reads), spacing,
  // uniformity.
  // With the outlier rule on the table, the search may run twice: each gets its own range.
  const double searchedAgain = outliersFromTable ? 0.14 : 0.25;
  r.K = std::min<int>(this->NumberOfNeighbors, r.N - 1);
  if (r.N >= 3)
  {
    r.FindNeighbors(0.02, searchedAgain);
  }
  if (r.Aborted)
  {
    return finish();
  }
  std::vector<uint8_t> far;
  std::vector<std::pair<vtkIdType, vtkIdType>> tablePileCopies;
  if (outliersFromTable && r.N >= 3 &&
    (pcs::DropOutliersAndPilesByTable(
       r.X, inputIds, r.Neighbors, r.K, this->OutlierFactor, far, tablePileCopies) > 0 ||
      !tablePileCopies.empty()))
  {
    // The flagged points and their exact copies leave the cloud (Status 4, NumberOfOutliers: the
    // copies of an outlier are outliers, not duplicates), and so do the pile copies (the points
    // of a pile but its first, smallest id) and their exact copies (Status 4, duplicates of the
    // pile's first); the table is made again without them.
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      if (representative[i] >= 0 && far[localOf[representative[i]]])
      {
        ++outliers;
        duplicates -= representative[i] != i ? 1 : 0;
        representative[i] = -1;
      }
    }
    duplicates +=
      pcs::RepresentPilesByFirst(representative.data(), numberOfPoints, tablePileCopies);
    const int32_t kept = static_cast<int32_t>(inputIds.size());
    r.N = kept;
    localOf.assign(numberOfPoints, -1);
    for (int32_t i = 0; i < kept; ++i)
    {
      localOf[inputIds[i]] = i;
    }
    r.K = std::min<int>(this->NumberOfNeighbors, r.N - 1);
    if (r.N >= 3)
    {
      r.FindNeighbors(searchedAgain, 0.25);
    }
    if (r.Aborted)
    {
      return finish();
    }
  }
  if (outliers > 0)
  {
    vtkWarningMacro(
      "Excluded " << outliers << " far outlier(s) (OutlierFactor " << this->OutlierFactor
                  << "): point data Used = 0, Status 4, field data NumberOfOutliers.");
  }
  if (duplicates > 0)
  {
    vtkWarningMacro(<< pcs::DuplicatesWarning(
                      duplicates, "the copy of smallest id is meshed (Status 4 for the others)"));
  }
  if (r.N < 3)
  {
    vtkWarningMacro("Fewer than 3 distinct finite points (" << r.N << "): no surface can be made.");
    return finish();
  }
  r.ExtendNeighbors();
  r.ComputeUniformity();
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    if (representative[i] >= 0)
    {
      uniformity->SetValue(i, r.Uniformity[localOf[representative[i]]]);
    }
  }
  if (!(r.Spacing > 0))
  {
    vtkWarningMacro("The points have no measurable spacing: no surface can be made.");
    return finish();
  }

  // Steps 1 to 7.
  {
    std::vector<double> finite;
    finite.reserve(r.Uniformity.size());
    for (double m : r.Uniformity)
    {
      if (std::isfinite(m))
      {
        finite.push_back(m);
      }
    }
    if (!finite.empty())
    {
      std::nth_element(finite.begin(), finite.begin() + finite.size() / 2, finite.end());
      r.MedianUniformity = finite[finite.size() / 2];
    }
  }
  // Steps 1 and 2, with the crossing test when asked for, or in automatic mode when the paper's
  // test leaves too few points correct.
  for (int pass = 0; pass < 2; ++pass)
  {
    const bool crossing = this->CrossingTest == CROSSING_TEST_ON || pass == 1;
    if (crossing)
    {
      r.ComputeNormals(pass == 1);
    }
    if (!r.Progress(pass == 0 ? 0.3 : 0.5))
    {
      return finish();
    }
    r.Step1GreedyEdges(pass == 0 ? 0.3 : 0.5, pass == 0 ? 0.45 : 0.57);
    if (r.Aborted)
    {
      return finish();
    }
    r.Step2Umbrella(pass == 0 ? 0.45 : 0.57, pass == 0 ? 0.5 : 0.6);
    if (r.Aborted)
    {
      return finish();
    }
    const double correct = static_cast<double>(r.N - r.LostPoints) / r.N;
    if (this->CrossingTest != CROSSING_TEST_AUTOMATIC || crossing ||
      correct >= this->AutomaticCorrectFraction)
    {
      break;
    }
  }
  steps = "1";
  steps += ", 2";
  for (int32_t v = 0; v < r.N; ++v)
  {
    if (r.Status[v] == CORRECT || r.Status[v] == BOUNDARY)
    {
      ++ssrPoints;
      if (std::isfinite(r.Uniformity[v]))
      {
        ssrUniformity += r.Uniformity[v];
        ++ssrUniformityCount;
      }
    }
  }
  // Steps 3 to 8 on the regions of step 2, and on the same regions grown into the lost points of
  // the islands step 2 dissolved (GrowRegions): the grown ones are kept when the repaired mesh
  // uses more points without more boundary edges. And (issue 7) on the regions of step 2 whose
  // front is grown into all the lost points: its pieces taken where the growth replaced repairs.
  // Progress from `begin` to `end` (one call per result).
  auto repair = [](Reconstruction& x, double begin, double end)
  {
    auto at = [begin, end](double fraction) { return begin + fraction * (end - begin); };
    x.Step3Status();
    if (!x.Progress(at(0.05)))
    {
      return false;
    }
    x.Step4Bridges();
    if (!x.Progress(at(0.2)))
    {
      return false;
    }
    x.Step6FillHoles(at(0.2), at(0.97));
    if (x.Aborted)
    {
      return false;
    }
    x.InsertLostPoints(at(0.97), end);
    if (x.Aborted)
    {
      return false;
    }
    x.RemoveGrownFlaps();
    x.CloseSmallLoops();
    x.CapOpenEnds();
    x.RemoveSmallOpenGrownParts();
    // The lost points still free (and those of the pieces taken back) get one more pass of the
    // insertion, into the mesh as the small loops and the caps left it.
    x.InsertLostPoints(end, end);
    x.Step7Swaps();
    return true;
  };
  // Step 1's triangles are read by steps 1 and 2 only: freed before the grown copy is made.
  std::vector<int32_t>().swap(r.Step1Triangles);
  // A copy of the regions of step 2 grown into the lost points (null when nothing was grown).
  auto grow = [&r](bool expandFront, double begin, double end)
  {
    std::unique_ptr<Reconstruction> copy(new Reconstruction(r));
    copy->GrowRegions(begin, end, expandFront);
    if (copy->Grown == 0 && !copy->Aborted)
    {
      copy.reset();
    }
    return copy;
  };
  std::unique_ptr<Reconstruction> grown, expanded;
  if (this->GrowRegions && !r.Dissolved.empty())
  {
    grown = grow(false, 0.6, 0.62);
  }
  if (this->GrowRegions && r.LostPoints > 0 && !(grown && grown->Aborted))
  {
    expanded = grow(true, 0.62, 0.63);
  }
  if ((grown && grown->Aborted) || (expanded && expanded->Aborted))
  {
    return finish();
  }
  const double repairedGrown = grown || expanded ? 0.75 : 0.98;
  if (!repair(r, 0.63, repairedGrown))
  {
    return finish();
  }
  if (grown)
  {
    if (!repair(*grown, repairedGrown, 0.86))
    {
      return finish();
    }
    auto unused = [](const Reconstruction& x)
    {
      vtkIdType count = 0;
      for (int32_t v = 0; v < x.N; ++v)
      {
        count += x.Mesh.IsFree(v) ? 1 : 0;
      }
      return count;
    };
    const bool grownWhole =
      grown->Mesh.GetNumberOfBoundaryHalfEdges() <= r.Mesh.GetNumberOfBoundaryHalfEdges() &&
      unused(*grown) < unused(r);
    // Otherwise piece by piece: the grown result's pieces that use more points without more
    // boundary edges (and add no component or handle). The reverse, pieces of the result of step 2
    // into a grown one kept whole, gave fills across the camel's tail: not done.
    if (grownWhole)
    {
      // The locator's points wrap r.X: r keeps that buffer (the copy holds the same values).
      grown->X.swap(r.X);
      r = std::move(*grown);
    }
    else
    {
      r.PiecesExchanged = r.TakeBetterPieces(*grown, false, true);
    }
    grown.reset();
  }
  if (expanded)
  {
    if (!repair(*expanded, 0.86, 0.98))
    {
      return finish();
    }
    // The pieces are exchanged without a topology check each (it reads the whole mesh: once per
    // piece tripled the filter's time on the noisy bunny); when the mesh's components or sum of
    // genera changed, all are put back.
    int64_t components, handles;
    r.Topology(components, handles);
    const pcs::SurfaceMesh mesh = r.Mesh;
    const std::vector<uint8_t> stage = r.Stage, status = r.Status;
    const std::vector<char> inserted = r.InsertedPoints;
    const vtkIdType insertedCount = r.Inserted;
    vtkIdType exchanged = r.TakeBetterPieces(*expanded, true, false);
    if (exchanged > 0)
    {
      int64_t componentsAfter, handlesAfter;
      r.Topology(componentsAfter, handlesAfter);
      if (componentsAfter != components || handlesAfter != handles)
      {
        r.Mesh = mesh;
        r.Stage = stage;
        r.Status = status;
        r.InsertedPoints = inserted;
        r.Inserted = insertedCount;
        exchanged = 0;
      }
    }
    r.PiecesExchanged += exchanged;
    expanded.reset();
  }
  r.SwapObtuseEdges();
  if (r.Bridges > 0)
  {
    steps += ", 3, 4";
  }
  if (r.Chords > 0)
  {
    steps += ", 5";
  }
  if (r.HolesFilled > 0)
  {
    steps += ", 6";
  }
  if (r.Bridges + r.Chords + r.ObtuseSwaps > 0)
  {
    steps += ", 7";
  }
  if (r.Inserted > 0)
  {
    steps += ", 8";
  }
  r.OrientOutwards();

  // Output triangles (local ids) and stages; then the hole fills refined and faired.
  const int64_t ids = r.Mesh.GetNumberOfTriangleIds();
  r.Stage.resize(static_cast<size_t>(ids), 6);
  std::vector<uint8_t> stages;
  for (int64_t t = 0; t < ids; ++t)
  {
    if (!r.Mesh.IsTriangleRemoved(t))
    {
      const int32_t* tri = r.Mesh.GetTriangle(t);
      connectivity.insert(connectivity.end(), tri, tri + 3);
      stages.push_back(r.Stage[t]);
    }
  }
  std::vector<double> added;
  if (this->FillHoles && this->FairHoleFills)
  {
    r.RefineAndFairFills(connectivity, stages, added, 0.98, 1.0);
    if (r.Aborted)
    {
      connectivity.clear();
      return finish();
    }
    r.Added = static_cast<vtkIdType>(added.size() / 3);
    if (r.Added > 0)
    {
      steps += ", 9";
    }
  }
  if (r.Added > 0)
  {
    // The new points after the input points, with the point data of the nearest input point.
    // The input points pass unchanged: DeepCopy converts them to the new array's type (float by
    // default), so it is the input's when floating point, double otherwise (integer points; the
    // new points are not on the integer grid).
    vtkNew<vtkPoints> outPoints;
    const int inputType = input->GetPoints()->GetDataType();
    outPoints->SetDataType(inputType == VTK_FLOAT ? VTK_FLOAT : VTK_DOUBLE);
    outPoints->DeepCopy(input->GetPoints());
    vtkPointData* inPD = input->GetPointData();
    vtkPointData* outPD = output->GetPointData();
    outPD->Initialize();
    outPD->CopyAllocate(inPD, numberOfPoints + r.Added);
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      outPD->CopyData(inPD, i, i);
    }
    for (vtkIdType k = 0; k < r.Added; ++k)
    {
      const double* x = &added[3 * k];
      const vtkIdType id = outPoints->InsertNextPoint(std::ldexp(x[0], -r.CoordinateExponent),
        std::ldexp(x[1], -r.CoordinateExponent), std::ldexp(x[2], -r.CoordinateExponent));
      const vtkIdType nearest = r.Locator->FindClosestPoint(x);
      if (nearest >= 0)
      {
        outPD->CopyData(inPD, inputIds[nearest], id);
      }
      used->InsertNextValue(1);
      status->InsertNextValue(ADDED_BY_HOLE_FILLING);
      uniformity->InsertNextValue(NaN);
    }
    output->SetPoints(outPoints);
  }
  auto point = [&](
                 int32_t v) { return v < r.N ? r.P(v) : &added[3 * static_cast<size_t>(v - r.N)]; };
  auto outputId = [&](int32_t v) {
    return v < r.N ? inputIds[v] : numberOfPoints + static_cast<vtkIdType>(v - r.N);
  };
  vtkNew<vtkIdTypeArray> cellIds;
  vtkNew<vtkIdTypeArray> offsets;
  cellIds->SetNumberOfValues(static_cast<vtkIdType>(connectivity.size()));
  offsets->SetNumberOfValues(static_cast<vtkIdType>(stages.size()) + 1);
  offsets->SetValue(0, 0);
  stage->SetNumberOfValues(static_cast<vtkIdType>(stages.size()));
  for (size_t t = 0; t < stages.size(); ++t)
  {
    const int32_t* tri = &connectivity[3 * t];
    for (int j = 0; j < 3; ++j)
    {
      cellIds->SetValue(static_cast<vtkIdType>(3 * t + j), outputId(tri[j]));
      if (tri[j] < r.N)
      {
        used->SetValue(inputIds[tri[j]], 1);
      }
    }
    offsets->SetValue(static_cast<vtkIdType>(t) + 1, static_cast<vtkIdType>(3 * t + 3));
    stage->SetValue(static_cast<vtkIdType>(t), stages[t]);
    double u[3], v[3], n[3];
    vtkMath::Subtract(point(tri[1]), point(tri[0]), u);
    vtkMath::Subtract(point(tri[2]), point(tri[0]), v);
    vtkMath::Cross(u, v, n);
    const double area = 0.5 * vtkMath::Norm(n);
    totalArea += area;
    ssrArea += stages[t] == 1 ? area : 0.0;
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, cellIds);
  output->SetPolys(polys);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    if (representative[i] == i)
    {
      status->SetValue(i, r.Status[localOf[i]]);
    }
  }
  // Lost points left unused (Status 2): without a warning a cloud the filter cannot read (scan
  // lines 12 times denser along than across: every point's K neighbours on its own line) gave
  // 2 triangles for 20,000 points silently.
  vtkIdType lostUnused = 0;
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    lostUnused += status->GetValue(i) == LOST && !used->GetValue(i) ? 1 : 0;
  }
  if (lostUnused > 0 && !connectivity.empty())
  {
    vtkWarningMacro(<< lostUnused << " of " << numberOfPoints
                    << " point(s) are not used by any triangle (Status 2, point data Used = 0).");
  }
  if (connectivity.empty())
  {
    vtkWarningMacro("No triangle could be made from the " << r.N
                                                          << " distinct points (collinear or too "
                                                             "sparse points?).");
  }
  return finish();
}

//------------------------------------------------------------------------------------------------
void vtkGreedySurfaceTriangulation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfNeighbors: " << this->NumberOfNeighbors << "\n";
  os << indent << "OutlierFactor: " << this->OutlierFactor << "\n";
  os << indent << "CrossingTest: " << this->CrossingTest << "\n";
  os << indent << "AutomaticCorrectFraction: " << this->AutomaticCorrectFraction << "\n";
  os << indent << "UniformityNeighbors: " << this->UniformityNeighbors << "\n";
  os << indent << "UniformityAngle: " << this->UniformityAngle << "\n";
  os << indent << "MaximumNormalDeviation: " << this->MaximumNormalDeviation << "\n";
  os << indent << "MinimumIslandTriangles: " << this->MinimumIslandTriangles << "\n";
  os << indent << "BoundaryVectorRadius: " << this->BoundaryVectorRadius << "\n";
  os << indent << "StatusNeutralAngle: " << this->StatusNeutralAngle << "\n";
  os << indent << "BridgeIslands: " << this->BridgeIslands << "\n";
  os << indent << "MaximumBridgeLength: " << this->MaximumBridgeLength << "\n";
  os << indent << "MinimumBridgeSeparation: " << this->MinimumBridgeSeparation << "\n";
  os << indent << "FillHoles: " << this->FillHoles << "\n";
  os << indent << "MaximumHoleDiameter: " << this->MaximumHoleDiameter << "\n";
  os << indent << "AuxiliaryPointDistance: " << this->AuxiliaryPointDistance << "\n";
  os << indent << "MaximumHolePoints: " << this->MaximumHolePoints << "\n";
  os << indent << "SwapBridgeEdges: " << this->SwapBridgeEdges << "\n";
  os << indent << "InsertLostPoints: " << this->InsertLostPoints << "\n";
  os << indent << "GrowRegions: " << this->GrowRegions << "\n";
  os << indent << "FairHoleFills: " << this->FairHoleFills << "\n";
  os << indent << "CapOpenEnds: " << this->CapOpenEnds << "\n";
  os << indent << "NumberOfTriangles: " << this->NumberOfTriangles << "\n";
  os << indent << "NumberOfLostPoints: " << this->NumberOfLostPoints << "\n";
  os << indent << "NumberOfIslands: " << this->NumberOfIslands << "\n";
  os << indent << "NumberOfBridges: " << this->NumberOfBridges << "\n";
  os << indent << "NumberOfHolesFilled: " << this->NumberOfHolesFilled << "\n";
  os << indent << "NumberOfUnusedPoints: " << this->NumberOfUnusedPoints << "\n";
  os << indent << "MeanSpacing: " << this->MeanSpacing << "\n";
}
