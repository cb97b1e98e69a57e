#include "catalogue/LatticeRows.hpp"

#include "core/Error.hpp"

namespace mfwave {

std::string latticeRowOf(const std::string& method, const std::string& variant, bool gradientCorrection,
                         const std::string& key) {
  if (method == "finite_difference" || method == "spectral_element") return method;
  if (method == "very_weak_sph") return "vwsph_" + variant;
  if (method == "reproducing_kernel") return "rkcm";
  if (method == "radial_basis") return "rbcm";
  if (method == "updated_lagrangian_sph") return gradientCorrection ? "ulsph_corrected" : "ulsph";
  if (method == "total_lagrangian_sph") return "ulsph_corrected";
  throw InputError(key, "'" + method + "' has no interior row in the lattice tools");
}

std::string catalogueSpellingOf(const std::string& row) {
  if (row.rfind("vwsph_", 0) == 0) return "very_weak_sph, variant " + row.substr(6);
  if (row == "rkcm") return "reproducing_kernel";
  if (row == "rbcm") return "radial_basis";
  if (row == "ulsph") return "updated_lagrangian_sph";
  if (row == "ulsph_corrected") return "updated_lagrangian_sph with the kernel-gradient correction";
  return "";
}

}  // namespace mfwave
