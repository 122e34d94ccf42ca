#include "renderer/scene/obj_loader.h"

#include "sampling/core/errors.h"
#include "sampling/core/printable.h"
#include "renderer/scene/text_file.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <span>
#include <sstream>
#include <string_view>
#include <tuple>

namespace pdrt {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw InputError(printable(where + ": " + what));
}

std::string in_quotes(std::string_view s) {
  std::string r(1, '"');  // built up, not '"' + s, which trips a GCC 12 -Wrestrict false positive
  r.append(s);
  r += '"';
  return r;
}

// `out` is cleared and reused: a large OBJ has a million lines.
void split_ws(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    size_t b = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > b) out.push_back(line.substr(b, i - b));
  }
}

template <class T>
bool parse_whole(std::string_view s, T& out) {
  if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);  // from_chars rejects "+1", OBJ writers emit it
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && p == s.data() + s.size();
}

// mtllib file names as tinyobjloader splits them: on spaces only, "\ " escaping a space.
std::vector<std::string> mtllib_names(std::string_view rest) {
  std::vector<std::string> names;
  std::string cur;
  for (size_t i = 0; i < rest.size(); ++i) {
    if (rest[i] == '\\' && i + 1 < rest.size() && rest[i + 1] == ' ') {
      cur += ' ', ++i;
    } else if (rest[i] == ' ') {
      if (!cur.empty()) names.push_back(cur), cur.clear();
    } else {
      cur += rest[i];
    }
  }
  if (!cur.empty()) names.push_back(cur);
  return names;
}

struct UseMtl {
  int line;
  std::string name;
};

