#include "methods/very_weak_sph/RowTypes.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mfwave {
namespace {

// The finaliser of splitmix64: every input bit affects every output bit.
std::uint64_t mix(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

}  // namespace

void RowKey::add(Real value) {
  const Real scaled = value * scale_;
  if (!(std::abs(scaled) < 4e18)) {  // also false for NaN
    valid_ = false;
    return;
  }
  entries_.push_back(std::llround(scaled));
}

std::uint64_t RowKey::hash() const {
  std::uint64_t h = mix(entries_.size());
  for (std::int64_t e : entries_) h = mix(h ^ (static_cast<std::uint64_t>(e) + 0x9e3779b97f4a7c15ULL));
  return h;
}

std::vector<Index> representativesByHash(const std::vector<std::uint64_t>& hash, const std::vector<char>& keyed) {
  const auto n = static_cast<Index>(hash.size());
  std::vector<Index> representative(hash.size());
  std::vector<std::pair<std::uint64_t, Index>> order;
  order.reserve(hash.size());
  for (Index a = 0; a < n; ++a) {
    representative[static_cast<std::size_t>(a)] = a;
    if (keyed[static_cast<std::size_t>(a)]) order.emplace_back(hash[static_cast<std::size_t>(a)], a);
  }
  std::sort(order.begin(), order.end());
  for (std::size_t k = 1; k < order.size(); ++k)
    if (order[k].first == order[k - 1].first)
      representative[static_cast<std::size_t>(order[k].second)] =
          representative[static_cast<std::size_t>(order[k - 1].second)];
  return representative;
}

}  // namespace mfwave
