#pragma once
// The discrete dispersion of the spectral elements (GLL nodes, lumped mass) by Bloch-wave analysis
// of one element of a periodic row of elements: the plan's phase error of the spectral-element
// method (mfwave plan), as the lattice rows give the other methods'.
//
// On a 1-D row of elements of order N and width h = N dx (dx the mean node spacing), u'' = c^2 u_xx
// with the GLL rule gives per element M = diag(w_i h / 2) and K_ij = (2 / h) sum_q w_q l_i'(x_q)
// l_j'(x_q). A Bloch wave u(x + h) = exp(i k h) u(x) leaves N unknowns per element (node N is node 0
// of the next element): omega^2 are the eigenvalues of M_B^-1 K_B c^2, N branches folded into
// |k h| <= pi. The acoustic branch of a wave of wavenumber k is the one closest to c k.
// A plane wave along a lattice axis of the 2-D or 3-D tensor elements (P or S) sees exactly this
// 1-D operator with its own speed: the transverse directions reproduce constants. Along other
// directions the error differs (not computed here).

#include "core/Types.hpp"

namespace mfwave {

// The acoustic branch's omega for wavenumber k > 0, speed c, GLL order N >= 1, mean node spacing dx.
// Throws InputError("order") for N < 1, InputError("wavenumber") for k <= 0.
Real spectralElementFrequency(int order, Real spacing, Real speed, Real wavenumber);

// The largest omega of the 1-D operator over every Bloch wavenumber (sampled finely): the 1-D
// central-difference limit is 2 / that.
Real spectralElementLargestFrequency(int order, Real spacing, Real speed);

}  // namespace mfwave
