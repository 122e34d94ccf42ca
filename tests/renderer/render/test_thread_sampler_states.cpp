// A thread's sampler states kept from tile to tile (renderer/render/thread_sampler_states.h):
// a lease gives the thread's own states again, a nested lease states of its own, and what a
// pixel draws does not depend on what the states drew before.
#include "renderer/render/thread_sampler_states.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace pdrt {
namespace {

// Pixel (x, y)'s first `n` pixel and light values under one pass of `n` (streams prepared).
std::vector<double> draw(PixelSampleState& ps, int x, int y, int n) {
  std::vector<double> v;
  ps.set_pixel_pass(0, n);
  for (int i = 0; i < n; ++i) {
    ps.start_pixel_sample(x, y, i);
    const Vec2 p = ps.get_2d(Family::Pixel), l = ps.get_2d(Family::Light, 1);
    v.insert(v.end(), {p[0], p[1], l[0], l[1]});
  }
  return v;
}

TEST(ThreadSamplerStates, ALeaseGivesTheThreadsStatesAgainAndANestedOneStatesOfItsOwn) {
  const auto sampler = make_sampler("poisson", 5);
  const auto decider = make_sampler("jitter", 6);
  ThreadSamplerStates states(*sampler, decider.get());
  const PixelSampleState* first = nullptr;
  {
    ThreadSamplerStates::Lease outer = states.lease();
    first = &outer.sampler();
    ASSERT_NE(outer.decider(), nullptr);
    EXPECT_EQ(&outer.decider()->sampler(), decider.get());
    ThreadSamplerStates::Lease nested = states.lease();
    EXPECT_NE(&nested.sampler(), first);
    EXPECT_EQ(&nested.sampler().sampler(), sampler.get());
  }
  ThreadSamplerStates::Lease again = states.lease();
  EXPECT_EQ(&again.sampler(), first);
  ThreadSamplerStates none(*sampler, nullptr);
  EXPECT_EQ(none.lease().decider(), nullptr);
}

// The same pixel drawn again after a lease ends (as when one thread's tile ends on the pixel
// another lease then starts with, a calibration block's pixel taken through its next pass) gives
// the values a fresh state gives, for a sampler whose streams the state prepares (poisson) and
// one whose values it computes (sobol).
TEST(ThreadSamplerStates, APixelDrawsTheSameWhateverTheStatesDrewBefore) {
  for (const char* name : {"poisson", "sobol"}) {
    const auto sampler = make_sampler(name, 11);
    PixelSampleState fresh(*sampler);
    const std::vector<double> want = draw(fresh, 3, 4, 16);
    ThreadSamplerStates states(*sampler, nullptr);
    {
      ThreadSamplerStates::Lease l = states.lease();
      draw(l.sampler(), 9, 1, 8);
      draw(l.sampler(), 3, 4, 8);  // the pixel's first 8, in a pass of 8
    }
    ThreadSamplerStates::Lease l = states.lease();
    EXPECT_EQ(draw(l.sampler(), 3, 4, 16), want) << name;
  }
}

}  // namespace
}  // namespace pdrt
