#include "pcsNormalEstimation.h"

#include "pcsDisjointSets.h"
#include "pcsDuplicatePoints.h"
#include "pcsNearestNeighbors.h"
#include "pcsSpatialSort.h"

#include "vtkMath.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>

namespace pcs
{
namespace
{
using Id = int32_t;

inline double Dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Agreement of the normal n of a point p with the normal m of a point q: (R n) . m, R the
// reflection through the plane bisecting p q. On a circle through p and q (the surface between
// them, bent in the plane of the chord) R maps the normal at p to the normal at q, so the sign
// says whether m is oriented like n and the magnitude (1 on a circle) how sure that is. With the
// chord in the tangent plane this is n . m (Hoppe et al.); with the chord along n (the other side
// of a thin part, in a neighbourhood) it is -n . m: the two sides' outward normals are opposite.
inline double ReflectedAgreement(const double* p, const double* n, const double* q, const double* m)
{
  const double chord[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
  const double length2 = Dot(chord, chord);
  if (!(length2 > 0.0))
  {
    return Dot(n, m);
  }
  return Dot(n, m) - 2.0 * Dot(n, chord) * Dot(chord, m) / length2;
}

// SmallestEigenvector (column 2) and LargestEigenvector (column 0): the eigenvector of the
// eigenvalue of rank `column` in decreasing order.
void ExtremeEigenvector(const double a[3][3], double values[3], int column, double vector[3])
{
  double scale = 0.0;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      scale = std::max(scale, std::fabs(a[r][c]));
    }
  }
  double b[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      b[r][c] = scale > 0.0 ? a[r][c] / scale : 0.0;
    }
  }
  const double q = (b[0][0] + b[1][1] + b[2][2]) / 3.0;
  const double off = b[0][1] * b[0][1] + b[0][2] * b[0][2] + b[1][2] * b[1][2];
  const double spread = (b[0][0] - q) * (b[0][0] - q) + (b[1][1] - q) * (b[1][1] - q) +
    (b[2][2] - q) * (b[2][2] - q) + 2.0 * off;
  const double p = std::sqrt(spread / 6.0);
  bool solved = false;
  if (scale > 0.0 && std::isfinite(scale) && p > 1e-12)
  {
    double c[3][3];
    for (int r = 0; r < 3; ++r)
    {
      for (int k = 0; k < 3; ++k)
      {
        c[r][k] = (b[r][k] - (r == k ? q : 0.0)) / p;
      }
    }
    const double half = 0.5 *
      (c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) -
        c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0]) +
        c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0]));
    const double phi = std::acos(std::min(1.0, std::max(-1.0, half))) / 3.0;
    const double largest = q + 2.0 * p * std::cos(phi);
    const double smallest = q + 2.0 * p * std::cos(phi + 2.0 * vtkMath::Pi() / 3.0);
    const double middle = 3.0 * q - largest - smallest;
    const double shift = column == 0 ? largest : smallest;
    double rows[3][3];
    for (int r = 0; r < 3; ++r)
    {
      for (int k = 0; k < 3; ++k)
      {
        rows[r][k] = b[r][k] - (r == k ? shift : 0.0);
      }
    }
    double best[3] = { 0.0, 0.0, 0.0 };
    double bestNorm2 = 0.0;
    for (int r = 0; r < 3; ++r)
    {
      double cross[3];
      vtkMath::Cross(rows[r], rows[(r + 1) % 3], cross);
      const double norm2 = Dot(cross, cross);
      if (norm2 > bestNorm2)
      {
        bestNorm2 = norm2;
        std::copy_n(cross, 3, best);
      }
    }
    if (bestNorm2 > 1e-12 && std::isfinite(bestNorm2))
    {
      const double norm = std::sqrt(bestNorm2);
      for (int k = 0; k < 3; ++k)
      {
        vector[k] = best[k] / norm;
      }
      values[0] = largest * scale;
      values[1] = middle * scale;
      values[2] = smallest * scale;
      solved = true;
    }
  }
  if (!solved)
  {
    double row0[3] = { a[0][0], a[0][1], a[0][2] }, row1[3] = { a[1][0], a[1][1], a[1][2] },
           row2[3] = { a[2][0], a[2][1], a[2][2] };
    double* matrix[3] = { row0, row1, row2 };
    double column0[3], column1[3], column2[3];
    double* vectors[3] = { column0, column1, column2 };
    vtkMath::Jacobi(matrix, values, vectors); // eigenvalues in decreasing order
    vector[0] = vectors[0][column];
    vector[1] = vectors[1][column];
    vector[2] = vectors[2][column];
  }
}
}

