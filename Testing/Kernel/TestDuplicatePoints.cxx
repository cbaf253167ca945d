// Standalone test of the exact-duplicate kernel (Filters/Kernel/pcsDuplicatePoints.h), compiled
// with its source (vtkSMPTools for the sort, hence VTK::CommonCore). Every expectation is known
// by construction:
// - k copies of m distinct random points, shuffled (2D and 3D, all points or a shuffled subset
//   as `ids`): m first copies, each copy maps to the smallest entry holding its position, the
//   sorted entries are runs of copies in lexicographic order each led by its first copy;
//   MergeExactDuplicates keeps the m first copies in their order (and lists them in lexicographic
//   order on demand) and maps every other copy to the copy of smallest id;
// - points one ulp apart stay distinct; +0.0 and -0.0 are one position;
// - a point with a NaN or infinite coordinate is never merged (two bit-identical NaN points, two
//   equal infinite points stay apart) and comes last in the sorted entries;
// - no point, one point, and 20,000 copies of one point.
#include "pcsDuplicatePoints.h"
#include "pcsKernelTest.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <vector>

namespace
{
using pcstest::Failures;

// k copies of each of m random points (dim coordinates), in a shuffled order; group[i] is the
// index (0..m-1) of the distinct point that point i copies.
struct Copies
{
  std::vector<double> Coords;
  std::vector<int32_t> Group;

