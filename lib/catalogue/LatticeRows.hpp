#pragma once
// A method's interior row in the lattice tools (spectra/LatticeMethods): the catalogue's name and
// its variant or options turned into the row the spectra, the stability atlas, the plane-wave study
// and the plan use, so that users name methods one way (the catalogue's) and the tools keep their
// row ids ("vwsph_galerkin", "rkcm", "ulsph_corrected", ...).

#include <string>
#include <vector>

namespace mfwave {

// finite_difference -> "finite_difference"; very_weak_sph + variant -> "vwsph_<variant>";
// reproducing_kernel -> "rkcm"; radial_basis -> "rbcm"; updated_lagrangian_sph -> "ulsph", or
// "ulsph_corrected" with the kernel-gradient correction; total_lagrangian_sph -> "ulsph_corrected"
// (its corrected gradients linearised at rest); spectral_element -> "spectral_element" (no lattice
// row: the plane-wave study runs its periodic elements). Throws InputError(key) for another name.
std::string latticeRowOf(const std::string& method, const std::string& variant, bool gradientCorrection,
                         const std::string& key = "method.name");

// The rows a tool's method list names: a row id stands for itself; a catalogue name for every row of
// the method (very_weak_sph: vwsph_published, vwsph_consistent, vwsph_galerkin; updated_lagrangian_sph:
// ulsph, ulsph_corrected; reproducing_kernel: rkcm; radial_basis: rbcm; finite_difference). Rows
// already listed are not repeated. Throws InputError(key) for a name that is neither.
std::vector<std::string> latticeRowsOf(const std::vector<std::string>& names, const std::string& key);

// What a tool's method list accepts: the row ids and the catalogue names that have rows.
std::vector<std::string> latticeRowChoices();

// The catalogue's spelling of a lattice row id: the inverse of latticeRowOf, for messages that tell a
// user of the old row names what to write ("vwsph_consistent" -> "very_weak_sph, variant consistent");
// empty for a name that is no row id.
std::string catalogueSpellingOf(const std::string& row);

}  // namespace mfwave
