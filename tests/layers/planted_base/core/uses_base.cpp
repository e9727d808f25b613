// Core over base: allowed, so the refusal of this folder must not name this file.
#include "base/error.hpp"
#include "core/body.hpp"
