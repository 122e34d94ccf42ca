#pragma once
// An enum's names: one table of (value, name) per vocabulary, the only place its names are
// written. Parsing, printing, the lists in messages and help, and JSON choices all read it.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace pdrt {

template <class E>
struct NamedValue {
  E value;
  const char* name;
};

// The name of `v` ("?" for a value the table lacks, which a static_assert beside each table rules out).
template <class E, std::size_t N>
constexpr const char* name_in(const NamedValue<E> (&table)[N], E v) {
  for (const NamedValue<E>& t : table)
    if (t.value == v) return t.name;
  return "?";
}

// False, leaving *out alone, for a name the table lacks.
template <class E, std::size_t N>
bool parse_name_in(const NamedValue<E> (&table)[N], const std::string& name, E* out) {
  for (const NamedValue<E>& t : table)
    if (name == t.name) return *out = t.value, true;
  return false;
}

// The value named `name`; std::invalid_argument for a name the table lacks.
template <class E, std::size_t N>
E value_named(const NamedValue<E> (&table)[N], const std::string& name) {
  E v{};
  if (!parse_name_in(table, name, &v)) throw std::invalid_argument("unknown name \"" + name + "\"");
  return v;
}

// Every name in table order.
template <class E, std::size_t N>
std::vector<std::string> names_in(const NamedValue<E> (&table)[N]) {
  std::vector<std::string> v;
  for (const NamedValue<E>& t : table) v.push_back(t.name);
  return v;
}

// "a, b, c" (or joined by `separator`, e.g. " | " for help text).
template <class E, std::size_t N>
std::string name_list(const NamedValue<E> (&table)[N], const char* separator = ", ") {
  std::string s;
  for (const NamedValue<E>& t : table) s += (s.empty() ? "" : separator) + std::string(t.name);
  return s;
}

// True when table[i] names the value i: tables list every value of 0..N-1 in order.
template <class E, std::size_t N>
constexpr bool covers_in_order(const NamedValue<E> (&table)[N]) {
  for (std::size_t i = 0; i < N; ++i)
    if (std::size_t(table[i].value) != i) return false;
  return true;
}

}  // namespace pdrt
