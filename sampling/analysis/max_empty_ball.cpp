#include "sampling/analysis/max_empty_ball.h"

#include "sampling/core/distance.h"
#include "sampling/measures/kd_tree.h"
#include "sampling/core/rng.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pdrt {
namespace {

double wrap01(double x) { return x - std::floor(x); }

// ---- 1-D: the largest gap, halved; the domain ends count as centres when not periodic.
EmptyBall empty_ball_1d(const PointSet& points, bool periodic) {
  std::vector<double> xs(points.coords);
  std::sort(xs.begin(), xs.end());
  EmptyBall best;
  best.method = "exact-1d";
  best.exact = true;
  auto consider = [&](double r, double c) {
    if (r > best.radius || best.center.empty()) best.radius = r, best.center = {c};
  };
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) consider(0.5 * (xs[i + 1] - xs[i]), 0.5 * (xs[i] + xs[i + 1]));
  if (periodic) {
    double gap = xs.front() + 1.0 - xs.back();
    consider(0.5 * gap, wrap01(xs.back() + 0.5 * gap));
  } else {
    consider(xs.front(), 0.0);
    consider(1.0 - xs.back(), 1.0);
  }
  return best;
}

// ---- 2-D: each site's Voronoi cell, built by clipping a starting box with the bisectors of
// its neighbours in order of distance. The largest empty circle is centred on a cell vertex
// (with the domain boundary when not periodic), so the answer is exact up to rounding.
struct Vec2 {
  double x, y;
};

struct Neighbour {
  double d2;
  Vec2 d;  // neighbour minus site
};

// Keeps the part of convex polygon `poly` nearer the site (origin) than the point at `d`.
void clip_by_bisector(std::vector<Vec2>& poly, std::vector<Vec2>& tmp, Vec2 d) {
  const double c = 0.5 * (d.x * d.x + d.y * d.y);
  tmp.clear();
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    Vec2 a = poly[i], b = poly[(i + 1) % n];
    double fa = a.x * d.x + a.y * d.y - c, fb = b.x * d.x + b.y * d.y - c;
    if (fa <= 0.0) tmp.push_back(a);
    if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0)) {
      double t = fa / (fa - fb);
      tmp.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    }
  }
  poly.swap(tmp);
}

EmptyBall empty_ball_2d(const PointSet& points, bool periodic) {
  const std::size_t n = points.size();
  const double* c = points.coords.data();
  KdTree tree(points.coords, 2, periodic);
  // About 2.5 mean spacings: most cells close within their first gather.
  const double first_gather = std::min(2.5 / std::sqrt(double(n)), periodic ? 0.49 : 2.0);

  std::vector<double> cell_r2(n, 0.0);
  std::vector<Vec2> cell_vertex(n, Vec2{0, 0});

  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const tbb::blocked_range<std::size_t>& range) {
    std::vector<Vec2> poly, tmp;
    std::vector<KdTree::Hit> hits;
    std::vector<Neighbour> nbrs;
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const double sx = c[2 * i], sy = c[2 * i + 1];
      // Periodic: the cell lies within the bisectors of the site's own images (a unit box).
      if (periodic)
        poly = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
      else
        poly = {{-sx, -sy}, {1.0 - sx, -sy}, {1.0 - sx, 1.0 - sy}, {-sx, 1.0 - sy}};
      auto max_r2 = [&] {
        double m = 0.0;
        for (auto v : poly) m = std::max(m, v.x * v.x + v.y * v.y);
        return m;
      };
      double r2 = max_r2();
      double used2 = -1.0;  // neighbours with d2 <= used2 have been applied
      double gather = first_gather;
      for (;;) {
        nbrs.clear();
        if (periodic && gather >= 0.5) {
          // Several images of one point may now be in reach: enumerate them. The cell fits in
          // the unit box, so 2*Rmax <= sqrt(2) and offsets up to 2 suffice.
          for (std::size_t j = 0; j < n; ++j)
            for (int ey = -2; ey <= 2; ++ey)
              for (int ex = -2; ex <= 2; ++ex) {
                Vec2 d{c[2 * j] - sx + ex, c[2 * j + 1] - sy + ey};
                double d2 = d.x * d.x + d.y * d.y;
                if (d2 > 0.0 && d2 <= gather * gather) nbrs.push_back({d2, d});
              }
        } else {
          // Below half the period each neighbour has at most one image in reach: the wrapped one.
          hits.clear();
          tree.within(&c[2 * i], gather * gather, hits);
          for (const auto& h : hits) {
            if (h.dist_sq <= 0.0) continue;  // the site itself or a duplicate (same cell)
            Vec2 d{axis_delta(c[2 * h.id], sx, periodic), axis_delta(c[2 * h.id + 1], sy, periodic)};
            nbrs.push_back({h.dist_sq, d});
          }
        }
        // Only the ring beyond the previous gather is new.
        std::erase_if(nbrs, [&](const Neighbour& nb) { return nb.d2 <= used2; });
        std::sort(nbrs.begin(), nbrs.end(), [](const Neighbour& a, const Neighbour& b) { return a.d2 < b.d2; });
        bool closed = false;
        for (const auto& nb : nbrs) {
          // A bisector farther than every vertex cannot cut the cell, nor can later ones.
          if (nb.d2 > 4.0 * r2) {
            closed = true;
            break;
          }
          clip_by_bisector(poly, tmp, nb.d);
          r2 = max_r2();
        }
        if (closed || 4.0 * r2 <= gather * gather) break;
        used2 = gather * gather;
        // Grow by rings: a cell still open on one side shrinks fast once the next ring is in.
        gather = std::min(2.0 * gather, 2.0 * std::sqrt(r2) * 1.0001);
      }
      cell_r2[i] = r2;
      for (auto v : poly)
        if (v.x * v.x + v.y * v.y == r2) cell_vertex[i] = v;
    }
  });

  std::size_t best = std::size_t(std::max_element(cell_r2.begin(), cell_r2.end()) - cell_r2.begin());
  EmptyBall ball;
  ball.method = "voronoi-2d";
  ball.exact = true;
  ball.radius = std::sqrt(cell_r2[best]);
  double cx = c[2 * best] + cell_vertex[best].x, cy = c[2 * best + 1] + cell_vertex[best].y;
  if (periodic)
    cx = wrap01(cx), cy = wrap01(cy);
  else
    cx = std::clamp(cx, 0.0, 1.0), cy = std::clamp(cy, 0.0, 1.0);
  ball.center = {cx, cy};
  return ball;
}

