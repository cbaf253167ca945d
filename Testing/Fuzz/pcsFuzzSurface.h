// Shared by the fuzz targets of the surface reconstruction filters (pcsFuzzPerimeterPeel.cxx,
// pcsFuzzLocalOptimumGrowth.cxx, pcsFuzzCDTAdvancingFront.cxx, pcsFuzzGreedy.cxx): fuzzer bytes
// -> a small, often degenerate point cloud, and the output invariants every filter documents.
//
// Input layout (missing bytes read as 0):
//   byte 0  flags: bits 0-1 normals (0 none, 1 radial from the centroid, 2 from the bytes, may
//           be zero; 3 radial with zero-length and NaN normals mixed in), bit 2 float
//           coordinates, bit 3 NaN/Inf coordinates mixed in, bit 4 exact duplicates mixed in,
//           bit 5 a 10^6 offset on every coordinate, bit 6 a vtkUnstructuredGrid of vertices
//           instead of a vtkPolyData, bit 7 coordinates scaled by 2^40 or 2^-40 (byte 1 parity)
//   byte 1  stride of the NaN / duplicate / bad-normal injections
//   bytes 2-5  filter parameters (each target maps them onto its parameters' ranges, limits
//           included)
//   byte 6  shape: % 10 in 0..5 the families of pcsFuzzInput.h (from byte 6 on: integer grids,
//           near-duplicates, UTM-like offsets, coplanar sets, raw doubles); 6 a sphere, 7 a
//           torus, 8 a height field, 9 two parallel sheets closer than their spacing. The
//           surfaces take byte 7 as the number of points (4..259) and 2 bytes per point
//           (quantized parameters: exact duplicates at the poles, collinear grid rows...).
//
// Invariants checked on every output (a violation prints the filter and the invariant and
// aborts, which libFuzzer reports as a crash):
// - a vtkPolyData with every input point, unchanged, and the input point data passed through;
// - only triangles, with 3 distinct point ids in range, none on a point with a non-finite
//   coordinate; no two points with identical coordinates both used (exact duplicates are meshed
//   once);
// - point data `Used` (unsigned char, one per point) is 1 exactly for the triangle vertices;
//   field data `NumberOfTriangles` is the number of triangles;
// - when the filter promises it (PromisesManifold), vtkReconstructionQuality finds no
//   non-manifold edge or vertex, no duplicate triangle and a consistent orientation (1).
// Environment PCS_FUZZ_DUMP=1 prints the cloud and the triangles (for minimized inputs).
#ifndef pcsFuzzSurface_h
#define pcsFuzzSurface_h

