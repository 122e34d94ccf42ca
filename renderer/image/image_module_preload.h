#pragma once
// Loads the image module (image_module.h) on a thread of its own while the caller goes on:
// OpenImageIO and its ~260 libraries cost 0.2 s of relocations. Started before the scene
// loads, the two overlap (a 510k-triangle OBJ takes about as long) instead of adding up on the
// main thread before the first pass. Not beside the render: dlopen holds glibc's loader lock
// for the whole load, and a thread's first thread_local with a destructor registers under it
// (__cxa_thread_atexit_impl), as does TBB's scheduler when it starts (it looks for libiomp5):
// tried, the render stalled for the load's 0.2 s in its first sampler call. A failed load is not
// reported here: image_module() called afterwards tries again and throws its message.
#include <thread>

namespace pdrt {

class ImageModulePreload {
 public:
  ImageModulePreload();
  ~ImageModulePreload() = default;  // joins: the load is done when this goes
  ImageModulePreload(const ImageModulePreload&) = delete;
  ImageModulePreload& operator=(const ImageModulePreload&) = delete;

 private:
  std::jthread loader_;
};

}  // namespace pdrt
