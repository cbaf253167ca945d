// The shared K-nearest-neighbour search (pcs::FindNearestNeighbors, pcsNearestNeighbors.h)
// against brute force, on a cloud with many exact distance ties and exact duplicates:
// - a 16 x 16 lattice of spacing 1 in the plane z = 0 (each point has 4 neighbours at 1, 4 at
//   sqrt(2), 4 at 2, ...: ties broken by the smaller id), 40 of its points repeated up to 3 times,
//   and 1,500 random points of a sphere of radius 5 around it;
// - the table of the k = 12 nearest others of each point, nearest first, ties by id, must equal
//   the sorted brute-force list, for the search on bins filed without a locator
//   (pcs::PointBins: about 4 bins per point; one bin; 40^3 bins, the ball's rows then cut short)
//   and on a built vtkStaticPointLocator's grid;
// - pcs::AddOffLineNeighbors builds the locator it is given only when a row is to be extended:
//   on the lattice alone (no point confined to a curve) it changes nothing and the locator stays
//   unbuilt; on scan lines (rows confined to their line) it builds it and extends every row, and
//   on bins filed without coordinates (two grids) it gives the same rows and stretches;
// - a pile of exact copies filed before single points in the same row of bins, for k from 1 to 8
//   and piles of 2 to 20 copies, with points in later rows (the candidate buffer must make room
//   for the whole pile and the rest of its row: a single point written past its end was zeroed
//   when the buffer grew for the next row).
// - the closed-form 3 x 3 symmetric eigenvectors (pcs::LargestEigenvector, used by the curve test
//   of AddOffLineNeighbors, and pcs::SmallestEigenvector) on matrices R diag(l) R^T of known
//   eigenvalues and random rotations R, from 1e-8 to 1e8 in scale: the eigenvector within 1e-9 of
//   the known axis (up to sign; the largest's sign vtkMath::Jacobi's, at least two non-negative
//   components), the eigenvalues within 1e-7 of the largest (the trigonometric solution loses
//   about half the digits of two nearly equal eigenvalues: 7e-9 on a rank-1 matrix); a multiple
//   of the identity and the zero matrix (the fallback) give unit vectors;
// - pcs::DistinctNeighbors (the table of the distinct positions of a cloud with exact copies,
//   taken from the table of its points) equals the search on the positions
//   (CheckDistinctNeighbors);
// - a few stray points far from the rest (10^4, 10^6 and 10^12 times the cloud's size away):
//   the bins (pcs::BuildSurfaceSampleBins, and those filed from a locator's grid) cover the bulk
//   of the points (pcs::BulkBounds, a box up to twice the cloud's along each axis), so no bucket
//   holds more than 8 times the fullest bucket of the cloud without the strays (before, the grid
//   spanned the strays and one bucket held every other point: the search became quadratic), and
//   the table still equals brute force, the strays filed in the clamped border buckets
//   (CheckFarStrays).
#include "pcsNearestNeighbors.h"
#include "pcsNormalEstimation.h"

#include "pcsTestUtilities.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <utility>
#include <vector>

namespace
{
std::vector<double> TiesAndDuplicates()
{
  std::vector<double> xyz;
  for (int j = 0; j < 16; ++j)
  {
    for (int i = 0; i < 16; ++i)
    {
      xyz.insert(xyz.end(), { static_cast<double>(i), static_cast<double>(j), 0.0 });
    }
  }
  for (int copy = 0; copy < 40; ++copy)
  {
    const int source = (37 * copy) % 256;
    for (int times = 0; times <= copy % 3; ++times)
    {
      xyz.insert(xyz.end(), { xyz[3 * source], xyz[3 * source + 1], xyz[3 * source + 2] });
    }
  }
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int p = 0; p < 1500; ++p)
  {
    double v[3] = { g(rng), g(rng), g(rng) };
    const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    xyz.insert(xyz.end(), { 7.5 + 5 * v[0] / length, 7.5 + 5 * v[1] / length, 5 * v[2] / length });
  }
  return xyz;
}

