#include "renderer/compare/flip.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace pdrt {

namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;
using Rgb = std::array<double, 3>;

constexpr double kPi = 3.14159265358979323846;

// Linear sRGB (D65) to CIE XYZ.
constexpr Mat3 kRgbToXyz = {
    {{0.4124564, 0.3575761, 0.1804375}, {0.2126729, 0.7151522, 0.0721750}, {0.0193339, 0.1191920, 0.9503041}}};

Rgb mul(const Mat3& m, const Rgb& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

Mat3 inverse(const Mat3& m) {
  Mat3 r{};
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      // The cofactor of (j, i), by cyclic indices.
      const int a = (j + 1) % 3, b = (j + 2) % 3, c = (i + 1) % 3, d = (i + 2) % 3;
      r[i][j] = (m[a][c] * m[b][d] - m[a][d] * m[b][c]) / det;
    }
  return r;
}

const Mat3& xyz_to_rgb() {
  static const Mat3 m = inverse(kRgbToXyz);
  return m;
}

// The reference white: XYZ of RGB (1, 1, 1).
const Rgb& white() {
  static const Rgb w = mul(kRgbToXyz, {1, 1, 1});
  return w;
}

// Linear RGB to YyCxCz: Yy = 116 Y / Yw - 16, Cx = 500 (X / Xw - Y / Yw), Cz = 200 (Y / Yw - Z / Zw).
Rgb rgb_to_ycxcz(const Rgb& rgb) {
  const Rgb xyz = mul(kRgbToXyz, rgb);
  const double x = xyz[0] / white()[0], y = xyz[1] / white()[1], z = xyz[2] / white()[2];
  return {116 * y - 16, 500 * (x - y), 200 * (y - z)};
}

Rgb ycxcz_to_rgb(const Rgb& c) {
  const double y = (c[0] + 16) / 116;
  return mul(xyz_to_rgb(), {(y + c[1] / 500) * white()[0], y * white()[1], (y - c[2] / 200) * white()[2]});
}

// Linear RGB to CIE L*a*b* (white as above), Hunt-adjusted: a and b scaled by 0.01 L.
Rgb rgb_to_hunt_lab(const Rgb& rgb) {
  const Rgb xyz = mul(kRgbToXyz, rgb);
  constexpr double d = 6.0 / 29;
  auto f = [&](double t) { return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29; };
  const double fx = f(xyz[0] / white()[0]), fy = f(xyz[1] / white()[1]), fz = f(xyz[2] / white()[2]);
  const double L = 116 * fy - 16;
  return {L, 0.01 * L * 500 * (fx - fy), 0.01 * L * 200 * (fy - fz)};
}

double hyab(const Rgb& p, const Rgb& q) { return std::abs(p[0] - q[0]) + std::hypot(p[1] - q[1], p[2] - q[2]); }

// A value of LDR-FLIP's input: clamped to [0, 1], NaN to 0.
double unit(float v) { return v > 0 ? std::min(double(v), 1.0) : 0.0; }

// Correlation of a W x H plane with kx along x and then ky along y (odd lengths, centred),
// replicating the border pixels.
std::vector<float> separable(const std::vector<float>& in, int W, int H, const std::vector<double>& kx,
                             const std::vector<double>& ky) {
  const int rx = int(kx.size()) / 2, ry = int(ky.size()) / 2;
  std::vector<float> tmp(in.size()), out(in.size());
  tbb::parallel_for(0, H, [&](int y) {
    for (int x = 0; x < W; ++x) {
      double s = 0;
      for (int d = -rx; d <= rx; ++d) s += kx[d + rx] * in[std::size_t(y) * W + std::clamp(x + d, 0, W - 1)];
      tmp[std::size_t(y) * W + x] = float(s);
    }
  });
  tbb::parallel_for(0, H, [&](int y) {
    for (int x = 0; x < W; ++x) {
      double s = 0;
      for (int d = -ry; d <= ry; ++d) s += ky[d + ry] * tmp[std::size_t(std::clamp(y + d, 0, H - 1)) * W + x];
      out[std::size_t(y) * W + x] = float(s);
    }
  });
  return out;
}

// A channel's contrast sensitivity function: a1 sqrt(pi / b1) exp(-pi^2 x^2 / b1) + the same in
// (a2, b2), x in degrees.
struct Csf {
  double a1, b1, a2, b2;
};
constexpr Csf kCsf[3] = {{1, 0.0047, 0, 1e-5}, {1, 0.0053, 0, 1e-5}, {34.1, 0.04, 13.5, 0.025}};

