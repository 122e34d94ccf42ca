#include "renderer/render/embree_device.h"

#include <stdexcept>

namespace pdrt {
namespace {
const char* error_name(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE:
      return "none";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
    default:
      return "unknown error";
  }
}
void on_error(void* user, RTCError code, const char* str) {
  auto* last = static_cast<std::string*>(user);
  *last = std::string("embree: ") + error_name(code) + (str ? std::string(": ") + str : std::string());
}
}  // namespace

EmbreeDevice::EmbreeDevice(const std::string& config) {
  device_ = rtcNewDevice(config.empty() ? nullptr : config.c_str());
  if (!device_)
    throw std::runtime_error(std::string("embree: cannot create device: ") + error_name(rtcGetDeviceError(nullptr)));
  rtcSetDeviceErrorFunction(device_, on_error, &last_error_);
}

EmbreeDevice::~EmbreeDevice() {
  if (device_) rtcReleaseDevice(device_);
}

void EmbreeDevice::check() const {
  if (!last_error_.empty()) {
    std::string msg;
    msg.swap(last_error_);
    throw std::runtime_error(msg);
  }
}

}  // namespace pdrt
