#pragma once
// Numeric command-line options parsed strictly. CLI11 wraps "-1" into 2^64-1 for unsigned
// targets and clamps or rounds some out-of-range text, so pdrt reads the text itself: an
// integer option takes only decimal digits, within its IntRange (the range is in the
// message); a real option takes only a finite number. Refusals are UsageErrors naming the
// option, thrown while the command line is parsed, before any work starts.
#include "sampling/core/int_range.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace pdrt::cli {

// --threads: 0 = all cores; TBB and Embree take any count, more than this is a typo.
inline constexpr IntRange kThreadsRange{0, 1024};

namespace detail {
template <class T>
struct option_value {
  using type = T;
};
template <class T>
struct option_value<std::optional<T>> {
  using type = T;
};
}  // namespace detail

uint64_t parse_integer_option(const std::string& option, const std::string& text, IntRange range);
double parse_real_option(const std::string& option, const std::string& text);
double parse_positive_real_option(const std::string& option, const std::string& text);

// "--seed" from "--seed,-s": the name messages use.
std::string option_display_name(const std::string& names);

// `target` is an integer type or std::optional of one; it is set only when the option is given.
template <class T>
CLI::Option* add_integer_option(CLI::App* cmd, const std::string& names, T& target, IntRange range,
                                const std::string& help) {
  const std::string name = option_display_name(names);
  return cmd
      ->add_option_function<std::string>(
          names,
          [&target, name, range](const std::string& s) {
            target = typename detail::option_value<T>::type(parse_integer_option(name, s, range));
          },
          help + " (integer in " + range.str() + ")")
      ->type_name("INT");
}

// `positive`: the number must be > 0 as well.
template <class T>
CLI::Option* add_real_option(CLI::App* cmd, const std::string& names, T& target, const std::string& help,
                             bool positive = false) {
  const std::string name = option_display_name(names);
  return cmd
      ->add_option_function<std::string>(
          names,
          [&target, name, positive](const std::string& s) {
            target = positive ? parse_positive_real_option(name, s) : parse_real_option(name, s);
          },
          help)
      ->type_name("FLOAT");
}

}  // namespace pdrt::cli