#include "pcsFuzzInput.h"
#include "vtkReconstructionQuality.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace pcsfuzz
{
struct SurfaceInput
{
  vtkSmartPointer<vtkPointSet> Data; // what the filter gets
  std::vector<double> XYZ;           // the coordinates as stored (after a float conversion)
  vtkIdType N = 0;
  uint8_t Parameters[4] = { 0, 0, 0, 0 };
  bool HasNormals = false;
};

inline void Quiet()
{
  static bool quiet = []
  {
    vtkObject::GlobalWarningDisplayOff();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    return true;
  }();
  (void)quiet;
}

[[noreturn]] inline void Fail(const char* filter, const std::string& what)
{
  std::fprintf(stderr, "%s fuzz target: invariant violated: %s\n", filter, what.c_str());
  std::abort();
}

/// Points on a surface from 2 bytes per point (the families 6..9 of the layout above).
inline std::vector<double> SurfaceCloud(const uint8_t* data, size_t size, int family)
{
  ByteReader in(data, size);
  const int n = 4 + in.Byte();
  std::vector<double> xyz;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n && !in.Empty(); ++i)
  {
    const int u = in.Byte();
    const int v = in.Byte();
    double p[3] = { 0, 0, 0 };
    switch (family)
    {
      case 6: // unit sphere: longitude from u, height from v (both poles reached exactly)
      {
        const double z = v / 127.5 - 1.0;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        p[0] = r * std::cos(2 * pi * u / 256.0);
        p[1] = r * std::sin(2 * pi * u / 256.0);
        p[2] = z;
        break;
      }
      case 7: // torus, radii 2 and 0.7
      {
        const double a = 2 * pi * u / 256.0;
        const double b = 2 * pi * v / 256.0;
        p[0] = (2.0 + 0.7 * std::cos(b)) * std::cos(a);
        p[1] = (2.0 + 0.7 * std::cos(b)) * std::sin(a);
        p[2] = 0.7 * std::sin(b);
        break;
      }
      case 8: // height field on a 16 x 16 lattice (collinear rows, cocircular squares)
      {
        p[0] = (u % 16) / 16.0;
        p[1] = (v % 16) / 16.0;
        p[2] = 0.25 * (p[0] - 0.5) * (p[0] - 0.5) - 0.125 * p[1] * p[1] + ((u / 16) % 3) / 256.0;
        break;
      }
      default: // two parallel sheets 1/64 apart, their lattice spacing 1/16
        p[0] = (u % 32) / 16.0;
        p[1] = (v % 32) / 16.0;
        p[2] = ((u / 32 + v) % 2) / 64.0;
        break;
    }
    xyz.insert(xyz.end(), { p[0], p[1], p[2] });
  }
  return xyz;
}

inline SurfaceInput MakeSurfaceInput(const uint8_t* data, size_t size)
{
  SurfaceInput input;
  auto at = [&](size_t k) -> uint8_t { return k < size ? data[k] : 0; };
  const uint8_t flags = at(0);
  const int stride = 2 + at(1) % 7;
  for (int k = 0; k < 4; ++k)
  {
    input.Parameters[k] = at(2 + k);
  }
  const int shape = at(6) % 10;
  std::vector<double> xyz;
  if (size > 6)
  {
    xyz = shape < 6 ? Cloud(data + 6, size - 6, 3) : SurfaceCloud(data + 7, size - 7, shape);
  }
  const vtkIdType n = static_cast<vtkIdType>(xyz.size() / 3);
  if (flags & 0x10) // exact duplicates of earlier points
  {
    for (vtkIdType i = 1; i < n; ++i)
    {
      if (i % stride == 0)
      {
        std::copy_n(&xyz[3 * (i / 2)], 3, &xyz[3 * i]);
      }
    }
  }
  if (flags & 0x20)
  {
    for (double& c : xyz)
    {
      c += 1e6;
    }
  }
  if (flags & 0x80)
  {
    for (double& c : xyz)
    {
      c = std::ldexp(c, (at(1) & 1) ? 40 : -40);
    }
  }
  if (flags & 0x08) // NaN, +Inf, -Inf on one coordinate of every stride-th point
  {
    const double bad[3] = { std::numeric_limits<double>::quiet_NaN(),
      std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() };
    for (vtkIdType i = 0; i < n; i += stride)
    {
      xyz[3 * i + (i % 3)] = bad[(i / stride) % 3];
    }
  }

  vtkNew<vtkPoints> points;
  points->SetDataType((flags & 0x04) ? VTK_FLOAT : VTK_DOUBLE);
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, &xyz[3 * i]);
    points->GetPoint(i, &xyz[3 * i]); // as stored
  }
  input.XYZ = xyz;
  input.N = n;

  vtkSmartPointer<vtkPointSet> set;
  if (flags & 0x40)
  {
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->SetPoints(points);
    grid->Allocate(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      grid->InsertNextCell(VTK_VERTEX, 1, &i);
    }
    set = grid;
  }
  else
  {
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    set = poly;
  }

  // A point data array that must pass through unchanged.
  vtkNew<vtkIntArray> pass;
  pass->SetName("PassThrough");
  pass->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    pass->SetValue(i, static_cast<int>(7 * i + 3));
  }
  set->GetPointData()->AddArray(pass);

  const int normals = flags & 3;
  if (normals != 0 && n > 0)
  {
    double centroid[3] = { 0, 0, 0 };
    vtkIdType finite = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double* p = &xyz[3 * i];
      if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))
      {
        for (int c = 0; c < 3; ++c)
        {
          centroid[c] += p[c];
        }
        ++finite;
      }
    }
    for (double& c : centroid)
    {
      c /= std::max<vtkIdType>(finite, 1);
    }
    vtkNew<vtkFloatArray> array;
    array->SetName("Normals");
    array->SetNumberOfComponents(3);
    array->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double v[3];
      for (int c = 0; c < 3; ++c)
      {
        v[c] = normals == 2 ? static_cast<int8_t>(at((3 * i + c) % std::max<size_t>(size, 1)))
                            : xyz[3 * i + c] - centroid[c];
      }
      if (normals == 3 && i % stride == 1)
      {
        v[0] = v[1] = v[2] = 0.0;
      }
      if (normals == 3 && i % stride == 2)
      {
        v[1] = std::numeric_limits<double>::quiet_NaN();
      }
      array->SetTuple(i, v);
    }
    set->GetPointData()->SetNormals(array);
    input.HasNormals = true;
  }
  input.Data = set;
  return input;
}

