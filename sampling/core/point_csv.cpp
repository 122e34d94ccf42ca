#include "sampling/core/point_csv.h"

#include "sampling/core/atomic_file.h"
#include "sampling/core/errors.h"
#include "sampling/core/text_writer.h"
#include "sampling/core/input_file.h"
#include "sampling/core/point_set.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace pdrt {

void write_point_csv(const std::filesystem::path& path, const PointSet& points) {
  write_file_atomically(path, [&](std::ostream& out) {
    TextWriter w(out);
    for (int k = 0; k < points.dim; ++k) {
      w.put(k ? ",x" : "x");
      w.integer(k);
    }
    if (points.has_radius()) w.put(",radius");
    w.put('\n');
    for (std::size_t i = 0; i < points.size(); ++i) {
      auto p = points.point(i);
      for (int k = 0; k < points.dim; ++k) {
        if (k) w.put(',');
        w.number(p[k]);
      }
      if (points.has_radius()) {
        w.put(',');
        w.number(points.radius[i]);
      }
      w.put('\n');
    }
  });
}

namespace {
std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    std::size_t c = s.find(',', start);
    out.push_back(s.substr(start, c == std::string::npos ? std::string::npos : c - start));
    if (c == std::string::npos) break;
    start = c + 1;
  }
  for (auto& f : out) {
    while (!f.empty() && (f.back() == ' ' || f.back() == '\r' || f.back() == '\t')) f.pop_back();
    while (!f.empty() && (f.front() == ' ' || f.front() == '\t')) f.erase(f.begin());
  }
  return out;
}
}  // namespace

PointSet read_point_csv(const std::filesystem::path& path) {
  std::ifstream in = open_for_reading(path, std::ios::in);
  const std::string name = path.string();
  std::string line;
  if (!std::getline(in, line) || split(line).empty() || (split(line).size() == 1 && split(line)[0].empty()))
    throw InputError(name + ":1: empty file, expected a header x0,x1,...[,radius]");
  auto header = split(line);
  PointSet ps;
  bool has_radius = header.back() == "radius";
  int dim = int(header.size()) - (has_radius ? 1 : 0);
  for (int k = 0; k < dim; ++k)
    if (header[k].size() < 2 || header[k][0] != 'x' || header[k].substr(1) != std::to_string(k))
      throw InputError(name + ":1: bad header column " + std::to_string(k + 1) + " '" + header[k] + "', expected 'x" +
                       std::to_string(k) + "'");
  if (dim < 1 || dim > kMaxDim)
    throw InputError(name + ":1: " + std::to_string(dim) + " coordinate columns, expected 1 to " +
                     std::to_string(kMaxDim));
  ps.dim = dim;
  std::size_t columns = header.size();
  long lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line == "\r") continue;
    auto f = split(line);
    if (f.size() != columns)
      throw InputError(name + ":" + std::to_string(lineno) + ": " + std::to_string(f.size()) + " columns, expected " +
                       std::to_string(columns));
    for (std::size_t k = 0; k < columns; ++k) {
      double v = 0;
      const char* b = f[k].data();
      const char* e = b + f[k].size();
      auto [ptr, ec] = std::from_chars(b, e, v);
      if (f[k].empty() || ec != std::errc() || ptr != e)
        throw InputError(name + ":" + std::to_string(lineno) + ": column " + std::to_string(k + 1) + ": '" + f[k] +
                         "' is not a number");
      if (!std::isfinite(v))
        throw InputError(name + ":" + std::to_string(lineno) + ": column " + std::to_string(k + 1) + ": " + f[k] +
                         " is not finite");
      if (int(k) < dim) {
        if (v < 0.0 || v >= 1.0)
          throw InputError(name + ":" + std::to_string(lineno) + ": x" + std::to_string(k) + " = " + f[k] +
                           " is outside [0,1)");
        ps.coords.push_back(v);
      } else {
        if (v < 0.0) throw InputError(name + ":" + std::to_string(lineno) + ": radius " + f[k] + " is negative");
        ps.radius.push_back(v);
      }
    }
  }
  if (ps.coords.empty()) throw InputError(name + ":2: no points after the header");
  return ps;
}

}  // namespace pdrt