std::vector<int32_t> BruteForce(const std::vector<double>& xyz, int k)
{
  const int32_t n = static_cast<int32_t>(xyz.size() / 3);
  std::vector<int32_t> table(static_cast<size_t>(n) * k, -1);
  std::vector<std::pair<double, int32_t>> all;
  for (int32_t i = 0; i < n; ++i)
  {
    all.clear();
    for (int32_t j = 0; j < n; ++j)
    {
      if (j != i)
      {
        const double d[3] = {
          xyz[3 * j] - xyz[3 * i], xyz[3 * j + 1] - xyz[3 * i + 1], xyz[3 * j + 2] - xyz[3 * i + 2]
        };
        all.emplace_back(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], j);
      }
    }
    std::partial_sort(all.begin(), all.begin() + k, all.end());
    for (int c = 0; c < k; ++c)
    {
      table[static_cast<size_t>(i) * k + c] = all[c].second;
    }
  }
  return table;
}

// The search on the bins of `divisions` over `bounds` (none: SurfaceSampleDivisions').
std::vector<int32_t> Search(const std::vector<double>& xyz,
  int k,
  const double bounds[6],
  const int* divisions = nullptr)
{
  const int32_t n = static_cast<int32_t>(xyz.size() / 3);
  int sample[3];
  pcs::SurfaceSampleDivisions(bounds, n, 4.0, sample);
  pcs::PointBins bins;
  bins.Build(bounds, divisions ? divisions : sample, xyz.data(), n, false);
  std::vector<int32_t> table;
  pcs::FindNearestNeighbors(bins, xyz.data(), n, k, table);
  return table;
}

bool SameTable(const std::vector<int32_t>& found,
  const std::vector<int32_t>& expected,
  int k,
  const char* what)
{
  PCS_CHECK(found.size() == expected.size(), what << ": " << found.size() << " entries");
  for (size_t e = 0; e < found.size(); ++e)
  {
    PCS_CHECK(found[e] == expected[e],
      what << ": point " << e / k << ", neighbour " << e % k << " is " << found[e] << ", not "
           << expected[e]);
  }
  return true;
}

void Bounds(const std::vector<double>& xyz, double bounds[6])
{
  for (int c = 0; c < 3; ++c)
  {
    bounds[2 * c] = bounds[2 * c + 1] = xyz[c];
  }
  for (size_t p = 0; p < xyz.size(); p += 3)
  {
    for (int c = 0; c < 3; ++c)
    {
      bounds[2 * c] = std::min(bounds[2 * c], xyz[p + c]);
      bounds[2 * c + 1] = std::max(bounds[2 * c + 1], xyz[p + c]);
    }
  }
}

vtkSmartPointer<vtkStaticPointLocator> Locator(const std::vector<double>& xyz, vtkPolyData* cloud)
{
  auto locator = vtkSmartPointer<vtkStaticPointLocator>::New();
  double bounds[6];
  Bounds(xyz, bounds);
  pcs::SetSurfaceSampleDivisions(locator, bounds, static_cast<int32_t>(xyz.size() / 3));
  locator->SetDataSet(cloud);
  return locator;
}

bool CheckAgainstBruteForce()
{
  const std::vector<double> xyz = TiesAndDuplicates();
  const int32_t n = static_cast<int32_t>(xyz.size() / 3);
  const int k = 12;
  const std::vector<int32_t> expected = BruteForce(xyz, k);
  double bounds[6];
  Bounds(xyz, bounds);
  bool ok = SameTable(Search(xyz, k, bounds), expected, k, "own grid");
  const int one[3] = { 1, 1, 1 }, fine[3] = { 40, 40, 40 };
  ok = SameTable(Search(xyz, k, bounds, one), expected, k, "one bin") && ok;
  ok = SameTable(Search(xyz, k, bounds, fine), expected, k, "40^3 bins") && ok;
  std::vector<int32_t> table;
  vtkSmartPointer<vtkPolyData> cloud = pcstest::MakeCloud(xyz);
  vtkSmartPointer<vtkStaticPointLocator> locator = Locator(xyz, cloud);
  locator->BuildLocator();
  pcs::FindNearestNeighbors(locator, xyz.data(), n, k, table);
  ok = SameTable(table, expected, k, "locator's grid") && ok;

  // On the lattice alone no point's 6 nearest lie along one line (every one has a neighbour at
  // 1 on each axis among them): the locator given is not built.
  const std::vector<double> lattice(xyz.begin(), xyz.begin() + 3 * 256);
  table = Search(lattice, k, bounds);
  vtkSmartPointer<vtkPolyData> latticeCloud = pcstest::MakeCloud(lattice);
  vtkSmartPointer<vtkStaticPointLocator> unbuilt = Locator(lattice, latticeCloud);
  const int32_t changed = pcs::AddOffLineNeighbors(unbuilt, lattice.data(), 256, k, table);
  PCS_CHECK(changed == 0, changed << " rows changed");
  PCS_CHECK(unbuilt->GetBuildTime() == 0, "the locator was built without a row to extend");
  return ok;
}

