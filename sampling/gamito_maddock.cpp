#include "errors.h"
#include "generator.h"

namespace pdrt {
PointSet generate_gamito(const GeneratorParams&) { throw InputError("method not implemented yet"); }
}  // namespace pdrt
