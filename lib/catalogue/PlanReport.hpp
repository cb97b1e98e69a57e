#pragma once
// What `mfwave check`, `mfwave plan` and `mfwave methods` print: the resolved model of a scene, a
// prediction as text or as one JSON object, and the catalogue. Formatting only; the numbers come
// from ScenePrediction and the catalogue.

#include "catalogue/MethodCatalogue.hpp"
#include "catalogue/ScenePrediction.hpp"

#include <nlohmann/json.hpp>
#include <ostream>

namespace mfwave {

// The scene as the method will see it: particles, box, material, boundaries, loads, probes, method,
// integrator and the predicted step.
void printResolvedModel(std::ostream& out, const Scene& scene, const MethodChoice& choice, const Prediction& p);

// The prediction, one line per figure, with what it rests on.
void printPrediction(std::ostream& out, const Prediction& p);

// One JSON object: particles, memory_bytes, stable_step, time_step, steps, wall_seconds, phase_error
// (null without a source), points_per_wavelength, dominant_frequency, method, spacing, notes.
nlohmann::json predictionJson(const Prediction& p);

// Every entry: name, title, what it supports, its options (the schema's method.* keys), step rule,
// programs. `json` for the machine-readable form.
void printCatalogue(std::ostream& out);
nlohmann::json catalogueJson();

}  // namespace mfwave