// tinyobjloader reads out-of-range face indices without complaint (or reports only the
// last line of the file), so check the text first, with line numbers, before it runs.
std::vector<UseMtl> check_obj_text(const std::string& text, const std::string& name, const fs::path& dir,
                                   int64_t& short_faces) {
  std::vector<std::string_view> lines;
  for (size_t b = 0; b <= text.size();) {
    size_t e = text.find('\n', b);
    if (e == std::string::npos) e = text.size();
    std::string_view l(text.data() + b, e - b);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    lines.push_back(l);
    b = e + 1;
  }
  auto keyword = [](const std::vector<std::string_view>& tok) { return tok.empty() ? std::string_view() : tok[0]; };
  std::vector<std::string_view> tok;
  long total_v = 0, total_vn = 0, total_vt = 0;
  for (std::string_view l : lines) {  // the first token alone
    const size_t b = std::min(l.find_first_not_of(" \t"), l.size());
    const std::string_view kw = l.substr(b, l.find_first_of(" \t", b) - b);
    total_v += kw == "v", total_vn += kw == "vn", total_vt += kw == "vt";
  }
  std::vector<UseMtl> usemtl;
  long seen_v = 0, seen_vn = 0, seen_vt = 0;
  for (size_t li = 0; li < lines.size(); ++li) {
    // The location, built only for a message.
    struct Where {
      const std::string& name;
      size_t line;
      operator std::string() const { return name + ":" + std::to_string(line); }
    } at{name, li + 1};
    split_ws(lines[li], tok);
    std::string_view kw = keyword(tok);
    if (kw == "v" || kw == "vn") {
      if (tok.size() < 4) fail(at, std::string(kw == "v" ? "vertex" : "normal") + " needs 3 coordinates");
      for (size_t k = 1; k < tok.size(); ++k) {
        float x;
        if (!parse_whole(tok[k], x) || !std::isfinite(x))
          fail(at, std::string(kw == "v" ? "vertex" : "normal") + " coordinate " + in_quotes(tok[k]) +
                       " is not a finite number");
      }
      if (kw == "vn") {
        float x, y, z;
        parse_whole(tok[1], x), parse_whole(tok[2], y), parse_whole(tok[3], z);
        if (x == 0 && y == 0 && z == 0) fail(at, "normal has zero length");
      }
      (kw == "v" ? seen_v : seen_vn)++;
    } else if (kw == "vt") {
      // u [v [w]]: pdrt uses u and v (a missing v is 0, as tinyobjloader reads it).
      if (tok.size() < 2) fail(at, "texture coordinate needs u (and v)");
      for (size_t k = 1; k < tok.size(); ++k) {
        float x;
        if (!parse_whole(tok[k], x) || !std::isfinite(x))
          fail(at, "texture coordinate " + in_quotes(tok[k]) + " is not a finite number");
      }
      ++seen_vt;
    } else if (kw == "f") {
      if (tok.size() < 4) ++short_faces;
      for (size_t k = 1; k < tok.size(); ++k) {
        // v, v/t, v//n or v/t/n (t is required after one slash, n after two). OBJ indices
        // are 1-based; negative ones count back from the last vertex read.
        std::string_view t = tok[k];
        std::array<std::string_view, 3> part_at;
        size_t n_parts = 0;
        for (size_t b = 0;;) {
          size_t e = t.find('/', b);
          if (n_parts == part_at.size()) fail(at, "bad face vertex " + in_quotes(t));
          part_at[n_parts++] = t.substr(b, e == std::string_view::npos ? e : e - b);
          if (e == std::string_view::npos) break;
          b = e + 1;
        }
        const std::span<const std::string_view> parts(part_at.data(), n_parts);
        bool shape_ok = (parts.size() != 2 || !parts[1].empty()) && (parts.size() != 3 || !parts[2].empty());
        if (!shape_ok) fail(at, "bad face vertex " + in_quotes(t));
        auto check = [&](std::string_view part, long total, long seen, const char* what, const char* plural) {
          long idx = 0;
          if (!parse_whole(part, idx)) fail(at, "bad face vertex " + in_quotes(t));
          if (idx == 0) fail(at, std::string("face ") + what + "index 0 is invalid (OBJ indices start at 1)");
          bool ok = idx > 0 ? idx <= total : seen + idx >= 0;
          if (!ok)
            fail(at, std::string("face ") + what + "index " + std::to_string(idx) + " out of range (" +
                         std::to_string(idx > 0 ? total : seen) + " " + plural + ")");
        };
        check(parts[0], total_v, seen_v, "", "vertices");
        if (parts.size() == 3) check(parts[2], total_vn, seen_vn, "normal ", "normals");
        if (parts.size() >= 2 && !parts[1].empty())
          check(parts[1], total_vt, seen_vt, "texture coordinate ", "texture coordinates");
      }
    } else if (kw == "mtllib") {
      // tinyobjloader skips one separator after the keyword, then splits on spaces.
      size_t start = std::min(lines[li].find("mtllib") + 7, lines[li].size());
      auto files = mtllib_names(lines[li].substr(start));
      if (files.empty()) fail(at, "mtllib names no file");
      for (const std::string& f : files) {
        std::string reason;
        if (!can_open_file(dir / f, reason)) fail(at, "mtllib cannot open " + in_quotes(f) + ": " + reason);
      }
    } else if (kw == "usemtl" && tok.size() >= 2) {
      usemtl.push_back({int(li + 1), std::string(tok[1])});
    }
  }
  return usemtl;
}

// Reads MTL files relative to the OBJ's directory. tinyobjloader's own reader splits its
// base directory on ':' (a search path), which breaks directories containing one.
class MtlReader : public tinyobj::MaterialReader {
 public:
  explicit MtlReader(fs::path dir) : dir_(std::move(dir)) {}
  bool operator()(const std::string& id, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* by_name, std::string* warn, std::string* err) override {
    std::string reason;
    auto text = read_text_file(dir_ / id, reason);
    if (!text) {
      if (warn) *warn += "Material file [ " + id + " ] cannot be read: " + reason + "\n";
      return false;
    }
    std::istringstream in(*text);
    tinyobj::LoadMtl(by_name, materials, &in, warn, err);
    return true;
  }

 private:
  fs::path dir_;
};

Vec3 rgb(const tinyobj::real_t* c) { return {float(c[0]), float(c[1]), float(c[2])}; }

std::string rgb_text(const Vec3& c) {
  std::ostringstream s;
  s << "[" << c.x << ", " << c.y << ", " << c.z << "]";
  return s.str();
}

