// K nearest neighbours of every point of a cloud through vtkStaticPointLocator (private helper of
// the surface filters, not wrapped).
#ifndef pcsNearestNeighbors_h
#define pcsNearestNeighbors_h

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

class vtkStaticPointLocator;

namespace pcs
{
/// The points of a cloud filed into the bucket grid of a vtkStaticPointLocator (its divisions
/// and bounds) in flat arrays: the ids of each bucket contiguous, in id order, with their
/// coordinates copied in the same order, so that a radius query reads memory in order and makes
/// no virtual call per point (FindPointsWithinRadius' per-point GetPoint and per-call
/// BuildLocator check). Bucket b = i + j nx + k nx ny, the locator's numbering. The points are
/// sorted into the buckets by a counting sort on BucketIndex, the locator's index formula clamped
/// to the grid; it is monotone, so the buckets that the box of a ball overlaps (BucketRange, a
/// hair wider against rounding) hold every point within its radius, whichever bucket the locator
/// itself files a point on a bucket boundary under: the answers are those of
/// FindPointsWithinRadius (as a set). Memory: one int32 per bucket, one int32 and three doubles
/// per point. Queries are thread safe.
class PointBins
{
public:
  /// Files the `n` points of `xyz` (packed x, y, z; the points `locator` was built on, in this
  /// order) into the locator's grid (as many buckets over BulkBounds' box instead when a few
  /// points lie far from the rest). Without `withCoordinates` only the ids are filed (GetXYZ()
  /// is then empty and ForEachPointWithinRadius may not be called).
  void Build(vtkStaticPointLocator* locator,
    const double* xyz,
    int32_t n,
    bool withCoordinates = true);

  /// The same on the grid of `divisions` buckets over the box `bounds` (xmin, xmax, ymin, ...),
  /// no locator needed: e.g. SurfaceSampleDivisions' grid, the bins SetSurfaceSampleDivisions
  /// gives a locator, when no locator is to be built.
  void Build(const double bounds[6],
    const int divisions[3],
    const double* xyz,
    int32_t n,
    bool withCoordinates = true);

  /// Files the coordinates too (the same `xyz` as Build; GetXYZ() is then in slot order) when
  /// Build was called without them; nothing when they are filed already.
  void FileCoordinates(const double* xyz);

  /// The index along axis c of coordinate v, clamped to [0, divisions - 1] (NaN: 0).
  int BucketIndex(double v, int c) const
  {
    const double f = (v - this->Origin[c]) * this->Inverse[c];
    return !(f > 0.0) ? 0
                      : (f >= this->Divisions[c] ? this->Divisions[c] - 1 : static_cast<int>(f));
  }

  /// The buckets along each axis that the box x -/+ r (a hair wider) overlaps: low to high.
  void BucketRange(const double* x, double r, int low[3], int high[3]) const
  {
    const double margin = r * (1.0 + 1e-9) + 1e-300;
    for (int c = 0; c < 3; ++c)
    {
      low[c] = this->BucketIndex(x[c] - margin, c);
      high[c] = this->BucketIndex(x[c] + margin, c);
    }
  }

  /// The position of coordinate v along axis c in bucket units (BucketIndex before the clamp).
  double BucketCoordinate(double v, int c) const
  {
    return (v - this->Origin[c]) * this->Inverse[c];
  }
  /// The width of the buckets along axis c (0 on an axis of one bucket over a flat box).
  double GetBucketWidth(int c) const
  {
    return this->Inverse[c] > 0.0 ? 1.0 / this->Inverse[c] : 0.0;
  }

  int64_t GetNumberOfBuckets() const { return static_cast<int64_t>(this->Offsets.size()) - 1; }
  const int* GetDivisions() const { return this->Divisions; }
  /// Bucket b holds the slots [GetOffsets()[b], GetOffsets()[b + 1]) of GetIds() and GetXYZ().
  const int32_t* GetOffsets() const { return this->Offsets.data(); }
  const int32_t* GetIds() const { return this->Ids.data(); }
  const double* GetXYZ() const { return this->XYZ.data(); }

