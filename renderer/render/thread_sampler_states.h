#pragma once
// A thread's PixelSampleStates, kept from one tile (or calibration block) to the next: a state
// is ~45 KB of stream slots, and streams that computed values keep their buffers, where a
// state per tile or per 4 x 4 block made and zeroed them again. A lease starts from no pixel
// (PixelSampleState::forget_pixel), so what a pixel draws never depends on what the thread
// rendered before; a lease taken while the thread holds one (a nested TBB wait that runs
// another tile) gets states of its own.
#include "sampling/samplers/sampler.h"

#include <tbb/enumerable_thread_specific.h>

#include <memory>
#include <optional>

namespace pdrt {

class ThreadSamplerStates {
  struct Held {
    std::optional<PixelSampleState> sampler, decider;
    bool leased = false;
  };

 public:
  // `decider`: the decision samples' sampler under "split", else nullptr.
  ThreadSamplerStates(const Sampler& sampler, const Sampler* decider) : sampler_(sampler), decider_(decider) {}

  class Lease {
   public:
    PixelSampleState& sampler() { return *held_->sampler; }
    PixelSampleState* decider() { return held_->decider ? &*held_->decider : nullptr; }
    ~Lease() {
      if (!own_) held_->leased = false;
    }
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;

   private:
    friend class ThreadSamplerStates;
    Lease(Held& thread, const Sampler& s, const Sampler* d)
        : own_(thread.leased ? std::make_unique<Held>() : nullptr), held_(own_ ? own_.get() : &thread) {
      held_->leased = true;
      if (!held_->sampler) held_->sampler.emplace(s);
      if (d && !held_->decider) held_->decider.emplace(*d);
      held_->sampler->forget_pixel();
      if (held_->decider) held_->decider->forget_pixel();
    }
    std::unique_ptr<Held> own_;  // the nested lease's
    Held* held_;
  };

  Lease lease() { return Lease(held_.local(), sampler_, decider_); }

 private:
  const Sampler& sampler_;
  const Sampler* decider_;
  tbb::enumerable_thread_specific<Held> held_;
};

}  // namespace pdrt