// ---- 3-D and up: probe densely, then let the most promising probes climb.
//
// f(x) = distance to the nearest sample is a minimum of distance functions; its steepest
// ascent direction is the minimum-norm point of the convex hull of the unit vectors pointing
// away from the samples that are (nearly) nearest. Steps of length s only need the samples
// within f + s, since farther ones cannot become nearest. Where that minimum norm is zero, x is
// a local maximum: a Voronoi vertex (or a boundary point when not periodic).

// Minimum-norm point of conv{g_j} by Frank–Wolfe with exact line search.
void min_norm_in_hull(const std::vector<double>& g, int dim, std::vector<double>& u) {
  const std::size_t m = g.size() / std::size_t(dim);
  u.assign(g.begin(), g.begin() + dim);
  std::vector<double> w(dim);
  for (int it = 0; it < 500; ++it) {
    std::size_t jbest = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < m; ++j) {
      double dot = 0.0;
      for (int k = 0; k < dim; ++k) dot += u[k] * g[j * dim + k];
      if (dot < best) best = dot, jbest = j;
    }
    double uu = 0.0;
    for (int k = 0; k < dim; ++k) uu += u[k] * u[k];
    if (uu - best <= 1e-15) return;  // duality gap closed
    double uw = 0.0, ww = 0.0;
    for (int k = 0; k < dim; ++k) {
      w[k] = g[jbest * dim + k] - u[k];
      uw += u[k] * w[k];
      ww += w[k] * w[k];
    }
    if (ww <= 0.0) return;
    double t = std::clamp(-uw / ww, 0.0, 1.0);
    for (int k = 0; k < dim; ++k) u[k] += t * w[k];
  }
}

struct Climber {
  const KdTree& tree;
  const PointSet& points;
  bool periodic;

  double f(const double* x) const { return std::sqrt(tree.nearest(x).dist_sq); }