// The MTL -> Material mapping of docs/scene-format.md ("OBJ materials").
Material material_from_mtl(const tinyobj::material_t& m, const std::string& stem, const std::string& obj_name) {
  std::string at = obj_name + ": material " + in_quotes(m.name);
  auto color = [&](const char* key, const tinyobj::real_t* c, bool unit) {
    Vec3 v = rgb(c);
    if (!is_finite(v) || std::min({v.x, v.y, v.z}) < 0 || (unit && max_component(v) > 1))
      fail(at, std::string(key) + (unit ? " must be in [0,1], got " : " must be >= 0, got ") + rgb_text(v));
    return v;
  };
  Vec3 kd = color("Kd", m.diffuse, true), ks = color("Ks", m.specular, true), ke = color("Ke", m.emission, false);
  Vec3 tf = color("Tf", m.transmittance, true);
  if (!std::isfinite(m.shininess) || m.shininess < 0) fail(at, "Ns must be >= 0, got " + std::to_string(m.shininess));
  if (!std::isfinite(m.ior) || m.ior <= 0) fail(at, "Ni must be > 0, got " + std::to_string(m.ior));
  if (!std::isfinite(m.dissolve) || m.dissolve < 0 || m.dissolve > 1)
    fail(at, "d must be in [0,1], got " + std::to_string(m.dissolve));

  Material r;
  r.name = stem + "/" + m.name;
  if (!is_black(ke)) {
    r.type = MaterialType::Emitter;
    r.radiance = ke;
  } else if (m.illum == 4 || m.illum == 6 || m.illum == 7 || m.dissolve < 1) {
    r.type = MaterialType::Dielectric;
    // tinyobjloader stores 1 when Ni is absent; an ior of exactly 1 would be invisible anyway.
    r.ior = m.ior == 1 ? 1.5f : float(m.ior);
    r.albedo = is_black(tf) ? Vec3(1.0f) : tf;
  } else if (max_component(ks) > 0 && m.shininess > 0 && max_component(ks) >= max_component(kd)) {
    r.type = MaterialType::Glossy;
    r.lobe = GlossLobe::Phong;
    r.exponent = float(m.shininess);
    r.albedo = ks;
  } else {
    r.type = MaterialType::Diffuse;
    r.albedo = kd;
  }
  return r;
}

struct Corner {
  int v, n, t;  // position, normal and texture coordinate indices (-1: none)
};

// An OBJ is text: a NUL or other control byte means a binary (or wrong) file, which would
// otherwise surface as "no triangles" or a confusing parse error.
void check_is_text(std::string_view text, const std::string& name) {
  if (text.find_first_not_of(" \t\r\n\f\v") == std::string_view::npos)
    fail(name,
         text.empty() ? "empty file, expected OBJ text (v and f lines)" : "holds only white space, expected OBJ text");
  int line = 1;
  for (unsigned char c : text) {
    if (c == '\n') ++line;
    if ((c < 0x20 && c != '\t' && c != '\r' && c != '\n' && c != '\f' && c != '\v') || c == 0x7F) {
      char byte[8];
      std::snprintf(byte, sizeof byte, "0x%02X", c);
      fail(name + ":" + std::to_string(line),
           std::string("not a text file (control byte ") + byte + "); an OBJ must be Wavefront text");
    }
  }
}

}  // namespace

