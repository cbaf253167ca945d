// Disjoint sets (union-find) over the ids 0..n-1: the one union-find of the filters and kernels
// (private kernel, header only).
//
// Find halves the path it walks (each node visited is linked to its grandparent), and Union
// links the root of the smaller set under that of the larger (union by size; the first
// argument's root on a tie), so that any sequence of m operations on n ids costs
// O(m alpha(n)) (Tarjan and van Leeuwen, "Worst-case analysis of set union algorithms", 1984).
//
// Which id represents a set (its root) is an implementation detail: callers compare roots, count
// them or index their own per-set data by them, and never rely on a particular id (such as the
// smallest) representing a set.
#ifndef pcsDisjointSets_h
#define pcsDisjointSets_h

#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace pcs
{
template<typename Id>
class DisjointSets
{
public:
  DisjointSets() = default;
  explicit DisjointSets(Id count) { this->Reset(count); }

  /// `count` singletons 0..count-1.
  void Reset(Id count)
  {
    this->Parent.resize(static_cast<size_t>(count));
    std::iota(this->Parent.begin(), this->Parent.end(), Id(0));
    this->Size.assign(static_cast<size_t>(count), Id(1));
  }

  /// A new singleton, whose id (the number of ids before) is returned.
  Id Add()
  {
    const Id id = static_cast<Id>(this->Parent.size());
    this->Parent.push_back(id);
    this->Size.push_back(Id(1));
    return id;
  }

  /// The root of the set of i.
  Id Find(Id i)
  {
    while (this->Parent[i] != i)
    {
      i = this->Parent[i] = this->Parent[this->Parent[i]];
    }
    return i;
  }

  /// Joins the sets of a and b; false when they were one set already.
  bool Union(Id a, Id b)
  {
    a = this->Find(a);
    b = this->Find(b);
    if (a == b)
    {
      return false;
    }
    this->Link(a, b);
    return true;
  }

  /// Joins the sets of the distinct roots a and b: the root of the smaller set is linked under
  /// the other (b under a on a tie), which is returned.
  Id Link(Id a, Id b)
  {
    if (this->Size[a] < this->Size[b])
    {
      std::swap(a, b);
    }
    this->Parent[b] = a;
    this->Size[a] += this->Size[b];
    return a;
  }

  /// The number of ids in the set of root r.
  Id GetSize(Id r) const { return this->Size[r]; }
  Id GetNumberOfIds() const { return static_cast<Id>(this->Parent.size()); }

private:
  std::vector<Id> Parent;
  std::vector<Id> Size; // per root
};
}

#endif