  Copies(int dim, int32_t m, int k, std::mt19937& random)
  {
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<double> distinct(static_cast<size_t>(dim) * m);
    for (double& c : distinct)
    {
      c = uniform(random);
    }
    this->Group.resize(static_cast<size_t>(m) * k);
    for (size_t i = 0; i < this->Group.size(); ++i)
    {
      this->Group[i] = static_cast<int32_t>(i % m);
    }
    std::shuffle(this->Group.begin(), this->Group.end(), random);
    for (const int32_t g : this->Group)
    {
      this->Coords.insert(this->Coords.end(),
        &distinct[static_cast<size_t>(dim) * g],
        &distinct[static_cast<size_t>(dim) * g] + dim);
    }
  }
};

// Checks FindExactDuplicates on the entries `ids` (null: every point) of `c`.
void CheckGroups(const Copies& c,
  int dim,
  const std::vector<int32_t>* ids,
  int32_t m,
  const char* what)
{
  const int32_t n = ids ? static_cast<int32_t>(ids->size()) : static_cast<int32_t>(c.Group.size());
  auto group = [&](int32_t j) { return c.Group[ids ? (*ids)[j] : j]; };
  std::vector<int32_t> first, sorted;
  const int32_t distinct =
    pcs::FindExactDuplicates(c.Coords.data(), dim, ids ? ids->data() : nullptr, n, first, &sorted);
  EXPECT(distinct == m, what << ": " << distinct << " first copies, expected " << m);

  // The expected first copy: the smallest entry of each group.
  std::map<int32_t, int32_t> smallest;
  for (int32_t j = n - 1; j >= 0; --j)
  {
    smallest[group(j)] = j;
  }
  int32_t wrong = 0;
  for (int32_t j = 0; j < n; ++j)
  {
    wrong += first[j] == smallest[group(j)] ? 0 : 1;
  }
  EXPECT(wrong == 0, what << ": " << wrong << " entries not mapped to their smallest copy");

  // Sorted: a permutation, runs of one group each led by its first copy, in lexicographic order.
  std::vector<int32_t> seen(sorted);
  std::sort(seen.begin(), seen.end());
  std::vector<int32_t> all(static_cast<size_t>(n));
  std::iota(all.begin(), all.end(), 0);
  EXPECT(seen == all, what << ": the sorted entries are not a permutation");
  int32_t runs = 0, badOrder = 0;
  for (int32_t r = 0; r < n; ++r)
  {
    const int32_t j = sorted[r];
    if (r == 0 || group(j) != group(sorted[r - 1]))
    {
      ++runs;
      badOrder += first[j] == j ? 0 : 1;
      if (r > 0)
      {
        const double* p =
          &c.Coords[static_cast<size_t>(dim) * (ids ? (*ids)[sorted[r - 1]] : sorted[r - 1])];
        const double* q = &c.Coords[static_cast<size_t>(dim) * (ids ? (*ids)[j] : j)];
        badOrder += std::lexicographical_compare(p, p + dim, q, q + dim) ? 0 : 1;
      }
    }
    else
    {
      badOrder += j > sorted[r - 1] ? 0 : 1; // copies by entry
    }
  }
  EXPECT(runs == m, what << ": " << runs << " runs in the sorted entries, expected " << m);
  EXPECT(badOrder == 0, what << ": " << badOrder << " entries out of order");
}

void TestCopies()
{
  std::mt19937 random(7);
  for (const int dim : { 2, 3 })
  {
    const int32_t m = 1500;
    const int k = 4;
    Copies c(dim, m, k, random);
    CheckGroups(c, dim, nullptr, m, dim == 2 ? "2D, all points" : "3D, all points");

    // A shuffled subset holding every group: the first 2 copies of each group, in random order.
    std::vector<int32_t> ids, taken(static_cast<size_t>(m), 0);
    for (int32_t i = 0; i < static_cast<int32_t>(c.Group.size()); ++i)
    {
      if (taken[c.Group[i]]++ < 2)
      {
        ids.push_back(i);
      }
    }
    std::shuffle(ids.begin(), ids.end(), random);
    CheckGroups(c, dim, &ids, m, dim == 2 ? "2D, shuffled subset" : "3D, shuffled subset");

    // MergeExactDuplicates on every point in ascending order: the copy of smallest id is kept.
    std::vector<int32_t> ascending(c.Group.size());
    std::iota(ascending.begin(), ascending.end(), 0);
    std::vector<std::pair<int32_t, int32_t>> merged;
    std::vector<int32_t> lexicographic;
    const int32_t removed =
      pcs::MergeExactDuplicates(c.Coords.data(), dim, ascending, merged, &lexicographic);
    EXPECT(removed == m * (k - 1) && static_cast<int32_t>(merged.size()) == removed,
      "merge: " << removed << " removed, expected " << m * (k - 1));
    std::vector<int32_t> smallest(static_cast<size_t>(m), -1);
    for (int32_t i = 0; i < static_cast<int32_t>(c.Group.size()); ++i)
    {
      if (smallest[c.Group[i]] < 0)
      {
        smallest[c.Group[i]] = i;
      }
    }
    std::vector<int32_t> expectedKept(smallest);
    std::sort(expectedKept.begin(), expectedKept.end());
    EXPECT(ascending == expectedKept, "merge: the kept ids are not the smallest copies, ascending");
    // The kept ids in lexicographic order: the same ids, strictly increasing positions.
    std::vector<int32_t> keptSet(lexicographic);
    std::sort(keptSet.begin(), keptSet.end());
    EXPECT(keptSet == expectedKept, "merge: the lexicographic list is not the kept ids");
    int32_t unordered = 0;
    for (size_t r = 1; r < lexicographic.size(); ++r)
    {
      const double* p = &c.Coords[static_cast<size_t>(dim) * lexicographic[r - 1]];
      const double* q = &c.Coords[static_cast<size_t>(dim) * lexicographic[r]];
      unordered += std::lexicographical_compare(p, p + dim, q, q + dim) ? 0 : 1;
    }
    EXPECT(unordered == 0, "merge: " << unordered << " kept ids out of lexicographic order");
    int32_t wrong = 0;
    for (const auto& copy : merged)
    {
      wrong += copy.first != copy.second && copy.second == smallest[c.Group[copy.first]] ? 0 : 1;
    }
    EXPECT(wrong == 0, "merge: " << wrong << " copies not mapped to the smallest id");
  }
}

void TestSpecialValues()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const double next = std::nextafter(1.0, 2.0);
  // 0: (1, 0, 0)         1: (1 + ulp, 0, 0) distinct from 0
  // 2: (0, 0, 0)         3: (-0, 0, -0) same as 2     4: (0, -0, 0) same as 2
  // 5: (NaN, 0, 0)       6: (NaN, 0, 0) not merged with 5
  // 7: (inf, 0, 0)       8: (inf, 0, 0) not merged with 7
  // 9: (1, 0, 0) same as 0
  const std::vector<double> xyz = { 1,
    0,
    0,
    next,
    0,
    0,
    0,
    0,
    0,
    -0.0,
    0,
    -0.0,
    0,
    -0.0,
    0,
    nan,
    0,
    0,
    nan,
    0,
    0,
    inf,
    0,
    0,
    inf,
    0,
    0,
    1,
    0,
    0 };
  std::vector<int32_t> first, sorted;
  const int32_t distinct = pcs::FindExactDuplicates(xyz.data(), 3, nullptr, 10, first, &sorted);
  EXPECT(distinct == 7, "special values: " << distinct << " first copies, expected 7");
  const std::vector<int32_t> expectedFirst = { 0, 1, 2, 2, 2, 5, 6, 7, 8, 0 };
  EXPECT(first == expectedFirst, "special values: wrong first copies");
  // Sorted: (-0/0 group) 2 3 4, then 0 9, then 1, then the non-finite 5 6 7 8 by entry.
  const std::vector<int32_t> expectedSorted = { 2, 3, 4, 0, 9, 1, 5, 6, 7, 8 };
  EXPECT(sorted == expectedSorted, "special values: wrong sorted order");

