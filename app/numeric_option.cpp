#include "app/numeric_option.h"

#include "sampling/core/errors.h"

#include <charconv>
#include <cmath>

namespace pdrt::cli {

uint64_t parse_integer_option(const std::string& option, const std::string& text, IntRange range) {
  auto refuse = [&](const char* why) {
    throw UsageError(option + " must be an integer in " + range.str() + ", got \"" + text + "\" (" + why + ")");
  };
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) {
    // Name the usual mistakes: a sign, a fraction or an exponent.
    double d = 0;
    auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), d);
    const bool number = !text.empty() && ec != std::errc::invalid_argument && p == text.data() + text.size();
    if (number && text[0] == '-') refuse("negative");
    refuse(number ? "not a whole number in decimal digits" : "not a number");
  }
  uint64_t v = 0;
  auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec == std::errc::result_out_of_range || !range.contains(v)) refuse("out of range");
  return v;
}

double parse_real_option(const std::string& option, const std::string& text) {
  double d = 0;
  std::string_view t = text;
  if (t.size() > 1 && t[0] == '+') t.remove_prefix(1);
  auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), d);
  if (t.empty() || ec != std::errc() || p != t.data() + t.size() || !std::isfinite(d))
    throw UsageError(option + " must be a finite number, got \"" + text + "\"");
  return d;
}

double parse_positive_real_option(const std::string& option, const std::string& text) {
  const double d = parse_real_option(option, text);
  if (!(d > 0)) throw UsageError(option + " must be > 0, got \"" + text + "\"");
  return d;
}

std::string option_display_name(const std::string& names) {
  std::string first;
  for (size_t b = 0; b <= names.size();) {
    size_t e = names.find(',', b);
    if (e == std::string::npos) e = names.size();
    std::string n = names.substr(b, e - b);
    if (n.rfind("--", 0) == 0) return n;
    if (first.empty()) first = n;
    b = e + 1;
  }
  return first;
}

}  // namespace pdrt::cli
