#pragma once
// One stencil applied along a run of consecutive lattice nodes that share it (the middle of a
// lattice line, where the x position no longer changes the row type): the hot loop of the lattice
// storage, vectorised across the run's nodes.
//
// The input is interleaved (node * D + component). The stencil's entries come sorted by offset, so
// entries on the same neighbouring line (same offset apart from x) are consecutive; each such line
// is copied once into a component-major scratch (the deinterleave), and every coefficient then
// updates the whole run with unit-stride loads, which the compiler vectorises. Each node's sum runs
// over the entries, rows and columns in the same order as LatticeStencils::rowProduct. The AVX-512
// and AVX2 builds of the loop (chosen at run time by the processor) fuse multiply and add, the
// portable one does not, so the last bit of a result depends on the processor; on one machine a
// node always takes the same path (the middle of its line, or its own row at the ends), so the
// results are bitwise the same on any thread count.

#include "core/Types.hpp"

#include <cstdint>
#include <vector>

namespace mfwave {

// One stencil: `entries` blocks (D x D, row-major, in `blocks`), each at node offset flat[e] whose x
// part is dx[e]. `table` names the stencil (a number from freshStencilNumbers, taken when its table
// was made; tables never change after): a thread keeps the terms of the last stencil it ran.
struct StencilView {
  const Real* blocks;
  const Index* flat;
  const Index* dx;
  Index entries;
  std::uint64_t table;
};

// Deinterleaved lines of one product's input, kept between the runs of one thread: the run of the
// next line along y needs six of the nine lines a 3-D stencil of reach 1 reads, so each line is
// copied about three times instead of nine.
struct StencilRunCache {
  std::uint64_t product = 0;  // the product (nextStencilProduct) the lines belong to
  const Real* x = nullptr;
  Index width = 0;
  std::vector<Real> lines;          // slot * D * width
  std::vector<Index> start;         // per slot: the first node it holds, -1 for none
  std::vector<std::uint64_t> used;  // per slot: the run that last read it
  std::uint64_t runs = 0;
};

// A fresh number for each product (each pass over the lattice), so that no cache outlives its input.
std::uint64_t nextStencilProduct();
// The first of `count` fresh numbers (from the same counter), one per stencil of a table.
std::uint64_t freshStencilNumbers(std::uint64_t count);

// out[c * length + l] = sum_e sum_d B_e[c][d] x[D (first + l + flat_e) + d] for l in [0, length).
// `cache` belongs to the calling thread; `product` is the pass's nextStencilProduct().
template <int D>
void stencilRun(const StencilView& stencil, const Real* x, Index first, Index length, Real* out,
                StencilRunCache& cache, std::uint64_t product);

}  // namespace mfwave
