#include "renderer/scene/texture_desc.h"

#include <algorithm>

namespace pdrt {

std::vector<int> texture_inputs(const TextureDesc& t) {
  std::vector<int> out;
  auto add = [&](const TextureInput& in) {
    if (in.texture >= 0) out.push_back(in.texture);
  };
  switch (t.kind) {
    case TextureDesc::Kind::Checkerboard:
      add(t.color0), add(t.color1);
      break;
    case TextureDesc::Kind::Scale:
      add(t.tex), add(t.scale);
      break;
    case TextureDesc::Kind::Mix:
      add(t.tex1), add(t.tex2), add(t.amount);
      break;
    case TextureDesc::Kind::Invert:
    case TextureDesc::Kind::Power:
      add(t.tex);
      break;
    default:
      break;
  }
  return out;
}

long long texture_node_cost(const TextureDesc& t, const std::vector<long long>& cost) {
  long long c = 0;
  const std::vector<int> in = texture_inputs(t);
  if (t.kind == TextureDesc::Kind::Checkerboard) {
    // One of the two inputs, reached by a loop (no recursion): the larger.
    for (int k : in) c = std::max(c, cost[size_t(k)]);
  } else if (!in.empty()) {
    c = 1;
    for (int k : in) c += cost[size_t(k)];
  }
  return std::min(c, 1LL << 40);  // saturates: a deep diamond graph doubles per level
}

std::vector<long long> texture_evaluation_cost(const std::vector<TextureDesc>& textures,
                                               const std::vector<int>& order) {
  std::vector<long long> cost(textures.size(), 0);
  if (order.empty()) {
    for (size_t i = 0; i < textures.size(); ++i) cost[i] = texture_node_cost(textures[i], cost);
  } else {
    for (int i : order) cost[size_t(i)] = texture_node_cost(textures[size_t(i)], cost);
  }
  return cost;
}

}  // namespace pdrt
