// Turns fuzzer bytes into a small point cloud, for the fuzz targets of Testing/Fuzz. The first
// byte selects a family that makes degeneracies likely, the next one the number of points
// (4..67); each coordinate then comes from one or more bytes:
//   0: integers in [-3, 3]          (grids: duplicates, coplanar, cospherical, collinear sets)
//   1: integers in [-128, 127]
//   2: 1 + k 2^-50, k in [-128, 127] (near-duplicates at the last bits of 1)
//   3: 10^6 + k / 64               (a large offset with fine detail, as UTM coordinates)
//   4: x, y integers from bytes, z = 0 or +-2^-52 (coplanar and nearly coplanar)
//   5: raw doubles (8 bytes), non-finite ones replaced by 0, magnitudes brought into
//      [2^-60, 2^60] by powers of two (the range the kernels accept; the filters scale into it)
#ifndef pcsFuzzInput_h
#define pcsFuzzInput_h

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace pcsfuzz
{
class ByteReader
{
public:
  ByteReader(const uint8_t* data, size_t size)
    : Data(data)
    , Size(size)
  {
  }
  bool Empty() const { return this->Position >= this->Size; }
  uint8_t Byte()
  {
    return this->Position < this->Size ? this->Data[this->Position++] : 0;
  }
  double Raw()
  {
    uint64_t bits = 0;
    for (int i = 0; i < 8; ++i)
    {
      bits = (bits << 8) | this->Byte();
    }
    double x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
  }

private:
  const uint8_t* Data;
  size_t Size;
  size_t Position = 0;
};

inline double SafeRange(double x)
{
  if (!std::isfinite(x) || x == 0.0)
  {
    return 0.0;
  }
  int exponent = 0;
  const double mantissa = std::frexp(x, &exponent);
  exponent = exponent > 60 ? 60 - (exponent % 8) : exponent;
  exponent = exponent < -60 ? -60 + ((-exponent) % 8) : exponent;
  return std::ldexp(mantissa, exponent);
}

/// Packed x, y, z coordinates (dim 3) or x, y pairs (dim 2).
inline std::vector<double> Cloud(const uint8_t* data, size_t size, int dim)
{
  ByteReader in(data, size);
  const int family = in.Byte() % 6;
  const int n = 4 + in.Byte() % 64;
  std::vector<double> xyz;
  for (int i = 0; i < n && !in.Empty(); ++i)
  {
    for (int k = 0; k < dim; ++k)
    {
      const int8_t b = static_cast<int8_t>(in.Byte());
      double x = 0.0;
      switch (family)
      {
        case 0:
          x = static_cast<double>(b % 4);
          break;
        case 1:
          x = static_cast<double>(b);
          break;
        case 2:
          x = 1.0 + std::ldexp(static_cast<double>(b), -50);
          break;
        case 3:
          x = 1e6 + static_cast<double>(b) / 64.0;
          break;
        case 4:
        {
          const int r = ((b % 3) + 3) % 3;
          x = k + 1 < dim ? static_cast<double>(b) : (r == 0 ? 0.0 : (r == 1 ? 1.0 : -1.0) * 0x1p-52);
          break;
        }
        default:
          x = SafeRange(in.Raw());
          break;
      }
      xyz.push_back(x);
    }
  }
  // Drop an incomplete last point.
  xyz.resize(xyz.size() - xyz.size() % dim);
  return xyz;
}
} // namespace pcsfuzz

#endif
