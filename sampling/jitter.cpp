#include "errors.h"
#include "generator.h"

namespace pdrt {
PointSet generate_jitter(const GeneratorParams&) { throw InputError("method not implemented yet"); }
}  // namespace pdrt