// `plane` filtered by `csf` on the 2-D grid of radius r: each Gaussian term is separable,
// exp(-pi^2 (dx^2 + dy^2) / (b ppd^2)) = g(dx) g(dy), and the sum is normalised to 1 over the grid.
std::vector<float> csf_filter(const std::vector<float>& plane, int W, int H, const Csf& csf, double ppd) {
  const int r = int(std::ceil(3 * std::sqrt(0.04 / (2 * kPi * kPi)) * ppd));  // 0.04: the largest b
  std::vector<double> out(plane.size(), 0.0);
  double total = 0;
  for (auto [a, b] : {std::pair{csf.a1, csf.b1}, std::pair{csf.a2, csf.b2}}) {
    if (a == 0) continue;
    std::vector<double> g(std::size_t(2 * r + 1));
    for (int d = -r; d <= r; ++d) g[d + r] = std::exp(-kPi * kPi * d * d / (b * ppd * ppd));
    const double weight = a * std::sqrt(kPi / b), sum = std::accumulate(g.begin(), g.end(), 0.0);
    const std::vector<float> f = separable(plane, W, H, g, g);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] += weight * f[i];
    total += weight * sum * sum;
  }
  std::vector<float> res(plane.size());
  for (std::size_t i = 0; i < res.size(); ++i) res[i] = float(out[i] / total);
  return res;
}

// The edge (first derivative) or point (second derivative) detector along one axis, positive
// weights normalised to sum 1 and negative ones to -1, and the Gaussian across it summing to 1.
struct FeatureKernels {
  std::vector<double> edge, point, gauss;
};
FeatureKernels feature_kernels(double ppd) {
  const double sd = 0.5 * 0.082 * ppd;  // w = 0.082 degrees, peak to trough of the edge detector
  const int r = int(std::ceil(3 * sd));
  FeatureKernels k;
  for (int d = -r; d <= r; ++d) {
    const double g = std::exp(-d * d / (2 * sd * sd));
    k.gauss.push_back(g), k.edge.push_back(-d * g), k.point.push_back((d * d / (sd * sd) - 1) * g);
  }
  const double gs = std::accumulate(k.gauss.begin(), k.gauss.end(), 0.0);
  for (double& g : k.gauss) g /= gs;
  for (auto* v : {&k.edge, &k.point}) {
    double pos = 0, neg = 0;
    for (double w : *v) (w > 0 ? pos : neg) += w;
    for (double& w : *v) w = w > 0 ? w / pos : w / -neg;
  }
  return k;
}

// |(response along x, response along y)| of `kernel` on the achromatic plane.
std::vector<float> feature_magnitude(const std::vector<float>& y, int W, int H, const std::vector<double>& kernel,
                                     const std::vector<double>& gauss) {
  const std::vector<float> fx = separable(y, W, H, kernel, gauss), fy = separable(y, W, H, gauss, kernel);
  std::vector<float> m(y.size());
  for (std::size_t i = 0; i < m.size(); ++i) m[i] = std::hypot(fx[i], fy[i]);
  return m;
}

// c_max of the colour remap: the HyAB distance of green and blue, raised to q_c.
double colour_max() {
  static const double c = std::pow(hyab(rgb_to_hunt_lab({0, 1, 0}), rgb_to_hunt_lab({0, 0, 1})), 0.7);
  return c;
}

// HyAB^q_c remapped to [0, 1]: [0, p_c c_max) linearly to [0, p_t), the rest to [p_t, 1].
double remap_colour(double e) {
  constexpr double pc = 0.4, pt = 0.95;
  const double cmax = colour_max(), knee = pc * cmax;
  return e < knee ? pt / knee * e : pt + (e - knee) / (cmax - knee) * (1 - pt);
}

// The ACES fit's coefficients, with the fit's 0.6 pre-exposure folded in.
constexpr double kAces[5] = {0.6 * 0.6 * 2.51, 0.6 * 0.03, 0.6 * 0.6 * 2.43, 0.6 * 0.59, 0.14};

// x with T(x) = t: (k0 - k3 t) x^2 + (k1 - k4 t) x - k5 t = 0, the positive root.
double aces_inverse(double t) {
  const double c0 = (kAces[1] - kAces[3] * t) / (kAces[0] - kAces[2] * t),
               c1 = -kAces[4] * t / (kAces[0] - kAces[2] * t);
  return -0.5 * c0 + std::sqrt(0.25 * c0 * c0 - c1);
}

double median(std::vector<double> v) {
  const std::size_t n = v.size(), m = n / 2;
  std::nth_element(v.begin(), v.begin() + m, v.end());
  if (n % 2) return v[m];
  return 0.5 * (v[m] + *std::max_element(v.begin(), v.begin() + m));
}

}  // namespace

