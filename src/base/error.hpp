// The error every layer throws for bad input. Messages are for users: they say
// what is wrong, why, and how to fix it.
#pragma once

#include <stdexcept>

namespace tumble {
namespace base {

/// Bad input (scene values, cloud contents, options). The app maps it to exit code 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace base

using base::InputError;

}  // namespace tumble
