#include "renderer/scene/render_settings.h"

#include "renderer/scene/crop_window.h"
#include "sampling/samplers/image_plane_pattern.h"
#include "sampling/core/errors.h"

#include <sstream>

namespace pdrt {

std::string adaptive_spp_problem(const AdaptiveDesc& ad) {
  if (!ad.enabled || ad.min_spp <= ad.max_spp) return "";
  return "min_spp (" + std::to_string(ad.min_spp) + ") must be <= max_spp (" + std::to_string(ad.max_spp) + ")";
}

std::string decision_problem(const AdaptiveDesc& ad, Reconstruction reconstruction) {
  if (!ad.enabled || ad.decision != AdaptiveDecision::Split || reconstruction != Reconstruction::Rank) return "";
  return std::string("\"") + adaptive_decision_name(AdaptiveDecision::Split) + "\" needs reconstruction \"" +
         reconstruction_name(Reconstruction::Importance) + "\" or \"" + reconstruction_name(Reconstruction::Splat) +
         "\", not \"" + reconstruction_name(Reconstruction::Rank) + "\"";
}

std::string crop_window_problem(const FilmDesc& f) {
  const PixelRect px = crop_pixels(f.crop_window, f.width, f.height);
  if (!px.empty()) return "";
  std::ostringstream s;
  s << "covers no pixel of the " << f.width << "x" << f.height << " film (pixels ceil(size * bound) are [" << px.x0
    << ", " << px.x1 << ") x [" << px.y0 << ", " << px.y1 << "))";
  return s.str();
}

std::string pixel_order_problem(const SamplerDesc& d, const FilmDesc& f) {
  SamplerKind kind{};
  if (!parse_sampler(d.type, &kind) || !orders_pixels(kind)) return "";
  const int spp = d.adaptive.enabled ? d.adaptive.min_spp : d.spp;
  const int bits = pixel_order_bits(spp, f.width, f.height);
  if (bits <= kPixelOrderBits) return "";
  return "\"" + d.type + "\" orders " + std::to_string(f.width) + "x" + std::to_string(f.height) + " pixels at " +
         std::to_string(spp) + " spp with " + std::to_string(bits) + " bits of Morton and sample index, at most " +
         std::to_string(kPixelOrderBits) + " (fewer samples per pixel or a smaller image)";
}

std::string image_plane_problem(const SamplerDesc& d, const FilmDesc& f) {
  SamplerKind kind{};
  if (!parse_sampler(d.type, &kind) || !samples_image_plane(kind)) return "";
  const std::string name = "\"" + d.type + "\"";
  if (d.adaptive.enabled)
    return name + " cannot refine adaptively (its pixels' samples are one image-plane pattern's, whose counts a " +
           "pixel cannot raise alone)";
  if (f.filter.reconstruction != Reconstruction::Splat)
    return name + " needs reconstruction \"" + reconstruction_name(Reconstruction::Splat) +
           "\" (its pixels take varying counts of one image-plane pattern's samples), got \"" +
           reconstruction_name(f.filter.reconstruction) + "\"";
  if (d.spp > kImagePlanePoints)
    return name + " takes at most " + std::to_string(kImagePlanePoints) +
           " spp (the points of its image-plane pattern), got " + std::to_string(d.spp);
  return "";
}

std::string sampler_problem(const SamplerDesc& d, const FilmDesc& f) {
  if (std::string p = pixel_order_problem(d, f); !p.empty()) return p;
  return image_plane_problem(d, f);
}

std::optional<SettingsProblem> render_settings_problem(const SceneDesc& s) {
  using Setting = SettingsProblem::Setting;
  const AdaptiveDesc& ad = s.sampler.adaptive;
  if (std::string p = adaptive_spp_problem(ad); !p.empty())
    return SettingsProblem{Setting::AdaptiveSpp, "adaptive: " + p};
  if (std::string p = decision_problem(ad, s.film.filter.reconstruction); !p.empty())
    return SettingsProblem{Setting::AdaptiveDecision, "adaptive decision " + p};
  if (std::string p = crop_window_problem(s.film); !p.empty())
    return SettingsProblem{Setting::CropWindow, "film.crop_window " + p};
  if (std::string p = pixel_order_problem(s.sampler, s.film); !p.empty())
    return SettingsProblem{Setting::PixelOrder, "sampler " + p};
  if (std::string p = image_plane_problem(s.sampler, s.film); !p.empty())
    return SettingsProblem{Setting::ImagePlane, "sampler " + p};
  return std::nullopt;
}

void check_render_settings(const SceneDesc& s) {
  const std::optional<SettingsProblem> p = render_settings_problem(s);
  if (!p) return;
  if (p->setting == SettingsProblem::Setting::CropWindow || p->setting == SettingsProblem::Setting::PixelOrder)
    throw InputError(s.film.size_where + ": " + p->message);
  if (p->setting == SettingsProblem::Setting::ImagePlane) throw InputError(s.sampler.type_where + ": " + p->message);
  throw InputError(p->message);
}

}  // namespace pdrt