/// One-value field data array `name`, which must exist.
inline double Field(const char* filter, vtkPolyData* out, const char* name)
{
  vtkDataArray* array = out->GetFieldData()->GetArray(name);
  if (!array || array->GetNumberOfTuples() != 1)
  {
    Fail(filter, std::string("field data ") + name + " missing");
  }
  return array->GetTuple1(0);
}

/// Point data array `name` with one value per point, which must exist.
inline vtkDataArray* PointArray(const char* filter, vtkPolyData* out, const char* name)
{
  vtkDataArray* array = out->GetPointData()->GetArray(name);
  if (!array || array->GetNumberOfTuples() != out->GetNumberOfPoints() ||
    array->GetNumberOfComponents() != 1)
  {
    Fail(filter, std::string("point data ") + name + " missing or of the wrong size");
  }
  return array;
}

/// Cell data array `name` with one value per cell, which must exist.
inline vtkDataArray* CellArray(const char* filter, vtkPolyData* out, const char* name)
{
  vtkDataArray* array = out->GetCellData()->GetArray(name);
  if (!array || array->GetNumberOfTuples() != out->GetNumberOfCells())
  {
    Fail(filter, std::string("cell data ") + name + " missing or of the wrong size");
  }
  return array;
}

inline bool Finite(const double* p)
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