  EXPECT(pcs::SamePosition(&xyz[6], &xyz[9], 3), "+0 and -0 are one position");
  EXPECT(!pcs::SamePosition(&xyz[15], &xyz[15], 3), "a NaN point is not the same as itself");
  EXPECT(!pcs::SamePosition(&xyz[21], &xyz[24], 3), "infinite points are never the same");
  EXPECT(pcs::ComparePositions(&xyz[0], &xyz[3], 3) < 0, "1 before 1 + ulp");
  EXPECT(pcs::ComparePositions(&xyz[3], &xyz[0], 3) > 0, "1 + ulp after 1");
  EXPECT(pcs::ComparePositions(&xyz[6], &xyz[9], 3) == 0, "+0 and -0 compare equal");
  EXPECT(pcs::ComparePositions(&xyz[0], &xyz[15], 3) < 0, "finite before NaN");
  EXPECT(pcs::ComparePositions(&xyz[21], &xyz[0], 3) > 0, "infinite after finite");
  EXPECT(pcs::ComparePositions(&xyz[15], &xyz[21], 3) == 0, "non-finite pairs are ties");

  // Merging keeps the non-finite entries and maps 3, 4 to 2 and 9 to 0 (ids in ascending order).
  std::vector<int32_t> ids(10);
  std::iota(ids.begin(), ids.end(), 0);
  std::vector<std::pair<int32_t, int32_t>> merged;
  std::vector<int32_t> lexicographic;
  EXPECT(pcs::MergeExactDuplicates(xyz.data(), 3, ids, merged, &lexicographic) == 3,
    "special values: 3 merged");
  const std::vector<int32_t> expectedLexicographic = { 2, 0, 1, 5, 6, 7, 8 };
  EXPECT(lexicographic == expectedLexicographic, "special values: wrong lexicographic order");
  const std::vector<int32_t> expectedIds = { 0, 1, 2, 5, 6, 7, 8 };
  const std::vector<std::pair<int32_t, int32_t>> expectedMerged = { { 3, 2 }, { 4, 2 }, { 9, 0 } };
  EXPECT(ids == expectedIds, "special values: wrong kept ids");
  EXPECT(merged == expectedMerged, "special values: wrong merged pairs");
}

void TestSmallAndDegenerate()
{
  std::vector<int32_t> first, sorted;
  EXPECT(pcs::FindExactDuplicates(nullptr, 3, nullptr, 0, first, &sorted) == 0 && first.empty() &&
      sorted.empty(),
    "no point");
  const double one[3] = { 0.5, -2, 3 };
  EXPECT(pcs::FindExactDuplicates(one, 3, nullptr, 1, first) == 1 && first[0] == 0, "one point");

  // 20,000 copies of one point, given in descending id order: the first entry is the
  // representative of all (entry order, not id order, decides).
  const int32_t n = 20000;
  std::vector<double> xyz;
  for (int32_t i = 0; i < n; ++i)
  {
    xyz.insert(xyz.end(), one, one + 3);
  }
  std::vector<int32_t> ids(static_cast<size_t>(n));
  std::iota(ids.rbegin(), ids.rend(), 0);
  std::vector<std::pair<int32_t, int32_t>> merged;
  EXPECT(pcs::MergeExactDuplicates(xyz.data(), 3, ids, merged) == n - 1, "one position");
  EXPECT(ids.size() == 1 && ids[0] == n - 1, "one position: the first entry is kept");
  EXPECT(std::all_of(merged.begin(),
           merged.end(),
           [n](const std::pair<int32_t, int32_t>& copy) { return copy.second == n - 1; }),
    "one position: every copy maps to the first entry");
}
} // namespace

int main()
{
  TestCopies();
  TestSpecialValues();
  TestSmallAndDegenerate();
  if (Failures > 0)
  {
    std::cerr << Failures << " failure(s)" << std::endl;
    return 1;
  }
  std::cout << "TestDuplicatePoints: all passed" << std::endl;
  return 0;
}
