#include "io/scene/MaterialSpec.hpp"

#include "io/scene/Format.hpp"

namespace mfwave {

MaterialSpec readMaterial(SceneReader& reader) {
  reader.table("material", true);
  MaterialSpec m;
  const bool lambda = reader.has("material.lambda"), mu = reader.has("material.mu");
  const bool young = reader.has("material.youngs_modulus"), poisson = reader.has("material.poisson_ratio");
  const std::string choice = "give either lambda and mu, or youngs_modulus and poisson_ratio";
  if ((lambda || mu) && (young || poisson))
    reader.fail(young ? "material.youngs_modulus" : "material.poisson_ratio",
                "cannot be combined with " + std::string(lambda ? "lambda" : "mu") + ": " + choice);
  if (!lambda && !mu && !young && !poisson) reader.fail("material", "missing elastic constants: " + choice);
  if (young || poisson) {
    if (!young) reader.fail("material.youngs_modulus", "missing required key (poisson_ratio needs youngs_modulus)");
    if (!poisson) reader.fail("material.poisson_ratio", "missing required key (youngs_modulus needs poisson_ratio)");
  } else {
    if (!lambda) reader.fail("material.lambda", "missing required key (mu needs lambda)");
    if (!mu) reader.fail("material.mu", "missing required key (lambda needs mu)");
  }
  m.density = reader.number("material.density");
  try {
    if (young) {
      const Material built = Material::fromYoung(reader.number("material.youngs_modulus"),
                                                 reader.number("material.poisson_ratio"), m.density);
      m.lambda = built.lambda();
      m.mu = built.mu();
      m.givenAsYoung = true;
    } else {
      m.lambda = reader.number("material.lambda");
      m.mu = reader.number("material.mu");
      Material::fromLame(m.lambda, m.mu, m.density);
    }
  } catch (const SceneError&) {
    throw;
  } catch (const InputError& e) {
    reader.fail("material." + e.key(), scene::problemOf(e));
  }
  return m;
}

}  // namespace mfwave
