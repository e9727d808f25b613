// The "# expect: <text>" lines of a test input file (broken and unreadable
// scene corpora): the messages loading it must report, one per line.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

inline std::vector<std::string> expectations(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  const std::string tag = "# expect: ";
  for (std::string line; std::getline(in, line);)
    if (line.rfind(tag, 0) == 0) out.push_back(line.substr(tag.size()));
  return out;
}
