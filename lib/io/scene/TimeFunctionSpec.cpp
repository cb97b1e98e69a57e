#include "io/scene/TimeFunctionSpec.hpp"

#include "io/scene/Format.hpp"
#include "io/scene/ScenePath.hpp"

#include <filesystem>

namespace mfwave {

TimeFunction readTimeFunction(SceneReader& reader, const std::string& path, bool required) {
  reader.table(path, required, required ? "" : "{ type = \"constant\", value = 1.0 }");
  const auto key = [&](const char* name) { return scene::childPath(path, name); };
  const std::string type = reader.string(key("type"));
  try {
    if (type == "constant") return TimeFunction::constant(reader.number(key("value")));
    if (type == "ramp") {
      const Real start = reader.number(key("start"));
      const Real duration = reader.number(key("duration"));
      return TimeFunction::ramp(start, duration, reader.number(key("amplitude")));
    }
    if (type == "triangle") {
      const Real start = reader.number(key("start"));
      const Real rise = reader.number(key("rise"));
      const Real fall = reader.number(key("fall"), rise);
      return TimeFunction::triangle(start, rise, fall, reader.number(key("amplitude")));
    }
    if (type == "ricker") {
      const Real frequency = reader.number(key("peak_frequency"));
      const Real delay = reader.number(key("delay"), kRickerDelayPeriods / frequency);
      return TimeFunction::ricker(frequency, delay, reader.number(key("amplitude")));
    }
    // tabulated
    const bool file = reader.has(key("file"));
    const bool table = reader.has(key("times")) || reader.has(key("values"));
    if (file && table)
      reader.fail(key("file"), "cannot be combined with times and values: give either times and values, or file");
    if (file) {
      const std::string name = reader.string(key("file"));
      namespace fs = std::filesystem;
      fs::path csv(name);
      if (csv.is_relative()) csv = fs::path(reader.baseDirectory()) / csv;
      csv = fs::absolute(csv).lexically_normal();
      std::error_code ec;
      if (!fs::is_regular_file(csv, ec))
        reader.fail(key("file"), "cannot open the time-function table '" + csv.string() + "' (no such file)");
      TimeFunction f = TimeFunction::fromCsv(csv.string());
      reader.resolveString(key("file"), csv.string());
      return f;
    }
    if (!table)
      reader.fail(key("times"), "missing required key (a tabulated time function needs times and values, or file)");
    std::vector<Real> times = reader.numbers(key("times"));
    std::vector<Real> values = reader.numbers(key("values"));
    return TimeFunction::tabulated(std::move(times), std::move(values));
  } catch (const SceneError&) {
    throw;
  } catch (const InputError& e) {
    reader.fail(key(e.key().c_str()), scene::problemOf(e));
  }
}

}  // namespace mfwave
