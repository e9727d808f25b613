// Core including nothing but base and core: check_layers.cmake must pass this
// folder (ctest layers_allow_base_in_core).
#include "base/format.hpp"
#include "core/body.hpp"
