#include "catalogue/LatticeRows.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <utility>

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

namespace {

// The catalogue's methods that have interior rows, and their rows, in the tools' order.
const std::vector<std::pair<std::string, std::vector<std::string>>>& rowsByMethod() {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> rows = {
      {"finite_difference", {"finite_difference"}},
      {"very_weak_sph", {"vwsph_published", "vwsph_consistent", "vwsph_galerkin"}},
      {"reproducing_kernel", {"rkcm"}},
      {"radial_basis", {"rbcm"}},
      {"updated_lagrangian_sph", {"ulsph", "ulsph_corrected"}}};
  return rows;
}

}  // namespace

std::vector<std::string> latticeRowChoices() {
  std::vector<std::string> choices;
  for (const auto& [method, rows] : rowsByMethod()) choices.insert(choices.end(), rows.begin(), rows.end());
  for (const auto& [method, rows] : rowsByMethod())
    if (std::find(choices.begin(), choices.end(), method) == choices.end()) choices.push_back(method);
  return choices;
}

std::vector<std::string> latticeRowsOf(const std::vector<std::string>& names, const std::string& key) {
  std::vector<std::string> out;
  const auto add = [&out](const std::string& row) {
    if (std::find(out.begin(), out.end(), row) == out.end()) out.push_back(row);
  };
  for (const std::string& name : names) {
    bool found = false;
    for (const auto& [method, rows] : rowsByMethod()) {
      if (name == method) {
        for (const std::string& row : rows) add(row);
        found = true;
      } else if (std::find(rows.begin(), rows.end(), name) != rows.end()) {
        add(name);
        found = true;
      }
      if (found) break;
    }
    if (!found) throw InputError(key, "'" + name + "' is neither a lattice row nor a catalogue method with rows");
  }
  return out;
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
