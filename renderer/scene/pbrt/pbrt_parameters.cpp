#include "renderer/scene/pbrt/pbrt_parameters.h"

#include "sampling/core/errors.h"

#include <cmath>
#include <sstream>

namespace pdrt {

std::string pbrt_canonical_type(const std::string& type) {
  if (type == "point") return "point3";
  if (type == "normal") return "normal3";
  if (type == "vector") return "vector3";
  if (type == "color") return "rgb";
  for (const char* t : {"integer", "float", "point2", "vector2", "point3", "vector3", "normal3", "bool", "string",
                        "texture", "rgb", "spectrum", "blackbody"})
    if (type == t) return type;
  return "";
}

const PbrtParam* PbrtParams::find(const std::string& name) const {
  for (const PbrtParam& p : list)
    if (p.name == name) return &p;
  return nullptr;
}

const PbrtParam* PbrtParams::typed(const std::string& name, std::initializer_list<const char*> types) const {
  const PbrtParam* p = find(name);
  if (!p) return nullptr;
  const std::string t = pbrt_canonical_type(p->type);
  std::string expected;
  for (const char* want : types) {
    if (t == want) {
      p->used = true;
      return p;
    }
    expected += std::string(expected.empty() ? "" : " or ") + want;
  }
  throw InputError(p->where() + " must be of type " + expected + ", not " + p->type);
}

namespace {

void expect_one(const PbrtParam& p, size_t n) {
  if (n != 1) throw InputError(p.where() + " takes one value, got " + std::to_string(n));
}

}  // namespace

std::optional<double> PbrtParams::find_float(const std::string& name) const {
  const PbrtParam* p = typed(name, {"float"});
  if (!p) return std::nullopt;
  expect_one(*p, p->numbers.size());
  return p->numbers[0];
}

std::optional<int64_t> PbrtParams::find_int(const std::string& name) const {
  std::vector<int64_t> v = ints(name);
  const PbrtParam* p = find(name);
  if (!p) return std::nullopt;
  expect_one(*p, v.size());
  return v[0];
}

std::optional<bool> PbrtParams::find_bool(const std::string& name) const {
  const PbrtParam* p = typed(name, {"bool"});
  if (!p) return std::nullopt;
  expect_one(*p, p->bools.size());
  return bool(p->bools[0]);
}

std::optional<std::string> PbrtParams::find_string(const std::string& name) const {
  const PbrtParam* p = typed(name, {"string"});
  if (!p) return std::nullopt;
  expect_one(*p, p->strings.size());
  return p->strings[0];
}

std::optional<std::string> PbrtParams::find_texture(const std::string& name) const {
  const PbrtParam* p = typed(name, {"texture"});
  if (!p) return std::nullopt;
  expect_one(*p, p->strings.size());
  return p->strings[0];
}

std::vector<double> PbrtParams::floats(const std::string& name) const {
  const PbrtParam* p = typed(name, {"float"});
  return p ? p->numbers : std::vector<double>{};
}

std::vector<int64_t> PbrtParams::ints(const std::string& name) const {
  const PbrtParam* p = typed(name, {"integer"});
  if (!p) return {};
  std::vector<int64_t> out;
  out.reserve(p->numbers.size());
  for (double x : p->numbers) {
    if (!(x == std::floor(x) && std::abs(x) <= 9.007199254740992e15))
      throw InputError(p->where() + " must hold integers, got " + std::to_string(x));
    out.push_back(int64_t(x));
  }
  return out;
}

namespace {

std::vector<Vec3> triples(const PbrtParam* p) {
  if (!p) return {};
  if (p->numbers.size() % 3)
    throw InputError(p->where() + " needs a multiple of 3 values, got " + std::to_string(p->numbers.size()));
  std::vector<Vec3> out;
  out.reserve(p->numbers.size() / 3);
  for (size_t i = 0; i < p->numbers.size(); i += 3)
    out.push_back({float(p->numbers[i]), float(p->numbers[i + 1]), float(p->numbers[i + 2])});
  return out;
}

}  // namespace

std::vector<Vec3> PbrtParams::point3s(const std::string& name) const { return triples(typed(name, {"point3"})); }
std::vector<Vec3> PbrtParams::normal3s(const std::string& name) const { return triples(typed(name, {"normal3"})); }
std::vector<Vec3> PbrtParams::vector3s(const std::string& name) const { return triples(typed(name, {"vector3"})); }

std::vector<std::array<float, 2>> PbrtParams::point2s(const std::string& name) const {
  const PbrtParam* p = typed(name, {"point2", "float"});  // pbrt-v3 files give uv as a float list
  if (!p) return {};
  if (p->numbers.size() % 2)
    throw InputError(p->where() + " needs an even number of values, got " + std::to_string(p->numbers.size()));
  std::vector<std::array<float, 2>> out;
  out.reserve(p->numbers.size() / 2);
  for (size_t i = 0; i < p->numbers.size(); i += 2) out.push_back({float(p->numbers[i]), float(p->numbers[i + 1])});
  return out;
}

std::vector<const PbrtParam*> PbrtParams::unused() const {
  std::vector<const PbrtParam*> out;
  for (const PbrtParam& p : list)
    if (!p.used) out.push_back(&p);
  return out;
}

std::string pbrt_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace pdrt
