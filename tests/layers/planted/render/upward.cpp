// A planted upward include: check_layers.cmake must refuse this folder
// (ctest layers_refuse_upward_include).
#include "app/commands.hpp"