// 20 lines of 200 points, 0.01 apart along x, lines 0.2 apart in y (within 4 times the 12th
// neighbour's distance): every row is confined to its line; the locator is built on demand and
// each row gets the 3 nearest points of each line beside.
bool CheckScanLines()
{
  std::vector<double> xyz;
  for (int line = 0; line < 20; ++line)
  {
    for (int i = 0; i < 200; ++i)
    {
      xyz.insert(xyz.end(), { 0.01 * i, 0.2 * line, 0.0 });
    }
  }
  const int32_t n = static_cast<int32_t>(xyz.size() / 3);
  const int k = 12;
  double bounds[6];
  Bounds(xyz, bounds);
  std::vector<int32_t> table = Search(xyz, k, bounds);
  const std::vector<int32_t> plain = table;
  vtkSmartPointer<vtkPolyData> cloud = pcstest::MakeCloud(xyz);
  vtkSmartPointer<vtkStaticPointLocator> unbuilt = Locator(xyz, cloud);
  std::vector<double> stretch;
  const int32_t changed = pcs::AddOffLineNeighbors(unbuilt, xyz.data(), n, k, table, &stretch);
  PCS_CHECK(changed == n, changed << " rows changed, not " << n);
  PCS_CHECK(unbuilt->GetBuildTime() > 0, "the locator was not built");
  // The same extension on bins filed without coordinates, on two other grids (the search's own,
  // and 7 x 5 x 1 bins): the same rows and stretches.
  int sample[3];
  pcs::SurfaceSampleDivisions(bounds, n, 4.0, sample);
  const int coarse[3] = { 7, 5, 1 };
  for (const int* divisions : { static_cast<const int*>(sample), coarse })
  {
    pcs::PointBins bins;
    bins.Build(bounds, divisions, xyz.data(), n, /*withCoordinates=*/false);
    std::vector<int32_t> onBins = plain;
    std::vector<double> stretchOnBins;
    const int32_t changedOnBins =
      pcs::AddOffLineNeighbors(bins, xyz.data(), n, k, onBins, &stretchOnBins);
    PCS_CHECK(changedOnBins == changed && onBins == table && stretchOnBins == stretch,
      "the extension on " << divisions[0] << " x " << divisions[1] << " x " << divisions[2]
                          << " bins differs from the locator's");
  }
  int32_t offLine = 0;
  for (int32_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < k; ++c)
    {
      const int32_t q = table[static_cast<size_t>(i) * k + c];
      offLine += q >= 0 && xyz[3 * q + 1] != xyz[3 * i + 1] ? 1 : 0;
    }
  }
  // k / 4 = 3 per side, one side only on the first and last lines.
  PCS_CHECK(offLine == 3 * (2 * n - 2 * 200), offLine << " off-line neighbours");
  return true;
}

