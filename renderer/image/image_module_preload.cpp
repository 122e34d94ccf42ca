#include "renderer/image/image_module_preload.h"

#include "renderer/image/image_module.h"

namespace pdrt {

ImageModulePreload::ImageModulePreload()
    : loader_([] {
        try {
          image_module();
        } catch (...) {  // said by the caller's own image_module() call
        }
      }) {}

}  // namespace pdrt
