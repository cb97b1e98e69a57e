#include "catalogue/LatticeRows.hpp"

#include "core/Error.hpp"

#include <algorithm>

namespace mfwave {
namespace {

// Every interior row of the lattice tools, in their order, and what the catalogue calls it: one
// table for both directions.
struct Row {
  const char* id;
  const char* method;
  const char* variant;   // very_weak_sph's method.variant ("" for the others)
  bool corrected;        // updated_lagrangian_sph's kernel-gradient correction
};

const std::vector<Row>& rows() {
  static const std::vector<Row> table = {
      {"finite_difference", "finite_difference", "", false},
      {"vwsph_published", "very_weak_sph", "published", false},
      {"vwsph_consistent", "very_weak_sph", "consistent", false},
      {"vwsph_galerkin", "very_weak_sph", "galerkin", false},
      {"rkcm", "reproducing_kernel", "", false},
      {"rbcm", "radial_basis", "", false},
      {"ulsph", "updated_lagrangian_sph", "", false},
      {"ulsph_corrected", "updated_lagrangian_sph", "", true}};
  return table;
}

}  // namespace

std::string latticeRowOf(const std::string& method, const std::string& variant, bool gradientCorrection,
                         const std::string& key) {
  if (method == "spectral_element") return method;  // no row: the plane-wave study runs its elements
  if (method == "total_lagrangian_sph") return "ulsph_corrected";
  for (const Row& r : rows())
    if (method == r.method && (method != "very_weak_sph" || variant == r.variant) &&
        (method != "updated_lagrangian_sph" || gradientCorrection == r.corrected))
      return r.id;
  throw InputError(key, "'" + method + "' has no interior row in the lattice tools");
}

std::vector<std::string> latticeRowChoices() {
  std::vector<std::string> choices;
  for (const Row& r : rows()) choices.push_back(r.id);
  for (const Row& r : rows())
    if (std::find(choices.begin(), choices.end(), r.method) == choices.end()) choices.push_back(r.method);
  return choices;
}

std::vector<std::string> latticeRowsOf(const std::vector<std::string>& names, const std::string& key) {
  std::vector<std::string> out;
  for (const std::string& name : names) {
    bool found = false;
    for (const Row& r : rows())
      if (name == r.id || name == r.method) {
        found = true;
        if (std::find(out.begin(), out.end(), r.id) == out.end()) out.push_back(r.id);
        if (name == r.id) break;
      }
    if (!found) throw InputError(key, "'" + name + "' is neither a lattice row nor a catalogue method with rows");
  }
  return out;
}

std::string catalogueSpellingOf(const std::string& row) {
  for (const Row& r : rows()) {
    if (row != r.id || row == r.method) continue;
    std::string spelling = r.method;
    if (*r.variant) spelling += std::string(", variant ") + r.variant;
    if (r.corrected) spelling += " with the kernel-gradient correction";
    return spelling;
  }
  return "";
}

}  // namespace mfwave
