#include "pcsNormalEstimation.h"

#include "pcsNearestNeighbors.h"

#include "vtkMath.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

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
  bool withPoint, double covariance[3][3])
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
  }
  return s0;
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
      !(vtkMath::Dot(normals + 3 * static_cast<size_t>(row[j]), normal) >= minimumNormalDot))
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

// The covariance of a neighbourhood and the point (OffsetCovariance).
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

bool OrientNormals(const double* pts,
  Id count,
  const std::vector<int32_t>& table,
  int others,
  const std::vector<double>& variation,
  std::vector<double>& normals,
  const std::function<bool(double)>& progress)
{
  // The symmetric graph, compressed rows.
  std::vector<int64_t> start(static_cast<size_t>(count) + 1, 0);
  for (Id i = 0; i < count; ++i)
  {
    for (int j = 0; j < others; ++j)
    {
      const int32_t w = table[static_cast<size_t>(i) * others + j];
      if (w >= 0)
      {
        ++start[i + 1];
        ++start[w + 1];
      }
    }
  }
  for (Id i = 0; i < count; ++i)
  {
    start[i + 1] += start[i];
  }
  std::vector<Id> adjacent(static_cast<size_t>(start[count]));
  {
    std::vector<int64_t> fill(start.begin(), start.end() - 1);
    for (Id i = 0; i < count; ++i)
    {
      for (int j = 0; j < others; ++j)
      {
        const int32_t w = table[static_cast<size_t>(i) * others + j];
        if (w >= 0)
        {
          adjacent[fill[i]++] = w;
          adjacent[fill[w]++] = i;
        }
      }
    }
  }
  // A pair of mutual neighbours is one edge: each row sorted, its repeats left out (end[i]).
  std::vector<int64_t> end(static_cast<size_t>(count));
  vtkSMPTools::For(0,
    count,
    [&](Id begin, Id last)
    {
      for (Id i = begin; i < last; ++i)
      {
        auto first = adjacent.begin() + start[i];
        std::sort(first, adjacent.begin() + start[i + 1]);
        end[i] = std::unique(first, adjacent.begin() + start[i + 1]) - adjacent.begin();
      }
    });
  struct Step
  {
    float Cost;
    Id From;
    Id To;
    bool operator>(const Step& other) const { return this->Cost > other.Cost; }
  };
  std::priority_queue<Step, std::vector<Step>, std::greater<Step>> steps;
  std::vector<uint8_t> reached(static_cast<size_t>(count), 0);
  auto point = [&](Id k) { return &pts[3 * static_cast<size_t>(k)]; };
  auto normal = [&](Id k) { return &normals[3 * static_cast<size_t>(k)]; };
  auto flip = [&](Id k)
  {
    double* n = normal(k);
    n[0] = -n[0];
    n[1] = -n[1];
    n[2] = -n[2];
  };
  // The cheapest step found so far to each point not reached (Prim's key: a step is only queued
  // when it is cheaper than the point's queued ones).
  std::vector<float> cheapest(static_cast<size_t>(count), std::numeric_limits<float>::infinity());
  auto leave = [&](Id i)
  {
    for (int64_t a = start[i]; a < end[i]; ++a)
    {
      const Id w = adjacent[a];
      if (!reached[w])
      {
        const double agreement = ReflectedAgreement(point(i), normal(i), point(w), normal(w));
        const float cost =
          static_cast<float>(1.0 - std::fabs(agreement) + variation[i] + variation[w]);
        if (cost < cheapest[w])
        {
          cheapest[w] = cost;
          steps.push({ cost, i, w });
        }
      }
    }
  };
  std::vector<Id> part; // the points of the connected part being oriented
  Id done = 0;
  for (Id seed = 0; seed < count; ++seed)
  {
    if (reached[seed])
    {
      continue;
    }
    reached[seed] = 1;
    part.assign(1, seed);
    leave(seed);
    while (!steps.empty())
    {
      const Step step = steps.top();
      steps.pop();
      if (reached[step.To])
      {
        continue;
      }
      reached[step.To] = 1;
      part.push_back(step.To);
      if (ReflectedAgreement(point(step.From), normal(step.From), point(step.To), normal(step.To)) <
        0.0)
      {
        flip(step.To);
      }
      leave(step.To);
      if ((++done & 0xffff) == 0 && progress && !progress(static_cast<double>(done) / count))
      {
        return false;
      }
    }
    double vote = 0.0;
    for (int axis = 0; axis < 3; ++axis)
    {
      Id low = part[0], high = part[0];
      for (Id k : part)
      {
        low = point(k)[axis] < point(low)[axis] ? k : low;
        high = point(k)[axis] > point(high)[axis] ? k : high;
      }
      vote += normal(high)[axis] - normal(low)[axis];
    }
    if (vote < 0.0)
    {
      for (Id k : part)
      {
        flip(k);
      }
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
  double rowShare)
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
  if (!FindNearestNeighbors(bins, xyz, n, others, neighbors, progressIn(0.0, 0.8)))
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