/// The invariants shared by every surface filter (see the top of the file). Returns the
/// quality measures of the output (vtkReconstructionQuality, distances off) for the
/// filter-specific checks.
inline vtkSmartPointer<vtkPolyData> CheckSurface(
  const char* filter, const SurfaceInput& input, vtkPolyData* out, bool promisesManifold)
{
  if (!out)
  {
    Fail(filter, "no output");
  }
  const vtkIdType n = input.N;
  if (std::getenv("PCS_FUZZ_DUMP")) // diagnostics: the cloud and the triangles, as text
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      std::fprintf(stderr, "p %lld %.17g %.17g %.17g\n", static_cast<long long>(i),
        input.XYZ[3 * i], input.XYZ[3 * i + 1], input.XYZ[3 * i + 2]);
    }
    for (vtkIdType t = 0; t < out->GetNumberOfPolys(); ++t)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      out->GetPolys()->GetCellAtId(t, npts, pts);
      std::fprintf(stderr, "t %lld:", static_cast<long long>(t));
      for (vtkIdType k = 0; k < npts; ++k)
      {
        std::fprintf(stderr, " %lld", static_cast<long long>(pts[k]));
      }
      std::fprintf(stderr, "\n");
    }
  }
  if (out->GetNumberOfPoints() != n)
  {
    Fail(filter, "the output does not have every input point");
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    for (int c = 0; c < 3; ++c)
    {
      const double q = input.XYZ[3 * i + c];
      if (!(p[c] == q || (std::isnan(p[c]) && std::isnan(q))))
      {
        Fail(filter, "an output point differs from the input point");
      }
    }
  }
  vtkDataArray* pass = out->GetPointData()->GetArray("PassThrough");
  if (n > 0 && (!pass || pass->GetNumberOfTuples() != n))
  {
    Fail(filter, "point data PassThrough not passed");
  }
  for (vtkIdType i = 0; pass && i < n; ++i)
  {
    if (pass->GetTuple1(i) != 7 * i + 3)
    {
      Fail(filter, "point data PassThrough changed");
    }
  }
  if (out->GetNumberOfVerts() + out->GetNumberOfLines() + out->GetNumberOfStrips() != 0)
  {
    Fail(filter, "cells other than triangles in the output");
  }

  // Triangles: ids in range, distinct, on finite points; the vertices.
  const vtkIdType triangles = out->GetNumberOfPolys();
  std::vector<unsigned char> vertex(static_cast<size_t>(n), 0);
  vtkCellArray* polys = out->GetPolys();
  for (vtkIdType t = 0; t < triangles; ++t)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    polys->GetCellAtId(t, npts, pts);
    if (npts != 3)
    {
      Fail(filter, "a polygon that is not a triangle");
    }
    for (int k = 0; k < 3; ++k)
    {
      if (pts[k] < 0 || pts[k] >= n)
      {
        Fail(filter, "a point id out of range");
      }
      if (!Finite(&input.XYZ[3 * pts[k]]))
      {
        Fail(filter, "a triangle on a point with a non-finite coordinate");
      }
      vertex[pts[k]] = 1;
    }
    if (pts[0] == pts[1] || pts[1] == pts[2] || pts[0] == pts[2])
    {
      Fail(filter, "a triangle with a repeated point id");
    }
  }

  // Used = the triangle vertices; counts.
  vtkDataArray* used = PointArray(filter, out, "Used");
  if (used->GetDataType() != VTK_UNSIGNED_CHAR)
  {
    Fail(filter, "point data Used is not unsigned char");
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (used->GetTuple1(i) != vertex[i])
    {
      Fail(filter, "point data Used differs from the triangle vertices");
    }
  }
  if (Field(filter, out, "NumberOfTriangles") != triangles)
  {
    Fail(filter, "field data NumberOfTriangles differs from the triangles");
  }

  // Exact duplicates: at most one point of each group of identical coordinates is used.
  std::vector<std::array<double, 3>> usedPoints;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (vertex[i])
    {
      usedPoints.push_back({ input.XYZ[3 * i], input.XYZ[3 * i + 1], input.XYZ[3 * i + 2] });
    }
  }
  std::sort(usedPoints.begin(), usedPoints.end());
  if (std::adjacent_find(usedPoints.begin(), usedPoints.end()) != usedPoints.end())
  {
    Fail(filter, "two used points with identical coordinates");
  }

  vtkNew<vtkReconstructionQuality> quality;
  quality->SetInputData(out);
  quality->ComputeDistancesOff();
  quality->Update();
  auto measures = vtkSmartPointer<vtkPolyData>::New();
  measures->ShallowCopy(quality->GetOutput());
  if (promisesManifold && triangles > 0)
  {
    if (Field(filter, measures, "NumberOfNonManifoldEdges") != 0)
    {
      Fail(filter, "a non-manifold edge");
    }
    if (Field(filter, measures, "NumberOfNonManifoldVertices") != 0)
    {
      Fail(filter, "a non-manifold vertex");
    }
    if (Field(filter, measures, "NumberOfDuplicateTriangles") != 0)
    {
      Fail(filter, "a duplicate triangle");
    }
    if (Field(filter, measures, "OrientationConsistency") != 1.0)
    {
      Fail(filter, "inconsistently oriented triangles");
    }
  }
  return measures;
}
} // namespace pcsfuzz

#endif
