#include "renderer/scene/scene_writer.h"

#include "renderer/image/image_output.h"

#include "sampling/core/atomic_file.h"
#include "sampling/core/errors.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

namespace pdrt {
namespace {

ojson vec(const Vec3& v) { return ojson::array({v.x, v.y, v.z}); }

ojson matrix(const Affine& a) {
  ojson m = ojson::array();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) m.push_back(a.m[r][c]);
  return m;
}

bool identity(const Affine& a) { return a.m == Affine{}.m; }

ojson motion(const std::vector<MotionKey>& keys, bool sphere) {
  ojson out = ojson::array();
  for (const MotionKey& k : keys) {
    ojson j;
    j["time"] = k.time;
    j["translate"] = vec(k.translate);
    const double w = std::clamp(double(k.rotate.w), -1.0, 1.0), s = std::sqrt(std::max(0.0, 1 - w * w));
    if (s > 1e-12) {
      const double deg = 2 * std::acos(w) * 180 / M_PI;
      j["rotate"] = {{"axis", ojson::array({k.rotate.x / s, k.rotate.y / s, k.rotate.z / s})}, {"degrees", deg}};
    }
    // A sphere's keys scale uniformly (the loader's rule); its decomposition may differ in the last bit.
    if (sphere) {
      j["scale"] = k.scale.x;
    } else {
      j["scale"] = vec(k.scale);
    }
    out.push_back(j);
  }
  return out;
}

void place(ojson& j, const Affine& transform, const std::vector<MotionKey>& keys, bool sphere = false) {
  if (!identity(transform)) j["transform"] = {{"matrix", matrix(transform)}};
  if (!keys.empty()) j["motion"] = motion(keys, sphere);
}

// Built by appending: GCC 12's -Wrestrict misreads "t" + std::to_string(i) (a false positive).
std::string numbered(char prefix, size_t i) {
  std::string s(1, prefix);
  s += std::to_string(i);
  return s;
}
std::string texture_name(int i) { return numbered('t', size_t(i)); }

ojson texture_input(const TextureInput& in) {
  if (in.texture >= 0) return texture_name(in.texture);
  return vec(in.value);
}

const char* filter_name(TextureFilter f) {
  switch (f) {
    case TextureFilter::None:
      return "none";
    case TextureFilter::Bilinear:
      return "bilinear";
    case TextureFilter::Trilinear:
      return "trilinear";
    default:
      return "ewa";
  }
}

const char* wrap_name(TextureWrap w) {
  switch (w) {
    case TextureWrap::Repeat:
      return "repeat";
    case TextureWrap::Clamp:
      return "clamp";
    case TextureWrap::Black:
      return "black";
    default:
      return "mirror";
  }
}

const char* encoding_name(TextureEncoding e) {
  switch (e) {
    case TextureEncoding::Srgb:
      return "srgb";
    case TextureEncoding::Linear:
      return "linear";
    default:
      return "auto";
  }
}

Vec3 unit(Vec3 c) {
  for (int i = 0; i < 3; ++i) c[i] = std::clamp(c[i], 0.0f, 1.0f);
  return c;
}

// The slab of a layered coat (coated_diffuse "model": "layered", coated_conductor).
void layers(const CoatLayers& l, ojson& j) {
  j["thickness"] = l.thickness;
  j["medium_albedo"] = vec(unit(l.albedo));
  j["g"] = l.g;
  j["max_depth"] = l.max_depth;
  j["samples"] = l.samples;
}

ojson material(const Material& m) {
  ojson j;
  switch (m.type) {
    case MaterialType::Diffuse:
      j = {{"type", "diffuse"}, {"albedo", vec(unit(m.albedo))}};
      break;
    case MaterialType::Glossy:
      j = {{"type", "glossy"}, {"albedo", vec(unit(m.albedo))}};
      if (m.lobe == GlossLobe::Phong) {
        j["exponent"] = m.exponent;
      } else {
        j["roughness"] = m.roughness;
        j["energy_compensation"] = m.energy_compensation;
      }
      break;
    case MaterialType::Mirror:
      j = {{"type", "mirror"}, {"albedo", vec(unit(m.albedo))}};
      break;
    case MaterialType::Dielectric:
      j = {{"type", "dielectric"},
           {"albedo", vec(unit(m.albedo))},
           {"ior", m.ior},
           {"roughness", m.roughness},
           {"energy_compensation", m.energy_compensation}};
      break;
    case MaterialType::Conductor:
      j = {{"type", "conductor"},
           {"eta", vec(m.eta)},
           {"k", vec(m.k)},
           {"roughness", m.roughness},
           {"energy_compensation", m.energy_compensation}};
      break;
    case MaterialType::CoatedDiffuse:
      j = {{"type", "coated_diffuse"}, {"albedo", vec(unit(m.albedo))}, {"roughness", m.roughness}, {"ior", m.ior}};
      if (m.layered) {
        j["model"] = "layered";
        layers(m.layers, j);
      } else {
        j["coat_color"] = vec(unit(m.coat_color));
        j["coat_thickness"] = m.coat_thickness;
      }
      break;
    case MaterialType::CoatedConductor:
      j = {{"type", "coated_conductor"},
           {"roughness", m.roughness},
           {"ior", m.ior},
           {"eta", vec(m.eta)},
           {"k", vec(m.k)},
           {"base_roughness", m.base_roughness}};
      layers(m.layers, j);
      break;
    case MaterialType::Emitter:
      j = {{"type", "emitter"}, {"radiance", vec(m.radiance)}, {"two_sided", m.two_sided}};
      break;
    case MaterialType::ThinDielectric:
      j = {{"type", "thin_dielectric"}, {"albedo", vec(unit(m.albedo))}, {"ior", m.ior}};
      break;
    case MaterialType::Mix:
      j = {{"type", "mix"},
           {"materials", ojson::array({numbered('m', size_t(m.mix[0])), numbered('m', size_t(m.mix[1]))})},
           {"amount", std::clamp(m.amount, 0.0f, 1.0f)}};
      break;
  }
  for (const TextureBinding& b : m.textures) {
    switch (b.param) {
      case MaterialParam::Albedo:
        j["albedo"] = texture_name(b.texture);
        break;
      case MaterialParam::Roughness:
        j["roughness"] = texture_name(b.texture);
        break;
      case MaterialParam::CoatColor:
        j["coat_color"] = texture_name(b.texture);
        break;
      case MaterialParam::Radiance:
        j["radiance"] = texture_name(b.texture);
        j["scale"] = vec(m.radiance);
        break;
      case MaterialParam::Amount:
        j["amount"] = texture_name(b.texture);
        break;
      case MaterialParam::Reflectance:
        j.erase("eta"), j.erase("k");  // the loader takes reflectance instead of them
        j["reflectance"] = texture_name(b.texture);
        break;
      case MaterialParam::BaseRoughness:
        j["base_roughness"] = texture_name(b.texture);
        break;
    }
  }
  return j;
}

// Positions, normals and uvs at 9 significant digits: every float reads back exactly.
void write_obj(const MeshData& mesh, const fs::path& file) {
  write_file_atomically(file, [&](std::ostream& out) {
    char line[160];
    out << "# written by pdrt convert\n";
    for (const Vec3& p : mesh.positions) {
      std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
      out << line;
    }
    for (const Vec3& n : mesh.normals) {
      std::snprintf(line, sizeof line, "vn %.9g %.9g %.9g\n", n.x, n.y, n.z);
      out << line;
    }
    for (const auto& t : mesh.uvs) {
      std::snprintf(line, sizeof line, "vt %.9g %.9g\n", t[0], t[1]);
      out << line;
    }
    const bool n = !mesh.normals.empty(), t = !mesh.uvs.empty();
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
      out << "f";
      for (int k = 0; k < 3; ++k) {
        const uint32_t v = mesh.indices[i + k] + 1;
        out << ' ' << v;
        if (t || n) out << '/';
        if (t) out << v;
        if (n) out << '/' << v;
      }
      out << '\n';
    }
  });
}