void SmallestEigenvector(const double a[3][3], double values[3], double vector[3])
{
  ExtremeEigenvector(a, values, 2, vector);
}

void LargestEigenvector(const double a[3][3], double values[3], double vector[3])
{
  ExtremeEigenvector(a, values, 0, vector);
  // vtkMath::Jacobi's sign: at least two non-negative components.
  const int nonNegative =
    (vector[0] >= 0.0 ? 1 : 0) + (vector[1] >= 0.0 ? 1 : 0) + (vector[2] >= 0.0 ? 1 : 0);
  if (nonNegative < 2)
  {
    vector[0] = -vector[0];
    vector[1] = -vector[1];
    vector[2] = -vector[2];
  }
}

double OffsetCovariance(const double* xyz, const double* p, const int32_t* row, int count,
  bool withPoint, double covariance[3][3], double mean[3])
{
  double s0 = withPoint ? 1.0 : 0.0;
  double s1[3] = { 0.0, 0.0, 0.0 };
  double s2[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 }; // xx yy zz xy xz yz
  for (int j = 0; j < count; ++j)
  {
    if (row[j] < 0)
    {
      continue;
    }
    const double* q = xyz + 3 * static_cast<size_t>(row[j]);
    const double d[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
    if (!(std::isfinite(d[0]) && std::isfinite(d[1]) && std::isfinite(d[2])))
    {
      continue;
    }
    s0 += 1.0;
    s1[0] += d[0];
    s1[1] += d[1];
    s1[2] += d[2];
    s2[0] += d[0] * d[0];
    s2[1] += d[1] * d[1];
    s2[2] += d[2] * d[2];
    s2[3] += d[0] * d[1];
    s2[4] += d[0] * d[2];
    s2[5] += d[1] * d[2];
  }
  if (s0 > 0.0)
  {
    const double m[3] = { s1[0] / s0, s1[1] / s0, s1[2] / s0 };
    covariance[0][0] = s2[0] / s0 - m[0] * m[0];
    covariance[1][1] = s2[1] / s0 - m[1] * m[1];
    covariance[2][2] = s2[2] / s0 - m[2] * m[2];
    covariance[0][1] = covariance[1][0] = s2[3] / s0 - m[0] * m[1];
    covariance[0][2] = covariance[2][0] = s2[4] / s0 - m[0] * m[2];
    covariance[1][2] = covariance[2][1] = s2[5] / s0 - m[1] * m[2];
    if (mean)
    {
      std::copy_n(m, 3, mean);
    }
  }
  return s0;
}

double Median(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  const auto middle = values.begin() + values.size() / 2;
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

double QuadricHeightNoise(const double* xyz,
  const double* normals,
  const double* p,
  const double* normal,
  const int32_t* row,
  int count,
  double minimumNormalDot)
{
  // Tangent frame (t1, t2, normal); the lateral coordinates are divided by the largest offset
  // for the conditioning of the normal equations. Two passes over the neighbours (the extent,
  // then the sums), nothing stored.
  double t1[3], t2[3];
  vtkMath::Perpendiculars(normal, t1, t2, 0.0);
  auto offset = [&](int j, double uvh[3])
  {
    if (row[j] < 0 ||
      (normals &&
        !(vtkMath::Dot(normals + 3 * static_cast<size_t>(row[j]), normal) >= minimumNormalDot)))
    {
      return false;
    }
    const double* q = xyz + 3 * static_cast<size_t>(row[j]);
    const double d[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
    uvh[0] = vtkMath::Dot(d, t1);
    uvh[1] = vtkMath::Dot(d, t2);
    uvh[2] = vtkMath::Dot(d, normal);
    return std::isfinite(uvh[0]) && std::isfinite(uvh[1]) && std::isfinite(uvh[2]);
  };
  double extent = 0.0;
  int m = 1; // p itself, at (0, 0, 0)
  for (int j = 0; j < count; ++j)
  {
    double uvh[3];
    if (offset(j, uvh))
    {
      extent = std::max({ extent, std::fabs(uvh[0]), std::fabs(uvh[1]) });
      ++m;
    }
  }
  constexpr int terms = 6;
  if (m <= terms || !(extent > 0.0))
  {
    return -1.0;
  }
  // Normal equations of h = a + b u + c v + d u^2 + e u v + f v^2 (u, v scaled), and the sum of
  // the squared heights: the residual is sum h^2 - beta . (X^T h).
  double normalMatrix[terms][terms] = {};
  double rightSide[terms] = {};
  double heights2 = 0.0;
  auto accumulate = [&](const double uvh[3])
  {
    const double u = uvh[0] / extent, v = uvh[1] / extent;
    const double f[terms] = { 1.0, u, v, u * u, u * v, v * v };
    for (int r = 0; r < terms; ++r)
    {
      rightSide[r] += f[r] * uvh[2];
      for (int col = 0; col < terms; ++col)
      {
        normalMatrix[r][col] += f[r] * f[col];
      }
    }
    heights2 += uvh[2] * uvh[2];
  };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  accumulate(origin);
  for (int j = 0; j < count; ++j)
  {
    double uvh[3];
    if (offset(j, uvh))
    {
      accumulate(uvh);
    }
  }
  double projected[terms];
  std::copy(rightSide, rightSide + terms, projected);
  // Gaussian elimination with partial pivoting; a pivot below 1e-9 of the largest diagonal
  // entry (the lateral coordinates are at most 1) means a singular fit.
  double largest = 0.0;
  for (int r = 0; r < terms; ++r)
  {
    largest = std::max(largest, normalMatrix[r][r]);
  }
  for (int col = 0; col < terms; ++col)
  {
    int pivot = col;
    for (int r = col + 1; r < terms; ++r)
    {
      if (std::fabs(normalMatrix[r][col]) > std::fabs(normalMatrix[pivot][col]))
      {
        pivot = r;
      }
    }
    if (!(std::fabs(normalMatrix[pivot][col]) > 1e-9 * largest))
    {
      return -1.0;
    }
    std::swap(normalMatrix[pivot], normalMatrix[col]);
    std::swap(rightSide[pivot], rightSide[col]);
    for (int r = col + 1; r < terms; ++r)
    {
      const double factor = normalMatrix[r][col] / normalMatrix[col][col];
      for (int k = col; k < terms; ++k)
      {
        normalMatrix[r][k] -= factor * normalMatrix[col][k];
      }
      rightSide[r] -= factor * rightSide[col];
    }
  }
  for (int r = terms - 1; r >= 0; --r)
  {
    for (int k = r + 1; k < terms; ++k)
    {
      rightSide[r] -= normalMatrix[r][k] * rightSide[k];
    }
    rightSide[r] /= normalMatrix[r][r];
  }
  double fitted = 0.0; // beta . (X^T h)
  for (int r = 0; r < terms; ++r)
  {
    fitted += rightSide[r] * projected[r];
  }
  const double noise = std::sqrt(std::max(0.0, heights2 - fitted) / (m - terms));
  return std::isfinite(noise) ? noise : -1.0;
}

namespace
{
// The least-squares plane of the point `i` and its first `count` neighbours in `row`: the unit
// normal, the offset from the point to the centroid and the eigenvalues of the covariance
// (decreasing). Returns false when there is no plane (fewer than 3 points, or all on a line).
bool LocalPlane(const double* xyz, Id i, const int32_t* table, int count, const double* normals,
  double minimumNormalDot, double normal[3], double centroidOffset[3], double values[3])
{
  const double* p = &xyz[3 * static_cast<size_t>(i)];
  // The neighbours of the same sheet (with `normals`: those within the bound of the point's).
  std::array<int32_t, MaximumPlaneNeighbors> kept;
  count = std::min<int>(count, MaximumPlaneNeighbors);
  const int32_t* row = table;
  if (normals)
  {
    const double* own = &normals[3 * static_cast<size_t>(i)];
    int m = 0;
    for (int j = 0; j < count; ++j)
    {
      if (table[j] >= 0 &&
        Dot(&normals[3 * static_cast<size_t>(table[j])], own) >= minimumNormalDot)
      {
        kept[m++] = table[j];
      }
    }
    row = kept.data();
    count = m;
  }
  double covariance[3][3];
  if (!(OffsetCovariance(xyz, p, row, count, true, covariance, centroidOffset) >= 3.0))
  {
    return false;
  }
  SmallestEigenvector(covariance, values, normal);
  return values[1] > 0.0 && std::isfinite(normal[0]) && std::isfinite(normal[1]) &&
    std::isfinite(normal[2]);
}

// SamplingNoise on the points sample(0), ..., sample(samples - 1).
template <typename Sample>
SamplingNoiseMeasure MeasureNoise(const double* xyz, Id n, const std::vector<int32_t>& neighbors,
  int k, int planeOthers, Id samples, const Sample& sample, const double* normals,
  double minimumNormalDot)
{
  SamplingNoiseMeasure measure;
  const int count = std::min(k, planeOthers);
  if (n <= 0 || count <= 0 || samples <= 0)
  {
    return measure;
  }
  std::vector<double> noise(static_cast<size_t>(samples), -1.0);
  std::vector<double> plane(static_cast<size_t>(samples), -1.0);
  std::vector<double> spacing(static_cast<size_t>(samples), -1.0);
  vtkSMPTools::For(0, samples,
    [&](Id begin, Id end)
    {
      for (Id s = begin; s < end; ++s)
      {
        const Id i = sample(s);
        const double* p = &xyz[3 * static_cast<size_t>(i)];
        const int32_t* row = neighbors.data() + static_cast<size_t>(i) * k;
        double normal[3], offset[3], values[3];
        if (!LocalPlane(xyz, i, row, count, normals, minimumNormalDot, normal, offset, values))
        {
          continue;
        }
        plane[s] = std::sqrt(std::max(0.0, values[2]));
        // Without `normals` every neighbour is fitted, over the point's own plane.
        noise[s] = QuadricHeightNoise(xyz, normals, p,
          normals ? &normals[3 * static_cast<size_t>(i)] : normal, row, count, minimumNormalDot);
        double sum = 0.0;
        int m = 0;
        for (int j = 0; j < count; ++j)
        {
          if (row[j] >= 0)
          {
            const double* q = &xyz[3 * static_cast<size_t>(row[j])];
            const double d[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
            sum += std::sqrt(Dot(d, d));
            ++m;
          }
        }
        spacing[s] = m > 0 && std::isfinite(sum) ? sum / m : -1.0;
      }
    });
  std::vector<double> noiseValues, planeValues, spacingValues;
  for (Id s = 0; s < samples; ++s)
  {
    if (noise[s] >= 0.0 && spacing[s] > 0.0)
    {
      noiseValues.push_back(noise[s]);
      planeValues.push_back(plane[s]);
      spacingValues.push_back(spacing[s]);
    }
  }
  measure.Measured = static_cast<int64_t>(noiseValues.size());
  const double medianNoise = Median(std::move(noiseValues));
  const double medianPlane = Median(std::move(planeValues));
  const double medianSpacing = Median(std::move(spacingValues));
  measure.Level = medianSpacing > 0.0 ? medianNoise / medianSpacing : 0.0;
  measure.Share = medianPlane > 0.0 ? medianNoise / medianPlane : 0.0;
  measure.Noisy = measure.Level > NoisyLevel && measure.Share > NoisyShare;
  return measure;
}
} // namespace

SamplingNoiseMeasure SamplingNoise(const double* xyz, Id n, const std::vector<int32_t>& neighbors,
  int k, int planeOthers, int stride, const double* normals, double minimumNormalDot)
{
  stride = std::max(1, stride);
  return MeasureNoise(xyz, n, neighbors, k, planeOthers, n > 0 ? (n + stride - 1) / stride : 0,
    [stride](Id s) { return s * stride; }, normals, minimumNormalDot);
}

SamplingNoiseMeasure MeasureSamplingNoise(const double* xyz, Id n,
  const std::vector<int32_t>& neighbors, int k, int planeOthers, const double* normals,
  double minimumNormalDot)
{
  if (n > 2 * SamplingNoisePilotSamples)
  {
    // A fixed pseudo-random sample (not a stride: a stride can fall in step with the rows of a
    // regular sampling), from a linear congruential generator (Knuth's MMIX constants).
    std::vector<Id> pilot(SamplingNoisePilotSamples);
    uint64_t state = 0x9E3779B97F4A7C15ull;
    for (Id& i : pilot)
    {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      i = static_cast<Id>((state >> 33) % static_cast<uint64_t>(n));
    }
    const SamplingNoiseMeasure measure = MeasureNoise(xyz, n, neighbors, k, planeOthers,
      SamplingNoisePilotSamples, [&pilot](Id s) { return pilot[s]; }, normals, minimumNormalDot);
    if (measure.Level < NoisyLevel / SamplingNoisePilotMargin ||
      measure.Share < NoisyShare / SamplingNoisePilotMargin)
    {
      return measure;
    }
  }
  return SamplingNoise(xyz, n, neighbors, k, planeOthers, std::max<Id>(1, n / SamplingNoiseSamples),
    normals, minimumNormalDot);
}

void ProjectOntoLocalPlanes(const double* xyz, Id n, const std::vector<int32_t>& neighbors, int k,
  int planeOthers, std::vector<double>& projected, const double* normals, double minimumNormalDot)
{
  projected.assign(xyz, xyz + 3 * static_cast<size_t>(std::max<Id>(n, 0)));
  const int count = std::min(k, planeOthers);
  if (n <= 0 || count <= 0)
  {
    return;
  }
  vtkSMPTools::For(0, n,
    [&](Id begin, Id end)
    {
      for (Id i = begin; i < end; ++i)
      {
        double normal[3], offset[3], values[3];
        if (LocalPlane(xyz, i, neighbors.data() + static_cast<size_t>(i) * k, count, normals,
              minimumNormalDot, normal, offset, values))
        {
          // p - ((p - c) . n) n with c = p + offset.
          const double height = Dot(offset, normal);
          double* x = &projected[3 * static_cast<size_t>(i)];
          for (int c = 0; c < 3; ++c)
          {
            x[c] += height * normal[c];
          }
        }
      }
    });
  // Distinct points stay distinct: points whose projections coincide exactly (two points on
  // one normal line with the same plane, e.g. the two sides of a plate thinner than the
  // neighbourhood) keep their own coordinates, until no two distinct input points share a
  // projected position (each pass restores at least one point, so this ends). Copies of one
  // input position may share one.
  std::vector<int32_t> first;
  for (bool restored = true; restored;)
  {
    restored = false;
    if (FindExactDuplicates(projected.data(), 3, nullptr, n, first) == n)
    {
      break;
    }
    for (Id j = 0; j < n; ++j)
    {
      const Id r = first[j];
      if (r != j &&
        !SamePosition(&xyz[3 * static_cast<size_t>(j)], &xyz[3 * static_cast<size_t>(r)], 3))
      {
        for (const Id t : { j, r })
        {
          std::copy_n(&xyz[3 * static_cast<size_t>(t)], 3, &projected[3 * static_cast<size_t>(t)]);
        }
        restored = true;
      }
    }
  }
}

void EstimatePlaneNormals(const double* pts,
  Id count,
  const std::vector<int32_t>& table,
  int others,
  std::vector<double>& normals,
  std::vector<double>& variation)
{
  normals.assign(3 * static_cast<size_t>(count), 0.0);
  variation.assign(static_cast<size_t>(count), 1.0);
  vtkSMPTools::For(0,
    count,
    [&](Id begin, Id end)
    {
      for (Id i = begin; i < end; ++i)
      {
        const double* p = &pts[3 * static_cast<size_t>(i)];
        const int32_t* row = table.data() + static_cast<size_t>(i) * others;
        double covariance[3][3];
        OffsetCovariance(pts, p, row, others, true, covariance);
        double values[3];
        SmallestEigenvector(covariance, values, &normals[3 * static_cast<size_t>(i)]);
        const double sum = values[0] + values[1] + values[2];
        variation[i] = sum > 0.0 ? std::min(1.0, std::max(0.0, 3.0 * values[2] / sum)) : 1.0;
      }
    });
}

namespace
{
// A spanning forest in compressed rows: the tree neighbours of point i are
// Adjacent[Start[i], Start[i + 1]), each with the key of its edge's cost.
struct SpanningForest
{
  std::vector<int64_t> Start;
  std::vector<KeyedId> Adjacent; // (cost key, other end)
};

// The minimum spanning forest of OrientNormals' graph (Kruskal). The edges, a pair of mutual
// neighbours once (from the row of the smaller id), are keyed by the bits of their float cost,
// mapped so that the keys sort as the floats do, and radix-sorted (11-bit digits: about 10 edges
// per point); ties keep the order of the rows. An edge whose cost is not finite (NaN normals) is
// left out: Prim's propagation never takes it either.
SpanningForest MinimumSpanningForest(const double* pts,
  Id count,
  const std::vector<int32_t>& table,
  int others,
  const std::vector<double>& variation,
  const std::vector<double>& normals)
{
  auto holds = [&](Id w, Id i)
  {
    const int32_t* row = &table[static_cast<size_t>(w) * others];
    return std::find(row, row + others, i) != row + others;
  };
  std::vector<std::pair<Id, Id>> ends;
  std::vector<KeyedId> keyed;
  ends.reserve(static_cast<size_t>(count) * others);
  keyed.reserve(static_cast<size_t>(count) * others);
  for (Id i = 0; i < count; ++i)
  {
    const double* p = &pts[3 * static_cast<size_t>(i)];
    const double* n = &normals[3 * static_cast<size_t>(i)];
    for (int j = 0; j < others; ++j)
    {
      const Id w = table[static_cast<size_t>(i) * others + j];
      if (w < 0 || w == i || (w < i && holds(w, i)))
      {
        continue;
      }
      const double agreement = ReflectedAgreement(
        p, n, &pts[3 * static_cast<size_t>(w)], &normals[3 * static_cast<size_t>(w)]);
      const float cost =
        static_cast<float>(1.0 - std::fabs(agreement) + variation[i] + variation[w]);
      if (!(cost < std::numeric_limits<float>::infinity()))
      {
        continue;
      }
      uint32_t bits;
      std::memcpy(&bits, &cost, sizeof bits);
      bits = (bits & 0x80000000u) ? ~bits : (bits | 0x80000000u);
      keyed.emplace_back(bits, static_cast<int32_t>(ends.size()));
      ends.emplace_back(i, w);
    }
  }
  std::vector<KeyedId> scratch;
  SortKeys(keyed.begin(), keyed.end(), 32, scratch, 11);
  // Each edge that joins two trees is kept (union-find).
  DisjointSets<Id> trees(count);
  SpanningForest forest;
  forest.Start.assign(static_cast<size_t>(count) + 1, 0);
  std::vector<KeyedId> tree;
  for (const KeyedId& edge : keyed)
  {
    const std::pair<Id, Id>& e = ends[edge.second];
    if (trees.Union(e.first, e.second))
    {
      tree.push_back(edge);
      ++forest.Start[e.first + 1];
      ++forest.Start[e.second + 1];
      if (static_cast<Id>(tree.size()) == count - 1)
      {
        break;
      }
    }
  }
  std::partial_sum(forest.Start.begin(), forest.Start.end(), forest.Start.begin());
  forest.Adjacent.resize(static_cast<size_t>(forest.Start[count]));
  std::vector<int64_t> fill(forest.Start.begin(), forest.Start.end() - 1);
  for (const KeyedId& edge : tree)
  {
    const std::pair<Id, Id>& e = ends[edge.second];
    forest.Adjacent[fill[e.first]++] = { edge.first, e.second };
    forest.Adjacent[fill[e.second]++] = { edge.first, e.first };
  }
  return forest;
}

// The extreme points of each tree along -x, +x, -y, +y, -z, +z (`part`: the tree of each point,
// its smallest id), for OrientNormals' vote. Among points of equal coordinate the first reached
// by Prim's propagation from the tree's smallest id counts (the order of the propagation before
// it was made on Kruskal's tree, whose Prim order is the same: a minimum spanning tree holds the
// cheapest edge out of every subtree); that order is found only for the trees that have such
// ties (flat scans, quantized coordinates).
std::vector<std::array<Id, 6>> ExtremePoints(const double* pts,
  Id count,
  const SpanningForest& forest,
  const std::vector<Id>& part)
{
  auto point = [&](Id k) { return &pts[3 * static_cast<size_t>(k)]; };
  std::vector<std::array<Id, 6>> extremes(static_cast<size_t>(count));
  std::vector<uint8_t> tied(static_cast<size_t>(count), 0);
  for (Id k = 0; k < count; ++k)
  {
    std::array<Id, 6>& extreme = extremes[part[k]];
    if (part[k] == k)
    {
      extreme.fill(k);
      continue;
    }
    for (int axis = 0; axis < 3; ++axis)
    {
      Id& low = extreme[2 * axis];
      Id& high = extreme[2 * axis + 1];
      const double x = point(k)[axis];
      tied[part[k]] |= (x == point(low)[axis] || x == point(high)[axis]) ? 1 : 0;
      low = x < point(low)[axis] ? k : low;
      high = x > point(high)[axis] ? k : high;
    }
  }
  if (std::find(tied.begin(), tied.end(), 1) == tied.end())
  {
    return extremes;
  }
  std::vector<Id> rank(static_cast<size_t>(count), 0); // Prim order in the tied trees
  std::priority_queue<KeyedId, std::vector<KeyedId>, std::greater<KeyedId>> steps;
  for (Id seed = 0; seed < count; ++seed)
  {
    if (!tied[seed])
    {
      continue;
    }
    Id reached = 0;
    steps.push({ 0, seed });
    while (!steps.empty())
    {
      const Id from = steps.top().second;
      steps.pop();
      rank[from] = reached++;
      for (int64_t a = forest.Start[from]; a < forest.Start[from + 1]; ++a)
      {
        const Id to = forest.Adjacent[a].second;
        if (to != seed && rank[to] == 0)
        {
          steps.push(forest.Adjacent[a]);
        }
      }
    }
  }
  for (Id k = 0; k < count; ++k)
  {
    if (!tied[part[k]])
    {
      continue;
    }
    std::array<Id, 6>& extreme = extremes[part[k]];
    for (int axis = 0; axis < 3; ++axis)
    {
      Id& low = extreme[2 * axis];
      Id& high = extreme[2 * axis + 1];
      const double x = point(k)[axis];
      low = x < point(low)[axis] || (x == point(low)[axis] && rank[k] < rank[low]) ? k : low;
      high = x > point(high)[axis] || (x == point(high)[axis] && rank[k] < rank[high]) ? k : high;
    }
  }
  return extremes;
}
}

bool OrientNormals(const double* pts,
  Id count,
  const std::vector<int32_t>& table,
  int others,
  const std::vector<double>& variation,
  std::vector<double>& normals,
  const std::function<bool(double)>& progress)
{
  auto point = [&](Id k) { return &pts[3 * static_cast<size_t>(k)]; };
  auto normal = [&](Id k) { return &normals[3 * static_cast<size_t>(k)]; };
  auto flip = [&](Id k)
  {
    double* n = normal(k);
    n[0] = -n[0];
    n[1] = -n[1];
    n[2] = -n[2];
  };
  const SpanningForest forest =
    MinimumSpanningForest(pts, count, table, others, variation, normals);
  // The propagation from the smallest id of each tree, breadth first: a point takes the side
  // that agrees with its parent's normal (final when it is reached).
  std::vector<Id> part(static_cast<size_t>(count), -1); // tree of each point: its smallest id
  std::vector<Id> queue;
  queue.reserve(static_cast<size_t>(count));
  Id done = 0;
  for (Id seed = 0; seed < count; ++seed)
  {
    if (part[seed] >= 0)
    {
      continue;
    }
    part[seed] = seed;
    queue.assign(1, seed);
    for (size_t head = 0; head < queue.size(); ++head)
    {
      const Id from = queue[head];
      for (int64_t a = forest.Start[from]; a < forest.Start[from + 1]; ++a)
      {
        const Id to = forest.Adjacent[a].second;
        if (part[to] >= 0)
        {
          continue;
        }
        part[to] = seed;
        if (ReflectedAgreement(point(from), normal(from), point(to), normal(to)) < 0.0)
        {
          flip(to);
        }
        queue.push_back(to);
        if ((++done & 0xffff) == 0 && progress && !progress(static_cast<double>(done) / count))
        {
          return false;
        }
      }
    }
  }
  // Each tree turned outwards by a vote of its extreme points: flipped when the sum of n . d at
  // the extreme points along d = +-x, +-y, +-z is negative.
  const std::vector<std::array<Id, 6>> extremes = ExtremePoints(pts, count, forest, part);
  std::vector<uint8_t> turned(static_cast<size_t>(count), 0);
  for (Id k = 0; k < count; ++k)
  {
    if (part[k] == k)
    {
      const std::array<Id, 6>& extreme = extremes[k];
      double vote = 0.0;
      for (int axis = 0; axis < 3; ++axis)
      {
        vote += normal(extreme[2 * axis + 1])[axis] - normal(extreme[2 * axis])[axis];
      }
      turned[k] = vote < 0.0 ? 1 : 0;
    }
  }
  for (Id k = 0; k < count; ++k)
  {
    if (turned[part[k]])
    {
      flip(k);
    }
  }
  return true;
}

bool EstimateNormals(PointBins& bins,
  const double* xyz,
  int32_t n,
  int sampleSize,
  bool orient,
  std::vector<double>& normals,
  std::vector<double>& variation,
  std::vector<int32_t>& neighbors,
  int& k,
  const std::function<bool(double)>& progress,
  std::vector<double>* stretch,
  double scanLineShare,
  double scanLineRadiusFactor,
  double rowLinearity,
  double rowRadiusFactor,
  double rowShare,
  bool neighborsGiven)
{
  normals.assign(3 * static_cast<size_t>(std::max(n, 0)), 0.0);
  variation.assign(static_cast<size_t>(std::max(n, 0)), 1.0);
  k = 0;
  const int others = std::max(0, std::min<int>(sampleSize, n) - 1);
  // Progress: the search 0-80 %, the scan lines 80-85 %, the rows 85-90 %, the orientation the
  // rest.
  auto progressIn = [&progress](double from, double to)
  {
    return [&progress, from, to](double fraction)
    { return !progress || progress(from + (to - from) * fraction); };
  };
  const bool given =
    neighborsGiven && neighbors.size() == static_cast<size_t>(std::max(n, 0)) * others;
  if (!given && !FindNearestNeighbors(bins, xyz, n, others, neighbors, progressIn(0.0, 0.8)))
  {
    return false;
  }
  k = others;
  if (stretch)
  {
    const int32_t changed = AddOffLineNeighbors(bins,
      xyz,
      n,
      others,
      neighbors,
      stretch,
      0.05,
      scanLineRadiusFactor,
      scanLineShare,
      progressIn(0.8, 0.85));
    if (changed < 0)
    {
      return false;
    }
    if (changed == 0)
    {
      stretch->clear();
    }
  }
  // The planes' neighbourhoods: the table, or a copy in which the points whose nearest lie along
  // one curve have neighbours off it too (the table itself stays the caller's).
  std::vector<int32_t> rowTable;
  if (rowLinearity > 0.0)
  {
    rowTable = neighbors;
    if (AddOffLineNeighbors(bins,
          xyz,
          n,
          others,
          rowTable,
          nullptr,
          rowLinearity,
          rowRadiusFactor,
          rowShare,
          progressIn(0.85, 0.9)) < 0)
    {
      return false;
    }
  }
  EstimatePlaneNormals(
    xyz, n, rowLinearity > 0.0 ? rowTable : neighbors, others, normals, variation);
  if (progress && !progress(0.9))
  {
    return false;
  }
  if (orient &&
    !OrientNormals(xyz,
      n,
      neighbors,
      others,
      variation,
      normals,
      [&](double fraction) { return !progress || progress(0.9 + 0.1 * fraction); }))
  {
    return false;
  }
  return !progress || progress(1.0);
}
}
