#include "core/NumberText.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace mfwave {

std::string shortestNumber(Real value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[400];
  // Shortest round-trip digits in both notations; fixed unless it is much longer (1e-06, 7e10).
  auto result = std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::fixed);
  const std::string fixed(buffer, result.ptr);
  result = std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::scientific);
  std::string scientific(buffer, result.ptr);
  // "7e+10" -> "7e10", "3e-04" -> "3e-4"
  const auto e = scientific.find('e');
  std::string exponent = scientific.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent = exponent.substr(1);
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  scientific = scientific.substr(0, e + 1) + (negative ? "-" : "") + exponent;
  return fixed.size() <= scientific.size() + 3 ? fixed : scientific;
}

}  // namespace mfwave