// A mesh as inline JSON arrays (floats print with the shortest digits that read back exactly).
ojson inline_mesh(const MeshData& mesh) {
  ojson o = {{"type", "mesh"}};
  ojson v = ojson::array(), n = ojson::array(), t = ojson::array();
  for (const Vec3& p : mesh.positions) v.push_back(vec(p));
  for (const Vec3& p : mesh.normals) n.push_back(vec(p));
  for (const auto& uv : mesh.uvs) t.push_back(ojson::array({uv[0], uv[1]}));
  o["vertices"] = v;
  if (!mesh.normals.empty()) o["normals"] = n;
  if (!mesh.uvs.empty()) o["uvs"] = t;
  o["indices"] = mesh.indices;
  return o;
}

ojson camera_json(const CameraDesc& c) {
  ojson cam = {{"position", vec(c.position)},
               {"look_at", vec(c.look_at)},
               {"up", vec(c.up)},
               {"vfov_deg", c.vfov_deg},
               {"aperture_radius", c.aperture_radius}};
  if (c.focus_distance > 0) cam["focus_distance"] = c.focus_distance;
  if (c.aperture_blades)
    cam["aperture_blades"] = c.aperture_blades, cam["aperture_rotation_deg"] = c.aperture_rotation_deg;
  cam["shutter"] = ojson::array({c.shutter_open, c.shutter_close});
  if (c.flip_x) cam["flip_x"] = true;
  if (c.projection == CameraDesc::Projection::Orthographic)
    cam["type"] = "orthographic", cam["ortho_height"] = c.ortho_height;
  if (c.has_screen_window)
    cam["screen_window"] =
        ojson::array({c.screen_window[0], c.screen_window[1], c.screen_window[2], c.screen_window[3]});
  if (!c.motion.empty()) {
    cam["motion"] = ojson::array();
    for (const CameraKey& k : c.motion)
      cam["motion"].push_back({{"time", k.time}, {"position", vec(k.position)}, {"look_at", vec(k.look_at)}});
  }
  return cam;
}