  /// Calls visit(id, d2) for each point within `radius` of x, in bucket order, with d2 its
  /// squared distance to x (|p - x|^2 summed over x, y, z), until visit returns false. Returns
  /// false when visit stopped the walk.
  template<typename Visit>
  bool ForEachPointWithinRadius(double radius, const double* x, Visit&& visit) const
  {
    const double r2 = radius * radius;
    return this->ForEachBucketRow(radius,
      x,
      [&](int32_t begin, int32_t end)
      {
        for (int32_t m = begin; m < end; ++m)
        {
          const double d2 = this->Distance2To(m, x);
          if (d2 <= r2 && !visit(this->Ids[m], d2))
          {
            return false;
          }
        }
        return true;
      });
  }

  /// The points of ForEachPointWithinRadius (the same order, the same d2) gathered into `found`,
  /// a buffer that only grows: the first count entries, count returned. Each point of the
  /// buckets walked is written before the test on its distance decides whether the next one
  /// overwrites it: no branch on that test, which half of the points pass and fail at random.
  size_t GatherWithinRadius(double radius,
    const double* x,
    std::vector<std::pair<int32_t, double>>& found) const
  {
    size_t count = 0;
    this->GatherWithinRadius(radius,
      x,
      found,
      std::numeric_limits<size_t>::max(),
      [&count](size_t gathered)
      {
        count = gathered;
        return true;
      });
    return count;
  }

  /// The same in pieces: take(count) is called with the points gathered since its last call in
  /// found[0, count) as soon as `piece` of them are gathered (within a bucket too), and once at
  /// the end (count may be 0), until take returns false (the walk then stops and false is
  /// returned). For a caller that may stop early, so that a dense cluster is not walked whole.
  /// piece must be at least 1 (with 0, take(0) would be called for every point that fails).
  template<typename Take>
  bool GatherWithinRadius(double radius,
    const double* x,
    std::vector<std::pair<int32_t, double>>& found,
    size_t piece,
    Take&& take) const
  {
    const double r2 = radius * radius;
    size_t count = 0;
    const bool walked = this->ForEachBucketRow(radius,
      x,
      [&](int32_t begin, int32_t end)
      {
        if (found.size() < count + static_cast<size_t>(end - begin))
        {
          found.resize(2 * (count + static_cast<size_t>(end - begin)));
        }
        for (int32_t m = begin; m < end; ++m)
        {
          const double d2 = this->Distance2To(m, x);
          found[count] = { this->Ids[m], d2 };
          count += d2 <= r2 ? 1 : 0;
          if (count == piece) // (rarely true: a well predicted branch)
          {
            count = 0;
            if (!take(piece))
            {
              return false;
            }
          }
        }
        return true;
      });
    return walked && take(count);
  }

private:
  // Calls row(begin, end) with the slots [begin, end) of each row of buckets (fixed y and z) that
  // the box of the ball (x, radius) overlaps, in bucket order, until row returns false.
  template<typename Row>
  bool ForEachBucketRow(double radius, const double* x, Row&& row) const
  {
    if (this->Offsets.size() < 2)
    {
      return true;
    }
    int low[3], high[3];
    this->BucketRange(x, radius, low, high);
    const int64_t nx = this->Divisions[0];
    const int64_t nxy = nx * this->Divisions[1];
    for (int k = low[2]; k <= high[2]; ++k)
    {
      for (int j = low[1]; j <= high[1]; ++j)
      {
        const int64_t first = j * nx + k * nxy;
        if (!row(this->Offsets[first + low[0]], this->Offsets[first + high[0] + 1]))
        {
          return false;
        }
      }
    }
    return true;
  }

  // The squared distance from x to the point of slot m.
  double Distance2To(int32_t m, const double* x) const
  {
    const double* p = &this->XYZ[3 * static_cast<size_t>(m)];
    const double d[3] = { p[0] - x[0], p[1] - x[1], p[2] - x[2] };
    return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  }

  void Fill(const double* xyz, int32_t n, bool withCoordinates);