bool CheckPileBeforeSinglePoints()
{
  bool ok = true;
  for (int k = 1; k <= 8; ++k)
  {
    for (int copies = 2; copies <= 20; ++copies)
    {
      // Row y = 0: the query point, the pile, then single points; rows y = 0.3, 0.6: more points.
      std::vector<double> xyz = { 0.0, 0.0, 0.0 };
      for (int c = 0; c < copies; ++c)
      {
        xyz.insert(xyz.end(), { 0.1, 0.0, 0.0 });
      }
      for (int s = 0; s < 4; ++s)
      {
        xyz.insert(xyz.end(), { 0.15 + 0.05 * s, 0.0, 0.0 });
      }
      for (int r = 1; r <= 2; ++r)
      {
        for (int s = 0; s < 6; ++s)
        {
          xyz.insert(xyz.end(), { 0.06 * s, 0.3 * r, 0.0 });
        }
      }
      double bounds[6];
      Bounds(xyz, bounds);
      const int rows[3] = { 1, 3, 1 }, one[3] = { 1, 1, 1 };
      const std::vector<int32_t> expected = BruteForce(xyz, k);
      ok = SameTable(Search(xyz, k, bounds, rows), expected, k, "pile, three rows") && ok;
      ok = SameTable(Search(xyz, k, bounds, one), expected, k, "pile, one bin") && ok;
    }
  }
  return ok;
}

bool CheckExtremeEigenvectors()
{
  bool ok = true;
  std::mt19937 random(7);
  std::normal_distribution<double> gaussian;
  auto unit = [&](double v[3])
  {
    const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int c = 0; c < 3; ++c)
    {
      v[c] /= length;
    }
  };
  const double spectra[][3] = { { 5.0, 1.0, 0.01 },
    { 1.0, 1e-3, 1e-4 },
    { 1.0, 0.5, 0.49 },
    { 1.0, 0.99, 1e-3 },
    { 2.0, 1e-12, 0.0 } };
  for (const double scale : { 1e-8, 1.0, 1e8 })
  {
    for (const auto& spectrum : spectra)
    {
      for (int trial = 0; trial < 100; ++trial)
      {
        // An orthonormal frame: the largest's axis, the middle's, the smallest's.
        double axes[3][3];
        for (int c = 0; c < 3; ++c)
        {
          axes[0][c] = gaussian(random);
          axes[1][c] = gaussian(random);
        }
        unit(axes[0]);
        const double along =
          axes[1][0] * axes[0][0] + axes[1][1] * axes[0][1] + axes[1][2] * axes[0][2];
        for (int c = 0; c < 3; ++c)
        {
          axes[1][c] -= along * axes[0][c];
        }
        unit(axes[1]);
        axes[2][0] = axes[0][1] * axes[1][2] - axes[0][2] * axes[1][1];
        axes[2][1] = axes[0][2] * axes[1][0] - axes[0][0] * axes[1][2];
        axes[2][2] = axes[0][0] * axes[1][1] - axes[0][1] * axes[1][0];
        double a[3][3];
        for (int r = 0; r < 3; ++r)
        {
          for (int c = 0; c < 3; ++c)
          {
            a[r][c] = 0.0;
            for (int k = 0; k < 3; ++k)
            {
              a[r][c] += scale * spectrum[k] * axes[k][r] * axes[k][c];
            }
          }
        }
        const bool largestSeparated = spectrum[0] - spectrum[1] >= 0.1 * spectrum[0];
        const bool smallestSeparated = spectrum[1] - spectrum[2] >= 0.1 * spectrum[0];
        for (const bool largest : { true, false })
        {
          if (largest ? !largestSeparated : !smallestSeparated)
          {
            continue;
          }
          double values[3], vector[3];
          if (largest)
          {
            pcs::LargestEigenvector(a, values, vector);
          }
          else
          {
            pcs::SmallestEigenvector(a, values, vector);
          }
          const double* axis = axes[largest ? 0 : 2];
          const double dot = vector[0] * axis[0] + vector[1] * axis[1] + vector[2] * axis[2];
          const double length2 =
            vector[0] * vector[0] + vector[1] * vector[1] + vector[2] * vector[2];
          bool good = std::fabs(std::fabs(dot) - 1.0) <= 1e-9 && std::fabs(length2 - 1.0) <= 1e-12;
          for (int k = 0; k < 3; ++k)
          {
            good = good && std::fabs(values[k] - scale * spectrum[k]) <= 1e-7 * scale * spectrum[0];
          }
          if (largest)
          {
            const int nonNegative =
              (vector[0] >= 0.0 ? 1 : 0) + (vector[1] >= 0.0 ? 1 : 0) + (vector[2] >= 0.0 ? 1 : 0);
            good = good && nonNegative >= 2;
          }
          if (!good)
          {
            std::cerr << (largest ? "LargestEigenvector" : "SmallestEigenvector") << ", scale "
                      << scale << ", eigenvalues " << spectrum[0] << " " << spectrum[1] << " "
                      << spectrum[2] << ": dot with the axis " << dot << ", values " << values[0]
                      << " " << values[1] << " " << values[2] << "\n";
            ok = false;
          }
        }
      }
    }
  }
  // No separated eigenvalue (the fallback): still unit vectors and the eigenvalues.
  for (const double diagonal : { 3.0, 0.0 })
  {
    const double a[3][3] = {
      { diagonal, 0.0, 0.0 }, { 0.0, diagonal, 0.0 }, { 0.0, 0.0, diagonal }
    };
    for (const bool largest : { true, false })
    {
      double values[3], vector[3];
      if (largest)
      {
        pcs::LargestEigenvector(a, values, vector);
      }
      else
      {
        pcs::SmallestEigenvector(a, values, vector);
      }
      const double length2 = vector[0] * vector[0] + vector[1] * vector[1] + vector[2] * vector[2];
      if (std::fabs(length2 - 1.0) > 1e-12 || values[0] != diagonal || values[2] != diagonal)
      {
        std::cerr << "eigenvector of " << diagonal << " I: squared length " << length2 << "\n";
        ok = false;
      }
    }
  }
  return ok;
}

