// A planted include of core from base: base sits below the physics, so
// check_layers.cmake must refuse this folder (ctest layers_refuse_core_in_base).
#include "core/body.hpp"
