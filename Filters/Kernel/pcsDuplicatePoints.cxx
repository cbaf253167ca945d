// Exact duplicate points (private kernel). See pcsDuplicatePoints.h.
#include "pcsDuplicatePoints.h"

#include "vtkSMPTools.h"

#include <cmath>

namespace pcs
{
int ComparePositions(const double* p, const double* q, int dim)
{
  const bool finiteP = IsFinitePosition(p, dim);
  const bool finiteQ = IsFinitePosition(q, dim);
  if (!finiteP || !finiteQ)
  {
    return finiteP == finiteQ ? 0 : (finiteP ? -1 : 1);
  }
  for (int i = 0; i < dim; ++i)
  {
    if (p[i] != q[i])
    {
      return p[i] < q[i] ? -1 : 1;
    }
  }
  return 0;
}

namespace
{
// Sorts the entries [begin, end) (finite points) lexicographically by position, ties by entry.
template<int Dim>
void SortByPosition(const double* coords, const int32_t* ids, int32_t* begin, int32_t* end)
{
  vtkSMPTools::Sort(begin,
    end,
    [coords, ids](int32_t a, int32_t b)
    {
      const double* p = coords + Dim * static_cast<int64_t>(ids ? ids[a] : a);
      const double* q = coords + Dim * static_cast<int64_t>(ids ? ids[b] : b);
      for (int i = 0; i < Dim; ++i)
      {
        if (p[i] != q[i])
        {
          return p[i] < q[i];
        }
      }
      return a < b;
    });
}
} // namespace

int32_t FindExactDuplicates(const double* coords,
  int dim,
  const int32_t* ids,
  int32_t n,
  std::vector<int32_t>& first,
  std::vector<int32_t>* sorted)
{
  auto point = [coords, dim, ids](int32_t j)
  { return coords + static_cast<int64_t>(dim) * (ids ? ids[j] : j); };
  std::vector<int32_t> localOrder;
  std::vector<int32_t>& order = sorted ? *sorted : localOrder;
  // Finite entries first, then the non-finite ones, each part in entry order; the finite part is
  // then sorted by position (ties by entry), with no finiteness test in the comparison.
  order.resize(static_cast<size_t>(n));
  int32_t finite = 0;
  for (int32_t j = 0; j < n; ++j)
  {
    finite += IsFinitePosition(point(j), dim) ? 1 : 0;
  }
  for (int32_t j = 0, f = 0, g = finite; j < n; ++j)
  {
    order[IsFinitePosition(point(j), dim) ? f++ : g++] = j;
  }
  if (dim == 2)
  {
    SortByPosition<2>(coords, ids, order.data(), order.data() + finite);
  }
  else
  {
    SortByPosition<3>(coords, ids, order.data(), order.data() + finite);
  }
  first.resize(static_cast<size_t>(n));
  int32_t distinct = 0;
  for (int32_t k = 0; k < n; ++k)
  {
    const int32_t j = order[k];
    if (k > 0 && SamePosition(point(j), point(order[k - 1]), dim))
    {
      first[j] = first[order[k - 1]];
    }
    else
    {
      first[j] = j;
      ++distinct;
    }
  }
  return distinct;
}

int32_t MergeExactDuplicates(const double* coords,
  int dim,
  std::vector<int32_t>& ids,
  std::vector<std::pair<int32_t, int32_t>>& merged,
  std::vector<int32_t>* kept)
{
  merged.clear();
  std::vector<int32_t> first, sorted;
  const int32_t n = static_cast<int32_t>(ids.size());
  const int32_t distinct =
    FindExactDuplicates(coords, dim, ids.data(), n, first, kept ? &sorted : nullptr);
  if (kept)
  {
    kept->clear();
    kept->reserve(static_cast<size_t>(distinct));
    for (const int32_t j : sorted)
    {
      if (first[j] == j)
      {
        kept->push_back(ids[j]);
      }
    }
  }
  if (distinct == n)
  {
    return 0;
  }
  for (int32_t j = 0; j < n; ++j)
  {
    if (first[j] != j)
    {
      merged.emplace_back(ids[j], ids[first[j]]);
    }
  }
  size_t count = 0;
  for (int32_t j = 0; j < n; ++j)
  {
    if (first[j] == j)
    {
      ids[count++] = ids[j];
    }
  }
  ids.resize(count);
  return n - distinct;
}
} // namespace pcs