// pcs::DistinctNeighbors: the table of the distinct positions taken from the table of all the
// points equals the search on the positions (FindNearestNeighbors, checked against brute force
// above), entry for entry, ties included. The positions: the lattice and sphere points of
// TiesAndDuplicates without its copies; the cloud holds each of them 1 to 12 times, in a
// shuffled order (the first copy of a position is anywhere in the cloud), so that point rows
// hold copies and leave fewer than k positions, searched again: `copiedShare` of the positions
// have copies (2/3: most rows are short, all searched again at once; 1/200: a few, each row
// searched alone).
bool CheckDistinctNeighbors(double copiedShare)
{
  const std::vector<double> all = TiesAndDuplicates();
  std::vector<double> distinct(all.begin(), all.begin() + 3 * 256); // the lattice, then the sphere
  const size_t sphere = all.size() - 3 * 1500;
  distinct.insert(distinct.end(), all.begin() + sphere, all.end());
  const int32_t positions = static_cast<int32_t>(distinct.size() / 3);
  std::vector<int32_t> sourceOf; // per point of the cloud: its position in `distinct`
  std::mt19937_64 rng(5);
  for (int32_t d = 0; d < positions; ++d)
  {
    const bool copied = std::uniform_real_distribution<double>(0.0, 1.0)(rng) < copiedShare;
    const int copies = copied ? 2 + static_cast<int>(rng() % 11) : 1;
    sourceOf.insert(sourceOf.end(), copies, d);
  }
  std::shuffle(sourceOf.begin(), sourceOf.end(), rng);
  const int32_t n = static_cast<int32_t>(sourceOf.size());
  std::vector<double> xyz;
  std::vector<int32_t> firstOf(positions, -1); // per source position: its first copy
  for (int32_t i = 0; i < n; ++i)
  {
    const double* q = &distinct[3 * static_cast<size_t>(sourceOf[i])];
    xyz.insert(xyz.end(), q, q + 3);
    firstOf[sourceOf[i]] = firstOf[sourceOf[i]] < 0 ? i : firstOf[sourceOf[i]];
  }
  // The positions numbered as their first copies: positionIds increasing.
  std::vector<int32_t> positionIds(firstOf);
  std::sort(positionIds.begin(), positionIds.end());
  std::vector<int32_t> positionOf(n);
  std::vector<double> packed;
  std::vector<int32_t> numberOfFirst(n, -1);
  for (int32_t d = 0; d < positions; ++d)
  {
    numberOfFirst[positionIds[d]] = d;
    packed.insert(packed.end(),
      &xyz[3 * static_cast<size_t>(positionIds[d])],
      &xyz[3 * static_cast<size_t>(positionIds[d])] + 3);
  }
  for (int32_t i = 0; i < n; ++i)
  {
    positionOf[i] = numberOfFirst[firstOf[sourceOf[i]]];
  }
  double bounds[6];
  Bounds(packed, bounds);
  const int k = 8;
  const std::vector<int32_t> expected = Search(packed, k, bounds);
  PCS_CHECK(SameTable(expected, BruteForce(packed, k), k, "positions, brute force"),
    "the search on the positions");
  Bounds(xyz, bounds);
  int divisions[3];
  pcs::SurfaceSampleDivisions(bounds, n, 4.0, divisions);
  pcs::PointBins bins;
  bins.Build(bounds, divisions, xyz.data(), n, false);
  for (const int width : { 8, 9, 12 })
  {
    const std::vector<int32_t> pointTable = Search(xyz, width, bounds);
    std::vector<int32_t> found;
    pcs::DistinctNeighbors(
      bins, xyz.data(), n, pointTable, width, positionOf, positionIds, k, found);
    PCS_CHECK(SameTable(found, expected, k, "distinct positions from the point table"),
      "distinct positions from a table of width " << width << ", " << copiedShare
                                                  << " of them copied");
  }
  return true;
}
}

