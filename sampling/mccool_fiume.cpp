#include "errors.h"
#include "generator.h"

namespace pdrt {
PointSet generate_mccool(const GeneratorParams&) { throw InputError("method not implemented yet"); }
}  // namespace pdrt