  int Divisions[3] = { 1, 1, 1 };
  double Origin[3] = { 0, 0, 0 };
  double Inverse[3] = { 0, 0, 0 };
  std::vector<int32_t> Offsets;
  std::vector<int32_t> Ids;
  std::vector<double> XYZ;
};

/// For each of the `n` points of `xyz` (packed x, y, z; `locator` built on exactly these points,
/// in this order), its `k` nearest other points, nearest first, ties broken by the smaller id:
/// `neighbors` gets n * k ids (-1 where a point has fewer than k others). Exact duplicates of a
/// point are neighbours like any other point; the copies at one position are one candidate of
/// the bucket walk, of which at most k ids are taken, so a pile of d copies costs O(k) per query
/// instead of O(d) (10^6 copies of one point: O(n k) in all).
///
/// The search uses radius queries on the locator's buckets, several times faster than
/// FindClosestNPoints for surface samples: each query starts from a radius a little beyond the
/// previous point's k-th neighbour (the first from the mean nearest-neighbour distance of a
/// sample) and grows until the ball holds k other points. The points are filed once into the
/// locator's bucket grid (its divisions and bounds) by a counting sort, and the buckets a ball
/// overlaps are walked directly on `xyz` (row by row of buckets, each over the x range of the
/// ball's section there), as FindPointsWithinRadius does but without its per-point virtual
/// GetPoint and per-call BuildLocator checks (2.2x fewer instructions on a 2 x 10^4-point
/// sphere). The coordinates are copied once in bucket order, the queries run in
/// that order (neighbouring queries one after the other), and only the candidates inside the
/// ball are kept for the partial sort. The result does not depend on those radii, on the query
/// order, nor on the number of threads (vtkSMPTools, in blocks). `progress` (optional) receives
/// the fraction done between blocks; returning false stops the search (the function then returns
/// false and the table is incomplete).
bool FindNearestNeighbors(vtkStaticPointLocator* locator, const double* xyz, int32_t n, int k,
  std::vector<int32_t>& neighbors, const std::function<bool(double)>& progress = nullptr);

/// The same search on points already filed into `bins` (PointBins::Build, with or without
/// coordinates; the same `xyz` and `n`), without a locator. The result does not depend on the
/// grid.
bool FindNearestNeighbors(const PointBins& bins,
  const double* xyz,
  int32_t n,
  int k,
  std::vector<int32_t>& neighbors,
  const std::function<bool(double)>& progress = nullptr);

/// The table of the distinct positions of a cloud with exact copies, taken from the table of all
/// its points instead of searched again: the table FindNearestNeighbors gives on the positions
/// (their coordinates those of their first copies), entry for entry. `bins`, `xyz`, `n`: the
/// cloud's points and the bins (PointBins::Build, any grid, with or without coordinates) that
/// `pointTable` was searched on; `pointTable`: FindNearestNeighbors' table of the points (`width`
/// nearest per point, not extended by AddOffLineNeighbors); `positionOf`: the position of each
/// point; `positionIds`: the point of each position whose row is read, the copy of smallest id of
/// its group, in increasing order (so that the positions are numbered as their first copies and
/// ties stay broken by the smaller id). A position's row is its first copy's row without its own
/// copies, each other position once, in the order of its first copy there (that copy comes first
/// among the position's copies: same distance, smaller id). A row left with fewer than k
/// positions from a full point row (copies took the places) is searched again, exactly, by
/// FindNearestNeighbors' query on `bins` among the first copies only: those rows, or all the rows
/// when more than a quarter are short (every point copied). A point row that is not full holds
/// every other point. Cost: O(count k width) without short rows.
void DistinctNeighbors(const PointBins& bins,
  const double* xyz,
  int32_t n,
  const std::vector<int32_t>& pointTable,
  int width,
  const std::vector<int32_t>& positionOf,
  const std::vector<int32_t>& positionIds,
  int k,
  std::vector<int32_t>& neighbors);

/// Scan-line (strongly anisotropic) sampling: points much denser along lines than across them,
/// as laser-line and LiDAR scanners give. When the lines are more than about k / 2 spacings
/// apart, the k nearest neighbours of a point all lie on its own line and a filter working on
/// them sees a curve, not a surface. This function finds those points in a table made by
/// FindNearestNeighbors (same `xyz`, `n`, `k`) and gives them neighbours off their line, searched
/// with `locator` (set on exactly these points; built here, once, only when some point needs it).
///
/// A point's neighbourhood is confined to a curve when its max(2, k / 2) nearest neighbours
/// spread along one direction e only: with lambda1 >= lambda2 >= lambda3 the eigenvalues of
/// their covariance, (lambda1 lambda2 + lambda1 lambda3 + lambda2 lambda3) / (lambda1 + lambda2 +
/// lambda3)^2 <= `linearity` (about lambda2 / lambda1 when lambda3 is small; 0 on a straight
/// line; default 0.05: a spread across the line below 0.22 times the spread along it, which a
/// circular arc reaches when the neighbours span 100 degrees of it), and none of them is off the
/// line p + t e (below). Half of the k: lines whose spacing across is only 5 to 10 times that
/// along them have the next line among the k nearest but not among the k / 2 nearest, and a
/// filter's candidates there are still nearly all on the line. Ordinary surface samples rarely
/// meet it: over CGAL's bunny00, armadillo, camel, elephant, knot2 and fandisk_large vertices
/// (k = 20) one point of the camel; a few points of a random sample, where 10 points happen to
/// lie along a curve.
///
/// For such a point p, with dk the distance to its k-th neighbour, a point q within
/// `radiusFactor` dk of p (default 4: lines up to about 4 k / 2 spacings apart; a larger factor
/// is searched only where no point within 4 dk is off the line) is off the line
/// when its distance to the line p + t e exceeds its distance along it (|(q - p) x e| > |(q - p) .
/// e|: within 45 degrees of the plane normal to e, so the line's own points, even bent, are not
/// taken). The off-line points are split in two sides by the sign of their component normal to e
/// along that of the nearest one; the nearest max(1, k / 4) of each side (fewer when a side has
/// fewer, none on the last line of a scan) replace the farthest entries of the row that are not
/// among them, and the row is sorted again, nearest first, ties by the smaller id. Rows of fewer
/// than 2 neighbours, of coincident neighbours only, or of a non-finite point are left alone. The
/// result does not depend on the number of threads. Returns the number of rows changed; `progress`
/// as for FindNearestNeighbors (returns -1 when it stops the work, the table then partly changed).
///
/// `minimumShare` (default 0: every such point) asks that scan-line sampling be the pattern of
/// the region, not of one point: a point confined to a curve is given off-line neighbours (and a
/// stretch) only when at least this share of its k neighbours in the table are confined too. On
/// lines every point is; in an ordinary sample, clean or noisy, the few points whose nearest
/// happen to lie along a curve come alone or in small groups along it. With k = 12 and a share
/// of 1/2 (vtkGreedySurfaceTriangulation): none of CGAL's bunny00, armadillo, elephant and knot1
/// vertices, nor of the noisy camel, bunny00, elephant and knot1 and 10^5 noisy samples of bunny00
/// (2 of the clean samples); 15 of the camel's vertices, a patch sampled in lines (129 points
/// without the share).
///
/// `stretch` (optional) gets 3 values per point: zero, except at the points given off-line
/// neighbours, where it is sqrt(A^2 - 1) e with A = (distance to the nearest off-line point) /
/// (distance to the nearest neighbour), the sampling's anisotropy there (1 when A <= 1). A filter
/// measuring |w|^2 + (w . stretch)^2 for an offset w instead of |w|^2 sees the scan line's
/// spacing stretched to the spacing across lines: a triangle between two lines then has edges of
/// comparable lengths (the metric of anisotropic meshing).
int32_t AddOffLineNeighbors(vtkStaticPointLocator* locator,
  const double* xyz,
  int32_t n,
  int k,
  std::vector<int32_t>& neighbors,
  std::vector<double>* stretch = nullptr,
  double linearity = 0.05,
  double radiusFactor = 4.0,
  double minimumShare = 0.0,
  const std::function<bool(double)>& progress = nullptr);

/// The same on points already filed into `bins` (PointBins::Build on the same `xyz` and `n`, any
/// grid), without a locator: their coordinates are filed (PointBins::FileCoordinates) only when
/// some row is to be extended. The result does not depend on the grid.
int32_t AddOffLineNeighbors(PointBins& bins,
  const double* xyz,
  int32_t n,
  int k,
  std::vector<int32_t>& neighbors,
  std::vector<double>* stretch = nullptr,
  double linearity = 0.05,
  double radiusFactor = 4.0,
  double minimumShare = 0.0,
  const std::function<bool(double)>& progress = nullptr);

/// The squared length of the offset `w` in the scan-line sampling's metric between two points
/// whose stretches (3 values each, as made by AddOffLineNeighbors; null for none) are `sa` and
/// `sb`: |w|^2 + max((w . sa)^2, (w . sb)^2). The larger of the two components: the stretches of
/// two neighbours on one line are nearly parallel, and an offset along a line stays long where
/// one end (the end of a line, the edge of a scanned region) got no stretch. |w|^2 where both
/// are zero.
inline double StretchedLength2(const double w[3], const double* sa, const double* sb)
{
  const double alongA = sa ? w[0] * sa[0] + w[1] * sa[1] + w[2] * sa[2] : 0.0;
  const double alongB = sb ? w[0] * sb[0] + w[1] * sb[1] + w[2] * sb[2] : 0.0;
  const double along2 = alongA * alongA > alongB * alongB ? alongA * alongA : alongB * alongB;
  return w[0] * w[0] + w[1] * w[1] + w[2] * w[2] + along2;
}

/// True when the triangle (a, b, c) of points of `xyz` lies along one scan line: each of its three
/// edges runs along the line at one of its ends, within 45 degrees of the stretch there (|w x s|
/// <= |w . s|: AddOffLineNeighbors' rule for a line's own points; `stretch` 3 values per point).
/// Such a triangle is a sliver of three points of one line (in the sampling's metric an angle
/// near 180 degrees), never part of the surface between the lines. False where the stretches are
/// zero.
bool OnOneScanLine(const double* xyz, const double* stretch, int32_t a, int32_t b, int32_t c);

/// OnOneScanLine without its first test (at least two of a, b, c have a non-zero stretch; the
/// edge tests imply it), for a caller that made that test already, e.g. on flags of its own.
bool EdgesAlongOneScanLine(const double* xyz,
  const double* stretch,
  int32_t a,
  int32_t b,
  int32_t c);

/// Bin grid of `locator` (divisions set, Automatic off) for a sample of a surface: `n` points in
/// the box `bounds`, about `binsPerPoint` bins per point over the box's volume (its area when
/// flat, its length when straight). VTK's automatic grid aims at a few points per bin of the box,
/// but a surface sample occupies only a thin layer of those bins, so the bins it does occupy
/// hold many points; finer bins keep the radius queries of FindNearestNeighbors short. Call it
/// before BuildLocator; zero or non-finite extents give one division on that axis.
void SetSurfaceSampleDivisions(
  vtkStaticPointLocator* locator, const double bounds[6], int32_t n, double binsPerPoint = 4.0);

/// The divisions SetSurfaceSampleDivisions gives a locator, for PointBins::Build without one.
void SurfaceSampleDivisions(const double bounds[6],
  int32_t n,
  double binsPerPoint,
  int divisions[3]);

/// The box a bucket grid over the `n` points of `xyz` covers: their bounding box `bounds`, shrunk
/// to the bulk of the points when a few lie far outside it (stray returns of a scanner, a far
/// outlier). Per axis, the bulk is the range between the 1st and 99th percentiles of a stride
/// sample of at most 65,536 points, widened on each side by half the largest such range over the
/// axes; `grid` gets `bounds` intersected with the widened bulk when that halves the box along
/// some axis, else `bounds` itself (a cloud without far points, or a mild tail, keeps its grid).
/// The points outside `grid` are filed into the clamped first and last buckets
/// (PointBins::BucketIndex), where the queries still find them: the grid changes the cost of the
/// queries, never their answers. Without this one point 10^4 object sizes away put every other
/// point into a few buckets, and the neighbour search became quadratic (10^5 points: 30 to 110 s
/// instead of 1 to 2 s).
void BulkBounds(const double* xyz, int32_t n, const double bounds[6], double grid[6]);

/// Files the `n` points of `xyz` (finite) into `bins` on SurfaceSampleDivisions' grid (4 bins per
/// point over the box's volume, area or length) over their BulkBounds box; their bounding box is
/// returned in `bounds` (xmin, xmax, ymin, ...; zeros when n is 0): the bins of a surface sample,
/// no locator built. VTK's automatic bins suit points filling their box; on a surface sample a bin
/// would be about ten spacings wide and every query of a few spacings would visit many points it
/// does not return (on the benchmark clouds these bins are 2.5 to 5 mean spacings wide). The grid
/// changes the cost of the queries, never their answers. Used by vtkCDTAdvancingFront and
/// vtkLocalOptimumGrowth.
void BuildSurfaceSampleBins(
  PointBins& bins, const double* xyz, int32_t n, bool withCoordinates, double bounds[6]);
}

#endif