// The largest number of points in one bucket of `bins`.
int32_t FullestBucket(const pcs::PointBins& bins)
{
  int32_t fullest = 0;
  for (int64_t b = 0; b < bins.GetNumberOfBuckets(); ++b)
  {
    fullest = std::max(fullest, bins.GetOffsets()[b + 1] - bins.GetOffsets()[b]);
  }
  return fullest;
}

bool CheckFarStrays()
{
  std::vector<double> xyz = TiesAndDuplicates();
  pcs::PointBins bins;
  double bounds[6];
  pcs::BuildSurfaceSampleBins(
    bins, xyz.data(), static_cast<int32_t>(xyz.size() / 3), false, bounds);
  const int32_t fullestWithout = FullestBucket(bins);
  xyz.insert(xyz.end(), { 1e5, 2e5, -3e5, -4e7, 1e7, 5e6, 3e13, -1e13, 2e13 });
  const int32_t n = static_cast<int32_t>(xyz.size() / 3);
  const int k = 12;
  const std::vector<int32_t> expected = BruteForce(xyz, k);
  pcs::BuildSurfaceSampleBins(bins, xyz.data(), n, false, bounds);
  PCS_CHECK(bounds[1] == 3e13 && bounds[2] == -1e13 && bounds[5] == 2e13,
    "BuildSurfaceSampleBins returns the points' bounding box");
  std::cout << "fullest bucket: " << fullestWithout << " points without the strays, "
            << FullestBucket(bins) << " with them" << std::endl;
  PCS_CHECK(FullestBucket(bins) <= 8 * fullestWithout,
    "a bucket holds " << FullestBucket(bins) << " points");
  std::vector<int32_t> table;
  pcs::FindNearestNeighbors(bins, xyz.data(), n, k, table);
  bool ok = SameTable(table, expected, k, "far strays, own grid");
  vtkSmartPointer<vtkPolyData> cloud = pcstest::MakeCloud(xyz);
  vtkSmartPointer<vtkStaticPointLocator> locator = Locator(xyz, cloud);
  locator->BuildLocator();
  pcs::PointBins fromLocator;
  fromLocator.Build(locator, xyz.data(), n, false);
  PCS_CHECK(FullestBucket(fromLocator) <= 8 * fullestWithout,
    "a bucket of the locator's bins holds " << FullestBucket(fromLocator) << " points");
  pcs::FindNearestNeighbors(locator, xyz.data(), n, k, table);
  ok = SameTable(table, expected, k, "far strays, locator's grid") && ok;
  return ok;
}

int TestNearestNeighbors(int, char*[])
{
  bool ok = CheckAgainstBruteForce();
  ok = CheckScanLines() && ok;
  ok = CheckPileBeforeSinglePoints() && ok;
  ok = CheckExtremeEigenvectors() && ok;
  ok = CheckDistinctNeighbors(2.0 / 3.0) && ok;
  ok = CheckDistinctNeighbors(1.0 / 200.0) && ok;
  ok = CheckFarStrays() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
