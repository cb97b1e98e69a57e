#pragma once
// Row types: rows of a per-particle assembly that are identical up to translation, found by a
// canonical key, so that an expensive per-row computation runs once per type.
//
// Why: on a lattice almost every row of the consistent correction (ConsistentCorrection.hpp) repeats
// one of a few hundred types (the interior row, and one per distance to each face: 125 on a uniform
// 3-D block), and the correction's small least-squares solve dominated the assembly (40 s of 51 s at
// 185,193 particles).
//
// A key is the row's inputs rounded to integer multiples of a quantum (in the row's own
// dimensionless units), compared exactly. Rounding, rather than a tolerance, keeps grouping a
// partition (equality is transitive) and independent of the visiting order; inputs that agree to
// round-off may straddle a rounding edge, which only costs a miss. The quantum must be far above
// round-off (1e-14 on a lattice) and far below any real difference between rows.

#include "core/Types.hpp"

#include <cstdint>
#include <vector>

namespace mfwave {

class RowKey {
 public:
  explicit RowKey(Real quantum) : scale_(1 / quantum) {}

  void clear() {
    entries_.clear();
    valid_ = true;
  }
  // A value in the row's units; a value that is not finite or too large to round makes the key
  // invalid (the row is then its own type).
  void add(Real value);
  void addCount(Index count) { entries_.push_back(count); }
  void invalidate() { valid_ = false; }

  bool valid() const { return valid_; }
  std::uint64_t hash() const;
  bool operator==(const RowKey& other) const { return valid_ && other.valid_ && entries_ == other.entries_; }
  bool operator!=(const RowKey& other) const { return !(*this == other); }

 private:
  Real scale_;
  std::vector<std::int64_t> entries_;
  bool valid_ = true;
};

// The representative of every row: the smallest row with the same hash (keyed[a] false: the row
// itself). Deterministic, whatever the order the hashes were computed in. Equal hashes are not a
// proof of equal keys: callers compare the keys before they reuse anything.
std::vector<Index> representativesByHash(const std::vector<std::uint64_t>& hash, const std::vector<char>& keyed);

}  // namespace mfwave
