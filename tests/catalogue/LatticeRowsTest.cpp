// The catalogue's names and the lattice tools' row ids, one way and the other.
#include "catalogue/LatticeRows.hpp"

#include "spectra/LatticeMethods.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

namespace mfwave {
namespace {

TEST(LatticeRows, ACatalogueNameStandsForItsRowsAndARowIdForItself) {
  EXPECT_EQ(latticeRowsOf({"very_weak_sph"}, "k"),
            (std::vector<std::string>{"vwsph_published", "vwsph_consistent", "vwsph_galerkin"}));
  EXPECT_EQ(latticeRowsOf({"rkcm", "updated_lagrangian_sph", "ulsph"}, "k"),
            (std::vector<std::string>{"rkcm", "ulsph", "ulsph_corrected"}));
  EXPECT_EQ(testing::inputErrorKey([] { latticeRowsOf({"fem"}, "study.methods"); }), "study.methods");
}

TEST(LatticeRows, EveryRowOfTheToolsIsReachedAndNamedBack) {
  const std::vector<std::string> all =
      latticeRowsOf({"finite_difference", "very_weak_sph", "reproducing_kernel", "radial_basis", "updated_lagrangian_sph"},
                    "k");
  EXPECT_EQ(all, latticeMethodNames());
  EXPECT_EQ(latticeRowOf("very_weak_sph", "galerkin", false), "vwsph_galerkin");
  EXPECT_EQ(latticeRowOf("updated_lagrangian_sph", "", true), "ulsph_corrected");
  EXPECT_EQ(catalogueSpellingOf("vwsph_consistent"), "very_weak_sph, variant consistent");
  EXPECT_EQ(catalogueSpellingOf("finite_difference"), "");
}

}  // namespace
}  // namespace mfwave
