// Exceptions of the physics: a body that cannot rotate, a run that diverged.
// Messages are for users: they say what is wrong, why, and how to fix it.
#pragma once

#include <stdexcept>
#include <string>

#include "base/error.hpp"

namespace tumble {

/// A body whose mass distribution cannot define a rotation (no NaN ever leaks).
class DegenerateBody : public InputError {
 public:
  using InputError::InputError;
};

/// A state became non-finite (or a torque-free energy blew up) mid-run.
/// The app maps it to exit code 3 and keeps what was already written.
class Diverged : public std::runtime_error {
 public:
  Diverged(const std::string& what, double t, long step)
      : std::runtime_error(what), time(t), step_index(step) {}
  double time;       ///< s, end of the failing step (where the bad state was found)
  long step_index;   ///< index of the failing step
};

}  // namespace tumble
