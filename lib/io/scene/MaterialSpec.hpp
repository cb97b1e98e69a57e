#pragma once
// [material]: density and either the Lame constants (lambda, mu) or Young's modulus and
// Poisson's ratio; validated by building a core Material.

#include "core/Material.hpp"
#include "io/scene/SceneReader.hpp"

namespace mfwave {

struct MaterialSpec {
  Real density = 0;
  Real lambda = 0, mu = 0;  // always set (converted when given as E, nu)
  bool givenAsYoung = false;

  Material material() const { return Material::fromLame(lambda, mu, density); }
};

MaterialSpec readMaterial(SceneReader& reader);

}  // namespace mfwave
