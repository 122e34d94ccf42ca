#pragma once
// An Embree device with pdrt's error callback registered: Embree errors become
// exceptions with a one-line message instead of silent failures.
#include <embree3/rtcore.h>

#include <string>

namespace pdrt {

class EmbreeDevice {
 public:
  explicit EmbreeDevice(const std::string& config = "");
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;
  RTCDevice get() const { return device_; }
  // Throws if the callback recorded an error since the last call.
  void check() const;

 private:
  RTCDevice device_ = nullptr;
  mutable std::string last_error_;
};

}  // namespace pdrt
