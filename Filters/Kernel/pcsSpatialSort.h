// Spatially coherent insertion order for incremental constructions (private kernel).
//
// BRIO (Amenta, Choi, Rote, "Incremental constructions con BRIO", cited by paper 002): the
// points are shuffled with a fixed seed and split into rounds of geometrically growing size
// (the last round holds 7/8 of the points, the one before 7/8 of the rest, and so on, down to
// minimumRoundSize), and each round is sorted along a Hilbert curve. The ratio 1/8 measured 5 %
// faster than 1/2 on 10^6 uniform points. Inserting in this order keeps the walk
// of the point location short while keeping the randomization that bounds the expected cost.
#ifndef pcsSpatialSort_h
#define pcsSpatialSort_h

#include <cstdint>
#include <vector>

namespace pcs
{
/// Reorder `ids` (indices into `coords`, a packed array with `dim` = 2 or 3 doubles per point)
/// into a BRIO order with Hilbert-sorted rounds. Deterministic for a given seed.
void BRIOHilbertOrder(const double* coords, int dim, std::vector<int32_t>& ids,
  unsigned int seed = 42, int32_t minimumRoundSize = 1000);

/// Sort `ids` along a Hilbert curve through the bounding box of the referenced points.
void HilbertSort(const double* coords, int dim, int32_t* begin, int32_t* end);
} // namespace pcs

#endif
