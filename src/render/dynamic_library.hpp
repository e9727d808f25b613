// RAII wrapper over dlopen, so each GL backend is optional at run time: a
// machine without libEGL can still render through OSMesa and vice versa.
#pragma once

#include <string>

namespace tumble::render {

class DynamicLibrary {
 public:
  /// Opens `soname` (RTLD_NOW | RTLD_LOCAL); throws with `hint` on failure.
  DynamicLibrary(const std::string& soname, const std::string& hint);
  ~DynamicLibrary();
  DynamicLibrary(const DynamicLibrary&) = delete;
  DynamicLibrary& operator=(const DynamicLibrary&) = delete;

  /// Looks up a symbol; throws naming the library when it is missing.
  void* symbol(const char* name) const;

  /// Typed lookup: the cast from void* is the POSIX-sanctioned dlsym idiom.
  template <class Fn>
  Fn get(const char* name) const {
    return reinterpret_cast<Fn>(symbol(name));
  }

 private:
  void* handle_ = nullptr;
  std::string soname_;
};

}  // namespace tumble::render
