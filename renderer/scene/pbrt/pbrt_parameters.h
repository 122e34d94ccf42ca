#pragma once
// A directive's parameter list: `"type name" value` or `"type name" [values]` (pbrt-v4 file
// format, "Parameter lists"). Lookups check the declared type and the number of values and
// mark the parameter used, so that what a scene sets but pdrt ignores can be reported the way
// pbrt-v4 reports unused parameters.
#include "renderer/scene/pbrt/pbrt_tokenizer.h"
#include "renderer/scene/vec3.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pdrt {

struct PbrtParam {
  std::string type;  // integer float point2 vector2 point3 vector3 normal3 normal point vector bool
                     // string texture rgb color spectrum blackbody (as written)
  std::string name;
  PbrtLocation at;                   // of the "type name" string
  std::vector<double> numbers;       // numeric types (and spectrum given as lambda/value pairs)
  std::vector<std::string> strings;  // string, texture, spectrum given by name or file
  std::vector<bool> bools;
  mutable bool used = false;
  std::string quoted() const { return "\"" + type + " " + name + "\""; }  // "rgb L", quotes included
  std::string where() const { return at.str() + ": " + quoted(); }
};

// The declared type's canonical name (point -> point3, normal -> normal3, vector -> vector3,
// color -> rgb), or "" for a type pbrt-v4 does not have.
std::string pbrt_canonical_type(const std::string& type);

// A number as messages print it (an ostream's default format: 0.5, 1e+06).
std::string pbrt_number(double v);

class PbrtParams {
 public:
  std::vector<PbrtParam> list;

  const PbrtParam* find(const std::string& name) const;  // any type; marks nothing
  bool has(const std::string& name) const { return find(name) != nullptr; }

  // Single values: nullopt when absent. Throws InputError naming the parameter when it has
  // another type or not exactly one value.
  std::optional<double> find_float(const std::string& name) const;
  std::optional<int64_t> find_int(const std::string& name) const;
  std::optional<bool> find_bool(const std::string& name) const;
  std::optional<std::string> find_string(const std::string& name) const;
  std::optional<std::string> find_texture(const std::string& name) const;
  double get_float(const std::string& name, double fallback) const { return find_float(name).value_or(fallback); }
  int64_t get_int(const std::string& name, int64_t fallback) const { return find_int(name).value_or(fallback); }
  bool get_bool(const std::string& name, bool fallback) const { return find_bool(name).value_or(fallback); }
  std::string get_string(const std::string& name, const std::string& fallback) const {
    return find_string(name).value_or(fallback);
  }

  // Arrays (empty when absent): every value of the type; triples for the 3-vector types.
  std::vector<double> floats(const std::string& name) const;
  std::vector<int64_t> ints(const std::string& name) const;
  std::vector<Vec3> point3s(const std::string& name) const;                  // point3 / point
  std::vector<Vec3> normal3s(const std::string& name) const;                 // normal3 / normal
  std::vector<Vec3> vector3s(const std::string& name) const;                 // vector3 / vector
  std::vector<std::array<float, 2>> point2s(const std::string& name) const;  // point2 (also a flat float list)

  // The parameters no lookup has touched, in file order.
  std::vector<const PbrtParam*> unused() const;

 private:
  const PbrtParam* typed(const std::string& name, std::initializer_list<const char*> types) const;
};

}  // namespace pdrt
