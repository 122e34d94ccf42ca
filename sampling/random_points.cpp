#include "errors.h"
#include "generator.h"

namespace pdrt {
PointSet generate_random(const GeneratorParams&) { throw InputError("method not implemented yet"); }
}  // namespace pdrt
