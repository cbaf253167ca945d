// Power-of-two scaling of coordinates into the range the exact predicates accept (private
// kernel, shared by the filters that triangulate).
#ifndef pcsCoordinateScaling_h
#define pcsCoordinateScaling_h

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pcs
{
/// The exact predicates assume that their products neither overflow nor underflow (degree 5 for
/// insphere). Coordinates far from 1 in magnitude are therefore scaled by a power of two, which
/// is exact, before triangulation: returns the exponent k (coordinates times 2^k), 0 when the
/// largest magnitude (of the coordinates, or of the referenced points) is already within
/// [2^-60, 2^60] (or is not finite).
inline int PredicateSafeExponent(double largest)
{
  if (largest == 0.0 || !std::isfinite(largest) ||
    (largest <= std::ldexp(1.0, 60) && largest >= std::ldexp(1.0, -60)))
  {
    return 0;
  }
  int exponent;
  std::frexp(largest, &exponent);
  return -exponent; // largest * 2^-exponent is in [0.5, 1)
}

/// The same for the points ids[0, count) of `coords` (dim values per point).
inline int PredicateSafeExponent(const double* coords, int dim, const int32_t* ids, size_t count)
{
  double largest = 0.0;
  for (size_t k = 0; k < count; ++k)
  {
    for (int i = 0; i < dim; ++i)
    {
      largest = std::max(largest, std::fabs(coords[dim * static_cast<int64_t>(ids[k]) + i]));
    }
  }
  return PredicateSafeExponent(largest);
}

/// The same for the points `ids` of `coords` (dim values per point).
inline int PredicateSafeExponent(const double* coords, int dim, const std::vector<int32_t>& ids)
{
  return PredicateSafeExponent(coords, dim, ids.data(), ids.size());
}

/// The largest magnitude among the finite values of coords[0, count) and `largest` (0 when there
/// are none): the argument of PredicateSafeExponent for data that may hold NaN or infinite
/// coordinates (they are left out), accumulated over several arrays through `largest`.
inline double LargestFiniteMagnitude(const double* coords, size_t count, double largest = 0.0)
{
  for (size_t i = 0; i < count; ++i)
  {
    largest = std::isfinite(coords[i]) ? std::max(largest, std::fabs(coords[i])) : largest;
  }
  return largest;
}

/// coords[0, count) times 2^exponent, in place (exact unless a value overflows or underflows).
inline void ScaleInPlace(double* coords, size_t count, int exponent)
{
  if (exponent != 0)
  {
    for (size_t i = 0; i < count; ++i)
    {
      coords[i] = std::ldexp(coords[i], exponent);
    }
  }
}

/// The first `count` values of `coords` times 2^exponent.
inline std::vector<double> ScaledCopy(const double* coords, size_t count, int exponent)
{
  std::vector<double> scaled(coords, coords + count);
  ScaleInPlace(scaled.data(), count, exponent);
  return scaled;
}
} // namespace pcs

#endif
