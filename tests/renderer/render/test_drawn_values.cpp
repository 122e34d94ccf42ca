// Which sampler streams a render draws: a value nothing reads is not drawn (the shutter time of
// a scene where nothing moves, a pinhole camera's lens point, a lone light's pick number, a
// single lobe's choice, a mirror's direction), which saves the sampler's work and changes no
// image, since every decision is a stream of its own.
#include "renderer/render/renderer.h"
#include "renderer/render/sample_dimensions.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <atomic>
#include <memory>

namespace pdrt {
namespace {

using test::add_material;
using test::base_scene;
using test::diffuse;
using test::emitter;
using test::quad;
using test::sphere;

// `poisson` that records the (family, bounce) of every stream asked for, bounces below 64.
class RecordingSampler final : public Sampler {
 public:
  RecordingSampler() : Sampler(7), inner_(make_sampler("poisson", 7)) {}
  std::string name() const override { return "recording"; }
  double get_1d(int px, int py, int64_t i, Family f, int bounce) const override {
    note(f, bounce);
    return inner_->get_1d(px, py, i, f, bounce);
  }
  Vec2 get_2d(int px, int py, int64_t i, Family f, int bounce) const override {
    note(f, bounce);
    return inner_->get_2d(px, py, i, f, bounce);
  }
  void prepare(int px, int py, Family f, int bounce, PreparedStream* out) const override {
    note(f, bounce);
    inner_->prepare(px, py, f, bounce, out);
  }
  bool prepare_computes(Family f) const override { return inner_->prepare_computes(f); }
  int64_t samples_available(int px, int py) const override { return inner_->samples_available(px, py); }
  bool drawn(Family f, int bounce) const { return (seen_[int(f)].load() >> bounce) & 1; }

 private:
  void note(Family f, int bounce) const {
    if (bounce >= 0 && bounce < 64) seen_[int(f)].fetch_or(uint64_t(1) << bounce);
  }
  std::unique_ptr<Sampler> inner_;
  mutable std::atomic<uint64_t> seen_[kFamilyCount] = {};
};

// A diffuse sphere on a diffuse floor under one spherical light, seen by a pinhole camera.
SceneDesc one_light_scene() {
  SceneDesc s = base_scene(16, 12, 4);
  s.camera.position = {0, 1, 4}, s.camera.look_at = {0, 0.5f, 0};
  s.integrator.max_depth = 3;
  s.shapes.push_back(quad({-3, 0, -3}, {0, 0, 6}, {6, 0, 0}, add_material(s, diffuse(0.6f))));
  s.shapes.push_back(sphere({0, 0.6f, 0}, 0.6f, add_material(s, diffuse(0.5f))));
  // One light: a sphere (a quad emitter is two triangles, two lights to pick from).
  s.shapes.push_back(sphere({0, 3, 0}, 0.3f, add_material(s, emitter(10))));
  return s;
}

RecordingSampler& render_recorded(const SceneDesc& s, RecordingSampler& r) {
  RenderOptions o;
  o.quiet = true;
  render(s, r, o);
  return r;
}

TEST(DrawnValues, AStillSceneSeenByAPinholeWithOneLightAndDiffuseSurfacesDrawsOnlyWhatItReads) {
  RecordingSampler r;
  render_recorded(one_light_scene(), r);
  EXPECT_TRUE(r.drawn(Family::Pixel, kSaltFilmPoint));
  EXPECT_FALSE(r.drawn(Family::Time, kSaltShutterTime));  // nothing moves
  EXPECT_FALSE(r.drawn(Family::Lens, kSaltLensPoint));
  for (int d = 0; d < 3; ++d) {
    EXPECT_TRUE(r.drawn(Family::Light, salt_light_point(d))) << d;
    EXPECT_TRUE(r.drawn(Family::Gloss, salt_bsdf_direction(d))) << d;
    EXPECT_FALSE(r.drawn(Family::Time, salt_light_pick(d))) << d;
    EXPECT_FALSE(r.drawn(Family::Time, salt_lobe(d))) << d;
  }
}

TEST(DrawnValues, MotionAnApertureASecondLightAndACompensatedGlossyLobeAreDrawn) {
  SceneDesc s = one_light_scene();
  MotionKey k0, k1;
  k1.time = 1, k1.translate = {0.2f, 0, 0};
  s.shapes[1].motion = {k0, k1};  // the sphere moves: the shutter time matters
  s.camera.aperture_radius = 0.05f, s.camera.focus_distance = 4;
  s.shapes.push_back(quad({1.5f, 3, -0.5f}, {1, 0, 0}, {0, 0, 1}, add_material(s, emitter(5))));
  Material glossy;
  glossy.type = MaterialType::Glossy, glossy.lobe = GlossLobe::GGX, glossy.roughness = 0.4f, glossy.albedo = Vec3(0.7f);
  s.shapes[1].material = add_material(s, glossy);  // the sphere: GGX with its compensation lobe
  RecordingSampler r;
  render_recorded(s, r);
  EXPECT_TRUE(r.drawn(Family::Time, kSaltShutterTime));
  EXPECT_TRUE(r.drawn(Family::Lens, kSaltLensPoint));
  EXPECT_TRUE(r.drawn(Family::Time, salt_light_pick(0)));
  EXPECT_TRUE(r.drawn(Family::Time, salt_lobe(0)));
}

}  // namespace
}  // namespace pdrt
