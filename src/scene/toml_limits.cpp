#include "scene/toml_limits.hpp"

#include <vector>

#include "scene/scene.hpp"

namespace tumble::scene {

namespace {

// Walks the text once, skipping strings and comments, and tracks whether a
// key or a value is being read (only a key's dots nest tables).
class Scanner {
 public:
  Scanner(std::string_view text, const std::string& source) : t_(text), source_(source) {}

  void run() {
    while (i_ < t_.size()) {
      const char c = t_[i_];
      if (c == '"' || c == '\'') {
        skip_string(c);
        continue;
      }
      if (c == '#') {
        while (i_ < t_.size() && t_[i_] != '\n') ++i_;
        continue;
      }
      if (c == '\n') newline();
      else if (c == '.' && in_key_ && ++dots_ >= kMaxKeyDepth) fail("a key of more than " + std::to_string(kMaxKeyDepth) + " dotted parts (the key-depth limit)");
      else if (c == '=') in_key_ = false, dots_ = 0, count();
      else if (c == '[' || c == '{') open(c);
      else if (c == ']' || c == '}') close();
      else if (c == ',') in_key_ = !stack_.empty() && stack_.back() == '{', dots_ = 0, count();
      ++i_, ++col_;
    }
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    Diagnostic d;
    d.file = source_;
    d.line = line_;
    d.column = col_;
    d.message = "the scene has " + what + "; refused before parsing";
    throw SceneError({d});
  }
  void count() {
    if (++values_ > kMaxSceneValues)
      fail("more than " + std::to_string(kMaxSceneValues) + " values (the scene-size limit; put large clouds in a cloud file)");
  }
  void newline() {
    ++line_, col_ = 0;
    if (stack_.empty()) in_key_ = true, dots_ = 0;
  }
  void open(char c) {
    count();
    if (stack_.empty() && in_key_) {  // a [table] or [[array]] header: a key until ']'
      if (t_.substr(i_, 2) == "[[") {
        ++i_, ++col_;
        if (header_name() == "bodies" && ++bodies_ > kMaxBodies)
          fail("more than " + std::to_string(kMaxBodies) + " [[bodies]] (the body cap)");
      }
      return;
    }
    stack_.push_back(c);
    if (stack_.size() > kMaxNesting)
      fail("arrays or inline tables nested more than " + std::to_string(kMaxNesting) + " deep (the nesting limit)");
    in_key_ = c == '{', dots_ = 0;
  }
  std::string_view header_name() const {
    const std::size_t end = t_.find(']', i_);
    std::string_view n = t_.substr(i_ + 1, end == std::string_view::npos ? 0 : end - i_ - 1);
    while (!n.empty() && (n.front() == ' ' || n.front() == '\t')) n.remove_prefix(1);
    while (!n.empty() && (n.back() == ' ' || n.back() == '\t')) n.remove_suffix(1);
    return n;
  }
  void close() {
    if (!stack_.empty()) stack_.pop_back();
    in_key_ = false;
  }
  void skip_string(char q) {
    const bool triple = t_.substr(i_, 3) == std::string_view(q == '"' ? "\"\"\"" : "'''");
    const std::size_t w = triple ? 3 : 1;
    i_ += w, col_ += static_cast<int>(w);
    while (i_ < t_.size()) {
      const char c = t_[i_];
      if (c == '\\' && q == '"') {
        i_ += 2, col_ += 2;
        continue;
      }
      if (c == '\n') {
        if (!triple) return;  // toml++ reports the unterminated string
        ++line_, col_ = 0;
      }
      if (c == q && (!triple || t_.substr(i_, 3) == std::string_view(q == '"' ? "\"\"\"" : "'''"))) {
        i_ += w, col_ += static_cast<int>(w);
        return;
      }
      ++i_, ++col_;
    }
  }

  std::string_view t_;
  const std::string& source_;
  std::size_t i_ = 0, dots_ = 0, values_ = 0, bodies_ = 0;
  int line_ = 1, col_ = 1;
  bool in_key_ = true;
  std::vector<char> stack_;
};

}  // namespace

void check_toml_limits(std::string_view text, const std::string& source_name) { Scanner(text, source_name).run(); }

}  // namespace tumble::scene
