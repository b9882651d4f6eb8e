// The libraries' build signature (core/build_info.h), expanded with their flags.
#include "core/build_info.h"

namespace framedyn::core {

const char* library_build_signature() { return FRAMEDYN_BUILD_SIGNATURE; }

}  // namespace framedyn::core