FlipView flip_view(const std::vector<float>& rgb, int W, int H, double ppd) {
  if (W < 1 || H < 1 || rgb.size() != std::size_t(3) * W * H) throw std::invalid_argument("flip_view: bad image");
  const std::size_t n = std::size_t(W) * H;
  std::vector<float> opp[3], achromatic(n);
  for (auto& p : opp) p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Rgb c = rgb_to_ycxcz({unit(rgb[3 * i]), unit(rgb[3 * i + 1]), unit(rgb[3 * i + 2])});
    for (int k = 0; k < 3; ++k) opp[k][i] = float(c[k]);
    achromatic[i] = float((c[0] + 16) / 116);
  }
  for (int k = 0; k < 3; ++k) opp[k] = csf_filter(opp[k], W, H, kCsf[k], ppd);
  FlipView v;
  v.width = W, v.height = H;
  v.L.resize(n), v.a.resize(n), v.b.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Rgb c = ycxcz_to_rgb({opp[0][i], opp[1][i], opp[2][i]});
    for (double& x : c) x = std::clamp(x, 0.0, 1.0);
    const Rgb lab = rgb_to_hunt_lab(c);
    v.L[i] = float(lab[0]), v.a[i] = float(lab[1]), v.b[i] = float(lab[2]);
  }
  const FeatureKernels k = feature_kernels(ppd);
  v.edge = feature_magnitude(achromatic, W, H, k.edge, k.gauss);
  v.point = feature_magnitude(achromatic, W, H, k.point, k.gauss);
  return v;
}

std::vector<float> flip_error(const FlipView& r, const FlipView& t) {
  if (r.width != t.width || r.height != t.height) throw std::invalid_argument("flip_error: images differ in size");
  std::vector<float> e(r.L.size());
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double colour = remap_colour(std::pow(hyab({r.L[i], r.a[i], r.b[i]}, {t.L[i], t.a[i], t.b[i]}), 0.7));
    const double feature =
        std::sqrt(std::max(std::abs(r.edge[i] - t.edge[i]), std::abs(r.point[i] - t.point[i])) / std::sqrt(2.0));
    e[i] = float(std::pow(colour, 1 - feature));
  }
  return e;
}

std::vector<float> ldr_flip(const Image& r, const Image& t, double ppd) {
  return flip_error(flip_view(r.rgb, r.width, r.height, ppd), flip_view(t.rgb, t.width, t.height, ppd));
}

FlipExposures hdr_flip_exposures(const Image& ref) {
  std::vector<double> Y, positive;  // the finite luminances, and the positive ones
  for (std::size_t i = 0; i < std::size_t(ref.width) * ref.height; ++i) {
    const double y = luminance(Vec3(ref.rgb[3 * i], ref.rgb[3 * i + 1], ref.rgb[3 * i + 2]));
    if (!std::isfinite(y)) continue;
    Y.push_back(y);
    if (y > 0) positive.push_back(y);
  }
  FlipExposures e;
  const double top = Y.empty() ? 0.0 : *std::max_element(Y.begin(), Y.end());
  if (!(top > 0)) return e;
  double mid = median(Y);
  if (!(mid > 0)) mid = median(positive);
  const double x = aces_inverse(0.85);
  e.start = std::log2(x / top), e.stop = std::log2(x / mid);
  e.count = std::max(2, int(std::ceil(e.stop - e.start)));
  return e;
}

std::vector<float> flip_tone_map(const Image& im, double exposure) {
  const double scale = std::exp2(exposure);
  std::vector<float> out(im.rgb.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double x = im.rgb[i] > 0 ? scale * im.rgb[i] : 0.0;  // NaN to 0
    const double y = std::isinf(x) ? 1.0 : (kAces[0] * x + kAces[1]) * x / ((kAces[2] * x + kAces[3]) * x + kAces[4]);
    out[i] = float(std::clamp(y, 0.0, 1.0));
  }
  return out;
}

HdrFlipReference hdr_flip_reference(const Image& ref, double ppd) {
  HdrFlipReference h;
  h.exposures = hdr_flip_exposures(ref), h.ppd = ppd;
  h.views.resize(std::size_t(h.exposures.count));
  tbb::parallel_for(0, h.exposures.count, [&](int i) {
    h.views[std::size_t(i)] = flip_view(flip_tone_map(ref, h.exposures.at(i)), ref.width, ref.height, ppd);
  });
  return h;
}

std::vector<float> hdr_flip(const HdrFlipReference& ref, const Image& test) {
  std::vector<std::vector<float>> per(ref.views.size());
  tbb::parallel_for(std::size_t(0), per.size(), [&](std::size_t i) {
    per[i] = flip_error(ref.views[i],
                        flip_view(flip_tone_map(test, ref.exposures.at(int(i))), test.width, test.height, ref.ppd));
  });
  std::vector<float> m = per[0];
  for (const auto& p : per)
    for (std::size_t k = 0; k < m.size(); ++k) m[k] = std::max(m[k], p[k]);
  return m;
}

std::vector<float> hdr_flip(const Image& reference, const Image& test, double ppd) {
  return hdr_flip(hdr_flip_reference(reference, ppd), test);
}

double mean_flip(const std::vector<float>& map) {
  double s = 0;
  for (float v : map) s += v;
  return map.empty() ? 0.0 : s / double(map.size());
}

}  // namespace pdrt
