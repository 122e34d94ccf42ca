#include "app/unknown_options.h"

#include <algorithm>
#include <cctype>

namespace pdrt::cli {

int edit_distance(const std::string& a, const std::string& b) {
  const size_t n = a.size(), m = b.size();
  std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1));
  for (size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
  for (size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
  for (size_t i = 1; i <= n; ++i)
    for (size_t j = 1; j <= m; ++j) {
      int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::string nearest_name(const std::string& typed, const std::vector<std::string>& names) {
  std::string best;
  int best_d = 0;
  for (const std::string& name : names) {
    int d = edit_distance(typed, name);
    if (best.empty() || d < best_d) best = name, best_d = d;
  }
  // A typo is a few edits, relative to the word: "sampls" -> "samples", not "o" -> "seed".
  const int allowed = std::max<int>(1, static_cast<int>(std::min(typed.size(), best.size())) / 3);
  if (best.empty() || best_d > allowed) return "";
  return best;
}

namespace {

const CLI::App* chosen_subcommand(const CLI::App& app, int argc, const char* const* argv) {
  if (argc < 2) return nullptr;
  for (const CLI::App* sub : app.get_subcommands({}))
    if (sub->get_name() == argv[1]) return sub;
  return nullptr;
}

bool looks_like_option(const std::string& t) {
  return t.size() >= 2 && t[0] == '-' &&
         (std::isalpha(static_cast<unsigned char>(t[1])) || (t[1] == '-' && t.size() > 2));
}

}  // namespace

std::string describe_unexpected_arguments(const CLI::App& app, int argc, const char* const* argv) {
  const CLI::App* sub = chosen_subcommand(app, argc, argv);
  std::vector<std::string> longs, shorts;
  for (const CLI::App* scope : {&app, sub}) {
    if (!scope) continue;
    for (const CLI::Option* opt : scope->get_options()) {
      for (const std::string& l : opt->get_lnames()) longs.push_back(l);
      for (const std::string& s : opt->get_snames()) shorts.push_back(s);
    }
  }
  const std::string where = sub ? sub->get_name() + ": " : std::string();
  std::vector<std::string> unknown;
  for (int i = sub ? 2 : 1; i < argc; ++i) {
    std::string t = argv[i];
    if (t == "--") break;
    if (!looks_like_option(t)) continue;
    bool known;
    if (t[1] == '-') {
      std::string name = t.substr(2, t.find('=') == std::string::npos ? std::string::npos : t.find('=') - 2);
      known = std::find(longs.begin(), longs.end(), name) != longs.end();
      if (!known) {
        std::string near = nearest_name(name, longs);
        unknown.push_back("--" + name + (near.empty() ? "" : " (did you mean --" + near + "?)"));
      }
    } else {
      known = std::find(shorts.begin(), shorts.end(), t.substr(1, 1)) != shorts.end();
      if (!known) unknown.push_back(t.substr(0, 2));
    }
  }
  if (!unknown.empty()) {
    std::string msg = where + (unknown.size() == 1 ? "unknown option " : "unknown options ");
    for (size_t k = 0; k < unknown.size(); ++k) msg += (k ? ", " : "") + unknown[k];
    return msg;
  }
  // Every option was known: the extras are positional words, named in the order typed.
  std::vector<std::string> extras = sub ? sub->remaining() : app.remaining();
  std::string msg = where + (extras.size() == 1 ? "unexpected argument" : "unexpected arguments");
  for (const std::string& e : extras) msg += " \"" + e + "\"";
  return msg;
}

}  // namespace pdrt::cli