// Film, sampler and integrator.
void write_render_options(const SceneDesc& s, ojson& j) {
  static const char* kFilters[] = {"box", "tent", "gaussian", "mitchell"};
  j["film"] = {{"width", s.film.width},
               {"height", s.film.height},
               {"filter",
                {{"type", kFilters[int(s.film.filter.type)]},
                 {"radius", s.film.filter.radius},
                 {"reconstruction", reconstruction_name(s.film.filter.reconstruction)}}},
               {"exposure", s.film.exposure}};
  if (s.film.filter.sigma > 0) j["film"]["filter"]["sigma"] = s.film.filter.sigma;
  if (s.film.crop_window != std::array<float, 4>{0, 1, 0, 1})
    j["film"]["crop_window"] =
        ojson::array({s.film.crop_window[0], s.film.crop_window[1], s.film.crop_window[2], s.film.crop_window[3]});
  ojson sampler = {{"type", s.sampler.type}, {"spp", s.sampler.spp}, {"seed", s.sampler.seed}};
  if (s.sampler.adaptive.enabled) {
    const AdaptiveDesc& a = s.sampler.adaptive;
    sampler["adaptive"] = {{"min_spp", a.min_spp},
                           {"max_spp", a.max_spp},
                           {"metric", adaptive_metric_name(a.metric)},
                           {"variance", adaptive_variance_name(a.variance)},
                           {"decision", adaptive_decision_name(a.decision)}};
    if (a.threshold > 0) sampler["adaptive"]["threshold"] = a.threshold;
  }
  j["sampler"] = sampler;
  j["integrator"] = {{"max_depth", s.integrator.max_depth}, {"rr_depth", s.integrator.rr_depth}};
  if (s.integrator.regularize) j["integrator"]["regularize"] = true;
  if (s.integrator.environment_sampling != EnvironmentSampling::Full)
    j["integrator"]["environment_sampling"] = environment_sampling_name(s.integrator.environment_sampling);
}

ojson textures_json(const SceneDesc& s) {
  ojson tx = ojson::object();
  for (size_t i = 0; i < s.textures.size(); ++i) {
    const TextureDesc& t = s.textures[i];
    ojson o;
    if (t.kind == TextureDesc::Kind::Constant) {
      o = {{"type", "constant"}, {"value", vec(unit(t.value))}};
    } else if (t.kind == TextureDesc::Kind::Checkerboard) {
      o = {{"type", "checkerboard"},
           {"scale", ojson::array({t.scale_u, t.scale_v})},
           {"color0", texture_input(t.color0)},
           {"color1", texture_input(t.color1)}};
    } else if (t.kind == TextureDesc::Kind::Image) {
      o = {{"type", "image"},
           {"file", fs::absolute(t.file).string()},
           {"filter", filter_name(t.filter)},
           {"wrap", wrap_name(t.wrap)},
           {"encoding", encoding_name(t.encoding)},
           {"scale", ojson::array({t.scale_u, t.scale_v})}};
    } else if (t.kind == TextureDesc::Kind::Scale) {
      o = {{"type", "scale"}, {"tex", texture_input(t.tex)}, {"scale", texture_input(t.scale)}};
    } else if (t.kind == TextureDesc::Kind::Mix) {
      o = {{"type", "mix"}, {"tex1", texture_input(t.tex1)}, {"tex2", texture_input(t.tex2)}};
      o["amount"] = t.amount.texture >= 0 ? ojson(texture_name(t.amount.texture))
                                          : ojson(std::clamp(t.amount.value.x, 0.0f, 1.0f));
    } else if (t.kind == TextureDesc::Kind::Invert) {
      o = {{"type", "invert"}, {"tex", texture_input(t.tex)}};
    } else {
      o = {{"type", "power"}, {"tex", texture_input(t.tex)}, {"exponent", t.exponent}};
    }
    tx[texture_name(int(i))] = o;
  }
  return tx;
}