  // Climbs from x in place; returns the final nearest-sample distance.
  double climb(std::vector<double>& x) const {
    const int dim = points.dim;
    double fx = f(x.data());
    if (fx <= 0.0) return fx;
    double s = 0.5 * fx;
    std::vector<KdTree::Hit> hits;
    std::vector<double> g, u, trial(dim);
    std::vector<char> pinned(dim);
    for (int it = 0; it < 400 && s > 1e-10 * fx; ++it) {
      hits.clear();
      tree.within(x.data(), (fx + s) * (fx + s), hits);
      g.clear();
      for (const auto& h : hits) {
        double norm = std::sqrt(h.dist_sq);
        if (norm <= 0.0) continue;
        for (int k = 0; k < dim; ++k)
          g.push_back(axis_delta(x[k], points.coords[std::size_t(h.id) * dim + k], periodic) / norm);
      }
      if (g.empty()) break;
      // Not periodic: on a face of the cube, drop the components that would leave it.
      std::fill(pinned.begin(), pinned.end(), 0);
      double unorm = 0.0;
      for (int pass = 0; pass <= dim; ++pass) {
        min_norm_in_hull(g, dim, u);
        bool changed = false;
        if (!periodic)
          for (int k = 0; k < dim; ++k)
            if (!pinned[k] && ((x[k] <= 0.0 && u[k] < 0.0) || (x[k] >= 1.0 && u[k] > 0.0))) {
              pinned[k] = 1, changed = true;
              for (std::size_t j = 0; j < g.size() / dim; ++j) g[j * dim + k] = 0.0;
            }
        if (!changed) break;
      }
      unorm = 0.0;
      for (int k = 0; k < dim; ++k) unorm += u[k] * u[k];
      unorm = std::sqrt(unorm);
      if (unorm < 1e-12) {
        s *= 0.5;
        continue;
      }
      for (int k = 0; k < dim; ++k) {
        double v = x[k] + s * u[k] / unorm;
        trial[k] = periodic ? wrap01(v) : std::clamp(v, 0.0, 1.0);
      }
      double ft = f(trial.data());
      if (ft > fx) {
        x.assign(trial.begin(), trial.end());
        fx = ft;
        s *= 1.5;
      } else {
        s *= 0.5;
      }
    }
    return fx;
  }
};

EmptyBall empty_ball_probe(const PointSet& points, bool periodic, uint64_t seed) {
  const int dim = points.dim;
  const std::size_t n = points.size();
  KdTree tree(points.coords, dim, periodic);
  // Probe budget shrinks with dimension, where each nearest query costs more.
  double cap = 400000.0 / std::pow(2.0, dim - 3);
  std::size_t m = std::size_t(std::max(4096.0, std::min(std::max(8192.0, 8.0 * double(n)), cap)));
  std::vector<double> probes;
  probes.reserve((m + (std::size_t(1) << dim)) * dim);
  Rng rng(seed, 0xC0FE);
  for (std::size_t i = 0; i < m * std::size_t(dim); ++i) probes.push_back(rng.uniform());
  if (!periodic)  // corners are frequent maxima of a bounded domain
    for (uint32_t corner = 0; corner < (1u << dim); ++corner)
      for (int k = 0; k < dim; ++k) probes.push_back((corner >> k) & 1u ? 1.0 : 0.0);
  const std::size_t total = probes.size() / dim;
  std::vector<double> fval(total);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, total, 512), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) fval[i] = std::sqrt(tree.nearest(&probes[i * dim]).dist_sq);
  });
  std::size_t climbers = std::clamp<std::size_t>(total / 64, 32, 400);
  climbers = std::min(climbers, total);
  std::vector<std::size_t> order(total);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(climbers), order.end(),
                    [&](std::size_t a, std::size_t b) { return fval[a] > fval[b]; });
  std::vector<double> result(climbers);
  std::vector<std::vector<double>> where(climbers);
  Climber climber{tree, points, periodic};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, climbers, 1), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      std::vector<double> x(probes.begin() + std::ptrdiff_t(order[i] * dim),
                            probes.begin() + std::ptrdiff_t((order[i] + 1) * dim));
      result[i] = climber.climb(x);
      where[i] = std::move(x);
    }
  });
  std::size_t best = std::size_t(std::max_element(result.begin(), result.end()) - result.begin());
  EmptyBall ball;
  ball.method = "probe-ascent";
  ball.exact = false;
  ball.radius = result[best];
  ball.center = where[best];
  ball.probes = total;
  return ball;
}

}  // namespace

EmptyBall max_empty_ball(const PointSet& points, bool periodic, uint64_t seed) {
  if (points.size() == 0) return {};
  if (points.dim == 1) return empty_ball_1d(points, periodic);
  if (points.dim == 2) return empty_ball_2d(points, periodic);
  return empty_ball_probe(points, periodic, seed);
}

}  // namespace pdrt
