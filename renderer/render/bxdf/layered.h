#pragma once
// pbrt-v4's layered BSDF (Pharr, Jakob & Humphreys, 4th ed. §14.3; bxdfs.h LayeredBxDF with
// CoatedDiffuseBxDF and CoatedConductorBxDF): a dielectric interface (coat_interface.h) over an
// opaque base (layer_base.h), a slab of `thickness` between them holding a homogeneous medium
// of extinction 1 per unit thickness, single-scattering `albedo` and Henyey-Greenstein `g`
// (albedo 0: it only absorbs, transmittance exp(-thickness / |cos|) per crossing). Two-sided,
// reflection only (the base is opaque).
// f, pdf and sample are stochastic, as pbrt-v4's: random walks through the slab of at most
// `max_depth` events (Russian roulette after 3 once the throughput is below 1/4), `samples`
// walks per call.
//   eval    pbrt-v4's f(): the entrance reflection plus walks entering the top, each vertex at
//           the base (or in the medium) connected to wi through the top by next-event
//           estimation, MIS (power heuristic) against the walk's own sampled direction.
//   sample  pbrt-v4's Sample_f(): sample the top; reflection is returned, transmission starts a
//           walk until the top transmits back out. weight = the walk's f cos / pdf (unbiased for
//           f cos / the true density), pdf = this->pdf() (pbrt-v4's pdfIsProportional), or the
//           product of discrete probabilities for a path of specular events only (delta).
//   pdf     pbrt-v4's PDF(): an estimate for MIS only, 0.1 / (4 pi) + 0.9 (entrance reflection
//           pdf + a stochastic estimate of the pdf through the slab); it need not integrate to 1
//           (MIS stays unbiased with any positive weights that sum to one).
// Replayable: the random numbers of one call come from a pcg stream seeded by a hash of the
// caller's key (PixelSampleState::walk_key: seed, pixel, sample index, vertex), the call's kind
// and its direction (and sample) arguments; no state outlives a call.
#include "renderer/render/bxdf/bsdf_sample.h"
#include "renderer/render/bxdf/coat_interface.h"
#include "renderer/render/bxdf/layer_base.h"
#include "renderer/scene/material.h"

#include <cstdint>

namespace pdrt {

class Rng;

class LayeredBxdf {
 public:
  static constexpr bool kDelta = false;  // delta() decides at run time
  static constexpr bool kKeyed = true;   // eval, pdf and sample take the random-walk key
  LayeredBxdf() = default;
  // How f() weighs a walk's direction leaving through the top against the virtual light path
  // (tests/renderer/render/test_layered_bxdf.cpp measures both):
  //   Pbrt        as pbrt-v4 (bxdfs.h): with the top's pdf of wi given the inner direction, a
  //               density over outside directions where the light path's is over inside ones,
  //               so the two weights need not sum to one; f() of a rough coat comes out above
  //               Sample_f()'s mean (pbrt-v4 issue #187: "f() and PDF() ... different result
  //               than using Sample() directly"). The default: pbrt-v4's images.
  //   Consistent  with the light path's own density of that inner direction: f() and
  //               Sample_f() then agree.
  enum class ExitMis { Pbrt, Consistent };
  LayeredBxdf(const CoatInterface& top, const LayerBase& bottom, const CoatLayers& layers,
              ExitMis exit_mis = ExitMis::Pbrt);
  // coated_diffuse with "model": "layered", and coated_conductor, as pbrt-v4's materials.cpp
  // builds them (the conductor's eta and k relative to the coat: divided by its index).
  static LayeredBxdf coated_diffuse(const Material& m);
  static LayeredBxdf coated_conductor(const Material& m);

  Vec3 eval(Vec3 wo, Vec3 wi, uint64_t key) const;
  float pdf(Vec3 wo, Vec3 wi, uint64_t key) const;
  bool sample(Vec3 wo, float u1, float u2, float uc, BsdfSample* out, uint64_t key) const;
  // Every path is specular (smooth coat over a smooth conductor, no scattering medium): no
  // light sampling, as pbrt-v4's flags without Diffuse or Glossy.
  bool delta() const { return top_.specular() && bottom_.specular() && !scatters_; }

 private:
  Vec3 walk_eval(const Vec3& wi, const LayerSample& wos, const LayerSample& wis, Rng& rng) const;
  bool walk_sample(const LayerSample& entered, Rng& rng, BsdfSample* out) const;
  float tr(float dz, const Vec3& w) const;
  float exit_mis_pdf(const Vec3& w, const Vec3& wi) const;  // w: the inner direction toward the top

  ExitMis exit_mis_ = ExitMis::Pbrt;  // transmittance of a straight segment of height dz

  CoatInterface top_;
  LayerBase bottom_ = LayerBase::diffuse(Vec3(0.0f));
  float thickness_ = 0.01f;
  Vec3 albedo_{0.0f};
  bool scatters_ = false;  // albedo is not black
  float g_ = 0;
  int max_depth_ = 10, samples_ = 1;
};

}  // namespace pdrt