// Shapes, prototypes (into j["prototypes"]) and instances; meshes as OBJ files beside
// json_file unless inlined.
ojson objects_json(const SceneDesc& s, const fs::path& json_file, const SceneWriteOptions& options, ojson& j) {
  const fs::path mesh_dir = json_file.parent_path() / (json_file.stem().string() + ".meshes");
  ojson objects = ojson::array();
  bool made_dir = false;
  // A shape as an object; meshes go to `mesh_dir / name`.
  auto shape_object = [&](const ShapeDesc& sh, const std::string& name) {
    ojson o;
    if (sh.kind == ShapeDesc::Kind::Sphere) {
      o = {{"type", "sphere"}, {"center", vec(sh.center)}, {"radius", sh.radius}};
    } else if (options.inline_meshes) {
      o = inline_mesh(sh.mesh);
    } else {
      if (!made_dir) {
        std::error_code ec;
        fs::create_directories(mesh_dir, ec);
        if (ec) throw InputError(mesh_dir.string() + ": cannot create the mesh folder: " + ec.message());
        made_dir = true;
      }
      write_obj(sh.mesh, mesh_dir / name);
      o = {{"type", "obj"}, {"file", (fs::path(mesh_dir.filename()) / name).string()}};
    }
    o["material"] = numbered('m', size_t(sh.material));
    place(o, sh.transform, sh.motion, sh.kind == ShapeDesc::Kind::Sphere);
    return o;
  };
  // Prototypes as p0, p1, ...: each mesh written once, however many instances place it.
  if (!s.prototypes.empty()) {
    ojson protos = ojson::object();
    for (size_t p = 0; p < s.prototypes.size(); ++p) {
      ojson shapes = ojson::array();
      for (size_t k = 0; k < s.prototypes[p].shapes.size(); ++k)
        shapes.push_back(
            shape_object(s.prototypes[p].shapes[k], numbered('p', p) + "_shape" + std::to_string(k) + ".obj"));
      protos[numbered('p', p)] = shapes;
    }
    j["prototypes"] = protos;
  }
  for (size_t i = 0; i < s.shapes.size(); ++i) {
    std::string name = "shape";
    name += std::to_string(i);
    name += ".obj";
    objects.push_back(shape_object(s.shapes[i], name));
  }
  for (const InstanceDesc& in : s.instances) {
    ojson o = {{"type", "instance"}, {"prototype", numbered('p', size_t(in.prototype))}};
    place(o, in.transform, in.motion);
    objects.push_back(o);
  }
  return objects;
}

// Delta lights and the environment; a resampled environment image is written beside json_file.
ojson lights_json(const SceneDesc& s, const fs::path& json_file) {
  ojson lights = ojson::array();
  for (const DeltaLightDesc& l : s.delta_lights) {
    ojson o;
    if (l.kind == DeltaLightDesc::Kind::Distant) {
      o = {{"type", "distant"}, {"direction", vec(l.direction)}, {"irradiance", vec(l.irradiance)}};
    } else {
      o = {{"type", l.kind == DeltaLightDesc::Kind::Point ? "point" : "spot"},
           {"position", vec(l.position)},
           {"intensity", vec(l.intensity)}};
      if (l.kind == DeltaLightDesc::Kind::Spot) {
        o["direction"] = vec(l.direction);
        o["cone_angle_deg"] = std::acos(std::clamp(double(l.cos_cone), -1.0, 1.0)) * 180 / M_PI;
        o["falloff_start_deg"] = std::acos(std::clamp(double(l.cos_falloff_start), -1.0, 1.0)) * 180 / M_PI;
      }
      place(o, l.transform, l.motion, true);
    }
    lights.push_back(o);
  }
  const EnvironmentDesc& e = s.environment;
  if (e.has_map()) {
    std::string file = fs::absolute(e.file).string();
    if (e.resampled) {
      // The image pdrt renders is not the file it came from: write it beside the scene.
      const fs::path exr = json_file.parent_path() / (json_file.stem().string() + ".environment.exr");
      write_linear_rgb(exr, e.width, e.height, e.rgb, {{"pdrt:source", e.file}});
      file = exr.filename().string();
    }
    lights.push_back(
        {{"type", "environment"}, {"file", file}, {"scale", vec(e.scale)}, {"rotation_deg", e.rotation_deg}});
  } else if (!is_black(e.radiance)) {
    lights.push_back({{"type", "environment"}, {"radiance", vec(e.radiance)}});
  }
  return lights;
}

}  // namespace

void write_scene_json(const SceneDesc& s, const fs::path& json_file, const SceneWriteOptions& options) {
  ojson j;
  j["camera"] = camera_json(s.camera);
  write_render_options(s, j);
  if (!s.textures.empty()) j["textures"] = textures_json(s);
  ojson mats = ojson::object();
  for (size_t i = 0; i < s.materials.size(); ++i) mats[numbered('m', i)] = material(s.materials[i]);
  j["materials"] = mats;
  j["objects"] = objects_json(s, json_file, options, j);
  const ojson lights = lights_json(s, json_file);
  if (!lights.empty()) j["lights"] = lights;
  write_file_atomically(json_file, [&](std::ostream& out) { out << j.dump(1) << "\n"; });
}

}  // namespace pdrt
