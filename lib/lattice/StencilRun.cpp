#include "lattice/StencilRun.hpp"

#include <algorithm>
#include <atomic>

namespace mfwave {
namespace {

constexpr Index kChunk = 8;  // nodes summed at once: one AVX-512 register, two AVX2 ones

// Eight doubles as one GCC vector: lowered to one AVX-512 register, two AVX2 ones or four SSE2 ones
// by the build that inlines the loop. Lane k only ever meets lane k, so each node's sum runs in
// the same order whatever the run; the AVX builds fuse each multiply with its add.
typedef Real Chunk __attribute__((vector_size(kChunk * sizeof(Real))));

// The loop itself, inlined into each instruction-set build below.
template <int D>
__attribute__((always_inline)) inline void stencilRunBody(const Real* coefficients, const Index* sources,
                                                           const Index* rowEnd, Index length, const Real* scratch,
                                                           Real* out) {
  Index t0 = 0;
  for (int c = 0; c < D; ++c) {
    const Index t1 = rowEnd[c];
    for (Index l0 = 0; l0 < length; l0 += kChunk) {
      Chunk acc = {};
      for (Index t = t0; t < t1; ++t) {
        Chunk column;
        __builtin_memcpy(&column, scratch + sources[t] + l0, sizeof column);
        acc += coefficients[t] * column;
      }
      const Index valid = std::min(kChunk, length - l0);
      __builtin_memcpy(out + c * length + l0, &acc, static_cast<std::size_t>(valid) * sizeof(Real));
    }
    t0 = t1;
  }
}

template <int D>
void runPortable(const Real* coefficients, const Index* sources, const Index* rowEnd, Index length,
                 const Real* scratch, Real* out) {
  stencilRunBody<D>(coefficients, sources, rowEnd, length, scratch, out);
}

#if defined(__x86_64__) && defined(__GNUC__)
template <int D>
__attribute__((target("avx2,fma"))) void runAvx2(const Real* coefficients, const Index* sources, const Index* rowEnd,
                                             Index length, const Real* scratch, Real* out) {
  stencilRunBody<D>(coefficients, sources, rowEnd, length, scratch, out);
}

template <int D>
__attribute__((target("avx512f"))) void runAvx512(const Real* coefficients, const Index* sources, const Index* rowEnd,
                                                  Index length, const Real* scratch, Real* out) {
  stencilRunBody<D>(coefficients, sources, rowEnd, length, scratch, out);
}

enum class Isa { Portable, Avx2, Avx512 };

Isa detectedIsa() {
  static const Isa isa = [] {
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f")) return Isa::Avx512;
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return Isa::Avx2;
    return Isa::Portable;
  }();
  return isa;
}
#endif

}  // namespace

template <int D>
void stencilRun(const StencilView& s, const Real* x, Index first, Index length, Real* out, StencilRunCache& cache,
                std::uint64_t product) {
  Index reach = 0;
  for (Index e = 0; e < s.entries; ++e) reach = std::max(reach, s.dx[e] < 0 ? -s.dx[e] : s.dx[e]);
  // one scratch line per neighbouring line of the stencil, D components each, padded to whole chunks
  const Index width = length + 2 * reach + kChunk;
  thread_local std::vector<Index> lines, slotOf;
  lines.clear();
  for (Index e = 0; e < s.entries; ++e)
    if (e == 0 || s.flat[e] - s.dx[e] != s.flat[e - 1] - s.dx[e - 1]) lines.push_back(s.flat[e] - s.dx[e]);
  // The cache holds deinterleaved lines of this product's x: the next run along y needs most of them.
  const std::size_t slots = 3 * lines.size();
  if (cache.product != product || cache.x != x || cache.width != width || cache.start.size() < slots) {
    cache.product = product;
    cache.x = x;
    cache.width = width;
    cache.start.assign(std::max(slots, cache.start.size()), -1);
    cache.used.assign(cache.start.size(), 0);
    cache.lines.resize(cache.start.size() * static_cast<std::size_t>(D * width), 0.0);
  }
  const std::uint64_t run = ++cache.runs;
  slotOf.resize(lines.size());
  for (std::size_t g = 0; g < lines.size(); ++g) {
    const Index start = first + lines[g] - reach;
    std::size_t slot = cache.start.size();
    for (std::size_t k = 0; k < cache.start.size(); ++k)
      if (cache.start[k] == start) {
        slot = k;
        break;
      }
    if (slot == cache.start.size()) {  // not cached: the least recently used slot
      slot = 0;
      for (std::size_t k = 1; k < cache.start.size(); ++k)
        if (cache.used[k] < cache.used[slot]) slot = k;
      // deinterleave the line's nodes [start, start + length + 2 reach)
      const Real* source = x + D * start;
      Real* line = cache.lines.data() + static_cast<Index>(slot) * D * width;
      for (Index i = 0; i < length + 2 * reach; ++i)
        for (int d = 0; d < D; ++d) line[d * width + i] = source[D * i + d];
      cache.start[slot] = start;
    }
    cache.used[slot] = run;
    slotOf[g] = static_cast<Index>(slot);
  }
  // The terms: the nonzero coefficients in the order rowProduct sums them (entry, then column), row
  // by row, each with its line and its place in that line's scratch. They depend on the stencil
  // table and the run's width only (which entries share a line is the same on every line, also
  // where a periodic lattice wraps the offsets), so a thread keeps the last table's and resolves
  // the lines per run.
  struct Terms {
    std::uint64_t table = 0;
    Index entries = -1, width = -1;
    std::vector<Real> coefficients;
    std::vector<Index> line, place, sources;
    Index rowEnd[3] = {};
  };
  thread_local Terms terms;
  if (terms.table != s.table || terms.entries != s.entries || terms.width != width) {
    terms.table = s.table;
    terms.entries = s.entries;
    terms.width = width;
    terms.coefficients.clear();
    terms.line.clear();
    terms.place.clear();
    for (int c = 0; c < D; ++c) {
      Index g = -1;
      for (Index e = 0; e < s.entries; ++e) {
        if (e == 0 || s.flat[e] - s.dx[e] != s.flat[e - 1] - s.dx[e - 1]) ++g;
        for (int d = 0; d < D; ++d) {
          const Real coefficient = s.blocks[D * D * e + D * c + d];
          if (coefficient == 0) continue;
          terms.coefficients.push_back(coefficient);
          terms.line.push_back(g);
          terms.place.push_back(d * width + reach + s.dx[e]);
        }
      }
      terms.rowEnd[c] = static_cast<Index>(terms.coefficients.size());
    }
    terms.sources.resize(terms.coefficients.size());
  }
  for (std::size_t t = 0; t < terms.sources.size(); ++t)
    terms.sources[t] = slotOf[static_cast<std::size_t>(terms.line[t])] * D * width + terms.place[t];
  const Real* coefficients = terms.coefficients.data();
  const Index* sources = terms.sources.data();
  const Index* rowEnd = terms.rowEnd;
#if defined(__x86_64__) && defined(__GNUC__)
  switch (detectedIsa()) {
    case Isa::Avx512: return runAvx512<D>(coefficients, sources, rowEnd, length, cache.lines.data(), out);
    case Isa::Avx2: return runAvx2<D>(coefficients, sources, rowEnd, length, cache.lines.data(), out);
    case Isa::Portable: break;
  }
#endif
  runPortable<D>(coefficients, sources, rowEnd, length, cache.lines.data(), out);
}

template void stencilRun<1>(const StencilView&, const Real*, Index, Index, Real*, StencilRunCache&, std::uint64_t);
template void stencilRun<2>(const StencilView&, const Real*, Index, Index, Real*, StencilRunCache&, std::uint64_t);
template void stencilRun<3>(const StencilView&, const Real*, Index, Index, Real*, StencilRunCache&, std::uint64_t);

namespace {
std::atomic<std::uint64_t> stencilCounter{0};
}  // namespace

std::uint64_t nextStencilProduct() { return ++stencilCounter; }

std::uint64_t freshStencilNumbers(std::uint64_t count) { return stencilCounter.fetch_add(count) + 1; }

}  // namespace mfwave
