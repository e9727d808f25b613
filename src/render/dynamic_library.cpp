#include "render/dynamic_library.hpp"

#include <dlfcn.h>

#include <stdexcept>

namespace tumble::render {

DynamicLibrary::DynamicLibrary(const std::string& soname, const std::string& hint)
    : soname_(soname) {
  // RTLD_NODELETE: GL drivers keep threads, TLS and atexit hooks alive past
  // context destruction, so unmapping them on dlclose is asking for a crash
  // at exit; it also keeps their frames symbolised in sanitizer reports.
  handle_ = dlopen(soname.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  if (handle_ == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error("cannot load " + soname + " (" + (why ? why : "unknown") +
                             "); " + hint);
  }
}

DynamicLibrary::~DynamicLibrary() {
  if (handle_ != nullptr) dlclose(handle_);
}

void* DynamicLibrary::symbol(const char* name) const {
  void* p = dlsym(handle_, name);
  if (p == nullptr) {
    throw std::runtime_error("symbol " + std::string(name) + " missing in " + soname_);
  }
  return p;
}

}  // namespace tumble::render
