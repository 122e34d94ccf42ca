#pragma once
// A compensated lobe (ggx_reflection.h, rough_dielectric.h) is a mixture: its single-scattering
// lobe with probability 1 - p and the compensation lobe with p (their ms_probability). f and
// the pdf add, and a sample of either lobe carries the whole f cos over the whole pdf, so that
// MIS sees the mixture's pdf.
#include "renderer/render/bxdf/bsdf_sample.h"

#include <cmath>

namespace pdrt {

inline float ms_mixture_pdf(float p, float pdf_ss, float pdf_ms) { return (1.0f - p) * pdf_ss + p * pdf_ms; }

// `out` holds a sample of the single-scattering lobe (weight f_ss cos / pdf_ss, pdf pdf_ss);
// pdf_ms and f_ms are the compensation lobe's at out->wi. False when the mixture's pdf is 0.
inline bool ms_mixture_from_single(float p, float pdf_ms, const Vec3& f_ms, BsdfSample* out) {
  float cos_i = std::abs(out->wi.z), pdf_ss = out->pdf;
  out->pdf = ms_mixture_pdf(p, pdf_ss, pdf_ms);
  if (!(out->pdf > 0)) return false;
  out->weight = (out->weight * pdf_ss + f_ms * cos_i) / out->pdf;
  return true;
}

// `out->wi` drawn from the compensation lobe; pdf and f are the whole mixture's there.
inline bool ms_mixture_from_compensation(float pdf, const Vec3& f, BsdfSample* out) {
  out->pdf = pdf;
  if (!(out->pdf > 0)) return false;
  out->weight = f * (std::abs(out->wi.z) / out->pdf);
  return true;
}

}  // namespace pdrt
