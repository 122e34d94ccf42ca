#pragma once
// Integers read from pdrt's own JSON files (a plan, a job's mark, the request a plan stores),
// checked: nlohmann's get<int>() converts a float out of the type's range (undefined
// behaviour: 1e300 in a hand-edited plan.json), truncates 2.5 and wraps a large integer.
#include <nlohmann/json.hpp>

#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace pdrt {

// object[key] as a T; std::out_of_range when the key is missing, std::invalid_argument naming
// the key when the value is not an integer or does not fit in T.
template <class T>
T json_integer(const nlohmann::json& object, const char* key) {
  const nlohmann::json& v = object.at(key);
  if (v.is_number_unsigned()) {
    if (const auto u = v.get<uint64_t>(); std::in_range<T>(u)) return T(u);
  } else if (v.is_number_integer()) {
    if (const auto i = v.get<int64_t>(); std::in_range<T>(i)) return T(i);
  }
  throw std::invalid_argument(std::string("\"") + key + "\" must be an integer in [" +
                              std::to_string(std::numeric_limits<T>::min()) + ", " +
                              std::to_string(std::numeric_limits<T>::max()) + "], got " + v.dump());
}

}  // namespace pdrt
