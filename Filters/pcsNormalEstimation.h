// Point normals estimated from a cloud: least-squares planes of nearest-neighbour
// neighbourhoods, optionally oriented consistently (private helper of the surface filters, not
// wrapped).
#ifndef pcsNormalEstimation_h
#define pcsNormalEstimation_h

#include <cstdint>
#include <functional>
#include <vector>

namespace pcs
{
class PointBins;
/// Eigenvalues (decreasing, in `values`) of the symmetric 3x3 matrix `a` and the unit
/// eigenvector of the smallest (`vector`). Closed form: the eigenvalues from the characteristic
/// cubic (trigonometric solution, on the matrix scaled to entries of at most 1), the eigenvector
/// the largest cross product of two rows of a - l I. Where that is not well defined (the two
/// smallest eigenvalues equal to about 1e-6 of the scale, or a multiple of the identity) it
/// falls back to vtkMath::Jacobi. Several times cheaper than Jacobi's iterations.
void SmallestEigenvector(const double a[3][3], double values[3], double vector[3]);

/// SmallestEigenvector's solver for the unit eigenvector of the largest eigenvalue (`values` as
/// there), the sign as vtkMath::Jacobi's (at least two non-negative components). Well defined
/// where the largest eigenvalue is well separated from the others (the principal direction of
/// points spread along a curve); falls back to vtkMath::Jacobi where the cross products vanish.
void LargestEigenvector(const double a[3][3], double values[3], double vector[3]);

/// Covariance of the offsets q - p from the point `p` to its neighbours `row` (`count` ids into
/// `xyz`, packed x, y, z; -1 for none; an offset with a non-finite coordinate is skipped), with
/// p itself as one more offset 0 when `withPoint` is true: C = S2 / s0 - m m^T with m = S1 / s0,
/// S1 and S2 the sums of the offsets and of their products, summed in one pass. Returns s0, the
/// number of offsets used (C is left unset when it is 0). `mean`, when given, receives m (the
/// offset from p to the centroid; left unset when s0 is 0).
double OffsetCovariance(const double* xyz, const double* p, const int32_t* row, int count,
  bool withPoint, double covariance[3][3], double mean[3] = nullptr);

/// The upper median of `values` (the element of rank size / 2), 0 when empty.
double Median(std::vector<double> values);

/// Height noise at the point `p` with unit normal `normal`: the root mean square residual of the
/// least-squares quadric height field h(u, v) = a + b u + c v + d u^2 + e u v + f v^2 over the
/// tangent frame of the normal, fitted to p and those of its neighbours `row` (`count` ids into
/// `xyz`, -1 for none) whose unit normal (in `normals`) has a dot product of at least
/// `minimumNormalDot` with `normal` (the same smooth sheet: not the other side of a crease or of a
/// thin part; every neighbour when `normals` is null), with m - 6 degrees of freedom for m points
/// (an unbiased variance for Gaussian height noise). A smooth surface is a quadric up to
/// third-order terms, so its curvature does not count as noise (a plane fit's residual would).
/// Returns -1 when fewer than 7 points are usable or the fit is singular (the neighbours near a
/// conic in the tangent plane).
double QuadricHeightNoise(const double* xyz,
  const double* normals,
  const double* p,
  const double* normal,
  const int32_t* row,
  int count,
  double minimumNormalDot);

/// Sampling noise of a cloud, measured on its nearest-neighbour table (SamplingNoise below).
struct SamplingNoiseMeasure
{
  double Level = 0.0;   ///< median height noise over median local spacing
  double Share = 0.0;   ///< median height noise over median plane residual
  int64_t Measured = 0; ///< points with a quadric fit (at least 7 distinct points, not singular)
  bool Noisy = false;   ///< Level > NoisyLevel and Share > NoisyShare
};

/// The neighbours of a point whose plane and quadric SamplingNoise fits (the point and its 9
/// nearest: vtkCDTAdvancingFront's default NormalSampleSize, the noise band's neighbourhood).
constexpr int NoiseNeighbors = 9;
/// The neighbours of a point whose plane the surface filters project it onto (the point and its
/// 19 nearest, vtkLocalOptimumGrowth's default table; see ProjectOntoLocalPlanes).
constexpr int ProjectionNeighbors = 19;
/// At most this many neighbours make a plane of SamplingNoise or ProjectOntoLocalPlanes.
constexpr int MaximumPlaneNeighbors = 64;

/// The values of the filters' LocalPlaneProjection.
enum LocalPlaneProjectionMode
{
  ProjectionOff = 0,
  ProjectionOn = 1,
  ProjectionAutomatic = 2
};

/// The thresholds of SamplingNoise (see there).
constexpr double NoisyLevel = 0.05;
constexpr double NoisyShare = 1.0;
/// About this many points are measured by the filters (SamplingNoise's stride).
constexpr int32_t SamplingNoiseSamples = 25000;

/// Whether the `n` points of `xyz` are a noisy sample, from the first min(`k`, `planeOthers`)
/// columns of each row of `neighbors` (n * `k` ids, nearest first, -1 for none): at each point the
/// plane of the point and those neighbours (centroid and smallest covariance eigenvector), the root
/// mean square distance of the points to it (the plane residual, curvature and noise), the height
/// noise of QuadricHeightNoise over that plane (noise only: a smooth surface is a quadric up to
/// third-order terms) and the local spacing (the mean distance to those neighbours). The cloud is
/// noisy when the median height noise is more than NoisyLevel (1/20) of the median local spacing
/// and more than NoisyShare (1.0) times the median plane residual: the residual is noise, not
/// curvature (Gaussian noise alone gives 1.1-1.2: the plane's residual has 3 degrees of freedom
/// fitted away, the quadric's 6 accounted for; curvature only adds to the plane's). Measured
/// (Benchmarks/results/local_optimum.md, "Denoising"): noisy spheres and tori with sigma from 0.1
/// to 0.3 sqrt(area / N), level 0.078-0.21 and share 1.11-1.17; of the 92 CGAL mesh vertex sets
/// (meshes/*.off of 50 to 200,000 points) and 11 clean random, Fibonacci and grid samples, those
/// with a level above 1/20 share at most 0.97 (femur; b9_mesh 0.95, mpi 0.90, bones 0.85, all
/// others below 0.75), and those sharing more than 1 (flat patches with a little noise, a gear)
/// have levels below 0.005. Every point when `stride` is 1, else every `stride`-th (the filters
/// call it through MeasureSamplingNoise: a sample of 500 points first, then about 25,000 points
/// when needed). With `normals` (3 n, unit, consistently oriented) only the neighbours whose normal
/// has a dot product of at least `minimumNormalDot` with the point's are fitted (the same side: two
/// grids 0.3 spacings apart with opposite normals, a thin plate, are not noise). Threads:
/// vtkSMPTools.
SamplingNoiseMeasure SamplingNoise(const double* xyz, int32_t n,
  const std::vector<int32_t>& neighbors, int k, int planeOthers, int stride = 1,
  const double* normals = nullptr, double minimumNormalDot = 0.0);

/// The points MeasureSamplingNoise measures first.
constexpr int32_t SamplingNoisePilotSamples = 500;
/// MeasureSamplingNoise settles a cloud as not noisy on its first sample when its level or its
/// share is below the threshold divided by this margin.
constexpr double SamplingNoisePilotMargin = 1.25;

/// SamplingNoise as the filters decide LocalPlaneProjection's automatic mode, in two stages.
/// Clouds of more than 2 SamplingNoisePilotSamples points are first measured on
/// SamplingNoisePilotSamples points drawn by a fixed pseudo-random generator (the same for every
/// run; not a stride, which can fall in step with the rows of a regular sampling); when their
/// level is under NoisyLevel / SamplingNoisePilotMargin or their share under
/// NoisyShare / SamplingNoisePilotMargin the cloud is not noisy and that measure is returned.
/// Otherwise (and for smaller clouds) the measure of SamplingNoise with the stride
/// max(1, n / SamplingNoiseSamples). The median of 500 values is within a few percent of the
/// cloud's (measured on the CGAL vertex sets and noisy spheres: Benchmarks/results/cdt.md, "The
/// noise test on a sample"), far inside the margin, and the clean clouds are settled at a
/// fiftieth of the cost on 25,000 points (the noisy ones are projected, which costs more).
/// Same arguments as SamplingNoise.
SamplingNoiseMeasure MeasureSamplingNoise(const double* xyz, int32_t n,
  const std::vector<int32_t>& neighbors, int k, int planeOthers, const double* normals = nullptr,
  double minimumNormalDot = 0.0);

/// Denoised copy of the `n` points of `xyz` (packed x, y, z) for the geometric decisions of the
/// surface filters (vtkLocalOptimumGrowth, vtkCDTAdvancingFront; vtkGreedySurfaceTriangulation
/// and vtkPerimeterPeelSurface could use it the same way): each point projected onto the
/// least-squares plane of itself and its first min(`k`, `planeOthers`) neighbours in
/// `neighbors` (n * `k` ids, nearest first, -1 for none): the plane through their centroid
/// normal to the smallest eigenvector of their covariance (Hoppe et al.'s tangent plane; one
/// plane per point, not iterated). A point whose neighbourhood has no plane (fewer than 3 points,
/// or all on a line: the two smallest eigenvalues 0) keeps its coordinates, and so do two
/// distinct points whose projections coincide exactly (copies of one position may share one).
/// Measured with 20 points on random unit-sphere samples of 20,000 (spacing h = sqrt(4 pi / N),
/// Python model of this routine): Gaussian noise of rms 0.30 h and 0.10 h falls to 0.084 h and
/// 0.044 h; the plane through the centroid lies inside the curved surface, so the points move
/// inwards by 0.036 h on average (0.016 h with 10 points). `projected` gets 3 n values.
/// With `normals` (3 n, unit, consistently oriented) only the neighbours whose normal has a dot
/// product of at least `minimumNormalDot` with the point's make its plane (the same sheet: the
/// two sides of a plate thinner than the neighbourhood stay apart), as in SamplingNoise.
/// Threads: vtkSMPTools; the result does not depend on their number.
void ProjectOntoLocalPlanes(const double* xyz, int32_t n, const std::vector<int32_t>& neighbors,
  int k, int planeOthers, std::vector<double>& projected, const double* normals = nullptr,
  double minimumNormalDot = 0.0);

/// Unoriented unit normal of each of the `n` points of `xyz` (packed x, y, z): the eigenvector
/// of the smallest eigenvalue of the covariance of its neighbourhood, the point and its `k`
/// nearest points (`neighbors`, n * k ids as made by FindNearestNeighbors, -1 for none): Hoppe
/// et al.'s tangent plane ("Surface reconstruction from unorganized points", 1992, section 3.2),
/// as vtkPCANormalEstimation with k + 1 as its sample size. The covariance is summed in one pass
/// over the offsets from the point. `normals` gets 3 n values (sign arbitrary); `variation`
/// gets the surface variation of each neighbourhood, 3 l0 / (l0 + l1 + l2) with l0 the smallest
/// eigenvalue: 0 on a plane, 1 for an isotropic neighbourhood or a lone point (a normal without
/// meaning). Threads: vtkSMPTools; the result does not depend on their number.
void EstimatePlaneNormals(const double* xyz,
  int32_t n,
  const std::vector<int32_t>& neighbors,
  int k,
  std::vector<double>& normals,
  std::vector<double>& variation);

/// Consistent orientation of the unit normals `normals` (each kept or flipped): Hoppe et al.'s
/// propagation along a minimum spanning tree of the symmetric graph joining each point to its `k`
/// nearest points (`neighbors`), the most certain edges first (Kruskal's algorithm on the edges
/// radix-sorted by cost, then the tree walked from its smallest id; the tree and the orientation
/// are those of Prim's propagation). Two points p, q with
/// normals n, m agree by the sign of (R n) . m, R the reflection through the plane bisecting p q
/// (the normal carried along a circle through both; cf. Koenig and Gumhold, "Consistent
/// propagation of normal orientations in point clouds", 2009): n . m with the chord in the
/// tangent plane, -n . m across a part thinner than a neighbourhood. An edge costs
/// 1 - |(R n) . m| plus the surface variations (`variation`, from EstimatePlaneNormals) of its end
/// points, so the propagation goes around the points whose plane is uncertain. Each connected
/// part of the graph is then turned outwards by a vote of its extreme points along +-x, +-y, +-z
/// (at the extreme point along d the outward normal of a closed surface is d): flipped when the
/// sum of n . d is negative. `progress` (optional) receives the fraction of points oriented
/// every 65,536 points; returning false stops (the function then returns false, the normals
/// partly oriented).
bool OrientNormals(const double* xyz,
  int32_t n,
  const std::vector<int32_t>& neighbors,
  int k,
  const std::vector<double>& variation,
  std::vector<double>& normals,
  const std::function<bool(double)>& progress = nullptr);

/// The whole estimation for the `n` points of `xyz` (`bins` filed from exactly these points, in
/// this order): the table of the `sampleSize` - 1 nearest other points of each point
/// (FindNearestNeighbors; the neighbourhood is the `sampleSize` nearest points including the
/// point, as vtkPCANormalEstimation's SampleSize), the planes (EstimatePlaneNormals) and, with
/// `orient`, their orientation (OrientNormals). Outputs: `normals` (3 n, unit), `variation`
/// (n), `neighbors` (the table, n * `k` ids, kept for the caller's other uses) and `k` (the
/// number of neighbours per point, min(sampleSize, n) - 1; 0 until the table is complete).
/// `progress` (optional) receives the fraction done (the search is the first 80 %); returning
/// false stops the estimation and the function returns false (outputs incomplete).
///
/// With `stretch` (optional), scan-line sampling is handled before the planes: the table is
/// extended by AddOffLineNeighbors (pcsNearestNeighbors.h; `scanLineShare` its minimumShare,
/// `scanLineRadiusFactor` its radiusFactor), whose stretch vectors `stretch` receives (3 n
/// values). On lines 6 or more times denser along
/// than across, the nearest points of a point lie on its own line and their plane, any plane
/// through the line, is not the surface's; with the points of the lines beside it, it is.
///
/// With `rowLinearity` > 0, the planes (not the table, nor the orientation graph) are then
/// fitted to a copy of the table in which the points whose max(2, k / 2) nearest spread along one
/// curve get the off-line neighbours of AddOffLineNeighbors (`rowLinearity` its linearity,
/// `rowRadiusFactor` its radiusFactor, `rowShare` its minimumShare): the rows of dense points with
/// sparse gaps of irregular samplings (decimated meshes keep dense rows along details), which the
/// scan-line rule leaves alone when they are short or bend too much for its linearity. A row
/// that bends with the surface (a ring around a body or a leg) lies in a plane through the
/// surface normal, so the plane of its points alone can be off by up to 90 degrees.
///
/// `bins`: PointBins::Build on the same `xyz` and `n`, with or without coordinates (the off-line
/// passes file them when they need them); one grid for the search, both off-line passes and the
/// caller's own radius queries. With `neighborsGiven`, `neighbors` already holds that table
/// (FindNearestNeighbors on the same bins, points and min(sampleSize, n) - 1 neighbours, e.g.
/// searched by the caller for its outlier rule) and the search is skipped; a table of another
/// size is searched again.
bool EstimateNormals(PointBins& bins,
  const double* xyz,
  int32_t n,
  int sampleSize,
  bool orient,
  std::vector<double>& normals,
  std::vector<double>& variation,
  std::vector<int32_t>& neighbors,
  int& k,
  const std::function<bool(double)>& progress = nullptr,
  std::vector<double>* stretch = nullptr,
  double scanLineShare = 0.5,
  double scanLineRadiusFactor = 4.0,
  double rowLinearity = 0.0,
  double rowRadiusFactor = 2.0,
  double rowShare = 0.5,
  bool neighborsGiven = false);
}

#endif