ObjModel load_obj(const fs::path& file, bool override_materials) {
  const std::string name = file.string();
  std::string reason;
  auto text = read_text_file(file, reason);
  if (!text) fail(name, "cannot open: " + reason);
  check_is_text(*text, name);
  ObjModel model;
  std::vector<UseMtl> usemtl = check_obj_text(*text, name, file.parent_path(), model.degenerate_triangles);

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  // tinyobjloader reads a stream: one over the text already in memory (an istringstream would
  // copy tens of megabytes).
  struct TextBuf : std::streambuf {
    explicit TextBuf(std::string& t) { setg(t.data(), t.data(), t.data() + t.size()); }
  } buf(*text);
  std::istream in(&buf);
  MtlReader mtl(file.parent_path());
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, &mtl, /*triangulate=*/true))
    fail(name, err.empty() ? "tinyobjloader failed" : err.substr(0, err.find('\n')));
  // The line checks above catch these first; this is the net for anything they missed.
  for (const char* bad : {"Material file", "Failed to load material"})
    if (size_t p = warn.find(bad); p != std::string::npos) fail(name, warn.substr(p, warn.find('\n', p) - p));
  if (!override_materials) {
    std::map<std::string, int> known;
    for (size_t i = 0; i < materials.size(); ++i) known[materials[i].name] = int(i);
    for (const UseMtl& u : usemtl)
      if (!known.count(u.name))
        fail(name + ":" + std::to_string(u.line),
             "usemtl " + in_quotes(u.name) + " names no material in the mtllib files");
  }

  // Group triangles by material (-1 = none), keeping tinyobjloader's material order.
  const long nv = long(attrib.vertices.size() / 3), nn = long(attrib.normals.size() / 3),
             nt = long(attrib.texcoords.size() / 2);
  std::map<int, std::vector<Corner>> groups;
  for (const tinyobj::shape_t& s : shapes) {
    size_t offset = 0;
    for (size_t f = 0; f < s.mesh.num_face_vertices.size(); ++f) {
      size_t count = s.mesh.num_face_vertices[f];
      if (count != 3) fail(name, "tinyobjloader left a face with " + std::to_string(count) + " vertices");
      int mat = override_materials ? -1 : s.mesh.material_ids[f];
      auto& g = groups[mat];
      for (size_t k = 0; k < 3; ++k) {
        const tinyobj::index_t& ix = s.mesh.indices[offset + k];
        if (ix.vertex_index < 0 || ix.vertex_index >= nv || ix.normal_index >= nn || ix.texcoord_index >= nt)
          fail(name, "face index out of range after triangulation");
        g.push_back({ix.vertex_index, ix.normal_index, ix.texcoord_index});
      }
      offset += count;
    }
  }

  auto position = [&](int v) {
    return Vec3(attrib.vertices[3 * v], attrib.vertices[3 * v + 1], attrib.vertices[3 * v + 2]);
  };
  const std::string stem = file.stem().string();
  // Per position, its first (normal, texture coordinate) in the current group and that mesh
  // vertex; the group's other combinations in `others`.
  struct First {
    int group = -1, n = 0, t = 0;
    uint32_t index = 0;
  };
  std::vector<First> first(static_cast<std::size_t>(nv));
  std::map<std::tuple<int, int, int>, uint32_t> others;
  int group = -1;
  for (auto& [mat, corners] : groups) {
    bool has_normals = true, has_uvs = true;
    for (const Corner& c : corners) has_normals &= c.n >= 0, has_uvs &= c.t >= 0;
    ObjPart part;
    // Each distinct (vertex, normal, texture coordinate) becomes one mesh vertex, numbered in
    // order of first use. Most OBJs give a position one normal and one texture coordinate, so
    // the first combination of each position is kept in an array and only others in a map.
    ++group;
    others.clear();
    auto vertex = [&](const Corner& c) {
      const int n = has_normals ? c.n : -1, t = has_uvs ? c.t : -1;
      const uint32_t next = uint32_t(part.mesh.positions.size());
      First& f = first[std::size_t(c.v)];
      uint32_t index;
      if (f.group != group) {
        f = {group, n, t, next}, index = next;
      } else if (f.n == n && f.t == t) {
        return f.index;
      } else {
        auto [it, added] = others.try_emplace({c.v, n, t}, next);
        if (!added) return it->second;
        index = next;
      }
      part.mesh.positions.push_back(position(c.v));
      if (has_normals)
        part.mesh.normals.push_back(
            {attrib.normals[3 * c.n], attrib.normals[3 * c.n + 1], attrib.normals[3 * c.n + 2]});
      if (has_uvs) part.mesh.uvs.push_back({attrib.texcoords[2 * c.t], attrib.texcoords[2 * c.t + 1]});
      return index;
    };
    for (size_t t = 0; t < corners.size(); t += 3) {
      const Corner *a = &corners[t], *b = a + 1, *c = a + 2;
      Vec3 n = cross(position(b->v) - position(a->v), position(c->v) - position(a->v));
      if (a->v == b->v || b->v == c->v || a->v == c->v || is_black(n)) {
        ++model.degenerate_triangles;
        continue;
      }
      for (const Corner* k : {a, b, c}) part.mesh.indices.push_back(vertex(*k));
    }
    if (part.mesh.indices.empty()) continue;
    if (!override_materials) {
      if (mat >= 0) {
        part.material = material_from_mtl(materials[mat], stem, name);
      } else {
        part.material = Material{};
        part.material->name = stem + "/default";
      }
    }
    model.parts.push_back(std::move(part));
  }
  return model;
}

}  // namespace pdrt
